"""The stages of a REXS model, and the gear pair behind one cylindrical stage.

A ``cylindrical_stage`` names its two gears by a ``stage`` relation (roles ``gear_1``, ``gear_2``);
``gear_1`` becomes femgear's pinion.  A gear sits on a shaft by an ``assembly`` relation (shaft in
role ``assembly``, gear in role ``part``).  The pair kind:

- **double-helical**: each gear has, on its own shaft, a second gear of the same module, tooth count
  and helix angle of the opposite sign: the two halves of a herringbone member.  The halves usually
  mesh in a second cylindrical stage; either stage id selects the same pair;
- **spur**: helix angle 0; **single-helical** otherwise.

Other stage types (planetary, bevel, worm, ...), and cylindrical stages inside a planetary stage or
with an internal gear, are listed and refused with one line.
"""

from __future__ import annotations

from dataclasses import dataclass

from femgear.rexs.model import Component, Model

#: how each refused stage type is named
UNSUPPORTED = {"planetary_stage": "a planetary stage", "bevel_stage": "a bevel stage", "worm_stage": "a worm stage"}
GEAR_TYPES = ("cylindrical_gear",)


@dataclass(frozen=True)
class PairParts:
    """The components of one femgear pair: per member its gear halves (1, or 2 for double-helical)."""

    stages: tuple[Component, ...]             #: the cylindrical stage(s), one per helix
    members: tuple[tuple[Component, ...], tuple[Component, ...]]   #: (pinion halves, gear halves)
    shafts: tuple[Component | None, Component | None]
    kind: str                                 #: "double-helical", "single-helical" or "spur"


@dataclass(frozen=True)
class StageRow:
    """One line of ``femgear rexs FILE``."""

    id: int
    type: str
    name: str
    note: str                       #: the pair kind, or why the stage is refused
    supported: bool
    teeth: tuple[int, int] | None = None
    module: float | None = None     #: [m]
    helix_deg: float | None = None
    face_width: float | None = None  #: [m]
    centre_distance: float | None = None  #: [m]


def stage_components(model: Model) -> list[Component]:
    """Every stage of the model (``*_stage`` components), by id."""
    return sorted((c for c in model.components.values() if c.type.endswith("_stage")), key=lambda c: c.id)


def stage_gears(model: Model, stage: Component) -> tuple[Component, Component]:
    """(gear_1, gear_2) of a cylindrical stage's ``stage`` relation."""
    found = {}
    for role in ("gear_1", "gear_2"):
        ids = model.related("stage", "stage", stage.id, role)
        if len(ids) != 1:
            raise model.error(stage, None, f"needs one 'stage' relation naming its {role} (found {len(ids)})")
        found[role] = model.component(ids[0], stage, "gear")
    return found["gear_1"], found["gear_2"]


def _refusal(model: Model, stage: Component) -> str | None:
    """Why femgear cannot model this stage, or None."""
    if stage.type != "cylindrical_stage":
        return UNSUPPORTED.get(stage.type, f"a {stage.type.replace('_', ' ')}")
    for rel in model.relations:
        if any(r.id == stage.id for r in rel.refs) and any(
                model.components.get(r.id) is not None and model.components[r.id].type == "planetary_stage"
                for r in rel.refs):
            return "part of a planetary stage"
    for gear in stage_gears(model, stage):
        if gear.type not in GEAR_TYPES:
            return f"its gear {gear.id} is a {gear.type.replace('_', ' ')} (internal or not cylindrical)"
    return None


def shaft_of(model: Model, gear: Component) -> Component | None:
    """The shaft a gear is assembled on (an ``assembly`` relation), or None."""
    for sid in model.related("assembly", "part", gear.id, "assembly"):
        comp = model.components.get(sid)
        if comp is not None and comp.type == "shaft":
            return comp
    return None


def _signature(model: Model, gear: Component) -> tuple[int, float, float]:
    return (model.value(gear, "number_of_teeth", required=True), model.value(gear, "normal_module", required=True),
            model.value(gear, "helix_angle_reference_diameter", required=True))


def _shaft_mates(model: Model, gear: Component):
    """(other gear, {attribute: whether it agrees with ``gear`` as its opposite-hand half}) for every other gear on
    ``gear``'s shaft that has a tooth count, module and helix angle (none without a shaft)."""
    shaft = shaft_of(model, gear)
    if shaft is None:
        return
    z, m, beta = _signature(model, gear)
    for gid in model.related("assembly", "assembly", shaft.id, "part"):
        other = model.components.get(gid)
        if other is None or other.id == gear.id or other.type not in GEAR_TYPES:
            continue
        z2, m2, beta2 = (model.value(other, a) for a in ("number_of_teeth", "normal_module",
                                                          "helix_angle_reference_diameter"))
        if None in (z2, m2, beta2):  # a gear that cannot be a half of this one
            continue
        yield other, {"number_of_teeth": z2 == z, "normal_module": abs(m2 - m) <= 1e-9 * m,
                      "helix_angle_reference_diameter": abs(beta2 + beta) <= 1e-9 * abs(beta)}


def twin_half(model: Model, gear: Component) -> Component | None:
    """The opposite-hand half of a double-helical member on ``gear``'s shaft, or None."""
    if _signature(model, gear)[2] == 0:
        return None
    twins = [other for other, same in _shaft_mates(model, gear) if all(same.values())]
    if len(twins) > 1:
        shaft = shaft_of(model, gear)
        raise model.error(gear, None, f"shaft {shaft.id} holds several opposite-hand twins of this gear "
                                      f"({', '.join(str(t.id) for t in twins)}): which is its other half is ambiguous")
    return twins[0] if twins else None


