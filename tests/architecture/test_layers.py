"""Identities of the package structure: no import cycles, no long functions.

The import graph counts every ``import`` statement of ``femgear`` (module level and
inside functions: a lazy import is still a dependency; those under ``if TYPE_CHECKING:`` are not), each edge pointing at the
imported module itself (``from femgear.a import b`` → ``femgear.a.b`` when that is a
module, else ``femgear.a``).  Strongly connected components of more than one module
are cycles.
"""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

import femgear

ROOT = Path(femgear.__file__).parent
MAX_FUNCTION_LINES = 100


def _modules() -> dict[str, Path]:
    mods = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        mods[".".join(parts)] = path
    return mods


def _imports(name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out = set()
    typing_only = {id(n) for block in ast.walk(tree) if isinstance(block, ast.If)
                   and getattr(block.test, "id", getattr(block.test, "attr", None)) == "TYPE_CHECKING"
                   for stmt in block.body for n in ast.walk(stmt)}     # never run: not a dependency
    for node in ast.walk(tree):
        if id(node) in typing_only:
            continue
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names if a.name.startswith("femgear"))
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package.split(".")[: len(package.split(".")) - node.level + 1] + ([base] if base else []))
            if not base.startswith("femgear"):
                continue
            for a in node.names:
                out.add(f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base)
    return {m for m in out if m in modules and m != name}


def import_graph() -> tuple[list[str], dict[str, set[str]]]:
    modules = _modules()
    names = sorted(modules)
    return names, {n: _imports(n, modules[n], modules) for n in names}


def test_no_import_cycles():
    names, edges = import_graph()
    index = {n: i for i, n in enumerate(names)}
    rows = [index[a] for a in names for b in edges[a]]
    cols = [index[b] for a in names for b in edges[a]]
    graph = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(names),) * 2)
    n_comp, labels = connected_components(graph, directed=True, connection="strong")
    cycles = [sorted(np.array(names)[labels == c]) for c in range(n_comp) if np.sum(labels == c) > 1]
    assert not cycles, f"import cycles: {cycles}"


def test_graph_sees_known_edges():
    """The graph is not vacuous: it finds the dynamics → stiffness and cli → cli.common edges."""
    _, edges = import_graph()
    assert any(m.startswith("femgear.edge.cli.common") for m in edges["femgear.edge.cli.common"] | edges["femgear.edge.cli.run"])
    assert len(sum((list(v) for v in edges.values()), [])) > 100


def test_functions_are_short():
    long = []
    for name, path in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_FUNCTION_LINES:
                    long.append(f"{name}.{node.name}: {n} lines")
    assert not long, "functions longer than 100 lines: " + "; ".join(long)
