"""Nonlinear multigrid (FAS / FMG) for the point-contact EHL problem.

Full Approximation Scheme (Brandt 1977, Math. Comp. 31:333; Brandt 1984, GMD-Studien 85)
as applied to EHL by Lubrecht (1987, thesis, Twente) and Venner & Lubrecht (2000,
"Multilevel Methods in Lubrication", Tribology Series 37, ch. 3 and 7), on the FD
discretisation of :mod:`femgear.physics.ehl.fd.operator`:

* smoothing: zebra line relaxation, Gauss-Seidel / distributive by eps/h^2
  (:mod:`femgear.physics.ehl.fd.relax`), ``pre`` sweeps before and ``post`` after the coarse-grid
  correction; the film by DC-FFT on every level (no multi-integration needed);
* coarse-grid correction: the solution injected, the residual restricted by full
  weighting (zero at cavitated nodes), the coarse right-hand side
  f_c = L_c(I P) + R r and load target g_c = load_c(I P) + (g - load(P)); the correction
  prolonged bilinearly and P projected onto P >= 0; H0 is a global unknown, taken from
  the coarse grid;
* coarsest grid: solved exactly, load balance included, by dense semi-smooth Newton
  (:mod:`femgear.physics.ehl.fd.newton`) instead of Venner's H0 relaxation with a factor 0.05-0.1;
* FMG: the coarsest grid solved from the start, then on each finer grid the cubic
  interpolation of the coarser solution followed by V (gamma = 1) or W (gamma = 2)
  cycles until the films change by less than ``film_tol`` per cycle and the load error
  is below ``load_tol``; a level whose residual grows in a cycle from the third on
  continues with W-cycles (measured: (10, 10) on 257^2 sat in a period-2 limit cycle of
  its V-cycles at the pressure spike, dP ~ 4e-3 on 8 nodes and Hmin +-1e-4, and fell back
  to Newton; W-cycles converge, 8 cycles in all). The central and minimum films of every
  FMG level feed the Richardson error estimate (:mod:`femgear.physics.ehl.core.accuracy`).

Every cycle appends the rms complementarity residual and the relative load error of its
level to the history (:class:`femgear.physics.ehl.core.history.History`); a level that does not reach
its tolerances within ``max_cycles``, or whose residual grows or stalls, raises
:class:`ConvergenceError` with that history.

Measured (2-core Xeon, shared; ``studies/benchmarks/ehl.py``): (20, 10) converges in
4 / 4 / 5 cycles on 33^2 / 65^2 / 129^2 (coarse-grid convergence factor ~0.2-0.3 per
cycle), 257^2 in 4 / 4 / 3 / 5 (``relax_fine``: the Gauss-Seidel factor 0.6; with 0.8
the line sweeps diverge at the outlet constriction and the cycles took 14). Warm starts
along a path (``warm=`` of :meth:`FAS.solve_level`): one or two V-cycles per grid from the
secant prediction of :mod:`femgear.physics.ehl.fd.point`. From alpha_bar ~13
((50, 10), (20, 20), (200, 10)) the standard cycles stall on the coarse grids, which is why
``solve_point(method='auto')`` keeps the Newton solver there; beyond alpha_bar 17 the
options HIGH_ALPHA of :mod:`femgear.physics.ehl.fd.point` (a larger per-sweep cap, sweeps after each FMG
interpolation; on 257^2 the correction kept off the outlet spike, the spike nodes
eliminated by exact local solves, :mod:`eliminate`) converge (20, 20) and (100, 20) on
129^2 and 257^2.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy import ndimage

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.fd.eliminate import SpikeElimination
from femgear.physics.ehl.fd.newton import CoarseNewton
from femgear.physics.ehl.fd.operator import FDLevel, inject, prolong_bilinear, prolong_cubic, restrict_full_weighting
from femgear.physics.ehl.fd.relax import RelaxOptions, sweep

# the contraction credited to a warm cycle: its residual ratio clipped to [0.1, 0.5] (0.5:
# the largest film contraction per V-cycle measured on the FMG levels of (20, 10), 0.28-0.45;
# a larger residual ratio is the residual floor of the spike, reached from a good start)
WARM_Q = (0.1, 0.5)


@dataclass(frozen=True)
class FasOptions:
    """Cycle parameters (Venner & Lubrecht's standard: 2 pre-, 1 post-sweep, V-cycle)."""

    pre: int = 2
    post: int = 1
    gamma: int = 1
    max_cycles: int = 30
    film_tol: float = 1e-4  # relative change of Hc, Hmin, H0 per cycle (finest level)
    # the load error moves the films by about 0.07 x itself (h ~ W^-0.067, Hamrock & Dowson
    # 1977): 1e-5 is far below film_tol; at 1e-6 the 257^2 cycles of (20, 5) and (10, 10)
    # stall on a period-2 oscillation of the load error of 1e-6 - 4e-5
    load_tol: float = 1e-5
    # the FMG levels below the finest (a start and a term of the error estimate)
    coarse_film_tol: float = 1e-3
    coarse_load_tol: float = 1e-4
    coarse_newton: int = 3  # Newton steps on the coarsest grid per cycle
    # (pre, post) sweeps of the cycles from a predicted state (a path): measured on the
    # 41-position benchmark path, (1, 1) costs 7.5 cold solves in sweeps, (2, 1) 10.1, both
    # with warm films within 4e-4 of the cold ones
    warm_sweeps: tuple[int, int] = (1, 1)
    relax: RelaxOptions = field(default_factory=RelaxOptions)
    # solves finer than 129^2 (all their levels): a smaller Gauss-Seidel factor. Measured
    # at (20, 10) on 257^2: with omega_gs 0.8 the line Gauss-Seidel sweeps alone diverge at
    # the outlet constriction (X ~ 0.72, the residual grows from the 7th sweep on; also
    # with xi_switch 0.1 or 1 and with the first-order wedge), so more smoothing (V(3,2),
    # W-cycles) diverges and V(2,1) oscillates (14 cycles with omega_dist 0.5); with
    # omega_gs 0.5 the sweeps smooth monotonically, and omega_gs 0.6 takes 5 cycles
    relax_fine: RelaxOptions = field(default_factory=lambda: RelaxOptions(omega_dist=0.7, omega_gs=0.6))
    # strongly piezoviscous contacts (all off by default; the preset HIGH_ALPHA of
    # fd.point, measured there): relaxation sweeps on each FMG level after the cubic
    # interpolation, before its first cycle (:meth:`FAS.presmooth`); on levels finer than
    # SPIKE_GUARD_NX the coarse-grid correction left out within ``spike_guard`` nodes of
    # the outlet spike (:func:`_steep`) and the relaxation ``relax_top``; the switch to
    # W-cycles; the stall test (residual ratio over 5 cycles > 0.5) from cycle
    # ``stall_after`` on
    fmg_sweeps: int = 0
    spike_guard: int = 0
    relax_top: RelaxOptions | None = None
    w_switch: bool = True
    stall_after: int = 8
    # nonlinear elimination of the spike (:mod:`eliminate`; Cai & Li 2011) on levels finer
    # than SPIKE_GUARD_NX: after each cycle the nodes within ``eliminate`` of the steep
    # faces solved exactly; ``freeze_guard``: the level below keeps the nodes under the
    # guard fixed (its correction elsewhere then agrees with the finer level, which drops
    # the guarded one: measured at (20, 20) on 257^2, without it the films oscillate by
    # 3e-3 from cycle to cycle, with it by 2e-5)
    eliminate: int = 0
    freeze_guard: bool = False
    # the coarse-grid correction (P and H0) of levels finer than SPIKE_GUARD_NX scaled by
    # this factor (a damped coarse-grid correction, Hackbusch 1985, "Multi-Grid Methods and
    # Applications", ch. 9). Measured at (20, 20) on 257^2 with the elimination: with 1 the
    # cycles end in a period-2 limit cycle (the load error alternating 2.1e-5 / 3.3e-5,
    # never below load_tol; Hc +-1e-4); with 0.7 the load error falls to 1e-6 and the films
    # stay fixed to 1e-6
    top_damping: float = 1.0


def _steep(eps: np.ndarray, radius: int, jump: float = 2.0) -> np.ndarray:
    """Nodes within ``radius`` of a face across which ln eps changes by more than
    ``jump`` (the outlet pressure spike, where P falls from ~2 to ~0.1 within a cell).

    Measured at (20, 20) on 257^2 from the 129^2 solution and 40 sweeps (residual 1.5e-3):
    one V-cycle raised the residual to 1.3 and the cycles diverged (also with H0 held fixed,
    with the correction clipped to 4/alpha_bar, with first-order wedges, or with W-cycles:
    the coarser grid cannot carry the finer grid's spike); without the correction within 5
    nodes of the spike the cycles stay bounded (residual 0.02 -> 0.012 in 6 cycles)."""
    le = np.log(np.maximum(eps, 1e-300))
    m = np.zeros(eps.shape, bool)
    dx, dy = np.abs(np.diff(le, axis=1)) > jump, np.abs(np.diff(le, axis=0)) > jump
    m[:, 1:] |= dx
    m[:, :-1] |= dx
    m[1:] |= dy
    m[:-1] |= dy
    # grown by ``radius`` nodes along the grid lines (4-neighbour cross; iterations=0 would
    # mean "until nothing changes" in scipy)
    return ndimage.binary_dilation(m, iterations=radius) if radius > 0 else m


# levels finer than this take ``spike_guard``, ``relax_top``, ``eliminate`` (FasOptions)
SPIKE_GUARD_NX = 129


def _sweep(lv: FDLevel, P: np.ndarray, H0: float, f: np.ndarray, ro: RelaxOptions,
           frozen: np.ndarray | None) -> None:
    """One relaxation sweep; the ``frozen`` nodes (full-grid bool) keep their values."""
    keep = None if frozen is None else P[frozen]
    sweep(lv, P, H0, f, ro)
    if keep is not None:
        P[frozen] = keep


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
        self.sweeps, self.gamma = (self.opts.pre, self.opts.post), self.opts.gamma
        self._elim: SpikeElimination | None = None  # the last spike elimination (cycle)

    def cycle(self, k: int, P: np.ndarray, H0: float, f: np.ndarray, g: float,
              frozen: np.ndarray | None = None):
        """One FAS cycle on level k for L(P, H0) = f, load(P) = g (None: H0 fixed);
        returns (P, H0). ``frozen`` (full-grid bool): nodes this level keeps fixed (the
        spike of the finer level, :attr:`FasOptions.freeze_guard`)."""
        if k == 0:  # a few Newton steps: the coarse grid only approximates the finer ones
            P, H0, _ = self.coarse.solve(P, H0, f, g, self.case, strict=False,
                                         max_iter=self.opts.coarse_newton, chord=True)
            return P, H0
        lv, c, o = self.levels[k], self.levels[k - 1], self.opts
        ro, (pre, post) = self.relax, self.sweeps
        top = lv.nx > SPIKE_GUARD_NX
        if o.relax_top is not None and top:
            ro = o.relax_top
        for _ in range(pre):
            _sweep(lv, P, H0, f, ro, frozen)
        r, _, eps_f, _ = lv.residual(P, H0, f)
        r = lv.complementarity(P, r)
        guard = _steep(eps_f, o.spike_guard) if o.spike_guard and top else frozen
        Pc = inject(P)
        Hc = c.film(Pc, H0)
        fc = c.operator(Pc, Hc, *c.coefficients(Pc, Hc)) + restrict_full_weighting(r)
        gc = None if g is None else c.load_of(Pc) + (g - lv.load_of(P))
        Pn, H0n = Pc.copy(), H0
        below = guard[::2, ::2] if (o.freeze_guard and top and guard is not None) else None
        for _ in range(self.gamma if k > 1 else 1):
            Pn, H0n = self.cycle(k - 1, Pn, H0n, fc, gc, below)
        # the correction acts on the pressurised nodes only (Venner & Lubrecht 2000, 7.4)
        corr = np.where(P > 0.0, prolong_bilinear(Pn - Pc), 0.0)
        if guard is not None:
            corr[guard] = 0.0
        damp = o.top_damping if top else 1.0
        P += damp * corr
        np.maximum(P, 0.0, out=P)
        H0 = H0n if damp == 1.0 else H0 + damp * (H0n - H0)  # undamped: bit-identical
        for _ in range(post):
            _sweep(lv, P, H0, f, ro, frozen)
        if o.eliminate and top:  # the spike nodes solved exactly (module eliminate)
            mask = _steep(lv.coefficients(P, lv.film(P, H0))[0], o.eliminate)[1:-1, 1:-1]
            el = self._elim
            if el is None or el.lv is not lv or not np.array_equal(el.mask, mask):
                el = self._elim = SpikeElimination(lv, mask)  # else: the last one's factors
            self.hist.eliminated.append(el.solve(P, H0, f)[-1])
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

    def solve_level(self, k: int, P: np.ndarray, H0: float, films, final: bool = True,
                    warm: tuple[float, float] | None = None) -> tuple[np.ndarray, float, int]:
        """Cycles on level k until the films (``films(k, P, H0)``) and H0 change by less
        than ``film_tol`` per cycle and the load error is below ``load_tol`` (not
        ``final``: the coarse tolerances); raises when the residual stalls or grows.

        ``warm = (tol, load_tol)``: from a predicted state (a path, :mod:`femgear.physics.ehl.fd.point`),
        ``warm_sweeps`` cycles until the algebraic error of the films is bounded by
        ``tol``: a cycle contracting the error by q leaves at most change * q / (1 - q)
        (the a-posteriori bound of the contraction mapping theorem), the change counted
        from the predicted state and q the cycle's residual ratio clipped to ``WARM_Q``."""
        lv, o = self.levels[k], self.opts
        ftol, ltol = (o.film_tol, o.load_tol) if final else (o.coarse_film_tol, o.coarse_load_tol)
        f = np.zeros((lv.ny - 2, lv.nx - 2))
        if warm is None:
            prev = (*films(k, P, H0), H0)
        else:  # the predicted state's residual starts the contraction estimate
            (ftol, ltol), self.sweeps = warm, o.warm_sweeps
            prev = films(k, P, H0, self.record(k, P, H0))
        n0 = len(self.hist.residual) - (warm is not None)
        try:
            for it in range(o.max_cycles):
                with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                    P, H0 = self.cycle(k, P, H0, f, lv.load)
                H = self.record(k, P, H0)
                cur = (*films(k, P, H0, H), H0)[:len(prev)]
                change = max(abs(a - b) / max(abs(b), 1e-3) for a, b in zip(cur, prev))
                prev, res = cur, self.hist.residual[n0:]
                if warm is not None:
                    q = min(max(res[-1] / max(res[-2], 1e-300), WARM_Q[0]), WARM_Q[1])
                    change *= q / (1.0 - q)
                if change < ftol and self.hist.load_error[-1] < ltol:
                    return P, H0, it + 1
                if o.w_switch and warm is None and it >= 2 and res[-1] > res[-2]:
                    self.gamma = 2  # V-cycles in a limit cycle: W-cycles (module docstring)
                if (it >= 2 and res[-1] > 1e2 * min(res)) or (it >= o.stall_after and res[-1] > 0.5 * res[-6]):
                    break  # diverging, or stalled (less than a factor 2 in 5 cycles)
        finally:
            self.sweeps, self.gamma = (o.pre, o.post), o.gamma
        raise ConvergenceError(self.case, f"FAS: no convergence in {it + 1} cycles on "
                               f"{lv.nx}x{lv.ny}", self.hist.as_dict())

    def presmooth(self, k: int, P: np.ndarray, H0: float) -> None:
        """``fmg_sweeps`` relaxation sweeps on level k (in place), H0 fixed: an interpolated
        start's error at the pressure spike smoothed before the first coarse-grid correction
        (measured at (20, 20) on 129^2: cycles from the interpolated 65^2 solution, load
        error 2 %, jump to a residual of 1.2 and stall at 0.03; after 40 sweeps the same
        cycles contract by ~0.5 each)."""
        lv = self.levels[k]
        f = np.zeros((lv.ny - 2, lv.nx - 2))
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            for _ in range(self.opts.fmg_sweeps):
                sweep(lv, P, H0, f, self.relax)

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
            self.presmooth(first, P, H0)
            P, H0, n = self.solve_level(first, P, H0, films, final=first == top)
        if on_level(first, P, H0, n):
            return P, H0, first
        for k in range(first + 1, top + 1):
            P = np.maximum(prolong_cubic(P), 0.0)
            P[0], P[-1], P[:, 0], P[:, -1] = 0.0, 0.0, 0.0, 0.0
            self.presmooth(k, P, H0)
            P, H0, n = self.solve_level(k, P, H0, films, final=k == top)
            if on_level(k, P, H0, n):
                if k < top:  # stopped early (tol): the final tolerances on this level
                    P, H0, _ = self.solve_level(k, P, H0, films, final=True)
                return P, H0, k
        return P, H0, top
