"""Identities of the package structure: imports only point down, no cycles, no long functions.

The import graph counts every ``import`` statement of ``femgear`` — at module level, inside
functions (a lazy import is still a dependency) and under ``if TYPE_CHECKING:`` (a type-only import
never runs, but a reader follows it as a dependency all the same: an annotation naming a higher
layer's class is an upward edge). Each edge points at the imported module itself (``from femgear.a import b`` → ``femgear.a.b``
when that is a module, else ``femgear.a``).

The allowed directions are data (:data:`ORDER`): for a package, its children in tiers from low
to high.  A module may import a module of its own unit, or of a unit in a strictly lower tier
of the first package where their paths part; siblings of one tier may not import each other.
``"*"`` stands for the package's own ``__init__``.  A child of an ordered package that no tier
names fails :func:`test_every_unit_has_a_place`: a new folder or module must be placed in the
order, not slip in unordered.

Layers of ``femgear`` (low → high; ARCHITECTURE.md says why):
base (errors, docfields, perf) · physics (the leaves: arrays, numbers, typed objects) · input
(scene, with the catalogue of levels as data; rexs) · case (the Case, built once per run) · levels
(one registry of factories per sub-model, each ``(case, **options) -> product``: the only place
that dispatches on a level name) · system (dynamics, coupling) · driver (results, rate, stages,
pipeline, summary) · edge (plot, io, run, sweep, cli; ``__main__``).

The physics leaves form a DAG, read from what they compute:
geometry (the gear) and excitation (errors, backlash) use no other leaf; mesh (gmsh sections
and bodies of the gear) and stiffness (ISO 6336 and potential-energy tooth stiffness, the
MeshStiffness table) read the geometry; contact (path kinematics, Hertz, load sharing by the
stiffness) and body (FE elasticity, conduction, compliance on those meshes) come next;
lubrication (oil laws, traction, flash temperature along the contact path), wear (Archard
on the path) and housing (the gearbox housing's FE model on its gmsh mesh, Craig–Bampton, FRFs, substructuring and
radiated sound); ehl (isothermal EHL of one contact, with its oil laws) and rating (ISO 6336
with the body's fillet, the stiffness factors and the flash temperature); tehl (thermal EHL
on the EHL solvers) and ltca (loaded tooth contact on the FE bodies, with the rating's
contact stress) on top.  Inside ``ehl`` the shared core (groups, rheology, grids, the
half-space, results, error estimates, roughness) is below its two discretisations, FE
Newton–Krylov (``fe``) and FD multigrid (``fd``), which never import each other; the entry
modules are on top: ``point.solve_point`` choosing between them, then ``dimensional`` (SI entry),
``transient`` (FE time steps from the steady solve) and ``output``, then ``path`` (the ``ehl-line``
level along the gear path, on the SI entry).
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

# low → high tiers of each ordered package's children ("*": the package's own __init__)
LAYERS = {
    "base": [["*"], ["errors", "docfields"], ["perf"]],   # "*": femgear/__init__ (a docstring and __version__)
    "physics": [["physics"]],
    "input": [["scene"], ["rexs"]],
    "case": [["case"]],
    "levels": [["levels"]],
    "system": [["system"]],
    "driver": [["results"], ["rate"], ["stages"], ["pipeline", "summary"]],
    "edge": [["edge"], ["__main__"]],
}
ORDER: dict[str, list[list[str]]] = {
    "femgear": [tier for tiers in LAYERS.values() for tier in tiers],
    "femgear.physics": [["geometry", "excitation"], ["mesh", "stiffness"], ["contact", "body"],
                        ["lubrication", "wear", "housing"], ["ehl", "rating"], ["tehl", "ltca"]],
    "femgear.physics.ehl": [["core"], ["fe"], ["fd"], ["point", "line"], ["dimensional", "transient"], ["path"], ["*"]],
    "femgear.system": [["dynamics"], ["coupling"]],
    "femgear.edge": [["plot"], ["io"], ["run"], ["sweep"], ["cli"]],
}

# The only file writers below the edge: build-once disk caches and the resumable wear checkpoint (ARCHITECTURE.md:
# "cached on disk where costly"), which write only under out/cache or a path the caller passes.
CACHES = {"femgear.physics.ltca.compliance", "femgear.physics.wear.archard"}
WRITE_CALLS = {"write_text", "write_bytes", "savefig", "save", "savez", "savez_compressed", "dump", "to_csv",
               "write_vtk", "to_file"}


def _modules() -> dict[str, Path]:
    mods = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        mods[".".join(parts)] = path
    return mods


def _imports(name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    return _imports_of_source(path.read_text(encoding="utf-8"), name, path, modules)


def _imports_of_source(source: str, name: str, path: Path, modules: dict[str, Path]) -> set[str]:
    """The femgear modules that ``source`` (module ``name`` at ``path``) imports, type-only imports included."""
    tree = ast.parse(source)
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    out = set()
    for node in ast.walk(tree):
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


def unit_path(module: str) -> list[tuple[str, str, int]]:
    """(package, unit, tier) at each ordered package on the way to ``module``.

    The unit is the child of the package that holds ``module`` (``"*"`` for the package's own
    ``__init__`` where the package has a ``"*"`` tier); a package's ``__init__`` without a ``"*"``
    tier ends the path (it belongs to its package, no tier)."""
    path, package, rest = [], "femgear", module.split(".")[1:]
    while package in ORDER:
        tiers = ORDER[package]
        child = rest[0] if rest else None
        unit = "*" if child is None else child
        if not any(unit in t for t in tiers):
            if child is None:
                break
            raise KeyError(f"{package}.{child} is in no tier of ORDER[{package!r}]: place it")
        path.append((package, unit, next(i for i, t in enumerate(tiers) if unit in t)))
        if unit == "*":
            break
        package, rest = f"{package}.{child}", rest[1:]
    return path


def direction(importer: str, imported: str) -> str:
    """'down' (or within one unit) when ``importer`` may import ``imported``, else 'up' / 'sideways'
    with the first package where their paths part."""
    for (pkg, ua, ra), (_, ub, rb) in zip(unit_path(importer), unit_path(imported)):
        if ua == ub:
            continue
        return "down" if rb < ra else f"{'up' if rb > ra else 'sideways'} in {pkg}: {ua} (tier {ra}) → {ub} (tier {rb})"
    return "down"


def upward_edges() -> dict[tuple[str, str], str]:
    names, edges = import_graph()
    out = {}
    for a in names:
        for b in sorted(edges[a]):
            d = direction(a, b)
            if d != "down":
                out[(a, b)] = d
    return out


def test_every_unit_has_a_place():
    missing = []
    for name in _modules():
        try:
            unit_path(name)
        except KeyError as exc:
            missing.append(str(exc))
    assert not missing, "; ".join(sorted(set(missing)))


def test_imports_only_point_down():
    found = upward_edges()
    assert not found, "upward imports:\n" + "\n".join(f"  {a} → {b}  ({d})" for (a, b), d in sorted(found.items()))


def test_order_catches_an_upward_import():
    """The rule itself: physics below the case, the case below the levels' factories, the catalogue of
    levels (input) below the case, ehl's core below its discretisations, FD above FE (its line solver
    drives FE's damped Newton), never the reverse."""
    assert direction("femgear.physics.lubrication.oil", "femgear.case").startswith("up in femgear")
    assert direction("femgear.case.checks", "femgear.levels.stiffness").startswith("up in femgear")
    assert direction("femgear.levels.stiffness", "femgear.case") == "down"
    assert direction("femgear.scene.schema", "femgear.levels.dynamics").startswith("up in femgear")
    assert direction("femgear.levels.registry", "femgear.scene.levels") == "down"
    assert direction("femgear.physics.ehl.core.grid", "femgear.physics.ehl.fe.level").startswith("up")
    assert direction("femgear.physics.ehl.fe.point", "femgear.physics.ehl.fd.point").startswith("up")
    assert direction("femgear.physics.ehl.fd.line", "femgear.physics.ehl.fe.newton") == "down"
    assert direction("femgear.physics.ehl.fd.point", "femgear.physics.ehl.core.grid") == "down"
    assert direction("femgear.edge.plot.path", "femgear.physics.contact.path") == "down"
    assert direction("femgear.physics.geometry.gear", "femgear.physics.geometry") == "down"


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
    """The graph is not vacuous: it finds the cli → cli.common and lazy edges, and type-only ones."""
    _, edges = import_graph()
    assert any(m.startswith("femgear.edge.cli.common") for m in edges["femgear.edge.cli.common"] | edges["femgear.edge.cli.run"])
    assert "femgear.physics.body.elastic3d" in edges["femgear.physics.ltca.compliance"]  # a lazy import
    assert len(sum((list(v) for v in edges.values()), [])) > 100
    src = "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from femgear.case import Case\nimport femgear.errors\n"
    probe = ROOT / "physics" / "_probe.py"      # not written: _imports reads the text through this stand-in
    seen = _imports_of_source(src, "femgear.physics._probe", probe, _modules())
    assert seen == {"femgear.case", "femgear.errors"}     # the type-only import counts (an upward edge here)


