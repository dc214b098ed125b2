"""Point-contact EHL by full multigrid (the ``method='fas'`` of :func:`solve_point`).

Grid levels of :class:`femgear.physics.ehl.core.grid.Grid` (``16 * 2**k`` intervals along X, the same
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
:func:`femgear.physics.ehl.core.accuracy.error_estimate`, and with ``tol`` the FMG stops at the first
level whose estimate meets it.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from femgear.errors import ConvergenceError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.grid import Domain, Grid
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fd.fas import FAS, FasOptions
from femgear.physics.ehl.fd.newton import CoarseNewton
from femgear.physics.ehl.fd.operator import FDLevel, inject, prolong_cubic
from femgear.physics.ehl.fd.relax import RelaxOptions

ALPHA_STEPS = (0.0, 0.25, 0.5, 0.75, 1.0)
# the coarsest grid (17^2) takes the first-order upwind wedge (a coarse-grid approximation
# of the finer grids' second-order operator; its solution is no term of the estimate)
SECOND_ORDER_FROM = 1  # FAS level index (0 = the coarsest)
COARSE_33_ALPHA = 12.0
# warm solves of a path stop when the bound on the films' algebraic error is below this
# fraction of the start's error estimate (or ``film_tol``, whichever is larger), and the
# load error below WARM_LOAD_TOL: the central film varies as W^-0.067 (Hamrock & Dowson
# 1977, ASME J. Lubr. Technol. 99:264), so a load error of 1e-4 moves it by < 1e-5
WARM_FRACTION = 0.05
WARM_LOAD_TOL = 1e-4
# the grid below only feeds the two-level estimate: an algebraic error e of its films moves
# the estimate by e/3, so it is cycled to WARM_COARSE x the tolerance of the finest grid
WARM_COARSE = 5.0
# strongly piezoviscous contacts (alpha_bar > HIGH_ALPHA_FROM, beyond every case validated
# with the standard options, FAS_ALPHA_MAX_SLENDER of point.py): the cycle options of
# HIGH_ALPHA. Measured at (20, 20) (alpha_bar 19.8) and (100, 20) (33.8), where the standard
# cycles stall on 65^2: the line sweeps there diverge with omega_gs 0.8 and, with 0.5, are
# held back by the per-sweep cap 4/alpha_bar (residual erratic between 0.3 and 2.6 over
# 30 sweeps on 129^2; with the cap 20/alpha_bar 0.64 -> 0.006 monotonically); 40 sweeps
# after each interpolation (FasOptions.fmg_sweeps); 10 coarse Newton steps per cycle (3 left
# the load error at 1e-2); on 257^2 the coarse-grid correction kept off the outlet spike
# (spike_guard 4, fas._steep) and the spike eliminated by an exact local Newton solve within
# 6 nodes of it after each cycle (eliminate; Cai & Li 2011, femgear.physics.ehl.fd.eliminate), the
# 129^2 level of those cycles keeping the guarded nodes fixed (freeze_guard), the
# correction damped by 0.7 (top_damping), omega 0.3 there, no W-cycles, no stall test (the
# residual falls unevenly). Result on 257^2: (20, 20) in 13 cycles (with the guard alone
# its cycles stayed at a residual of ~0.4), (100, 20) in 6 (with the guard alone 50).
HIGH_ALPHA_FROM = 17.0
_RELAX_HIGH = RelaxOptions(omega_dist=0.5, omega_gs=0.5, max_log_eta=20.0)
HIGH_ALPHA = FasOptions(relax=_RELAX_HIGH, relax_fine=_RELAX_HIGH, coarse_newton=10, fmg_sweeps=40,
                        spike_guard=4, eliminate=6, freeze_guard=True, top_damping=0.7,
                        max_cycles=60, w_switch=False, stall_after=99,
                        relax_top=RelaxOptions(omega_dist=0.3, omega_gs=0.3, max_log_eta=20.0))


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
        if opts is None:
            opts = HIGH_ALPHA if alpha > HIGH_ALPHA_FROM else FasOptions()
        self.fas = FAS(self.level, opts, case)

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

    def _warm(self, start: EHLResult, top: int, on_level, path: _PointPath):
        """The finest grid and the grid below (its films make the two-level error
        estimate) from ``path``'s predictions, cycled to the warm tolerance; without a
        prediction (or when the cycles fail from it): the finest grid from ``start``
        interpolated to the final tolerances, then the grid below from the injected
        solution."""
        fas = self.fas
        fas.select_relax(top)
        lev = top + self.coarsest
        pred = [path.predict(start, self.M, self.L, g, self.nvm_hertz) for g in (lev - 1, lev)]
        if all(p is not None and p[0].shape == fas.levels[k].X.shape
               for p, k in zip(pred, (top - 1, top))):
            tol = max(fas.opts.film_tol, WARM_FRACTION * max(
                (e for e in start.error_estimate.values() if e is not None), default=0.0))
            try:
                got = [fas.solve_level(k, p[0].copy(), p[1], self.films, warm=(f * tol, WARM_LOAD_TOL))
                       for k, p, f in zip((top - 1, top), pred, (WARM_COARSE, 1.0))]
                for k, (P, H0, n) in zip((top - 1, top), got):
                    on_level(k, P, H0, n)
                return P, H0, top
            except ConvergenceError:
                pass  # the prediction was no start: from ``start`` itself
        P, H0 = self.warm_start(start, top)
        P, H0, n = fas.solve_level(top, P, H0, self.films, final=True)
        Pc, H0c, nc = fas.solve_level(top - 1, inject(P), H0, self.films, final=False)
        on_level(top - 1, Pc, H0c, nc)
        on_level(top, P, H0, n)
        return P, H0, top

    def solve(self, top: int, tol: float | None, t0: float, start: EHLResult | None = None,
              fallback_start=None, reuse: dict | None = None):
        """(P, H0, FAS level index reached, per-level summaries); ``top`` is a grid level
        (``16 * 2**top`` intervals). ``fallback_start()`` -> (P (ny, nx), H0, grid level),
        a start from another solver, is used when the coarse-grid Newton start fails (high
        M: the coarsest grids cannot carry the thin film). ``reuse``: the caller's dict
        of a sequence of solves, where :class:`_PointPath` keeps the last two solutions."""
        path = _PointPath.of(reuse, self.dom, self.ratio)
        solved: dict[int, tuple[np.ndarray, float]] = {}
        top -= self.coarsest
        if top < 0:
            raise ConvergenceError(self.case, "grid level below the coarsest multigrid grid")
        per_level: list[dict] = []

        def on_level(k, P, H0, cycles):
            solved[k + self.coarsest] = (P.copy(), H0)
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
            P, H0, k = self._warm(start, top, on_level, path)
        else:
            try:
                if self.coarsest > 0 and fallback_start is not None:
                    raise ConvergenceError(self.case, "33^2 coarsest grid: Newton start")
                P, H0, k0 = self.cold_start()
                done = True
            except ConvergenceError:
                if fallback_start is None:
                    raise
                P, H0, k0 = fallback_start()
                k0 -= self.coarsest
                if k0 >= top or k0 < 0:
                    raise
                P, k0, done = _prolong_start(P), k0 + 1, False  # FD solved one level finer
            P, H0, k = self.fas.fmg(P, H0, k0, top, self.films, on_level, solved=done)
        path.record(self.M, self.L, solved)
        return P, H0, k, per_level


def solve_point_fas(M: float, L: float, *, level: int, ratio: float, dom: Domain, rheology: dict,
                    rigid: bool, tol: float | None, case: str, t0: float,
                    start: EHLResult | None = None, extra_flags: tuple[str, ...] = (),
                    opts: FasOptions | None = None, fallback_start=None,
                    reuse: dict | None = None) -> EHLResult:
    """The multigrid solve behind ``solve_point(method='fas')``; raises ConvergenceError
    (with the per-cycle residual and load-error history) when it fails."""
    from femgear.physics.ehl.core.assemble import assemble

    fp = FasPoint(M, L, ratio=ratio, dom=dom, rheology=rheology, rigid=rigid, case=case, opts=opts)
    P, H0, k, per_level = fp.solve(level, tol, t0, start, fallback_start, reuse)
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


class _PointPath:
    """The last two solutions of a sequence of point solves (kept in the caller's
    ``reuse`` dict, per domain and ellipticity), grid level by grid level, and the secant
    predictor of the next one (Allgower & Georg 1990, Numerical Continuation Methods,
    ch. 2): along s = (ln M, ln L) the solution is extrapolated linearly from the last two,
    x = x1 + t (x1 - x0), t the projection of s - s1 onto s1 - s0 (clipped to [0, 2]);
    with one entry the last solution itself, H0 shifted by the NVM change of the central
    film. The point contact's pressure spike is smooth enough on these grids to be
    extrapolated node by node (measured along the benchmark path at 129^2: the
    predicted films within 1.4e-3 of the solution, the previous solution 1e-2 off)."""

    def __init__(self, entries: list):
        self.entries = entries

    @classmethod
    def of(cls, reuse: dict | None, dom: Domain, ratio: float) -> _PointPath:
        key = ("point path", dom, ratio)
        return cls([] if reuse is None else reuse.setdefault(key, []))

    def record(self, M: float, L: float, solved: dict) -> None:
        self.entries[:] = [*self.entries[-1:], (M, L, solved)]

    def predict(self, start: EHLResult, M: float, L: float, lev: int, nvm):
        """(P, H0) on grid level ``lev`` for (M, L), or None when the history does not
        end at ``start`` or lacks the level; ``nvm(M, L)``: the NVM film (Hertzian)."""
        if not self.entries or self.entries[-1][:2] != (start.M, start.L) or lev not in self.entries[-1][2]:
            return None
        P1, H1 = self.entries[-1][2][lev]
        if len(self.entries) < 2 or lev not in self.entries[0][2]:
            return P1, H1 + nvm(M, L) - nvm(start.M, start.L)
        (M0, L0, s0), (M1, L1, _) = self.entries
        d0 = np.log([M1 / M0, (L1 + 1e-300) / (L0 + 1e-300)])
        d1 = np.log([M / M1, (L + 1e-300) / (L1 + 1e-300)])
        t = float(np.clip(d1 @ d0 / max(float(d0 @ d0), 1e-300), 0.0, 2.0))
        P0, H00 = s0[lev]
        return np.maximum(P1 + t * (P1 - P0), 0.0), H1 + t * (H1 - H00)
