#!/usr/bin/env python3
"""The module graph of the library (src/) and of the command (cli/src/): no import cycle,
and the library's layers point one way.

Usage: python3 scripts/check_layers.py [--graph] [--self-test] [ROOT]     (ROOT: the repository, default
the parent of this script's folder). Exit status 0 when the graph is acyclic and every edge
of the library goes down the layer order below; 1 otherwise, with the cycles and the
offending edges (and the file and line of one import making each edge). `--graph` prints
every edge; `--self-test` runs the check on small made-up trees with a cycle, an upward
edge and a leaf importing a client, and fails unless each is caught.

An edge A -> B is a reference from a file of module A to module B: a `use` declaration
(`use crate::..`, `use super::..`, `use self::..`, brace groups expanded) or a fully qualified
`crate::..` / `super::..` path anywhere in the code. Comments (so doc links) and string
literals are ignored; tests inside the modules count (a test's import is an import). Nodes
are the library's top-level modules (`crate::X`) and, in the command, its modules two levels
deep (`cli::X` for cli/src/X.rs, `cli::X::Y` for cli/src/X/Y.rs). Names the crate root
re-exports (`crate::Sobol`) resolve to the module defining them (lib.rs's `pub use`); the
root files (lib.rs, main.rs) and the library's `prelude` are facades, not nodes.

Layer order of the library (a module may use its own layer's modules, acyclically, and the
layers below it; never a layer above):

  0 leaf          dispatch (CPU-feature dispatch: imports nothing of the crate but bits and
                  error; today nothing at all)
  1 core          bits, hash, error, size, work, sampler
  2 randomize     randomize (scramblers, shuffles, digit permutations: on top of the core
                  only, so that constructions may apply them inside: OwenSobol, the
                  radical inverse's digit scrambles)
  3 constructions radical_inverse, digital, lattice, random, pmj
  4 uses          pixel, blue_noise, warp, collect (`Vec`s of points of named
                  constructions: it names Sobol', Halton and their scrambles), buffer
                  (as the crate's documentation lays the tree out)
  5 analysis      analysis (feature `analysis`: measurements of any construction)
  6 catalog       catalog (the names of every construction, and their measured claims,
                  which may use analysis under that feature)

The command (cli) is checked for cycles only (it sits above the whole library).
"""

import re
import sys
from collections import defaultdict
from pathlib import Path

LAYERS = [
    ("leaf", ["dispatch"]),
    ("core", ["bits", "hash", "error", "size", "work", "sampler"]),
    ("randomize", ["randomize"]),
    ("constructions", ["radical_inverse", "digital", "lattice", "random", "pmj"]),
    ("uses", ["pixel", "blue_noise", "warp", "collect", "buffer"]),
    ("analysis", ["analysis"]),
    ("catalog", ["catalog"]),
]
# Modules a leaf may import (at most).
LEAF_MAY_USE = {"bits", "error"}
FACADES = {"prelude"}


