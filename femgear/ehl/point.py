"""Point (circular / elliptical) contact EHL: nested iteration over levels.

Solve on the coarsest level with dense Newton from a Hertzian start (with continuation
in alpha_bar if the direct start fails), then interpolate to each finer level and solve
there with Newton-Krylov preconditioned by the multilevel cycle (:mod:`newton`).
Inputs are Moes groups (Venner & Lubrecht 2000 scaling, see :mod:`params`); the
ellipticity ``ratio`` is lambda = R_x/R_y (geometry X^2/2 + lambda Y^2/2, as in
Nijenbanning, Venner & Moes 1994).

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
from functools import lru_cache

import numpy as np

from femgear.contact.film import nvm_central
from femgear.contact.hertz import hertz_point
from femgear.ehl import accuracy as acc
from femgear.ehl import params as pr
from femgear.ehl.assemble import assemble
from femgear.ehl.fas_point import HIGH_ALPHA_FROM, solve_point_fas
from femgear.ehl.grid import Domain, Grid, prolongation
from femgear.ehl.level import Level
from femgear.ehl.newton import History, newton_dense, newton_krylov
from femgear.ehl.results import EHLResult
from femgear.ehl.rheology import Rheology
from femgear.ehl.surface import apply_surface, evaluate
from femgear.errors import ConvergenceError, SceneError

CONTINUATION = (0.0, 0.25, 0.5, 0.75, 1.0)
STABILISATION = (2.0, 1.5, 1.2)
DEFAULT_LEVEL = 3  # 129^2
# Newton stops after a full step onto this scaled residual (or a relative step < newton_tol):
# 1e-8 moves Hc and Hmin by < 1e-7 relative, far below any grid's discretisation error
RESIDUAL_TOL = 1e-8
MAX_LEVEL = 5  # 513^2: the finest grid a tol-driven solve may reach


@lru_cache(maxsize=64)
def hertz_ellipse(ratio: float) -> tuple[float, float, float]:
    """(a, b, p_h) of the dry Hertz ellipse for lambda = R_x/R_y = ``ratio`` in the units of
    the circular contact on R_x (a/a_c, b/a_c, p_h/p_c): a along X (entrainment), b along Y.

    Exact elliptic-integral solution (Johnson 1985, eq. 4.39; :func:`femgear.contact.hertz.
    hertz_point`) with F = 1, R_x = 1, E' = 3/2, for which a_c = (3 F R_x / 2E')^(1/3) = 1
    and p_c = 3F/(2 pi a_c^2) = 3/(2 pi). At lambda = 0.02: a = 0.4712, b = 5.688,
    p_h = 0.373 (the table of /work/shared/notes/ehl_extensions.md, tested)."""
    if ratio == 1.0:
        return 1.0, 1.0, 1.0
    hz = hertz_point(1.0, 1.0, 1.0 / ratio, 1.5)
    return hz.a, hz.b, hz.max_pressure * 2.0 * math.pi / 3.0


def default_domain(ratio: float = 1.0, H_hertz: float | None = None,
                   enlarge: tuple[float, float] = (1.0, 1.0)) -> Domain:
    """The contact domain in units of the circular contact on R_x (a_c).

    lambda = R_x/R_y = 1: X in [-4.5, 1.5], Y in [-3, 3], square cells (Venner & Lubrecht
    2000); a low-M case whose inlet this truncates is refused by :func:`solve_point`.

    lambda != 1: the domain follows the Hertz ellipse (a, b) = :func:`hertz_ellipse`:
    X in [-x_in a, x_in a / 3], Y in [-3 b, 3 b], and stretched cells hy/hx = b/a, so the
    contact has as many nodes across it in Y as in X and a slender contact costs the same
    as a circular one. The inlet x_in = max(4.5, 1.2 m*), with m* Hamrock & Dowson's (1977)
    fully flooded inlet distance in units of a for the expected central film ``H_hertz``
    (Hertzian units on a_c; converted to a by (a_c/a)^2): at low M and small lambda the
    inlet build-up reaches ~12 a (M = 20, lambda = 0.02). The outlet x_in a / 3 (1.5 a for
    the default inlet) keeps X = 0 on a node of every level (12 of the 16 level-0 intervals
    upstream), so that Hc is read at the centre on every level.

    ``enlarge`` = (fx, fy), for domain-convergence studies (studies/ehl_elliptic_domain.py):
    the inlet times fx and the Y half-width times fy; the outlet is lengthened to the next
    length that keeps X = 0 on a level-0 node (a domain that moves the centre off the nodes
    reads Hc beside the centre: -1.7 % at (20, 10), lambda = 0.1, inlet x2), and the cells
    keep the default's aspect scaled by fy / (length ratio along X), so that the enlarged
    grid one level up per doubling has the default's cells. (1, 1) is the default domain."""
    fx, fy = enlarge
    if not (fx >= 1.0 and fy >= 1.0):
        raise ValueError(f"enlarge factors must be >= 1, got {enlarge!r}")
    if ratio == 1.0:
        d0 = Domain(-4.5, 1.5, -3.0, 3.0)
    else:
        a, b, _ = hertz_ellipse(ratio)
        x_in = 4.5 if H_hertz is None else max(4.5, 1.2 * acc.inlet_distance(H_hertz / a**2))
        d0 = Domain(-x_in * a, x_in * a / 3.0, -3.0 * b, 3.0 * b, aspect=b / a)
    if (fx, fy) == (1.0, 1.0):
        return d0
    x_in = -d0.x0 * fx
    upstream = math.floor(16 * x_in / (x_in + d0.x1) + 1e-9)  # level-0 intervals upstream of X = 0
    x_out = x_in * (16 - upstream) / upstream
    stretch = (x_in + x_out) / (d0.x1 - d0.x0)
    aspect = (1.0 if d0.aspect is None else d0.aspect) * fy / stretch
    return Domain(-x_in, x_out, d0.y0 * fy, d0.y1 * fy, aspect=aspect)


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


