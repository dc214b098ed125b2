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

#: default steps per mesh period of ``expo`` (converged to < 0.5 % in amplitudes, see the benchmark)
EXPO_STEPS_PER_PERIOD = 200
#: the paper's RK4 step [s]
RK4_STEP = 1e-5


@dataclass(frozen=True)
class DynamicsRun:
    simulation: Simulation
    response: Response
    modal: ModalResult
    summary: dict
    files: dict = field(default_factory=dict)


def default_step(model, method: str) -> float:
    """``expo``: 1/200 of the mesh period; ``rk4``: the paper's 1e-5 s, or 0.9× the stability
    limit if that is smaller; ``newmark``: 1/400 of the mesh period."""
    if method == "expo":
        return expo_step(model, model.mesh_period / EXPO_STEPS_PER_PERIOD)[0]
    if method == "rk4":
        return min(RK4_STEP, 0.9 * stability_limit(model))
    return model.mesh_period / 400


def run_dynamics(scene, out: str | Path | None = None, *, level: str | None = None, stiffness=None,
                 method: str | None = None, dt: float | None = None, cycles: float = 100.0,
                 transient_cycles: float = 50.0, plots: bool = True, **build_kw) -> DynamicsRun:
    """Simulate ``cycles`` mesh periods, drop ``transient_cycles`` (paper: 50), analyse, write files.

    ``out``: folder for ``dynamics.json``/``dynamics.npz`` and PNG plots (None: nothing written).
    ``method``: default ``expo`` for the 12 rigid-member coordinates of ``lumped`` and ``rk4``
    for ``timoshenko`` (24 coordinates: expo's 48-state propagators cost more to build than
    RK4 needs to run 100 mesh periods).
    """
    if not cycles > transient_cycles >= 0:
        raise ValueError(f"cycles ({cycles}) must exceed transient_cycles ({transient_cycles}) ≥ 0")
    model = build_model(scene, level, stiffness=stiffness, **build_kw)
    if method is None:
        method = "expo" if model.n <= 12 else "rk4"
    step = default_step(model, method) if dt is None else dt
    sim = simulate(model, cycles * model.mesh_period, step, method)
    res = analyse(sim, transient_cycles)
    modal = modal_analysis(model)
    from femgear.dynamics.output import summary, write_results

    info = summary(sim, res)
    info["modes"] = [{"frequency_hz": float(f), "dominant": modal.dominant_group(i), "mesh_energy": float(modal.energy["mesh"][i])}
                     for i, f in enumerate(modal.frequencies)]
    files: dict = {}
    if out is not None:
        files.update(write_results(sim, res, out))
        if plots:
            from femgear.dynamics import plot

            out = Path(out)
            files["time_histories"] = plot.plot_time_histories(res, out / "dynamics_time.png")
            files["mesh_force"] = plot.plot_mesh_force(res, out / "dynamics_mesh_force.png")
            files["phase_planes"] = plot.plot_phase_planes(res, out / "dynamics_phase.png")
            files["spectra"] = plot.plot_spectra(res, out / "dynamics_spectra.png")
    return DynamicsRun(simulation=sim, response=res, modal=modal, summary=info, files=files)
