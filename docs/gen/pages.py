"""Pages of the docs site generated from the code at build time (never hand-copied).

- ``reference/scene-keys.md``: every scene key with type, default, unit and meaning, from the schema
  (:func:`femgear.scene.keys.scene_keys`);
- ``reference/result-fields.md``: every field of :class:`femgear.results.RunResult` and the typed results
  it holds, with meaning and unit, from the attribute docstrings under each field (:mod:`femgear.docfields`
  where it is present; the same docstrings read with :mod:`ast` otherwise);
- ``reference/levels.md``: the levels of every sub-model with their one-line summaries, from the
  catalogue :mod:`femgear.scene.levels`;
- ``gallery.md``: every figure femgear draws, with its command and what to read in it, from the table of
  ``docs/gen/gallery.py`` (the pictures are committed in ``docs/gallery/``).

``docs/gen/hooks.py`` adds them to the site (MkDocs hook); ``python docs/gen/pages.py OUTDIR`` writes them
as files, for a look without MkDocs; ``python docs/gen/pages.py --readme`` rewrites the README's levels
table from the registries (``tests/docs/test_pages.py`` fails when it is out of date).
"""

from __future__ import annotations

import ast
import dataclasses
import functools
import importlib.util
import inspect
import re
import sys
import types
import typing
from pathlib import Path

_UNIT_END = re.compile(r"\[([^\[\]]+)\]\s*$")


def _cell(text: object) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ").replace("[", "\\[").replace("]", "\\]")


def _default(value: object) -> str:
    if value is None:
        return "—"
    if isinstance(value, str):
        return f'`"{value}"`'
    if isinstance(value, bool):
        return f"`{str(value).lower()}`"
    return f"`{value!r}`"


def scene_keys_page() -> str:
    """Markdown: one table per scene table, every key with type, default, unit and meaning."""
    from femgear.scene.keys import scene_keys, scene_tables

    keys = scene_keys()
    out = ["# Scene keys", "",
           "Every key of a scene file, generated from the schema (`femgear/scene/schema.py`) when the docs are "
           "built. Units are SI; angles are in degrees in the keys ending in `_deg`. **required** keys have no "
           "default. `femgear new` writes the same information as a commented template; "
           "`--set table.key=value` overrides any key from the command line.", ""]
    for t in scene_tables():
        rows = [k for k in keys if k.table == t.table]
        if not rows:
            continue
        optional = " (optional table)" if t.optional else ""
        out += [f"## `[{t.table}]`{optional}", "", _cell(t.doc), "",
                "| key | type | default | unit | meaning |", "|---|---|---|---|---|"]
        for k in rows:
            default = "**required**" if k.required else _default(k.default)
            out.append(f"| `{k.name}` | {_cell(k.type)} | {default} | {_cell(k.unit or '')} | {_cell(k.description)} |")
        out.append("")
    return "\n".join(out)


def levels_page() -> str:
    """Markdown: the levels of every sub-model (the ``[physics]`` keys), cheapest first, from the catalogue."""
    from femgear.scene.levels import CATALOGUE, PHYSICS

    out = ["# Physics levels", "",
           "The `[physics]` table of a scene picks one level per sub-model; this page is generated from the "
           "catalogue `femgear/scene/levels.py` (the one source of level names), cheapest level first. "
           "How to choose: [Choosing levels](../guide/levels.md).", ""]
    for sub in PHYSICS:
        levels = CATALOGUE[sub].levels
        out += [f"## `physics.{sub}`", "", "| level | what it computes |", "|---|---|"]
        out += [f"| `{s.name}` | {_cell(s.summary)} |" for s in levels if not s.planned]
        out += [f"| `{s.name}` | planned, refused as \"not available yet\" |" for s in levels if s.planned]
        out.append("")
    return "\n".join(out)


README_MARKERS = ("<!-- levels:begin -->", "<!-- levels:end -->")