def _near_twin(model: Model, gear: Component, mate: Component) -> None:
    """Raise naming the attribute where a gear on ``gear``'s shaft differs from it while its ``mate`` is a
    double-helical member: the other half of ``gear`` with a typo (its module, tooth count or helix angle), which
    would otherwise read as a pair of mixed helix kinds."""
    for other, same in _shaft_mates(model, gear):
        if sum(same.values()) != 2:             # one attribute off: a half with a typo, not another gear
            continue
        attr = next(a for a, ok in same.items() if not ok)
        mine, theirs = model.value(gear, attr), model.value(other, attr)
        value, own = {"number_of_teeth": (theirs, mine), "normal_module": (f"{theirs * 1e3:g} mm", f"{mine * 1e3:g} mm"),
                      "helix_angle_reference_diameter": (f"{theirs:+g}°", f"{-mine:+g}°")}[attr]
        raise model.error(other, attr, f"{value} differs from {own} of its other half {gear.label()} on the same "
                                       f"shaft {shaft_of(model, gear).id}: the halves of a double-helical member agree "
                                       f"in tooth count and module and have opposite hands (its mate {mate.label()} "
                                       "is double-helical)")


def pair_parts(model: Model, stage: Component) -> PairParts:
    """The pair of a supported cylindrical stage (double-helical halves found on the shafts)."""
    g1, g2 = stage_gears(model, stage)
    t1, t2 = twin_half(model, g1), twin_half(model, g2)
    shafts = (shaft_of(model, g1), shaft_of(model, g2))
    if (t1 is None) != (t2 is None):
        lone, other = (g1, g2) if t1 is not None else (g2, g1)
        half = t1 if t1 is not None else t2
        _near_twin(model, other, lone)
        raise model.error(lone, "helix_angle_reference_diameter",
                          f"has an opposite-hand half (gear {half.id}) on its shaft, a double-helical member, but its "
                          f"mate {other.label()} has none: the pair is neither single- nor double-helical")
    if t1 is None:
        beta = model.value(g1, "helix_angle_reference_diameter", required=True)
        return PairParts((stage,), ((g1,), (g2,)), shafts, "spur" if beta == 0 else "single-helical")
    stages = [stage]
    for other in stage_components(model):
        if other.id != stage.id and other.type == "cylindrical_stage" and set(stage_gears(model, other)) == {t1, t2}:
            stages.append(other)
    halves = sorted([(g1, g2), (t1, t2)], key=lambda h: (_u(model, h[0]), h[0].id))
    return PairParts(tuple(sorted(stages, key=lambda s: s.id)), (tuple(h[0] for h in halves),
                                                                tuple(h[1] for h in halves)), shafts, "double-helical")


def _u(model: Model, gear: Component) -> float:
    u = model.value(gear, "u_coordinate_on_shaft")
    return 0.0 if u is None else u


def select_stage(model: Model, stage_id: int | None) -> tuple[Component, PairParts]:
    """The stage ``stage_id`` (None: the model's only cylindrical stage) and its pair; refusals are errors."""
    stages = stage_components(model)
    if stage_id is None:
        cylindrical = [s for s in stages if s.type == "cylindrical_stage"]
        pairs = {tuple(p.id for p in pair_parts(model, s).stages) for s in cylindrical if _refusal(model, s) is None}
        if len(pairs) != 1:
            listing = ", ".join(f"{s.id} ({s.type})" for s in stages) or "none"
            raise model.error(None, None, f"give --stage ID: the model holds {len(pairs)} femgear pairs "
                                          f"(stages: {listing}; list them with femgear rexs FILE)")
        stage_id = next(iter(pairs))[0]
    match = [s for s in stages if s.id == stage_id]
    if not match:
        listing = ", ".join(f"{s.id} ({s.type})" for s in stages) or "none"
        raise model.error(None, None, f"--stage {stage_id}: no such stage (the model's stages: {listing})")
    stage = match[0]
    reason = _refusal(model, stage)
    if reason is not None:
        raise model.error(stage, None, f"{reason}: not supported (femgear models external cylindrical gear pairs: "
                                       "spur, single- or double-helical)")
    return stage, pair_parts(model, stage)


def stage_rows(model: Model) -> list[StageRow]:
    """A row per stage: the pair's key figures, or why femgear refuses it."""
    rows = []
    for stage in stage_components(model):
        reason = _refusal(model, stage)
        if reason is not None:
            rows.append(StageRow(stage.id, stage.type, stage.name, f"not supported: {reason}", False))
            continue
        parts = pair_parts(model, stage)
        g1, g2 = parts.members[0][0], parts.members[1][0]
        note = parts.kind
        if parts.kind == "double-helical" and len(parts.stages) > 1:
            note += f" (halves in stages {', '.join(str(s.id) for s in parts.stages)})"
        elif parts.kind == "double-helical":
            note += f" (halves: gears {', '.join(str(g.id) for g in parts.members[0] + parts.members[1])})"
        rows.append(StageRow(stage.id, stage.type, stage.name, note, True,
                             (model.value(g1, "number_of_teeth"), model.value(g2, "number_of_teeth")),
                             model.value(g1, "normal_module"), model.value(g1, "helix_angle_reference_diameter"),
                             model.value(g1, "face_width"), model.value(stage, "center_distance")))
    return rows
