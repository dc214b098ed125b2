"""The bidirectional tribo-dynamic loop (the paper's Fig. 9) as a generator of states.

One iteration:

1. flank deviations → the drive- and coast-flank deviation tables of each helix over
   one mesh period (:mod:`femgear.system.coupling.profile`): wear h1 + h2 acts on the loaded
   (drive) flanks only, thermal expansion ζ_T1 + ζ_T2 on both; each enters the
   dynamics once (:class:`femgear.system.dynamics.model.MeshDeviation`).  With the ``ltca``
   stiffness level the drive flanks' deviations instead re-run the loaded tooth contact
   analysis on the worn and expanded topography (the compliance is reused), whose loaded
   TE excites the dynamics (:func:`femgear.system.dynamics.build.with_deviated_tooth_contact`);
   the coast flanks keep the contact-line mean of −ζ_T;
2. dynamics with the mesh stiffness, μ(u) and those deviations → the dynamic mesh
   force of each helix over one mesh period (phase average of the steady state);
3. load sharing along the contact lines → passage-mean load intensity w̄'(u): a Winkler
   layer c_l(u) on the flank deviations, or with ``ltca`` the load distribution of the
   pass's (deviated) LTCA cycle scaled to the dynamic force
   (:func:`femgear.system.coupling.setup.ltca_reference`);
4. lubrication at every path position (load, radius, entrainment, slide-to-roll,
   bulk temperature: the supply temperature plus the previous pass's bulk flank rise of step 5,
   :func:`femgear.levels.lubrication.bulk_temperature`) → μ(u) and the contact temperature rise ΔT(u);
5. thermal expansion of both flanks for the bulk (body) temperature rise
   (:func:`femgear.system.coupling.thermal.bulk_temperature_rise`: the scene's ``thermal.flank_temperature_rise``, or,
   when that is 0, ``thermal.bulk_fraction`` × the mean contact temperature rise along
   the path, the ISO/TS 6336-21 integral-temperature estimate) → ζ_T1, ζ_T2;
6. Archard wear after ``wear.cycles`` under the dynamic load → h1, h2 (with ``ltca``: the
   load shared like the unworn LTCA cycle, modifications included, moved by the wear grown
   by the Winkler layer, :func:`femgear.physics.wear.load_sharing.reference_loads`; or blended
   towards the pass's cycle, :attr:`~femgear.system.coupling.setup.CouplingSetup.wear_anchor`);
7. relaxation of the inputs of the next iteration (μ, ζ_T, h) by ``relax``.

Build once, apply many: the dynamic model, its modes, the thermal unit responses and
the lubrication solver are built once per case (:class:`~femgear.system.coupling.setup.CouplingSetup`);
each pass (the pure functions of :mod:`femgear.system.coupling.passes`) replaces only friction
and deviations.  The states are immutable (:mod:`femgear.system.coupling.state`); stopping,
relaxation policy and logging stay with the caller (:func:`run_coupled` is the standard one: it
stops when the dynamic mesh force and μ change by less than their tolerances and
raises with the history otherwise).
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable, Iterator
from dataclasses import replace

import numpy as np

from femgear.errors import ConvergenceError
from femgear.perf import Progress
from femgear.system.coupling.passes import contact_response, pass_dynamics, pass_thermal, pass_wear, reference_loads
from femgear.system.coupling.setup import CouplingSetup
from femgear.system.coupling.state import CoupledResult, CouplingHistory, CouplingState

log = logging.getLogger(__name__)

#: the loop's tolerance on the dynamic mesh force between two passes, relative (the paper's 1e-6) [-]
TOL_FORCE = 1e-6
#: the loop's tolerance on μ between two passes, absolute [-]
TOL_MU = 1e-6
#: passes after which a loop that has not converged raises [-]
MAX_PASSES = 30
#: the passes whose every second pair agrees that make a two-state alternation [-]
ALTERNATION_PASSES = 4


def coupling_iterations(setup: CouplingSetup, relax: float = 1.0) -> Iterator[CouplingState]:
    """Yield the quasi-static start (iteration 0) and then one state per pass of the loop."""
    if not 0 < relax <= 1:
        raise ValueError(f"relax must be in (0, 1] (got {relax!r})")
    t0 = time.perf_counter()
    force = np.full((2, setup.n_phase), setup.static_force)
    zero = np.zeros((2, setup.kin.u.size))
    ref_wear, ref_contact = reference_loads(setup, setup.ltca, zero, zero)
    wear, face = pass_wear(setup, force, ref_wear)
    w, mu, dT = contact_response(setup, force, wear.sum(axis=0), ref_contact, setup.case.thermal.flank_temperature_rise)
    rise, zeta, zeta_face = pass_thermal(setup, dT)
    state = CouplingState(iteration=0, mesh_force=force, load_per_length=w, mu=mu, temperature_rise=dT,
                          flank_temperature_rise=rise, thermal_deviation=zeta, wear=wear,
                          seconds=time.perf_counter() - t0, wear_face=face, thermal_face=zeta_face)
    yield state
    while True:
        t0 = time.perf_counter()
        force, run, cycle, deviated = pass_dynamics(setup, state)
        t1 = time.perf_counter()
        ref_wear, ref_contact = reference_loads(setup, cycle, state.wear, state.thermal_deviation, state.wear_face,
                                                state.thermal_face)
        wear_new, face_new = pass_wear(setup, force, ref_wear)
        t2 = time.perf_counter()
        w, mu_new, dT = contact_response(setup, force, state.removed, ref_contact, state.flank_temperature_rise)
        rise, zeta_new, zeta_face = pass_thermal(setup, dT)
        mix = lambda old, new: old + relax * (new - old)  # noqa: E731
        lte = math.nan if cycle is None else cycle.lte_peak_to_peak
        rerun = 0.0 if cycle is None or cycle is setup.ltca else cycle.seconds
        timings = {"ltca": rerun, "dynamics": t1 - t0, "wear": t2 - t1, "contact": time.perf_counter() - t2}
        state = replace(
            state, iteration=state.iteration + 1, mesh_force=force, load_per_length=w, mu=mix(state.mu, mu_new),
            temperature_rise=dT, flank_temperature_rise=rise, thermal_deviation=mix(state.thermal_deviation, zeta_new),
            wear=mix(state.wear, wear_new),
            mesh_force_change=_force_change(force, state.mesh_force),
            mu_change=float(np.max(np.abs(mu_new - state.mu))), dynamics=run, lte_peak_to_peak=lte,
            seconds=time.perf_counter() - t0, timings=timings,
            wear_face=None if face_new is None else mix(state.wear_face, face_new),
            thermal_face=None if zeta_face is None else mix(state.thermal_face, zeta_face), deviated=deviated)
        for name, value in (("mesh_force", force), ("mu", state.mu), ("wear", state.wear)):
            if not np.all(np.isfinite(value)):
                raise ConvergenceError("coupling", f"non-finite {name} in iteration {state.iteration}")
        yield state



def _force_change(new: np.ndarray, old: np.ndarray) -> float:
    """The loop's mesh-force change: max |new − old| relative to max |new|."""
    return float(np.max(np.abs(new - old)) / np.max(np.abs(new)))


