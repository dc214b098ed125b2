"""ISO 6336-3 method B: tooth-root bending stress σ_F, permissible σ_FP and safety S_F.

Nominal and actual root stress, per member (method B: load at the outer point of single
tooth contact of the virtual spur gear, 30° tangents to the root fillet):

    σ_F0 = F_t/(b m_n) Y_F Y_S Y_β Y_B Y_DT,   σ_F = σ_F0 K_A K_v K_Fβ K_Fα        (ISO 6336-3 eqs. 2, 3)
    K_Fβ = K_Hβ^N_F,  N_F = (b/h)² / (1 + b/h + (b/h)²)                            (ISO 6336-1 eq. 67)

Root geometry of the virtual spur gear (z_n = z/(cos²β_b cos β)) cut by the basic rack
(h_fP, ρ_fP, α_n; no protuberance), ISO 6336-3 §6.2 (2006 numbering):

    E = π m_n/4 − h_fP tan α_n − (1 − sin α_n) ρ_fP / cos α_n
    G = ρ_fP/m_n − h_fP/m_n + x,   H = 2/z_n (π/2 − E/m_n) − π/3
    θ = 2G/z_n tan θ − H          (fixed point, θ₀ = π/6)
    s_Fn/m_n = z_n sin(π/3 − θ) + √3 (G/cos θ − ρ_fP/m_n)
    ρ_F/m_n  = ρ_fP/m_n + 2G² / (cos θ (z_n cos²θ − 2G))
    d_en = 2 √{[√((d_an/2)² − (d_bn/2)²) − p_bn (ε_αn − 1)]² + (d_bn/2)²},  ε_αn = ε_α/cos²β_b
    α_en = arccos(d_bn/d_en),  γ_e = (π/2 + 2x tan α_n)/z_n + inv α_n − inv α_en,  α_Fen = α_en − γ_e
    h_Fe/m_n = ½[(cos γ_e − sin γ_e tan α_Fen) d_en/m_n − z_n cos(π/3 − θ) − G/cos θ + ρ_fP/m_n]
    Y_F = 6 (h_Fe/m_n) cos α_Fen / ((s_Fn/m_n)² cos α_n)
    Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L)),  L = s_Fn/h_Fe,  q_s = s_Fn/(2ρ_F)

These are the closed form of the trochoid that :func:`femgear.physics.geometry.profile.tooth_profile`
generates from the same rack: for a spur gear the 30° tangent point, s_Fn and ρ_F of the
generated profile agree with them (``tests/rating/test_bending.py``).

Other factors:
    Y_β = 1 − ε_β β/120°, with ε_β ≤ 1 and β ≤ 30° in the formula                     (ISO 6336-3:2006 eq. 35)
    Y_B = 1 for s_R/h_t ≥ 1.2, 1.6 ln(2.242 h_t/s_R) for 0.5 < s_R/h_t < 1.2           (rim thickness factor)
    Y_DT = 1 for ε_αn ≤ 2.05, −0.666 ε_αn + 2.366 up to 2.5, 0.7 above (accuracy grade ≤ 4 only;
           femgear does not know the grade: Y_DT is applied, and said so, only when given)
    σ_FG = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X,  σ_FP = σ_FG/S_Fmin,  S_F = σ_FG/σ_F   (eqs. 4–6)
    Y_ST = 2;  Y_NT (case-hardened, Table 3): N_L ≤ 1e3: 2.5, ≤ 3e6: (3e6/N_L)^0.1151,
           ≤ 1e10: (3e6/N_L)^0.02, beyond 0.85
    Y_δrelT = (1 + √(ρ' χ*)) / (1 + √(ρ' χ*_T)),  χ* = (1 + 2 q_s)/5 mm⁻¹, χ*_T = 1.2 mm⁻¹,
           ρ' = 0.003 mm (case-hardened steel; slip-layer thickness)                       (eqs. 41, 44)
    Y_RrelT = 1.674 − 0.529 (R_z + 1)^0.1 (case-hardened, 1 ≤ R_z ≤ 40 µm), 1.12 below R_z 1 µm  (eq. 50)
    Y_X = 1 (m_n ≤ 5 mm), 1.05 − 0.01 m_n (5 < m_n < 25 mm), 0.8 above (case-hardened)      (Table 5)

A double-helical pair is rated per helix (F_t/2 on the helix width b).  SI inside; the
empirical constants take mm and µm where the standard writes them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair, inv
from femgear.physics.stiffness.iso6336 import virtual_teeth


@document_fields
@dataclass(frozen=True)
class RootGeometry:
    """The 30°-tangent root section of one member's virtual spur gear (SI)."""

    z_n: float
    """virtual number of teeth [-]"""
    theta: float
    """the auxiliary angle θ of the 30° tangent [rad]"""
    s_Fn: float
    """tooth root chord at the 30° tangents [m]"""
    rho_F: float
    """root fillet radius at the 30° tangent [m]"""
    h_Fe: float
    """bending moment arm, load at the outer point of single contact [m]"""
    alpha_Fen: float
    """load direction angle at that point [rad]"""
    d_en: float
    """diameter of the outer point of single contact (virtual gear) [m]"""

    @property
    def q_s(self) -> float:
        return self.s_Fn / (2 * self.rho_F)