def strip_code(text):
    """The text with comments and string/char literals blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
            continue
        if text.startswith("/*", i):
            depth, j = 1, i + 2
            while j < n and depth:
                if text.startswith("/*", j):
                    depth, j = depth + 1, j + 2
                elif text.startswith("*/", j):
                    depth, j = depth - 1, j + 2
                else:
                    j += 1
            out.append("\n" * text.count("\n", i, j))
            i = j
            continue
        m = re.match(r'r(#*)"', text[i:i + 10]) if c == "r" and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")) else None
        if m:
            end = text.find('"' + m.group(1), i + len(m.group(0)))
            end = n if end < 0 else end + 1 + len(m.group(1))
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
            continue
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j + 1
            continue
        if c == "'":
            # A char literal ('a', '\n', '\u{..}'), not a lifetime.
            m = re.match(r"'(\\u\{[0-9a-fA-F]+\}|\\.|[^\\'])'", text[i:i + 12])
            if m:
                out.append("' '")
                i += len(m.group(0))
                continue
        out.append(c)
        i += 1
    return "".join(out)


def expand_use_tree(tree):
    """`a::{b, c::{d, e}}` -> [["a","b"], ["a","c","d"], ["a","c","e"]] (`as` dropped)."""
    tree = re.sub(r"\s+", "", tree)

    def parse(s, pos):
        """Parses a list of trees from pos until '}' or end; returns (paths, pos)."""
        paths = []
        while pos < len(s) and s[pos] != "}":
            prefix = []
            m = re.match(r"((?:[A-Za-z_][A-Za-z0-9_]*|\*)(?:::)?)+", s[pos:])
            seg_text = m.group(0) if m else ""
            pos += len(seg_text)
            prefix = [p for p in seg_text.split("::") if p]
            if pos < len(s) and s[pos] == "{":
                inner, pos = parse(s, pos + 1)
                pos += 1  # '}'
                paths += [prefix + p for p in inner] or [prefix]
            else:
                if s.startswith("as", pos):
                    m2 = re.match(r"as[A-Za-z_][A-Za-z0-9_]*", s[pos:])
                    pos += len(m2.group(0)) if m2 else 0
                paths.append(prefix)
            if pos < len(s) and s[pos] == ",":
                pos += 1
            elif pos < len(s) and s[pos] not in "}":
                pos += 1  # anything unexpected: skip a character
        return paths, pos

    paths, _ = parse(tree, 0)
    # `a::{self, b}`: `self` names `a`.
    return [p[:1] + [x for x in p[1:] if x != "self"] for p in paths]


class Crate:
    """One crate's files, node naming and root re-exports."""

    def __init__(self, name, src, depth, prefix):
        self.name, self.src, self.depth, self.prefix = name, src, depth, prefix
        self.reexports = {}
        self.top = set()
        lib = src / "lib.rs"
        if lib.exists():
            text = strip_code(lib.read_text(encoding="utf-8"))
            for m in re.finditer(r"\bmod\s+([A-Za-z_][A-Za-z0-9_]*)\s*;", text):
                self.top.add(m.group(1))
            for m in re.finditer(r"\bpub(?:\([^)]*\))?\s+use\s+([^;]+);", text):
                for p in expand_use_tree(m.group(1)):
                    p = [x for x in p if x not in ("crate", "self")]
                    if len(p) >= 2 and p[0] in self.top:
                        self.reexports[p[-1]] = p[0]
        # Module paths that have their own file (a node is the longest such prefix).
        self.files = {tuple(self.module_path(f)) for f in src.rglob("*.rs")}
        main = src / "main.rs"
        if main.exists():
            text = strip_code(main.read_text(encoding="utf-8"))
            for m in re.finditer(r"\bmod\s+([A-Za-z_][A-Za-z0-9_]*)\s*;", text):
                self.top.add(m.group(1))

    def module_path(self, f):
        """The module path of file f (['randomize', 'owen'] for src/randomize/owen.rs)."""
        rel = f.relative_to(self.src).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "mod":
            parts.pop()
        if parts in (["lib"], ["main"]):
            return []
        return parts

    def node(self, path):
        """The graph node of a module path, or None for the root and facades."""
        if not path or path[0] in FACADES or path[0] not in self.top:
            return None
        for k in range(min(self.depth, len(path)), 0, -1):
            if tuple(path[:k]) in self.files:
                return self.prefix + "::".join(path[:k])
        return self.prefix + path[0]

    def resolve(self, base, path):
        """The module path `path` (from `use` or a qualified path) names, seen from `base`."""
        if not path:
            return None
        if path[0] == "crate":
            rest = path[1:]
            if rest and rest[0] not in self.top and rest[0] in self.reexports:
                return [self.reexports[rest[0]]]
            return rest
        if path[0] in ("super", "self"):
            cur = list(base)
            while path and path[0] in ("super", "self"):
                if path[0] == "super":
                    if not cur:
                        return None
                    cur.pop()
                path = path[1:]
            full = cur + path
            if full and full[0] not in self.top and full[0] in self.reexports:
                return [self.reexports[full[0]]]
            return full
        return None  # an external crate, std, or a name in scope


def collect_edges(crate):
    """{(a, b): (file, line)} for every module edge a -> b (a != b) of the crate."""
    edges = {}
    for f in sorted(crate.src.rglob("*.rs")):
        base = crate.module_path(f)
        a = crate.node(base)
        if a is None:
            continue
        text = strip_code(f.read_text(encoding="utf-8"))
        refs = []
        for m in re.finditer(r"\buse\s+((?:crate|super|self)\b[^;]*);", text):
            for p in expand_use_tree(m.group(1)):
                refs.append((p, m.start()))
        for m in re.finditer(r"(?<![A-Za-z0-9_:])((?:crate|super)(?:::[A-Za-z_][A-Za-z0-9_]*)+)", text):
            refs.append((m.group(1).split("::"), m.start()))
        for p, pos in refs:
            target = crate.resolve(base, p)
            b = crate.node(target) if target else None
            if b is None or b == a:
                continue
            edges.setdefault((a, b), (f, text.count("\n", 0, pos) + 1))
    return edges


