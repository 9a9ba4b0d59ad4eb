#!/usr/bin/env python3
"""Small input sweeps on a scene: each variant studied, every figure compared with the base.

Usage: sweep.py FLAPWRIGHT_BINARY SCENE.toml BASE_STUDY_DIR OUT_DIR

Variants (text edits of the scene, written to OUT_DIR): every flap's landing_deg +/-0.2 deg,
and the `axis_offset_m` of the stations named in STATIONS +/-0.05 m. Each variant is run
with `BINARY study VARIANT --out OUT_DIR/<variant>`, tabulated with extract.py, and every
kind x station figure (peak actuator load, travel, lead or gear ratio, fairing depth and
length, sized member mass) is compared with the base study; a ratio above 2 or below 0.5,
or a clearance verdict that changes, is flagged.
"""
import json
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
STATIONS = ("track-1", "track-3")
KEYS = [("peak_load", "load"), ("travel", "travel"), ("lead_m", "lead"), ("gear_ratio", "gear"),
        ("fairing_depth_pct", "depth%"), ("fairing_length_pct", "length%"), ("members_mass_kg", "mass")]


def rows(scene, study, out):
    """extract.py's rows of one study, written to `out` (outside the study folder, which
    Flapwright replaces only when it holds its own files alone)."""
    subprocess.run([sys.executable, str(HERE / "extract.py"), str(scene), str(study), "--json", str(out)], check=True)
    return {(r["kind"], r["station"]): r for r in json.loads(out.read_text())}


def main():
    binary, scene, base_study, out_dir = sys.argv[1:5]
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    text = Path(scene).read_text()
    variants = {}
    landing = re.findall(r"landing_deg = ([0-9.]+)", text)
    for d in (-0.2, +0.2):
        variants[f"landing{d:+.1f}deg"] = re.sub(r"landing_deg = ([0-9.]+)", lambda m: f"landing_deg = {float(m.group(1)) + d:.1f}", text)
    for st in STATIONS:
        m = re.search(r'name = "%s"\nflap = "[^"]+"\naxis_offset_m = ([0-9.]+)' % re.escape(st), text)
        for d in (-0.05, +0.05):
            new = f"{float(m.group(1)) + d:.2f}"
            variants[f"{st}{d:+.2f}m"] = text[: m.start(1)] + new + text[m.end(1):]
    base = rows(scene, base_study, out_dir / "base.rows.json")
    for name, body in variants.items():
        path = out_dir / f"{name}.toml"
        path.write_text(body)
        study = out_dir / name
        subprocess.run([binary, "--quiet", "study", str(path), "--out", str(study)], check=True)
        var = rows(path, study, out_dir / f"{name}.rows.json")
        print(f"## {name}")
        for key, r in var.items():
            b = base[key]
            flags = []
            for k, lab in KEYS:
                if r.get(k) is None or b.get(k) is None:
                    continue
                x, y = abs(r[k]), abs(b[k])
                ratio = x / y if y else float("inf")
                if ratio > 2 or ratio < 0.5:
                    flags.append(f"{lab} x{ratio:.2f} ({y:.4g} -> {x:.4g})")
            if r["clears"] != b["clears"]:
                flags.append(f"clears {'yes' if b['clears'] else 'no'} -> {'yes' if r['clears'] else 'no'}")
            if flags:
                print(f"- {key[0]} at {key[1]}: " + "; ".join(flags))


if __name__ == "__main__":
    main()