def _same(a: CouplingState, b: CouplingState, tol_force: float, tol_mu: float) -> bool:
    """Whether two passes agree to the loop's tolerances (mesh force relative, μ absolute)."""
    return _force_change(a.mesh_force, b.mesh_force) < tol_force and float(np.max(np.abs(a.mu - b.mu))) < tol_mu


def run_coupled(setup: CouplingSetup, tol_force: float = TOL_FORCE, tol_mu: float = TOL_MU, max_iter: int = MAX_PASSES,
                relax: float = 1.0, one_way: bool = False,
                progress: Callable[[CouplingState], None] | None = None) -> CoupledResult:
    """Iterate to convergence; ``one_way`` stops after the first dynamic pass.

    ``progress``: called with every state (logging, progress display) as it arrives.

    Converged when the dynamic mesh force changes by less than ``tol_force`` (relative,
    paper: 1e-6) and μ by less than ``tol_mu`` between two passes.  A loop that instead alternates
    between two states (each of two successive passes within the tolerances of the pass before the
    last, over :data:`ALTERNATION_PASSES` passes) stops there with a warning and the difference of the two
    states in :attr:`CoupledResult.alternation`: a map with a jump (a contact switch of the discrete LTCA)
    cannot converge below it (the measured case: docs/validation/coupling.md).  Raises
    :class:`ConvergenceError` carrying the history after ``max_iter`` passes.
    """
    history: dict[str, list] = {"iteration": [], "mesh_force_change": [], "mu_change": [], "seconds": []}
    start = time.perf_counter()
    passes: list[CouplingState] = []
    lines = Progress(f"coupling of scene {setup.case.name!r}", None)     # shown once the loop has run 10 s

    def done(state: CouplingState, alternation: tuple[float, float] | None = None) -> CoupledResult:
        return CoupledResult(state, CouplingHistory(**{k: tuple(v) for k, v in history.items()}), True,
                             time.perf_counter() - start, alternation)

    for state in coupling_iterations(setup, relax):
        history["iteration"].append(state.iteration)
        history["mesh_force_change"].append(state.mesh_force_change)
        history["mu_change"].append(state.mu_change)
        history["seconds"].append(state.seconds)
        if progress is not None:
            progress(state)
        lines(state.iteration, f"pass {state.iteration} done in {state.seconds:.1f} s, mesh-force change "
                               f"{state.mesh_force_change:.3g}, μ change {state.mu_change:.3g}" if state.iteration else
                               f"quasi-static start done in {state.seconds:.1f} s")
        if state.iteration == 0:
            continue
        if one_way or (state.mesh_force_change < tol_force and state.mu_change < tol_mu):
            return done(state)
        passes = [*passes[1 - ALTERNATION_PASSES:], state]
        if len(passes) == ALTERNATION_PASSES and all(_same(passes[k], passes[k - 2], tol_force, tol_mu)
                                                     for k in range(2, ALTERNATION_PASSES)):
            log.warning(f"coupling of scene {setup.case.name!r}: passes {state.iteration - 3}-{state.iteration} "
                        f"alternate between two states (mesh force {state.mesh_force_change:.2g} relative, μ "
                        f"{state.mu_change:.2g} apart; a contact switch of the discrete LTCA): the last is the "
                        "result, their difference its uncertainty (summary.coupling.alternation)")
            return done(state, (state.mesh_force_change, state.mu_change))
        if state.iteration >= max_iter:
            raise ConvergenceError(
                f"coupling of scene {setup.case.name!r}",
                f"no convergence in {max_iter} iterations (tolerances {tol_force:g}, {tol_mu:g})", history)
    raise AssertionError("unreachable")  # pragma: no cover
