"""Continuity sweep of issue 37 on transport-flap.toml (reduced resolution).

Usage: python3 sweep.py BINARY WORKDIR [--full] [--only landing,gap,offset] [--design key=value ...] [study options, e.g. --kinds hooked-track]

Runs `BINARY study` on variants of data/scenes/transport-flap.toml: both flaps' landing
deflection 34-36 deg by 0.2 deg, both flaps' landing gap 1.5-2.5 %c by 0.1, and
ob-inner's axis_offset_m 1.4-1.6 m by 0.02 m (the issue asks 0.1 deg, 0.05 %c and 0.01 m:
this is half the resolution; `--full` takes the issue's steps). Prints per sweep, kind and station the largest ratio of the
peak actuator load and of the mechanism mass between neighbouring steps (with where), and
the clearance verdict of every step (y/n, - where the kind was not designed), how many
neighbouring steps change the topology the study states (`topology`: the hooked-track's,
the link-track's and the four-bar's), and the largest ratio (load or mass) between neighbours of one
topology, which the report does not explain.
"""
import json, os, re, subprocess, sys

BIN = sys.argv[1]; WORK = sys.argv[2]
ARGS = sys.argv[3:]
FULL = '--full' in ARGS
# `--only landing,gap` runs those sweeps alone (all three by default).
ONLY = None
if '--only' in ARGS:
    i = ARGS.index('--only'); ONLY = ARGS[i + 1].split(','); ARGS = ARGS[:i] + ARGS[i + 2:]
# `--design key=value` (repeatable) adds a `[design]` key to every variant.
DESIGN = []
while '--design' in ARGS:
    i = ARGS.index('--design'); DESIGN.append(ARGS[i + 1]); ARGS = ARGS[:i] + ARGS[i + 2:]
EXTRA = [a for a in ARGS if a != '--full']
TAG = 'v'
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
os.makedirs(WORK, exist_ok=True)
base = open(os.path.join(ROOT, 'data/scenes/transport-flap.toml')).read()
def variant(kind, value):
    s = base
    if kind == 'landing':
        s = s.replace('landing_deg = 35.0', f'landing_deg = {value:.2f}')
    elif kind == 'gap':
        s = re.sub(r'landing_gap_percent = [0-9.]+', f'landing_gap_percent = {value:.3f}', s)
    elif kind == 'offset':
        s = s.replace('axis_offset_m = 1.5\n', f'axis_offset_m = {value:.3f}\n', 1)
    if DESIGN:
        s += '\n[design]\n' + ''.join(f'{d}\n' for d in DESIGN)
    return s
def run(kind, value):
    path = os.path.join(WORK, f'{TAG}-{kind}-{value:.3f}')
    open(path + '.toml', 'w').write(variant(kind, value))
    subprocess.run(['rm', '-rf', path]); subprocess.run([BIN, 'study', path + '.toml', '--out', path, '--quiet'] + EXTRA, capture_output=True)
    try: r = json.load(open(path + '/study.json'))
    except Exception: return {}
    out = {}
    for k in r['kinds']:
        for s in k['stations']:
            if s.get('max_actuator_load') is None: continue
            out[(k['kind'], s['station'])] = (s['max_actuator_load'], s['mechanism_mass_kg'], s['clearance_passes'],
                                              json.dumps(s.get('topology'), sort_keys=True))
    return out
# Half the resolution by default; `--full` takes the issue's own steps.
STEPS = 21 if FULL else 11
sweeps = {kind: [start + (stop - start) * i / (STEPS - 1) for i in range(STEPS)]
          for kind, start, stop in (('landing', 34.0, 36.0), ('gap', 1.5, 2.5), ('offset', 1.4, 1.6))}
for kind, values in sweeps.items():
    if ONLY and kind not in ONLY: continue
    rows = [run(kind, v) for v in values]
    keys = sorted(set().union(*[r.keys() for r in rows]))
    for key in keys:
        worst = (1.0, None); worstm = (1.0, None)
        # The largest ratio between neighbours of one topology (the study's `topology`,
        # where the kind states one): a jump the report does not explain.
        same = 1.0
        for a, b, va, vb in zip(rows, rows[1:], values, values[1:]):
            if key in a and key in b:
                for idx, w in ((0, 'load'), (1, 'mass')):
                    x, y = a[key][idx], b[key][idx]
                    if x > 0 and y > 0:
                        ratio = max(x / y, y / x)
                        if idx == 0 and ratio > worst[0]: worst = (ratio, (va, vb, x, y))
                        if idx == 1 and ratio > worstm[0]: worstm = (ratio, (va, vb, x, y))
                        if a[key][3] == b[key][3]: same = max(same, ratio)
        clears = ''.join('y' if (key in r and r[key][2]) else ('n' if key in r else '-') for r in rows)
        changes = sum(1 for a, b in zip(rows, rows[1:]) if key in a and key in b and a[key][3] != b[key][3])
        print(kind, key[0], key[1], f'load x{worst[0]:.2f}', worst[1] and f'{worst[1][0]:.2f}->{worst[1][1]:.2f}: {worst[1][2]/1e3:.1f}->{worst[1][3]/1e3:.1f}', f'mass x{worstm[0]:.2f}', clears,
              f'topology changes {changes}, within one topology x{same:.2f}', flush=True)
