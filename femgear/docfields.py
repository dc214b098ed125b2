"""Field documentation of typed results: meaning and unit under each dataclass field.

Every field of a result dataclass carries an attribute docstring directly under it whose
text ends with its unit in square brackets (``[-]`` for a dimensionless number)::

    @document_fields
    @dataclass(frozen=True)
    class Tribology:
        load_per_length: np.ndarray
        \"\"\"passage-mean load per unit contact-line length along the path [N/m]\"\"\"

:func:`document_fields` reads those strings from the class's source (statically: the module is
parsed once with :mod:`ast`, nothing is executed or instantiated), refuses a field without a
docstring or without a trailing unit (:class:`FieldDocError`, naming the class and the field),
stores them and appends a "Fields" list to the class ``__doc__`` so that ``help()`` shows them.
:func:`field_docs` returns ``{name: FieldDoc(doc, unit)}`` (the docs site and the ``units``
table of ``results.json`` read it).

Python keeps no attribute docstrings at run time; where the source cannot be read (a frozen
application without ``.py`` files) the decorator leaves the class as it is and
:func:`field_docs` returns ``{}``.
"""

from __future__ import annotations

import ast
import dataclasses
import functools
import inspect
import linecache
import re
import sys
import typing
from typing import NamedTuple

_UNIT = re.compile(r"\[([^\[\]]+)\]\s*$")
_ATTR = "__field_docs__"
_REGISTRY: dict[str, list[type]] = {}     # documented classes by name: resolves annotations imported for typing only


class FieldDocError(TypeError):
    """A dataclass field without an attribute docstring, or one whose docstring does not end with a unit."""


class FieldDoc(NamedTuple):
    """One field's documentation: its meaning (``doc``, without the unit) and its ``unit`` (``-``: dimensionless)."""

    doc: str
    unit: str


@functools.cache
def _module_tree(filename: str) -> ast.Module | None:
    lines = linecache.getlines(filename)
    return ast.parse("".join(lines), filename) if lines else None


def _top_level_class(filename: str, name: str) -> ast.ClassDef | None:
    """The ``ClassDef`` of the top-level class ``name`` parsed from its own lines only (cheap: no module parse)."""
    lines = linecache.getlines(filename)
    head = re.compile(rf"class {re.escape(name)}\b")
    starts = [i for i, line in enumerate(lines) if head.match(line)]
    if len(starts) != 1:
        return None
    end = next((j for j in range(starts[0] + 1, len(lines))
                if lines[j].strip() and not lines[j][0].isspace() and not lines[j].startswith(("#", ")"))), len(lines))
    try:
        node = ast.parse("".join(lines[starts[0]:end])).body[0]
    except SyntaxError:
        return None
    return node if isinstance(node, ast.ClassDef) and node.name == name else None


def _class_node(cls: type) -> ast.ClassDef | None:
    """The ``ClassDef`` of ``cls`` in its module's source (followed along ``__qualname__``), None without source."""
    try:
        filename = inspect.getsourcefile(cls)
    except TypeError:       # built-in or defined in __main__ without a file
        return None
    if filename is None:
        return None
    if "." not in cls.__qualname__:
        node = _top_level_class(filename, cls.__name__)
        if node is not None:
            return node
    tree = _module_tree(filename)
    if tree is None:
        return None
    body: list[ast.stmt] = tree.body
    node = None
    for part in cls.__qualname__.split("."):
        if part == "<locals>":          # a class made inside a function: search that function's body
            continue
        found = [n for n in body if isinstance(n, (ast.ClassDef, ast.FunctionDef)) and n.name == part]
        if not found:
            found = [n for n in ast.walk(ast.Module(body=body, type_ignores=[]))
                     if isinstance(n, (ast.ClassDef, ast.FunctionDef)) and n.name == part]
        if not found:
            return None
        node = found[-1]
        body = node.body
    return node if isinstance(node, ast.ClassDef) else None


def _attribute_docstrings(node: ast.ClassDef) -> dict[str, str]:
    """{name: docstring} of the annotated assignments in a class body followed directly by a string."""
    out: dict[str, str] = {}
    body = node.body
    for stmt, nxt in zip(body, body[1:]):
        if (isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name)
                and isinstance(nxt, ast.Expr) and isinstance(nxt.value, ast.Constant)
                and isinstance(nxt.value.value, str)):
            out[stmt.target.id] = " ".join(inspect.cleandoc(nxt.value.value).split())
    return out


def _parse(cls: type) -> dict[str, FieldDoc] | None:
    """The field docs of dataclass ``cls`` from its source (base classes' fields from theirs); None without source."""
    texts: dict[str, str] = {}
    seen_source = False
    for klass in reversed(cls.__mro__):
        if klass is object or not dataclasses.is_dataclass(klass):
            continue
        node = _class_node(klass)
        if node is not None:
            seen_source = True
            texts.update(_attribute_docstrings(node))
    if not seen_source:
        return None
    out: dict[str, FieldDoc] = {}
    for f in dataclasses.fields(cls):
        text = texts.get(f.name)
        if not text:
            raise FieldDocError(f"{cls.__module__}.{cls.__qualname__}.{f.name}: no attribute docstring under the "
                                f"field (write its meaning and unit, e.g. \"\"\"normal load [N]\"\"\")")
        unit = _UNIT.search(text)
        if unit is None:
            raise FieldDocError(f"{cls.__module__}.{cls.__qualname__}.{f.name}: its docstring {text!r} does not end "
                                f"with a unit in square brackets ([-] for a dimensionless number)")
        out[f.name] = FieldDoc(text[:unit.start()].rstrip(" ,;:"), unit.group(1).strip())
    return out


