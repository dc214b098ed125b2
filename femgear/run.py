"""``femgear run``: run what a scene's ``[physics]`` asks for and write its outputs.

Always: the quasi-static geometry and contact pass along the path of contact (Hertz
pressure, film thickness, sliding) and the mesh stiffness of the ``stiffness`` level.

Without dynamics (``dynamics = "none"``), the sub-models run once at the static load:
friction and contact temperature from the ``lubrication`` level (``none``, ``constant``
μ, or ``formula``: thermal Eyring traction of the Hertzian film, :mod:`femgear.lubrication`),
the thermal flank deviation (``thermal``) for ``thermal.flank_temperature_rise`` and
the wear depth after ``wear.cycles`` (``wear = "archard"``).

With dynamics, everything goes through the coupling loop of :mod:`femgear.coupling`:
``coupling = "one-way"`` stops after the first dynamic pass (static load → lubrication,
thermal, wear → dynamics), ``"bidirectional"`` iterates to convergence.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from femgear.contact.path import contact_along_path
from femgear.geometry import GearPair
from femgear.io import write_json
from femgear.summary import scene_summary


@dataclass(frozen=True)
class RunResult:
    summary: dict[str, Any]
    files: dict[str, Path] = field(default_factory=dict)


def run_scene(scene, out_dir: str | Path, plots: bool = True) -> RunResult:
    """Run ``scene`` and write ``results.json`` (and PNGs) into ``out_dir``."""
    out_dir = Path(out_dir)
    pair = GearPair.from_scene(scene)
    contact = contact_along_path(scene, pair=pair)
    summary = scene_summary(scene, pair, contact)
    summary["physics"] = scene.physics.model_dump()
    k = contact.kin
    along_path = {
        "s": k.s, "radius_pinion": k.r1, "radius_gear": k.r2, "R": k.R, "v1": k.v1, "v2": k.v2,
        "entrainment_speed": k.ue, "sliding_speed": k.vs, "slide_to_roll": k.srr,
        "hertz_pressure": contact.hertz_pressure, "hertz_half_width": contact.hertz_half_width,
        "film_central": contact.film_central, "film_minimum": contact.film_minimum,
    }
    files: dict[str, Path] = {}
    extra: dict[str, Any] = {}
    if scene.physics.dynamics == "none":
        tribology = _static_passes(scene, pair, contact, out_dir)
        stiffness = _stiffness(scene)
        summary["stiffness"] = stiffness["summary"]
        extra["mesh_stiffness"] = stiffness["table"]
    else:
        tribology, coupled = _coupled(scene, out_dir, plots, files)
        summary.update(coupled["summary"])
        extra.update(coupled["extra"])
    summary.update(tribology["summary"])
    if scene.physics.dynamics == "none":
        along_path.update(tribology["along_path"])
    else:
        extra["coupled_path"] = tribology["along_path"]      # the coupling's own path grid
    files["results"] = write_json(out_dir / "results.json", {
        "summary": summary, "scene": scene.model_dump(), "along_path": along_path, **extra,
    })
    if plots:
        from femgear.plot.path import plot_contact_path, plot_friction_path

        files["contact_path_png"] = plot_contact_path(contact, out_dir / "contact_path.png", title=scene.meta.name)
        trib = extra.get("coupled_path", along_path)
        if "friction_coefficient" in trib:
            files["friction_path_png"] = plot_friction_path(
                np.asarray(trib["s"]), trib["friction_coefficient"], trib["temperature_rise"],
                out_dir / "friction_path.png", title=f"{scene.meta.name}: lubrication = {scene.physics.lubrication}")
    summary = {**summary, "outputs": {k: str(v) for k, v in files.items()}}
    return RunResult(summary=summary, files=files)


def _friction_summary(mu: np.ndarray, dT: np.ndarray, s: np.ndarray) -> dict[str, float]:
    return {"mu_pitch": float(np.interp(0.0, s, mu)), "mu_min": float(np.min(mu)), "mu_max": float(np.max(mu)),
            "mu_mean": float(np.mean(mu)), "max_temperature_rise": float(np.max(dT))}


def _static_passes(scene, pair, contact, out_dir: Path) -> dict[str, dict]:
    """Friction, thermal deviation and wear once, at the static load."""
    summary: dict[str, Any] = {}
    along: dict[str, Any] = {}
    k = contact.kin
    friction = friction_of(scene, contact)
    if friction is not None:
        along.update(friction_coefficient=friction["mu"], temperature_rise=friction["temperature_rise"])
        summary["friction"] = _friction_summary(friction["mu"], friction["temperature_rise"], k.s)
    if scene.physics.thermal != "none":
        from femgear.body.thermal import flank_deviation_from_scene

        z1, z2 = (flank_deviation_from_scene(scene, m, k.u) for m in (1, 2))
        along.update(thermal_deviation_pinion=z1, thermal_deviation_gear=z2)
        summary["thermal"] = _thermal_summary(scene.thermal.flank_temperature_rise, z1, z2, k.s)
    if scene.physics.wear == "archard":
        from femgear.wear import WearSetup, run_wear

        state = run_wear(WearSetup.from_scene(scene, k, pair), scene.wear.cycles,
                         checkpoint=out_dir / "wear_checkpoint.npz")
        along.update(wear_pinion=state.h1, wear_gear=state.h2)
        summary["wear"] = {"cycles": state.cycles, "steps": state.steps,
                           "max_depth_pinion": float(state.h1.max()), "max_depth_gear": float(state.h2.max())}
    return {"summary": summary, "along_path": along}


def _thermal_summary(rise: float, z1: np.ndarray, z2: np.ndarray, s: np.ndarray) -> dict[str, float]:
    return {"flank_temperature_rise": float(rise), "deviation_pitch_pinion": float(np.interp(0.0, s, z1)),
            "deviation_pitch_gear": float(np.interp(0.0, s, z2)),
            "max_deviation": float(max(np.max(np.abs(z1)), np.max(np.abs(z2))))}


def _coupled(scene, out_dir: Path, plots: bool, files: dict) -> tuple[dict, dict]:
    """Dynamics through the coupling loop; writes the final pass's dynamics outputs."""
    from femgear.coupling import CouplingSetup, run_coupled
    from femgear.dynamics.run import write_outputs

    setup = CouplingSetup.from_scene(scene)
    result = run_coupled(setup, one_way=scene.physics.coupling == "one-way")
    st = result.state
    run = write_outputs(st.dynamics, out_dir, plots)
    files.update({f"dynamics_{k}": v for k, v in run.files.items()})
    s = setup.kin.s
    along = {"s": s, "R": setup.kin.R, "entrainment_speed": setup.kin.ue, "sliding_speed": setup.kin.vs,
             "slide_to_roll": setup.kin.srr, "load_per_length": st.load_per_length,
             "friction_coefficient": st.mu, "temperature_rise": st.temperature_rise,
             "thermal_deviation_pinion": st.thermal_deviation[0], "thermal_deviation_gear": st.thermal_deviation[1],
             "wear_pinion": st.wear[0], "wear_gear": st.wear[1]}
    trib: dict[str, Any] = {}
    if scene.physics.lubrication != "none":
        trib["friction"] = _friction_summary(st.mu, st.temperature_rise, s)
    if scene.physics.thermal != "none":
        trib["thermal"] = _thermal_summary(st.flank_temperature_rise, *st.thermal_deviation, s)
    if scene.physics.wear != "none":
        trib["wear"] = {"cycles": scene.wear.cycles, "max_depth_pinion": float(st.wear[0].max()),
                        "max_depth_gear": float(st.wear[1].max())}
    ms = setup.stiffness
    coupled = {
        "summary": {
            "dynamics": run.summary,
            "stiffness": {"level": ms.level, "mean_total": ms.mean, "ripple_total": ms.ripple()},
            "coupling": {"mode": scene.physics.coupling, "converged": result.converged,
                         "iterations": st.iteration, "seconds": result.seconds, "history": result.history},
        },
        "extra": {"mesh_force_per_phase": {"left": st.mesh_force[0], "right": st.mesh_force[1]}},
    }
    return {"summary": trib, "along_path": along}, coupled


