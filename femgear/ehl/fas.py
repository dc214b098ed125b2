"""Nonlinear multigrid (FAS / FMG) for the point-contact EHL problem.

Full Approximation Scheme (Brandt 1977, Math. Comp. 31:333; Brandt 1984, GMD-Studien 85)
as applied to EHL by Lubrecht (1987, thesis, Twente) and Venner & Lubrecht (2000,
"Multilevel Methods in Lubrication", Tribology Series 37, ch. 3 and 7), on the FD
discretisation of :mod:`femgear.ehl.fd`:

* smoothing: zebra line relaxation, Gauss-Seidel / distributive by eps/h^2
  (:mod:`femgear.ehl.relax`), ``pre`` sweeps before and ``post`` after the coarse-grid
  correction; the film by DC-FFT on every level (no multi-integration needed);
* coarse-grid correction: the solution injected, the residual restricted by full
  weighting (zero at cavitated nodes), the coarse right-hand side
  f_c = L_c(I P) + R r and load target g_c = load_c(I P) + (g - load(P)); the correction
  prolonged bilinearly and P projected onto P >= 0; H0 is a global unknown, taken from
  the coarse grid;
* coarsest grid: solved exactly, load balance included, by dense semi-smooth Newton
  (:mod:`femgear.ehl.fdnewton`) instead of Venner's H0 relaxation with a factor 0.05-0.1;
* FMG: the coarsest grid solved from the start, then on each finer grid the cubic
  interpolation of the coarser solution followed by V (gamma = 1) or W (gamma = 2)
  cycles until the films change by less than ``film_tol`` per cycle and the load error
  is below ``load_tol``. The central and minimum films of every FMG level feed the
  Richardson error estimate (:mod:`femgear.ehl.accuracy`).

Every cycle appends the rms complementarity residual and the relative load error of its
level to the history (:class:`femgear.ehl.newton.History`); a level that does not reach
its tolerances within ``max_cycles``, or whose residual grows or stalls, raises
:class:`ConvergenceError` with that history.

Measured (2-core Xeon, shared; ``studies/benchmarks/ehl.py``): (20, 10) converges in
4 / 4 / 6 cycles on 33^2 / 65^2 / 129^2 (coarse-grid convergence factor ~0.2-0.3 per
cycle), 257^2 in 14 cycles with the smaller distributive factor; from alpha_bar ~13
((50, 10), (20, 20), (200, 10)) the cycles stall on the coarse grids, which is why
``solve_point(method='auto')`` keeps the Newton solver there.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError
from femgear.ehl.fd import FDLevel, inject, prolong_bilinear, prolong_cubic, restrict_full_weighting
from femgear.ehl.fdnewton import CoarseNewton
from femgear.ehl.newton import History
from femgear.ehl.relax import RelaxOptions, sweep


@dataclass(frozen=True)
class FasOptions:
    """Cycle parameters (Venner & Lubrecht's standard: 2 pre-, 1 post-sweep, V-cycle)."""

    pre: int = 2
    post: int = 1
    gamma: int = 1
    max_cycles: int = 30
    film_tol: float = 1e-4  # relative change of Hc, Hmin, H0 per cycle (finest level)
    load_tol: float = 1e-6
    # the FMG levels below the finest (a start and a term of the error estimate)
    coarse_film_tol: float = 1e-3
    coarse_load_tol: float = 1e-4
    coarse_newton: int = 3  # Newton steps on the coarsest grid per cycle
    relax: RelaxOptions = field(default_factory=RelaxOptions)
    # solves finer than 129^2 (all their levels): a smaller distributive factor (measured
    # at (20, 10): 0.7 converges in 6 cycles on 129^2 but oscillates on 257^2, also when
    # only the 257^2 level takes 0.5; 0.5 on all levels takes 9 / 14 cycles)
    relax_fine: RelaxOptions = field(default_factory=lambda: RelaxOptions(omega_dist=0.5))


class _Levels:
    """Levels built on first use by ``make(k)`` (a tol-driven solve may stop early)."""

    def __init__(self, make):
        self._make, self._built = make, {}

    def __getitem__(self, k: int) -> FDLevel:
        if k not in self._built:
            self._built[k] = self._make(k)
        return self._built[k]


class FAS:
    """FAS cycles over the levels ``make(k)``, k = 0 the coarsest."""

    def __init__(self, make, opts: FasOptions | None = None, case: str = "ehl fas"):
        self.levels, self.opts, self.case = _Levels(make), opts or FasOptions(), case
        self.coarse = CoarseNewton(self.levels[0])
        self.hist = History()
        self.relax = self.opts.relax

    def cycle(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, g: float):
        """One FAS cycle on level k for L(P, H0) = f, load(P) = g (None: H0 fixed);
        returns (P, H0)."""
        if k == 0:  # a few Newton steps: the coarse grid only approximates the finer ones
            P, H0, _ = self.coarse.solve(P, H0, f, g, self.case, strict=False,
                                         max_iter=self.opts.coarse_newton, chord=True)
            return P, H0
        lv, c, o = self.levels[k], self.levels[k - 1], self.opts
        ro = self.relax
        for _ in range(o.pre):
            sweep(lv, P, H0, f, ro)
        r, _, _, _ = lv.residual(P, H0, f)
        r = lv.complementarity(P, r)
        Pc = inject(P)
        Hc = c.film(Pc, H0)
        fc = c.operator(Pc, Hc, *c.coefficients(Pc, Hc)) + restrict_full_weighting(r)
        gc = None if g is None else c.load_of(Pc) + (g - lv.load_of(P))
        Pn, H0n = Pc.copy(), H0
        for _ in range(o.gamma if k > 1 else 1):
            Pn, H0n = self.cycle(k - 1, Pn, H0n, fc, gc)
        # the correction acts on the pressurised nodes only (Venner & Lubrecht 2000, 7.4)
        P += np.where(P > 0.0, prolong_bilinear(Pn - Pc), 0.0)
        np.maximum(P, 0.0, out=P)
        H0 = H0n
        for _ in range(o.post):
            sweep(lv, P, H0, f, ro)
        return P, H0

    def record(self, k: int, P, H0) -> np.ndarray:
        """Append the rms complementarity residual and the load error of level k (f = 0);
        returns the film."""
        lv = self.levels[k]
        r, H, _, _ = lv.residual(P, H0, np.zeros((lv.ny - 2, lv.nx - 2)))
        res = float(np.sqrt(np.mean(lv.complementarity(P, r) ** 2)))
        self.hist.residual.append(res)
        self.hist.load_error.append(abs(lv.load_of(P) - lv.load) / lv.load)
        self.hist.level.append(lv.nx * lv.ny)
        if not (np.isfinite(res) and np.isfinite(H0) and np.all(np.isfinite(P))):
            raise ConvergenceError(self.case, "non-finite multigrid iterate", self.hist.as_dict())
        return H

    def solve_level(self, k: int, P: np.ndarray, H0: float, films,
                    final: bool = True) -> tuple[np.ndarray, float, int]:
        """Cycles on level k until the films (``films(k, P, H0)``) and H0 change by less
        than ``film_tol`` per cycle and the load error is below ``load_tol`` (not
        ``final``: the coarse tolerances); raises when the residual stalls or grows."""
        lv, o = self.levels[k], self.opts
        ftol, ltol = (o.film_tol, o.load_tol) if final else (o.coarse_film_tol, o.coarse_load_tol)
        f = np.zeros((lv.ny - 2, lv.nx - 2))
        prev = (*films(k, P, H0), H0)
        for it in range(o.max_cycles):
            with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                P, H0 = self.cycle(k, P, H0, f, lv.load)
            H = self.record(k, P, H0)
            cur = (*films(k, P, H0, H), H0)
            change = max(abs(a - b) / max(abs(b), 1e-3) for a, b in zip(cur, prev))
            prev = cur
            if change < ftol and self.hist.load_error[-1] < ltol:
                return P, H0, it + 1
            res = self.hist.residual[-it - 1:]
            if (it >= 2 and res[-1] > 1e2 * min(res)) or (it >= 8 and res[-1] > 0.5 * res[-6]):
                break  # diverging, or stalled (less than a factor 2 in 5 cycles)
        raise ConvergenceError(self.case, f"FAS: no convergence in {it + 1} cycles on "
                               f"{lv.nx}x{lv.ny}", self.hist.as_dict())

    def select_relax(self, top: int) -> None:
        """The relaxation factors of a solve whose finest level is ``top``."""
        self.relax = self.opts.relax if self.levels[top].nx <= 129 else self.opts.relax_fine

    def fmg(self, P: np.ndarray, H0: float, first: int, top: int, films, on_level,
            solved: bool = False):
        """Full multigrid from (P, H0) on level ``first`` (``solved``: already converged
        there) to ``top``; ``on_level(k, P, H0, cycles)`` after each level returns True to
        stop there. Returns (P, H0, the level reached)."""
        self.select_relax(top)
        if solved:
            self.record(first, P, H0)
            n = 0
        else:
            P, H0, n = self.solve_level(first, P, H0, films, final=first == top)
        if on_level(first, P, H0, n):
            return P, H0, first
        for k in range(first + 1, top + 1):
            P = np.maximum(prolong_cubic(P), 0.0)
            P[0], P[-1], P[:, 0], P[:, -1] = 0.0, 0.0, 0.0, 0.0
            P, H0, n = self.solve_level(k, P, H0, films, final=k == top)
            if on_level(k, P, H0, n):
                if k < top:  # stopped early (tol): the final tolerances on this level
                    P, H0, _ = self.solve_level(k, P, H0, films, final=True)
                return P, H0, k
        return P, H0, top
