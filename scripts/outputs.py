#!/usr/bin/env python3
"""Snapshot and compare every file Flapwright writes on the shipped scenes.

    scripts/outputs.py snapshot BINARY DIR   # design, check, export and study on every
                                             # scene in data/scenes (and the embedded default)
    scripts/outputs.py compare DIR_A DIR_B   # byte for byte, `timings` apart

Made for moves that must not change outputs (issue 36: the library split): take a snapshot
with the binary before the change, another after, and compare. JSON files are compared
with their `timings` keys (at any depth) removed and everything else byte for byte; in a
manifest (`.flapwright-manifest.json`), the size and hash of a JSON file that holds timings
(`report.json`, `study.json`, a nested manifest) are left out, its name kept; every other file
byte for byte. Exit status 1 when any file differs or is missing on one side.
"""
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
COMMANDS = ("design", "check", "export", "study")


def snapshot(binary: str, out: pathlib.Path) -> None:
    scenes = [None] + sorted(ROOT.glob("data/scenes/*.toml"))
    for scene in scenes:
        name = "default" if scene is None else scene.stem
        # Relative output paths (run inside the snapshot), so that messages naming them
        # read the same in two snapshots.
        folder = out / name
        folder.mkdir(parents=True, exist_ok=True)
        for command in COMMANDS:
            args = [str(pathlib.Path(binary).resolve()), "--quiet", command]
            if scene is not None:
                args.append(str(scene))
            args += ["--out", command]
            if command == "check":
                args += ["--junit", "check.junit.xml"]
            result = subprocess.run(args, capture_output=True, text=True, cwd=folder)
            # The repository's own path, where a message names the scene, as `<repo>`: two
            # checkouts (worktrees) give the same snapshot.
            status = f"exit {result.returncode}\n--- stdout\n{result.stdout}--- stderr\n{result.stderr}"
            (folder / f"{command}.status").write_text(status.replace(str(ROOT), "<repo>"))


MANIFEST = ".flapwright-manifest.json"
TIMED = ("report.json", "study.json", MANIFEST)


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k != "timings"}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def without_timed_hashes(manifest):
    for entry in manifest.get("files", []):
        if entry.get("path", "").rsplit("/", 1)[-1] in TIMED:
            entry.pop("sha256", None)
            entry.pop("bytes", None)
    return manifest


def same(a: pathlib.Path, b: pathlib.Path) -> bool:
    left, right = a.read_bytes(), b.read_bytes()
    if left == right:
        return True
    if a.suffix == ".json":
        try:
            left, right = without_timings(json.loads(left)), without_timings(json.loads(right))
        except ValueError:
            return False
        if a.name == MANIFEST:
            left, right = without_timed_hashes(left), without_timed_hashes(right)
        return left == right
    return False


def compare(a: pathlib.Path, b: pathlib.Path) -> int:
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.is_file()}
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.is_file()}
    problems = [f"only in {a}: {p}" for p in sorted(files_a - files_b)]
    problems += [f"only in {b}: {p}" for p in sorted(files_b - files_a)]
    both = sorted(files_a & files_b)
    problems += [f"differs: {p}" for p in both if not same(a / p, b / p)]
    for line in problems:
        print(line)
    print(f"{len(both)} files compared, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "snapshot":
        snapshot(sys.argv[2], pathlib.Path(sys.argv[3]))
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])))
    else:
        print(__doc__)
        sys.exit(2)
