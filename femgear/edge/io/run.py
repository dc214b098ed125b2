"""``results.json`` of a run: the documented JSON layout, written from a :class:`RunResult`.

Layout (the contract; keys are added, never renamed without a README note):

- ``summary``: ``scene`` (name), ``geometry``, ``contact`` (pitch point and path
  extremes), ``rating`` (ISO 6336-2 pitting), ``stiffness_iso6336``, ``flash_temperature`` and ``power_loss``
  (from ``RunResult.figures``; the last two with the ``friction_level`` of their μ, the run's own), ``safety_factors``, ``bending``, ``scuffing``,
  ``micropitting`` (from ``RunResult.rating``, :mod:`femgear.physics.rating.summary`), ``physics`` (the levels), ``stiffness`` (level, mean_total, ripple_total, with ``fe``/``ltca`` body_level [and body_elements],
  and statically mean_per_helix, seconds), ``friction`` (level, mu_pitch/min/max/mean,
  max_temperature_rise; where a friction map stood in for the level, ``map_*``: its measured error beside its
  tolerance, ``map_within_tolerance`` and the line ``map_error``), ``thermal`` (flank_temperature_rise, deviation_pitch_pinion/
  gear, max_deviation), ``wear`` (cycles, max_depth_pinion/gear, statically steps; load: the load that
  wore, "asperity" or "total"; film_parameter_min, asperity_share_max: the film's share along the path; warnings),
  with ``stiffness = "ltca"`` ``transmission_error`` (:func:`femgear.edge.io.ltca.te_summary`: loaded TE
  p-p, harmonics, stiffness mean/ripple, load share, peak pressure and its edge flag, unloaded TE;
  ``units``; ``resolved_orders`` of the level; with dynamics ``lte_peak_to_peak_deviated``, the loaded
  TE p-p of the last coupling pass's worn and expanded flanks),
  without dynamics ``bearing_forces_static`` (the static loads of the bearing stations, ``RunResult.static_bearing_loads``),
  with ``[housing]`` ``housing`` (:func:`femgear.edge.io.housing.housing_summary`),
  with dynamics ``dynamics`` (:func:`femgear.edge.io.dynamics.dynamics_summary`, its ``bearing_forces`` and
  ``sidebands`` included) and
  ``coupling`` (mode, converged, alternation: None or the two states' difference where the loop settled into a
  two-pass cycle, iterations, seconds, history), ``outputs`` (every file in the folder, a
  ``.pvd`` collection's ``.vtu`` files under their relative path; docs/guide/outputs.md);
- ``scene``: the validated scene;
- ``along_path``: arrays over the ONE path grid of the case (s, radii, speeds, Hertz,
  films, and the tribology fields: load_per_length, friction_coefficient,
  temperature_rise, thermal_deviation_pinion/gear, wear_pinion/gear); ``film_central``,
  ``film_minimum`` (and ``film_pressure_max``, the numerical levels ``film_error_estimate``, thermal levels
  ``film_temperature_rise`` with ``film_temperature_error_estimate`` [K], ``film_central_isothermal``,
  ``thermal_loading``, ``inlet_factor_murch_wilson``, ``inlet_factor_gupta``, ``film_ratio_thermal``,
  ``flash_temperature_tehl``, ``flash_temperature_blok``) are those of the lubrication level that ran
  (``summary.film``: level, method, pitch and minimum values,
  ``error_estimate_max``, the thermal levels' pitch and extreme figures, ``temperature_error_estimate_max``), the
  formula films stay as ``film_*_formula``; ``specific_film`` λ = h_min / R_a (R_a the mean of both
  flanks, ``roughness.ra`` or its default by ``roughness.finishing``: ``summary.roughness``);
  ``summary.oil`` (the oil at the supply temperature and its sources), ``summary.roughness`` and
  ``summary.beside_iso`` (femgear's μ̄, contact temperature and loss beside ISO/TS 6336-20/21's) come from
  :func:`femgear.summary.scene_summary`;
- ``units``: ``{field path: unit}`` of every field of the typed result (``"contact.hertz_pressure": "Pa"``,
  ``"stiffness.k_left": "N/m"``; "-" dimensionless), generated from the field docs (:func:`result_units`);
  the keys above take the unit of the field they are written from;
- ``mesh_stiffness`` (phase, k_left, k_right) and, with dynamics,
  ``mesh_force_per_phase`` (left, right); with ``ltca`` ``transmission_error_per_phase``
  (:func:`femgear.edge.io.ltca.te_curves`: phase, lte, nlte, force_left/right, k_total).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from femgear.docfields import units_table
from femgear.edge.io.along_path import along_path
from femgear.edge.io.results import write_json
from femgear.results import INPUT_TYPES, RunResult, Tribology
from femgear.summary import scene_summary


def _friction_summary(mu: np.ndarray, dT: np.ndarray, s: np.ndarray, level: str) -> dict[str, Any]:
    return {"level": level, "mu_pitch": float(np.interp(0.0, s, mu)), "mu_min": float(np.min(mu)),
            "mu_max": float(np.max(mu)), "mu_mean": float(np.mean(mu)), "max_temperature_rise": float(np.max(dT))}


def _thermal_summary(rise: float, zeta: np.ndarray, s: np.ndarray) -> dict[str, float]:
    return {"flank_temperature_rise": float(rise), "deviation_pitch_pinion": float(np.interp(0.0, s, zeta[0])),
            "deviation_pitch_gear": float(np.interp(0.0, s, zeta[1])), "max_deviation": float(np.max(np.abs(zeta)))}


def tribology_summary(t: Tribology, s: np.ndarray, static: bool, level: str) -> dict[str, Any]:
    """``friction`` (μ of the lubrication ``level`` along the path, labelled with it), ``thermal``, ``wear``."""
    out: dict[str, Any] = {}
    if t.friction_coefficient is not None:
        out["friction"] = _friction_summary(t.friction_coefficient, t.temperature_rise, s, level)
        e = t.friction_map_error
        if e is not None:   # the friction map's own error beside its tolerance, flagged above it
            out["friction"].update(map_samples=e.samples, map_mu_error=e.mu_max_rel, map_mu_tolerance=e.mu_tolerance,
                                   map_temperature_error=e.dT_max_abs, map_temperature_tolerance=e.dT_tolerance,
                                   map_within_tolerance=e.within_tolerance, map_error=e.message())
    if t.thermal_deviation is not None:
        out["thermal"] = _thermal_summary(t.flank_temperature_rise, t.thermal_deviation, s)
    if t.wear is not None:
        out["wear"] = {"cycles": t.wear_cycles, "max_depth_pinion": float(t.wear[0].max()),
                       "max_depth_gear": float(t.wear[1].max()), **({"steps": t.wear_steps} if static else {}),
                       "load": t.wear_load, "film_parameter_min": t.wear_film_parameter,
                       "asperity_share_max": t.wear_asperity_share, "warnings": list(t.wear_warnings)}
    return out


def run_summary(result: RunResult) -> dict[str, Any]:
    """The ``summary`` object of ``results.json`` (without ``outputs``)."""
    case, ms = result.case, result.stiffness
    summary = scene_summary(case, result.contact, result.figures, ratings=result.rating)
    summary["physics"] = case.levels.model_dump()
    summary["stiffness"] = {"level": ms.level, "mean_total": ms.mean, "ripple_total": ms.ripple()}
    level = case.levels.spec("stiffness")
    if level.body is not None:     # the FE bodies' resolution (numerics.body_level unset: the body's default)
        summary["stiffness"]["body_level"] = case.numerics.level_of(level.body)
        if level.body_elements:
            summary["stiffness"]["body_elements"] = case.numerics.body_elements
    static = result.coupled is None
    if static:
        summary["stiffness"].update(mean_per_helix=[ms.mean_left, ms.mean_right], seconds=ms.seconds)
        if result.static_bearing_loads is not None:
            from femgear.system.dynamics.structure import STATIONS

            loads = result.static_bearing_loads
            summary["bearing_forces_static"] = {"axes": ["x", "y", "z"], "units": "N", **{
                name: {"mean": loads[j].tolist(), "radial_mean": float(np.hypot(*loads[j, :2]))}
                for j, name in enumerate(STATIONS)}}
    else:
        from femgear.edge.io.dynamics import dynamics_summary

        co = result.coupled
        h = co.history
        summary["dynamics"] = dynamics_summary(co.state.dynamics)
        summary["coupling"] = {"mode": case.levels.coupling, "converged": co.converged,
                               "alternation": None if co.alternation is None else
                               {"mesh_force_change": co.alternation[0], "mu_change": co.alternation[1]},
                               "iterations": co.state.iteration, "seconds": co.seconds,
                               "history": {"iteration": h.iteration, "mesh_force_change": h.mesh_force_change,
                                           "mu_change": h.mu_change, "seconds": h.seconds}}
    summary.update(tribology_summary(result.tribology, case.path.s, static, case.levels.lubrication))
    if result.transmission_error is not None:
        summary["transmission_error"] = _te_summary(result)
    if result.tribology.film is not None:
        summary["film"] = film_summary(result.tribology.film, case.path.s, result.contact.pitch_index)
    if result.housing is not None:
        from femgear.edge.io.housing import housing_summary

        summary["housing"] = housing_summary(result.housing)
    return summary


def _te_summary(result: RunResult) -> dict[str, Any]:
    from femgear.edge.io.ltca import UNITS, te_summary

    out = te_summary(result.transmission_error, math.cos(result.case.pair.beta_b))
    out["resolved_orders"] = result.stiffness.resolved_orders
    if result.coupled is not None and math.isfinite(result.coupled.state.lte_peak_to_peak):
        out["lte_peak_to_peak_deviated"] = result.coupled.state.lte_peak_to_peak
    out["units"] = {k: UNITS[k] for k in out if k in UNITS} | {"lte_peak_to_peak_deviated": "m"}
    return out


def film_summary(film, s: np.ndarray, pitch: int) -> dict[str, Any]:
    """The film of the lubrication level that ran, labelled with it."""
    i = int(np.argmin(film.minimum))
    out = {"level": film.level, "method": film.method, "central_pitch": float(film.central[pitch]),
           "minimum": float(film.minimum[i]), "minimum_position": float(s[i]),
           "pressure_max": float(np.max(film.pressure_max))}
    if film.error_estimate is not None:
        out["error_estimate_max"] = float(np.max(film.error_estimate))
    if film.spike_unresolved is not None:   # positions whose outlet spike the grid does not resolve
        out["spike_unresolved"] = int(np.count_nonzero(film.spike_unresolved))
    if film.central_isothermal is not None:
        out["central_isothermal_pitch"] = float(film.central_isothermal[pitch])
    if film.thermal is not None:
        th = film.thermal
        out.update(thermal_loading_max=float(np.max(th["thermal_loading"])),
                   phi_tehl_pitch=float(th["phi_tehl"][pitch]), phi_murch_wilson_pitch=float(th["phi_murch_wilson"][pitch]),
                   phi_gupta_pitch=float(th["phi_gupta"][pitch]), flash_tehl_max=float(np.max(th["flash_tehl"])),
                   flash_blok_max=float(np.max(th["flash_blok"])))
    if film.temperature_rise is not None:   # the film's peak with its walls (≥ flash_tehl_max)
        out["temperature_rise_max"] = float(np.max(film.temperature_rise))
    if film.temperature_error_estimate is not None:
        out["temperature_error_estimate_max"] = float(np.max(film.temperature_error_estimate))
    return out


def write_run(result: RunResult, out_dir: str | Path, plots: bool = True, vtk: bool = True
              ) -> tuple[dict[str, Any], dict[str, Path]]:
    """Write every file of a run into ``out_dir``: with dynamics ``dynamics.json``/``.npz``, the PNG figures
    (``plots``, :mod:`femgear.edge.plot`), the ParaView set (``vtk``, :mod:`femgear.edge.io.paraview_run`), and
    last ``results.json``, whose ``summary.outputs`` lists them all (a collection's ``.vtu`` files under their
    relative path); returns (summary, files)."""
    out_dir = Path(out_dir)
    files: dict[str, Path] = {}
    if result.coupled is not None:
        from femgear.edge.io.dynamics import write_dynamics

        dyn = write_dynamics(result.coupled.state.dynamics, out_dir, plots, name=result.case.name)
        files.update({f"dynamics_{k}": v for k, v in dyn.items()})
    if plots:
        files.update(_figures(result, out_dir))
    if result.housing is not None:
        from femgear.edge.io.housing import write_housing

        files.update(write_housing(result.housing, out_dir, plots, vtk, name=result.case.name))
    if vtk:
        from femgear.edge.io.paraview_run import write_run_paraview

        files.update(write_run_paraview(result, out_dir))
    checkpoint = out_dir / WEAR_CHECKPOINT
    if checkpoint.exists():
        files["wear_checkpoint"] = checkpoint
    summary = run_summary(result)
    files["results"] = out_dir / "results.json"
    summary["outputs"] = {k: str(v) for k, v in files.items()}
    ms = result.stiffness
    payload: dict[str, Any] = {
        "summary": summary, "scene": result.case.scene.model_dump(), "along_path": along_path(result),
        "mesh_stiffness": {"phase": ms.phase, "k_left": ms.k_left, "k_right": ms.k_right},
        "units": result_units(),
    }
    if result.coupled is not None:
        force = result.coupled.state.mesh_force
        payload["mesh_force_per_phase"] = {"left": force[0], "right": force[1]}
    if result.transmission_error is not None:
        from femgear.edge.io.ltca import te_curves

        payload["transmission_error_per_phase"] = te_curves(result.transmission_error)
    write_json(files["results"], payload)
    return summary, files


def result_units() -> dict[str, str]:
    """``{field path: unit}`` of every documented field of :class:`RunResult` (:func:`femgear.docfields.units_table`;
    the Case's inputs are the scene's, documented by its schema)."""
    return units_table(RunResult, stop=INPUT_TYPES)


def _figures(result: RunResult, out_dir: Path) -> dict[str, Path]:
    """``contact_path.png``, ``friction_path.png``, ``rating_path.png``, ``tribology_path.png`` (and with coupling
    ``convergence.png``), drawn by :mod:`femgear.edge.plot`."""
    from femgear.edge.io.figures import save_figure
    from femgear.edge.plot.coupled import plot_convergence, plot_coupled_path
    from femgear.edge.plot.path import plot_contact_path, plot_friction_path
    from femgear.edge.plot.rating import plot_rating_path

    case, t = result.case, result.tribology
    name = case.name
    files = {"contact_path_png": save_figure(plot_contact_path(
        result.contact, title=f"{name}:\nquasi-static contact along the path (Hertz, film formulas)"),
        out_dir / "contact_path.png")}
    if t.friction_coefficient is not None:
        files["friction_path_png"] = save_figure(plot_friction_path(
            case.path.s, t.friction_coefficient, t.temperature_rise,
            title=f"{name}:\nfriction and contact temperature along the path (lubrication {case.levels.lubrication})"),
            out_dir / "friction_path.png")
    if result.rating is not None:
        files["rating_path_png"] = save_figure(plot_rating_path(
            result.rating, case.pair.u_pitch, title=f"{name}:\nISO/TS 6336-20/22 scuffing and micropitting ratings"),
            out_dir / "rating_path.png")
    files["tribology_path_png"] = save_figure(plot_coupled_path(
        case.path.s, t.load_per_length, mu=t.friction_coefficient, temperature_rise=t.temperature_rise,
        thermal_deviation=t.thermal_deviation, wear=t.wear, wear_cycles=t.wear_cycles,
        title=f"{name}:\nload, friction, thermal deviation and wear along the path of contact"),
        out_dir / "tribology_path.png")
    if result.coupled is not None:
        h = result.coupled.history
        files["convergence_png"] = save_figure(plot_convergence(
            h.iteration, h.mesh_force_change, h.mu_change, title=f"{name}: convergence of the {case.levels.coupling} coupling"),
            out_dir / "convergence.png")
    return files


#: the wear checkpoint of a static run with ``wear.cycles`` (resumed by a rerun into the same folder)
WEAR_CHECKPOINT = "wear_checkpoint.npz"
