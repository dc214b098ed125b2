"""Results files of a dynamic run: a JSON summary and an NPZ of the time histories."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from femgear.dynamics.integrate import Simulation
from femgear.dynamics.response import Response


def summary(sim: Simulation, res: Response) -> dict:
    """Plain-JSON summary: settings, amplitudes (half peak-to-peak, SI), timings."""
    m = sim.model
    return {
        "level": m.level,
        "method": sim.method,
        "dt": sim.dt,
        "steps": sim.steps,
        "seconds": sim.seconds,
        "mesh_frequency": m.mesh_frequency,
        "stiffness": m.stiffness.label,
        "mean_mesh_stiffness": list(m.stiffness.mean),
        "friction_coefficient": m.mu,
        "rayleigh": list(m.rayleigh),
        "mesh_damping": m.mesh_damping.tolist(),
        "natural_frequencies_hz": m.info.get("flexible_modes_hz", []),
        "amplitudes": res.amplitudes,
    }


def write_results(sim: Simulation, res: Response, folder) -> dict[str, Path]:
    """Write ``dynamics.json`` and ``dynamics.npz`` into ``folder``; returns their paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    js = folder / "dynamics.json"
    js.write_text(json.dumps(summary(sim, res), indent=1), encoding="utf-8")
    npz = folder / "dynamics.npz"
    np.savez_compressed(npz, t=res.t, displacement=res.displacement, velocity=res.velocity, delta=res.delta,
                        mesh_force=res.mesh_force, bearing_acceleration=res.bearing_acceleration)
    return {"json": js, "npz": npz}
