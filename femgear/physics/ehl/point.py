"""Point (circular / elliptical) contact EHL: the entry that picks a discretisation.

:func:`solve_point` checks the domain (:mod:`femgear.physics.ehl.core.domain`) and solves by
full multigrid on the FD discretisation (:mod:`femgear.physics.ehl.fd.point`) inside its
validated range (:func:`fas_suits`), else, or when the multigrid fails, by the FE
Newton-Krylov nested iteration (:mod:`femgear.physics.ehl.fe.point`, whose docstring describes
its high-load and strong-piezoviscosity fallbacks).
Inputs are Moes groups (Venner & Lubrecht 2000 scaling, see :mod:`femgear.physics.ehl.core.params`); the
ellipticity ``ratio`` is lambda = R_x/R_y (geometry X^2/2 + lambda Y^2/2, as in
Nijenbanning, Venner & Moes 1994).
"""

from __future__ import annotations

import time

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import check_inlet, check_sides, default_domain
from femgear.physics.ehl.core.grid import Domain
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.fd.point import HIGH_ALPHA_FROM, solve_point_fas
from femgear.physics.ehl.fe.point import NestedPoint

DEFAULT_LEVEL = 3  # 129^2
# Newton stops after a full step onto this scaled residual (or a relative step < newton_tol):
# 1e-8 moves Hc and Hmin by < 1e-7 relative, far below any grid's discretisation error
RESIDUAL_TOL = 1e-8
MAX_LEVEL = 5  # 513^2: the finest grid a tol-driven solve may reach


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
    on (needs ``ph``). The Newton solver's high-load and strong-piezoviscosity fallbacks are
    described in :mod:`femgear.physics.ehl.fe.point`. Raises ConvergenceError (with the Newton history) on failure.

    Accuracy: ``tol`` (relative) makes the nested iteration stop at the first level whose
    Richardson estimates of Hc and Hmin (:mod:`accuracy`) are both <= tol, up to
    ``max_level`` (``level``, when given, caps it instead); without ``tol`` the finest
    level is ``level`` (default 3) and the result is flagged against
    :data:`accuracy.DEFAULT_TOL`. The default domain is checked against the fully flooded
    inlet distance for the NVM film: a case whose inlet it would truncate (low M, e.g.
    (3, 10)) raises :class:`SceneError` with the reason; an explicit ``domain`` that
    truncates it is solved and flagged.

    ``method``: 'fas' full multigrid on the FD discretisation of
    :mod:`femgear.physics.ehl.fd.point` (``start=`` a neighbouring point solution warm-starts it;
    ``reuse=`` a dict kept across a sequence of solves adds the secant predictor);
    'newton' the Newton-Krylov FE solver described above (``coarse_level``, ``ad_factor``,
    ``sd_factor``, ``newton_tol``, ``residual_tol`` and ``max_iter`` are its settings: a
    non-default ``ad_factor``/``sd_factor`` selects it); 'auto' (default) multigrid inside
    its validated range (:func:`fas_suits`), Newton elsewhere. A failed multigrid solve
    falls back to Newton; ``history['fallback']`` then holds the reason.

    ``dense_reuse``: the dense Newton steps on the coarse level keep the LU factors of an earlier Jacobian of
    this solve and take GMRES steps preconditioned by them (:func:`femgear.physics.ehl.fe.newton.newton_dense`
    ``reuse=``), refactorising when GMRES needs more than 12 iterations; the answer is set by the residual test.

    ``surface``: stationary roughness R(X, Y) in Hertzian units (:mod:`femgear.physics.ehl.core.surface`),
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
    inlet = None if rigid else check_inlet(dom, expected, ratio)
    if inlet and domain is None:
        raise SceneError("M", f"(M, L) = ({M:g}, {L:g}): {inlet}; pass a larger domain= "
                         "to solve it anyway (the result is then flagged)")
    rheology = dict(viscosity=viscosity, ph=ph, z=z, compressible=compressible)
    side = None if rigid else check_sides(dom, expected, ratio)
    flags = tuple(f"domain: {m}" for m in (inlet, side) if m)
    fallback = []
    solver = NestedPoint(M, L, ratio=ratio, dom=dom, coarse_level=coarse_level, level=level,
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
    res = solver.result(PI, H0, per_level, fine, time.perf_counter() - t0,
                        tol=acc.DEFAULT_TOL if tol is None else tol, extra_flags=flags)
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
# elimination (fd.point) converge where the FE Newton solver fails or is slow (measured on
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
    (fd.point.HIGH_ALPHA_FROM) the multigrid takes its HIGH_ALPHA cycles: on 129^2 Newton
    converges and stays the choice; on 257^2 and finer (HIGH_ALPHA_AUTO_LEVEL) the multigrid
    with the spike elimination does, because Newton fails there ((20, 20), (100, 20)).
    Slender ellipses on their stretched grids (lambda <= SLENDER) take the multigrid up to
    FAS_ALPHA_MAX_SLENDER."""
    alpha, circular = pr.point_alpha_bar(M, L), ratio > SLENDER
    alpha_max = FAS_ALPHA_MAX if circular else FAS_ALPHA_MAX_SLENDER
    strong = circular and level >= HIGH_ALPHA_AUTO_LEVEL and alpha > HIGH_ALPHA_FROM
    return (viscosity == "barus" and not compressible and not rigid and level >= 3
            and ratio <= 1.0 and (alpha <= alpha_max or strong))
