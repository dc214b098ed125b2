"""Oil viscosity from the two data sheet points REXS carries (ν at 40 °C and 100 °C).

Ubbelohde–Walther, as standardised in ASTM D341 (viscosity–temperature charts for liquid petroleum
products): log10 log10(ν + 0.7) = A − B log10 T, ν in mm²/s, T in K, through the two points.  Its
temperature slope gives femgear's temperature–viscosity coefficient β_T = −d ln η / dT at the
reference temperature, with η = ν ρ and ρ(T) = ρ0 (1 − ε (T − T0)) (femgear's density law,
:mod:`femgear.physics.lubrication.oil`).  Units: SI (ν in m²/s) at the interface.
"""

from __future__ import annotations

import math

T40, T100 = 313.15, 373.15
_SHIFT = 0.7  # mm²/s


def _w(nu_mm2s: float) -> float:
    return math.log10(math.log10(nu_mm2s + _SHIFT))


def walther_constants(nu40: float, nu100: float) -> tuple[float, float]:
    """(A, B) of log10 log10(ν[mm²/s] + 0.7) = A − B log10 T[K] through ν40, ν100 [m²/s]."""
    if not nu40 > nu100 > 0:
        raise ValueError(f"ν40 must exceed ν100 > 0 (got ν40 = {nu40 * 1e6:g}, ν100 = {nu100 * 1e6:g} mm²/s)")
    w40, w100 = _w(nu40 * 1e6), _w(nu100 * 1e6)
    b = (w40 - w100) / (math.log10(T100) - math.log10(T40))
    return w40 + b * math.log10(T40), b


def kinematic_viscosity(nu40: float, nu100: float, temperature: float) -> float:
    """ν(T) [m²/s] from ν40 and ν100 [m²/s] (ASTM D341)."""
    a, b = walther_constants(nu40, nu100)
    return (10 ** (10 ** (a - b * math.log10(temperature))) - _SHIFT) * 1e-6


def temperature_coefficient(nu40: float, nu100: float, temperature: float, expansion: float) -> float:
    """β_T = −d ln η/dT [1/K] at ``temperature``, η = ν ρ with ρ ∝ (1 − ε (T − T0)) and T0 = ``temperature``.

    d ln ν/dT follows from d/dT of log10 log10(ν + 0.7) = A − B log10 T:
    dν/dT = −(ν + 0.7) ln(ν + 0.7) B / T (ν in mm²/s).
    """
    _, b = walther_constants(nu40, nu100)
    nu = kinematic_viscosity(nu40, nu100, temperature) * 1e6
    z = nu + _SHIFT
    dnu_dt = -z * math.log(z) * b / temperature
    return -dnu_dt / nu + expansion


T38 = 311.15   #: the temperature of REXS's lubricant pressure_viscosity_coefficient_at_38_degrees_celsius [K]


def pressure_viscosity_at(law, temperature: float) -> float:
    """α(T) = ∂ln η/∂p at p = 0 [1/Pa] of femgear's oil law ``law`` (:class:`femgear.physics.lubrication.oil.OilLaw`)
    at ``temperature`` [K]: Roelands' α0 ((T − 138)/(T0 − 138))^(−S0), the slope of its pressure term (Barus: α0)."""
    if law.model == "barus":
        return law.alpha
    return law.alpha * ((temperature - 138.0) / (law.T0 - 138.0)) ** (-law.s0)


def pressure_viscosity_from(alpha_t: float, temperature: float, eta0: float, beta_t: float, t0: float) -> float:
    """α0 at the reference ``t0`` [1/Pa] of the Roelands law (η0, β_T at t0) whose α at ``temperature`` is
    ``alpha_t`` (the inverse of :func:`pressure_viscosity_at`; S0 does not depend on α)."""
    s0 = beta_t * (t0 - 138.0) / (math.log(eta0) + 9.67)
    return alpha_t * ((temperature - 138.0) / (t0 - 138.0)) ** s0