def _wrap(text: str, width: int = 92) -> list[str]:
    """``text`` in lines of at most ``width`` characters (greedy, at spaces; a longer word stays whole)."""
    lines, line = [], ""
    for word in text.split():
        if line and len(line) + 1 + len(word) > width:
            lines.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    return lines + [line] if line else lines


def _fields_section(docs: dict[str, FieldDoc]) -> str:
    items = "\n".join(f"    {name} [{d.unit}]" + "".join(f"\n        {line}" for line in _wrap(d.doc))
                      for name, d in docs.items())
    return f"Fields (name [unit], meaning):\n\n{items}\n"


def document_fields(cls: type) -> type:
    """Class decorator (above ``@dataclass``): check and record each field's docstring and unit and list them
    in the class ``__doc__``; raises :class:`FieldDocError` naming a field without a docstring or unit."""
    if not dataclasses.is_dataclass(cls):
        raise TypeError(f"document_fields: {cls.__qualname__} is not a dataclass (put @dataclass below it)")
    docs = _parse(cls)
    if docs is None:
        return cls
    setattr(cls, _ATTR, docs)
    _REGISTRY.setdefault(cls.__name__, []).append(cls)
    head = inspect.cleandoc(cls.__doc__ or "")
    if head.startswith(cls.__name__ + "("):      # the signature dataclass writes for a class without a docstring
        head = ""
    cls.__doc__ = (head + "\n\n" if head else "") + _fields_section(docs)
    return cls


def field_docs(cls: type) -> dict[str, FieldDoc]:
    """``{field name: FieldDoc(doc, unit)}`` of a dataclass, in field order (read from the source if ``cls`` is
    not decorated with :func:`document_fields`; ``{}`` without source)."""
    docs = cls.__dict__.get(_ATTR)
    if docs is None:
        docs = _parse(cls) or {}
    return dict(docs)


def is_documented(cls: type) -> bool:
    """Whether ``cls`` went through :func:`document_fields` (its own fields, not only a base class's)."""
    return _ATTR in cls.__dict__


def _field_types(cls: type) -> dict[str, list[type]]:
    """{field: the dataclass types in its annotation} (``X | None``, ``tuple[X, X]`` …).  Names that the defining
    module imports for typing only (``if TYPE_CHECKING:``) resolve to the documented class of that name."""
    registry = {name: classes[0] for name, classes in _REGISTRY.items() if len(classes) == 1}
    namespaces = [vars(sys.modules[k.__module__]) for k in cls.__mro__ if k.__module__ in sys.modules]
    out: dict[str, list[type]] = {}
    for f in dataclasses.fields(cls):
        tp = f.type
        if isinstance(tp, str):
            ns = {**registry}
            for module_ns in reversed(namespaces):
                ns.update(module_ns)
            try:
                tp = eval(tp, ns)       # an annotation of femgear's own source
            except Exception:           # an annotation naming what is not importable here: not a documented type
                continue
        out[f.name] = [t for t in _leaves(tp) if isinstance(t, type) and dataclasses.is_dataclass(t)]
    return out


def _leaves(tp) -> list:
    args = typing.get_args(tp)
    return [tp] if not args else [t for a in args for t in _leaves(a)]


def field_tree(cls: type, stop: tuple[str, ...] = ()) -> dict[type, str]:
    """Every dataclass reachable from ``cls`` through its fields' annotations, with the first field path that
    reaches it (``"RunResult.stiffness.ltca"``); classes named in ``stop`` (inputs documented elsewhere) and
    what lies behind them are left out."""
    seen: dict[type, str] = {}

    def walk(klass: type, path: str) -> None:
        if klass in seen or klass.__name__ in stop:
            return
        seen[klass] = path
        for name, types in _field_types(klass).items():
            for t in types:
                walk(t, f"{path}.{name}")

    walk(cls, cls.__name__)
    return seen


def units_table(cls: type, stop: tuple[str, ...] = ()) -> dict[str, str]:
    """``{field path: unit}`` of every documented leaf field reachable from ``cls`` (``"contact.hertz_pressure":
    "Pa"``); a field holding a documented dataclass is replaced by that class's fields.  ``stop`` as in
    :func:`field_tree`."""
    out: dict[str, str] = {}

    def walk(klass: type, prefix: str, trail: tuple[type, ...]) -> None:
        types = _field_types(klass)
        for name, doc in field_docs(klass).items():
            nested = [t for t in types.get(name, []) if t.__name__ not in stop and t not in trail]
            if nested:
                for t in dict.fromkeys(nested):
                    walk(t, f"{prefix}{name}.", trail + (t,))
            elif not any(t.__name__ in stop for t in types.get(name, [])):
                out[f"{prefix}{name}"] = doc.unit

    walk(cls, "", (cls,))
    return out
