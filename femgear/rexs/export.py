"""A femgear scene → a REXS 1.4 model of its pair (the inverse of :mod:`femgear.rexs.importer`).

What REXS has an attribute for is written there, in the database unit (mm, deg, N/mm², kg/dm³,
mm²/s, ...); what it has none for (inertia, support stiffness and damping, the oil's β_T, heat
capacity, the ``[rating]`` table and the ``[physics]`` levels: :mod:`femgear.rexs.ratings`) is written as femgear's
custom attributes (``custom_femgear_*``, :data:`femgear.rexs.database.CUSTOM`), so that the file re-imports to the
same scene and the same ratings.  Oil data go out at the temperatures their attributes name, carried there by the
oil's own laws: the density at 15 °C (ρ0 (1 − ε (T − T0))), ν at 40 and 100 °C, α at 38 °C (Roelands).  femgear's
computed figures go into the REXS attributes that hold them (reference, tip, root diameters,
centre distance, gear ratio, contact ratios, operating viscosity, oil viscosities at 40 and 100 °C
from the scene's oil law).

Layout: a gear unit; one ``cylindrical_stage`` per helix (a double-helical pair: two stages whose
gear halves share the members' shafts, at u = ∓(b + groove)/2; helix angle +β on the pinion's first
half, −β on its mate, mirrored on the second); per gear half its two flanks, stage gear data,
a rack-shaped tool (``manufacturing_step``), the material (``reference``); one lubricant.
"""

from __future__ import annotations

import math

from femgear.rexs.database import spec
from femgear.rexs.model import Attribute, Component, Model, Ref, Relation
from femgear.rexs.ratings import member_values, nu40_attribute, stage_values
from femgear.rexs.tables import HV_TO_PA, MEMBER_CUSTOM, OIL_CUSTOM
from femgear.rexs.units import from_scene_unit
from femgear.rexs.viscosity import T38

MEMBERS = ("pinion", "gear")


class _Builder:
    def __init__(self):
        self.components: dict[int, Component] = {}
        self.relations: list[Relation] = []

    def add(self, ctype: str, name: str, values: dict) -> Component:
        comp = Component(len(self.components) + 1, ctype, name)
        for attr, value in values.items():
            if value is None:
                continue
            unit, kind = spec(ctype, attr)
            if kind == "floating_point":
                value = from_scene_unit(float(value), unit)
            comp.attributes[attr] = Attribute(attr, unit, value)
        self.components[comp.id] = comp
        return comp

    def relate(self, rtype: str, *refs: tuple[Component, str], order: int | None = None) -> None:
        self.relations.append(Relation(len(self.relations) + 1, rtype,
                                       tuple(Ref(c.id, role, c.type) for c, role in refs), order))


def export_scene(scene, pair, source: str = "femgear") -> tuple[Model, list[str]]:
    """The REXS 1.4 model of ``scene``'s pair (``pair``, bound by :func:`femgear.case.build_case`), and what
    could not be exported (one line each)."""
    from femgear.physics.lubrication.oil import OilLaw

    law = OilLaw.from_table(scene.oil, scene.oil_reference_temperature)
    b = _Builder()
    skipped: list[str] = []
    unit = b.add("gear_unit", scene.meta.name, {})
    halves = 2 if pair.kind == "double-helical" else 1
    stages = [b.add("cylindrical_stage", scene.meta.name if halves == 1 else f"{scene.meta.name} {('left', 'right')[h]}",
                    _stage(scene, pair, law)) for h in range(halves)]
    nu40 = nu40_attribute(scene)
    for stage in stages if nu40 is not None else ():
        stage.attributes[nu40.id] = nu40
    mat = b.add("material", f"{scene.meta.name} steel", _material(scene))
    lub = b.add("lubricant", f"{scene.meta.name} oil", _lubricant(scene, law))
    b.relate("reference", (unit, "origin"), (lub, "referenced"))
    shafts = [b.add("shaft", f"{name} shaft", {}) for name in MEMBERS]
    for shaft in shafts:
        b.relate("assembly", (unit, "assembly"), (shaft, "part"))
    gears = [[_gear(b, scene, pair, i, h, halves, mat, shafts[i]) for h in range(halves)] for i in range(2)]
    for h in range(halves):
        stage = stages[h]
        b.relate("assembly", (unit, "assembly"), (stage, "part"))
        b.relate("stage", (stage, "stage"), (gears[0][h], "gear_1"), (gears[1][h], "gear_2"))
        for i in range(2):
            data = b.add("cylindrical_stage_gear_data", f"{MEMBERS[i]} in {stage.name}", _gear_data(scene, pair, i, halves))
            b.relate("stage_gear_data", (stage, "stage"), (gears[i][h], "gear"), (data, "stage_gear_data"))
    _modifications(b, scene, gears, skipped)
    model = Model(source, "1.4", "femgear", b.components, tuple(b.relations))
    return model, skipped