def friction_of(scene, contact) -> dict[str, np.ndarray] | None:
    """μ and the contact temperature rise along the path for the scene's lubrication level."""
    if scene.physics.lubrication == "none":
        return None
    from femgear.coupling.loop import lubrication_solver

    k = contact.kin
    if scene.physics.lubrication == "tehl":  # direct thermal EHL solves at every path position
        from femgear.tehl.solver import tehl_line_solver

        solver = tehl_line_solver(scene)
    else:
        solver = lubrication_solver(scene)
    mu, dT = solver(w=np.full(k.u.shape, contact.load_per_length), R=k.R, ue=k.ue,
                    srr=np.abs(k.srr), T=np.full(k.u.shape, scene.operating.ambient_temperature))
    return {"mu": np.asarray(mu, dtype=float), "temperature_rise": np.asarray(dT, dtype=float)}


def _stiffness(scene) -> dict[str, Any]:
    """The mesh stiffness of the scene's level over one mesh period, per helix."""
    from femgear.stiffness.tvms import mesh_stiffness_from_scene

    ms = mesh_stiffness_from_scene(scene)
    return {
        "summary": {"level": ms.level, "mean_total": ms.mean, "mean_per_helix": [ms.mean_left, ms.mean_right],
                    "ripple_total": ms.ripple(), "seconds": ms.seconds},
        "table": {"phase": ms.phase, "k_left": ms.k_left, "k_right": ms.k_right},
    }
