"""The bidirectional tribo-dynamic loop (the paper's Fig. 9) as a generator of states.

One iteration:

1. flank deviations (wear h1 + h2 minus thermal expansion ζ_T1 + ζ_T2) → profile
   excitation e_L, e_R and dynamic backlash b(t) over one mesh period
   (:mod:`femgear.coupling.profile`);
2. dynamics with the mesh stiffness, μ(u) and those excitations → the dynamic mesh
   force of each helix over one mesh period (phase average of the steady state);
3. load sharing along the contact lines → passage-mean load intensity w̄'(u);
4. lubrication at every path position (load, radius, entrainment, slide-to-roll,
   bulk temperature) → μ(u) and the contact temperature rise ΔT(u);
5. thermal expansion of both flanks for the flank temperature (the scene's
   ``thermal.flank_temperature_rise``, or, when that is 0, the mean contact temperature
   rise along the path, as the paper's Δf(t)) → ζ_T1, ζ_T2;
6. Archard wear after ``wear.cycles`` under the dynamic load → h1, h2;
7. relaxation of the inputs of the next iteration (μ, ζ_T, h) by ``relax``.

The states are immutable; stopping, relaxation policy and logging stay with the caller
(:func:`run_coupled` is the standard one: it stops when the dynamic mesh force and μ
change by less than their tolerances and raises with the history otherwise).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

import numpy as np

from femgear.coupling.profile import excitation_tables
from femgear.errors import ConvergenceError
from femgear.geometry import GearPair, PathKinematics, kinematics, path_positions
from femgear.wear.load_sharing import load_map

Lubrication = Callable[..., tuple[np.ndarray, np.ndarray]]
"""solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise) — the signature of friction maps."""


@dataclass(frozen=True)
class CouplingSetup:
    """What stays fixed over the iterations of one load case."""

    scene: object
    pair: GearPair
    kin: PathKinematics           #: positions u along the path (pitch point included)
    stiffness: object             #: mesh stiffness table of the scene's level (computed once)
    lubrication: Lubrication
    c_l: float                    #: mesh stiffness per unit contact-line length [N/m²]
    static_force: float           #: normal force per helix [N]
    n_phase: int = 128
    method: str | None = None     #: integrator; None: the dynamics' default for the scene

    @classmethod
    def from_scene(cls, scene, n_path: int = 61, n_phase: int = 128, lubrication: Lubrication | None = None,
                   method: str | None = None) -> CouplingSetup:
        from femgear.contact.path import normal_force, pinion_speed
        from femgear.stiffness.tvms import mesh_stiffness_from_scene

        pair = GearPair.from_scene(scene)
        u = np.unique(np.append(path_positions(pair, n_path), pair.u_pitch))
        kin = kinematics(pair, u, pinion_speed(scene) * 2 * math.pi / 60)
        stiffness = mesh_stiffness_from_scene(scene)
        c_l = float(np.mean(stiffness.k_left)) / pair.mean_contact_length
        F0 = normal_force(scene, pair) / 2
        return cls(scene=scene, pair=pair, kin=kin, stiffness=stiffness,
                   lubrication=lubrication or lubrication_solver(scene), c_l=c_l, static_force=F0,
                   n_phase=n_phase, method=method)


def lubrication_solver(scene) -> Lubrication:
    """The contact solver of the scene's ``physics.lubrication`` level, map signature.

    ``none``/``constant``: μ = 0 / ``friction.coefficient``, no heating; ``formula``: thermal
    Eyring traction of the Hertzian film (:mod:`femgear.lubrication`); ``ehl-line``: FE line
    EHL with Eyring traction and Blok's flash temperature (:mod:`femgear.ehl.path`); ``tehl``:
    a friction map of thermal EHL solves (:func:`femgear.tehl.solver.tehl_map_solver`).
    """
    level = scene.physics.lubrication
    if level in ("none", "constant"):
        mu0 = 0.0 if level == "none" else scene.friction.coefficient

        def constant(w, R, ue, srr, T):
            shape = np.broadcast(w, R, ue, srr, T).shape
            return np.full(shape, mu0), np.zeros(shape)

        return constant
    if level == "ehl-line":
        from femgear.ehl.path import ehl_line_solver

        return ehl_line_solver(scene)
    if level == "tehl":
        from femgear.tehl.solver import tehl_map_solver

        return tehl_map_solver(scene)
    from femgear.lubrication.map import hertz_level_solver

    return hertz_level_solver(scene)


@dataclass(frozen=True)
class CouplingState:
    """The loop after ``iteration`` passes; arrays over the path positions unless noted."""

    iteration: int
    mesh_force: np.ndarray          #: (2, n_phase) dynamic mesh force per helix over one mesh period [N]
    load_per_length: np.ndarray     #: passage-mean w̄' [N/m]
    mu: np.ndarray                  #: friction coefficient [-]
    temperature_rise: np.ndarray    #: contact (oil) temperature rise [K]
    flank_temperature_rise: float   #: used for the thermal expansion [K]
    thermal_deviation: np.ndarray   #: (2, n) ζ_T of pinion and gear [m]
    wear: np.ndarray                #: (2, n) wear depth of pinion and gear [m]
    change: dict = field(default_factory=dict)   #: 'mesh_force' (relative), 'mu' (absolute) vs previous
    amplitudes: dict = field(default_factory=dict)
    dynamics: object = field(default=None, repr=False, compare=False)   #: the pass's DynamicsRun
    seconds: float = 0.0

    @property
    def removed(self) -> np.ndarray:
        """Flank material removed at each position, h1 + h2 − ζ_T1 − ζ_T2 [m]."""
        return self.wear.sum(axis=0) - self.thermal_deviation.sum(axis=0)


def _contact_response(setup: CouplingSetup, force: np.ndarray, removed: np.ndarray):
    """w̄'(u) for per-helix forces over the mesh phases, then μ, ΔT from the lubrication."""
    pair, kin = setup.pair, setup.kin
    maps = [load_map(pair, kin.u, force[s], removed, setup.c_l, offset=off)
            for s, off in enumerate((0.0, setup.scene.pair.stagger))]
    w = 0.5 * (maps[0].mean_load + maps[1].mean_load)
    w = np.maximum(w, 1e-3 * setup.static_force / pair.mean_contact_length)   # never-loaded ends
    T0 = setup.scene.operating.ambient_temperature
    mu, dT = setup.lubrication(w=w, R=kin.R, ue=kin.ue, srr=np.abs(kin.srr), T=np.full(w.shape, T0))
    return w, np.asarray(mu, dtype=float), np.asarray(dT, dtype=float)


