#!/usr/bin/env python3
"""Tabulate a `flapwright study` folder against each station's air load.

Usage: extract.py SCENE.toml STUDY_DIR [--json OUT.json] [--md]

Reads STUDY_DIR/study.json and STUDY_DIR/<kind>/report.json (written by
`flapwright study SCENE --out STUDY_DIR`) and the scene file. The air load per station is
computed here, independently of the tool's load model: the flap planform area
(streamwise flap chord x dy, chord fraction linear along each flap, wing chord linear
between sections, between the flap's sides, which stand `side_gap_m` in from the
nominal span ends) is split between a flap's stations by the lever rule along y (spans
between stations simply supported, each overhang wholly to its end station), and
    N = C_N(landing deflection) q S,   q = 0.5 rho V^2,
the design load n N with the load case's load factor n. Station y comes from the scene
too: the hinge line through `chord_fraction` of the local chord at the flap's ends (the
leading edge from the panels' sweep and dihedral; twist and the depth below the chord
line ignored), the station `axis_offset_m` along it from the flap's inboard side.
"""
import json
import math
import sys
import tomllib
from pathlib import Path


def interp(xs, ys, x):
    if x <= xs[0]:
        return ys[0]
    for (x0, y0), (x1, y1) in zip(zip(xs, ys), zip(xs[1:], ys[1:])):
        if x <= x1:
            return y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    return ys[-1]


class Wing:
    def __init__(self, scene):
        w = scene["wing"]
        self.secs = w["sections"]
        self.panels = w["panels"]
        self.ys = [s["y_m"] for s in self.secs]
        self.cs = [s["chord_m"] for s in self.secs]
        le = list(w["root_leading_edge_m"])
        self.le = [le]
        for s0, s1, p in zip(self.secs, self.secs[1:], self.panels):
            dy = s1["y_m"] - s0["y_m"]
            x, _, z = self.le[-1]
            if w.get("sweep_reference", "leading-edge") == "quarter-chord":
                x1 = x + 0.25 * s0["chord_m"] + dy * math.tan(math.radians(p["sweep_deg"])) - 0.25 * s1["chord_m"]
            else:
                x1 = x + dy * math.tan(math.radians(p["sweep_deg"]))
            z1 = z + dy * math.tan(math.radians(p.get("dihedral_deg", 0.0)))
            self.le.append([x1, s1["y_m"], z1])

    def chord(self, y):
        return interp(self.ys, self.cs, y)

    def le_at(self, y):
        return [interp(self.ys, [p[i] for p in self.le], y) for i in (0, 2)]


def side_gaps(f, wing):
    """The flap's sides stand `side_gap_m` (default 0.5 % of the local chord) in from its
    nominal span ends; the tool measures `axis_offset_m` from the inboard side."""
    g = f.get("side_gap_m")
    gi = g if g is not None else 0.005 * wing.chord(f["y_inboard_m"])
    go = g if g is not None else 0.005 * wing.chord(f["y_outboard_m"])
    return f["y_inboard_m"] + gi, f["y_outboard_m"] - go


def station_ys(scene, wing):
    out = {}
    flaps = {f["name"]: f for f in scene["flap"]}
    for st in scene["station"]:
        f = flaps[st["flap"]]
        cf = f.get("hinge", {}).get("chord_fraction")
        pts = []
        for y in side_gaps(f, wing):
            x, z = wing.le_at(y)
            pts.append((x + (cf if cf is not None else 0.8) * wing.chord(y), y, z))
        d = [b - a for a, b in zip(*pts)]
        L = math.sqrt(sum(v * v for v in d))
        out[st["name"]] = pts[0][1] + st["axis_offset_m"] * d[1] / L
    return out


