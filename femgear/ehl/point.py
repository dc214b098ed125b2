"""Point (circular / elliptical) contact EHL: nested iteration over levels.

Solve on the coarsest level with dense Newton from a Hertzian start (with continuation
in alpha_bar if the direct start fails), then interpolate to each finer level and solve
there with Newton-Krylov preconditioned by the multilevel cycle (:mod:`newton`).
Inputs are Moes groups (Venner & Lubrecht 2000 scaling, see :mod:`params`); the
ellipticity ``ratio`` is lambda = R_x/R_y (geometry X^2/2 + lambda Y^2/2, as in
Nijenbanning, Venner & Moes 1994).
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.contact.film import nvm_central
from femgear.errors import ConvergenceError
from femgear.ehl import params as pr
from femgear.ehl.grid import Domain, Grid, prolongation
from femgear.ehl.level import Level
from femgear.ehl.newton import History, newton_dense, newton_krylov
from femgear.ehl.results import EHLResult, centre_values
from femgear.ehl.rheology import Rheology

CONTINUATION = (0.0, 0.25, 0.5, 0.75, 1.0)


def default_domain(ratio: float = 1.0) -> Domain:
    """X in [-4.5, 1.5], Y in [-3, 3] (Venner & Lubrecht 2000), Y widened by
    lambda^(-2/3) for wide elliptical contacts (lambda = R_x/R_y < 1)."""
    sy = max(1.0, ratio ** (-2.0 / 3.0))
    return Domain(-4.5, 1.5, -3.0 * sy, 3.0 * sy)


def _hertz_start(level: Level, ratio: float) -> np.ndarray:
    """Dry Hertz pressure on an ellipse of aspect ~ lambda^(-2/3), scaled to the load."""
    ay = ratio ** (-2.0 / 3.0) if ratio > 0 else 1.0
    ax = ay ** -0.5
    P = np.sqrt(np.maximum(1.0 - (level.X / ax) ** 2 - (level.Y / ay) ** 2, 0.0))
    PI = P[level.interior]
    return PI * level.load / (level.m @ PI)


def solve_point(M: float, L: float, *, level: int = 3, coarse_level: int = 1,
                ratio: float = 1.0, domain: Domain | None = None, viscosity: str = "barus",
                compressible: bool = False, ph: float | None = None, z: float = 0.68,
                rigid: bool = False, ad_factor: float = 1.0, sd_factor: float = 1.0,
                tol: float = 1e-5,
                max_iter: int = 40) -> EHLResult:
    """Isothermal point-contact EHL in Moes groups (M, L); returns :class:`EHLResult`.

    ``level`` is the finest grid (``16 * 2**level`` intervals along X), ``coarse_level``
    the level solved directly (dense Newton). ``viscosity`` 'barus' (default, with
    incompressible oil: the setting of the published film formulas) or 'roelands'
    (needs ``ph`` [Pa] and ``z``); ``compressible`` switches Dowson-Higginson density
    on (needs ``ph``). Raises ConvergenceError (with the Newton history) on failure.
    """
    if M <= 0 or L < 0 or ratio <= 0:
        raise ValueError("need M > 0, L >= 0, ratio > 0")
    if level < coarse_level:
        raise ValueError("level must be >= coarse_level")
    t0 = time.perf_counter()
    case = f"ehl point M={M:g} L={L:g} ratio={ratio:g} level={level}"
    fac = pr.point_h_moes_factor(M)
    dom = domain or default_domain(ratio)

    def make(M_: float, frac: float, lev: int) -> Level:
        rheo = Rheology(pr.point_alpha_bar(M_, L) * frac, viscosity=viscosity, ph=ph, z=z,
                        compressible=compressible)
        return Level(rheo, pr.point_lam_bar(M_), pr.POINT_LOAD, grid=Grid.build(dom, lev),
                     ratio=ratio, rigid=rigid, ad_factor=ad_factor, sd_factor=sd_factor)

    levels = [make(M, 1.0, k) for k in range(coarse_level, level + 1)]
    coarse = levels[0]
    hist = History()

    def hertz(lv: Level, M_: float):
        PI = _hertz_start(lv, ratio)
        H0 = float(nvm_central(M_, L, ratio)) / pr.point_h_moes_factor(M_) - float(
            lv.deflection(lv.full(PI))[np.argmin(lv.X**2 + lv.Y**2)])
        return PI, H0

    def solve_on(lvs: list[Level], PI, H0):
        if len(lvs) == 1:
            PI, H0, h = newton_dense(lvs[0], PI, H0, max_iter=max_iter, tol=tol, case=case)
        else:
            PI, H0, h = newton_krylov(lvs, PI, H0, max_iter=max_iter, tol=tol, case=case)
        hist.extend(h)
        return PI, H0

    def attempt(lvs, PI, H0):
        try:
            return solve_on(lvs, PI, H0)
        except ConvergenceError as exc:
            hist.extend(History(**exc.history))
            return None

    def start_solve(M_: float, depth: int = 0):
        """(PI, H0, n) for load M_ on the n-th level: (1) dense Newton on the coarse level
        from Hertz, (2) with continuation in alpha_bar, (3) Newton-Krylov on the next
        level from Hertz (a coarse grid cannot carry a very thin film), (4) continuation
        in the load from M_/sqrt(2) (solutions in Hertzian units are close)."""
        lvs = levels if M_ == M else [make(M_, 1.0, k) for k in range(coarse_level, level + 1)]
        got = attempt(lvs[:1], *hertz(lvs[0], M_))
        if got:
            return (*got, 1)
        PI, H0 = hertz(lvs[0], M_)
        for frac in CONTINUATION:
            stage = lvs[0] if frac == 1.0 else make(M_, frac, coarse_level)
            got = attempt([stage], PI, H0)
            if not got:
                break
            PI, H0 = got
        else:
            return PI, H0, 1
        if len(lvs) > 1:
            got = attempt(lvs[:2], *hertz(lvs[1], M_))
            if got:
                return (*got, 2)
        if M_ > 20.0 and depth < 8:
            PI, H0, n = start_solve(M_ / math.sqrt(2.0), depth + 1)
            got = attempt(lvs[:n], PI, H0)
            if got:
                return (*got, n)
        raise ConvergenceError(case, f"no start at M={M_:g} (direct, alpha and load "
                               "continuation, next-level Newton-Krylov)", hist.as_dict())

    PI, H0, start = start_solve(M)
    per_level = [_level_summary(levels[start - 1], PI, H0, fac, len(hist.residual), t0)]
    for k in range(start, len(levels)):
        fine, prev = levels[k], levels[k - 1]
        PI = (prolongation(prev.grid, fine.grid) @ prev.full(PI))[fine.interior]
        PI, H0, h = newton_krylov(levels[: k + 1], PI, H0, max_iter=max_iter, tol=tol, case=case)
        hist.extend(h)
        per_level.append(_level_summary(fine, PI, H0, fac, len(h.residual), t0))
    fine = levels[-1]
    return _result("point", M, L, fine, PI, H0, fac, hist, per_level, time.perf_counter() - t0)


def _level_summary(level: Level, PI, H0, fac, its, t0) -> dict:
    P, H = level.film(PI, H0)
    i0 = int(np.argmin(level.X**2 + level.Y**2))
    return {"nodes": level.n, "h": level.h, "Hc": float(H[i0] * fac),
            "Hmin": float(H.min() * fac), "Pmax": float(P.max()), "iterations": its,
            "seconds": time.perf_counter() - t0}


def _result(kind, M, L, level: Level, PI, H0, fac, hist: History, per_level, seconds):
    P, H = level.film(PI, H0)
    if not (np.all(np.isfinite(P)) and np.all(np.isfinite(H))):
        raise ConvergenceError(f"ehl {kind}", "non-finite solution", hist.as_dict())
    # the active set holds P = 0 up to round-off of the last Newton update
    P = np.where(np.abs(P) <= 1e-12 * max(P.max(), 1.0), np.maximum(P, 0.0), P)
    if level.dim == 2:
        g = level.grid
        x, y = g.x, g.y
        P2, H2 = P.reshape(g.ny, g.nx), H.reshape(g.ny, g.nx)
    else:
        x, y, P2, H2 = level.X, np.zeros(0), P, H
    Hc, Hmin, Pmax, at, outlet = centre_values(x, y, P2, H2)
    load_error = abs(level.m @ PI - level.load) / level.load
    return EHLResult(kind=kind, M=float(M), L=float(L), Hc=Hc * fac, Hmin=Hmin * fac,
                     Pmax=Pmax, Pmax_at=at, outlet_x=outlet, Hc_hertz=Hc, Hmin_hertz=Hmin,
                     H0=float(H0), load_error=float(load_error),
                     iterations=len(hist.residual), nodes=level.n, seconds=seconds,
                     x=x, y=y, P=P2, H=H2, history=hist.as_dict(), levels=tuple(per_level))