def _material(scene) -> dict:
    m = scene.material
    return {"elastic_modulus": m.youngs_modulus, "poisson_ratio": m.poisson_ratio, "density": m.density,
            "thermal_capacity": m.specific_heat, "thermal_conductivity": m.conductivity,
            "thermal_expansion_coefficient_plus": m.thermal_expansion, "surface_hardness_vickers": m.hardness / HV_TO_PA}


def _lubricant(scene, law) -> dict:
    oil, t0 = scene.oil, scene.oil_reference_temperature
    nu = {t: float(law.viscosity(0.0, t) / law.density(0.0, t)) for t in (313.15, 373.15)}
    if scene.rating.oil_viscosity_40 is not None:
        nu[313.15] = scene.rating.oil_viscosity_40 * 1e-6
    out = {"density_at_15_degree_celsius": oil.density * (1 - oil.thermal_expansion * (288.15 - t0)),
           "pressure_viscosity_coefficient_at_38_degrees_celsius": float(law.pressure_viscosity(T38)),
           "custom_femgear_temperature_viscosity_coefficient": oil.temperature_viscosity}
    if nu[313.15] > nu[373.15] > 0:
        out["viscosity_at_40_degree_celsius"] = nu[313.15]
        out["viscosity_at_100_degree_celsius"] = nu[373.15]
    for key, (attr, _) in OIL_CUSTOM.items():
        out[attr] = getattr(oil, key)
    if oil.reference_temperature is not None:
        out["custom_femgear_viscosity_reference_temperature"] = oil.reference_temperature
        out["custom_femgear_viscosity_at_reference_temperature"] = oil.viscosity
    out["custom_femgear_pressure_viscosity_at_reference_temperature"] = oil.pressure_viscosity   # exact, back
    return out


def _gear(b: _Builder, scene, pair, i: int, h: int, halves: int, mat, shaft) -> Component:
    member = getattr(scene, MEMBERS[i])
    z, x = (pair.z1, pair.x1) if i == 0 else (pair.z2, pair.x2)
    width = member.face_width or scene.pair.face_width
    sign = (1 if i == 0 else -1) * (1 if h == 0 else -1)
    drv = MEMBERS.index(scene.operating.driver)
    speed = scene.operating.speed_rpm * (1.0 if i == drv else -(pair.z1, pair.z2)[drv] / z)
    values = {"normal_module": pair.m_n, "number_of_teeth": z, "face_width": width,
              "helix_angle_reference_diameter": sign * scene.pair.helix_angle_deg,
              "reference_circle_diameter": 2 * (pair.r1 if i == 0 else pair.r2),
              "tip_diameter": member.tip_diameter or 2 * (pair.ra1 if i == 0 else pair.ra2),
              "root_diameter": 2 * (pair.rf1 if i == 0 else pair.rf2),
              "inner_diameter": 2 * member.bore_radius if member.bore_radius > 0 else None,
              "mass_of_component": member.mass / halves, "rotational_speed": speed,
              "u_coordinate_on_shaft": (h - 0.5) * (width + scene.pair.groove_width) if halves == 2 else 0.0}
    if scene.rating.roughness_rz is not None:
        values["averaged_peak_to_valley_height_flank"] = scene.rating.roughness_rz[i]
    if h == 0:
        values.update({attr: getattr(member, key) for key, attr in MEMBER_CUSTOM.items()})
        values.update(member_values(scene, i))
    name = f"{MEMBERS[i]}" + (f" {('left', 'right')[h]} half" if halves == 2 else "")
    gear = b.add("cylindrical_gear", name, values)
    b.relate("assembly", (shaft, "assembly"), (gear, "part"))
    b.relate("reference", (gear, "origin"), (mat, "referenced"))
    flank = {"addendum_modification_coefficient": x, "normal_pressure_angle": scene.pair.normal_pressure_angle_deg,
             "addendum_coefficient_basic_profile": pair.h_aP}
    left = b.add("cylindrical_gear_flank", f"{name} left flank", flank)
    right = b.add("cylindrical_gear_flank", f"{name} right flank", flank)
    b.relate("flank", (gear, "gear"), (left, "left"), (right, "right"))
    tool = b.add("rack_shaped_tool", f"{name} hob", {"normal_module": pair.m_n,
                                                      "normal_pressure_angle": scene.pair.normal_pressure_angle_deg,
                                                      "addendum_coefficient_reference_profile": pair.h_fP,
                                                      "tip_radius_factor": pair.rho_fP})
    settings = b.add("cylindrical_gear_manufacturing_settings", f"{name} hobbing", {})
    b.relate("manufacturing_step", (gear, "workpiece"), (tool, "tool"), (settings, "manufacturing_settings"))
    return gear


