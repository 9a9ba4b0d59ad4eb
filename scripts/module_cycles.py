#!/usr/bin/env python3
"""Import cycles among a crate's modules.

    scripts/module_cycles.py crates/flapwright/src [PREFIX]

Reads every `.rs` file under the source folder, takes each file's module path
(`pipeline/geometry.rs` -> `pipeline::geometry`), and an edge A -> B wherever A names
`crate::B...` (in `use` lines and paths in the code; tests modules included). Only the
modules under PREFIX (default: all) are kept, each reference cut to the deepest module that
exists. Prints each strongly connected component of more than one module (a cycle), and
exits 1 when there is one.
"""
import pathlib
import re
import sys


def module_of(root: pathlib.Path, path: pathlib.Path) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] in ("mod", "lib", "main"):
        parts = parts[:-1]
    return "::".join(parts)


def main() -> int:
    root = pathlib.Path(sys.argv[1])
    prefix = sys.argv[2] if len(sys.argv) > 2 else ""
    files = {module_of(root, p): p for p in root.rglob("*.rs")}
    modules = set(files)
    edges = {m: set() for m in modules}
    for module, path in files.items():
        text = path.read_text()
        # `use crate::a::{b, c::d}` and `crate::a::b::thing` in code
        for match in re.finditer(r"crate::([a-z_][a-z0-9_]*(?:::[a-z_][a-z0-9_]*)*)", text):
            names = match.group(1).split("::")
            target = None
            for depth in range(len(names), 0, -1):
                candidate = "::".join(names[:depth])
                if candidate in modules:
                    target = candidate
                    break
            if target and target != module and not module.startswith(target + "::"):
                edges[module].add(target)
        # `super::x` from a child module
        parent = "::".join(module.split("::")[:-1]) if path.name != "mod.rs" else "::".join(module.split("::")[:-1])
        for match in re.finditer(r"\bsuper::([a-z_][a-z0-9_]*)", text):
            base = module.split("::")[:-1] if path.name != "mod.rs" else module.split("::")[:-1]
            candidate = "::".join(base + [match.group(1)])
            if candidate in modules and candidate != module:
                edges[module].add(candidate)
    keep = {m for m in modules if m.startswith(prefix)}
    graph = {m: {t for t in edges[m] if t in keep} for m in keep}
    # Tarjan's strongly connected components
    index, low, stack, on, result, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                result.append(sorted(component))

    sys.setrecursionlimit(10000)
    for v in sorted(graph):
        if v not in index:
            visit(v)
    for component in result:
        print("cycle: {" + ", ".join(component) + "}")
        for m in component:
            inside = sorted(t for t in graph[m] if t in component)
            print(f"  {m} -> {', '.join(inside)}")
    print(f"{len(keep)} modules, {len(result)} cycle(s)")
    return 1 if result else 0


if __name__ == "__main__":
    sys.exit(main())
