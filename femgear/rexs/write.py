"""Text of a REXS model: XML (``.rexs``) and JSON (``.rexsj``), REXS 1.4 layout.

Numbers are written with Python's shortest round-trip representation, so a value read back is
the same double.  The caller writes the text to disk (atomically, :mod:`femgear.edge.io.atomic`).
"""

from __future__ import annotations

import json
from datetime import UTC, datetime
from typing import Any
from xml.etree.ElementTree import Element, SubElement, indent, tostring

from femgear.rexs.model import Model, value_kind


def _text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _date() -> str:
    return datetime.now(UTC).replace(microsecond=0).isoformat()


def to_xml(model: Model, application_version: str = "") -> str:
    """The model as REXS XML text."""
    root = Element("model", {"applicationId": model.application, "applicationVersion": application_version,
                             "date": _date(), "version": model.version})
    rels = SubElement(root, "relations")
    for rel in model.relations:
        attrs = {"id": str(rel.id), "type": rel.type}
        if rel.order is not None:
            attrs["order"] = str(rel.order)
        el = SubElement(rels, "relation", attrs)
        for ref in rel.refs:
            SubElement(el, "ref", {"hint": ref.hint, "id": str(ref.id), "role": ref.role})
    comps = SubElement(root, "components")
    for comp in model.components.values():
        el = SubElement(comps, "component", {"id": str(comp.id), "name": comp.name, "type": comp.type})
        for attr in comp.attributes.values():
            a = SubElement(el, "attribute", {"id": attr.id, "unit": attr.unit or "none"})
            a.text = _text(attr.value)
    indent(root, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + tostring(root, encoding="unicode") + "\n"


def to_json(model: Model, application_version: str = "") -> str:
    """The model as REXS JSON text (typed value keys: ``floating_point``, ``integer``, ...)."""
    comps = []
    for comp in model.components.values():
        attrs = []
        for attr in comp.attributes.values():
            kind = value_kind(comp.type, attr.id) or "string"
            attrs.append({"id": attr.id, "unit": attr.unit or "none", kind: attr.value})
        comps.append({"id": comp.id, "type": comp.type, "name": comp.name, "attributes": attrs})
    rels = []
    for rel in model.relations:
        item: dict[str, Any] = {"id": rel.id, "type": rel.type}
        if rel.order is not None:
            item["order"] = rel.order
        item["refs"] = [{"id": r.id, "role": r.role, "hint": r.hint} for r in rel.refs]
        rels.append(item)
    doc = {"model": {"version": model.version, "applicationId": model.application,
                     "applicationVersion": application_version, "date": _date(), "relations": rels,
                     "components": comps}}
    return json.dumps(doc, indent=1, ensure_ascii=False, allow_nan=False) + "\n"
