"""Inputs checked in engineering terms, before any derived geometry or computation.

A valid scene (right types, right signs) can still carry a unit slip: a module typed in mm
(``normal_module = 6``), a kinematic viscosity in cSt typed as Pa s (``viscosity = 39.7``),
α in GPa⁻¹ (``pressure_viscosity = 20``), a temperature in °C.  Such values used to pass and
fail far downstream, blamed on another key.  :func:`check_input_ranges` runs right after the
schema, on the keys as typed, and

- **refuses** (:class:`SceneError`, CLI exit 2) a value that no gear or oil can have, naming
  the key, the range and, where one fits, the likely unit slip ("did you mean 6 mm = 0.006?");
- **warns** (one ``key: message`` line each, returned; the loader logs them) where a value
  is possible but unusual.

Ranges (SI; "plausible" = no warning, "possible" = no error; sizes relative to the pair):

==============================  =====================================  ===================================
key                             plausible                              possible (else refused)
==============================  =====================================  ===================================
pair.normal_module              0.3–50 mm                              0.05–100 mm
pair/pinion/gear.face_width     2–80 m_n, ≤ 2.5 d_1                    0.2–500 m_n
pair.groove_width               ≤ 3 b                                  ≤ 20 b
pinion/gear.tip_diameter        0.8–1.25 × m_n (z/cos β + 2)           0.5–2 × m_n (z/cos β + 2)
pair.centre_distance            0.8–1.25 × reference a                 0.5–2 × (z1 + z2) m_n / (2 cos β)
pinion/gear.bore_radius         —                                      < reference radius
pinion/gear.shaft_diameter      ≤ d_a                                  ≤ 10 d_a
pinion/gear.bearing_span        ≤ 50 d_a                               ≥ the member's total face width,
                                                                       ≤ 200 d_a
oil.viscosity                   1e-3–1 Pa s                            1e-4–5 Pa s
oil.pressure_viscosity          5e-9–6e-8 1/Pa                         1e-9–1e-7 1/Pa
oil.temperature_viscosity       ≤ 0.1 1/K                              ≤ 0.5 1/K
oil.density                     700–2000 kg/m³                         500–2500 kg/m³
oil.specific_heat, conductivity 1500–3000 J/(kg K), 0.08–0.7 W/(m K)   500–10000, 0.02–2
temperatures (ambient, oil)     250–423 K (in plausibility)            200–600 K
thermal.*_temperature_rise      ≤ 150 K                                ≤ 250 K (steel tempers above)
operating.speed_rpm             pitch-line speed ≥ 0.1 m/s             ≥ 1 mm/s (tip burst: plausibility)
operating.torque                (Hertz pressure: plausibility)         nominal σ_H0 ≤ 8 GPa
pinion/gear.eccentricity        ≤ backlash and ≤ ISO 1328 class-11     < m_n
                                runout F_r/2
pinion/gear.cumulative_pitch_   ≤ ISO 1328 class-11 F_p/2              < m_n
  error
errors.profile_error, .random   ≤ ISO 1328 class-12 f_fα               < m_n / 4
pair.backlash                   ≤ 0.2 m_n                              < m_n
pinion/gear.unbalance           —                                      unbalance/mass < tip radius
material.youngs_modulus         —                                      1–1000 GPa
material.density                —                                      500–25000 kg/m³
material.hardness               —                                      0.1–20 GPa
material.thermal_expansion      —                                      1e-7–1e-4 1/K
material.conductivity, .spec.h. —                                      1–500 W/(m K), 100–5000 J/(kg K)
roughness.ra, .rq (per member)  R_a 0.02–12.5 µm (ISO 1302 N1–N10)     R_a ≤ min(50 µm, 0.05 m_n) (R_q × 1.25)
==============================  =====================================  ===================================

Sources of the bounds: ISO 54 / DIN 780 module series (0.05–100 mm), ISO 6336-1 (b/d1 of
pinions), ISO 1328-1:2013 §5.3 (tolerance formulas f_fα = 2.5√m + 0.17√d + 0.5,
F_p = 0.3 m + 1.25√d + 7 µm at class 5, ×√2 per class; F_r ≈ 0.8 F_p), ISO 3448 viscosity
grades (VG 2…1500), Bair, *High Pressure Rheology* (2007) for α of mineral, synthetic and
water-glycol fluids, ISO 76 (4.2 GPa static contact limit of hardened steel: 8 GPa nominal is
about twice it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.errors import SceneError

SIGMA_H0_IMPOSSIBLE = 8.0e9   #: Pa, nominal ISO contact stress no steel flank carries (≈ 2 × ISO 76's 4.2 GPa)
MIN_PITCH_SPEED = 1.0e-3      #: m/s, below: refused (no film; mesh period beyond the dynamic models)
LOW_PITCH_SPEED = 0.1         #: m/s, below: warned (boundary lubrication)
#: where unit hints start for values whose plausible range starts at 0 (:attr:`Range.hint_band`): a half backlash of
#: 0.005 m_n (a tenth of ISO/TR 10064-2's j_bn,min/2 at small centre distances), a tooth error or runout of 0.1 µm
#: (below ISO 1328 class 1), a composite roughness of 0.01 µm (below superfinished flanks)
BACKLASH_MIN = 0.005
FINEST_ERROR = 1e-7


@dataclass(frozen=True)
class Range:
    """A value checked against a possible and a plausible interval."""

    key: str
    value: float
    possible: tuple[float, float]
    plausible: tuple[float, float]
    unit: str                     #: the SI unit of the key
    what: str                     #: what the range is (printed)
    hints: tuple[tuple[float, float, str], ...] = ()  #: (factor, offset, unit typed): value·factor + offset in SI
    #: where a value converted by a hint must land for the hint to be offered (None: the plausible range); a
    #: range whose plausible values start at 0 (no backlash, a solid disc) gives here where real ones start, so
    #: that 0.15 is not offered as 0.15 µm of backlash, nor a bore as 0.012 mm
    hint_band: tuple[float, float] | None = None
    #: (key, message) refused instead when the value is impossible because of another key (the tooth count
    #: that makes the gear smaller than its bore, rather than the bore); None: the key itself
    blame: tuple[str, str] | None = None


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def _hint(r: Range) -> str:
    """'; did you mean 6 mm = 0.006 m?' for the first unit in which the value is plausible (:attr:`Range.hint_band`)."""
    lo, hi = r.plausible if r.hint_band is None else r.hint_band
    for factor, offset, unit in r.hints:
        converted = r.value * factor + offset
        if lo <= converted <= hi:
            return f"; did you mean {_fmt(r.value)} {unit} = {_fmt(converted)} {r.unit}?"
    return ""


def _band(lo: float, hi: float, unit: str) -> str:
    return f"{_fmt(lo)}…{_fmt(hi)} {unit}"


def _judge(r: Range) -> str | None:
    """Raise for an impossible value; the warning text for an unusual one (no unit hint: the value
    is possible as typed); None when plausible."""
    if not r.possible[0] <= r.value <= r.possible[1]:
        if r.blame is not None:
            raise SceneError(*r.blame)
        plausible = "" if r.plausible == r.possible else f", plausible {_band(*r.plausible, r.unit)}"
        raise SceneError(r.key, f"{_fmt(r.value)} {r.unit} is impossible for {r.what}: possible "
                                f"{_band(*r.possible, r.unit)}{plausible}{_hint(r)}")
    if not r.plausible[0] <= r.value <= r.plausible[1]:
        return f"{r.key}: {_fmt(r.value)} {r.unit} is unusual for {r.what}: plausible {_band(*r.plausible, r.unit)}"
    return None


MM = ((1e-3, 0.0, "mm"),)
UM_MM = ((1e-6, 0.0, "µm"), (1e-3, 0.0, "mm"))


def _reference_diameter(scene, member: str) -> float:
    z = getattr(scene, member).teeth
    return z * scene.pair.normal_module / math.cos(math.radians(scene.pair.helix_angle_deg))


def _size_ranges(scene) -> list[Range]:
    """Module, widths and diameters, each against the pair's own size (module first)."""
    p = scene.pair
    m = p.normal_module
    out = [Range("pair.normal_module", m, (5e-5, 0.1), (3e-4, 0.05), "m", "a gear module", MM)]
    d1 = _reference_diameter(scene, "pinion")
    for key, b in [("pair.face_width", p.face_width)] + [
            (f"{n}.face_width", getattr(scene, n).face_width) for n in ("pinion", "gear")
            if getattr(scene, n).face_width is not None]:
        out.append(Range(key, b, (0.2 * m, 500 * m), (2 * m, min(80 * m, 2.5 * d1)), "m",
                         f"a face width at m_n = {_fmt(m * 1e3)} mm, d1 = {_fmt(d1 * 1e3)} mm "
                         f"(plausible 2–80 m_n and ≤ 2.5 d1)", MM))
    out.append(Range("pair.groove_width", p.groove_width, (0.0, 20 * p.face_width), (0.0, 3 * p.face_width), "m",
                     f"the groove between helices of b = {_fmt(p.face_width * 1e3)} mm", MM,
                     hint_band=(0.5 * m, 3 * p.face_width)))
    beta = math.radians(p.helix_angle_deg)
    if p.centre_distance is not None:
        a = (scene.pinion.teeth + scene.gear.teeth) * m / (2 * math.cos(beta))
        out.append(Range("pair.centre_distance", p.centre_distance, (0.5 * a, 2 * a), (0.8 * a, 1.25 * a), "m",
                         f"this pair (reference centre distance {_fmt(a * 1e3)} mm)", MM))
    for n in ("pinion", "gear"):
        member, d = getattr(scene, n), _reference_diameter(scene, n)
        d_a = d + 2 * m
        if member.tip_diameter is not None:
            out.append(Range(f"{n}.tip_diameter", member.tip_diameter, (0.5 * d_a, 2 * d_a), (0.8 * d_a, 1.25 * d_a),
                             "m", f"this {n} (d + 2 m_n = {_fmt(d_a * 1e3)} mm)", MM))
        out.append(Range(f"{n}.bore_radius", member.bore_radius, (0.0, 0.5 * d), (0.0, 0.5 * d), "m",
                         f"the bore of this {n} (reference radius {_fmt(d / 2 * 1e3)} mm)", MM,
                         hint_band=(0.05 * d, 0.5 * d), blame=_teeth_blame(scene, n, d)))
        out.append(Range(f"{n}.shaft_diameter", member.shaft_diameter, (1e-3 * d_a, 10 * d_a), (0.02 * d_a, d_a),
                         "m", f"the shaft of this {n} (tip diameter ≈ {_fmt(d_a * 1e3)} mm)", MM))
        width = (member.face_width or p.face_width) * (2 if p.kind == "double-helical" else 1)
        width += p.groove_width if p.kind == "double-helical" else 0.0
        out.append(Range(f"{n}.bearing_span", member.bearing_span, (width, 200 * d_a), (width, 50 * d_a), "m",
                         f"the bearing span of this {n} (its toothed width is {_fmt(width * 1e3)} mm: the shaft "
                         "between the bearings is longer, the bearings sit outside the teeth)", MM))
    return out


