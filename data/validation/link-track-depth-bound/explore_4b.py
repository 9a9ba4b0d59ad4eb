"""Four-bars through the three precision positions on a grid of moving pivots (relaxed
rules), for the fairing-depth question: is any four-bar shallower than the dropped hinge?
Moving pivots: 30 chordwise x 12 depths (0-60 % c_f below the flap's lower surface, or
inside the flap); fixed pivot = centre of the three positions; fixed pivots in the wing or
below the lower contour; crank = first link; the loop sampled (97) on one branch through
take-off and landing in order; transmission angle >= 30 deg; the flap >= 9 mm from the
wing's trailing edge; pins never in the wing; links not through the wing (outside pivots).
Usage: explore_4b.py LINK_TRACK_REPORT.json (for the poses and sections)."""
import sys, numpy as np
from poses import load
from checks import seg_hits_poly, inside, dist_pt_poly, depth_below
poses, polys, s = load(sys.argv[1])
wing = polys['wing'][0]; flap = polys['outboard'][0]
cf = flap[:, 0].max() - flap[:, 0].min(); le = flap[:, 0].max()
LIPC = float(sys.argv[2]) if len(sys.argv) > 2 else 0.009
LIP = np.array(s['flap_position']['trailing_edge_st_m'])
def span_at(P, x):
    a = P; b = np.roll(P, -1, axis=0)
    m = ((a[:, 0] - x) * (b[:, 0] - x) <= 0) & (a[:, 0] != b[:, 0])
    ys = a[m, 1] + (b[m, 1] - a[m, 1]) * (x - a[m, 0]) / (b[m, 0] - a[m, 0])
    return (ys.min(), ys.max()) if len(ys) else None
depth = depth_below((wing, flap))
rot = lambda t: np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
def centre(a):
    pts = [a] + [R @ a + t for R, t, _ in poses]
    (x1, y1), (x2, y2), (x3, y3) = pts
    d = 2 * (x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2))
    if abs(d) < 1e-12: return None
    ux = ((x1**2 + y1**2) * (y2 - y3) + (x2**2 + y2**2) * (y3 - y1) + (x3**2 + y3**2) * (y1 - y2)) / d
    uy = ((x1**2 + y1**2) * (x3 - x2) + (x2**2 + y2**2) * (x1 - x3) + (x3**2 + y3**2) * (x2 - x1)) / d
    return np.array([ux, uy])
def turn(o, a, b):
    u = a - o; v = b - o; return np.arctan2(u[0] * v[1] - u[1] * v[0], u @ v)
cands = []
for i in range(30):
    x = le - cf * (0.02 + 0.93 * i / 29)
    sp = span_at(flap, x)
    if not sp: continue
    for j in range(12):
        y = sp[0] - cf * (-0.03 + 0.63 * j / 11)
        a = np.array([x, y]); o = centre(a)
        if o is None: continue
        if not (inside(wing, o) or (depth(o) > 0 and not inside(flap, o))): continue
        tu = [turn(o, a, R @ a + t) for R, t, _ in poses]
        if not (tu[0] * tu[1] > 0 and abs(tu[0]) < abs(tu[1]) < np.radians(150)): continue
        cands.append((a, o, tu))
print(len(cands), 'moving-pivot candidates')
found = []; why = {}
for a1, o1, tu in cands:
    for a2, o2, _ in cands:
        if np.linalg.norm(a2 - a1) < 0.1 * cf: continue
        l2 = np.linalg.norm(a2 - o2); cpl = np.linalg.norm(a2 - a1)
        prev = a2; ok = True; mu_min = 9; dep = max(depth(o1), depth(o2), 0); reason = ''
        hits = []
        for k in range(97):
            ph = tu[1] * k / 96
            A1 = o1 + rot(ph) @ (a1 - o1)
            d = np.linalg.norm(A1 - o2)
            if d > l2 + cpl or d < abs(l2 - cpl) or d == 0: ok = False; reason = 'no closure'; break
            aa = (cpl**2 - l2**2 + d**2) / (2 * d); h = np.sqrt(max(cpl**2 - aa**2, 0))
            u = (o2 - A1) / d; base = A1 + aa * u; perp = np.array([-u[1], u[0]])
            c1, c2 = base + h * perp, base - h * perp
            A2 = c1 if np.linalg.norm(c1 - prev) <= np.linalg.norm(c2 - prev) else c2
            if np.linalg.norm(A2 - prev) > 0.2 * cf: ok = False; reason = 'branch'; break
            prev = A2
            uc = (A2 - A1) / cpl; ur = (A2 - o2) / l2
            mu = np.arcsin(min(1, abs(uc[0] * ur[1] - uc[1] * ur[0]))); mu_min = min(mu_min, mu)
            v0 = a2 - a1; v1 = A2 - A1; th = np.arctan2(v0[0] * v1[1] - v0[1] * v1[0], v0 @ v1)
            F = (rot(th) @ (flap - a1).T).T + A1
            if inside(F, LIP) or dist_pt_poly(F, LIP) < LIPC: ok = False; reason = 'lip'; break
            if inside(wing, A1) or inside(wing, A2): ok = False; reason = 'pin in wing'; break
            if (not inside(wing, o1) and seg_hits_poly(o1, A1, wing)) or (not inside(wing, o2) and seg_hits_poly(o2, A2, wing)):
                ok = False; reason = 'link in wing'; break
            dep = max(dep, depth(A1), depth(A2))
            hits.append(A2)
        if ok:
            # Settings on this branch: take-off and landing at their crank turns.
            for (R, t, _), tt in zip(poses, tu):
                k = tt / tu[1] * 96
                if abs(k - round(k)) > 1e-9: pass
            land = hits[-1]; R, t, _ = poses[1]
            if np.linalg.norm(land - (R @ a2 + t)) > 1e-6: ok = False; reason = 'other branch'
        if ok and np.degrees(mu_min) < 30: ok = False; reason = 'transmission'
        why[reason] = why.get(reason, 0) + 1
        if ok: found.append((100 * dep / cf, np.degrees(mu_min), a1, o1, a2, o2))
found.sort(key=lambda r: r[0])
print('first failures:', why)
for r in found[:8]:
    print('%.1f%% mu %.0f A1 %s O1 %s A2 %s O2 %s' % (r[0], r[1], np.round(r[2], 3), np.round(r[3], 3), np.round(r[4], 3), np.round(r[5], 3)))