def _inlet_problem(dom: Domain, expected: float, ratio: float) -> str | None:
    """The inlet check of :mod:`accuracy` in units of the ellipse's X semi-axis a
    (Hamrock & Dowson's m* is measured in the semi-axis along the rolling direction)."""
    a = hertz_ellipse(ratio)[0]
    return acc.inlet_problem(dom.x0 / a, expected / a**2)


# the rigid film of a slender contact spreads along the contact line to |Y| ~ sqrt(2 H / lambda);
# beyond this fraction of the domain's half-width the default domain truncates it and Hc is off
# (studies/ehl_elliptic_regimes.py, studies/ehl_elliptic_domain.py: (20, 0) at lambda 0.1
# (ratio 0.34) 13 % low, (20, 10) at lambda 0.05 / 0.02 (0.52 / 0.81) 11 / 38 % low, but at
# lambda 0.12-0.1 (0.43) 13-17 % HIGH (the enlarged inlet and sides take load off the centre);
# (100, 10) (<= 0.28) unaffected)
SIDE_EXTENT_MAX = 0.33


def _side_problem(dom: Domain, expected: float, ratio: float) -> str | None:
    """A slender contact whose rigid-film side extent sqrt(2 H / lambda) (H the expected
    central film, Hertzian units) exceeds SIDE_EXTENT_MAX of the domain's Y half-width:
    the solution may be truncated along the contact line (flagged, not refused: the
    criterion is calibrated on a few cases and also flags some that are not truncated).
    The error has either sign: truncation starves the near-rigid film (Hc low, isoviscous
    and very slender cases) or keeps load on the centre that the unbounded domain spreads
    into the inlet and the sides (Hc high at (20, 10), lambda 0.1-0.15; docs/elliptic_regimes.md)."""
    if ratio >= 1.0:
        return None
    r = math.sqrt(2.0 * expected / ratio) / min(-dom.y0, dom.y1)
    if r <= SIDE_EXTENT_MAX:
        return None
    return (f"rigid-film side extent sqrt(2H/lambda) is {r:.2f} of the domain half-width "
            f"(> {SIDE_EXTENT_MAX}): the film may be truncated along the contact line and Hc off "
            "by 10-40 % either way (check with default_domain(..., enlarge=))")