def _teeth_blame(scene, n: str, d: float) -> tuple[str, str] | None:
    """A bore that fits the member's own shaft but not its reference circle: the tooth count (or the module) makes
    the gear too small, so ``<member>.teeth`` is refused, naming the bore, the shaft and the module."""
    member = getattr(scene, n)
    if 2 * member.bore_radius > member.shaft_diameter * (1 + 1e-9):
        return None
    return (f"{n}.teeth", f"{member.teeth} teeth at m_n = {_fmt(scene.pair.normal_module * 1e3)} mm make a reference "
                          f"radius of {_fmt(d / 2 * 1e3)} mm, inside this {n}'s bore ({n}.bore_radius "
                          f"{_fmt(member.bore_radius * 1e3)} mm, which fits its {_fmt(member.shaft_diameter * 1e3)} mm "
                          f"shaft): too few teeth for this shaft, or a module too small")


def _oil_ranges(scene) -> list[Range]:
    o = scene.oil
    cst = 1e-6 * o.density
    out = [
        Range("oil.viscosity", o.viscosity, (1e-4, 5.0), (1e-3, 1.0), "Pa s", "a gear oil's dynamic viscosity",
              ((cst, 0.0, f"cSt (mm²/s, × ρ = {_fmt(o.density)} kg/m³)"), (1e-3, 0.0, "mPa s"))),
        Range("oil.pressure_viscosity", o.pressure_viscosity, (1e-9, 1e-7), (5e-9, 6e-8), "1/Pa",
              "a lubricant's pressure-viscosity coefficient", ((1e-9, 0.0, "GPa⁻¹"), (1e-6, 0.0, "1/MPa"))),
        Range("oil.temperature_viscosity", o.temperature_viscosity, (0.0, 0.5), (0.0, 0.1), "1/K",
              "a temperature-viscosity coefficient"),
        Range("oil.density", o.density, (500.0, 2500.0), (700.0, 2000.0), "kg/m³", "a lubricant's density",
              ((1e3, 0.0, "g/cm³"),)),
        Range("oil.specific_heat", o.specific_heat, (500.0, 10000.0), (1500.0, 3000.0), "J/(kg K)",
              "a lubricant's specific heat", ((1e3, 0.0, "kJ/(kg K)"),)),
        Range("oil.conductivity", o.conductivity, (0.02, 2.0), (0.08, 0.7), "W/(m K)", "a lubricant's conductivity"),
    ]
    celsius = ((1.0, 273.15, "°C"),)
    temperatures = [("operating.ambient_temperature", scene.operating.ambient_temperature)]
    if o.reference_temperature is not None:
        temperatures.append(("oil.reference_temperature", o.reference_temperature))
    for key, t in temperatures:   # the 250/423 K warnings are plausibility's (they name the oil's limits)
        out.append(Range(key, t, (200.0, 600.0), (200.0, 600.0), "K", "an absolute oil temperature", celsius))
    for key in ("flank_temperature_rise", "shaft_temperature_rise"):
        rise = getattr(scene.thermal, key)
        out.append(Range(f"thermal.{key}", rise, (0.0, 250.0), (0.0, 150.0), "K",
                         "a temperature rise over the ambient (not an absolute temperature)"))
    return out