def levels_table() -> str:
    """The README's levels table: one row per sub-model, its levels cheapest first (from the catalogue)."""
    from femgear.scene.levels import CATALOGUE, PHYSICS

    rows = ["| `[physics]` key | levels, cheapest first |", "|---|---|"]
    for sub in PHYSICS:
        reg = CATALOGUE[sub]
        names = " · ".join(f"`{n}`" for n in reg.available)
        planned = f" (planned: {', '.join(f'`{n}`' for n in reg.planned)})" if reg.planned else ""
        rows.append(f"| `{sub}` | {names}{planned} |")
    return "\n".join(rows)


def update_readme(readme: Path) -> bool:
    """Rewrite the levels table between the README's markers; True when it changed."""
    text = readme.read_text(encoding="utf-8")
    begin, end = (text.index(m) for m in README_MARKERS)
    new = text[:begin + len(README_MARKERS[0])] + "\n" + levels_table() + "\n" + text[end:]
    if new != text:
        readme.write_text(new, encoding="utf-8")
    return new != text


# ---------------------------------------------------------------- result fields


def _source_docs(cls: type) -> dict[str, str]:
    """{field: text} from the class source: the attribute docstring under a field, or its ``#:`` comment."""
    try:
        lines, _ = inspect.getsourcelines(cls)
    except (OSError, TypeError):
        return {}
    src = inspect.cleandoc("".join(lines)) if lines[0].startswith((" ", "\t")) else "".join(lines)
    node = ast.parse(src).body[0]
    text_lines = src.splitlines()
    out: dict[str, str] = {}
    body = node.body
    for i, stmt in enumerate(body):
        if not (isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name)):
            continue
        nxt = body[i + 1] if i + 1 < len(body) else None
        if isinstance(nxt, ast.Expr) and isinstance(nxt.value, ast.Constant) and isinstance(nxt.value.value, str):
            out[stmt.target.id] = " ".join(inspect.cleandoc(nxt.value.value).split())
            continue
        line = text_lines[stmt.lineno - 1]
        if "#:" in line:
            out[stmt.target.id] = line.split("#:", 1)[1].strip()
            continue
        above = []
        j = stmt.lineno - 2
        while j >= 0 and text_lines[j].strip().startswith("#:"):
            above.insert(0, text_lines[j].strip()[2:].strip())
            j -= 1
        if above:
            out[stmt.target.id] = " ".join(above)
    return out


def field_docs(cls: type) -> dict[str, tuple[str, str | None]]:
    """{field: (meaning, unit or None)} of a result dataclass (femgear.docfields when present and complete)."""
    try:
        from femgear.docfields import field_docs as documented
        return {name: (d.doc, d.unit) for name, d in documented(cls).items()}
    except (ImportError, TypeError):  # not there yet, or a field without its unit: read what the source has
        pass
    texts = _source_docs(cls)
    out = {}
    for f in dataclasses.fields(cls):
        text = texts.get(f.name, "")
        m = _UNIT_END.search(text) or re.search(r"\[([^\[\]]+)\]", text)
        out[f.name] = (text[:m.start()].rstrip(" ,;:") + text[m.end():] if m else text, m.group(1) if m else None)
    return out


def _dataclasses_in(annotation: object) -> list[type]:
    origin = typing.get_origin(annotation)
    if origin in (typing.Union, types.UnionType):
        return [c for a in typing.get_args(annotation) for c in _dataclasses_in(a)]
    return [annotation] if isinstance(annotation, type) and dataclasses.is_dataclass(annotation) else []


#: types reached from RunResult that are not results (inputs), listed but not expanded
_NOT_EXPANDED = {"femgear.case.Case"}


def result_types(root: type | None = None) -> list[type]:
    """RunResult and every dataclass reachable through its fields' annotations (femgear.docfields.field_tree
    where present, stopping at the inputs; else a breadth-first walk of the resolved annotations)."""
    if root is None:
        from femgear.results import RunResult
        root = RunResult
        try:
            from femgear.docfields import field_tree
            from femgear.results import INPUT_TYPES
            return list(field_tree(root, stop=INPUT_TYPES))
        except ImportError:
            pass
    seen: list[type] = []
    queue = [root]
    while queue:
        cls = queue.pop(0)
        if cls in seen or f"{cls.__module__}.{cls.__qualname__}" in _NOT_EXPANDED:
            continue
        seen.append(cls)
        try:
            hints = typing.get_type_hints(cls)
        except (NameError, TypeError):  # an annotation that does not resolve: the fields are still listed
            hints = {}
        for f in dataclasses.fields(cls):
            queue += _dataclasses_in(hints.get(f.name))
    return seen


