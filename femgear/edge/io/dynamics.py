"""Results files of a dynamic run: ``dynamics.json`` (summary) and ``dynamics.npz`` (time histories: ``t``,
``displacement``, ``velocity``, ``delta``, ``mesh_force``, ``bearing_acceleration`` and ``bearing_force``, the
(n_t, 4, 3) loads of the bearing stations [N])."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from femgear.edge.io.atomic import write_bytes_atomic
from femgear.edge.io.results import write_json
from femgear.system.dynamics.bearings import BearingLoads
from femgear.system.dynamics.orders import Sidebands
from femgear.system.dynamics.run import DynamicsRun


def dynamics_summary(run: DynamicsRun) -> dict[str, Any]:
    """The JSON summary of a run: settings, amplitudes (half peak-to-peak, SI), modes, timings.

    ``friction_factor`` is the factor on the model's friction tables: the constant μ of a constant friction, or 1
    where μ(u) of the lubrication level is folded into the tables (that μ is ``summary.friction`` of
    ``results.json``, labelled with its level); it is not a second friction coefficient."""
    m, sim, modal = run.model, run.simulation, run.modal
    return {
        "level": m.level,
        "method": sim.method,
        "dt": sim.dt,
        "steps": sim.steps,
        "seconds": sim.seconds,
        "mesh_frequency": m.mesh_frequency,
        "stiffness": m.stiffness.label,
        "mean_mesh_stiffness": list(m.stiffness.mean),
        "friction_factor": m.mu,
        "rayleigh": list(m.rayleigh),
        "mesh_damping": m.mesh_damping.tolist(),
        "natural_frequencies_hz": list(m.flexible_modes_hz),
        "amplitudes": dict(run.amplitudes),
        "modes": [{"frequency_hz": float(f), "dominant": modal.dominant_group(i),
                   "mesh_energy": float(modal.energy["mesh"][i])} for i, f in enumerate(modal.frequencies)],
        **({} if run.response.bearings is None else {"bearing_forces": bearing_summary(run.response.bearings)}),
        **({"sidebands": {sb.member: sideband_summary(sb, run.response) for sb in run.response.sidebands}}
           if run.response.sidebands else {}),
    }


def sideband_summary(sb: Sidebands, res) -> dict[str, Any]:
    """``sidebands.<member>``: the lines k f_m + j f_s of the member (f_s its shaft frequency) per signal
    (``dte`` [m], ``mesh_force_L/R`` [N], ``bearing_<station>_x/y`` [N]): ``lines`` (K rows of mesh orders
    ``mesh_orders``, columns of sideband orders ``sides``, 0 the mesh order itself), ``shaft_orders`` (j f_s,
    j = 1 … J); amplitudes are half peak-to-peak.  A record shorter than one revolution of the member reports
    ``resolved: false`` with the mesh periods a revolution needs."""
    out: dict[str, Any] = {"shaft_frequency_hz": sb.shaft_frequency, "resolved": sb.revolutions > 0,
                           "revolutions": sb.revolutions, "mesh_orders": list(sb.mesh_orders), "sides": list(sb.sides)}
    if not sb.revolutions:
        recorded = float((res.t[-1] - res.t[0]) * res.mesh_frequency)
        out.update(needs_mesh_periods=round(res.mesh_frequency / sb.shaft_frequency), recorded_mesh_periods=recorded)
        return out
    out["lines"] = {k: v.tolist() for k, v in sb.lines.items()}
    out["shaft_orders"] = {k: v.tolist() for k, v in sb.shaft_orders.items()}
    return out


def bearing_summary(loads: BearingLoads) -> dict[str, Any]:
    """``bearing_forces`` of the summary: per station the load of the shaft on the bearing along x, y (radial) and
    z (axial) over the recorded mesh cycles: ``mean``, ``peak_to_peak`` and ``mesh_orders`` (amplitude, half
    peak-to-peak, of mesh orders 1, 2, … per axis), and ``radial_mean`` (√(F̄x² + F̄y²)); all in N."""
    out: dict[str, Any] = {"axes": ["x", "y", "z"], "units": "N"}
    for j, name in enumerate(loads.stations):
        out[name] = {"mean": loads.mean[j].tolist(), "peak_to_peak": loads.peak_to_peak[j].tolist(),
                     "radial_mean": float(loads.radial_mean[j]), "mesh_orders": loads.orders[:, j].tolist()}
    return out


def _save_npz(path: Path, **arrays: np.ndarray) -> Path:
    """``np.savez`` (uncompressed: the recorded float histories compress by ~10 % only, and zlib took
    ~0.85 s of the 100 rpm main job) through :func:`femgear.edge.io.atomic.write_bytes_atomic` (fsync, rename, 0644)."""
    import io

    buf = io.BytesIO()
    np.savez(buf, **arrays)
    return write_bytes_atomic(path, buf.getvalue())


def write_dynamics(run: DynamicsRun, folder: str | Path, plots: bool = True, name: str = "") -> dict[str, Path]:
    """Write ``dynamics.json``, ``dynamics.npz`` (and the PNG figures, titled with the scene ``name``) into
    ``folder``."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    res = run.response
    extra = {} if res.bearings is None else {"bearing_force": res.bearings.force}
    files = {
        "json": write_json(folder / "dynamics.json", dynamics_summary(run)),
        "npz": _save_npz(folder / "dynamics.npz", t=res.t, displacement=res.displacement, velocity=res.velocity,
                         delta=res.delta, mesh_force=res.mesh_force, bearing_acceleration=res.bearing_acceleration,
                         **extra),
    }
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot import dynamics as plot

        name = f"{name} ({run.model.level}, {run.model.stiffness.label} stiffness)" if name else ""
        files["time_histories"] = save_figure(plot.plot_time_histories(res, name=name), folder / "dynamics_time.png")
        files["mesh_force"] = save_figure(plot.plot_mesh_force(res, name=name), folder / "dynamics_mesh_force.png")
        files["phase_planes"] = save_figure(plot.plot_phase_planes(res, name=name), folder / "dynamics_phase.png")
        files["spectra"] = save_figure(plot.plot_spectra(res, name=name), folder / "dynamics_spectra.png")
        if res.bearings is not None:
            files["bearing_forces"] = save_figure(plot.plot_bearing_forces(res, name=name),
                                                  folder / "dynamics_bearings.png")
    return files