def area_shares(scene, wing, sty, steps=4000):
    shares = {}
    for f in scene["flap"]:
        sts = sorted([(sty[s["name"]], s["name"]) for s in scene["station"] if s["flap"] == f["name"]])
        y0, y1 = side_gaps(f, wing)
        total = 0.0
        acc = {n: 0.0 for _, n in sts}
        dy = (y1 - y0) / steps
        for i in range(steps):
            y = y0 + (i + 0.5) * dy
            t = (y - f["y_inboard_m"]) / (f["y_outboard_m"] - f["y_inboard_m"])
            cfr = f["chord_fraction_inboard"] + t * (f["chord_fraction_outboard"] - f["chord_fraction_inboard"])
            dA = cfr * wing.chord(y) * dy
            total += dA
            if len(sts) == 1 or y <= sts[0][0]:
                acc[sts[0][1]] += dA
            elif y >= sts[-1][0]:
                acc[sts[-1][1]] += dA
            else:
                for (ya, na), (yb, nb) in zip(sts, sts[1:]):
                    if ya <= y <= yb:
                        w = (yb - y) / (yb - ya)
                        acc[na] += w * dA
                        acc[nb] += (1 - w) * dA
                        break
        for n, a in acc.items():
            shares[n] = (a, f["name"], total)
    return shares


def peak_load(mech):
    best = (0.0, None, None)
    for lc in mech["load_cases"]:
        for s in lc["samples"]:
            if abs(s["actuator_load"]) > abs(best[0]):
                best = (s["actuator_load"], s["deflection_deg"], lc["load_case"])
    return best


