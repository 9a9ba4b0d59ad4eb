"""The Python call's overhead over the same design in Rust (issue 39: under 5 %).

Usage (after `pip install .`): python python/bench/overhead.py [SCENE] [REPEATS]

Times, alternately in one process, `flapwright.design(SCENE)` (the Rust design, its report
as JSON, `json.loads` and the `Record`s) and the Rust design alone
(`flapwright._native.design_seconds`, no report JSON); prints both medians and the
overhead of the Python call in per cent. Default: the small aircraft, 21 repeats.
"""
import os, statistics, sys, time

import flapwright
from flapwright import _native

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
scene = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "data", "scenes", "small-aircraft.toml")
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 21
text = open(scene, encoding="utf-8").read()
folder = os.path.dirname(os.path.abspath(scene))
python_s, rust_s = [], []
flapwright.design(scene)  # warm up (the airfoils, the allocator)
for _ in range(repeats):
    start = time.perf_counter()
    flapwright.design(scene)
    python_s.append(time.perf_counter() - start)
    rust_s.extend(_native.design_seconds(text, scene, folder, 1))
p, r = statistics.median(python_s), statistics.median(rust_s)
print(f"{os.path.basename(scene)}: Python call {p * 1e3:.1f} ms, Rust alone {r * 1e3:.1f} ms (medians of {repeats}): overhead {100 * (p - r) / r:.1f} %")
