"""Members' masses and supports, material, oil and operating point of one REXS stage.

Readings (each default is listed at the top of the written scene):

- mass: the sum of the halves' ``mass_of_component``; else a solid disc of the reference diameter
  d (bore d_i, width of all halves), m = ρ π (d² − d_i²) b / 4, J = m (d² + d_i²) / 8;
- supports: the concept bearings on the member's shaft act in parallel (radial and axial
  stiffnesses summed); the bearing span is the distance between two of them;
- material: one for both members (as the scene has): the two gears' materials must agree;
  hardness H = HV · 9.80665 N/mm² (the Vickers number is kgf/mm²);
- oil: the stage's ``temperature_lubricant`` is the ambient/oil temperature and the reference of
  the viscosity; η0 = ν ρ0 from the stage's ``operating_viscosity``, else from ν40 and ν100
  (ASTM D341, :mod:`femgear.rexs.viscosity`), which also give β_T; ρ0 from the density at 15 °C
  with femgear's law ρ(T) = ρ0 (1 − ε (T − T0)); α from the pressure–viscosity coefficient at 38 °C,
  carried to the reference temperature by the oil's Roelands law (α ∝ ((T − 138)/(T0 − 138))^(−S0));
- operating point: the driver is the gear whose ``is_driving_gear`` is true (default the pinion),
  its speed from the gear or its shaft (else the mate's speed times the ratio), its torque the sum
  over the pair's stages of its ``torque`` (else the mate's times the ratio, else power / ω).
"""

from __future__ import annotations

import math

from femgear.rexs.convert import MEMBERS, Conversion
from femgear.rexs.lookup import bearings_of, gear_data, lubricant_of, material_of
from femgear.rexs.viscosity import T38, kinematic_viscosity, pressure_viscosity_from, temperature_coefficient
from femgear.scene.schema import Member

STEEL = {"youngs_modulus": 210e9, "poisson_ratio": 0.3, "density": 7850.0, "specific_heat": 460.0,
         "conductivity": 45.0, "thermal_expansion": 11.5e-6}
MATERIAL = {"youngs_modulus": "elastic_modulus", "poisson_ratio": "poisson_ratio", "density": "density",
            "specific_heat": "thermal_capacity", "conductivity": "thermal_conductivity",
            "thermal_expansion": "thermal_expansion_coefficient_plus"}
HV_TO_PA = 9.80665e6
DEFAULT_SUPPORT_STIFFNESS = 1.0e9        #: [N/m]
DEFAULT_SPEED_RPM = 1000.0
DEFAULT_LINE_LOAD = 1.0e5                #: tangential load per face width when no torque is given [N/m]
MEMBER_CUSTOM = {"inertia": "custom_femgear_moment_of_inertia", "support_stiffness": "custom_femgear_support_stiffness",
                 "support_damping": "custom_femgear_support_damping", "axial_stiffness": "custom_femgear_axial_stiffness",
                 "axial_damping": "custom_femgear_axial_damping", "bearing_span": "custom_femgear_bearing_span",
                 "shaft_diameter": "custom_femgear_shaft_diameter", "eccentricity": "custom_femgear_eccentricity",
                 "eccentricity_phase_deg": "custom_femgear_eccentricity_phase", "unbalance": "custom_femgear_unbalance"}
OIL_CUSTOM = {"specific_heat": ("custom_femgear_specific_heat", 2000.0),
              "conductivity": ("custom_femgear_thermal_conductivity", 0.13),
              "thermal_expansion": ("custom_femgear_thermal_expansion", None),
              "eyring_stress": ("custom_femgear_eyring_stress", None),
              "limiting_shear_coeff": ("custom_femgear_limiting_shear_coefficient", None)}
VG100 = (100e-6, 11e-6, 880.0)   #: ν40, ν100 [m²/s], ρ15 [kg/m³] of an ISO VG 100 mineral oil (the default)


def material(conv: Conversion) -> None:
    """``[material]`` from the members' material components (one material for both)."""
    model, parts = conv.model, conv.parts
    mats = [m for halves, shaft in zip(parts.members, parts.shafts, strict=True) for h in halves
            if (m := material_of(model, h, shaft)) is not None]
    mats = list(dict.fromkeys(mats))
    for key, attr in MATERIAL.items():
        value, src = conv.agree(mats, attr, f"the {key.replace('_', ' ')} of the gear material (femgear has one "
                                            "material for both members)")
        if value is None:
            conv.default(f"material.{key}", STEEL[key], f"no {attr} in the model: steel assumed")
        elif value <= 0:
            raise model.error(src[0][0], attr, f"must be positive (got {value:g})")
        else:
            conv.put(f"material.{key}", value, src)
    hv, src = conv.agree(mats, "surface_hardness_vickers", "the flank hardness")
    if hv is not None:
        conv.put("material.hardness", hv * HV_TO_PA, src)