def main():
    scene_path, study_dir = Path(sys.argv[1]), Path(sys.argv[2])
    scene = tomllib.loads(scene_path.read_text())
    wing = Wing(scene)
    sty = station_ys(scene, wing)
    shares = area_shares(scene, wing, sty)
    lc = scene["loads"]["cases"][0]
    q = lc.get("dynamic_pressure_pa") or 0.5 * lc["density_kgpm3"] * lc["speed_mps"] ** 2
    n = lc.get("load_factor", 1.0)
    table = lc["normal_force_coefficient"]
    flaps = {f["name"]: f for f in scene["flap"]}
    study = json.loads((study_dir / "study.json").read_text())
    rows = []
    for k in study["kinds"]:
        kind = k["kind"]
        rep_path = study_dir / kind / "report.json"
        rep = json.loads(rep_path.read_text()) if rep_path.exists() else None
        for ks in k["stations"]:
            name = ks["station"]
            row = {"scene": scene["name"], "kind": kind, "station": name}
            if "reason" in ks and ks.get("max_actuator_load") is None:
                row["failed"] = ks.get("reason")
                rows.append(row)
                continue
            st = next(s for s in rep["stations"] if s["name"] == name)
            mech = st["mechanism"]
            flap = flaps[st["flap"]]
            delta_l = flap["settings"]["landing_deg"]
            cn = interp([r[0] for r in table], [r[1] for r in table], delta_l)
            S, _, flap_area = shares[name]
            N1 = cn * q * S
            load, at_deg, case = peak_load(mech)
            inp = mech["input"]
            travel = inp["deployed"] - inp["stowed"]
            act = mech["actuator"]
            rods = [r for r in rep["sizing"]["rods"] if r["station"] == name]
            screw = [r for r in rods if r["name"] == "screw"]
            members = [r for r in rods if r["name"] != "screw"]
            jacks = [j for j in rep["sizing"]["screw_jacks"] if j["station"] == name]
            fair = st["fairing"]
            flap_chord = fair["depth_m"] / (fair["depth_percent_flap_chord"] / 100) if fair["depth_percent_flap_chord"] else None
            fails = []
            for p in rep["interference"]["pairs"]:
                if p["passes"]:
                    continue
                a, b = p["part_a"], p["part_b"]
                mine = a.startswith(name + ".") or b.startswith(name + ".") or name in p.get("station", "").split("/")
                flap_level = (a == st["flap"] or b == st["flap"]) and not ("." in a or "." in b)
                if mine or flap_level:
                    fails.append({"pair": f"{a} / {b}", "clearance_mm": round(1000 * p["min_clearance_m"], 1),
                                  "penetration_mm": round(1000 * p["penetration_m"], 1),
                                  "at": round(p["at_parameter"], 3), "flap_level": flap_level and not mine})
            joints = [c for c in rep["interference"]["declared_contacts"] if not c["passes"] and c.get("station") == name]
            share_tool = mech["flap_load_share"]["flap_area_share_m2"]
            theta = math.radians(delta_l)
            row.update({
                "actuator": act["type"],
                "input": inp["quantity"],
                "travel": travel,
                "lead_m": act.get("screw", {}).get("lead_m"),
                "gear_ratio": act.get("gear_ratio"),
                "mean_arm_m_per_rad": travel / theta if inp["quantity"] == "stroke" else None,
                "input_per_flap_rad": travel / theta if inp["quantity"] == "angle" else None,
                "peak_load": load, "peak_at_deg": at_deg, "peak_case": case,
                "study_max_load": ks["max_actuator_load"],
                "fairing_depth_m": fair["depth_m"], "fairing_depth_pct": fair["depth_percent_flap_chord"],
                "fairing_length_m": fair.get("length_m"), "fairing_length_pct": fair.get("length_percent_flap_chord"),
                "fairing_part": fair["part"], "flap_chord_m": flap_chord,
                "members_mass_kg": sum(r["mass_kg"] for r in members),
                "members": {r["name"]: [r["governing"], round(r["radius_m"] * 1000, 1), round(r["mass_kg"], 2)] for r in members},
                "screw_mass_kg": sum(r["mass_kg"] for r in screw) if screw else None,
                "study_mass_kg": ks["mechanism_mass_kg"],
                "motor_torque_nm": jacks[0]["motor_torque_nm"] if jacks else None,
                "self_locking": jacks[0]["self_locking"] if jacks else None,
                "clears": ks["clearance_passes"], "fails": fails, "joints_apart": len(joints),
                "misses": [(m["setting"], round(m["gap_miss_percent_chord"], 2), round(m["overlap_miss_percent_chord"], 2)) for m in ks["setting_misses"]],
                "mu_deg": ks.get("transmission_angle_deg"),
                "area_share_m2": S, "area_share_tool_m2": share_tool, "flap_area_m2": flap_area,
                "station_y_m": sty[name], "station_y_tool_m": st["plane"]["frame"]["origin_m"][1],
                "cn": cn, "q_pa": q, "n": n, "air_load_n": N1, "design_air_load_n": n * N1,
                "ratio_to_design_air_load": abs(load) / (n * N1),
            })
            rows.append(row)
    if "--json" in sys.argv:
        Path(sys.argv[sys.argv.index("--json") + 1]).write_text(json.dumps(rows, indent=1))
    if "--md" in sys.argv:
        print("| station | kind | S m² (tool) | n C_N q S kN | peak load | at deg | ratio | travel | lead mm / gear | arm m/rad | depth % c_f (m) | length % c_f | members kg | screw kg | clears | failing pairs | TO miss gap/ovl %c | LD miss |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            if "failed" in r:
                print(f"| {r['station']} | {r['kind']} | not designed: {r['failed']} |")
                continue
            unit = "kN" if r["input"] == "stroke" else "kN m"
            trav = f"{1000*r['travel']:.0f} mm" if r["input"] == "stroke" else f"{math.degrees(r['travel']):.1f} deg"
            lg = f"{1000*r['lead_m']:.2f} mm" if r["lead_m"] is not None else f"{r['gear_ratio']:.0f}:1"
            arm = f"{r['mean_arm_m_per_rad']:.3f}" if r["mean_arm_m_per_rad"] is not None else f"link {r['input_per_flap_rad']:.2f} rad/rad"
            ratio = f"{r['ratio_to_design_air_load']:.2f}" + ("" if r["input"] == "stroke" else " m")
            fl = "; ".join(f"{f['pair']} {'pen ' + str(f['penetration_mm']) + ' mm' if f['penetration_mm'] else str(f['clearance_mm']) + ' mm'}" for f in r["fails"]) or "-"
            mis = {m[0]: m for m in r["misses"]}
            to = mis.get("takeoff"); ld = mis.get("landing")
            screw = f"{r['screw_mass_kg']:.2f}" if r["screw_mass_kg"] is not None else "-"
            print(f"| {r['station']} | {r['kind']} | {r['area_share_m2']:.2f} ({r['area_share_tool_m2']:.2f}) | {r['design_air_load_n']/1000:.1f} | {abs(r['peak_load'])/1000:.1f} {unit} | {r['peak_at_deg']:.1f} | {ratio} | {trav} | {lg} | {arm} | {r['fairing_depth_pct']:.1f} ({r['fairing_depth_m']:.3f}) | {r['fairing_length_pct']:.0f} | {r['members_mass_kg']:.1f} | {screw} | {'yes' if r['clears'] else 'no'} | {fl} | {to[1]:+.1f}/{to[2]:+.1f} | {ld[1]:+.1f}/{ld[2]:+.1f} |")


if __name__ == "__main__":
    main()
