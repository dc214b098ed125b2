"""Files of the whine analyses: the order sweep (``dynamics_sweep.json``/``.npz``, PNGs) and the run-up
(``runup.json``/``.npz``, PNGs).

No VTK: both results are curves and maps over speed and order, with no field on a body to show; the
time histories and maps are in the ``.npz`` files.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from femgear.edge.io.dynamics import _save_npz
from femgear.edge.io.results import write_json
from femgear.system.dynamics.modal import resonance_marks


def order_sweep_summary(sw, modal) -> dict[str, Any]:
    """The JSON of an order sweep: per speed the method, DTE RMS and mesh-order amplitudes (SI), the modes and the
    resonances in range, the hand-off warnings."""
    marks = resonance_marks(modal.frequencies, modal.energy["mesh"], float(sw.mesh_frequency.min()),
                            float(sw.mesh_frequency.max()), harmonics=len(sw.orders))
    return {"speed_rpm": sw.speed_rpm, "mesh_frequency": sw.mesh_frequency, "dte_rms": sw.dte_rms,
            "method": list(sw.method), "orders": sw.orders, "mesh_force_mean": sw.mesh_force_mean,
            "mesh_force_orders": sw.mesh_force,
            "bearing_force_orders": sw.bearing_force, "contact_margin": sw.contact_margin,
            "warnings": list(sw.warnings), "natural_frequencies_hz": modal.frequencies,
            "mesh_energy": modal.energy["mesh"],
            "resonances": [{"mesh_frequency": x, "harmonic": k, "natural_frequency": f} for x, k, f in marks]}


def write_order_sweep(sw, modal, folder: str | Path, plots: bool = True, name: str = "") -> dict[str, Path]:
    """``dynamics_sweep.json``, ``dynamics_sweep.npz`` and (``plots``) ``dynamics_sweep.png`` (DTE RMS) and
    ``dynamics_orders.png`` (mesh-order amplitudes) in ``folder``."""
    folder = Path(folder)
    files = {"json": write_json(folder / "dynamics_sweep.json", order_sweep_summary(sw, modal)),
             "npz": _save_npz(folder / "dynamics_sweep.npz", speed_rpm=sw.speed_rpm, mesh_frequency=sw.mesh_frequency,
                              dte_rms=sw.dte_rms, orders=sw.orders, mesh_force_mean=sw.mesh_force_mean,
                              mesh_force=sw.mesh_force,
                              bearing_force=sw.bearing_force, contact_margin=sw.contact_margin,
                              harmonic=np.array([m == "harmonic" for m in sw.method]))}
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.dynamics import plot_sweep
        from femgear.edge.plot.nvh import plot_order_sweep

        files["sweep"] = save_figure(plot_sweep(sw, modal, name=name), folder / "dynamics_sweep.png")
        files["orders"] = save_figure(plot_order_sweep(sw, modal, name=name), folder / "dynamics_orders.png")
    return files


def runup_summary(run, maps: dict, steady: np.ndarray | None) -> dict[str, Any]:
    """The JSON of a run-up: the ramp, the integration, the mesh-order cuts of each tracked signal against the blocks'
    speeds, and the stepped steady state (harmonic balance) of the mesh force beside them."""
    out = {"start_rpm": float(run.speed[0]), "end_rpm": float(run.speed[-1]),
           "duration": float(run.ramp_end - run.settle_time), "settle_time": float(run.settle_time), "dt": run.dt,
           "steps": run.steps, "seconds": run.seconds, "pinion_teeth": run.teeth,
           "block_speed_rpm": next(iter(maps.values())).speed,
           "mesh_orders": next(iter(maps.values())).mesh_orders, "revolutions": next(iter(maps.values())).revolutions,
           "cuts": {key: m.cuts for key, m in maps.items()}}
    if steady is not None:
        out["steady_mesh_force_orders"] = steady
    return out


def write_runup(run, maps: dict, steady: np.ndarray | None, folder: str | Path, plots: bool = True,
                name: str = "") -> dict[str, Path]:
    """``runup.json``, ``runup.npz`` (the histories and the waterfalls) and (``plots``) ``runup.png`` (mesh force)
    and ``runup_bearing.png`` (the bearing-load component with the largest first mesh order) in ``folder``."""
    folder = Path(folder)
    arrays = {"t": run.t, "speed": run.speed, "pinion_revolutions": run.pinion_revolutions,
              "mesh_force": run.mesh_force, "dte": run.dte, "bearing_force": run.bearing_force}
    for key, m in maps.items():
        arrays |= {f"{key}.orders": m.orders, f"{key}.speed": m.speed, f"{key}.amplitude": m.amplitude,
                   f"{key}.cuts": m.cuts}
    files = {"json": write_json(folder / "runup.json", runup_summary(run, maps, steady)),
             "npz": _save_npz(folder / "runup.npz", **arrays)}
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.nvh import plot_runup

        files["runup"] = save_figure(plot_runup(run, maps["mesh_force"], steady, name=name), folder / "runup.png")
        b = maps["bearing_force"]
        j, d = np.unravel_index(np.argmax(b.cuts[:, 0].max(axis=0)), b.cuts.shape[2:])
        station = ("pinion_L", "pinion_R", "gear_L", "gear_R")[j]
        sub = type(b)(orders=b.orders, speed=b.speed, amplitude=b.amplitude[..., j, d], mesh_orders=b.mesh_orders,
                      cuts=b.cuts[..., j, d], revolutions=b.revolutions)
        files["runup_bearing"] = save_figure(
            plot_runup(run, sub, None, name=name, what=f"bearing load {station} {'xyz'[d]}"),
            folder / "runup_bearing.png")
    return files
