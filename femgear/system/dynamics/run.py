"""One dynamic run: model → integration → response → modes, as a pure function.

:func:`run_dynamics` takes a built :class:`GearRotorModel` (build once, apply many: the
coupling loop replaces friction and flank deviations with
:func:`femgear.system.dynamics.build.with_friction` / ``with_deviation`` and re-runs) and
returns a frozen :class:`DynamicsRun`.  Files are written at the edge, by
:mod:`femgear.edge.io.dynamics` and :mod:`femgear.edge.plot.dynamics`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from femgear.docfields import document_fields
from femgear.system.dynamics.expo import default_substeps
from femgear.system.dynamics.integrate import Simulation, expo_step, simulate, stability_limit
from femgear.system.dynamics.modal import ModalResult, mesh_mode_limit, modal_analysis
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.response import Amplitudes, Response, analyse

#: Newmark/HHT needs this many times the steps of rk4/expo for the same accuracy (benchmark)
NEWMARK_STEP_FACTOR = 8
#: recorded samples per period of the highest mode that the mesh excitation reaches (0: no floor)
STEPS_PER_MODE_PERIOD = 8


@document_fields
@dataclass(frozen=True)
class DynamicsSettings:
    """Integrator, step and duration of a run (mesh periods)."""

    method: str
    """the time integrator that ran (e.g. ``expo``, ``newmark``) [-]"""
    dt: float
    """time step [s]"""
    cycles: float
    """recorded mesh periods after the transient [mesh periods]"""
    transient_cycles: float
    """mesh periods integrated and discarded before recording [mesh periods]"""


@document_fields
@dataclass(frozen=True)
class DynamicsRun:
    settings: DynamicsSettings
    """integrator, step and duration of the run [-]"""
    simulation: Simulation
    """the recorded time history in reduced coordinates, with its model [-]"""
    response: Response
    """the steady-state response: full-DOF histories, mesh forces, bearing accelerations, amplitudes [-]"""
    modal: ModalResult
    """natural frequencies and mode shapes of the mean system [-]"""

    @property
    def model(self) -> GearRotorModel:
        return self.simulation.model

    @property
    def amplitudes(self) -> Amplitudes:
        """Steady-state amplitudes by name (:func:`femgear.system.dynamics.response.analyse`)."""
        return self.response.amplitudes


def default_method(model: GearRotorModel) -> str:
    """``expo`` for the 12 rigid-member coordinates of ``lumped``, ``rk4`` for ``timoshenko``
    (24 coordinates: expo's 48-state propagators cost more to build than RK4 needs)."""
    return "expo" if model.n <= 12 else "rk4"


def step_plan(model: GearRotorModel, steps_per_period: int = 200) -> tuple[int, int]:
    """(steps per mesh period while recording, steps per mesh period of the transient) of the default step.

    What the response needs, not what the stiffest mode needs:

    - the mesh excitation: ``steps_per_period`` (scene ``numerics.steps_per_mesh_period``,
      200) places the contact-state checks of a backlash or contact-loss event and the
      friction and transmission-error holds on the mesh period — a floor at every speed,
      and all the transient (which only carries the state to the recorded window) gets;
    - the reading: the amplitudes are half peak-to-peak values read from the recorded
      steps by cubic Hermite interpolation with the derivatives, so while recording, the
      highest mode the mesh excitation reaches, f_r
      (:func:`femgear.system.dynamics.modal.mesh_mode_limit`), is sampled
      :data:`STEPS_PER_MODE_PERIOD` = 8 times (the baseline at 300 rpm, read from every
      2nd/3rd/4th sample of a fine run: −0.01 %, −0.02 %, −0.8 % on gear v_y at 12, 8, 6
      samples of its 8.3 kHz mode).  At low speed that mode rings between stiffness
      changes (at 100 rpm, mesh order 161, it holds ~1/5 of the gear's velocity
      amplitude), so it cannot be dropped: this floor grows as 1/speed, as the response's
      own content does.

    The integration sets no floor: ``expo`` is exact for the linear structure over a
    step, and the mesh stiffness is resolved inside it by sub-steps
    (:func:`femgear.system.dynamics.expo.default_substeps`), set-up once per structure rather
    than work per step.  The recording count is a whole multiple r of the transient's,
    r = ⌊need/floor⌋, so that both see the same stiffness staircase (the switch between
    them is seamless).  The rule before (12 samples of the highest mode at all times,
    200 halved: 3200 steps per mesh period at 100 rpm) cost ~4× the steps at 100 rpm.
    """
    floor = int(steps_per_period)
    f_r = mesh_mode_limit(model) if STEPS_PER_MODE_PERIOD else 0.0
    need = max(floor, math.ceil(STEPS_PER_MODE_PERIOD * f_r / model.mesh_frequency - 1e-9))
    r = max(1, need // floor)
    transient = math.ceil(need / r)
    return r * transient, transient


def default_step(model: GearRotorModel, method: str, steps_per_period: int = 200) -> float:
    """The default time step [s] while recording: T_m over the first count of :func:`step_plan`;
    ``rk4`` at most a quarter of its stability limit; ``newmark`` :data:`NEWMARK_STEP_FACTOR` times
    finer.  ``studies/dynamics/step_convergence.py`` prints the change when it is halved and
    ``studies/benchmarks/dynamics_speed.py`` the error against a converged small step."""
    h = model.mesh_period / step_plan(model, steps_per_period)[0]
    if method == "expo":
        return expo_step(model, h)[0]
    if method == "rk4":
        return min(h, 0.25 * stability_limit(model))
    return h / NEWMARK_STEP_FACTOR


def _simulate_default(model: GearRotorModel, cycles: float, transient_cycles: float, steps_per_period: int):
    """``expo`` with the default plan: the transient at its coarser step up to one mesh period before the
    recording starts (same stiffness staircase), then the recording step."""
    per, per_t = step_plan(model, steps_per_period)
    T = model.mesh_period
    switch = math.floor(transient_cycles) - 1
    substeps = default_substeps(model, per)
    if per_t == per or switch < 1:
        return simulate(model, cycles * T, T / per, "expo", substeps=substeps)
    first = simulate(model, switch * T, T / per_t, "expo", substeps=substeps * per // per_t, record_from=switch * T)
    rest = simulate(model, (cycles - switch) * T, T / per, "expo", substeps=substeps, q0=first.q[-1],
                    v0=first.v[-1], record_from=transient_cycles * T, t_start=switch * T)
    return replace(rest, steps=first.steps + rest.steps, seconds=first.seconds + rest.seconds,
                   info={**rest.info, "transient_steps_per_mesh_period": per_t, "transient_steps": first.steps,
                         "setup_seconds": first.info["setup_seconds"] + rest.info["setup_seconds"]})


def run_dynamics(model: GearRotorModel, *, method: str | None = None, dt: float | None = None,
                 cycles: float = 100.0, transient_cycles: float = 50.0, steps_per_period: int = 200,
                 modal: ModalResult | None = None) -> DynamicsRun:
    """Simulate ``cycles`` mesh periods, drop ``transient_cycles`` (paper: 50), analyse.

    ``modal``: the modes of the mean system when already known (they do not depend on
    friction or flank deviations, so the coupling computes them once).
    """
    if not (math.isfinite(cycles) and cycles > transient_cycles >= 0):
        raise ValueError(f"cycles ({cycles}) must exceed transient_cycles ({transient_cycles}) ≥ 0")
    method = method or default_method(model)
    if dt is None and method == "expo":
        sim = _simulate_default(model, cycles, transient_cycles, steps_per_period)
    else:
        step = default_step(model, method, steps_per_period) if dt is None else dt
        sim = simulate(model, cycles * model.mesh_period, step, method)
    return DynamicsRun(settings=DynamicsSettings(method, sim.dt, cycles, transient_cycles), simulation=sim,
                       response=analyse(sim, transient_cycles), modal=modal or modal_analysis(model))
