"""Which of the link-track's jumps in the continuity sweep coincide with a change of its
link's turning sense, of its rotation's side of 90 deg, or of where its pivot stands.

Usage: python3 topology.py WORKDIR [KIND] [--full]
WORKDIR is the folder `sweep.py` wrote (its `v-<sweep>-<value>/<kind>/report.json`); KIND
defaults to link-track. Prints every neighbouring pair of steps whose peak actuator load
or mechanism mass changes by more than 1.5x, with the link's rotation to landing at both
and SENSE (turns the other way), CLASS (one turns past 90 deg, the other not) or PLACE
(`link_pivot_place` differs), then how many of the jumps coincide with any of them.
"""
import json, sys

ARGS = [a for a in sys.argv[1:] if a != '--full']
WORK = ARGS[0]
KIND = ARGS[1] if len(ARGS) > 1 else 'link-track'
STEPS = 21 if '--full' in sys.argv[1:] else 11  # as sweep.py
SWEEPS = {kind: [start + (stop - start) * i / (STEPS - 1) for i in range(STEPS)]
          for kind, start, stop in (('landing', 34.0, 36.0), ('gap', 1.5, 2.5), ('offset', 1.4, 1.6))}


def load(path):
    try:
        report = json.load(open(path))
    except (OSError, ValueError):
        return None
    masses = {m['station']: m['mass_kg'] for m in report['sizing']['masses']['per_station']}
    out = {}
    for station in report['stations']:
        mechanism = station['mechanism']
        synthesis = mechanism['details']['synthesis']
        peak = max(abs(s['actuator_load']) for case in mechanism['load_cases'] for s in case['samples'])
        rotation = synthesis.get('link_rotation_rad', [0, 0])[1]
        out[station['name']] = (peak, masses.get(station['name'], 0.0), rotation, synthesis.get('link_pivot_place'))
    return out


jumps = explained = 0
for sweep, values in SWEEPS.items():
    rows = [load(f'{WORK}/v-{sweep}-{v:.3f}/{KIND}/report.json') for v in values]
    for a, b, va, vb in zip(rows, rows[1:], values, values[1:]):
        if not a or not b:
            continue
        for name in a:
            x, y = a[name], b[name]
            load_ratio = max(x[0], y[0]) / min(x[0], y[0])
            mass_ratio = max(x[1], y[1]) / max(1e-9, min(x[1], y[1]))
            if load_ratio <= 1.5 and mass_ratio <= 1.5:
                continue
            jumps += 1
            sense = (x[2] > 0) != (y[2] > 0)
            side = (abs(x[2]) > 1.5708) != (abs(y[2]) > 1.5708)
            place = x[3] != y[3]
            explained += sense or side or place
            marks = ' '.join(m for m, on in (('SENSE', sense), ('CLASS', side), ('PLACE', place)) if on)
            print(f'{sweep} {va:.2f}->{vb:.2f} {name} load x{load_ratio:.2f} mass x{mass_ratio:.2f} '
                  f'rotation {x[2]:+.2f}->{y[2]:+.2f} {marks}')
print(f'{jumps} jumps above 1.5x, {explained} with a change of sense, side of 90 deg or pivot place')
