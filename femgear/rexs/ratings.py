"""The scene's ``[rating]`` table and ``[physics]`` levels in REXS, both ways: femgear's custom attributes.

REXS 1.4 has no attributes for the application factor, the required life, the lubrication method or
femgear's fidelity levels, so an export through the REXS attributes alone lost the rating: on the marine
pair S_H went from 1.35 to 1.51 and S_F from 2.64 to 3.31 on re-import (issue 37).  Every ``[rating]`` key
is written as ``custom_femgear_<key>`` on each cylindrical stage (its per-member lists ``roughness_ra``,
``root_roughness_rz`` on the member's first gear half; ``roughness_rz`` is REXS's own
``averaged_peak_to_valley_height_flank``), every level as ``custom_femgear_physics_<submodel>``; a key at
None is not written.  ``rating.oil_viscosity_40`` (which sets Z_L and Z_v) is
``custom_femgear_rating_oil_viscosity_40``: in a model femgear wrote (it carries
``custom_femgear_lubrication_method``) the rating's ν40 is that one or, absent, none, whatever the
lubricant's ν40 (which the export writes from the oil law); in a model from elsewhere the lubricant's
``viscosity_at_40_degree_celsius`` sets it, as before.
"""

from __future__ import annotations

from femgear.rexs.convert import MEMBERS, Conversion
from femgear.rexs.model import Attribute
from femgear.rexs.units import normalise

#: [rating] keys of one value, written on the stage as ``custom_femgear_<key>`` (the ν40 under its own id)
STAGE_KEYS = ("application_factor", "dynamic_factor", "face_load_factor", "transverse_load_factor",
              "contact_stress_limit", "min_safety_factor", "life_hours", "work_hardening_factor", "size_factor",
              "bending_stress_limit", "bending_min_safety_factor", "finishing", "oil_type", "scuffing_load_stage",
              "micropitting_load_stage", "lubrication_method", "structural_factor", "fillet_fe",
              "load_factors", "accuracy_grade")
NU40 = "custom_femgear_rating_oil_viscosity_40"
MARKER = "custom_femgear_lubrication_method"     #: always written by femgear's export
MEMBER_KEYS = ("root_roughness_rz", "roughness_ra")
LEVELS = ("stiffness", "lubrication", "thermal", "wear", "dynamics", "coupling")


def stage_values(scene) -> dict:
    """The custom attributes of the rating and the levels for a cylindrical stage (scene units; None: not written)."""
    r = scene.rating
    out = {f"custom_femgear_{key}": getattr(r, key) for key in STAGE_KEYS}
    out.update({f"custom_femgear_physics_{level}": getattr(scene.physics, level) for level in LEVELS})
    return out


def nu40_attribute(scene) -> Attribute | None:
    """``rating.oil_viscosity_40`` as written, in mm²/s (the scene's own unit for it: no conversion, so it comes
    back to the last digit), or None."""
    nu = scene.rating.oil_viscosity_40
    return None if nu is None else Attribute(NU40, "mm^2 / s", float(nu))


def _nu40(conv: Conversion):
    """(ν40 [mm²/s], sources) of the stages' :data:`NU40` (checked and agreed like any attribute), or (None, [])."""
    si, src = conv.agree(conv.parts.stages, NU40, "the rating's ν40")
    if si is None:
        return None, []
    comp = src[0][0]
    raw = conv.model.attribute(comp, NU40)
    return (float(raw.value) if normalise(raw.unit) == "mm^2 / s" else si * 1e6), src


def member_values(scene, member: int) -> dict:
    """The custom attributes of the rating's per-member lists for the gear of ``member`` (0 pinion, 1 gear)."""
    r = scene.rating
    return {f"custom_femgear_{key}": None if getattr(r, key) is None else getattr(r, key)[member]
            for key in MEMBER_KEYS}


def ratings(conv: Conversion) -> None:
    """``[rating]`` and ``[physics]`` from femgear's custom attributes (after :func:`femgear.rexs.tables.oil`)."""
    stages = conv.parts.stages
    for key in STAGE_KEYS:
        value, src = conv.agree(stages, f"custom_femgear_{key}", f"the rating's {key.replace('_', ' ')}")
        if value is not None:
            conv.put(f"rating.{key}", value, src)
    if conv.agree(stages, MARKER, "the lubrication method")[0] is not None:     # written by femgear
        nu40, src = _nu40(conv)
        conv.drop("rating.oil_viscosity_40")
        if nu40 is not None:
            conv.put("rating.oil_viscosity_40", nu40, src)
    for key in MEMBER_KEYS:
        values = [conv.agree(halves[:1], f"custom_femgear_{key}", f"the {name}'s {key.replace('_', ' ')}")
                  for name, halves in zip(MEMBERS, conv.parts.members, strict=True)]
        if all(v is not None for v, _ in values):
            conv.put(f"rating.{key}", [v for v, _ in values], [s for _, src in values for s in src])
    for level in LEVELS:
        value, src = conv.agree(stages, f"custom_femgear_physics_{level}", f"the {level} level")
        if value is not None:
            conv.put(f"physics.{level}", value, src)
