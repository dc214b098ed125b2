"""ISO 6336-2:2019 method B: permissible contact stress σ_HP and safety factor S_H.

    σ_HG = σ_Hlim Z_NT Z_L Z_v Z_R Z_W Z_X,   σ_HP = σ_HG / S_Hmin,   S_H = σ_HG / σ_H   (eqs. 4–6)

Factors (σ_Hlim in N/mm² inside the empirical constants, clamped to 850…1200):
    Z_L = C_ZL + 4 (1 − C_ZL) / (1.2 + 134/ν40)²,  C_ZL = 0.83 + 0.08 (σ_Hlim − 850)/350   (eqs. 33, 34)
    Z_v = C_Zv + 2 (1 − C_Zv) / √(0.8 + 32/v),     C_Zv = C_ZL + 0.02, v at the reference circle [m/s]
    Z_R = (3 / R_z10)^C_ZR,  R_z10 = (R_z1 + R_z2)/2 · ∛(10/ρ_red),  C_ZR = 0.32 − 0.0002 σ_Hlim  (eqs. 37–41)
          ρ_red = ρ1 ρ2/(ρ1 + ρ2), ρ_i = r_bi tan α_wt at the pitch point [mm], R_z in µm
    Z_NT  life factor, curve of St, V, GGG, GTS, Eh, IF without permitted pitting (Table 2):
          N_L ≤ 1e5: 1.6;  ≤ 5e7: (5e7/N_L)^0.0756;  ≤ 1e10: (5e7/N_L)^0.0307;  beyond: 0.85
          N_L = 60 n L_h, one contact per revolution.
A factor whose input is not given is 1 (the reference test conditions).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating.contact_stress import ContactStress


@document_fields
@dataclass(frozen=True)
class MaterialLimits:
    """Inputs of the permissible stress (SI; None: the factor is 1)."""

    sigma_Hlim: float = 1.5e9
    """allowable stress number for contact σ_Hlim [Pa]"""
    S_Hmin: float = 1.0
    """minimum required pitting safety factor S_Hmin [-]"""
    life_hours: float | None = None
    """required life L_h (None: Z_NT = 1) [h]"""
    nu40: float | None = None
    """oil kinematic viscosity at 40 °C (None: Z_L = 1) [mm²/s]"""
    Rz: tuple[float, float] | None = None
    """flank roughness R_z of pinion, gear (None: Z_R = 1) [m]"""
    Z_W: float = 1.0
    """work-hardening factor Z_W [-]"""
    Z_X: float = 1.0
    """size factor Z_X [-]"""


@document_fields
@dataclass(frozen=True)
class PittingRating:
    """Permissible contact stress and safety of pinion and gear."""

    stress: ContactStress
    """the ISO 6336-2 contact stress of both members [-]"""
    limits: MaterialLimits
    """the material and lubrication inputs of the permissible stress [-]"""
    pitch_line_velocity: float
    """circumferential speed v at the reference circle [m/s]"""
    N_L: tuple[float, float] | None
    """load cycles of pinion, gear over the required life (None: no life given) [-]"""
    Z_NT: tuple[float, float]
    """life factor Z_NT of pinion, gear [-]"""
    Z_L: float
    """lubricant factor Z_L [-]"""
    Z_v: float
    """velocity factor Z_v [-]"""
    Z_R: float
    """roughness factor Z_R [-]"""
    sigma_HP: tuple[float, float]
    """permissible contact stress σ_HP of pinion, gear [Pa]"""
    S_H: tuple[float, float]
    """pitting safety factor S_H = σ_HP / σ_H of pinion, gear [-]"""

    @property
    def safe(self) -> bool:
        return min(self.S_H) >= self.limits.S_Hmin


def _clamped_mpa(sigma_Hlim: float) -> float:
    return min(max(sigma_Hlim * 1e-6, 850.0), 1200.0)


def life_factor(N_L: float) -> float:
    """Z_NT for N_L load cycles (ISO 6336-2 Table 2, no pitting permitted)."""
    if N_L <= 1e5:
        return 1.6
    if N_L <= 5e7:
        return (5e7 / N_L) ** 0.0756
    if N_L <= 1e10:
        return (5e7 / N_L) ** 0.0307
    return 0.85


def lubricant_factor(sigma_Hlim: float, nu40: float | None) -> float:
    if nu40 is None:
        return 1.0
    c = 0.83 + 0.08 * (_clamped_mpa(sigma_Hlim) - 850) / 350
    return c + 4 * (1 - c) / (1.2 + 134 / nu40) ** 2


def velocity_factor(sigma_Hlim: float, v: float, nu40: float | None) -> float:
    if nu40 is None:
        return 1.0
    c = 0.83 + 0.08 * (_clamped_mpa(sigma_Hlim) - 850) / 350 + 0.02
    return c + 2 * (1 - c) / math.sqrt(0.8 + 32 / v)


def roughness_factor(pair: GearPair, sigma_Hlim: float, Rz: tuple[float, float] | None) -> float:
    if Rz is None:
        return 1.0
    t = math.tan(pair.alpha_wt)
    r1, r2 = pair.rb1 * t * 1e3, pair.rb2 * t * 1e3          # mm
    rz10 = 0.5 * (Rz[0] + Rz[1]) * 1e6 * (10 / (r1 * r2 / (r1 + r2))) ** (1 / 3)
    c = 0.32 - 0.0002 * _clamped_mpa(sigma_Hlim)
    return (3 / rz10) ** c


def pitting_rating(pair: GearPair, stress: ContactStress, pinion_rpm: float,
                   limits: MaterialLimits = MaterialLimits()) -> PittingRating:
    """σ_HP and S_H of both members for ``stress`` at pinion speed ``pinion_rpm``."""
    v = math.pi * 2 * pair.r1 * pinion_rpm / 60
    if limits.life_hours is None:
        N_L, Z_NT = None, (1.0, 1.0)
    else:
        N_L = (60 * pinion_rpm * limits.life_hours, 60 * pinion_rpm * pair.z1 / pair.z2 * limits.life_hours)
        Z_NT = (life_factor(N_L[0]), life_factor(N_L[1]))
    Z_L = lubricant_factor(limits.sigma_Hlim, limits.nu40)
    Z_v = velocity_factor(limits.sigma_Hlim, v, limits.nu40)
    Z_R = roughness_factor(pair, limits.sigma_Hlim, limits.Rz)
    common = limits.sigma_Hlim * Z_L * Z_v * Z_R * limits.Z_W * limits.Z_X
    sigma_HG = (common * Z_NT[0], common * Z_NT[1])
    return PittingRating(
        stress=stress, limits=limits, pitch_line_velocity=v, N_L=N_L, Z_NT=Z_NT, Z_L=Z_L, Z_v=Z_v, Z_R=Z_R,
        sigma_HP=(sigma_HG[0] / limits.S_Hmin, sigma_HG[1] / limits.S_Hmin),
        S_H=(sigma_HG[0] / stress.sigma_H[0], sigma_HG[1] / stress.sigma_H[1]),
    )
