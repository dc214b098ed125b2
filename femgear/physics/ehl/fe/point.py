"""Point (circular / elliptical) contact EHL by the FE Newton–Krylov solver: nested iteration
over levels.

Solve on the coarsest level with dense Newton from a Hertzian start (with continuation
in alpha_bar if the direct start fails), then interpolate to each finer level and solve
there with Newton-Krylov preconditioned by the multilevel cycle (:mod:`femgear.physics.ehl.fe.newton`).
Inputs are Moes groups (Venner & Lubrecht 2000 scaling, see :mod:`femgear.physics.ehl.core.params`);
the ellipticity ``ratio`` is lambda = R_x/R_y (geometry X^2/2 + lambda Y^2/2, as in
Nijenbanning, Venner & Moes 1994). :func:`femgear.physics.ehl.point.solve_point` is the entry.

Two fallbacks, both automatic and reported in the result:

* High load (M ~ 1000 at L = 10): the coarse grids cannot carry the thin film, so no
  level yields a start. Then the case is reached by continuation in the load on the
  finest level, M/sqrt(2) -> M, solved recursively (in Hertzian units the solutions of
  neighbouring loads are close; each step takes ~4 Newton iterations).
* Strong piezoviscosity (L = 20 on 129^2): the outlet pressure spike is under-resolved
  and its ridge stair-steps across the cells; with the default artificial diffusion
  the semi-smooth Newton cycles at a residual ~1e-3 without converging. The stalled
  level is then solved with the diffusion of :mod:`reynolds` scaled by
  :data:`STABILISATION` (nested solve with the largest factor, then Newton with each
  smaller one from the previous solution); ``levels[k]['ad_factor']`` reports the factor
  used. The O(h^2) diffusion still vanishes under refinement; at (20, 20) the factors
  2 / 1.5 / 1.2 give Hc within 0.1 % of each other (Pmax: 1.78 / 1.93 / 2.11).
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.assemble import assemble
from femgear.physics.ehl.core.domain import hertz_ellipse
from femgear.physics.ehl.core.grid import Domain, Grid, prolongation
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.core.surface import apply_surface, evaluate
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.newton import newton_dense, newton_krylov

CONTINUATION = (0.0, 0.25, 0.5, 0.75, 1.0)
STABILISATION = (2.0, 1.5, 1.2)


def _hertz_start(level: Level, ratio: float) -> np.ndarray:
    """Dry Hertz pressure on the contact ellipse, scaled to the load.

    lambda = 1: the circle of radius 1. lambda != 1: the exact Hertz ellipse
    (:func:`hertz_ellipse`). On a grid coarser than the contact (huge domains at small M)
    the ellipse is widened to two cells in each direction, so that the start carries the
    load on some nodes (never 0/0)."""
    if ratio == 1.0:
        ax = ay = 1.0
        grow = max(1.0, 2.0 * level.h / min(ax, ay))
        ax, ay = grow * ax, grow * ay
    else:
        a, b, _ = hertz_ellipse(ratio)
        ax = a * max(1.0, 2.0 * level.h / a)
        ay = b * max(1.0, 2.0 * level.hy / b)
    P = np.sqrt(np.maximum(1.0 - (level.X / ax) ** 2 - (level.Y / ay) ** 2, 0.0))
    PI = P[level.interior]
    return PI * level.load / (level.m @ PI)


def _krylov_cap(ratio: float) -> dict:
    """Elliptic contacts on stretched cells: GMRES capped at 5 restarts (300 iterations);
    a preconditioner gone stale (a moved active set) otherwise costs up to 18000 iterations
    before Newton rebuilds it (measured: 300 s of a 20 s solve). Circular: unchanged."""
    return {} if ratio == 1.0 else {"maxiter_krylov": 5}


class NestedPoint:
    """One point-contact solve: the nested iteration over the levels with its fallbacks
    (alpha and load continuation, stabilisation continuation; see the module docstring)."""

    def __init__(self, M: float, L: float, *, ratio: float, dom: Domain, coarse_level: int,
                 level: int, tol: float | None, rigid: bool, ad_factor: float, sd_factor: float,
                 t0: float, rheology: dict, newton: dict, surface=None, dense_reuse: bool = False):
        self.M, self.L, self.ratio, self.dom = M, L, ratio, dom
        self.surface = surface
        self.coarse_level, self.level, self.tol = coarse_level, level, tol
        self.rigid, self.ad_factor, self.sd_factor = rigid, ad_factor, sd_factor
        self.t0, self.rheology, self.newton, self.case = t0, rheology, newton, newton["case"]
        self.fac = pr.point_h_moes_factor(M)
        self.hist = History()
        self.last_failure = ""  # reason of the last failed Newton attempt (for the error)
        self.factorised: dict = {}  # Level -> factorised preconditioner level, kept across levels
        self.dense = {} if dense_reuse else None   # LU factors of the dense Newton steps, kept across them
        self.levels = _LazyLevels(lambda k: self.make(M, 1.0, k), coarse_level, level)

    def make(self, M_: float, frac: float, lev: int, stab: float = 1.0) -> Level:
        rheo = Rheology(pr.point_alpha_bar(M_, self.L) * frac, **self.rheology)
        lv = Level(rheo, pr.point_lam_bar(M_), pr.POINT_LOAD, grid=Grid.build(self.dom, lev),
                   ratio=self.ratio, rigid=self.rigid, ad_factor=self.ad_factor * stab,
                   sd_factor=self.sd_factor * stab)
        apply_surface(lv, evaluate(self.surface, lv.X, lv.Y))
        return lv

    def nvm_hertz(self, M_: float) -> float:
        """NVM central film in Hertzian units."""
        return float(nvm_central(M_, self.L, self.ratio)) / pr.point_h_moes_factor(M_)

    def hertz(self, lv: Level, M_: float):
        PI = _hertz_start(lv, self.ratio)
        H0 = self.nvm_hertz(M_) - float(lv.deflection(lv.full(PI))[np.argmin(lv.X**2 + lv.Y**2)])
        return PI, H0

    def attempt(self, lvs, PI, H0):
        """(PI, H0) solved on the finest of ``lvs`` (dense Newton on one level), or None."""
        try:
            if len(lvs) == 1:
                PI, H0, h = newton_dense(lvs[0], PI, H0, **self.newton, reuse=self.dense)
            else:
                PI, H0, h = newton_krylov(lvs, PI, H0, reuse=self.factorised, **self.newton,
                                          **_krylov_cap(self.ratio))
        except ConvergenceError as exc:
            self.hist.extend(History(**exc.history))
            self.last_failure = str(exc).split(": ", 1)[-1].split(" (last: ")[0]
            return None
        self.hist.extend(h)
        return PI, H0

    def result(self, PI, H0, per_level, fine, seconds: float, *, tol: float, extra_flags=()) -> EHLResult:
        """The :class:`EHLResult` of a solve that ended on level ``fine`` with (PI, H0)."""
        return _result("point", self.M, self.L, fine, PI, H0, self.fac, self.hist, per_level, seconds,
                       tol=tol, extra_flags=extra_flags)

    def fas_start(self):
        """(P (ny, nx), H0, k): the Newton start (coarse levels, alpha continuation, next
        level) for the multigrid solver, on grid level k (ConvergenceError without one)."""
        got = self.start_solve(self.levels, self.M, 1.0)
        if not got:
            raise ConvergenceError(self.case, "no Newton start for the multigrid solver",
                                   self.hist.as_dict())
        PI, H0, n = got
        lv = self.levels[n - 1]
        return lv.full(PI).reshape(lv.grid.ny, lv.grid.nx), H0, n - 1 + self.coarse_level

    def summary(self, lv: Level, PI, H0, its: int, ad: float) -> dict:
        return _level_summary(lv, PI, H0, self.fac, its, self.t0, self.ad_factor * ad)

    def start_solve(self, lvs, M_: float, stab: float):
        """(PI, H0, n) for load M_ on the n-th level, or None: (1) dense Newton on the
        coarse level from Hertz, (2) with continuation in alpha_bar, (3) Newton-Krylov on
        the next level from Hertz (a coarse grid cannot carry a very thin film)."""
        got = self.attempt(lvs[:1], *self.hertz(lvs[0], M_))
        if got:
            return (*got, 1)
        PI, H0 = self.hertz(lvs[0], M_)
        for frac in CONTINUATION:
            stage = lvs[0] if frac == 1.0 else self.make(M_, frac, self.coarse_level, stab)
            got = self.attempt([stage], PI, H0)
            if not got:
                break
            PI, H0 = got
        else:
            return PI, H0, 1
        if len(lvs) > 1:
            got = self.attempt(lvs[:2], *self.hertz(lvs[1], M_))
            if got:
                return (*got, 2)
        return None

    def stabilised(self, lvs, M_: float, k: int):
        """Level k with the stabilisation continuation of :data:`STABILISATION`: nested
        solve up to level k with the largest factor, then Newton on level k with each
        smaller factor from the previous solution; (PI, H0) and the smallest factor that
        converged, or (None, None)."""
        try:
            PI, H0, _, _ = self.solve_at(M_, STABILISATION[0], k + self.coarse_level)
        except ConvergenceError:
            return None, None
        got, used = (PI, H0), STABILISATION[0]
        for factor in STABILISATION[1:]:
            nxt = self.attempt(lvs[:k] + [self.make(M_, 1.0, k + self.coarse_level, factor)], *got)
            if not nxt:
                break
            got, used = nxt, factor
        return got, used

    def refine(self, lvs, M_: float, PI, H0, start: int, per_level: list, stab: float):
        """Nested iteration from level ``start`` to the finest, or with ``tol`` to the first
        level whose error estimate meets it; (PI, H0, that level)."""
        k = start - 1
        for k in range(start, len(lvs)):
            if self.tol is not None and lvs is self.levels and all(
                    e is not None and e <= self.tol for e in acc.error_estimate(per_level).values()):
                return PI, H0, lvs[k - 1]
            fine, prev = lvs[k], lvs[k - 1]
            P0 = (prolongation(prev.grid, fine.grid) @ prev.full(PI))[fine.interior]
            n0 = len(self.hist.residual)
            got, used = self.attempt(lvs[: k + 1], P0, H0), stab
            failure = self.last_failure
            if not got and stab == 1.0:
                got, used = self.stabilised(lvs, M_, k)
            if not got:
                raise ConvergenceError(self.case, f"no convergence on level {k + self.coarse_level} "
                                       f"(M={M_:g}, also with stabilisation continuation; first "
                                       f"attempt: {failure})", self.hist.as_dict())
            PI, H0 = got
            per_level.append(self.summary(fine, PI, H0, len(self.hist.residual) - n0, used))
        return PI, H0, lvs[k]

    def solve_at(self, M_: float, stab: float = 1.0, top: int | None = None, depth: int = 0):
        """(PI, H0) on level ``top`` for load M_, the level summaries and that level.
        Without a start, continuation in the load on level ``top``: solve M_/sqrt(2)
        (recursively), shift H0 by the NVM change of the central film and take Newton from
        there (solutions in Hertzian units are close: ~4 Newton iterations a step)."""
        top = self.level if top is None else top
        lvs = (self.levels if (M_, stab, top) == (self.M, 1.0, self.level) else
               _LazyLevels(lambda k: self.make(M_, 1.0, k, stab), self.coarse_level, top))
        got = self.start_solve(lvs, M_, stab)
        if got:
            PI, H0, start = got
            per_level = [self.summary(lvs[start - 1], PI, H0, len(self.hist.residual), stab)]
            PI, H0, last = self.refine(lvs, M_, PI, H0, start, per_level, stab)
            return PI, H0, per_level, last
        if M_ <= 20.0 or depth >= 8:
            raise ConvergenceError(self.case, f"no start at M={M_:g} (direct, alpha continuation, "
                                   "next-level Newton-Krylov)", self.hist.as_dict())
        Mp = M_ / math.sqrt(2.0)
        PI, H0, _, _ = self.solve_at(Mp, stab, top, depth + 1)
        n0 = len(self.hist.residual)
        H0 += self.nvm_hertz(M_) - self.nvm_hertz(Mp)
        got = self.attempt(lvs, PI, H0)
        if not got:
            raise ConvergenceError(self.case, f"load continuation {Mp:g} -> {M_:g} failed",
                                   self.hist.as_dict())
        PI, H0 = got
        return PI, H0, [self.summary(lvs[-1], PI, H0, len(self.hist.residual) - n0, stab)], lvs[-1]


class _LazyLevels:
    """Levels ``lo..hi`` of one problem, built on first use (a tol-driven solve may stop
    long before the cap, and a 513^2 level costs a second to set up)."""

    def __init__(self, make, lo: int, hi: int):
        self._make, self._lo, self._built = make, lo, [None] * (hi - lo + 1)

    def __len__(self) -> int:
        return len(self._built)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(len(self)))]
        k = range(len(self))[k]
        if self._built[k] is None:
            self._built[k] = self._make(k + self._lo)
        return self._built[k]


def _level_summary(level: Level, PI, H0, fac, its, t0, ad_factor) -> dict:
    P, H = level.film(PI, H0)
    i0 = int(np.argmin(level.X**2 + level.Y**2))
    return {"nodes": level.n, "h": level.h, "Hc": float(H[i0] * fac),
            "Hmin": float(H.min() * fac), "Pmax": float(P.max()), "iterations": its,
            "ad_factor": ad_factor, "seconds": time.perf_counter() - t0}


def _result(kind, M, L, level: Level, PI, H0, fac, hist: History, per_level, seconds, *,
            tol: float = acc.DEFAULT_TOL, extra_flags: tuple[str, ...] = ()):
    P, H = level.film(PI, H0)
    if level.dim == 2:
        g = level.grid
        x, y = g.x, g.y
        P, H = P.reshape(g.ny, g.nx), H.reshape(g.ny, g.nx)
    else:
        x, y = level.X, np.zeros(0)
    load_error = abs(level.m @ PI - level.load) / level.load
    return assemble(kind, M, L, x, y, P, H, H0=H0, load_error=load_error, fac=fac,
                    history=hist.as_dict(), iterations=len(hist.residual), per_level=per_level,
                    seconds=seconds, tol=tol, extra_flags=extra_flags)
