"""Reading a REXS file (XML ``.rexs``, JSON ``.rexsj``, zipped ``.rexsz``) into a :class:`Model`.

The file comes from elsewhere, so it is treated as untrusted:

- XML is parsed with :mod:`defusedxml` with DTDs forbidden: entity expansion ("billion laughs")
  and external entities (XXE) are refused before anything is expanded;
- a file larger than :data:`MAX_MODEL_BYTES` is refused before it is read;
- in a zip, the model member's declared size is checked and at most :data:`MAX_MODEL_BYTES` + 1
  bytes are inflated (a zip bomb stops there); nothing is ever extracted to disk;
- every structural fault (truncated XML, JSON of another schema, a value of the wrong type) is a
  :class:`RexsError` naming the component and attribute where there is one.

Versions 1.0–1.4 are read (component types renamed since, and the old angle unit, are mapped to
their 1.4 names, :mod:`femgear.rexs.database`); a later 1.x is read with a warning.
"""

from __future__ import annotations

import io
import json
import logging
import math
import zipfile
from pathlib import Path
from typing import Any

from femgear.rexs.database import COMPONENT_RENAMES, UNIT_RENAMES, VERSIONS
from femgear.rexs.model import Attribute, Component, Model, Ref, Relation, RexsError, value_kind
from femgear.rexs.units import normalise

log = logging.getLogger(__name__)

MAX_MODEL_BYTES = 64 << 20    #: largest model read (file, or inflated zip member) [bytes]
MODEL_SUFFIXES = (".rexs", ".rexsj")
SUFFIXES = (".rexs", ".rexsj", ".rexsz")


def is_rexs_path(path: str | Path) -> bool:
    """True for a file name ending in .rexs, .rexsj or .rexsz (any case)."""
    return Path(path).suffix.lower() in SUFFIXES


def read_model(path: str | Path, load_case: int | None = None) -> Model:
    """Read and normalise a REXS file; ``load_case`` picks a load case by id (default: the first)."""
    path = Path(path)
    source = path.name
    try:
        size = path.stat().st_size
        if path.is_dir():
            raise RexsError(str(path), "is a folder, not a REXS file")
        if size > MAX_MODEL_BYTES:
            raise RexsError(str(path), f"{size} bytes is too large for a REXS model (limit {MAX_MODEL_BYTES})")
        data = path.read_bytes()
    except FileNotFoundError:
        raise RexsError(str(path), "REXS file not found") from None
    except OSError as exc:
        raise RexsError(str(path), f"cannot read the REXS file: {exc.strerror or exc}") from None
    if data[:4] == b"PK\x03\x04" or path.suffix.lower() == ".rexsz":
        data, member = _zip_member(data, source)
        source = f"{source}:{member}"
    head = data.lstrip(b"\xef\xbb\xbf \t\r\n")[:1]
    is_json = head in (b"{", b"[") or (head != b"<" and source.lower().endswith(".rexsj"))
    raw = _parse_json(data, source) if is_json else _parse_xml(data, source)
    return _select_load_case(raw, source, load_case)


def _zip_member(data: bytes, source: str) -> tuple[bytes, str]:
    """The one .rexs/.rexsj member of a zip, inflated up to the size cap."""
    try:
        archive = zipfile.ZipFile(io.BytesIO(data))
        infos = archive.infolist()
    except (zipfile.BadZipFile, EOFError, ValueError) as exc:
        raise RexsError(source, f"not a readable zip archive ({exc})") from None
    models = [i for i in infos if not i.is_dir() and i.filename.lower().endswith(MODEL_SUFFIXES)
              and not i.filename.startswith("__MACOSX/") and not Path(i.filename).name.startswith("._")]
    if not models:
        found = ", ".join(i.filename for i in infos[:5]) or "nothing"
        raise RexsError(source, f"the zip holds no REXS model (.rexs or .rexsj); found: {found}")
    if len(models) > 1:
        raise RexsError(source, "the zip holds several REXS models: " + ", ".join(i.filename for i in models[:5]))
    info = models[0]
    if info.file_size > MAX_MODEL_BYTES:
        raise RexsError(f"{source}:{info.filename}", f"declares {info.file_size} bytes inflated, over the limit "
                                                     f"of {MAX_MODEL_BYTES} (a zip bomb?)")
    try:
        with archive.open(info) as member:
            out = member.read(MAX_MODEL_BYTES + 1)
    except (zipfile.BadZipFile, EOFError, OSError, ValueError, NotImplementedError) as exc:
        raise RexsError(f"{source}:{info.filename}", f"cannot inflate the zip member ({exc})") from None
    if len(out) > MAX_MODEL_BYTES:
        raise RexsError(f"{source}:{info.filename}", f"inflates to more than {MAX_MODEL_BYTES} bytes (a zip bomb?)")
    return out, info.filename


# ---------------------------------------------------------------- XML

