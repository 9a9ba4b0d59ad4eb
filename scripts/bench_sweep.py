"""Issue 39's sweep bench: `flapwright sweep` against separate `flapwright design` processes.

Usage: python3 scripts/bench_sweep.py BINARY WORKDIR [--step 0.005] [--jobs 2]

Sweeps `data/scenes/transport-flap.toml`'s landing gap (both flaps) from 1.5 to 2.5 %c by
STEP, once with `flapwright sweep` (every core, the wing shared) and once as one
`flapwright design` process per variant, JOBS at a time, on variant files written here by
editing the gap lines. Prints the wall time and variants per minute of each, their ratio,
and checks that the sweep's table equals the one gathered here from the separate reports
(the same figures, read from each report.json independently of the library: deepest and
longest fairing, largest actuator load and peak power, summed work and mass, largest
setting miss, smallest clearance, warnings count and verdict; to 1e-12 relative).
Run it on an idle machine; it takes minutes (a transport design takes 1-3 s).
"""
import concurrent.futures, csv, json, os, re, subprocess, sys, time

BIN = os.path.abspath(sys.argv[1]); WORK = os.path.abspath(sys.argv[2])
ARGS = sys.argv[3:]
STEP = float(ARGS[ARGS.index('--step') + 1]) if '--step' in ARGS else 0.005
JOBS = int(ARGS[ARGS.index('--jobs') + 1]) if '--jobs' in ARGS else 2
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, 'data/scenes/transport-flap.toml')
os.makedirs(WORK, exist_ok=True)

count = round((2.5 - 1.5) / STEP) + 1
gaps = [round(1.5 + STEP * k, 12) for k in range(count)]

# The sweep.
subprocess.run(['rm', '-rf', os.path.join(WORK, 'sweep')])
start = time.time()
subprocess.run([BIN, 'sweep', SCENE, '--out', os.path.join(WORK, 'sweep'), '--quiet',
                '--vary', f'flap[*].settings.landing_gap_percent=1.5:2.5:{STEP}'], check=True)
sweep_s = time.time() - start
with open(os.path.join(WORK, 'sweep', 'sweep.csv')) as f:
    table = list(csv.DictReader(f))

# The separate designs.
text = open(SCENE).read()
def design(k):
    path = os.path.join(WORK, f'variant-{k}')
    variant = re.sub(r'landing_gap_percent = [0-9.]+', f'landing_gap_percent = {gaps[k]!r}', text)
    open(path + '.toml', 'w').write(variant)
    subprocess.run(['rm', '-rf', path])
    done = subprocess.run([BIN, 'design', path + '.toml', '--out', path, '--quiet'], capture_output=True)
    return k, done.returncode
start = time.time()
with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
    codes = dict(pool.map(design, range(count)))
separate_s = time.time() - start

def figures(k):
    r = json.load(open(os.path.join(WORK, f'variant-{k}', 'report.json')))
    stations = r['stations']
    per_station = {m['station']: m['mass_kg'] for m in r['sizing']['masses']['per_station']}
    loads, powers, works = [], [], []
    for s in stations:
        mech = s['mechanism']
        speed = mech['actuator']['nominal_speed_mps'] if 'nominal_speed_mps' in mech['actuator'] else mech['actuator']['nominal_speed_radps']
        peak = 0.0; work = 0.0
        for case in mech['load_cases']:
            samples = case['samples']
            peak = max([peak] + [abs(x['actuator_load']) for x in samples])
            w = sum(0.5 * (a['actuator_load'] + b['actuator_load']) * (b['input'] - a['input']) for a, b in zip(samples, samples[1:]))
            work = max(work, abs(w))
        loads.append(peak); powers.append(peak * speed); works.append(work)
    misses = [max(abs(m['gap_miss_percent_chord']), abs(m.get('overlap_miss_percent_chord') or 0.0))
              for s in stations for m in s['flap_position']['settings'] if m.get('gap_miss_percent_chord') is not None]
    return {
        'fairing_depth_percent_flap_chord': max(s['fairing']['depth_percent_flap_chord'] for s in stations),
        'fairing_length_percent_flap_chord': max(s['fairing']['length_percent_flap_chord'] for s in stations),
        'max_actuator_load': max(loads), 'peak_power_w': max(powers), 'work_per_deployment_j': sum(works),
        'mechanism_mass_kg': sum(per_station.get(s['name'], 0.0) for s in stations),
        'max_setting_miss_percent_chord': max(misses) if misses else 0.0,
        'min_clearance_m': min(p['min_clearance_m'] for p in r['interference']['pairs']),
        'warnings': len(r['warnings']),
        'verdict': 'pass' if r['interference']['passes'] else 'fail',
    }

mismatches = 0
for k in range(count):
    row = table[k]
    if codes[k] != 0:
        if row['verdict'] != 'error':
            mismatches += 1; print(f'variant {k}: design failed ({codes[k]}), sweep says {row["verdict"]}')
        continue
    want = figures(k)
    for key, value in want.items():
        got = row[key]
        ok = (got == value) if isinstance(value, str) else (
            int(got) == value if isinstance(value, int) else abs(float(got) - value) <= 1e-12 * max(abs(value), 1.0))
        if not ok:
            mismatches += 1; print(f'variant {k} {key}: sweep {got}, separate {value}')

print(f'{count} variants of transport-flap (landing gap 1.5-2.5 %c by {STEP})')
print(f'sweep:    {sweep_s:.1f} s, {count / sweep_s * 60:.1f} variants a minute')
print(f'separate: {separate_s:.1f} s, {count / separate_s * 60:.1f} variants a minute ({JOBS} at a time)')
print(f'ratio: {separate_s / sweep_s:.2f}x; table {"equal" if mismatches == 0 else f"differs in {mismatches} cells"}')
