#!/usr/bin/env python3
"""The module graph of a crate, from its `use` lines and inline `crate::`/`super::` paths.

    python3 tools/module_stack.py cga-trace/src [cga-core/src …]

For each source tree: its modules (one a file; `mod.rs` is its folder's module), the import
cycles among them (strongly connected components of more than one module), and its floors
(each module one floor above the highest it imports; a module importing nothing of the crate is
on floor 1); for a crate whose layers are declared below (`LAYERS`), any import of a
higher layer. A name that a module re-exports (`pub use x::Y`) is charged to the module that
defines it. Unit tests (what follows a file's `#[cfg(test)]`) and the binary's root
(`main.rs`) are left out: the stack is the library's. Exits 1 if there is a cycle or an import against
the layers, so CI can run it.
"""

import re
import sys
from pathlib import Path


def module_of(src: Path, file: Path) -> tuple:
    """`a/b.rs` → ("a", "b"), `a/mod.rs` → ("a",), `lib.rs` → ()."""
    parts = list(file.relative_to(src).with_suffix("").parts)
    if parts[-1] in ("mod", "lib"):
        parts.pop()
    return tuple(parts)


def code(text: str) -> str:
    """The text before its unit tests, without comments."""
    text = text.split("#[cfg(test)]")[0]
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return "\n".join(line.split("//")[0] for line in text.splitlines())


def expand(tree: str) -> list:
    """A `use` tree (`a::{b, c::{d, e}}`) as the paths it names."""
    tree = re.sub(r"\s+as\s+\w+", "", tree)
    tree = tree.replace(" ", "").replace("\n", "")
    depth, start = 0, None
    for i, ch in enumerate(tree):
        if ch == "{":
            if depth == 0:
                start = i
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                prefix, inner, rest = tree[:start], tree[start + 1 : i], tree[i + 1 :]
                items, depth2, cur = [], 0, ""
                for c in inner:
                    if c == "," and depth2 == 0:
                        items.append(cur)
                        cur = ""
                        continue
                    depth2 += c == "{"
                    depth2 -= c == "}"
                    cur += c
                items.append(cur)
                return [p for item in items if item for p in expand(prefix + item + rest)]
    return [tree]


def paths(text: str) -> list:
    """Every path the code names within the crate (from `crate`, `super`, `self`, or a child
    module by its name), each with whether a `pub use` names it (a re-export). A path that
    starts elsewhere (`std::`, another crate) resolves to the module itself and is dropped."""
    found = []
    for m in re.finditer(r"\b(pub(?:\([^)]*\))?\s+)?use\s+([^;]+);", text):
        for p in expand(m.group(2)):
            first = p.split("::")[0]
            found.append((p if first in ("crate", "super", "self") else "self::" + p, bool(m.group(1))))
    text = re.sub(r"\buse\s+[^;]+;", "", text)
    # (Not `#name::path`: a name interpolated into generated code by `quote!`.)
    for m in re.finditer(r"(?<![\w:#])(\w+)((?:::\w+)+)", text):
        first = m.group(1)
        found.append((m.group(0) if first in ("crate", "super", "self") else "self::" + m.group(0), False))
    return found


# The layers a crate's top-level modules are declared in, lowest first (ARCHITECTURE.md
# draws them): a module imports only from its own layer and those below.
LAYERS = {
    "cga-trace/src": [
        ("basics", ["limits", "ray", "frame", "bvh", "output", "input", "lanes", "film", "hash"]),
        ("geometry", ["shapes", "camera", "light", "shutter", "surface", "drawing", "label"]),
        ("checked values", ["invalid", "material", "picture", "settings", "import", "environment", "texture", "object"]),
        ("scene", ["scene"]),
        ("format", ["format"]),
        ("backend", ["backend"]),
        ("integrator", ["integrator"]),
        ("output side", ["colour", "figure", "mesh", "pipeline"]),
    ],
}


