"""The import graph of ``src/bearingsim``: no import cycle, no import of another package's private module.

Mechanism test (issue 12, "named contracts"): every module of the package is parsed with :mod:`ast` (nothing
is imported); an edge A → B is an ``import``/``from ... import`` that A executes when it is imported
(statements at module level and in class bodies; not inside functions, which run later, and not under
``if TYPE_CHECKING``).  Importing ``bearingsim.p.m`` also runs the package ``bearingsim.p`` (``__init__``),
so that edge is counted too unless A lives inside ``p`` already.

A private module is one whose name starts with ``_`` (``bearingsim.statics._kernels``); it may be imported
from its own package (and that package's sub-packages) only.  This rule counts every import, also those
inside functions.  Pairs that existed when the test was written are listed in :data:`KNOWN_PRIVATE`; the test
fails on any new one (remove a pair from the list when its import goes, so that it cannot come back).
"""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src"
PKG = "bearingsim"

#: pairs allowed to import another package's private module: none since issue 12 (the row layout is public in
#: statics.layout, the batch solver's entry in statics.batch); add none
KNOWN_PRIVATE: set[tuple[str, str]] = set()


def _modules() -> dict[str, Path]:
    out = {}
    for p in sorted((SRC / PKG).rglob("*.py")):
        rel = p.relative_to(SRC).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = p
    return out


def _is_package(mods: dict, name: str) -> bool:
    return mods[name].name == "__init__.py"


def _resolve(mods: dict, importer: str, level: int, module: str | None) -> str:
    if level == 0:
        return module or ""
    base = importer.split(".") if _is_package(mods, importer) else importer.split(".")[:-1]
    base = base[:len(base) - (level - 1)]
    return ".".join(base + ([module] if module else []))


def _imports(mods: dict, name: str, tree: ast.Module, module_level: bool) -> set[str]:
    """Modules of bearingsim that ``name`` imports (at import time when ``module_level``)."""
    found: set[str] = set()

    def visit(node, top: bool):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda):
                if not module_level:
                    visit(child, False)
                continue
            if isinstance(child, ast.If) and "TYPE_CHECKING" in ast.unparse(child.test):
                if not module_level:
                    visit(child, top)
                continue
            if isinstance(child, ast.Import):
                for a in child.names:
                    found.add(a.name)
            elif isinstance(child, ast.ImportFrom):
                target = _resolve(mods, name, child.level, child.module)
                found.add(target)
                for a in child.names:
                    if f"{target}.{a.name}" in mods:  # from package import submodule
                        found.add(f"{target}.{a.name}")
            visit(child, top)

    visit(tree, True)
    return {m for m in found if m == PKG or m.startswith(PKG + ".")}


def _graph(module_level: bool) -> dict[str, set[str]]:
    mods = _modules()
    graph = {}
    for name, path in mods.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
        edges = set()
        for target in _imports(mods, name, tree, module_level):
            parts = target.split(".")
            # the target and the packages it runs on the way, except the importer's own packages
            for i in range(2, len(parts) + 1):
                m = ".".join(parts[:i])
                if m in mods and m != name and not (name + ".").startswith(m + "."):
                    edges.add(m)
        graph[name] = edges
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def strong(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                strong(w)
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

    for v in sorted(graph):
        if v not in index:
            strong(v)
    return out


def _private_imports() -> set[tuple[str, str]]:
    mods = _modules()
    graph = _graph(module_level=False)
    bad = set()
    for name, targets in graph.items():
        own = name if _is_package(mods, name) else name.rsplit(".", 1)[0]
        for t in targets:
            parent, leaf = t.rsplit(".", 1)
            if leaf.startswith("_") and not leaf.startswith("__") and not (own + ".").startswith(parent + "."):
                bad.add((name, t))
    return bad


def test_graph_sees_the_known_edges():
    """The parser finds imports (a broken parser would find no cycle and no private import)."""
    g = _graph(module_level=True)
    assert "bearingsim.io.files" in g["bearingsim.io.bearing"]
    assert "bearingsim.dynamics.case" in g["bearingsim.io.case"]
    assert "bearingsim.dynamics" in g["bearingsim.io.case"]  # the package runs first
    lazy = _graph(module_level=False)
    assert "bearingsim.io.arrangement" in lazy["bearingsim.io.bearing"]  # inside a function
    assert "bearingsim.io.arrangement" not in g["bearingsim.io.bearing"]
    assert "bearingsim.io.bearing" in g["bearingsim.io.arrangement"]


def test_cycle_finder_finds_a_cycle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_no_import_cycle():
    cycles = _cycles(_graph(module_level=True))
    assert cycles == [], f"import cycles among bearingsim modules (module-level imports): {cycles}"


def test_no_new_import_of_a_private_module():
    found = _private_imports()
    new = sorted(found - KNOWN_PRIVATE)
    assert new == [], f"modules importing another package's private module: {new}"
