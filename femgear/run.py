"""``femgear run``: run what a scene's ``[physics]`` asks for and write its outputs.

Today that is the quasi-static geometry and contact pass along the path of contact
(Hertz pressure, film thickness, sliding) with friction and contact temperature from
the ``lubrication`` level (``none``, ``constant`` μ, or ``formula``: thermal Eyring
traction of the Hertzian film, :mod:`femgear.friction`); the mesh stiffness of the
``stiffness`` level over one mesh period; with ``thermal`` on, the thermal flank
deviation of both members for ``thermal.flank_temperature_rise``; with ``wear =
"archard"``, the wear depth of both flanks after ``wear.cycles``; with ``dynamics`` on,
the gear-rotor dynamics (:func:`femgear.dynamics.run.run_dynamics`).
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
    friction = friction_of(scene, contact)
    if friction is not None:
        along_path.update(friction_coefficient=friction["mu"], temperature_rise=friction["temperature_rise"])
        summary["friction"] = {
            "mu_pitch": friction["mu"][contact.pitch_index], "mu_min": float(np.min(friction["mu"])),
            "mu_max": float(np.max(friction["mu"])), "mu_mean": float(np.mean(friction["mu"])),
            "max_temperature_rise": float(np.max(friction["temperature_rise"])),
        }
    if scene.physics.thermal != "none":
        from femgear.body.thermal import flank_deviation_from_scene

        z1, z2 = (flank_deviation_from_scene(scene, m, k.u) for m in (1, 2))
        along_path.update(thermal_deviation_pinion=z1, thermal_deviation_gear=z2)
        summary["thermal"] = {"flank_temperature_rise": scene.thermal.flank_temperature_rise,
                              "deviation_pitch_pinion": float(np.interp(0.0, k.s, z1)),
                              "deviation_pitch_gear": float(np.interp(0.0, k.s, z2)),
                              "max_deviation": float(max(np.max(np.abs(z1)), np.max(np.abs(z2))))}
    stiffness = _stiffness(scene)
    summary["stiffness"] = stiffness["summary"]
    if scene.physics.wear == "archard":
        state = _wear(scene, pair, contact, out_dir)
        along_path.update(wear_pinion=state.h1, wear_gear=state.h2)
        summary["wear"] = {"cycles": state.cycles, "steps": state.steps,
                           "max_depth_pinion": float(state.h1.max()), "max_depth_gear": float(state.h2.max())}
    files: dict[str, Path] = {}
    if scene.physics.dynamics != "none":
        from femgear.dynamics.run import run_dynamics

        dyn = run_dynamics(scene, out_dir, plots=plots)
        summary["dynamics"] = dyn.summary
        files.update({f"dynamics_{k}": v for k, v in dyn.files.items()})
    files["results"] = write_json(out_dir / "results.json", {
        "summary": summary, "scene": scene.model_dump(), "along_path": along_path,
        "mesh_stiffness": stiffness["table"],
    })
    if plots:
        from femgear.plot.path import plot_contact_path

        files["contact_path_png"] = plot_contact_path(contact, out_dir / "contact_path.png", title=scene.meta.name)
        if friction is not None:
            from femgear.plot.path import plot_friction_path

            files["friction_path_png"] = plot_friction_path(
                contact.kin.s, friction["mu"], friction["temperature_rise"], out_dir / "friction_path.png",
                title=f"{scene.meta.name}: lubrication = {scene.physics.lubrication}")
    summary = {**summary, "outputs": {k: str(v) for k, v in files.items()}}
    return RunResult(summary=summary, files=files)


def friction_of(scene, contact) -> dict[str, np.ndarray] | None:
    """μ and the contact temperature rise along the path for the scene's lubrication level."""
    level = scene.physics.lubrication
    n = contact.kin.u.size
    if level == "none":
        return None
    if level == "constant":
        return {"mu": np.full(n, scene.friction.coefficient), "temperature_rise": np.zeros(n)}
    from femgear.friction.path import friction_along_path

    r = friction_along_path(scene, contact)
    return {"mu": r.mu, "temperature_rise": r.film_max}


def _stiffness(scene) -> dict[str, Any]:
    """The mesh stiffness of the scene's level over one mesh period, per helix."""
    from femgear.stiffness.tvms import mesh_stiffness_from_scene

    ms = mesh_stiffness_from_scene(scene)
    return {
        "summary": {"level": ms.level, "mean_total": ms.mean, "mean_per_helix": [ms.mean_left, ms.mean_right],
                    "ripple_total": ms.ripple(), "seconds": ms.seconds},
        "table": {"phase": ms.phase, "k_left": ms.k_left, "k_right": ms.k_right},
    }


def _wear(scene, pair, contact, out_dir: Path):
    """Archard wear over ``wear.cycles``, checkpointed in ``out_dir`` so a rerun resumes."""
    from femgear.wear import WearSetup, run_wear

    setup = WearSetup.from_scene(scene, contact.kin, pair)
    return run_wear(setup, scene.wear.cycles, checkpoint=out_dir / "wear_checkpoint.npz")
