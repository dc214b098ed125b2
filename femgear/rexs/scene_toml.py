"""The commented scene file of a converted REXS stage (``femgear rexs FILE --stage ID -o scene.toml``).

Every value carries a comment naming the REXS component id(s) and attribute id it came from; the
head of the file lists every femgear key the model did not provide: first those femgear filled with
a stated default (why), then every other scene key at the schema default.  Written by hand (TOML
has no comment-preserving writer in the standard library); numbers use Python's shortest
round-trip form, so the file re-reads to the same doubles.
"""

from __future__ import annotations

import json
from typing import Any

from pydantic import BaseModel

from femgear.rexs.convert import Conversion


def toml_value(value: Any) -> str:
    """A TOML literal: bool, int, float (round-trip exact), string, list of those."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    raise TypeError(f"no TOML form for {value!r}")


def _sources_comment(conv: Conversion, key: str) -> str:
    if key in conv.overridden:
        return "set on the command line (--set)"
    if key in conv.defaults:
        return f"not in the model: default used ({conv.defaults[key]})"
    sources = conv.sources.get(key) or []
    if not sources:
        return f"REXS {conv.stage.label()}"
    by_attr: dict[str, list[int]] = {}
    for comp, attr in sources:
        ids = by_attr.setdefault(attr, [])
        if comp.id not in ids:
            ids.append(comp.id)
    parts = [f"component{'s' if len(ids) > 1 else ''} {', '.join(map(str, ids))} attribute {attr}"
             for attr, ids in by_attr.items()]
    return "REXS " + "; ".join(parts)


def _leaves(prefix: str, node: BaseModel):
    """(dotted key, value) of every leaf of a validated scene table (sub-tables recursed)."""
    for name in type(node).model_fields:
        value = getattr(node, name)
        key = f"{prefix}.{name}"
        if isinstance(value, BaseModel):
            yield from _leaves(key, value)
        else:
            yield key, value


def scene_toml(conv: Conversion, scene) -> str:
    """The scene file text: head (sources, defaults), then the tables with a comment per value."""
    model, stage = conv.model, conv.stage
    lines = [f"# femgear scene from REXS {model.version}: {model.source} ({model.application or 'unknown tool'}), "
             f"stage {stage.id} \"{stage.name}\", a {conv.parts.kind} pair",
             "# written by `femgear rexs`; each value's comment names the REXS component id(s) and attribute id it",
             "# came from (several: they agree; derived values name what they were derived from).",
             "#", "# not in the model: default used"]
    lines += [f"#   {key} = {toml_value(conv.get(key))}  ({why})" for key, why in conv.defaults.items()]
    lines += ["#", "# not in the model: femgear's schema default used (REXS holds no such data)"]
    for section in type(scene).model_fields:
        value = getattr(scene, section)
        leaves = _leaves(section, value) if isinstance(value, BaseModel) else [(section, value)]
        for key, leaf in leaves:
            if conv.get(key) is None:
                lines.append(f"#   {key} = {'(none)' if leaf is None else toml_value(leaf)}")
    if conv.unused:
        lines += ["#", "# in the model but not used by femgear:"] + [f"#   {text}" for text in conv.unused]
    _tables(conv, conv.data, "", lines)
    return "\n".join(lines) + "\n"


def _tables(conv: Conversion, node: dict, prefix: str, lines: list[str]) -> None:
    leaves = {k: v for k, v in node.items() if not isinstance(v, dict)}
    if prefix and leaves:
        lines += ["", f"[{prefix}]"]
    for key, value in leaves.items():
        full = f"{prefix}.{key}" if prefix else key
        lines.append(f"{key} = {toml_value(value)}  # {_sources_comment(conv, full)}")
    for key, value in node.items():
        if isinstance(value, dict):
            _tables(conv, value, f"{prefix}.{key}" if prefix else key, lines)