@document_fields
@dataclass(frozen=True)
class BendingInputs:
    """Inputs of the root rating (SI; defaults: case-carburised steel, reference conditions)."""

    sigma_Flim: float = 5.0e8
    """nominal stress number for bending σ_Flim (ISO 6336-5 MQ: 500 N/mm²) [Pa]"""
    S_Fmin: float = 1.0
    """minimum required bending safety factor S_Fmin [-]"""
    K_A: float = 1.0
    """application factor K_A [-]"""
    K_v: float = 1.0
    """dynamic factor K_v [-]"""
    K_Hbeta: float = 1.0
    """face load factor K_Hβ; K_Fβ follows from it (ISO 6336-1 eq. 67) [-]"""
    K_Falpha: float = 1.0
    """transverse load factor for bending K_Fα [-]"""
    life_hours: float | None = None
    """required life L_h (None: Y_NT = 1) [h]"""
    root_Rz: tuple[float, float] = (1.0e-5, 1.0e-5)
    """root roughness R_z of pinion, gear [m]"""
    rim_ratio: tuple[float, float] = (math.inf, math.inf)
    """rim thickness over tooth height s_R/h_t of pinion, gear (∞: solid) [-]"""
    Y_DT: float = 1.0
    """deep-tooth factor Y_DT as given (1: not applied) [-]"""


@document_fields
@dataclass(frozen=True)
class BendingRating:
    """ISO 6336-3 method B root stress and safety of pinion and gear (tuples: pinion, gear)."""

    F_t: float
    """nominal tangential load at the reference circle, all helices [N]"""
    root: tuple[RootGeometry, RootGeometry]
    """the 30°-tangent root section of the pinion's and the gear's virtual spur gear [-]"""
    Y_F: tuple[float, float]
    """form factor Y_F of pinion, gear [-]"""
    Y_S: tuple[float, float]
    """stress correction factor Y_S of pinion, gear [-]"""
    Y_beta: float
    """helix angle factor Y_β [-]"""
    Y_B: tuple[float, float]
    """rim thickness factor Y_B of pinion, gear [-]"""
    Y_DT: float
    """deep-tooth factor Y_DT [-]"""
    K_Fbeta: float
    """face load factor for bending K_Fβ [-]"""
    sigma_F0: tuple[float, float]
    """nominal tooth-root stress σ_F0 of pinion, gear [Pa]"""
    sigma_F: tuple[float, float]
    """tooth-root stress σ_F = σ_F0 K_A K_v K_Fβ K_Fα of pinion, gear [Pa]"""
    N_L: tuple[float, float] | None
    """load cycles of pinion, gear over the required life (None: no life given) [-]"""
    Y_NT: tuple[float, float]
    """life factor Y_NT of pinion, gear [-]"""
    Y_deltarelT: tuple[float, float]
    """relative notch sensitivity factor Y_δrelT of pinion, gear [-]"""
    Y_RrelT: tuple[float, float]
    """relative surface factor Y_RrelT of pinion, gear [-]"""
    Y_X: float
    """size factor Y_X [-]"""
    sigma_FG: tuple[float, float]
    """tooth-root stress limit σ_FG of pinion, gear [Pa]"""
    sigma_FP: tuple[float, float]
    """permissible bending stress σ_FP = σ_FG / S_Fmin of pinion, gear [Pa]"""
    S_F: tuple[float, float]
    """bending safety factor S_F = σ_FG / σ_F of pinion, gear [-]"""
    inputs: BendingInputs
    """the inputs of the rating [-]"""


