"""Files of the housing layer: ``housing.json`` (the sweep as amplitudes), ``housing.npz`` (its complex
amplitudes), ``housing_orders.png`` and, for the FE housing, ``housing_ods.pvd`` (the operating deflection shape,
one period in 16 phases), and the ``summary.housing`` of ``results.json``."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import numpy as np

from femgear.edge.io.atomic import write_bytes_atomic
from femgear.edge.io.results import write_json
from femgear.system.dynamics.housing_result import HousingResult

#: phases of the deflection shape's ParaView time series
ODS_PHASES = 16
#: relative Craig–Bampton error in the retained band above which summary.housing.reduction_check is flagged
REDUCTION_TOLERANCE = 0.01


def _levels(h: HousingResult) -> dict[str, Any]:
    op, s = h.operating, h.sweep
    if op.sound_power is None:
        return {}
    from femgear.physics.housing.acoustics import a_weighting, power_level, total_level

    lw = power_level(op.sound_power)
    return {"sound_power_level": lw, "sound_power_level_total": float(power_level(op.sound_power.sum())),
            "sound_power_level_a": float(total_level(lw + a_weighting(op.frequency))),
            "sweep_max_sound_power_level": float(np.max(s.overall_sound_power_level)),
            "sweep_max_sound_power_level_speed": float(s.speeds[int(np.argmax(s.overall_sound_power_level))])}


def housing_summary(h: HousingResult) -> dict[str, Any]:
    """``summary.housing``: the model and its coupling, natural frequencies (first 12), the operating point's
    orders (sensor acceleration amplitudes per order and sensor, sound power levels), the sweep's maxima and the
    housing's effect on the bearing and mesh forces against a rigid housing; SI (levels in dB re 1 pW)."""
    op, s = h.operating, h.sweep
    change = s.force_change()
    a = np.abs(np.where(s.valid[..., None], s.sensor_acceleration, 0.0))
    out: dict[str, Any] = {
        "model": h.model, "coupling": h.coupling, "sensors": list(h.sensors),
        "rigid_natural_frequencies": h.rigid_natural_frequencies[:12],
        "linear_valid": h.linear_valid,
        "operating": {"pinion_rpm": op.speed, "source": op.source, "frequency": op.frequency,
                      "sensor_acceleration": np.abs(op.sensor_acceleration),
                      "bearing_force_radial": np.linalg.norm(op.bearing_force[..., :2], axis=-1), **_levels(h)},
        "sweep": {"pinion_rpm": [float(s.speeds[0]), float(s.speeds[-1])], "points": int(s.speeds.size),
                  "orders": int(s.frequency.shape[1]), "lines_valid": int(s.valid.sum()),
                  "max_sensor_acceleration": a.max(axis=(0, 1)),
                  "max_sensor_acceleration_rpm": s.speeds[a.max(axis=1).argmax(axis=0)]},
        "force_change": {k: {"median": float(np.median(v)), "p90": float(np.percentile(v, 90)), "max": float(v.max())}
                         for k, v in change.items() if v.size},
    }
    if h.ignored_inputs:
        out["ignored_inputs"] = list(h.ignored_inputs)
    if h.natural_frequencies is not None:
        out.update(natural_frequencies=h.natural_frequencies[:12], housing_frequencies=h.housing_frequencies[:12],
                   fixed_interface_modes=int(h.fixed_interface_hz.size),
                   fixed_interface_max_hz=float(h.fixed_interface_hz.max()) if h.fixed_interface_hz.size else 0.0,
                   full_dofs=h.full_dofs, housing_mass=h.housing_mass, surface_area=h.surface_area,
                   sensor_points=h.sensor_points, sensor_directions=h.sensor_directions)
    c = h.reduction_check
    if c is not None:
        out["reduction_check"] = {"band_hz": c.band, "modes_in_band": int(c.full.size), "max_error": c.max_error,
                                  "flagged": bool(c.max_error > REDUCTION_TOLERANCE)}
    return out


def _npz(path: Path, **arrays) -> Path:
    buf = io.BytesIO()
    np.savez(buf, **arrays)
    return write_bytes_atomic(path, buf.getvalue())


def ods_frames(h: HousingResult):
    """The deflection shape as :data:`ODS_PHASES` frames over one period: ``displacement`` Re(U e^{iφ}) [m],
    ``normal_velocity`` Re(v_n e^{iφ}) [m/s], ``amplitude`` |U| [m]."""
    import meshio

    from femgear.edge.io.paraview import Frame

    d = h.ods
    frames = []
    for k in range(ODS_PHASES):
        rot = np.exp(2j * np.pi * k / ODS_PHASES)
        mesh = meshio.Mesh(h.points.T, [("tetra", h.cells.T)],
                           point_data={"displacement": (d.displacement * rot).real,
                                       "normal_velocity": (d.normal_velocity * rot).real,
                                       "amplitude": np.linalg.norm(np.abs(d.displacement), axis=1)})
        frames.append(Frame(time=k / (ODS_PHASES * d.frequency), part=0, name="housing", mesh=mesh))
    return frames


def write_housing(h: HousingResult, out_dir: str | Path, plots: bool = True, vtk: bool = True,
                  name: str = "") -> dict[str, Path]:
    """Write the housing layer's files into ``out_dir``; returns them by name."""
    out_dir = Path(out_dir)
    s = h.sweep
    files = {"housing_json": write_json(out_dir / "housing.json", {
        "sensors": list(h.sensors), "pinion_rpm": s.speeds, "frequency": s.frequency, "valid": s.valid,
        "sensor_acceleration": np.abs(s.sensor_acceleration), "bearing_force": np.abs(s.bearing_force),
        "rigid_bearing_force": np.abs(s.rigid_bearing_force), "mesh_force": np.abs(s.mesh_force),
        "rigid_mesh_force": np.abs(s.rigid_mesh_force),
        **({} if s.sound_power is None else {"sound_power": s.sound_power, "sound_power_level": s.sound_power_level,
                                            "overall_sound_power_level": s.overall_sound_power_level,
                                            "overall_a_weighted": s.overall_a_weighted}),
        "units": {"pinion_rpm": "rev/min", "frequency": "Hz", "sensor_acceleration": "m/s^2", "bearing_force": "N",
                  "mesh_force": "N", "sound_power": "W", "sound_power_level": "dB re 1 pW"}}),
        "housing_npz": _npz(out_dir / "housing.npz", pinion_rpm=s.speeds, frequency=s.frequency, valid=s.valid,
                            sensor_acceleration=s.sensor_acceleration, bearing_force=s.bearing_force,
                            rigid_bearing_force=s.rigid_bearing_force, mesh_force=s.mesh_force,
                            rigid_mesh_force=s.rigid_mesh_force)}
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.housing import plot_housing_orders

        files["housing_orders_png"] = save_figure(plot_housing_orders(h, name=name), out_dir / "housing_orders.png")
    if vtk and h.ods is not None:
        from femgear.edge.io.paraview import collection_files, write_collection

        pvd = write_collection(out_dir, "housing_ods", ods_frames(h))
        files["housing_ods_pvd"] = pvd
        files.update({str(f.relative_to(out_dir)): f for f in collection_files(pvd)})
    return files
