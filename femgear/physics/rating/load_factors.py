"""ISO 6336-1 load factors: K_v (method B), K_Hβ (method C) and K_Hα (method B), with the ISO 1328-1 tolerances.

Sources (ISO 6336-1:2006, whose K_v, K_Hβ and K_Hα clauses the 2019 edition keeps; ISO 1328-1:1995):

- **Tolerances** of accuracy grade Q (ISO 1328-1:1995 §6, grade 5 formulas × 2^(0.5 (Q − 5)); d, m_n, b [mm]
  replaced by the geometric mean of the standard's range they fall in; values rounded to 0.1 µm below
  5 µm, 0.5 µm from 5 to 10 µm, 1 µm above): single pitch f_pt = 0.3 (m_n + 0.4 √d) + 4, profile form
  f_fα = 2.5 √m_n + 0.17 √d + 0.5, helix slope f_Hβ = 0.07 √d + 0.45 √b + 3 [µm]; the base pitch deviation
  f_pb = f_pt cos α_t, the larger of pinion and wheel (as the standard's examples take it).
- **K_v, method B** (§6.5): reduced mass per face width m_red = m₁* m₂*/(m₁* + m₂*),
  m_i* = (π/8) ρ (1 − q_i⁴) d_m,i⁴ / d_b,i² with d_m = (d_a + d_f)/2 and q = d_bore/d_m (eqs. 29–30);
  resonance speed n_E1 = 30 000/(π z₁) √(c_γα/m_red) [min⁻¹] (c_γα [N/(mm µm)], m_red [kg/mm], eq. 6) and
  resonance ratio N = n₁/n_E1 (eq. 9); the lower limit of the main resonance N_S = 0.5 + 0.35 √(F_t K_A/b / 100)
  below 100 N/mm, else 0.85 (eqs. 11–12); B_p = c′ f_pb,eff/(F_t K_A/b), B_f = c′ f_f,eff/(F_t K_A/b),
  B_k = |1 − c′ C_a/(F_t K_A/b)| (eqs. 15–17) with the running-in allowances of case-hardened steel
  y_p = y_α = 0.075 f_pb ≤ 3 µm and y_f = 0.075 f_fα ≤ 3 µm (f_eff = f − y), C_a the tip relief or, without
  one, the running-in relief C_ay = (σ_Hlim/97 − 18.45)²/18 + 1.5 µm (σ_Hlim in N/mm²); subcritical
  N ≤ N_S: K_v = 1 + N (C_v1 B_p + C_v2 B_f + C_v3 B_k); main resonance N_S < N ≤ 1.15:
  K_v = 1 + C_v1 B_p + C_v2 B_f + C_v4 B_k; supercritical N ≥ 1.5: K_v = C_v5 B_p + C_v6 B_f + C_v7;
  linear between N = 1.15 and 1.5 (eqs. 13–22; C_v1 … C_v7 of Table 8 by ε_γ).  Checked against ISO/TR
  6336-30:2017 example 1 (K_v 1.003 at 360 min⁻¹, ``tests/rating/test_load_factors.py``).
- **K_Hβ, method C** (§7.6): F_βy = F_βx − y_β, y_β = 0.15 F_βx ≤ 6 µm (case-hardened);
  K_Hβ = 1 + F_βy c_γβ/(2 F_m/b) up to 2, else √(2 F_βy c_γβ/(F_m/b)) (eqs. 41–42).  Both are the
  peak-over-mean load of an elastic bed of stiffness c_γβ per face width under a gap growing linearly to
  F_βy across the face (full contact, or a triangle over part of it); :func:`face_load_factor_bed` solves that
  bed for any gap, so a lead crowning C_β (both members, the circular arc to second order) enters it as
  the parabola C_β (2ζ/b − 1)² beside the misalignment: for C_β = 0 it is ISO's formula exactly.
- **K_Hα, method B** (§8.3): K_Hα = ε_γ/2 (0.9 + 0.4 c_γα (f_pb − y_α)/(F_tH/b)) for ε_γ ≤ 2,
  0.9 + 0.4 √(2 (ε_γ − 1)/ε_γ) c_γα (f_pb − y_α)/(F_tH/b) above, F_tH = F_t K_A K_v K_Hβ, limited to
  1 ≤ K_Hα ≤ ε_γ/(ε_α Z_ε²) (eqs. 73–75).

Units: SI in and out (the standard's N/mm, µm and N/(mm µm) inside the formulas only).  ``F_t`` is the
nominal tangential load of one helix (a double-helical pair is rated per helix).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair

#: ISO 1328-1:1995 range limits [mm] of the reference diameter, the normal module and the face width
D_RANGES = (5, 20, 50, 125, 280, 560, 1000, 1600, 2500, 4000, 6000, 8000, 10000)
M_RANGES = (0.5, 2, 3.5, 6, 10, 16, 25, 40, 70)
B_RANGES = (4, 10, 20, 40, 80, 160, 250, 400, 650, 1000)
RUNNING_IN_CAP = 3e-6      #: y_α, y_f ≤ 3 µm (case-hardened, ISO 6336-1 §8.3.3)
Y_BETA_CAP = 6e-6          #: y_β ≤ 6 µm (case-hardened, ISO 6336-1 §7.6)


def _range_mean(x: float, limits: tuple, name: str) -> float:
    """Geometric mean of the ISO 1328-1 range holding ``x`` [mm] (the standard's tables use it)."""
    for lo, hi in zip(limits[:-1], limits[1:]):
        if x <= hi:
            return math.sqrt(lo * hi) if x >= lo else math.sqrt(limits[0] * limits[1])
    raise ValueError(f"{name} = {x:g} mm is beyond the largest ISO 1328-1 range ({limits[-1]} mm)")


def _round(value_um: float) -> float:
    """ISO 1328-1 rounding: 0.1 µm below 5 µm, 0.5 µm from 5 to 10 µm, whole µm above."""
    step = 0.1 if value_um < 5 else 0.5 if value_um <= 10 else 1.0
    return round(value_um / step) * step


@document_fields
@dataclass(frozen=True)
class GradeTolerances:
    """ISO 1328-1:1995 tolerances of one accuracy grade for pinion and wheel (SI)."""

    grade: int
    """accuracy grade Q (1 finest … 12) [-]"""
    f_pt: tuple[float, float]
    """single pitch deviation tolerance of pinion, wheel [m]"""
    f_falpha: tuple[float, float]
    """profile form deviation tolerance f_fα of pinion, wheel [m]"""
    f_Hbeta: tuple[float, float]
    """helix slope deviation tolerance f_Hβ of pinion, wheel [m]"""
    f_pb: float
    """transverse base pitch deviation f_pb = f_pt cos α_t, the larger member [m]"""


def grade_tolerances(pair: GearPair, grade: int) -> GradeTolerances:
    """The :class:`GradeTolerances` of ``pair`` at ISO 1328-1 accuracy grade ``grade`` (1 … 12)."""
    if not (isinstance(grade, int) and 1 <= grade <= 12):
        raise ValueError(f"accuracy grade must be an integer 1 … 12, got {grade!r}")
    scale = 2.0 ** (0.5 * (grade - 5))
    m = _range_mean(pair.m_n * 1e3, M_RANGES, "m_n")
    b = _range_mean(pair.b * 1e3, B_RANGES, "b")
    f_pt, f_fa, f_hb = [], [], []
    for r in (pair.r1, pair.r2):
        d = _range_mean(2 * r * 1e3, D_RANGES, "d")
        f_pt.append(_round((0.3 * (m + 0.4 * math.sqrt(d)) + 4) * scale) * 1e-6)
        f_fa.append(_round((2.5 * math.sqrt(m) + 0.17 * math.sqrt(d) + 0.5) * scale) * 1e-6)
        f_hb.append(_round((0.07 * math.sqrt(d) + 0.45 * math.sqrt(b) + 3) * scale) * 1e-6)
    return GradeTolerances(grade, tuple(f_pt), tuple(f_fa), tuple(f_hb), max(f_pt) * math.cos(pair.alpha_t))


def running_in(deviation: float) -> float:
    """Running-in allowance y = 0.075 f ≤ 3 µm of a case-hardened pair (ISO 6336-1 §8.3.3) [m]."""
    return min(0.075 * deviation, RUNNING_IN_CAP)


def _cv(eps_gamma: float) -> tuple[float, ...]:
    """C_v1 … C_v7 of ISO 6336-1 Table 8."""
    eg = eps_gamma
    if eg <= 2:
        cv2, cv3, cv4, cv6 = 0.34, 0.23, 0.90, 0.47
    else:
        cv2, cv3, cv4, cv6 = 0.57 / (eg - 0.3), 0.096 / (eg - 1.56), (0.57 - 0.05 * eg) / (eg - 1.44), 0.12 / (eg - 1.74)
    cv7 = 0.75 if eg <= 1.5 else 0.125 * math.sin(math.pi * (eg - 2)) + 0.875 if eg <= 2.5 else 1.0
    return 0.32, cv2, cv3, cv4, 0.47, cv6, cv7


@document_fields
@dataclass(frozen=True)
class DynamicFactorB:
    """ISO 6336-1 method B dynamic factor and its inputs (SI)."""

    K_v: float
    """dynamic factor K_v [-]"""
    N: float
    """resonance ratio N = n₁/n_E1 [-]"""
    n_E1: float
    """resonance speed of the pinion n_E1 [rev/min]"""
    N_S: float
    """lower limit of the main resonance range [-]"""
    regime: str
    """"subcritical", "main resonance", "intermediate" or "supercritical" [-]"""
    m_red: float
    """reduced mass per unit face width, referred to the line of action [kg/m]"""
    B_p: float
    """non-dimensional base pitch deviation parameter [-]"""
    B_f: float
    """non-dimensional profile form deviation parameter [-]"""
    B_k: float
    """non-dimensional tip relief parameter [-]"""
    f_pb_eff: float
    """effective base pitch deviation f_pb − y_p [m]"""
    f_f_eff: float
    """effective profile form deviation f_fα − y_f [m]"""
    tip_relief: float
    """C_a used: the tip relief, or the running-in relief C_ay without one [m]"""
    line_load: float
    """F_t K_A / b of one helix [N/m]"""


def reduced_mass(pair: GearPair, density: float, bore_radius: tuple[float, float] = (0.0, 0.0)) -> float:
    """m_red per unit face width [kg/m] of ISO 6336-1 eqs. 29–30 (rim ratio q = bore diameter / d_m)."""
    inv = 0.0
    for r_a, r_f, r_b, bore in ((pair.ra1, pair.rf1, pair.rb1, bore_radius[0]), (pair.ra2, pair.rf2, pair.rb2,
                                                                                  bore_radius[1])):
        d_m = r_a + r_f
        q = 2 * bore / d_m
        inv += 1.0 / (math.pi / 8 * density * (1 - q**4) * d_m**4 / (2 * r_b) ** 2)
    return 1.0 / inv


def dynamic_factor_b(pair: GearPair, pinion_rpm: float, F_t: float, K_A: float, c_prime: float,
                     c_gamma_alpha: float, tolerances: GradeTolerances, density: float, tip_relief: float = 0.0,
                     sigma_Hlim: float = 1.5e9, bore_radius: tuple[float, float] = (0.0, 0.0)) -> DynamicFactorB:
    """K_v of ISO 6336-1 method B (module docstring) for the pinion speed ``pinion_rpm`` [rev/min], the tangential
    load ``F_t`` [N] of one helix, ``c_prime``, ``c_gamma_alpha`` [N/m per m face width, i.e. N/m²],
    ``tip_relief`` C_a [m] (0: C_ay) and the members' ``bore_radius`` [m]."""
    w = F_t * K_A / pair.b * 1e-3                                  # N/mm
    c_p, c_ga = c_prime * 1e-9, c_gamma_alpha * 1e-9               # N/(mm µm)
    m_red = reduced_mass(pair, density, bore_radius)               # kg/m
    n_E1 = 30000.0 / (math.pi * pair.z1) * math.sqrt(c_ga / (m_red * 1e-3))
    N = pinion_rpm / n_E1
    N_S = 0.5 + 0.35 * math.sqrt(w / 100) if w < 100 else 0.85
    C_ay = ((sigma_Hlim * 1e-6 / 97 - 18.45) ** 2 / 18 + 1.5) * 1e-6
    C_a = tip_relief if tip_relief > 0 else C_ay
    f_fa = max(tolerances.f_falpha)
    f_pb_eff = tolerances.f_pb - running_in(tolerances.f_pb)
    f_f_eff = f_fa - running_in(f_fa)
    B_p, B_f = c_p * f_pb_eff * 1e6 / w, c_p * f_f_eff * 1e6 / w
    B_k = abs(1 - c_p * C_a * 1e6 / w)
    cv1, cv2, cv3, cv4, cv5, cv6, cv7 = _cv(pair.eps_gamma)
    main = 1 + cv1 * B_p + cv2 * B_f + cv4 * B_k
    superc = cv5 * B_p + cv6 * B_f + cv7
    if N <= N_S:
        K_v, regime = 1 + N * (cv1 * B_p + cv2 * B_f + cv3 * B_k), "subcritical"
    elif N <= 1.15:
        K_v, regime = main, "main resonance"
    elif N < 1.5:
        K_v, regime = superc + (main - superc) * (1.5 - N) / 0.35, "intermediate"
    else:
        K_v, regime = superc, "supercritical"
    return DynamicFactorB(K_v=K_v, N=N, n_E1=n_E1, N_S=N_S, regime=regime, m_red=m_red, B_p=B_p, B_f=B_f, B_k=B_k,
                          f_pb_eff=f_pb_eff, f_f_eff=f_f_eff, tip_relief=C_a, line_load=w * 1e3)


def face_load_factor_bed(face_width: float, line_load: float, c_gamma_beta: float, gap_slope: float,
                         crowning: float = 0.0, n: int = 2001) -> float:
    """Peak over mean load of an elastic bed (stiffness ``c_gamma_beta`` [N/m²] per unit face width) carrying the
    mean ``line_load`` [N/m] over ``face_width`` [m] under the initial gap g(ζ) = gap_slope ζ/b + crowning
    (2ζ/b − 1)² [m]: w(ζ) = c max(0, δ − g), δ from ∫ w dζ = line_load b (bisection, ``n`` face points)."""
    if line_load <= 0 or c_gamma_beta <= 0:
        raise ValueError(f"line_load and c_gamma_beta must be positive, got {line_load}, {c_gamma_beta}")
    s = np.linspace(0.0, 1.0, n)
    g = abs(gap_slope) * s + crowning * (2 * s - 1) ** 2
    g -= g.min()

    def mean(delta):
        return float(np.trapezoid(c_gamma_beta * np.maximum(delta - g, 0.0), s))

    lo, hi = 0.0, line_load / c_gamma_beta + float(g.max())
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mean(mid) < line_load else (lo, mid)
    delta = 0.5 * (lo + hi)
    return c_gamma_beta * delta / line_load


@document_fields
@dataclass(frozen=True)
class FaceLoadC:
    """ISO 6336-1 method C face load factor and its inputs (SI)."""

    K_Hbeta: float
    """face load factor for the contact stress [-]"""
    F_beta_x: float
    """effective equivalent misalignment before running-in, transverse [m]"""
    y_beta: float
    """running-in allowance y_β = 0.15 F_βx ≤ 6 µm [m]"""
    F_beta_y: float
    """effective equivalent misalignment after running-in, F_βx − y_β [m]"""
    crowning: float
    """lead crowning of both members in the bed's gap, transverse [m]"""
    line_load: float
    """mean line load F_m / b = F_t K_A K_v / b of one helix [N/m]"""
    c_gamma_beta: float
    """mesh stiffness per unit face width c_γβ [N/m²]"""


def face_load_factor_c(face_width: float, line_load: float, c_gamma_beta: float, misalignment: float,
                       crowning: float = 0.0) -> FaceLoadC:
    """K_Hβ of ISO 6336-1 method C from the effective misalignment F_βx = ``misalignment`` [m] (transverse), the mean
    line load F_m/b [N/m], c_γβ [N/m²] and the lead ``crowning`` [m] of both members (0: the standard's
    formulas, eqs. 41–42; else its elastic bed with the crowning in the gap, :func:`face_load_factor_bed`)."""
    F_bx = abs(misalignment)
    y = min(0.15 * F_bx, Y_BETA_CAP)
    F_by = F_bx - y
    if crowning > 0:
        K = face_load_factor_bed(face_width, line_load, c_gamma_beta, F_by, crowning)
    else:
        K = 1 + F_by * c_gamma_beta / (2 * line_load)
        if K > 2:
            K = math.sqrt(2 * F_by * c_gamma_beta / line_load)
    return FaceLoadC(K, F_bx, y, F_by, crowning, line_load, c_gamma_beta)


def transverse_load_factor_b(pair: GearPair, c_gamma_alpha: float, f_pb: float, F_tH_per_b: float,
                             Z_eps: float) -> tuple[float, float]:
    """(K_Hα, its value before the limits) of ISO 6336-1 method B: ``c_gamma_alpha`` [N/m²], the base pitch
    deviation ``f_pb`` [m], F_tH/b = F_t K_A K_v K_Hβ / b [N/m] of one helix, Z_ε of the contact stress."""
    eg = pair.eps_gamma
    term = c_gamma_alpha * (f_pb - running_in(f_pb)) / F_tH_per_b
    raw = eg / 2 * (0.9 + 0.4 * term) if eg <= 2 else 0.9 + 0.4 * math.sqrt(2 * (eg - 1) / eg) * term
    return min(max(raw, 1.0), eg / (pair.eps_alpha * Z_eps**2)), raw


#: the sources a rating factor can name (results.json ``load_factors.<K>.source``)
SOURCES = ("scene", "femgear dynamics", "femgear LTCA", "ISO 6336-1 method B", "ISO 6336-1 method C")


@document_fields
@dataclass(frozen=True)
class RatingFactor:
    """One load factor of the rating: the value used, where it comes from, and ISO's value beside it."""

    value: float
    """the factor the rating uses [-]"""
    source: str
    """where ``value`` comes from: one of :data:`SOURCES` [-]"""
    iso: float
    """ISO 6336-1's own value (method B for K_v and K_Hα, C for K_Hβ) on the same pair and load [-]"""
    iso_method: str
    """the ISO method of ``iso`` [-]"""
    femgear: float | None = None
    """femgear's own value where its physics computed it (the dynamics, the LTCA), else None [-]"""
    note: str = ""
    """what the value rests on, in words (the misalignment the LTCA saw, the helix of the peak dynamic force) [-]"""


@document_fields
@dataclass(frozen=True)
class RatingFactors:
    """K_v, K_Hβ and K_Hα of a rating with their sources and ISO's values, and ISO's inputs (SI)."""

    K_v: RatingFactor
    """dynamic factor [-]"""
    K_Hbeta: RatingFactor
    """face load factor for the contact stress [-]"""
    K_Halpha: RatingFactor
    """transverse load factor for the contact stress [-]"""
    tolerances: GradeTolerances
    """ISO 1328-1 tolerances of the scene's accuracy grade [-]"""
    dynamic_b: DynamicFactorB
    """ISO 6336-1 method B K_v and its inputs [-]"""
    face_c: FaceLoadC
    """ISO 6336-1 method C K_Hβ and its inputs [-]"""
    K_v_helices: tuple[float, ...] = ()
    """femgear's K_v per loaded helix, max N_s(t) / mean N_s (empty without dynamics) [-]"""


@document_fields
@dataclass(frozen=True)
class DynamicFactorCurve:
    """K_v against the pinion speed: femgear's dynamics beside ISO 6336-1 method B (``femgear dynamics --sweep``)."""

    speed_rpm: np.ndarray
    """pinion speeds [rev/min]"""
    femgear: np.ndarray
    """(helix, speed) largest dynamic over static mesh force of each loaded helix (the time-domain sweep) [-]"""
    iso: np.ndarray
    """ISO 6336-1 method B K_v at each speed [-]"""
    N: np.ndarray
    """resonance ratio n₁/n_E1 at each speed [-]"""
    n_E1: float
    """ISO's resonance speed of the pinion [rev/min]"""
    N_S: float
    """lower limit of ISO's main resonance range [-]"""


__all__ = ["DynamicFactorB", "DynamicFactorCurve", "RatingFactor", "RatingFactors", "SOURCES", "FaceLoadC", "GradeTolerances", "dynamic_factor_b", "face_load_factor_bed",
           "face_load_factor_c", "grade_tolerances", "reduced_mass", "running_in", "transverse_load_factor_b"]