def members(conv: Conversion) -> None:
    """Mass, inertia and supports of ``[pinion]`` and ``[gear]``."""
    model, parts = conv.model, conv.parts
    rho = conv.get("material.density")
    for name, halves, shaft in zip(MEMBERS, parts.members, parts.shafts, strict=True):
        masses = [model.value(h, "mass_of_component") for h in halves]
        b = conv.get(f"{name}.face_width") or conv.get("pair.face_width")
        d = conv.get(f"{name}.teeth") * conv.get("pair.normal_module") / math.cos(math.radians(
            conv.get("pair.helix_angle_deg")))
        d_i = 2 * (conv.get(f"{name}.bore_radius") or 0.0)
        disc = f"a solid disc of the reference diameter {d * 1e3:.4g} mm, bore {d_i * 1e3:.4g} mm, {len(halves)} x " \
               f"{b * 1e3:.4g} mm wide"
        if None not in masses:
            conv.put(f"{name}.mass", sum(masses), [(h, "mass_of_component") for h in halves])
        else:
            conv.default(f"{name}.mass", rho * math.pi * (d**2 - d_i**2) / 4 * b * len(halves),
                         f"no mass_of_component: {disc}")
        for key, attr in MEMBER_CUSTOM.items():
            value = model.value(halves[0], attr)
            if value is not None:
                conv.put(f"{name}.{key}", value, [(halves[0], attr)])
        if conv.get(f"{name}.inertia") is None:
            conv.default(f"{name}.inertia", conv.get(f"{name}.mass") * (d**2 + d_i**2) / 8,
                         f"no moment of inertia in REXS: {disc}")
        _supports(conv, name, shaft)


def _supports(conv: Conversion, name: str, shaft) -> None:
    model = conv.model
    bearings = bearings_of(model, shaft)
    for key, attr in (("support_stiffness", "radial_stiffness"), ("axial_stiffness", "axial_stiffness")):
        if conv.get(f"{name}.{key}") is not None:
            continue
        values = [model.value(b, attr) for b in bearings]
        if bearings and None not in values and sum(values) > 0:
            conv.put(f"{name}.{key}", sum(values), [(b, attr) for b in bearings])
    if conv.get(f"{name}.support_stiffness") is None:
        conv.default(f"{name}.support_stiffness", DEFAULT_SUPPORT_STIFFNESS,
                     "no concept bearing with a radial_stiffness on the shaft")
    if conv.get(f"{name}.axial_stiffness") is None and conv.parts.kind == "single-helical":
        conv.default(f"{name}.axial_stiffness", conv.get(f"{name}.support_stiffness"),
                     "no axial_stiffness of a bearing on the shaft: the radial support stiffness")
    u = [model.value(b, "u_coordinate_on_shaft_inner_side") for b in bearings]
    if conv.get(f"{name}.bearing_span") is None and len(bearings) == 2 and None not in u:
        conv.put(f"{name}.bearing_span", abs(u[0] - u[1]),
                 [(b, "u_coordinate_on_shaft_inner_side") for b in bearings])
    if conv.get(f"{name}.bearing_span") is None:
        b = conv.get(f"{name}.face_width") or conv.get("pair.face_width")
        width = 2 * b + (conv.get("pair.groove_width") or 0.0) if conv.parts.kind == "double-helical" else b
        d = conv.get(f"{name}.shaft_diameter") or Member.model_fields["shaft_diameter"].default
        default = Member.model_fields["bearing_span"].default
        if width + 2 * d > default:       # the scene's default span would put the bearings under the teeth
            conv.default(f"{name}.bearing_span", width + 2 * d, "no two bearings with u coordinates on the shaft: "
                                                                "the toothed width and a shaft diameter each side")