def _iso1328(m: float, d: float, grade: int) -> tuple[float, float]:
    """(f_fα, F_r) of ISO 1328-1:2013 at ``grade`` [m] for module m and diameter d [m]."""
    step = 2.0 ** ((grade - 5) / 2)
    m_mm, d_mm = m * 1e3, d * 1e3
    f_f = (2.5 * math.sqrt(m_mm) + 0.17 * math.sqrt(d_mm) + 0.5) * step
    F_p = (0.3 * m_mm + 1.25 * math.sqrt(d_mm) + 7.0) * step
    return f_f * 1e-6, 0.8 * F_p * 1e-6


def _error_ranges(scene) -> list[Range]:
    """Eccentricity, errors, backlash and unbalance against the gear's size and quality."""
    p, m = scene.pair, scene.pair.normal_module
    out = [Range("pair.backlash", p.backlash, (0.0, m), (0.0, 0.2 * m), "m",
                 f"a normal backlash at m_n = {_fmt(m * 1e3)} mm", UM_MM, hint_band=(BACKLASH_MIN * m, 0.2 * m))]
    d_max = _reference_diameter(scene, "gear")
    f_f12, _ = _iso1328(m, d_max, 12)
    for key in ("profile_error", "random"):
        out.append(Range(f"errors.{key}", getattr(scene.errors, key), (0.0, 0.25 * m), (0.0, f_f12), "m",
                         f"a tooth error at m_n = {_fmt(m * 1e3)} mm (ISO 1328 class 12 f_fα = "
                         f"{_fmt(f_f12 * 1e6)} µm)", UM_MM, hint_band=(FINEST_ERROR, f_f12)))
    for n in ("pinion", "gear"):
        member, d = getattr(scene, n), _reference_diameter(scene, n)
        _, F_r11 = _iso1328(m, d, 11)
        limit = min(F_r11 / 2, p.backlash) if p.backlash > 0 else F_r11 / 2
        out.append(Range(f"{n}.eccentricity", member.eccentricity, (0.0, m), (0.0, limit), "m",
                         f"the eccentricity of this {n} (backlash {_fmt(p.backlash * 1e6)} µm: the teeth lose "
                         f"contact or jam once per revolution above it; ISO 1328 class 11 runout F_r/2 = "
                         f"{_fmt(F_r11 / 2 * 1e6)} µm)", UM_MM, hint_band=(FINEST_ERROR, limit)))
        F_p11 = F_r11 / 0.8
        out.append(Range(f"{n}.cumulative_pitch_error", member.cumulative_pitch_error, (0.0, m), (0.0, F_p11 / 2),
                         "m", f"the cumulative pitch deviation of this {n} (ISO 1328 class 11 F_p/2 = "
                              f"{_fmt(F_p11 / 2 * 1e6)} µm)", UM_MM, hint_band=(FINEST_ERROR, F_p11 / 2)))
        r_a = d / 2 + m
        out.append(Range(f"{n}.unbalance", member.unbalance, (0.0, member.mass * r_a), (0.0, member.mass * r_a),
                         "kg m", f"this {n}'s unbalance (mass × tip radius = {_fmt(member.mass * r_a)} kg m)",
                         ((1e-6, 0.0, "g mm"),)))
    mat = scene.material
    out += [Range("material.youngs_modulus", mat.youngs_modulus, (1e9, 1e12), (1e9, 1e12), "Pa",
                  "Young's modulus", ((1e9, 0.0, "GPa"),)),
            Range("material.density", mat.density, (500.0, 25000.0), (500.0, 25000.0), "kg/m³", "a gear material",
                  ((1e3, 0.0, "g/cm³"),)),
            Range("material.hardness", mat.hardness, (1e8, 2e10), (1e8, 2e10), "Pa", "a flank hardness",
                  ((9.80665e6, 0.0, "HV"), (1e6, 0.0, "MPa"))),
            Range("material.thermal_expansion", mat.thermal_expansion, (1e-7, 1e-4), (1e-7, 1e-4), "1/K",
                  "a linear expansion coefficient", ((1e-6, 0.0, "µm/(m K)"),)),
            Range("material.conductivity", mat.conductivity, (1.0, 500.0), (1.0, 500.0), "W/(m K)",
                  "a gear material's conductivity"),
            Range("material.specific_heat", mat.specific_heat, (100.0, 5000.0), (100.0, 5000.0), "J/(kg K)",
                  "a gear material's specific heat", ((1e3, 0.0, "kJ/(kg K)"),))]
    return out


