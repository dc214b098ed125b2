"""Point-contact EHL by full multigrid (the ``method='fas'`` of :func:`solve_point`).

Grid levels of :class:`femgear.ehl.grid.Grid` (``16 * 2**k`` intervals along X, the same
nodes as the Newton solver's levels) from the coarsest multigrid grid (17^2; 33^2 when
alpha_bar > ``COARSE_33_ALPHA``) to the finest; the FD discretisation of :mod:`fd` with
the second-order upstream wedge on every level but the coarsest (first-order upwind
there: a coarse-grid approximation only, no term of the error estimate); FAS cycles of
:mod:`fas`.

Start (cold): the coarsest grid (17^2) by dense Newton from the dry Hertz pressure and the
NVM film, with continuation in alpha_bar when the direct start fails. Otherwise (and
always on a 33^2 coarsest grid) the Newton FE solver's start (``fallback_start``: coarse
levels, continuation) is interpolated one grid finer and the FD equations are cycled
from there. Start (warm, ``start=`` a neighbouring
point solution): its pressure interpolated (Hertzian units) onto the finest grid, H0
shifted by the NVM change of the central film, cycles there; then cycles on the grid
below from the injected solution (two levels: the result still carries a Richardson
estimate, at a quarter of the cost of a finest-grid cycle each).

Each level is cycled until the central and minimum films change by less than
``film_tol`` per cycle and the load error is below ``load_tol``; the per-level films feed
:func:`femgear.ehl.accuracy.error_estimate`, and with ``tol`` the FMG stops at the first
level whose estimate meets it.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from femgear.contact.film import nvm_central
from femgear.errors import ConvergenceError
from femgear.ehl import accuracy as acc
from femgear.ehl import params as pr
from femgear.ehl.fas import FAS, FasOptions
from femgear.ehl.fd import FDLevel, inject, prolong_cubic
from femgear.ehl.fdnewton import CoarseNewton
from femgear.ehl.grid import Domain, Grid
from femgear.ehl.results import EHLResult
from femgear.ehl.rheology import Rheology

ALPHA_STEPS = (0.0, 0.25, 0.5, 0.75, 1.0)
# the coarsest grid (17^2) takes the first-order upwind wedge (a coarse-grid approximation
# of the finer grids' second-order operator; its solution is no term of the estimate)
SECOND_ORDER_FROM = 1  # FAS level index (0 = the coarsest)
COARSE_33_ALPHA = 12.0


class FasPoint:
    """One multigrid point-contact solve (levels built on first use)."""

    def __init__(self, M: float, L: float, *, ratio: float, dom: Domain, rheology: dict,
                 rigid: bool, case: str, opts: FasOptions | None = None, coarsest: int | None = None):
        self.M, self.L, self.ratio, self.dom, self.rigid = M, L, ratio, dom, rigid
        # the coarsest grid: 17^2, or 33^2 beyond alpha_bar = COARSE_33_ALPHA (a coarser grid
        # cannot carry the correction of a strongly piezoviscous film)
        alpha = pr.point_alpha_bar(M, L)
        self.coarsest = (1 if alpha > COARSE_33_ALPHA else 0) if coarsest is None else coarsest
        self.rheo = Rheology(pr.point_alpha_bar(M, L), **rheology)
        self.lam, self.fac, self.case = pr.point_lam_bar(M), pr.point_h_moes_factor(M), case
        self.fas = FAS(self.level, opts or FasOptions(), case)

    def level(self, k: int, wedge: str | None = None, alpha_frac: float = 1.0) -> FDLevel:
        wedge = wedge or ("first" if k < SECOND_ORDER_FROM else "second")
        rheo = self.rheo if alpha_frac == 1.0 else replace(self.rheo, alpha_bar=self.rheo.alpha_bar * alpha_frac)
        return FDLevel(Grid.build(self.dom, k + self.coarsest), rheo, self.lam, pr.POINT_LOAD, ratio=self.ratio,
                       rigid=self.rigid, wedge=wedge)

    def films(self, k: int, P: np.ndarray, H0: float, H: np.ndarray | None = None) -> tuple[float, float]:
        """(Hc, Hmin) in Moes units of level k's state (``H``: its film, when known)."""
        lv = self.fas.levels[k]
        H = lv.film(P, H0) if H is None else H
        j0, i0 = int(np.argmin(np.abs(lv.grid.y))), int(np.argmin(np.abs(lv.grid.x)))
        return float(H[j0, i0] * self.fac), float(H.min() * self.fac)

    def nvm_hertz(self, M: float, L: float) -> float:
        return float(nvm_central(M, L, self.ratio)) / pr.point_h_moes_factor(M)

    def cold_start(self) -> tuple[np.ndarray, float, int]:
        """(P, H0, 0) solved on the coarsest grid (module docstring)."""
        lv = self.fas.levels[0]
        ay = self.ratio ** (-2.0 / 3.0)
        P = np.sqrt(np.maximum(1.0 - lv.X**2 * ay - (lv.Y / ay) ** 2, 0.0))
        P *= lv.load / lv.load_of(P)
        j0, i0 = int(np.argmin(np.abs(lv.grid.y))), int(np.argmin(np.abs(lv.grid.x)))
        H0 = self.nvm_hertz(self.M, self.L) - float(lv.film(P, 0.0)[j0, i0])
        f0 = np.zeros((lv.ny - 2, lv.nx - 2))
        errors = []
        for fracs in ((1.0,), ALPHA_STEPS):
            try:
                Pk, Hk = P, H0
                for frac in fracs:
                    first = CoarseNewton(self.level(0, "first", frac))
                    Pk, Hk, _ = first.solve(Pk, Hk, f0, lv.load, self.case)
                Pk, Hk, _ = CoarseNewton(lv).solve(Pk, Hk, f0, lv.load, self.case)
                return Pk, Hk, 0
            except ConvergenceError as exc:
                errors.append(str(exc))
        raise ConvergenceError(self.case, "no coarse-grid start (direct and alpha continuation): "
                               + " | ".join(errors), self.fas.hist.as_dict())

    def warm_start(self, start: EHLResult, k: int) -> tuple[np.ndarray, float]:
        """``start``'s pressure on level k (scaled to the load) and its shifted H0."""
        if start.kind != "point":
            raise ValueError("start must be a point-contact EHLResult")
        lv = self.fas.levels[k]
        interp = RegularGridInterpolator((start.y, start.x), start.P, bounds_error=False, fill_value=0.0)
        P = np.maximum(interp(np.column_stack([lv.Y.ravel(), lv.X.ravel()])).reshape(lv.X.shape), 0.0)
        P[0], P[-1], P[:, 0], P[:, -1] = 0.0, 0.0, 0.0, 0.0
        P *= lv.load / lv.load_of(P)
        H0 = start.H0 + self.nvm_hertz(self.M, self.L) - self.nvm_hertz(start.M, start.L)
        return P, H0

    def _warm(self, start: EHLResult, top: int, on_level):
        """Cycles on the finest grid from ``start``, then on the grid below from the
        injected solution (its films make the two-level error estimate)."""
        fas = self.fas
        fas.select_relax(top)
        P, H0 = self.warm_start(start, top)
        P, H0, n = fas.solve_level(top, P, H0, self.films, final=True)
        Pc, H0c, nc = fas.solve_level(top - 1, inject(P), H0, self.films, final=False)
        on_level(top - 1, Pc, H0c, nc)
        on_level(top, P, H0, n)
        return P, H0, top

    def solve(self, top: int, tol: float | None, t0: float, start: EHLResult | None = None,
              fallback_start=None):
        """(P, H0, FAS level index reached, per-level summaries); ``top`` is a grid level
        (``16 * 2**top`` intervals). ``fallback_start()`` -> (P (ny, nx), H0, grid level),
        a start from another solver, is used when the coarse-grid Newton start fails (high
        M: the coarsest grids cannot carry the thin film)."""
        top -= self.coarsest
        if top < 0:
            raise ConvergenceError(self.case, "grid level below the coarsest multigrid grid")
        per_level: list[dict] = []

        def on_level(k, P, H0, cycles):
            if k < SECOND_ORDER_FROM:  # another discretisation: no term of the estimate
                return False
            hc, hmin = self.films(k, P, H0)
            lv = self.fas.levels[k]
            per_level.append({"nodes": lv.nx * lv.ny, "h": lv.hx, "Hc": hc, "Hmin": hmin,
                              "Pmax": float(P.max()), "iterations": cycles, "method": "fas",
                              "seconds": time.perf_counter() - t0})
            return tol is not None and all(e is not None and e <= tol
                                           for e in acc.error_estimate(per_level).values())

        if start is not None and top >= 2:
            P, H0, k = self._warm(start, top, on_level)
        else:
            try:
                if self.coarsest > 0 and fallback_start is not None:
                    raise ConvergenceError(self.case, "33^2 coarsest grid: Newton start")
                P, H0, k0 = self.cold_start()
                solved = True
            except ConvergenceError:
                if fallback_start is None:
                    raise
                P, H0, k0 = fallback_start()
                k0 -= self.coarsest
                if k0 >= top or k0 < 0:
                    raise
                P, k0, solved = _prolong_start(P), k0 + 1, False  # FD solved one level finer
            P, H0, k = self.fas.fmg(P, H0, k0, top, self.films, on_level, solved=solved)
        return P, H0, k, per_level