def root_geometry(pair: GearPair, member: int) -> RootGeometry:
    """s_Fn, ρ_F, h_Fe, α_Fen of ``member``'s virtual spur gear (ISO 6336-3 method B, external gear)."""
    z = pair.z1 if member == 1 else pair.z2
    x = pair.x1 if member == 1 else pair.x2
    ra = pair.ra1 if member == 1 else pair.ra2
    mn, an = pair.m_n, pair.alpha_n
    zn = virtual_teeth(z, pair.beta, pair.beta_b)
    rho, hf = pair.rho_fP, pair.h_fP                       # / m_n
    E = math.pi / 4 - hf * math.tan(an) - (1 - math.sin(an)) * rho / math.cos(an)   # / m_n
    G = rho - hf + x
    H = 2 / zn * (math.pi / 2 - E) - math.pi / 3
    theta = math.pi / 6
    for _ in range(200):
        new = 2 * G / zn * math.tan(theta) - H
        if abs(new - theta) < 1e-14:
            break
        theta = new
    else:
        raise ValueError(f"the 30° tangent iteration of member {member} did not converge (θ = {theta!r})")
    theta = new
    s_Fn = zn * math.sin(math.pi / 3 - theta) + math.sqrt(3) * (G / math.cos(theta) - rho)
    rho_F = rho + 2 * G**2 / (math.cos(theta) * (zn * math.cos(theta) ** 2 - 2 * G))
    d = 2 * (pair.r1 if member == 1 else pair.r2)
    dn, dbn = mn * zn, mn * zn * math.cos(an)
    dan = dn + 2 * ra - d
    eps_an = pair.eps_alpha / math.cos(pair.beta_b) ** 2
    p_bn = math.pi * mn * math.cos(an)
    den = 2 * math.sqrt((math.sqrt((dan / 2) ** 2 - (dbn / 2) ** 2) - p_bn * (eps_an - 1)) ** 2 + (dbn / 2) ** 2)
    a_en = math.acos(dbn / den)
    g_e = (math.pi / 2 + 2 * x * math.tan(an)) / zn + inv(an) - inv(a_en)
    a_Fen = a_en - g_e
    h_Fe = 0.5 * ((math.cos(g_e) - math.sin(g_e) * math.tan(a_Fen)) * den / mn - zn * math.cos(math.pi / 3 - theta)
                  - G / math.cos(theta) + rho)
    return RootGeometry(z_n=zn, theta=theta, s_Fn=s_Fn * mn, rho_F=rho_F * mn, h_Fe=h_Fe * mn, alpha_Fen=a_Fen,
                        d_en=den)


def form_factor(pair: GearPair, g: RootGeometry) -> float:
    """Y_F = 6 (h_Fe/m_n) cos α_Fen / ((s_Fn/m_n)² cos α_n)."""
    mn = pair.m_n
    return 6 * g.h_Fe / mn * math.cos(g.alpha_Fen) / ((g.s_Fn / mn) ** 2 * math.cos(pair.alpha_n))


def stress_correction_factor(g: RootGeometry) -> float:
    """Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L))."""
    L = g.s_Fn / g.h_Fe
    return (1.2 + 0.13 * L) * g.q_s ** (1 / (1.21 + 2.3 / L))


def helix_angle_factor(pair: GearPair) -> float:
    """Y_β = 1 − ε_β β/120° (ε_β ≤ 1, β ≤ 30° in the formula)."""
    eb = min(pair.eps_beta, 1.0)
    return 1 - eb * min(math.degrees(pair.beta), 30.0) / 120


def rim_factor(ratio: float) -> float:
    """Y_B of the rim thickness ratio s_R/h_t (external gears)."""
    if ratio >= 1.2:
        return 1.0
    if ratio < 0.5 * (1 - 1e-9):     # the limit itself, 0.5, is the thinnest rim the FE bodies mesh: Y_B = 2.40
        raise ValueError(f"rim thickness ratio s_R/h_t = {ratio:.3g} is below ISO 6336-3's limit 0.5")
    return 1.6 * math.log(2.242 / ratio)