def _stage(scene, pair, law) -> dict:
    t = scene.operating.ambient_temperature
    return {"center_distance": scene.pair.centre_distance or pair.a_w, "gear_ratio": pair.u, "common_face_width": pair.b,
            "minimum_normal_backlash": 2 * scene.pair.backlash, "maximum_normal_backlash": 2 * scene.pair.backlash,
            "temperature_lubricant": t, "operating_viscosity": float(law.viscosity(0.0, t) / law.density(0.0, t)),
            "radial_contact_ratio": pair.eps_alpha, "overlap_contact_ratio": pair.eps_beta,
            "total_contact_ratio": pair.eps_gamma,
            "custom_femgear_stagger": scene.pair.stagger or None,
            "custom_femgear_groove_width": scene.pair.groove_width if pair.n_helices == 1 and scene.pair.groove_width
            else None,  # one helix: no halves to place, the scene's groove kept as it is
            "custom_femgear_loop_stiffness": scene.operating.loop_stiffness or None, **stage_values(scene)}


def _gear_data(scene, pair, i: int, halves: int) -> dict:
    drv = MEMBERS.index(scene.operating.driver)
    z = (pair.z1, pair.z2)
    torque = scene.operating.torque / halves * (1.0 if i == drv else -z[i] / z[drv])
    return {"torque": torque, "is_driving_gear": i == drv}


def _modifications(b: _Builder, scene, gears, skipped: list[str]) -> None:
    """Modification components on both flanks of every half (helix slope on the pinion's halves)."""
    mods = scene.modifications
    for i, halves in enumerate(gears):
        m = mods.member(i + 1)
        if m.topography is not None:
            skipped.append(f"modifications.{MEMBERS[i]}.topography: a measured grid is not exported")
        for h, gear in enumerate(halves):
            specs = _mod_specs(m)
            slope = (mods.helix_slope_deviation_left, mods.helix_slope_deviation_right)[h] if i == 0 else 0.0
            if slope:
                specs.append(("helix_slope", {"helix_slope": slope}))
            flanks = [b.components[r.id] for rel in b.relations if rel.type == "flank" and gear.id in rel.role("gear")
                      for r in rel.refs if r.role in ("left", "right")]
            for flank in flanks:
                for order, (ctype, values) in enumerate(specs, start=1):
                    comp = b.add(ctype, f"{flank.name} {ctype.replace('_', ' ')}", values)
                    b.relate("ordered_assembly", (flank, "assembly"), (comp, "part"), order=order)
    if len(gears[0]) == 1 and mods.helix_slope_deviation_right:
        skipped.append("modifications.helix_slope_deviation_right: a single helix has only the left slope")


def _mod_specs(m) -> list[tuple[str, dict]]:
    out = []
    if m.tip_relief > 0:
        out.append(("tip_relief", {"tip_relief_depth": m.tip_relief, "tip_relief_datum_length": m.tip_relief_length,
                                   "shape_of_relief": m.tip_relief_shape}))
    if m.root_relief > 0:
        out.append(("root_relief", {"root_relief_depth": m.root_relief, "root_relief_datum_length": m.root_relief_length,
                                    "shape_of_relief": m.root_relief_shape}))
    if m.crowning > 0:
        out.append(("helix_crowning", {"helix_crowning_amount_datum_face": m.crowning,
                                       "helix_crowning_amount_non_datum_face": m.crowning}))
    if m.end_relief > 0:
        out.append(("end_relief_datum_face", {"end_relief_depth_datum_face": m.end_relief,
                                              "end_relief_length_datum_face": m.end_relief_length}))
        out.append(("end_relief_non_datum_face", {"end_relief_depth_non_datum_face": m.end_relief,
                                                  "end_relief_length_non_datum_face": m.end_relief_length}))
    return out


def check_finite(model: Model) -> None:
    """Every number written is finite (a NaN never reaches a file)."""
    for comp in model.components.values():
        for attr in comp.attributes.values():
            if isinstance(attr.value, float) and not math.isfinite(attr.value):
                raise ValueError(f"{comp.label()} attribute {attr.id} is not finite")