def _writes(path: Path) -> list[str]:
    """Calls in ``path`` that write a file: ``x.write_text(...)``, ``np.savez``, ``fig.savefig``, ``grid.save``,
    ``json.dump``, ``meshio.write``, ``open(..., "w"/"a"/"x")``."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if not isinstance(node, ast.Call):
            continue
        f = node.func
        if isinstance(f, ast.Attribute) and (f.attr in WRITE_CALLS or ast.unparse(f) == "meshio.write"):
            found.append(f"{ast.unparse(f)}() line {node.lineno}")
        elif isinstance(f, ast.Name) and f.id == "open":
            mode = node.args[1] if len(node.args) > 1 else next((k.value for k in node.keywords if k.arg == "mode"), None)
            if isinstance(mode, ast.Constant) and set(str(mode.value)) & set("wax"):
                found.append(f"open(..., {mode.value!r}) line {node.lineno}")
    return found


def test_only_the_edge_writes_files():
    """Physics, levels, input, case, system and driver write no file (figures and files are the edge's)."""
    bad = {}
    for name, path in _modules().items():
        top = unit_path(name)[0][1]
        if top in ("edge", "__main__") or name in CACHES:
            continue
        if found := _writes(path):
            bad[name] = found
    assert not bad, f"file writing below the edge: {bad}"
    assert all(_writes(_modules()[m]) for m in CACHES), "a listed writer writes no more: unlist it"


def test_functions_are_short():
    long = []
    for name, path in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_FUNCTION_LINES:
                    long.append(f"{name}.{node.name}: {n} lines")
    assert not long, "functions longer than 100 lines: " + "; ".join(long)