def _thermal(setup: CouplingSetup, dT: np.ndarray) -> tuple[float, np.ndarray]:
    scene = setup.scene
    n = setup.kin.u.size
    if scene.physics.thermal == "none":
        return 0.0, np.zeros((2, n))
    from femgear.body.thermal import flank_deviation

    rise = scene.thermal.flank_temperature_rise or float(np.mean(dT))
    m = scene.material
    dev = [flank_deviation(setup.pair, member, setup.kin.u, scene.physics.thermal, rise,
                           scene.thermal.shaft_temperature_rise, m.thermal_expansion, m.youngs_modulus,
                           m.poisson_ratio, m.conductivity, bore, scene.thermal.mesh_size)
           for member, bore in ((1, scene.pinion.bore_radius), (2, scene.gear.bore_radius))]
    return rise, np.array(dev)


def _wear(setup: CouplingSetup, force: np.ndarray) -> np.ndarray:
    scene = setup.scene
    n = setup.kin.u.size
    if scene.physics.wear == "none" or scene.wear.cycles == 0:
        return np.zeros((2, n))
    from femgear.wear import WearSetup, run_wear

    ws = WearSetup(pair=setup.pair, kin=setup.kin, force=force.mean(axis=0), c_l=setup.c_l,
                   coefficient=scene.wear.coefficient, hardness=scene.material.hardness, n_phase=setup.n_phase)
    state = run_wear(ws, scene.wear.cycles)
    return np.array([state.h1, state.h2])


def _dynamics(setup: CouplingSetup, state: CouplingState):
    """Dynamic mesh force per helix over one mesh period for the inputs in ``state``."""
    from femgear.dynamics.run import run_dynamics

    (eL, eR), db = excitation_tables(setup.pair, setup.kin.u, state.removed, setup.scene.pair.stagger, setup.n_phase)
    u_tab, mu_tab = setup.kin.u, state.mu
    mu = (lambda u: np.interp(u, u_tab, mu_tab)) if np.any(mu_tab > 0) else 0.0
    run = run_dynamics(setup.scene, None, stiffness=setup.stiffness, method=setup.method, plots=False,
                       friction_coefficient=mu, profile_deviation=(eL, eR), backlash_variation=db)
    return phase_average(run.response, setup.n_phase), run