def _parse_xml(data: bytes, source: str) -> dict:
    from xml.etree.ElementTree import ParseError

    from defusedxml import DefusedXmlException
    from defusedxml.ElementTree import fromstring

    try:
        root = fromstring(data, forbid_dtd=True, forbid_entities=True, forbid_external=True)
    except DefusedXmlException as exc:
        raise RexsError(source, f"refused: the XML declares a DTD or entities ({type(exc).__name__}); entity "
                                "expansion and external entities are not allowed in a REXS model") from None
    except ParseError as exc:
        line, col = getattr(exc, "position", (0, 0))
        raise RexsError(source, f"not well-formed XML (line {line}, column {col}): truncated or damaged file") from None
    if root.tag != "model":
        raise RexsError(source, f"the XML root element is <{root.tag}>, not a REXS <model>")
    relations = [_xml_relation(r, source) for r in root.findall("./relations/relation")]
    components = [_xml_component(c, source) for c in root.findall("./components/component")]
    cases = [(int(_int(lc.get("id"), source, "load_case id")),
              [_xml_component(c, source) for c in lc.findall("./component")])
             for lc in root.findall("./load_spectrum/load_case")]
    return {"version": root.get("version"), "application": root.get("applicationId", ""),
            "relations": relations, "components": components, "load_cases": cases}


def _int(text: Any, source: str, what: str) -> int:
    try:
        return int(str(text).strip())
    except (TypeError, ValueError):
        raise RexsError(source, f"{what} must be an integer (got {text!r})") from None


def _xml_relation(el, source: str) -> Relation:
    rid = _int(el.get("id"), source, "relation id")
    refs = tuple(Ref(_int(r.get("id"), source, f"relation {rid}: ref id"), r.get("role", ""), r.get("hint", ""))
                 for r in el.findall("ref"))
    order = el.get("order")
    return Relation(rid, el.get("type", ""), refs, None if order is None else _int(order, source, "relation order"))


def _xml_component(el, source: str) -> Component:
    cid = _int(el.get("id"), source, "component id")
    ctype = COMPONENT_RENAMES.get(el.get("type", ""), el.get("type", ""))
    comp = Component(cid, ctype, el.get("name", ""))
    for a in el.findall("attribute"):
        aid = a.get("id", "")
        kind = value_kind(ctype, aid)
        text = a.text or ""
        value = text if kind is None else _xml_value(text, kind, comp, aid, source)
        comp.attributes[aid] = Attribute(aid, _unit(a.get("unit")), value)
    return comp


def _xml_value(text: str, kind: str, comp: Component, aid: str, source: str) -> Any:
    text = text.strip()
    where = f"{source}, {comp.label()}, attribute {aid}"
    try:
        if kind == "floating_point":
            return float(text)
        if kind == "integer":
            return int(text)
        if kind == "boolean":
            if text.lower() not in ("true", "false"):
                raise ValueError
            return text.lower() == "true"
    except ValueError:
        raise RexsError(where, f"{text!r} is not a valid {kind.replace('_', ' ')} value") from None
    return text


def _unit(unit: str | None) -> str | None:
    unit = normalise(unit)
    return UNIT_RENAMES.get(unit, unit) if unit else None


# ---------------------------------------------------------------- JSON

_JSON_KINDS = {"floating_point": ("floating_point", "integer"), "integer": ("integer",), "boolean": ("boolean",),
               "enum": ("enum", "string"), "string": ("string", "enum")}


def _parse_json(data: bytes, source: str) -> dict:
    try:
        doc = json.loads(data.decode("utf-8"), parse_constant=_no_constant)
    except UnicodeDecodeError as exc:
        raise RexsError(source, f"not UTF-8 text (invalid byte at {exc.start})") from None
    except RecursionError:
        raise RexsError(source, "JSON nested too deeply to be a REXS model") from None
    except json.JSONDecodeError as exc:
        raise RexsError(source, f"not valid JSON (line {exc.lineno}, column {exc.colno}): truncated or damaged "
                                "file") from None
    model = doc.get("model") if isinstance(doc, dict) else None
    if not isinstance(model, dict):
        raise RexsError(source, 'JSON of another schema: no "model" object at the top (REXS JSON is '
                                '{"model": {"version", "relations", "components", ...}})')
    rels = _list(model, "relations", source, "model")
    comps = _list(model, "components", source, "model")
    spectrum = model.get("load_spectrum") or {}
    if not isinstance(spectrum, dict):
        raise RexsError(source, 'JSON of another schema: "model.load_spectrum" must be an object')
    cases = []
    for i, lc in enumerate(_list(spectrum, "load_cases", source, "model.load_spectrum", required=False)):
        where = f"model.load_spectrum.load_cases[{i}]"
        lc = _obj(lc, source, where)
        cases.append((_json_int(lc, "id", source, where),
                      [_json_component(c, source, f"{where}.components[{j}]")
                       for j, c in enumerate(_list(lc, "components", source, where))]))
    return {"version": model.get("version"), "application": str(model.get("applicationId", "")),
            "relations": [_json_relation(r, source, f"model.relations[{i}]") for i, r in enumerate(rels)],
            "components": [_json_component(c, source, f"model.components[{i}]") for i, c in enumerate(comps)],
            "load_cases": cases}


