"""Dimensional entry: SI inputs -> Moes groups -> EHL solve -> metres and pascals.

Point contact (Venner & Lubrecht 2000; Moes 1992), with u_m = (u1 + u2)/2 and
R_x the reduced radius along the entrainment direction:
    U = eta0 u_m/(E' R_x), G = alpha E', W = F/(E' R_x^2), M = W (2U)^(-3/4), L = G (2U)^(1/4),
    a^3 = 3 F R_x/(2 E'), p_h = 3 F/(2 pi a^2),  h = H a^2/R_x,  x = X a,  p = P p_h.
For an elliptical contact (R_y finite) a and p_h are the reference values built on R_x
(the actual Hertz ellipse follows from the solution); lambda = R_x/R_y.
Line contact (load per unit length w'):
    W' = w'/(E' R), M = W' (2U)^(-1/2), b = R sqrt(8 W'/pi), p_h = E' sqrt(W'/(2 pi)),
    h = H b^2/R, x = X b.
Roelands: z = alpha p0/(ln eta0 + 9.67) unless given (seed paper eq. 3.1.3, p0 = 1.96e8 Pa),
so that Roelands and Barus share the low-pressure slope alpha; eta0 must then be in Pa s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from femgear.physics.contact.film import moes_line, moes_point
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.core.rheology import ROELANDS_P0
from femgear.physics.ehl.line import solve_line
from femgear.physics.ehl.point import solve_point


@dataclass(frozen=True)
class EHLOil:
    """Isothermal lubricant: eta0 [Pa s], alpha [1/Pa]; ``viscosity`` 'barus' or
    'roelands' (pressure index ``z``, default from alpha); Dowson-Higginson density if
    ``compressible``."""

    eta0: float
    alpha: float
    viscosity: str = "barus"
    z: float | None = None
    compressible: bool = False

    def roelands_z(self) -> float:
        if self.z is not None:
            return self.z
        c = math.log(self.eta0) + 9.67
        if c <= 0:
            raise ValueError("Roelands needs ln(eta0 [Pa s]) + 9.67 > 0")
        return self.alpha * ROELANDS_P0 / c


@dataclass(frozen=True)
class DimensionalEHL:
    """SI result: films [m], pressures [Pa], coordinates [m] and the dimensionless record."""

    hc: float
    hmin: float
    pmax: float
    pmax_at: tuple[float, float]
    outlet_x: float
    a: float  # reference half-width [m] (a for point, b for line)
    ph: float  # reference Hertz pressure [Pa]
    M: float
    L: float
    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    p: np.ndarray = field(repr=False)
    h: np.ndarray = field(repr=False)
    result: EHLResult = field(repr=False)


def _check(**v: float) -> None:
    for k, val in v.items():
        if not (val > 0 and math.isfinite(val)):
            raise ValueError(f"{k} must be positive and finite, got {val!r}")


def _opts(oil: EHLOil, ph: float) -> dict:
    return {"viscosity": oil.viscosity, "compressible": oil.compressible, "ph": ph,
            "z": oil.roelands_z() if oil.viscosity == "roelands" else 0.68}


def solve_point_dimensional(load: float, Rx: float, Ry: float | None, um: float,
                            E_red: float, oil: EHLOil, *, level: int = 3,
                            **kwargs) -> DimensionalEHL:
    """Point contact: load F [N], radii R_x, R_y [m] (R_y None = R_x), mean entrainment
    speed u_m [m/s], reduced modulus E' [Pa] (2/E' = sum (1-nu^2)/E), ``oil``."""
    Ry = Rx if Ry is None else Ry
    _check(load=load, Rx=Rx, Ry=Ry, um=um, E_red=E_red, eta0=oil.eta0)
    U = oil.eta0 * um / (E_red * Rx)
    W = load / (E_red * Rx**2)
    M, L = moes_point(W, U, oil.alpha * E_red)
    a = (3.0 * load * Rx / (2.0 * E_red)) ** (1.0 / 3.0)
    ph = 3.0 * load / (2.0 * math.pi * a * a)
    res = solve_point(M, L, level=level, ratio=Rx / Ry, **_opts(oil, ph), **kwargs)
    return _dimensional(res, a, a * a / Rx, ph)


def solve_line_dimensional(load_per_length: float, R: float, um: float, E_red: float,
                           oil: EHLOil, *, level: int | None = None, **kwargs) -> DimensionalEHL:
    """Line contact: load per unit length w' [N/m], reduced radius R [m], u_m [m/s], E' [Pa].

    :func:`femgear.physics.ehl.line.solve_line` does the solve: by default converged to its
    tolerance on the grid it picks (``tol=``, ``method=`` and the rest in ``kwargs``);
    ``level`` fixes the grid instead."""
    _check(load_per_length=load_per_length, R=R, um=um, E_red=E_red, eta0=oil.eta0)
    U = oil.eta0 * um / (E_red * R)
    Wl = load_per_length / (E_red * R)
    M, L = moes_line(Wl, U, oil.alpha * E_red)
    b = R * math.sqrt(8.0 * Wl / math.pi)
    ph = E_red * math.sqrt(Wl / (2.0 * math.pi))
    res = solve_line(M, L, level=level, **_opts(oil, ph), **kwargs)
    return _dimensional(res, b, b * b / R, ph)


def _dimensional(res: EHLResult, a: float, hscale: float, ph: float) -> DimensionalEHL:
    return DimensionalEHL(
        hc=res.Hc_hertz * hscale, hmin=res.Hmin_hertz * hscale, pmax=res.Pmax * ph,
        pmax_at=(res.Pmax_at[0] * a, res.Pmax_at[1] * a), outlet_x=res.outlet_x * a,
        a=a, ph=ph, M=res.M, L=res.L, x=res.x * a, y=res.y * a, p=res.P * ph,
        h=res.H * hscale, result=res)