def _operating_checks(scene) -> list[str]:
    """Speed and torque against the pair's size (pitch-line speed, nominal contact stress)."""
    p, op = scene.pair, scene.operating
    out: list[str] = []
    z1, z2 = scene.pinion.teeth, scene.gear.teeth
    d1 = _reference_diameter(scene, "pinion")
    n1 = scene.pinion_rpm
    v = math.pi * d1 * n1 / 60
    if v < MIN_PITCH_SPEED:
        raise SceneError("operating.speed_rpm", f"{_fmt(op.speed_rpm)} rpm is a pitch-line speed of {_fmt(v)} m/s, "
                                                f"below {MIN_PITCH_SPEED:g} m/s: no lubricant film forms and one mesh "
                                                f"period lasts {_fmt(60 / (z1 * n1))} s, beyond femgear's models")
    if v < LOW_PITCH_SPEED:
        out.append(f"operating.speed_rpm: pitch-line speed {_fmt(v)} m/s is below {LOW_PITCH_SPEED:g} m/s: boundary "
                   "lubrication (the film formulas give a film far below any roughness) and slow dynamics")
    T1 = op.torque if op.driver == "pinion" else op.torque * z1 / z2
    sigma = _nominal_contact_stress(scene, T1, d1)
    if sigma > SIGMA_H0_IMPOSSIBLE:
        hint = _torque_hint(scene, T1, d1)
        b = p.face_width * (2 if p.kind == "double-helical" else 1)
        raise SceneError("operating.torque", f"{_fmt(op.torque)} N m on this pair (d1 = {_fmt(d1 * 1e3)} mm, "
                                             f"b = {_fmt(b * 1e3)} mm) is a nominal contact stress σ_H0 ≈ "
                                             f"{_fmt(sigma / 1e9)} GPa, far above what any steel flank carries "
                                             f"({SIGMA_H0_IMPOSSIBLE / 1e9:g} GPa){hint}")
    return out