def oil(conv: Conversion) -> None:
    """``[oil]`` and ``operating.ambient_temperature`` from the lubricant and the stage(s)."""
    model, parts = conv.model, conv.parts
    lub = lubricant_of(model, parts.stages[0])
    lubs = [lub] if lub is not None else []
    t_op, src = conv.agree(parts.stages, "temperature_lubricant", "the oil temperature")
    if t_op is None:
        t_op, src = conv.agree(model.of_type("gear_casing"), "temperature_lubricant", "the oil temperature")
    if t_op is None:
        conv.default("operating.ambient_temperature", 313.0, "no temperature_lubricant in the model")
        t_op = 313.0
    else:
        conv.put("operating.ambient_temperature", t_op, src)
    for key, (attr, fallback) in OIL_CUSTOM.items():
        value, src = conv.agree(lubs, attr, f"the oil {key}")
        if value is not None:
            conv.put(f"oil.{key}", value, src)
        elif fallback is not None:
            conv.default(f"oil.{key}", fallback, "not in REXS: a mineral oil's value")
    eps = conv.get("oil.thermal_expansion") or 6.5e-4
    t_ref, src_t = conv.agree(lubs, "custom_femgear_viscosity_reference_temperature", "the viscosity reference")
    if t_ref is not None:
        conv.put("oil.reference_temperature", t_ref, src_t)
    t0 = t_op if t_ref is None else t_ref
    rho15, src = conv.agree(lubs, "density_at_15_degree_celsius", "the oil density")
    if rho15 is None:
        rho15 = VG100[2]
        conv.default("oil.density", rho15 / (1 - eps * (288.15 - t0)), "no density_at_15_degree_celsius: 880 kg/m³ "
                                                                       "at 15 °C")
    else:
        conv.put("oil.density", rho15 / (1 - eps * (288.15 - t0)), src)
    _viscosity(conv, lubs, t0, t_ref is not None, eps)
    alpha, src = conv.agree(lubs, "pressure_viscosity_coefficient_at_38_degrees_celsius", "the oil's α")
    own, src_own = conv.agree(lubs, "custom_femgear_pressure_viscosity_at_reference_temperature", "the oil's α")
    if own is not None:     # femgear's own α at the reference temperature (written beside the 38 °C value)
        conv.put("oil.pressure_viscosity", own, src_own)
    elif alpha is None:
        conv.default("oil.pressure_viscosity", 2.0e-8, "no pressure_viscosity_coefficient_at_38_degrees_celsius: "
                                                       "a mineral oil's 20 GPa⁻¹")
    else:       # α at 38 °C carried to the reference temperature by the oil's own (Roelands) law
        conv.put("oil.pressure_viscosity", pressure_viscosity_from(alpha, T38, conv.get("oil.viscosity"),
                                                                   conv.get("oil.temperature_viscosity"), t0),
                 src + conv.sources["oil.viscosity"] + conv.sources.get("oil.temperature_viscosity", []))


def _viscosity(conv: Conversion, lubs: list, t0: float, custom_reference: bool, eps: float) -> None:
    """η0 at T0 and β_T: femgear's own attributes, else the operating viscosity, else ν40/ν100."""
    model, parts = conv.model, conv.parts
    nu40, s40 = conv.agree(lubs, "viscosity_at_40_degree_celsius", "the oil's ν40")
    nu100, s100 = conv.agree(lubs, "viscosity_at_100_degree_celsius", "the oil's ν100")
    if (nu40 is None) != (nu100 is None):
        missing = "viscosity_at_100_degree_celsius" if nu100 is None else "viscosity_at_40_degree_celsius"
        raise model.error(lubs[0], missing, "missing: femgear needs both ν40 and ν100 for the viscosity-temperature "
                                            "law")
    given = nu40 is not None
    if given and not nu40 > nu100 > 0:
        raise model.error(lubs[0], "viscosity_at_100_degree_celsius",
                          f"{nu100 * 1e6:g} mm²/s must be positive and below ν40 = {nu40 * 1e6:g} mm²/s")
    if given:
        conv.put("rating.oil_viscosity_40", nu40 * 1e6, s40)
    eta_ref, src = conv.agree(lubs, "custom_femgear_viscosity_at_reference_temperature", "the oil viscosity")
    nu_op, src_op = conv.agree(parts.stages, "operating_viscosity", "the operating viscosity")
    rho0 = conv.get("oil.density")
    if custom_reference and eta_ref is not None:
        conv.put("oil.viscosity", eta_ref, src)
    elif nu_op is not None:
        conv.put("oil.viscosity", nu_op * rho0, src_op + conv.sources["oil.density"])
    elif given:
        conv.put("oil.viscosity", kinematic_viscosity(nu40, nu100, t0) * rho0, s40 + s100)
    else:
        nu40, nu100 = VG100[:2]
        conv.default("oil.viscosity", kinematic_viscosity(nu40, nu100, t0) * rho0,
                     "no operating_viscosity or ν40/ν100: an ISO VG 100 mineral oil (ν40 100, ν100 11 mm²/s)")
    beta, src = conv.agree(lubs, "custom_femgear_temperature_viscosity_coefficient", "the oil's β_T")
    if beta is not None:
        conv.put("oil.temperature_viscosity", beta, src)
    elif given:
        conv.put("oil.temperature_viscosity", temperature_coefficient(nu40, nu100, t0, eps), s40 + s100)
    else:
        conv.default("oil.temperature_viscosity", temperature_coefficient(*VG100[:2], t0, eps),
                     "no ν40/ν100 in the model: the slope of an ISO VG 100 mineral oil")


