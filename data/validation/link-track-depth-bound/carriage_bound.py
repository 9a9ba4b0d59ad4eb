"""Lower bound on a link-track's fairing depth from its carriage alone.

For each track direction (every 0.1 deg) the carriage point whose three precision
positions lie on one line along it (two linear equations) must run from its stowed place
to its landing place along the track, in order (take-off between). The track beam is fixed
and the carriage passes every point of it, so the fairing is at least as deep as the
segment [C0, C_landing] (below the stowed sections' lower contour), plus the carriage's
radius. Admissible: C0 and C_landing outside the wing section and the segment not crossing
it. Inputs: a link-track report.json of `flapwright study` (for the precision positions and
the station's sections)."""
import sys, numpy as np
from poses import load
from checks import seg_hits_poly, inside, depth_below
poses, polys, s = load(sys.argv[1])
nut = s['mechanism']['details']['hardware']['nut_radius_m']
wing = polys['wing'][0]; flap = polys['outboard'][0]
cf = flap[:, 0].max() - flap[:, 0].min()
depth = depth_below((wing, flap), 8001)
best = None; admissible = 0
for k in range(3600):
    a = np.radians(k / 10); d = np.array([np.cos(a), np.sin(a)]); m = np.array([d[1], -d[0]])
    M = np.array([(R - np.eye(2)).T @ m for R, t, _ in poses]); rhs = np.array([-m @ t for R, t, _ in poses])
    if abs(np.linalg.det(M)) < 1e-12: continue
    c = np.linalg.solve(M, rhs)
    tr = [d @ (R @ c + t - c) for R, t, _ in poses]
    if not (tr[0] > 0 and tr[1] > tr[0]): continue
    cl = c + d * tr[1]
    if inside(wing, c) or inside(wing, cl) or seg_hits_poly(c, cl, wing): continue
    admissible += 1
    dep = max(depth(c + (cl - c) * u) for u in np.linspace(0, 1, 201)) + nut
    if best is None or dep < best[0]: best = (dep, k / 10, c, cl)
dep, ang, c, cl = best
print(f"{sys.argv[1]}: {admissible} admissible track directions of 3600; shallowest carriage "
      f"{dep:.3f} m = {100*dep/cf:.1f} % c_f (direction {ang:.1f} deg, C0 {np.round(c,3)}, C_landing {np.round(cl,3)})")