def _no_constant(name: str):
    raise json.JSONDecodeError(f"{name} is not a finite number", name, 0)


def _obj(x: Any, source: str, where: str) -> dict:
    if not isinstance(x, dict):
        raise RexsError(source, f"JSON of another schema: {where} must be an object (got {type(x).__name__})")
    return x


def _list(obj: dict, key: str, source: str, where: str, required: bool = True) -> list:
    if key not in obj and not required:
        return []
    value = obj.get(key)
    if not isinstance(value, list):
        raise RexsError(source, f'JSON of another schema: {where}.{key} must be a list (got '
                                f'{type(value).__name__ if key in obj else "nothing"})')
    return value


def _json_int(obj: dict, key: str, source: str, where: str) -> int:
    value = obj.get(key)
    if isinstance(value, bool) or not isinstance(value, int):
        raise RexsError(source, f"JSON of another schema: {where}.{key} must be an integer (got {value!r})")
    return value


def _json_relation(r: Any, source: str, where: str) -> Relation:
    r = _obj(r, source, where)
    refs = []
    for i, ref in enumerate(_list(r, "refs", source, where)):
        ref = _obj(ref, source, f"{where}.refs[{i}]")
        refs.append(Ref(_json_int(ref, "id", source, f"{where}.refs[{i}]"), str(ref.get("role", "")),
                        str(ref.get("hint", ""))))
    order = r.get("order")
    return Relation(_json_int(r, "id", source, where), str(r.get("type", "")), tuple(refs),
                    order if isinstance(order, int) else None)


def _json_component(c: Any, source: str, where: str) -> Component:
    c = _obj(c, source, where)
    ctype = str(c.get("type", ""))
    comp = Component(_json_int(c, "id", source, where), COMPONENT_RENAMES.get(ctype, ctype), str(c.get("name", "")))
    for i, a in enumerate(_list(c, "attributes", source, where, required=False)):
        a = _obj(a, source, f"{where}.attributes[{i}]")
        aid = a.get("id")
        if not isinstance(aid, str):
            raise RexsError(f"{source}, {comp.label()}", f"JSON of another schema: attributes[{i}] has no text \"id\"")
        kind = value_kind(comp.type, aid)
        comp.attributes[aid] = Attribute(aid, _unit(a.get("unit")), _json_value(a, kind, comp, aid, source))
    return comp


def _json_value(a: dict, kind: str | None, comp: Component, aid: str, source: str) -> Any:
    keys = [k for k in a if k not in ("id", "unit")]
    if kind is None:
        return a[keys[0]] if keys else None
    for key in _JSON_KINDS[kind]:
        if key in a:
            value = a[key]
            if kind == "floating_point" and isinstance(value, (int, float)) and not isinstance(value, bool):
                return float(value) if math.isfinite(value) else value
            return value
    raise RexsError(f"{source}, {comp.label()}, attribute {aid}",
                    f"JSON of another schema: no {kind} value (the attribute holds {', '.join(keys) or 'no value'})")


# ---------------------------------------------------------------- normalised model

def _select_load_case(raw: dict, source: str, load_case: int | None) -> Model:
    version = raw["version"]
    if not isinstance(version, str) or not version:
        raise RexsError(source, "the model declares no REXS version")
    major, _, minor = version.partition(".")
    if version not in VERSIONS:
        if major == "1" and minor.isdigit() and int(minor) > 4:
            log.warning("%s: REXS %s is newer than 1.4; reading it with the 1.4 attribute ids", source, version)
        else:
            raise RexsError(source, f"REXS version {version!r} is not supported (femgear reads 1.0–1.4)")
    components: dict[int, Component] = {}
    for comp in raw["components"]:
        if comp.id in components:
            raise RexsError(f"{source}, {comp.label()}", "a second component with this id")
        components[comp.id] = comp
    cases = {cid: comps for cid, comps in raw["load_cases"]}
    chosen: dict[int, dict[str, Attribute]] = {}
    if load_case is not None and load_case not in cases:
        raise RexsError(source, f"--load-case {load_case}: the model holds load cases "
                                f"{', '.join(map(str, cases)) or '(none)'}")
    if cases:
        pick = load_case if load_case is not None else next(iter(cases))
        for comp in cases[pick]:
            chosen.setdefault(comp.id, {}).update(comp.attributes)
        if pick is not None:
            log.info("%s: load case %s of %d", source, pick, len(cases))
    return Model(source, version, raw["application"], components, tuple(raw["relations"]), tuple(cases), chosen)
