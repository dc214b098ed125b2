"""Following a REXS model's relations from a gear to what femgear reads about it.

Relation types and roles (REXS 1.4): ``flank`` (gear; left, right), ``stage_gear_data`` (stage, gear,
stage_gear_data), ``reference`` (origin; referenced: a material or lubricant), ``side`` (a bearing
as ``assembly``; the shaft as ``inner_part``), ``assembly``/``ordered_assembly`` (a flank as
``assembly``; its modifications as ``part``), ``manufacturing_step`` (the gear as ``workpiece``; the
tool as ``tool``).
"""

from __future__ import annotations

from femgear.rexs.model import Component, Model

#: flank modification components femgear reads (the others are reported as not used)
MODIFICATIONS = ("tip_relief", "root_relief", "helix_crowning", "helix_slope", "end_relief_datum_face",
                 "end_relief_non_datum_face")
#: modification components femgear cannot represent
OTHER_MODIFICATIONS = ("profile_crowning", "profile_slope", "profile_twist", "triangular_tip_relief",
                       "triangular_root_relief", "topographical_modification")


def _components(model: Model, ids: list[int], *types: str) -> list[Component]:
    out = []
    for cid in ids:
        comp = model.components.get(cid)
        if comp is not None and (not types or comp.type in types) and comp not in out:
            out.append(comp)
    return out


def flanks_of(model: Model, gear: Component) -> list[Component]:
    """The gear's left and right flank components (those present), left first."""
    return [c for role in ("left", "right")
            for c in _components(model, model.related("flank", "gear", gear.id, role), "cylindrical_gear_flank")]


def modifications_of(model: Model, flank: Component) -> list[Component]:
    """Modification components assembled on a flank (``assembly`` or ``ordered_assembly``)."""
    ids = model.related("assembly", "assembly", flank.id, "part") + \
        model.related("ordered_assembly", "assembly", flank.id, "part")
    return _components(model, ids, *MODIFICATIONS, *OTHER_MODIFICATIONS)


def tools_of(model: Model, gear: Component) -> list[Component]:
    """Rack-shaped tools that made the gear (any relation naming it ``workpiece`` and a ``tool``)."""
    ids = []
    for rel in model.relations:
        if gear.id in rel.role("workpiece"):
            ids.extend(rel.role("tool"))
    return _components(model, ids, "rack_shaped_tool")


def referenced(model: Model, origin: Component, ctype: str) -> list[Component]:
    """Components of ``ctype`` that ``origin`` references (``reference`` relation)."""
    return _components(model, model.related("reference", "origin", origin.id, "referenced"), ctype)


def material_of(model: Model, gear: Component, shaft: Component | None) -> Component | None:
    """The gear's material: referenced by the gear, else by its shaft."""
    for origin in (gear, shaft):
        if origin is not None:
            found = referenced(model, origin, "material")
            if found:
                return found[0]
    return None


def lubricant_of(model: Model, stage: Component) -> Component | None:
    """The model's lubricant: the one the stage references, else the only one in the model."""
    found = referenced(model, stage, "lubricant")
    if found:
        return found[0]
    every = model.of_type("lubricant")
    if len(every) > 1:
        raise model.error(stage, None, "the model holds several lubricants (components "
                                       f"{', '.join(str(c.id) for c in every)}) and the stage references none")
    return every[0] if every else None


def gear_data(model: Model, stage: Component, gear: Component) -> Component | None:
    """The ``cylindrical_stage_gear_data`` of ``gear`` in ``stage``, or None."""
    for rel in model.relations:
        if rel.type == "stage_gear_data" and stage.id in rel.role("stage") and gear.id in rel.role("gear"):
            found = _components(model, rel.role("stage_gear_data"), "cylindrical_stage_gear_data")
            if found:
                return found[0]
    return None


def bearings_of(model: Model, shaft: Component | None) -> list[Component]:
    """Concept bearings carrying the shaft (``side`` relations with the shaft as inner part)."""
    if shaft is None:
        return []
    return _components(model, model.related("side", "inner_part", shaft.id, "assembly"), "concept_bearing")
