"""One dynamic run: model → integration → response → modes, as a pure function.

:func:`run_dynamics` takes a built :class:`GearRotorModel` (build once, apply many: the
coupling loop replaces friction and flank deviations with
:func:`femgear.dynamics.build.with_friction` / ``with_deviation`` and re-runs) and
returns a frozen :class:`DynamicsRun`.  Files are written at the edge, by
:mod:`femgear.io.dynamics` and :mod:`femgear.dynamics.plot`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.dynamics.integrate import Simulation, expo_step, simulate, stability_limit
from femgear.dynamics.modal import ModalResult, modal_analysis
from femgear.dynamics.model import GearRotorModel
from femgear.dynamics.response import Amplitudes, Response, analyse

#: Newmark/HHT needs this many times the steps of rk4/expo for the same accuracy (benchmark)
NEWMARK_STEP_FACTOR = 8
#: samples per period of the highest flexible mode that the default step resolves
STEPS_PER_MODE_PERIOD = 12


@dataclass(frozen=True)
class DynamicsSettings:
    """Integrator, step and duration of a run (mesh periods)."""

    method: str
    dt: float
    cycles: float
    transient_cycles: float


@dataclass(frozen=True)
class DynamicsRun:
    settings: DynamicsSettings
    simulation: Simulation
    response: Response
    modal: ModalResult

    @property
    def model(self) -> GearRotorModel:
        return self.simulation.model

    @property
    def amplitudes(self) -> Amplitudes:
        """Steady-state amplitudes by name (:func:`femgear.dynamics.response.analyse`)."""
        return self.response.amplitudes


def default_method(model: GearRotorModel) -> str:
    """``expo`` for the 12 rigid-member coordinates of ``lumped``, ``rk4`` for ``timoshenko``
    (24 coordinates: expo's 48-state propagators cost more to build than RK4 needs)."""
    return "expo" if model.n <= 12 else "rk4"


def default_step(model: GearRotorModel, method: str, steps_per_period: int = 200) -> float:
    """The default time step [s].

    T_m/``steps_per_period`` halved until it is at most 1/(:data:`STEPS_PER_MODE_PERIOD`
    f_max), f_max the highest flexible mode of the mean system: the amplitudes are read
    from the recorded steps, and at low speed the mesh modes that stiffness steps and
    contact switches excite ring between them (at 100 rpm, 200 steps per mesh period
    sample the 8 kHz mode 1.3 times per period: the velocity amplitudes moved 21 % when
    the step was halved).  Halving (not an arbitrary fraction) keeps ``expo``'s stiffness
    sub-sampling of the mesh period the same, so the table is seen alike at h and h/2.
    ``studies/step_convergence.py`` prints the change when the default step is halved.  ``rk4`` at most a quarter of its stability limit;
    ``newmark`` :data:`NEWMARK_STEP_FACTOR` times finer.
    """
    h = model.mesh_period / steps_per_period
    if STEPS_PER_MODE_PERIOD and model.flexible_modes_hz:     # halve until the highest mode is resolved
        h_mode = 1.0 / (STEPS_PER_MODE_PERIOD * max(model.flexible_modes_hz))
        h /= 2 ** max(0, math.ceil(math.log2(h / h_mode)))
    if method == "expo":
        return expo_step(model, h)[0]
    if method == "rk4":
        return min(h, 0.25 * stability_limit(model))
    return h / NEWMARK_STEP_FACTOR


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
    step = default_step(model, method, steps_per_period) if dt is None else dt
    sim = simulate(model, cycles * model.mesh_period, step, method)
    return DynamicsRun(settings=DynamicsSettings(method, sim.dt, cycles, transient_cycles), simulation=sim,
                       response=analyse(sim, transient_cycles), modal=modal or modal_analysis(model))