def solve_point(M: float, L: float, *, level: int | None = None, coarse_level: int = 1,
                ratio: float = 1.0, domain: Domain | None = None, viscosity: str = "barus",
                compressible: bool = False, ph: float | None = None, z: float = 0.68,
                rigid: bool = False, ad_factor: float = 1.0, sd_factor: float = 1.0,
                tol: float | None = None, newton_tol: float = 1e-5, max_level: int = MAX_LEVEL,
                residual_tol: float = RESIDUAL_TOL, max_iter: int = 40, method: str = "auto",
                start: EHLResult | None = None, surface=None, reuse: dict | None = None,
                dense_reuse: bool = False) -> EHLResult:
    """Isothermal point-contact EHL in Moes groups (M, L); returns :class:`EHLResult`.

    ``level`` is the finest grid (``16 * 2**level`` intervals along X), ``coarse_level``
    the level solved directly (dense Newton). ``viscosity`` 'barus' (default, with
    incompressible oil: the setting of the published film formulas) or 'roelands'
    (needs ``ph`` [Pa] and ``z``); ``compressible`` switches Dowson-Higginson density
    on (needs ``ph``). The high-load and strong-piezoviscosity fallbacks are described in
    the module docstring. Raises ConvergenceError (with the Newton history) on failure.

    Accuracy: ``tol`` (relative) makes the nested iteration stop at the first level whose
    Richardson estimates of Hc and Hmin (:mod:`accuracy`) are both <= tol, up to
    ``max_level`` (``level``, when given, caps it instead); without ``tol`` the finest
    level is ``level`` (default 3) and the result is flagged against
    :data:`accuracy.DEFAULT_TOL`. The default domain is checked against the fully flooded
    inlet distance for the NVM film: a case whose inlet it would truncate (low M, e.g.
    (3, 10)) raises :class:`SceneError` with the reason; an explicit ``domain`` that
    truncates it is solved and flagged.

    ``method``: 'fas' full multigrid on the FD discretisation of
    :mod:`femgear.ehl.fas_point` (``start=`` a neighbouring point solution warm-starts it;
    ``reuse=`` a dict kept across a sequence of solves adds the secant predictor);
    'newton' the Newton-Krylov FE solver described above (``coarse_level``, ``ad_factor``,
    ``sd_factor``, ``newton_tol``, ``residual_tol`` and ``max_iter`` are its settings: a
    non-default ``ad_factor``/``sd_factor`` selects it); 'auto' (default) multigrid inside
    its validated range (:func:`fas_suits`), Newton elsewhere. A failed multigrid solve
    falls back to Newton; ``history['fallback']`` then holds the reason.

    ``dense_reuse``: the dense Newton steps on the coarse level keep the LU factors of an earlier
    Jacobian of this solve and take GMRES steps preconditioned by them
    (:func:`femgear.ehl.newton.newton_dense` ``reuse=``), refactorising when GMRES needs more
    than 12 iterations; the converged answer is set by the residual test alone.

    ``surface``: stationary roughness R(X, Y) in Hertzian units (:mod:`femgear.ehl.surface`),
    a callable f(X, Y) evaluated on every level's nodes; the film is H0 + G + D - R. None
    (default) leaves the smooth solve untouched. A rough surface is solved by Newton (the
    multigrid has no surface term).
    """
    if M <= 0 or L < 0 or ratio <= 0:
        raise ValueError("need M > 0, L >= 0, ratio > 0")
    if method not in ("auto", "fas", "newton"):
        raise SceneError("method", f"method must be 'auto', 'fas' or 'newton', not {method!r}")
    if tol is not None and not 0.0 < tol < 1.0:
        raise SceneError("tol", f"relative tolerance must lie in (0, 1), got {tol!r}")
    level = (DEFAULT_LEVEL if tol is None else max_level) if level is None else level
    if level < coarse_level:
        raise ValueError("level must be >= coarse_level")
    t0 = time.perf_counter()
    case = f"ehl point M={M:g} L={L:g} ratio={ratio:g} level={level}"
    fac = pr.point_h_moes_factor(M)
    expected = float(nvm_central(M, L, ratio)) / fac
    dom = domain or default_domain(ratio, None if rigid else expected)
    inlet = None if rigid else _inlet_problem(dom, expected, ratio)
    if inlet and domain is None:
        raise SceneError("M", f"(M, L) = ({M:g}, {L:g}): {inlet}; pass a larger domain= "
                         "to solve it anyway (the result is then flagged)")
    rheology = dict(viscosity=viscosity, ph=ph, z=z, compressible=compressible)
    side = None if rigid else _side_problem(dom, expected, ratio)
    flags = tuple(f"domain: {m}" for m in (inlet, side) if m)
    fallback = []
    solver = _NestedPoint(M, L, ratio=ratio, dom=dom, coarse_level=coarse_level, level=level,
                          tol=tol, rigid=rigid, ad_factor=ad_factor, sd_factor=sd_factor, t0=t0,
                          surface=surface, rheology=rheology,
                          newton=dict(max_iter=max_iter, tol=newton_tol, case=case,
                                      residual_tol=residual_tol), dense_reuse=dense_reuse)
    if method == "auto":
        method = "fas" if surface is None and fas_suits(M, L, level, rigid, viscosity, compressible, ratio) else "newton"
    if method == "fas" and surface is not None:
        raise SceneError("method", "the multigrid has no roughness term: use method='newton' or 'auto' "
                         "with surface=")
    if method == "fas" and ad_factor == 1.0 and sd_factor == 1.0:
        try:
            res = solve_point_fas(M, L, level=level, ratio=ratio, dom=dom, rheology=rheology,
                                  rigid=rigid, tol=tol, case=case, t0=t0, start=start,
                                  extra_flags=flags, fallback_start=solver.fas_start, reuse=reuse)
            res.history["method"] = "fas"
            return res
        except ConvergenceError as exc:
            fallback.append(f"fas: {exc}")
    PI, H0, per_level, fine = solver.solve_at(M)
    res = _result("point", M, L, fine, PI, H0, solver.fac, solver.hist, per_level,
                  time.perf_counter() - t0, tol=acc.DEFAULT_TOL if tol is None else tol,
                  extra_flags=flags)
    res.history["method"] = "newton"
    if fallback:
        res.history["fallback"] = fallback
    return res


