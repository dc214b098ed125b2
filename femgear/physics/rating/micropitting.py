"""Micropitting: ISO/TS 6336-22 method B, local specific film thickness and safety S_λ.

At each path position Y (the grid of :func:`femgear.physics.rating.scuffing.flash_path`):

    h_Y     = 1.6 ρ_n,Y G_M^0.6 U_Y^0.7 W_Y^-0.13 S_GF,Y^0.22     (Dowson–Higginson 1961 form, TS eq. 12)
    G_M     = α E_r,   U_Y = η_θM v_Σ,Y / (2 E_r ρ_n,Y),   W_Y = w_n,Y / (E_r ρ_n,Y) = 2π p_H,Y²/E_r²
    S_GF,Y  = α_θB,Y η_θB,Y / (α_38 η_38)                           local sliding (thermal) parameter
    θ_B,Y   = θ_M + θ_fl,Y  (flash temperature and bulk temperature of ISO/TS 6336-20, as in the TS)
    λ_GF,Y  = h_Y / R_a,   R_a = (R_a1 + R_a2)/2;   λ_GF,min = min_Y λ_GF,Y
    λ_GFP   = 1.4 W_W λ_GFT,   S_λ = λ_GF,min / λ_GFP
    λ_GFT   = λ_GF,min of the FZG C test gear at the oil's micropitting failure load stage of the
              GF-C/8.3/90 test (FVA 54/I-IV: 8.3 m/s, 90 °C oil, dip lubrication, R_a 0.5 µm), computed by
              this same method on femgear's FZG C pair (the TS's own definition of λ_GFT).

Oil: the viscosity and pressure–viscosity laws are the caller's ``viscosity(T)`` and
``pressure_viscosity`` (a number: a constant α; a callable: α(T), femgear's oil law,
:meth:`femgear.physics.lubrication.oil.OilLaw.pressure_viscosity`), so G_M takes α at θ_M and S_GF,Y
the product α η at θ_B,Y against 38 °C.  W_W = 1 (case-carburised).  SI inside.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating.scuffing import ScuffingInputs, flash_path, fzg_torque

#: the FZG C test gear of the GF-C/8.3/90 test (gear_methods.md §10)
FZG_C = dict(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014, x1=0.1817, x2=0.1715,
             kind="spur")
T38 = 311.15


@document_fields
@dataclass(frozen=True)
class MicropittingRating:
    """Local film and specific film thickness along the path, and S_λ (SI)."""

    u: np.ndarray
    """path positions, measured from T1 (the pinion's transverse roll length) [m]"""
    film: np.ndarray
    """local film thickness h_Y along the path [m]"""
    lambda_GF: np.ndarray
    """local specific film thickness λ_GF,Y along the path [-]"""
    lambda_GFmin: float
    """smallest local specific film thickness λ_GF,min [-]"""
    u_min: float
    """path position of λ_GF,min, measured from T1 [m]"""
    lambda_GFT: float
    """λ_GF of the FZG C test gear at the oil's failure load stage [-]"""
    lambda_GFP: float
    """permissible specific film thickness λ_GFP [-]"""
    S_lambda: float
    """micropitting safety factor S_λ = λ_GF,min / λ_GFP (ISO/TS 6336-22) [-]"""
    theta_M: float
    """bulk temperature [K]"""
    stage: float
    """the oil's GF-C/8.3/90 failure load stage [-]"""


def _alpha_of(pressure_viscosity: float | Callable[[float], float]) -> Callable[[float], float]:
    if callable(pressure_viscosity):
        return lambda T: float(pressure_viscosity(T))
    return lambda T: float(pressure_viscosity)


def local_film(pair: GearPair, pinion_torque: float, pinion_rpm: float, inputs: ScuffingInputs,
               viscosity: Callable[[float], float], pressure_viscosity: float | Callable[[float], float],
               n: int = 81):
    """(u, h_Y, λ_GF,Y, θ_M) along the path of ``pair`` (``pressure_viscosity``: α [1/Pa] or α(T))."""
    alpha = _alpha_of(pressure_viscosity)
    path = flash_path(pair, pinion_torque, pinion_rpm, inputs, n)
    theta_M = inputs.oil_temperature + 0.47 * inputs.X_S * inputs.X_mp * path.mean_flash
    u = path.u
    cb = math.cos(pair.beta_b)
    r1, r2 = u / cb, (pair.line_of_action - u) / cb
    rho = r1 * r2 / (r1 + r2)
    E_r = inputs.youngs_modulus / (1 - inputs.poisson_ratio**2)
    w1 = pinion_rpm * 2 * math.pi / 60
    v_sum = w1 * u + w1 / pair.u * (pair.line_of_action - u)
    eta_M = viscosity(theta_M)
    G = alpha(theta_M) * E_r
    U = eta_M * v_sum / (2 * E_r * rho)
    W = path.line_load / (E_r * rho)
    S = np.array([alpha(theta_M + t) * viscosity(theta_M + t) for t in path.flash]) / (alpha(T38) * viscosity(T38))
    h = 1.6 * rho * G**0.6 * U**0.7 * W**-0.13 * S**0.22
    Ra = 0.5 * (inputs.Ra[0] + inputs.Ra[1])
    return u, h, h / Ra, theta_M


def micropitting_rating(pair: GearPair, pinion_torque: float, pinion_rpm: float, inputs: ScuffingInputs,
                        viscosity: Callable[[float], float], pressure_viscosity: float | Callable[[float], float],
                        stage: float,
                        W_W: float = 1.0, n: int = 81) -> MicropittingRating:
    """ISO/TS 6336-22 method B for an oil with GF-C/8.3/90 failure load stage ``stage``."""
    u, h, lam, theta_M = local_film(pair, pinion_torque, pinion_rpm, inputs, viscosity, pressure_viscosity, n)
    lam_T = reference_film_thickness(stage, inputs, viscosity, pressure_viscosity)
    i = int(np.argmin(lam))
    lam_P = 1.4 * W_W * lam_T
    return MicropittingRating(u=u, film=h, lambda_GF=lam, lambda_GFmin=float(lam[i]), u_min=float(u[i]),
                              lambda_GFT=lam_T, lambda_GFP=lam_P, S_lambda=float(lam[i]) / lam_P, theta_M=theta_M,
                              stage=stage)


def reference_film_thickness(stage: float, inputs: ScuffingInputs, viscosity: Callable[[float], float],
                        pressure_viscosity: float | Callable[[float], float]) -> float:
    """λ_GFT: λ_GF,min of the FZG C gear in the GF-C/8.3/90 test at load stage ``stage``."""
    pair = GearPair(**FZG_C)
    rpm = 8.3 / (math.pi * 2 * pair.rw1) * 60
    test = replace(inputs, oil_temperature=363.15, oil_viscosity=viscosity(363.15), Ra=(0.5e-6, 0.5e-6), K=1.0,
                   X_S=1.0, X_mp=1.0)
    return float(np.min(local_film(pair, fzg_torque(stage), rpm, test, viscosity, pressure_viscosity)[2]))
