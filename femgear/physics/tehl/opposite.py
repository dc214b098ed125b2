"""Thermal EHL of a line contact whose surfaces move in opposite directions, down to zero entrainment.

At u_e = (v1 + v2)/2 = 0 the reduced Reynolds equation has no wedge at all (its Couette flux ρ u_e h
vanishes), and no isothermal film exists.  The film that forms (Dyson & Wilson 1968; Kaneta's
interferometry, with a central dimple) is carried by the temperature-viscosity wedge of the generalised
Reynolds equation (:mod:`femgear.physics.tehl.generalised`): the oil entering with the forward surface on
one side and with the backward one on the other is heated as it passes, so that on each half of the contact
the colder, more viscous layer lies on the side of the surface that brought it, the Couette flux q_c
points from both ends towards the centre and its convergence builds the pressure (Yang, Cui, Kaneta &
Kyogoku 2001, *J. Tribol.* 123:36: line contacts at slide-roll ratios up to infinity; "the contact
surfaces take a shape of concave in the middle, and the concavity increases with increasing load but
decreases with increasing surface velocity", Yang et al.'s abstract of the same analysis in *Tribology*
(China)).

Solve: the Reynolds equation is scaled with the half speed difference U = (v1 − v2)/2 (its Moes M, L,
the isothermal start: pure rolling at U), on a domain symmetric about the centre (the oil enters from both
ends).  Continuation in the entrainment from the contact with the backward surface at rest (u_e = U,
the :func:`femgear.physics.tehl.line.solve_tehl_line` envelope's SRR = 2 corner) down to the requested
u_e, on the coarsest thermal level, with the step halved where a stage fails; then the thermal levels up
to the isothermal solve's and beyond until the Richardson estimate of h_c and h_min meets ``tol``.  The
energy transport is upwinded by the sign of each layer's flux (:func:`femgear.physics.tehl.energy.solve_energy`):
at u_e = 0 the layers by surface 1 flow forward and those by surface 2 backward everywhere.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.fd.line import DEFAULT_TOL, MAX_LEVEL, LineProblem, _level_of, solve_line_fd
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.tehl.energy import ThermalProps
from femgear.physics.tehl.line import (
    MIN_THERMAL_LEVEL,
    THERMAL_LEVELS,
    TEHLResult,
    _Contact,
    _domain_of,
    _inject,
    _rheology,
    _Run,
)

#: the smallest continuation step in the entrainment (a fraction of the half speed difference U) before the
#: solve gives up and raises with its history
MIN_STEP = 1.0 / 64.0
STAGE_TOL = 1.0   #: the thermal tolerance of the continuation's intermediate stages [K]


def solve_tehl_opposite(w: float, R: float, v1: float, v2: float, T_bulk: float, oil: OilLaw, E_red: float,
                        props: ThermalProps, *, model: str = "eyring", tau0: float = 5e6,
                        limiting_shear: float = 0.0, tol: float = DEFAULT_TOL, max_level: int = MAX_LEVEL,
                        nz: int = 16, compressible: bool = True, thermal_tol: float = 0.1, relax: float = 0.8,
                        max_iter: int = 100, max_rise: float = 400.0, max_step: float = 25.0) -> TEHLResult:
    """Thermal EHL line contact with surface 1 moving forward at ``v1`` > 0 and surface 2 backward at ``v2`` < 0
    (or surface 2 forward, v2 > 0 > v1: the bodies swapped), v1 + v2 ≥ 0 (entrainment u_e = (v1 + v2)/2 from 0 to
    below the half speed difference, where the surfaces move apart; at and above it use
    :func:`femgear.physics.tehl.line.solve_tehl_line`): load per length
    ``w`` [N/m], reduced radius ``R`` [m], bulk temperature ``T_bulk`` [K]; the other arguments as
    :func:`~femgear.physics.tehl.line.solve_tehl_line`.  The result's ``hc_isothermal`` is the isothermal film of
    the scaling contact (pure rolling at U = (v1 − v2)/2), the isothermal film at u_e = 0 being nil.  Raises
    :class:`ConvergenceError` with the history when the continuation stalls (module docstring)."""
    for name, v in (("w", w), ("R", R), ("T_bulk", T_bulk), ("E_red", E_red)):
        if not (v > 0 and math.isfinite(v)):
            raise ValueError(f"{name} must be positive and finite (got {v!r})")
    opts = dict(model=model, tau0=tau0, limiting_shear=limiting_shear, tol=tol, max_level=max_level, nz=nz,
                compressible=compressible, thermal_tol=thermal_tol, relax=relax, max_iter=max_iter,
                max_rise=max_rise, max_step=max_step)
    if math.isfinite(v1) and math.isfinite(v2) and v1 < 0 < v2 and v1 + v2 >= 0:
        # surface 2 forward: the same contact with the bodies swapped (the film mirrored across its thickness)
        swapped = replace(props, B1=props.B2, B2=props.B1, k1=props.k2, k2=props.k1)
        return _swap_bodies(solve_tehl_opposite(w, R, v2, v1, T_bulk, oil, E_red, swapped, **opts))
    if not (v1 > 0 > v2 and math.isfinite(v1) and math.isfinite(v2) and v1 + v2 >= 0):
        raise ValueError(f"v1, v2 must have opposite signs with v1 + v2 >= 0 (got v1={v1!r}, v2={v2!r}): opposite "
                         "sliding (a negative entrainment is the mirror image: negate both speeds)")
    U, ue = 0.5 * (v1 - v2), 0.5 * (v1 + v2)
    case = f"tehl opposite w={w:.4g} R={R:.4g} v1={v1:.4g} v2={v2:.4g} T={T_bulk:.4g}"

    def flow(s: float) -> tuple[float, float]:
        u = ue + s * (U - ue)
        return u + U, u - U
    return solve_continued(w, R, U, T_bulk, oil, E_red, props, flow, case, symmetric=True, **opts)


def _swap_bodies(r: TEHLResult) -> TEHLResult:
    """The result of a contact solved with its bodies swapped, in the original bodies' terms."""
    heat = {**r.heat, "solid1": r.heat["solid2"], "solid2": r.heat["solid1"]}
    return replace(r, mu_couette=-r.mu_couette, tau=-r.tau, T_film=r.T_film[:, ::-1], T_surface1=r.T_surface2,
                   T_surface2=r.T_surface1, heat=heat)