def phase_average(res, n_phase: int) -> np.ndarray:
    """Mesh force per helix averaged over the recorded mesh periods, at phases i/n_phase.

    Samples are binned by mesh phase (at most as many bins as samples per period, so
    no bin is empty) and the bin means interpolated periodically onto the n_phase grid.
    """
    phase = np.mod(res.t * res.mesh_frequency, 1.0)
    per_period = res.t.size / max(res.mesh_frequency * (res.t[-1] - res.t[0]), 1.0)
    n_bins = int(min(n_phase, np.floor(per_period)))
    if n_bins < 8:
        raise ValueError(f"too few recorded samples per mesh period ({per_period:.1f}) for the phase average")
    bins = np.minimum((phase * n_bins).astype(int), n_bins - 1)
    count = np.bincount(bins, minlength=n_bins)
    centres = (np.arange(n_bins) + 0.5) / n_bins
    grid = np.arange(n_phase) / n_phase
    out = []
    for s in range(2):
        mean = np.bincount(bins, res.mesh_force[:, s], n_bins) / np.maximum(count, 1)
        ok = count > 0
        out.append(np.interp(grid, centres[ok], mean[ok], period=1.0))
    return np.array(out)


def coupling_iterations(setup: CouplingSetup, relax: float = 1.0) -> Iterator[CouplingState]:
    """Yield the quasi-static start (iteration 0) and then one state per pass of the loop."""
    if not 0 < relax <= 1:
        raise ValueError(f"relax must be in (0, 1] (got {relax!r})")
    t0 = time.perf_counter()
    force = np.full((2, setup.n_phase), setup.static_force)
    wear = _wear(setup, force)
    w, mu, dT = _contact_response(setup, force, wear.sum(axis=0))
    rise, zeta = _thermal(setup, dT)
    state = CouplingState(0, force, w, mu, dT, rise, zeta, wear, seconds=time.perf_counter() - t0)
    yield state
    while True:
        t0 = time.perf_counter()
        force, run = _dynamics(setup, state)
        wear_new = _wear(setup, force)
        w, mu_new, dT = _contact_response(setup, force, state.removed)
        rise, zeta_new = _thermal(setup, dT)
        mix = lambda old, new: old + relax * (new - old)  # noqa: E731
        change = {
            "mesh_force": float(np.max(np.abs(force - state.mesh_force)) / np.max(np.abs(force))),
            "mu": float(np.max(np.abs(mu_new - state.mu))),
        }
        state = CouplingState(state.iteration + 1, force, w, mix(state.mu, mu_new), dT, rise,
                              mix(state.thermal_deviation, zeta_new), mix(state.wear, wear_new), change,
                              run.summary["amplitudes"], run, time.perf_counter() - t0)
        for name, value in (("mesh_force", force), ("mu", state.mu), ("wear", state.wear)):
            if not np.all(np.isfinite(value)):
                raise ConvergenceError("coupling", f"non-finite {name} in iteration {state.iteration}")
        yield state


@dataclass(frozen=True)
class CoupledResult:
    state: CouplingState
    history: dict
    converged: bool
    seconds: float


def run_coupled(setup: CouplingSetup, tol_force: float = 1e-6, tol_mu: float = 1e-6, max_iter: int = 30,
                relax: float = 1.0, one_way: bool = False) -> CoupledResult:
    """Iterate to convergence; ``one_way`` stops after the first dynamic pass.

    Converged when the dynamic mesh force changes by less than ``tol_force`` (relative,
    paper: 1e-6) and μ by less than ``tol_mu`` between two passes.  Raises
    :class:`ConvergenceError` carrying the history after ``max_iter`` passes.
    """
    history: dict[str, list] = {"iteration": [], "mesh_force_change": [], "mu_change": [], "seconds": []}
    start = time.perf_counter()
    for state in coupling_iterations(setup, relax):
        history["iteration"].append(state.iteration)
        history["mesh_force_change"].append(state.change.get("mesh_force", float("nan")))
        history["mu_change"].append(state.change.get("mu", float("nan")))
        history["seconds"].append(state.seconds)
        if state.iteration == 0:
            continue
        if one_way:
            return CoupledResult(state, history, True, time.perf_counter() - start)
        if state.change["mesh_force"] < tol_force and state.change["mu"] < tol_mu:
            return CoupledResult(state, history, True, time.perf_counter() - start)
        if state.iteration >= max_iter:
            raise ConvergenceError(
                f"coupling of scene {setup.scene.meta.name!r}",
                f"no convergence in {max_iter} iterations (tolerances {tol_force:g}, {tol_mu:g})", history)
    raise AssertionError("unreachable")  # pragma: no cover

