"""Hertz contact: line contact, circular and elliptical point contact.

Conventions (Hamrock): E' = 2 / [(1−ν1²)/E1 + (1−ν2²)/E2] (twice Johnson's E*);
x is the rolling direction with reduced radius R_x, y the transverse one with R_y.

Sources: K. L. Johnson, *Contact Mechanics* (1985), §4.2–4.3 (eqs. 4.39) for the
elliptical contact with complete elliptic integrals; B. J. Hamrock & D. E. Brewe,
J. Lubr. Technol. 105 (1983) 171 for the curve fits kept as a cross-check.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.optimize import brentq
from scipy.special import ellipe, ellipk


def reduced_modulus(E1: float, nu1: float, E2: float | None = None, nu2: float | None = None) -> float:
    """E' = 2 / [(1−ν1²)/E1 + (1−ν2²)/E2] [Pa]; body 2 defaults to body 1."""
    E2 = E1 if E2 is None else E2
    nu2 = nu1 if nu2 is None else nu2
    return 2.0 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)


def _positive(**values: float) -> None:
    for name, value in values.items():
        if not (value > 0 and math.isfinite(value)):
            raise ValueError(f"{name} must be positive and finite (got {value!r})")


@dataclass(frozen=True)
class HertzLine:
    """Line contact of load ``w`` per unit length [N/m]."""

    half_width: float     #: b [m]
    max_pressure: float   #: p_h [Pa]
    load: float           #: w' [N/m]
    radius: float         #: R [m]

    @property
    def mean_pressure(self) -> float:
        return math.pi * self.max_pressure / 4


def hertz_line(w: float, R: float, E_red: float) -> HertzLine:
    """b = √(8 w' R/(π E')), p_h = 2 w'/(π b)  (Johnson eq. 4.45)."""
    _positive(w=w, R=R, E_red=E_red)
    b = math.sqrt(8 * w * R / (math.pi * E_red))
    return HertzLine(half_width=b, max_pressure=2 * w / (math.pi * b), load=w, radius=R)


@dataclass(frozen=True)
class HertzPoint:
    """Elliptical (or circular) point contact.

    ``a`` is the semi-axis along x (radius R_x), ``b`` along y (R_y).
    """

    a: float              #: semi-axis along x [m]
    b: float              #: semi-axis along y [m]
    max_pressure: float   #: p_h = 3F/(2π a b) [Pa]
    approach: float       #: mutual approach δ of distant points [m]
    load: float           #: F [N]

    @property
    def ellipticity(self) -> float:
        """k = b/a (> 1 when R_y > R_x)."""
        return self.b / self.a

    @property
    def mean_pressure(self) -> float:
        return 2 * self.max_pressure / 3


def _k_minus_e_over_m(m: float) -> float:
    """(K(m) − E(m))/m, with its series π/4 (1 + 3m/8 + 15m²/64) near m = 0."""
    if m < 1e-6:
        return math.pi / 4 * (1 + 3 * m / 8 + 15 * m * m / 64)
    return (ellipk(m) - ellipe(m)) / m


def ellipticity_exact(radius_ratio: float) -> float:
    """Exact k = a_major/a_minor ≥ 1 for curvature ratio R_major/R_minor ≥ 1.

    Solves R_major/R_minor = (k² E(m) − K(m)) / (K(m) − E(m)), m = 1 − 1/k² (Johnson 4.39a).
    """
    _positive(radius_ratio=radius_ratio)
    if radius_ratio < 1:
        raise ValueError("radius_ratio must be ≥ 1 (pass the larger radius over the smaller)")
    if radius_ratio - 1 < 1e-12:
        return 1.0

    def f(k: float) -> float:
        m = 1 - 1 / k**2
        K, E = ellipk(m), ellipe(m)
        return (k * k * E - K) / (K - E) - radius_ratio

    hi = 2.0
    while f(hi) < 0:
        hi *= 2
    return brentq(f, 1 + 1e-12, hi, xtol=1e-14, rtol=1e-14)


def hertz_point(F: float, Rx: float, Ry: float | None, E_red: float) -> HertzPoint:
    """Elliptical Hertz contact from load F [N], radii R_x, R_y [m] (None: circular).

    With the major semi-axis a_M along the direction of the larger radius R_M, the
    minor a_m = a_M/k and m = 1 − 1/k² (Johnson 4.39):

        a_M³ = 6 F R_M (K − E)/(π E' m),   p_h = 3F/(2π a_M a_m),   δ = 3 F K/(π a_M E').

    For k = 1 these reduce to a³ = 3FR/(2E'), p_h = 3F/(2πa²), δ = a²/R.
    """
    Ry = Rx if Ry is None else Ry
    _positive(F=F, Rx=Rx, Ry=Ry, E_red=E_red)
    R_major, R_minor = max(Rx, Ry), min(Rx, Ry)
    k = ellipticity_exact(R_major / R_minor)
    m = 1 - 1 / k**2
    a_major = (6 * F * R_major * _k_minus_e_over_m(m) / (math.pi * E_red)) ** (1 / 3)
    a_minor = a_major / k
    p_h = 3 * F / (2 * math.pi * a_major * a_minor)
    delta = 3 * F * ellipk(m) / (math.pi * a_major * E_red)
    a, b = (a_minor, a_major) if Ry >= Rx else (a_major, a_minor)
    return HertzPoint(a=a, b=b, max_pressure=p_h, approach=delta, load=F)


def ellipticity_hamrock_brewe(Rx: float, Ry: float) -> float:
    """Hamrock–Brewe (1983) fit k ≈ 1.0339 (R_y/R_x)^0.636 (a few % accurate)."""
    _positive(Rx=Rx, Ry=Ry)
    return 1.0339 * (Ry / Rx) ** 0.636