def _torque_hint(scene, T1: float, d1: float) -> str:
    """'; did you mean …?' for the readings of an impossible ``operating.torque`` under which the pair would run
    at a nominal contact stress σ_H0 no higher than its own ``rating.contact_stress_limit`` (a torque in N mm, a
    power in W at the driver's speed); '' when neither is plausible."""
    op = scene.operating
    n_driver = op.speed_rpm
    readings = [(op.torque * 1e-3, f"{_fmt(op.torque)} N mm = {_fmt(op.torque * 1e-3)} N m")]
    if n_driver > 0:
        T_power = op.torque / (n_driver * math.pi / 30)
        readings.append((T_power, f"a power of {_fmt(op.torque)} W = {T_power:.6g} N m at {n_driver:.6g} rpm"))
    ratio = T1 / op.torque
    fits = [text for torque, text in readings
            if _nominal_contact_stress(scene, torque * ratio, d1) <= scene.rating.contact_stress_limit]
    return f"; did you mean {' or '.join(fits)}?" if fits else ""


def _nominal_contact_stress(scene, T1: float, d1: float) -> float:
    """ISO 6336-2 σ_H0 = Z_H Z_E √(F_t (u+1)/(d1 b u)) with Z_H of the unshifted pair, Z_ε = Z_β = 1 [Pa]."""
    p, mat = scene.pair, scene.material
    alpha_n, beta = math.radians(p.normal_pressure_angle_deg), math.radians(p.helix_angle_deg)
    alpha_t = math.atan(math.tan(alpha_n) / math.cos(beta))
    beta_b = math.atan(math.tan(beta) * math.cos(alpha_t))
    Z_H = math.sqrt(2 * math.cos(beta_b) / (math.cos(alpha_t) * math.sin(alpha_t)))
    Z_E = math.sqrt(mat.youngs_modulus / (2 * math.pi * (1 - mat.poisson_ratio ** 2)))
    u = scene.gear.teeth / scene.pinion.teeth
    b = p.face_width * (2 if p.kind == "double-helical" else 1)
    return Z_H * Z_E * math.sqrt(2 * T1 / d1 / (d1 * b) * (u + 1) / u)


def check_input_ranges(scene) -> list[str]:
    """Raise :class:`SceneError` for the first impossible input; return the warnings (``key: message``).

    Order: sizes (module first, as the others are judged against it), oil and temperatures,
    errors and material, then speed and torque.
    """
    warnings: list[str] = []
    for r in _size_ranges(scene) + _oil_ranges(scene) + _error_ranges(scene):
        message = _judge(r)
        if message:
            warnings.append(message)
    from femgear.scene.roughness import check_roughness

    warnings += check_roughness(scene)
    warnings += _operating_checks(scene)
    return warnings


__all__ = ["Range", "check_input_ranges"]