FAS_ALPHA_MAX = 12.0
# slender ellipses (lambda <= 0.2, stretched cells): the multigrid stays within 1 % of Newton
# up to (100, 10), alpha_bar 16.9 (measured at lambda 0.2, 0.1, 0.05, 0.02 on 129^2: error
# estimates 0.3-1.2 %, 25-60x faster than Newton)
FAS_ALPHA_MAX_SLENDER, SLENDER = 17.0, 0.2
# strongly piezoviscous contacts on 257^2 and finer: the HIGH_ALPHA cycles with the spike
# elimination (fas_point) converge where the FE Newton solver fails or is slow (measured on
# 257^2: (20, 20) 13 cycles and (100, 20) 6 cycles, Newton fails both; (200, 10) 8.8 s against
# Newton's 54 s, Hc/Hmin 1.5/4.4 % apart, inside their flagged estimates; (500, 10) falls back
# to Newton at no extra cost; docs/ehl_multigrid.md)
HIGH_ALPHA_AUTO_LEVEL = 4


def fas_suits(M: float, L: float, level: int, rigid: bool, viscosity: str, compressible: bool,
              ratio: float = 1.0) -> bool:
    """Whether ``method='auto'`` takes the multigrid solver: Barus, incompressible, elastic,
    circular or wide (lambda = R_x/R_y <= 1; at (20, 10) lambda = 0.5 agrees with Newton to
    0.5 %, lambda = 2 stalls on 33^2 and needs the anisotropic grids of slender contacts),
    a finest grid of 129^2 or more (on 65^2 the FD scheme's error, ~3 % at (20, 10), is
    over twice the FE scheme's), and alpha_bar = alpha p_h <= FAS_ALPHA_MAX. Measured
    (benchmark and tests): the multigrid converges in 4-8 cycles per level at (10, 10),
    (20, 10), (20, 5) (alpha_bar 4.9-9.9); at (50, 10), (100, 10) (alpha_bar 13-17) it
    converges on a 33^2 coarsest grid but its 129^2 answer is less accurate than Newton's
    ((100, 10): estimate 4.3 %), so Newton keeps that band. Beyond alpha_bar 17
    (fas_point.HIGH_ALPHA_FROM) the multigrid takes its HIGH_ALPHA cycles: on 129^2 Newton
    converges and stays the choice; on 257^2 and finer (HIGH_ALPHA_AUTO_LEVEL) the multigrid
    with the spike elimination does, because Newton fails there ((20, 20), (100, 20)).
    Slender ellipses on their stretched grids (lambda <= SLENDER) take the multigrid up to
    FAS_ALPHA_MAX_SLENDER."""
    alpha, circular = pr.point_alpha_bar(M, L), ratio > SLENDER
    alpha_max = FAS_ALPHA_MAX if circular else FAS_ALPHA_MAX_SLENDER
    strong = circular and level >= HIGH_ALPHA_AUTO_LEVEL and alpha > HIGH_ALPHA_FROM
    return (viscosity == "barus" and not compressible and not rigid and level >= 3
            and ratio <= 1.0 and (alpha <= alpha_max or strong))


class _NestedPoint:
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