def operating(conv: Conversion) -> None:
    """``[operating]``: driver, speed and torque (the temperature comes with the oil)."""
    model, parts = conv.model, conv.parts
    data = [[gear_data(model, s, halves[i]) for s in parts.stages for i in range(len(halves))
             if halves[i] in _stage_pair(conv, s)] for halves in parts.members]
    driving = [any(model.value(d, "is_driving_gear") for d in ds if d is not None) for ds in data]
    if all(driving):
        raise model.error(next(d for d in data[1] if d is not None), "is_driving_gear",
                          "both gears of the stage are marked as driving")
    drv = 1 if driving[1] else 0
    srcs = [(d, "is_driving_gear") for ds in data for d in ds if d is not None and
            model.value(d, "is_driving_gear") is not None]
    if srcs:
        conv.put("operating.driver", MEMBERS[drv], srcs)
    else:
        conv.default("operating.driver", "pinion", "no is_driving_gear in the model")
    z = [conv.get(f"{n}.teeth") for n in MEMBERS]
    speed, src = _speed(conv, drv)
    if speed is None:
        conv.default("operating.speed_rpm", DEFAULT_SPEED_RPM, "no rotational_speed of a gear or shaft")
        speed = DEFAULT_SPEED_RPM
    else:
        conv.put("operating.speed_rpm", speed, src)
    torque, src = _sum(conv, data[drv], "torque")
    if torque is None:
        other, src = _sum(conv, data[1 - drv], "torque")
        torque = None if other is None else other * z[drv] / z[1 - drv]
    if torque is None:
        power, src = _sum(conv, data[drv], "power_for_rotational_speed")
        torque = None if power is None else power / (speed * math.pi / 30)
    if torque is None:
        d = z[drv] * conv.get("pair.normal_module") / math.cos(math.radians(conv.get("pair.helix_angle_deg")))
        width = conv.get("pair.face_width") * (2 if parts.kind == "double-helical" else 1)
        conv.default("operating.torque", DEFAULT_LINE_LOAD * width * d / 2,
                     "no torque or power in the model: a tangential load of 100 N/mm of face width")
    else:
        conv.put("operating.torque", torque, src)
    loop, src = conv.agree(parts.stages, "custom_femgear_loop_stiffness", "the loop stiffness")
    if loop is not None:
        conv.put("operating.loop_stiffness", loop, src)


def _stage_pair(conv: Conversion, stage) -> set:
    from femgear.rexs.stages import stage_gears

    return set(stage_gears(conv.model, stage))


def _speed(conv: Conversion, drv: int):
    model, parts = conv.model, conv.parts
    z = [conv.get(f"{n}.teeth") for n in MEMBERS]
    for member, ratio in ((drv, 1.0), (1 - drv, z[1 - drv] / z[drv])):
        for comp in (*parts.members[member], parts.shafts[member]):
            if comp is not None and (n := model.value(comp, "rotational_speed")) is not None and n != 0:
                return abs(n) * ratio, [(comp, "rotational_speed")]
    return None, []


def _sum(conv: Conversion, data: list, attr: str):
    """Σ |attr| over the member's stage gear data (one per helix), None unless every one has it."""
    values = [None if d is None else conv.model.value(d, attr) for d in data]
    if not values or None in values:
        return None, []
    return sum(abs(v) for v in values), [(d, attr) for d in data]
