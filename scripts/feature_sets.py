#!/usr/bin/env python3
"""Checks that `cargo run --release` and `cargo test --workspace --release` ask for the
same features of every crate they share, so that the README's test command reuses the run
command's build (crates/cli/Cargo.toml lists the features the tests' dev-dependencies add).
Exit 1 naming each crate whose features differ, with what the binary's build lacks."""
import subprocess
import sys


def features(args):
    text = subprocess.run(
        ["cargo", "tree", *args, "--format", "{p}|{f}", "--prefix", "none"],
        check=True, capture_output=True, text=True,
    ).stdout
    found = {}
    for line in text.splitlines():
        if "|" not in line:
            continue
        package, listed = line.split("|", 1)
        name = " ".join(package.split()[:2])
        if "(/" in package:  # a workspace crate: built for both anyway
            continue
        found[name] = set(f for f in listed.replace("(*)", "").strip().split(",") if f)
    return found


run = features(["-p", "flapwright-cli", "-e", "normal,build"])
test = features(["--workspace", "-e", "normal,build,dev"])
differ = [(name, sorted(test[name] - run[name]), sorted(run[name] - test[name]))
          for name in sorted(run) if name in test and run[name] != test[name]]
for name, missing, extra in differ:
    print(f"{name}: the run build lacks {missing}" + (f", has more {extra}" if extra else ""))
if differ:
    print("add the features to crates/cli/Cargo.toml's [dependencies] (see its comment)")
    sys.exit(1)
print(f"{len(run)} crates shared by the run and test builds, with the same features")