def deep_tooth_factor(eps_an: float) -> float:
    """Y_DT of the virtual contact ratio (accuracy grade ≤ 4)."""
    if eps_an <= 2.05:
        return 1.0
    return -0.666 * eps_an + 2.366 if eps_an <= 2.5 else 0.7


def face_load_factor_root(pair: GearPair, K_Hbeta: float) -> float:
    """K_Fβ = K_Hβ^N_F, h the tooth depth (mean of both members)."""
    h = 0.5 * ((pair.ra1 - pair.rf1) + (pair.ra2 - pair.rf2))
    bh = pair.b / h
    return K_Hbeta ** (bh**2 / (1 + bh + bh**2))


def life_factor_root(N_L: float) -> float:
    """Y_NT of case-hardened steel (ISO 6336-3 Table 3)."""
    if N_L <= 1e3:
        return 2.5
    if N_L <= 3e6:
        return (3e6 / N_L) ** 0.1151
    if N_L <= 1e10:
        return (3e6 / N_L) ** 0.02
    return 0.85


def notch_sensitivity_factor(q_s: float) -> float:
    """Y_δrelT for case-hardened steel (ρ' = 0.003 mm)."""
    rho = 0.003
    return (1 + math.sqrt(rho * (1 + 2 * q_s) / 5)) / (1 + math.sqrt(rho * 1.2))


def surface_factor(Rz: float) -> float:
    """Y_RrelT of the root roughness R_z [m] (case-hardened)."""
    rz = Rz * 1e6
    return 1.12 if rz < 1 else 1.674 - 0.529 * (rz + 1) ** 0.1


def size_factor_root(m_n: float) -> float:
    mm = m_n * 1e3
    return 1.0 if mm <= 5 else (1.05 - 0.01 * mm if mm < 25 else 0.8)


def bending_rating(pair: GearPair, pinion_torque: float, pinion_rpm: float,
                   inputs: BendingInputs = BendingInputs()) -> BendingRating:
    """ISO 6336-3 method B rating of both members under ``pinion_torque`` [N m] at ``pinion_rpm``."""
    if not (pinion_torque > 0 and math.isfinite(pinion_torque)):
        raise ValueError(f"pinion_torque must be positive and finite, got {pinion_torque!r}")
    F_t = 2 * pinion_torque / (2 * pair.r1)
    roots = (root_geometry(pair, 1), root_geometry(pair, 2))
    Y_F = tuple(form_factor(pair, g) for g in roots)
    Y_S = tuple(stress_correction_factor(g) for g in roots)
    Y_beta = helix_angle_factor(pair)
    Y_B = tuple(rim_factor(r) for r in inputs.rim_ratio)
    K_Fb = face_load_factor_root(pair, inputs.K_Hbeta)
    nominal = F_t / pair.n_helices / (pair.b * pair.m_n)
    s0 = tuple(nominal * Y_F[i] * Y_S[i] * Y_beta * Y_B[i] * inputs.Y_DT for i in range(2))
    K = inputs.K_A * inputs.K_v * K_Fb * inputs.K_Falpha
    sF = tuple(s * K for s in s0)
    if inputs.life_hours is None:
        N_L, Y_NT = None, (1.0, 1.0)
    else:
        N_L = (60 * pinion_rpm * inputs.life_hours, 60 * pinion_rpm * pair.z1 / pair.z2 * inputs.life_hours)
        Y_NT = (life_factor_root(N_L[0]), life_factor_root(N_L[1]))
    Y_d = tuple(notch_sensitivity_factor(g.q_s) for g in roots)
    Y_R = tuple(surface_factor(r) for r in inputs.root_Rz)
    Y_X = size_factor_root(pair.m_n)
    sG = tuple(inputs.sigma_Flim * 2.0 * Y_NT[i] * Y_d[i] * Y_R[i] * Y_X for i in range(2))
    return BendingRating(
        F_t=F_t, root=roots, Y_F=Y_F, Y_S=Y_S, Y_beta=Y_beta, Y_B=Y_B, Y_DT=inputs.Y_DT, K_Fbeta=K_Fb,
        sigma_F0=s0, sigma_F=sF, N_L=N_L, Y_NT=Y_NT, Y_deltarelT=Y_d, Y_RrelT=Y_R, Y_X=Y_X, sigma_FG=sG,
        sigma_FP=tuple(s / inputs.S_Fmin for s in sG), S_F=tuple(sG[i] / sF[i] for i in range(2)), inputs=inputs)
