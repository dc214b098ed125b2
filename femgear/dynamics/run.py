"""One dynamic run of a scene: model → integration → response → modal → files.

:func:`run_dynamics` is what ``femgear dynamics`` (and ``femgear run`` when a scene asks
for ``physics.dynamics``) calls; it returns a frozen :class:`DynamicsRun`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from femgear.dynamics.integrate import Simulation, expo_step, simulate, stability_limit
from femgear.dynamics.modal import ModalResult, modal_analysis
from femgear.dynamics.model import build_model
from femgear.dynamics.response import Response, analyse

#: Newmark/HHT needs this many times the steps of rk4/expo for the same accuracy (benchmark)
NEWMARK_STEP_FACTOR = 8


@dataclass(frozen=True)
class DynamicsRun:
    simulation: Simulation
    response: Response
    modal: ModalResult
    summary: dict
    files: dict = field(default_factory=dict)


def default_step(model, method: str, steps_per_period: int = 200) -> float:
    """The step for ``steps_per_period`` steps per mesh period (200: amplitudes converged to
    < 0.5 % at 500 rpm, see the benchmark); ``rk4`` at most a quarter of its stability limit,
    so that the highest mesh modes stay resolved at low speed (long mesh periods), where
    accelerations would otherwise depend on the step; ``newmark``
    :data:`NEWMARK_STEP_FACTOR` times finer."""
    h = model.mesh_period / steps_per_period
    if method == "expo":
        return expo_step(model, h)[0]
    if method == "rk4":
        return min(h, 0.25 * stability_limit(model))
    return h / NEWMARK_STEP_FACTOR


def run_dynamics(scene, out: str | Path | None = None, *, level: str | None = None, stiffness=None,
                 method: str | None = None, dt: float | None = None, cycles: float | None = None,
                 transient_cycles: float | None = None, plots: bool = True, **build_kw) -> DynamicsRun:
    """Simulate ``cycles`` mesh periods, drop ``transient_cycles`` (paper: 50), analyse, write files.

    ``out``: folder for ``dynamics.json``/``dynamics.npz`` and PNG plots (None: nothing written).
    ``method``: default ``expo`` for the 12 rigid-member coordinates of ``lumped`` and ``rk4``
    for ``timoshenko`` (24 coordinates: expo's 48-state propagators cost more to build than
    RK4 needs to run 100 mesh periods).
    """
    num = scene.numerics
    cycles = num.dynamics_cycles if cycles is None else cycles
    transient_cycles = num.transient_cycles if transient_cycles is None else transient_cycles
    if not cycles > transient_cycles >= 0:
        raise ValueError(f"cycles ({cycles}) must exceed transient_cycles ({transient_cycles}) ≥ 0")
    model = build_model(scene, level, stiffness=stiffness, **build_kw)
    method = method or num.dynamics_method or ("expo" if model.n <= 12 else "rk4")
    step = default_step(model, method, num.steps_per_mesh_period) if dt is None else dt
    sim = simulate(model, cycles * model.mesh_period, step, method)
    res = analyse(sim, transient_cycles)
    modal = modal_analysis(model)
    from femgear.dynamics.output import summary

    info = summary(sim, res)
    info["modes"] = [{"frequency_hz": float(f), "dominant": modal.dominant_group(i), "mesh_energy": float(modal.energy["mesh"][i])}
                     for i, f in enumerate(modal.frequencies)]
    run = DynamicsRun(simulation=sim, response=res, modal=modal, summary=info)
    return write_outputs(run, out, plots) if out is not None else run


def write_outputs(run: DynamicsRun, out: str | Path, plots: bool = True) -> DynamicsRun:
    """Write the results files (and PNGs) of ``run`` into ``out``; returns it with ``files`` set."""
    from femgear.dynamics.output import write_results

    out = Path(out)
    files = dict(write_results(run.simulation, run.response, out))
    if plots:
        from femgear.dynamics import plot

        res = run.response
        files["time_histories"] = plot.plot_time_histories(res, out / "dynamics_time.png")
        files["mesh_force"] = plot.plot_mesh_force(res, out / "dynamics_mesh_force.png")
        files["phase_planes"] = plot.plot_phase_planes(res, out / "dynamics_phase.png")
        files["spectra"] = plot.plot_spectra(res, out / "dynamics_spectra.png")
    return DynamicsRun(simulation=run.simulation, response=run.response, modal=run.modal, summary=run.summary,
                       files=files)
