"""Oil viscosity from two data sheet points (ν at 40 °C and 100 °C, or any two temperatures).

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


def walther_through(t1: float, nu1: float, t2: float, nu2: float) -> tuple[float, float]:
    """(A, B) of log10 log10(ν[mm²/s] + 0.7) = A − B log10 T[K] through (t1, ν1), (t2, ν2) [K, m²/s], t1 < t2."""
    if not (t2 > t1 > 0 and nu1 > nu2 > 0):
        raise ValueError(f"need t1 < t2 and ν1 > ν2 > 0 (got {t1:g} K: {nu1 * 1e6:g}, {t2:g} K: {nu2 * 1e6:g} mm²/s)")
    w1, w2 = _w(nu1 * 1e6), _w(nu2 * 1e6)
    b = (w1 - w2) / (math.log10(t2) - math.log10(t1))
    return w1 + b * math.log10(t1), b


def walther_constants(nu40: float, nu100: float) -> tuple[float, float]:
    """(A, B) of log10 log10(ν[mm²/s] + 0.7) = A − B log10 T[K] through ν40, ν100 [m²/s]."""
    if not nu40 > nu100 > 0:
        raise ValueError(f"ν40 must exceed ν100 > 0 (got ν40 = {nu40 * 1e6:g}, ν100 = {nu100 * 1e6:g} mm²/s)")
    return walther_through(T40, nu40, T100, nu100)


def walther_viscosity(a: float, b: float, temperature: float) -> float:
    """ν(T) [m²/s] of the Walther line (A, B)."""
    return (10 ** (10 ** (a - b * math.log10(temperature))) - _SHIFT) * 1e-6


def walther_slope(a: float, b: float, temperature: float) -> float:
    """−d ln ν/dT [1/K] of the Walther line (A, B): dν/dT = −(ν + 0.7) ln(ν + 0.7) B / T (ν in mm²/s)."""
    nu = walther_viscosity(a, b, temperature) * 1e6
    z = nu + _SHIFT
    return z * math.log(z) * b / temperature / nu


def kinematic_viscosity(nu40: float, nu100: float, temperature: float) -> float:
    """ν(T) [m²/s] from ν40 and ν100 [m²/s] (ASTM D341)."""
    return walther_viscosity(*walther_constants(nu40, nu100), temperature)


def temperature_coefficient(nu40: float, nu100: float, temperature: float, expansion: float) -> float:
    """β_T = −d ln η/dT [1/K] at ``temperature``, η = ν ρ with ρ ∝ (1 − ε (T − T0)) and T0 = ``temperature``."""
    return walther_slope(*walther_constants(nu40, nu100), temperature) + expansion