def upward(src: str, edges: dict) -> list:
    """The imports that reach a higher layer than the importer's, and the modules no layer
    names, for a crate with declared layers."""
    layers = LAYERS.get(src.rstrip("/"))
    if layers is None:
        return []
    floor = {m: k for k, (_, ms) in enumerate(layers) for m in ms}
    out = [f"{name(m)} is in no layer" for m in edges if m[0] not in floor]
    for m, ts in edges.items():
        for t in sorted(ts):
            if m[0] in floor and t[0] in floor and floor[t[0]] > floor[m[0]]:
                out.append(f"{name(m)} ({layers[floor[m[0]]][0]}) imports {name(t)} ({layers[floor[t[0]]][0]})")
    return out


# (importer, imported) → the names taken, for the report.
NAMES = {}


def graph(src: Path) -> dict:
    """Module → the modules it imports."""
    files = {module_of(src, f): f for f in sorted(src.rglob("*.rs")) if f.name != "main.rs"}
    texts = {m: code(f.read_text()) for m, f in files.items()}
    # Re-exports: (module, name) → the module that holds it.
    reexports = {}

    def resolve(module: tuple, path: str):
        segs = path.split("::")
        if segs[0] == "crate":
            here, segs = (), segs[1:]
        else:
            here = module
            while segs and segs[0] in ("super", "self"):
                if segs[0] == "super":
                    here = here[:-1]
                segs = segs[1:]
        # The longest prefix that is a module, then a re-exported name within it.
        target = here
        for s in segs:
            if target + (s,) in files:
                target = target + (s,)
            else:
                while (target, s) in reexports and reexports[(target, s)] != target:
                    target = reexports[(target, s)]
                break
        return target

    for _ in range(3):  # re-exports of re-exports
        for m, text in texts.items():
            for full, reexport in paths(text):
                name = full.split("::")[-1]
                if reexport and name not in ("*", "self"):
                    target = resolve(m, full)
                    if target != m:
                        reexports[(m, name)] = target
    edges = {m: set() for m in files}
    for m, text in texts.items():
        for p, reexport in paths(text):
            t = resolve(m, p)
            # A folder's module naming what its own files define is no use of them.
            if t != m and not (reexport and t[: len(m)] == m):
                edges[m].add(t)
                NAMES.setdefault((m, t), set()).add(p.split("::")[-1])
    del edges[()]
    for e in edges.values():
        e.discard(())
    return edges


def cycles(edges: dict) -> list:
    """Strongly connected components of more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in edges:
        if v not in index:
            visit(v)
    return out


def floors(edges: dict, comps: list) -> dict:
    """Each module's floor (a cycle's modules share one)."""
    rep = {m: m for m in edges}
    for c in comps:
        for m in c:
            rep[m] = c[0]
    memo = {}

    def floor(r, seen=()):
        if r in memo:
            return memo[r]
        members = [m for m in edges if rep[m] == r]
        below = {rep[t] for m in members for t in edges[m] if t in rep and rep[t] != r}
        memo[r] = 1 + max((floor(b) for b in below), default=0)
        return memo[r]

    return {m: floor(rep[m]) for m in edges}


def name(m: tuple) -> str:
    return "::".join(m)


def main() -> int:
    bad = 0
    for arg in sys.argv[1:] or ["cga-trace/src"]:
        edges = graph(Path(arg))
        comps = cycles(edges)
        fl = floors(edges, comps)
        print(f"{arg}: {len(edges)} modules, {len(comps)} cycles, {max(fl.values(), default=0)} floors")
        # The same with each folder as one module (its files' imports of each other dropped).
        top = {}
        for m, ts in edges.items():
            top.setdefault(m[:1], set()).update(t[:1] for t in ts if t[:1] != m[:1])
        sizes = sorted((len(c) for c in cycles(top)), reverse=True)
        print(f"  top level: {len(top)} modules, {len(sizes)} cycles{' of ' + ', '.join(map(str, sizes)) if sizes else ''}")
        for c in comps:
            print(f"  cycle of {len(c)}: {', '.join(map(name, c))}")
            members = set(c)
            for m in c:
                for t in sorted(edges[m] & members):
                    print(f"    {name(m)} -> {name(t)}: {', '.join(sorted(NAMES.get((m, t), ())))}")
        for line in upward(arg, edges):
            print(f"  against the layers: {line}")
            bad += 1
        for f in sorted(set(fl.values()), reverse=True):
            print(f"  floor {f:2}: {', '.join(sorted(name(m) for m in fl if fl[m] == f))}")
        bad += bool(comps)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
