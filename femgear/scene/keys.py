"""Every scene key with its type, default, unit and meaning, read from the schema.

The one source of the scene-key documentation: :mod:`femgear.scene.schema` holds a
``description`` on every field, ending in (or carrying) its unit in square brackets
(``[m]``, ``[N/m]``, ``[-]`` for dimensionless numbers); :func:`scene_keys` walks the
schema and returns one :class:`KeyDoc` per key.  The docs site's scene-key page, the
template of ``femgear new`` (:mod:`femgear.scene.template`) and the test that no key
lands undocumented (``tests/scene/test_key_docs.py``) all read it.
"""

from __future__ import annotations

import re
import types
import typing
from dataclasses import dataclass
from typing import Any, Literal

from pydantic import BaseModel
from pydantic_core import PydanticUndefined

from femgear.scene.schema import Scene

#: a unit in square brackets: letters, digits and unit signs only (not a key path like ``[modifications.pinion]``)
_UNIT = re.compile(r"\[([-A-Za-z0-9/^ ²³µ°·()]+)\]")


@dataclass(frozen=True)
class KeyDoc:
    """One scene key."""

    key: str                 #: dotted path, e.g. ``pair.backlash``
    table: str               #: the TOML table it sits in, e.g. ``pair`` or ``modifications.pinion``
    name: str                #: the key within its table
    type: str                #: human-readable type: float, int, str, bool, one of …, list of …
    required: bool           #: no default: the scene must give it
    default: Any             #: the default (None: none / derived, see the description)
    description: str         #: meaning and convention, with the unit
    unit: str | None         #: the unit from the description (``-`` dimensionless), None for text/choices
    numeric: bool            #: a number (or list of numbers): needs a unit


@dataclass(frozen=True)
class TableDoc:
    """One TOML table: its path, what it holds (the model's docstring) and whether it may be absent."""

    table: str
    doc: str
    optional: bool


def unit_of(description: str) -> str | None:
    """The unit in ``description`` (the first bracketed unit), or None."""
    m = _UNIT.search(description or "")
    return m.group(1).strip() if m else None


def _strip_none(annotation: Any) -> tuple[Any, bool]:
    """(annotation without ``None``, whether None was allowed)."""
    origin = typing.get_origin(annotation)
    if origin in (typing.Union, types.UnionType):
        args = [a for a in typing.get_args(annotation) if a is not type(None)]
        if len(args) == 1:
            return args[0], True
    return annotation, False


def _model(annotation: Any) -> type[BaseModel] | None:
    inner, _ = _strip_none(annotation)
    return inner if isinstance(inner, type) and issubclass(inner, BaseModel) else None


def _type_name(annotation: Any) -> tuple[str, bool]:
    """(readable type, numeric?)."""
    inner, _ = _strip_none(annotation)
    origin = typing.get_origin(inner)
    if origin is typing.Annotated:
        return _type_name(typing.get_args(inner)[0])
    if origin is Literal:
        return "one of " + ", ".join(f'"{a}"' for a in typing.get_args(inner)), False
    if origin is list:
        item, numeric = _type_name(typing.get_args(inner)[0])
        return f"list of {item}", numeric
    if inner is bool:
        return "bool", False
    if inner in (int, float):
        return inner.__name__, True
    if inner is str:
        return "str", False
    return str(inner), False


def _doc(model: type[BaseModel]) -> str:
    return " ".join((model.__doc__ or "").split("\n\n")[0].replace("``", "").split())


def scene_tables(model: type[BaseModel] = Scene, prefix: str = "") -> list[TableDoc]:
    """Every table of the scene, in schema order."""
    out: list[TableDoc] = []
    for name, field in model.model_fields.items():
        sub = _model(field.annotation)
        if sub is None:
            continue
        path = f"{prefix}{name}"
        out.append(TableDoc(path, _doc(sub), optional=field.default is None))
        out.extend(scene_tables(sub, prefix=f"{path}."))
    return out


def scene_keys(model: type[BaseModel] = Scene, prefix: str = "") -> list[KeyDoc]:
    """Every key of the scene (tables recursed into), in schema order."""
    out: list[KeyDoc] = []
    for name, field in model.model_fields.items():
        sub = _model(field.annotation)
        path = f"{prefix}{name}"
        if sub is not None:
            out.extend(scene_keys(sub, prefix=f"{path}."))
            continue
        type_name, numeric = _type_name(field.annotation)
        required = field.default is PydanticUndefined and field.default_factory is None
        description = " ".join((field.description or "").split())
        out.append(KeyDoc(key=path, table=prefix.rstrip("."), name=name, type=type_name, required=required,
                          default=None if required else field.default, description=description,
                          unit=unit_of(description), numeric=numeric))
    return out