def solve_point_fas(M: float, L: float, *, level: int, ratio: float, dom: Domain, rheology: dict,
                    rigid: bool, tol: float | None, case: str, t0: float,
                    start: EHLResult | None = None, extra_flags: tuple[str, ...] = (),
                    opts: FasOptions | None = None, fallback_start=None) -> EHLResult:
    """The multigrid solve behind ``solve_point(method='fas')``; raises ConvergenceError
    (with the per-cycle residual and load-error history) when it fails."""
    from femgear.ehl.assemble import assemble

    fp = FasPoint(M, L, ratio=ratio, dom=dom, rheology=rheology, rigid=rigid, case=case, opts=opts)
    P, H0, k, per_level = fp.solve(level, tol, t0, start, fallback_start)
    lv = fp.fas.levels[k]
    hist = fp.fas.hist.as_dict()
    return assemble("point", M, L, lv.grid.x, lv.grid.y, P, lv.film(P, H0), H0=H0,
                    load_error=abs(lv.load_of(P) - lv.load) / lv.load, fac=fp.fac, history=hist,
                    iterations=len(hist["residual"]), per_level=per_level,
                    seconds=time.perf_counter() - t0,
                    tol=acc.DEFAULT_TOL if tol is None else tol, extra_flags=extra_flags)


def _prolong_start(P: np.ndarray) -> np.ndarray:
    out = np.maximum(prolong_cubic(P), 0.0)
    out[0], out[-1], out[:, 0], out[:, -1] = 0.0, 0.0, 0.0, 0.0
    return out
