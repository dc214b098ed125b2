"""ISO 6336-2:2019 method B: contact stress σ_H0, σ_H and its Z factors.

    σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d_1 b) · (u + 1)/u)                      (ISO 6336-2 eq. 2)
    σ_H1,2 = Z_B,D σ_H0 √(K_A K_v K_Hβ K_Hα)                                (eqs. 1, 3)
    Z_H = √(2 cos β_b cos α_wt / (cos²α_t sin α_wt))                        (eq. 10)
    Z_E = √(1 / (π [(1 − ν1²)/E1 + (1 − ν2²)/E2]))                          (eq. 22)
    Z_ε = √((4 − ε_α)/3 (1 − ε_β) + ε_β/ε_α)  (ε_β < 1),  √(1/ε_α)  (ε_β ≥ 1)   (eqs. 23–25)
    Z_β = 1/√(cos β)                                                          (eq. 26)
    M_1 = tan α_wt / √{[√(d_a1²/d_b1² − 1) − 2π/z_1][√(d_a2²/d_b2² − 1) − (ε_α − 1) 2π/z_2]}
    M_2 = the same with the indices exchanged                                 (eqs. 11, 12)
    Z_B = max(1, M_1 − ε_β (M_1 − 1)) for ε_β < 1, else 1 (Z_D likewise with M_2)  (§6.2)

F_t = 2 T_1/d_1 is the nominal tangential load at the reference circle; a double-helical
pair is rated per helix (F_t/2 on the helix width b).  SI inside: stresses in Pa, Z_E
in √Pa.  Checked against ISO/TR 6336-30:2017 example 1 in ``tests/rating``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.iso6336 import virtual_teeth


@document_fields
@dataclass(frozen=True)
class LoadFactors:
    """K_A, K_v, K_Hβ, K_Hα (defaults 1: give the application's values)."""

    K_A: float = 1.0
    """application factor K_A [-]"""
    K_v: float = 1.0
    """dynamic factor K_v [-]"""
    K_Hbeta: float = 1.0
    """face load factor for contact stress K_Hβ [-]"""
    K_Halpha: float = 1.0
    """transverse load factor for contact stress K_Hα [-]"""

    def __post_init__(self):
        for name in ("K_A", "K_v", "K_Hbeta", "K_Halpha"):
            value = getattr(self, name)
            if not (value >= 1 and math.isfinite(value)):
                raise ValueError(f"{name} must be ≥ 1 and finite, got {value!r}")

    @property
    def product(self) -> float:
        return self.K_A * self.K_v * self.K_Hbeta * self.K_Halpha


@document_fields
@dataclass(frozen=True)
class ContactStress:
    """ISO 6336-2 method B contact stress of a pair (both members; SI)."""

    F_t: float
    """nominal tangential load at the reference circle, all helices [N]"""
    z_n: tuple[float, float]
    """virtual numbers of teeth [-]"""
    Z_H: float
    """zone factor Z_H [-]"""
    Z_E: float
    """elasticity factor Z_E [√Pa]"""
    Z_eps: float
    """contact ratio factor Z_ε [-]"""
    Z_beta: float
    """helix angle factor Z_β [-]"""
    Z_B: float
    """single pair tooth contact factor of the pinion Z_B [-]"""
    Z_D: float
    """single pair tooth contact factor of the gear Z_D [-]"""
    M_1: float
    """auxiliary M_1 of Z_B (ISO 6336-2 eq. 12) [-]"""
    M_2: float
    """auxiliary M_2 of Z_D (ISO 6336-2 eq. 13) [-]"""
    sigma_H0: float
    """nominal contact stress at the pitch point [Pa]"""
    sigma_H: tuple[float, float]
    """contact stress of the pinion (with Z_B) and gear (with Z_D), σ_H = Z_B,D σ_H0 √(K_A K_v K_Hβ K_Hα) [Pa]"""
    factors: LoadFactors
    """the load factors K_A, K_v, K_Hβ, K_Hα [-]"""


def zone_factor(pair: GearPair) -> float:
    """Z_H = √(2 cos β_b cos α_wt / (cos²α_t sin α_wt))."""
    return math.sqrt(2 * math.cos(pair.beta_b) * math.cos(pair.alpha_wt)
                     / (math.cos(pair.alpha_t) ** 2 * math.sin(pair.alpha_wt)))


def elasticity_factor(E1: float, nu1: float, E2: float | None = None, nu2: float | None = None) -> float:
    """Z_E = √(1/(π[(1−ν1²)/E1 + (1−ν2²)/E2])) [√Pa]."""
    E2 = E1 if E2 is None else E2
    nu2 = nu1 if nu2 is None else nu2
    return math.sqrt(1 / (math.pi * ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)))


def contact_ratio_factor(eps_alpha: float, eps_beta: float) -> float:
    """Z_ε of ISO 6336-2 eqs. 23–25."""
    if eps_beta >= 1:
        return math.sqrt(1 / eps_alpha)
    return math.sqrt((4 - eps_alpha) / 3 * (1 - eps_beta) + eps_beta / eps_alpha)


def single_pair_factors(pair: GearPair) -> tuple[float, float, float, float]:
    """(M_1, M_2, Z_B, Z_D): the pitch-to-inner-single-contact-point ratios of ISO 6336-2 §6."""
    ea, eb = pair.eps_alpha, pair.eps_beta
    f1 = math.sqrt(pair.ra1**2 / pair.rb1**2 - 1)
    f2 = math.sqrt(pair.ra2**2 / pair.rb2**2 - 1)
    t = math.tan(pair.alpha_wt)
    M1 = t / math.sqrt((f1 - 2 * math.pi / pair.z1) * (f2 - (ea - 1) * 2 * math.pi / pair.z2))
    M2 = t / math.sqrt((f2 - 2 * math.pi / pair.z2) * (f1 - (ea - 1) * 2 * math.pi / pair.z1))

    def z(M: float) -> float:
        if eb >= 1 or M <= 1:
            return 1.0
        return M - eb * (M - 1)

    return M1, M2, z(M1), z(M2)


def contact_stress(pair: GearPair, pinion_torque: float, E: float, nu: float,
                   factors: LoadFactors = LoadFactors()) -> ContactStress:
    """σ_H0, σ_H of ``pair`` under pinion torque ``pinion_torque`` [N m] (same material on both members)."""
    if not (pinion_torque > 0 and math.isfinite(pinion_torque)):
        raise ValueError(f"pinion_torque must be positive and finite, got {pinion_torque!r}")
    d1 = 2 * pair.r1
    F_t = 2 * pinion_torque / d1
    u = pair.u
    Z_H, Z_E = zone_factor(pair), elasticity_factor(E, nu)
    Z_eps = contact_ratio_factor(pair.eps_alpha, pair.eps_beta)
    Z_beta = 1 / math.sqrt(math.cos(pair.beta))
    M1, M2, Z_B, Z_D = single_pair_factors(pair)
    s0 = Z_H * Z_E * Z_eps * Z_beta * math.sqrt(F_t / pair.n_helices / (d1 * pair.b) * (u + 1) / u)
    k = math.sqrt(factors.product)
    return ContactStress(
        F_t=F_t, z_n=(virtual_teeth(pair.z1, pair.beta, pair.beta_b), virtual_teeth(pair.z2, pair.beta, pair.beta_b)),
        Z_H=Z_H, Z_E=Z_E, Z_eps=Z_eps, Z_beta=Z_beta, Z_B=Z_B, Z_D=Z_D, M_1=M1, M_2=M2,
        sigma_H0=s0, sigma_H=(Z_B * s0 * k, Z_D * s0 * k), factors=factors,
    )