def solve_continued(w: float, R: float, u_ref: float, T_bulk: float, oil: OilLaw, E_red: float, props: ThermalProps,
                    flow, case: str, *, symmetric: bool = False,
                    model: str = "eyring", tau0: float = 5e6, limiting_shear: float = 0.0, tol: float = DEFAULT_TOL,
                    max_level: int = MAX_LEVEL, nz: int = 16, compressible: bool = True, thermal_tol: float = 0.1,
                    relax: float = 0.8, max_iter: int = 100, max_rise: float = 400.0,
                    max_step: float = 25.0) -> TEHLResult:
    """The thermal line contact of load ``w`` [N/m] and radius ``R`` [m] whose Reynolds equation is scaled with the
    speed ``u_ref`` [m/s] (its Moes M, L and isothermal start: rolling at u_ref), continued along the surface speeds
    ``flow(s)`` = (v1, v2) [m/s] from s = 1 to the answer at s = 0 (:func:`_continue`), with the generalised
    Reynolds equation, then refined to ``tol``; ``symmetric``: the domain mirrored about the centre (the oil
    entering at both ends).  Also the continuation in the slide of a contact whose loop fails from the isothermal
    start (``studies/ehl/tehl_runaway.py``)."""
    t0 = time.perf_counter()
    c = _Contact.of(w, R, u_ref, 0.0, T_bulk, oil, E_red, compressible)
    factory = _rheology(c, oil, compressible)
    ehl = c.ehl_oil
    kw = dict(tol=tol, max_level=max_level, viscosity=ehl.viscosity, ph=c.ph, compressible=compressible,
              z=ehl.roelands_z() if ehl.viscosity == "roelands" else 0.68, rheology_factory=factory)
    reuse: dict = {}
    iso = solve_line_fd(c.M, c.L, reuse=reuse, **kw)
    if symmetric:
        x0 = _domain_of(iso).x0
        iso = solve_line_fd(c.M, c.L, x0=x0, x1=-x0, reuse=reuse, **kw)
    t_iso = time.perf_counter() - t0
    prob = LineProblem(c.M, c.L, _domain_of(iso), {}, rheology_factory=factory)
    top = _level_of(iso)
    opts = dict(model=model, tau0=tau0, limiting_shear=limiting_shear, heat=True)
    loop = dict(thermal_tol=thermal_tol, relax=relax, max_iter=max_iter, max_rise=max_rise, max_step=max_step)
    run = _Run(prob, c, oil, props, opts, loop, nz, reuse, case, (top, iso.P[1:-1], float(iso.H0)),
               (oil, compressible))
    k = max(top - THERMAL_LEVELS + 1, MIN_THERMAL_LEVEL)
    try:
        state = _continue(run, c, k, _inject(iso, prob, k), flow)
    except ConvergenceError as exc:
        if k >= top:
            raise
        # the coarsest thermal level's loop did not settle (as in solve_tehl_line): the continuation one level up
        run.history["continuation"].append({"level": k, "reason": f"skipped: {str(exc)[:160]}"})
        k += 1
        run.last = None
        state = _continue(run, c, k, _inject(iso, prob, k), flow)
    del run.summaries[:-1]      # the continuation's stages: only the last is a thermal level of the estimate
    est = {"Hc": None, "Hmin": None}
    while True:
        if len(run.summaries) >= 2:
            est = acc.error_estimate(run.summaries[-THERMAL_LEVELS:])
        if k >= max_level or (k >= top and len(run.summaries) >= THERMAL_LEVELS and all(
                e is not None and e <= tol for e in est.values())):
            break
        k += 1
        state = run.level(k, state)
    return run.result(iso, t0, t_iso, est)


def _continue(run: _Run, c: _Contact, k: int, state, flow):
    """The thermal loop on level ``k`` along the speeds ``flow(s)``, s from 1 to 0, the step in s halved where a
    stage fails (down to :data:`MIN_STEP`); the last state."""
    s = s_good = 1.0
    ds = 0.5
    good = None
    tol = run.loop["thermal_tol"]
    while True:
        run.c = replace(c, flow=flow(s))
        # the stages before the last are starting points only: their loops stop at STAGE_TOL
        run.loop = {**run.loop, "thermal_tol": tol if s <= 0.0 else max(tol, STAGE_TOL)}
        try:
            state = run.level(k, state if good is None else good)
        except ConvergenceError as exc:
            if good is None or ds <= MIN_STEP:
                raise ConvergenceError(run.case, f"continuation stalled at the speeds "
                                       f"{run.c.speeds[0]:.4g}, {run.c.speeds[1]:.4g} m/s: "
                                       f"{exc}", run.history) from exc
            v1, v2 = run.c.speeds
            run.history["continuation"].append({"level": k, "reason": f"speeds {v1:.4g}, {v2:.4g} m/s failed; "
                                                "step halved"})
            ds *= 0.5
            s = max(s_good - ds, 0.0)
            continue
        good, s_good = state, s
        if s <= 0.0:
            return state
        s = max(s - ds, 0.0)