def find_cycles(nodes, edges):
    """The strongly connected components with more than one node (Tarjan)."""
    adj = defaultdict(list)
    for a, b in edges:
        adj[a].append(b)
    index, low, on, stack, comps = {}, {}, set(), [], []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in adj[v]:
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
                comps.append(sorted(comp))

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return comps


def self_test():
    """The check on small made-up trees: it must fail on a cycle (through `use` trees,
    `super::` and a qualified path), on a layer going up and on the leaf importing a
    client, and pass on a clean tree. Returns 0 when it does."""
    import tempfile

    cases = {
        "clean": ({"bits.rs": "", "sampler.rs": "use crate::bits::x;",
                   "randomize/mod.rs": "use crate::{bits, sampler::{self, S}};",
                   "digital/mod.rs": "pub fn f() { crate::randomize::g(); }"}, ""),
        "cycle": ({"bits.rs": "", "digital/mod.rs": "use crate::random::X;",
                   "random/mod.rs": "mod inner;", "random/inner.rs":
                   "// use crate::lattice is a comment\nuse super::super::digital::Y;"},
                  "import cycle in qmckit among digital, random:"),
        "up": ({"sampler.rs": "fn f() { let _ = crate::pixel::P; }", "pixel/mod.rs": ""},
               "layer order: sampler (core) uses pixel (uses)"),
        "leaf": ({"dispatch.rs": "use crate::randomize::Scrambler;",
                  "randomize/mod.rs": ""},
                 "dispatch is a leaf but uses `randomize`"),
    }
    bad = 0
    for name, (files, want) in cases.items():
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            mods = sorted({f.split("/")[0].removesuffix(".rs") for f in files})
            (root / "src").mkdir()
            (root / "src" / "lib.rs").write_text("".join(f"mod {m};\n" for m in mods))
            for f, text in files.items():
                (root / "src" / f).parent.mkdir(parents=True, exist_ok=True)
                (root / "src" / f).write_text(text)
            (root / "cli" / "src").mkdir(parents=True)
            (root / "cli" / "src" / "lib.rs").write_text("")
            import contextlib
            import io

            with contextlib.redirect_stdout(io.StringIO()) as log:
                got = main([str(root)])
            if got != (1 if want else 0) or want not in log.getvalue():
                bad += 1
                print(f"self-test {name}: exit {got}, expected {want}\n{log.getvalue()}")
    print(f"check_layers self-test: {len(cases) - bad}/{len(cases)} cases as expected")
    return 1 if bad else 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    show = "--graph" in argv
    args = [a for a in argv if not a.startswith("--")]
    root = Path(args[0]) if args else Path(__file__).resolve().parent.parent
    lib = Crate("qmckit", root / "src", 1, "")
    cli = Crate("qmckit-cli", root / "cli" / "src", 2, "cli::")
    failures = []
    layer_of = {m: k for k, (_, mods) in enumerate(LAYERS) for m in mods}
    for m in sorted(lib.top - FACADES):
        if m not in layer_of:
            failures.append(f"library module `{m}` has no layer: add it to LAYERS in {__file__}")
    for crate in (lib, cli):
        edges = collect_edges(crate)
        nodes = {n for e in edges for n in e}
        if show:
            for (a, b), (f, line) in sorted(edges.items()):
                print(f"{a} -> {b}    ({f.relative_to(root)}:{line})")
        for comp in find_cycles(nodes, edges):
            lines = [f"import cycle in {crate.name} among {', '.join(comp)}:"]
            for (a, b), (f, line) in sorted(edges.items()):
                if a in comp and b in comp:
                    lines.append(f"    {a} -> {b}    ({f.relative_to(root)}:{line})")
            failures.append("\n".join(lines))
        if crate is lib:
            for (a, b), (f, line) in sorted(edges.items()):
                la, lb = layer_of.get(a), layer_of.get(b)
                where = f"({f.relative_to(root)}:{line})"
                if a == "dispatch" and b not in LEAF_MAY_USE:
                    failures.append(f"dispatch is a leaf but uses `{b}` {where}")
                elif la is not None and lb is not None and lb > la:
                    failures.append(
                        f"layer order: {a} ({LAYERS[la][0]}) uses {b} ({LAYERS[lb][0]}), "
                        f"a layer above it {where}"
                    )
    if failures:
        print("\n".join(failures))
        print(f"check_layers: {len(failures)} problem(s)")
        return 1
    print(f"check_layers: no import cycle in the library or the command; the library's "
          f"{len(LAYERS)} layers point one way")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
