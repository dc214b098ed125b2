"""Scuffing: ISO/TS 6336-20 (flash temperature) and ISO/TS 6336-21 (integral temperature).

Along the path of contact (transverse roll length u from T1; ρ_1 = u, ρ_2 = g − u, the
normal radii ρ/cos β_b, rolling speeds v_i = ω_i ρ_i):

    w_n(u)   = X_Γ(u) K F_t / (b cos α_wt)                      local normal load per length [N/m]
    θ_fl(u)  = 1.11 μ_m w_n |v1 − v2| / (√(2 b_H) (B_M1 √v1 + B_M2 √v2))    Blok's flash temperature
               (:func:`femgear.physics.lubrication.flash.blok_flash_temperature`; ISO/TS 6336-20 writes the
               same expression in the closed form μ_m X_M X_J X_G (X_Γ w_Bt)^0.75 v^0.5/a^0.25, X_M the
               steel's E_r^¼/B_M = 50 K N^-¾ s^½ m^-½ mm; X_J = 1: no approach-factor increase)
    b_H      = √(8 w_n ρ_red,n/(π E_r)),  E_r = E/(1 − ν²)
    μ_m      = 0.045 (w_Bt K/(v_ΣC ρ_redC))^0.2 η_oil^-0.05 X_R X_L,  X_R = 2.2 (R_a/ρ_redC)^0.25
               (w in N/mm, v in m/s, ρ in mm, η in mPa s, R_a = (R_a1 + R_a2)/2 in µm; ISO/TS 6336-21,
               used for both methods)
    X_Γ      load sharing: spur, unmodified: 1/3 → 2/3 over A–B, 1 over B–D, 2/3 → 1/3 over D–E;
               ε_β ≥ 1: 1/ε_α; 0 < ε_β < 1: the blend (1 − ε_β) X_Γ,spur + ε_β/ε_α (ISO/TS 6336-20 §5.5)

Flash temperature method (ISO/TS 6336-20):
    θ_M = θ_oil + 0.47 X_S X_mp θ_fl,m  (θ_fl,m the mean over the path),  θ_B = θ_M + θ_fl
    S_B = (θ_S − θ_oil) / (θ_B,max − θ_oil)
Integral temperature method (ISO/TS 6336-21):
    θ_fla,int = θ_fl,m,   θ_M = θ_oil + C_1 X_mp θ_fla,int,   θ_int = θ_M + C_2 θ_fla,int   (C_1 0.7, C_2 1.5)
    S_intS = θ_intS / θ_int   (temperatures in °C, as the TS writes them)

Scuffing temperatures from the oil's FZG load stage: the TS's empirical θ_S and θ_intS are
fits of the contact temperatures that the same methods give for the FZG A test gear
(ISO 14635-1, A/8.3/90: z 16/24, m 4.5 mm, x 0.8532/−0.5, b 20 mm, a 91.5 mm, 8.3 m/s at the
pitch circle, 90 °C dip-lubricated) at the failure load stage.  femgear computes them
exactly that way, on its own FZG A pair, with the scene's oil and the torque of the
stage (:data:`FZG_A_TORQUE`), so that the FZG A gear at its failure stage has S_B = S_intS = 1
by construction, and ISO's simplifications cancel between the test and the application
(structural factor X_W scales the test's flash part).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair
from femgear.physics.lubrication.flash import blok_flash_temperature

#: FZG pinion torques of load stages 1–14 [N m] (ISO 14635-1, 0.5 m load lever; stage 10 is 372.6,
#: GEARpie's table prints 272.7, out of sequence)
FZG_A_TORQUE = (3.3, 13.7, 35.3, 60.8, 94.1, 135.5, 183.4, 239.3, 302.0, 372.6, 450.1, 534.5, 626.9, 714.2)
#: X_L of the oil type (ISO/TS 6336-20 Table 3)
OIL_FACTOR = {"mineral": 1.0, "pao": 0.8, "pag": 0.7, "pag-water": 0.6, "traction": 1.5, "phosphate-ester": 1.3}
C1, C2 = 0.7, 1.5


def fzg_a_pair() -> GearPair:
    """The FZG A scuffing test gear pair (ISO 14635-1; tip diameters 88.5/112.3 mm from x and a_w, the
    rig's are 88.77/112.5 mm).  Not checked: the A wheel (x = −0.5, z = 24) lies just beyond the ISO 53
    rack's undercut limit; the rating needs only its radii."""
    return GearPair(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.020, x1=0.8532, x2=-0.5,
                    kind="spur")


def fzg_torque(stage: float) -> float:
    """Pinion torque of FZG load stage ``stage`` (1–14; fractional stages interpolate) [N m]."""
    if not 1 <= stage <= 14:
        raise ValueError(f"FZG load stage must lie in 1…14, got {stage!r}")
    return float(np.interp(stage, np.arange(1, 15), FZG_A_TORQUE))


@dataclass(frozen=True)
class ScuffingInputs:
    """Inputs shared by both scuffing methods (SI)."""

    oil_temperature: float          #: θ_oil [K]
    oil_viscosity: float            #: dynamic viscosity at θ_oil [Pa s]
    youngs_modulus: float = 206e9
    poisson_ratio: float = 0.3
    effusivity: float = 13795.0     #: B_M = √(λρc) of the flanks [W s^½/(m² K)]
    Ra: tuple[float, float] = (0.5e-6, 0.5e-6)  #: arithmetic mean roughness of pinion, gear [m]
    X_L: float = 1.0                #: oil type factor (mineral 1)
    K: float = 1.0                  #: K_A K_v K_Bβ K_Bα
    X_S: float = 1.0                #: lubrication: 1 dip, 1.2 spray
    X_mp: float = 1.0               #: (1 + n_p)/2, n_p the number of meshes of the pinion
    X_W: float = 1.0                #: structural factor of the application's material relative to the test


@document_fields
@dataclass(frozen=True)
class FlashPath:
    """Flash temperature along the path (arrays over u, SI, temperatures in K)."""

    u: np.ndarray
    """path positions, measured from T1 (the pinion's transverse roll length ρ₁) [m]"""
    load_sharing: np.ndarray
    """load sharing factor X_Γ along the path [-]"""
    line_load: np.ndarray
    """normal load per unit face width w_n along the path [N/m]"""
    mu_m: float
    """mean friction coefficient [-]"""
    flash: np.ndarray
    """flash temperature θ_fl along the path [K]"""

    @property
    def mean_flash(self) -> float:
        """θ_fl,m, the path mean (trapezoid) [K]."""
        return float(np.trapezoid(self.flash, self.u) / (self.u[-1] - self.u[0]))


@document_fields
@dataclass(frozen=True)
class ScuffingRating:
    """Both scuffing methods for one pair (temperatures in K; ratios as the TS defines them)."""

    path: FlashPath
    """the flash temperature along the path of the flash temperature method [-]"""
    theta_oil: float
    """oil (supply) temperature θ_oil [K]"""
    theta_M: float
    """bulk temperature of the flash method [K]"""
    contact_temperature: np.ndarray
    """θ_B = θ_M + θ_fl along the path [K]"""
    theta_S: float
    """scuffing temperature [K]"""
    S_B: float
    """scuffing safety factor of the flash temperature method S_B (ISO/TS 6336-20) [-]"""
    theta_M_int: float
    """bulk temperature of the integral method [K]"""
    theta_int: float
    """integral temperature [K]"""
    theta_intS: float
    """permissible integral temperature [K]"""
    S_intS: float
    """scuffing safety factor of the integral temperature method S_intS (ISO/TS 6336-21) [-]"""
    fzg_stage: float
    """the oil's FZG A/8.3/90 failure load stage [-]"""

    @property
    def max_contact_temperature(self) -> float:
        return float(np.max(self.contact_temperature))


def _path_grid(pair: GearPair, n: int) -> np.ndarray:
    u = np.linspace(pair.u_start, pair.u_end, n)
    marks = [pair.u_end - pair.p_bt, pair.u_start + pair.p_bt, pair.u_pitch]
    return np.unique(np.concatenate([u, [m for m in marks if pair.u_start < m < pair.u_end]]))


def load_sharing_factor(pair: GearPair, u: np.ndarray) -> np.ndarray:
    """X_Γ along the path (unmodified profiles, buttressing neglected)."""
    uA, uE, pb = pair.u_start, pair.u_end, pair.p_bt
    uB, uD = uE - pb, uA + pb
    if pair.eps_alpha < 2:          # A–B double, B–D single, D–E double contact
        spur = np.ones_like(u)
        spur = np.where(u < uB, 1 / 3 + (u - uA) / (uB - uA) / 3, spur)
        spur = np.where(u > uD, 1 / 3 + (uE - u) / (uE - uD) / 3, spur)
    else:
        spur = np.full_like(u, 1 / pair.eps_alpha)
    eb = pair.eps_beta
    if eb >= 1:
        return np.full_like(u, 1 / pair.eps_alpha)
    return (1 - eb) * spur + eb / pair.eps_alpha


def mean_friction(pair: GearPair, F_t: float, pinion_rpm: float, inputs: ScuffingInputs) -> float:
    """μ_mC of ISO/TS 6336-21 (w in N/mm, v in m/s, ρ in mm, η in mPa s, R_a in µm)."""
    w_Bt = inputs.K * F_t / pair.n_helices / pair.b * 1e-3
    v_t = math.pi * 2 * pair.r1 * pinion_rpm / 60
    v_sum = 2 * v_t * math.sin(pair.alpha_wt)
    rho_C = pair.u / (1 + pair.u) ** 2 * pair.a_w * math.sin(pair.alpha_wt) / math.cos(pair.beta_b) * 1e3
    Ra = 0.5 * (inputs.Ra[0] + inputs.Ra[1]) * 1e6
    X_R = 2.2 * (Ra / rho_C) ** 0.25
    return 0.045 * (w_Bt / (v_sum * rho_C)) ** 0.2 * (inputs.oil_viscosity * 1e3) ** -0.05 * X_R * inputs.X_L


def flash_path(pair: GearPair, pinion_torque: float, pinion_rpm: float, inputs: ScuffingInputs,
               n: int = 81) -> FlashPath:
    """Blok flash temperature along the path of contact with the ISO load sharing and μ_m."""
    if not (pinion_torque > 0 and pinion_rpm > 0):
        raise ValueError(f"torque and speed must be positive, got {pinion_torque!r}, {pinion_rpm!r}")
    u = _path_grid(pair, n)
    F_t = pinion_torque / pair.r1
    X = load_sharing_factor(pair, u)
    w = X * inputs.K * F_t / pair.n_helices / (pair.b * math.cos(pair.alpha_wt))
    cb = math.cos(pair.beta_b)
    r1, r2 = u / cb, (pair.line_of_action - u) / cb
    R = r1 * r2 / (r1 + r2)
    E_r = inputs.youngs_modulus / (1 - inputs.poisson_ratio**2)
    b = np.sqrt(8 * w * R / (math.pi * E_r))
    w1 = pinion_rpm * 2 * math.pi / 60
    v1, v2 = w1 * u, w1 / pair.u * (pair.line_of_action - u)
    mu = mean_friction(pair, F_t, pinion_rpm, inputs)
    B = inputs.effusivity
    theta = blok_flash_temperature(mu, w, v1 - v2, b, v1, v2, B, B)
    return FlashPath(u=u, load_sharing=X, line_load=w, mu_m=mu, flash=np.asarray(theta, float))


def _temperatures(path: FlashPath, theta_oil: float, inputs: ScuffingInputs) -> tuple[float, float, float]:
    """(θ_B,max of the flash method, θ_M of the flash method, θ_int) [K]."""
    m = path.mean_flash
    theta_M = theta_oil + 0.47 * inputs.X_S * inputs.X_mp * m
    theta_int = theta_oil + C1 * inputs.X_mp * m + C2 * m
    return theta_M + float(np.max(path.flash)), theta_M, theta_int


def fzg_scuffing_temperatures(stage: float, inputs: ScuffingInputs, test_viscosity: float) -> tuple[float, float]:
    """(θ_S, θ_intS) [K] of an oil failing at FZG A/8.3/90 load stage ``stage``: the contact and integral
    temperatures of the FZG A test gear there (dip lubrication, 90 °C, the oil's viscosity ``test_viscosity``
    [Pa s] at 90 °C, test flanks R_a 0.35 µm; X_W scales the flash part)."""
    pair = fzg_a_pair()
    rpm = 8.3 / (math.pi * 2 * pair.rw1) * 60
    test = replace(inputs, oil_temperature=363.15, oil_viscosity=test_viscosity, Ra=(0.35e-6, 0.35e-6), K=1.0,
                   X_S=1.0, X_mp=1.0)
    path = flash_path(pair, fzg_torque(stage), rpm, test)
    m, peak = path.mean_flash, float(np.max(path.flash))
    theta_S = 363.15 + inputs.X_W * (0.47 * m + peak)
    theta_intS = 363.15 + C1 * m + inputs.X_W * C2 * m
    return theta_S, theta_intS


def scuffing_rating(pair: GearPair, pinion_torque: float, pinion_rpm: float, inputs: ScuffingInputs,
                    fzg_stage: float, test_viscosity: float, n: int = 81) -> ScuffingRating:
    """Flash- and integral-temperature scuffing rating of ``pair`` for an oil of FZG failure stage ``fzg_stage``."""
    path = flash_path(pair, pinion_torque, pinion_rpm, inputs, n)
    th_oil = inputs.oil_temperature
    B_max, theta_M, theta_int = _temperatures(path, th_oil, inputs)
    theta_S, theta_intS = fzg_scuffing_temperatures(fzg_stage, inputs, test_viscosity)
    c = 273.15
    return ScuffingRating(
        path=path, theta_oil=th_oil, theta_M=theta_M, contact_temperature=theta_M + path.flash, theta_S=theta_S,
        S_B=(theta_S - th_oil) / (B_max - th_oil), theta_M_int=th_oil + C1 * inputs.X_mp * path.mean_flash,
        theta_int=theta_int, theta_intS=theta_intS, S_intS=(theta_intS - c) / (theta_int - c), fzg_stage=fzg_stage)