def result_fields_page() -> str:
    """Markdown: every field of the typed results of a run with its meaning and unit."""
    out = ["# Result fields", "",
           "The typed results of `run_case` (`RunResult` and the results it holds), generated from the "
           "docstrings under each field when the docs are built. Units are SI; `-` is dimensionless. "
           "`results.json` is written from these objects (`femgear/edge/io/run.py` documents its layout). "
           "Conventions: along the path of contact, `u` (`PathKinematics.u`, the arrays of the physics) is the "
           "distance from T1, the pinion's base-circle tangent point, along the transverse line of action, and "
           "`s` (`along_path.s` in `results.json`, the plots) the signed distance from the pitch point C, "
           "positive towards the pinion tip (the end of contact E); mesh stiffness, mesh forces and flank "
           "deviations act along the normal line of action of each helix; arrays over (2, n) are (pinion, "
           "gear) or (left, right) helix as their field says.", ""]
    missing = []
    for cls in result_types():
        docs = field_docs(cls)
        head = inspect.cleandoc(cls.__doc__ or "").split("\n\n")[0]
        if head.startswith(cls.__name__ + "("):
            head = ""
        out += [f"## `{cls.__name__}`", "", f"`{cls.__module__}.{cls.__qualname__}`. {' '.join(head.split())}", "",
                "| field | unit | meaning |", "|---|---|---|"]
        for name, (doc, unit) in docs.items():
            if unit is None:
                missing.append(f"{cls.__name__}.{name}")
            out.append(f"| `{name}` | {_cell(unit or '—')} | {_cell(doc) or '*(undocumented)*'} |")
        out.append("")
    if missing:
        out += ["!!! note \"Fields without a unit in their docstring\"",
                "    " + ", ".join(f"`{m}`" for m in missing), ""]
    return "\n".join(out + _results_json_layout())


def _results_json_layout() -> list[str]:
    """The layout of results.json: the module docstring of its writer (read statically, the contract)."""
    path = Path(__file__).resolve().parents[2] / "femgear" / "edge" / "io" / "run.py"
    if not path.exists():
        return []
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
    doc = re.sub(r":(?:func|mod|class|meth|attr):`([^`]+)`", r"`\1`", doc).replace("``", "`")
    return ["## `results.json`", "",
            "The file `femgear run` writes is made from these objects by `femgear/edge/io/run.py`; its docstring, "
            "the layout contract, reads:", "", doc, ""]


@functools.cache
def gallery():
    """``docs/gen/gallery.py`` (the gallery's table and page), loaded by path: ``docs/gen`` is no package."""
    spec = importlib.util.spec_from_file_location("femgear_doc_gallery", Path(__file__).with_name("gallery.py"))
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module              # dataclasses look their module up while the class is made
    spec.loader.exec_module(module)
    return module


def gallery_page() -> str:
    """Markdown: every figure femgear draws, from the gallery's table (``docs/gen/gallery.py``)."""
    return gallery().page()


PAGES = {"reference/scene-keys.md": scene_keys_page, "reference/result-fields.md": result_fields_page,
         "reference/levels.md": levels_page, "gallery.md": gallery_page}


if __name__ == "__main__":
    if sys.argv[1:] == ["--readme"]:
        changed = update_readme(Path(__file__).resolve().parents[2] / "README.md")
        print("README levels table " + ("rewritten" if changed else "up to date"))
        sys.exit(0)
    target = Path(sys.argv[1] if len(sys.argv) > 1 else "out/docs-pages")
    for rel, make in PAGES.items():
        path = target / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(make(), encoding="utf-8")
        print(path)
