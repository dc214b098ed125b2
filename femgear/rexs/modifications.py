"""Flank modifications of a REXS stage → ``[modifications]`` (ISO 21771 §§8–9 terms).

REXS holds modifications per flank (left, right) of each gear; a femgear member has one set for
both flanks and both helices, so they must agree (else one line names both).  Mapping:

- ``tip_relief``: depth C_αa → ``tip_relief``, datum length L_Ca → ``tip_relief_length`` (a roll
  length in both), ``shape_of_relief`` linear/parabolic; ``root_relief`` likewise;
- ``helix_crowning``: the amounts at the datum and non-datum face must agree → ``crowning``;
- ``end_relief_datum_face`` and ``end_relief_non_datum_face``: depth and length must agree →
  ``end_relief``, ``end_relief_length``;
- ``helix_slope`` C_Hβ of the pinion and gear half of a helix add up to femgear's
  ``helix_slope_deviation_left/right`` of that helix (both open the gap at the outer end);
- other modification types (profile crowning, profile slope, topography, ...) are listed in the
  scene as in the model but not used.
"""

from __future__ import annotations

from femgear.rexs.convert import MEMBERS, Conversion
from femgear.rexs.lookup import OTHER_MODIFICATIONS, flanks_of, modifications_of

#: (component type, attribute) -> femgear key (amounts and lengths)
KEYS = {("tip_relief", "tip_relief_depth"): "tip_relief", ("tip_relief", "tip_relief_datum_length"): "tip_relief_length",
        ("tip_relief", "shape_of_relief"): "tip_relief_shape",
        ("root_relief", "root_relief_depth"): "root_relief", ("root_relief", "root_relief_datum_length"): "root_relief_length",
        ("root_relief", "shape_of_relief"): "root_relief_shape",
        ("helix_crowning", "helix_crowning_amount_datum_face"): "crowning",
        ("helix_crowning", "helix_crowning_amount_non_datum_face"): "crowning",
        ("end_relief_datum_face", "end_relief_depth_datum_face"): "end_relief",
        ("end_relief_datum_face", "end_relief_length_datum_face"): "end_relief_length",
        ("end_relief_non_datum_face", "end_relief_depth_non_datum_face"): "end_relief",
        ("end_relief_non_datum_face", "end_relief_length_non_datum_face"): "end_relief_length",
        ("helix_slope", "helix_slope"): "helix_slope"}
SHAPES = ("linear", "parabolic")


def _flank_values(conv: Conversion, flank) -> dict[str, tuple]:
    """femgear key -> (value, [(component, attribute)]) of one flank; values of one key must agree."""
    model = conv.model
    out: dict[str, tuple] = {}
    for mod in modifications_of(model, flank):
        if mod.type in OTHER_MODIFICATIONS:
            conv.unused.append(f"{mod.label()} on flank {flank.id}: femgear has no {mod.type.replace('_', ' ')}")
            continue
        for (ctype, attr), key in KEYS.items():
            if ctype != mod.type or (value := model.value(mod, attr)) is None:
                continue
            if key.endswith("_shape") and value not in SHAPES:
                raise model.error(mod, attr, f"shape {value!r} is not supported (femgear: linear or parabolic)")
            if key in out and out[key][0] != value:
                first = out[key][1][0]
                raise model.error(mod, attr, f"{value!r} differs from {first[0].label()} attribute {first[1]} "
                                             f"({out[key][0]!r}): femgear has one {key.replace('_', ' ')} at both faces")
            out.setdefault(key, (value, []))[1].append((mod, attr))
    return out


def _member_values(conv: Conversion, halves) -> tuple[dict[str, tuple], list[dict[str, tuple]]]:
    """The modifications every flank of the member's halves has in common; and the per-half values."""
    model = conv.model
    per_half = []
    result: dict[str, tuple] | None = None
    ref = None
    for half in halves:
        merged: dict[str, tuple] = {}
        for flank in flanks_of(model, half):
            values = _flank_values(conv, flank)
            if result is None:
                result, ref = values, flank
            elif {k: v[0] for k, v in values.items() if k != "helix_slope"} != \
                    {k: v[0] for k, v in result.items() if k != "helix_slope"}:
                raise model.error(flank, None, f"its modifications differ from those of {ref.label()}: femgear has "
                                               "one set of modifications per member (both flanks, both helices)")
            for k, (v, src) in values.items():
                if k in merged and merged[k][0] != v:
                    raise model.error(src[0][0], src[0][1], f"{v!r} differs from the other flank's {merged[k][0]!r}: "
                                                            f"femgear has one {k.replace('_', ' ')} per helix")
                merged.setdefault(k, (v, []))[1].extend(src)
        per_half.append(merged)
    return result or {}, per_half


def modifications(conv: Conversion) -> None:
    """``[modifications]`` (shared keys when both members agree, else per member)."""
    parts = conv.parts
    members = [_member_values(conv, halves) for halves in parts.members]
    tables = [{k: v for k, v in common.items() if k != "helix_slope"} for common, _ in members]
    if tables[0] or tables[1]:
        same = {k: v[0] for k, v in tables[0].items()} == {k: v[0] for k, v in tables[1].items()}
        for i, name in enumerate(MEMBERS):
            if same and i == 1:
                break
            prefix = "modifications" if same else f"modifications.{name}"
            for key, (value, src) in tables[i].items():
                sources = src + (tables[1][key][1] if same else [])
                conv.put(f"{prefix}.{key}", value, sources)
    slopes = [[half.get("helix_slope") for half in per_half] for _, per_half in members]
    for h, side in enumerate(("left", "right")[:len(parts.members[0])]):
        found = [s[h] for s in slopes if h < len(s) and s[h] is not None]
        if found:
            conv.put(f"modifications.helix_slope_deviation_{side}", sum(v for v, _ in found),
                     [x for _, src in found for x in src])
