"""The ``along_path`` object of ``results.json``: the arrays over the ONE path grid of a run (also the fields of
``flanks.pvd``, :func:`femgear.edge.io.paraview_run.flank_frames`)."""

from __future__ import annotations

import numpy as np

from femgear.results import RunResult

#: the thermal levels' per-position figures (:attr:`femgear.levels.lubrication.LevelFilm.thermal`) and their
#: ``along_path`` names
THERMAL_FIELDS = {"thermal_loading": "thermal_loading", "phi_murch_wilson": "inlet_factor_murch_wilson",
                  "phi_gupta": "inlet_factor_gupta", "phi_tehl": "film_ratio_thermal",
                  "flash_tehl": "flash_temperature_tehl", "flash_blok": "flash_temperature_blok"}


def along_path(result: RunResult) -> dict[str, np.ndarray]:
    c, k, t = result.contact, result.case.path, result.tribology
    fields = {
        "s": k.s, "radius_pinion": k.r1, "radius_gear": k.r2, "R": k.R, "v1": k.v1, "v2": k.v2,
        "entrainment_speed": k.ue, "sliding_speed": k.vs, "slide_to_roll": k.srr,
        "hertz_pressure": c.hertz_pressure, "hertz_half_width": c.hertz_half_width,
        "film_central": c.film_central, "film_minimum": c.film_minimum, "load_per_length": t.load_per_length,
    }
    if t.film is not None:      # the film of the level that ran replaces the formula film, which stays as *_formula
        fields.update(film_central_formula=c.film_central, film_minimum_formula=c.film_minimum,
                      film_central=t.film.central, film_minimum=t.film.minimum, film_pressure_max=t.film.pressure_max)
        if t.film.temperature_rise is not None:
            fields["film_temperature_rise"] = t.film.temperature_rise
        if t.film.error_estimate is not None:
            fields["film_error_estimate"] = t.film.error_estimate
        if t.film.temperature_error_estimate is not None:
            fields["film_temperature_error_estimate"] = t.film.temperature_error_estimate
        if t.film.central_isothermal is not None:
            fields["film_central_isothermal"] = t.film.central_isothermal
        for key, name in THERMAL_FIELDS.items():
            if t.film.thermal is not None and key in t.film.thermal:
                fields[name] = t.film.thermal[key]
    if t.friction_coefficient is not None:
        fields.update(friction_coefficient=t.friction_coefficient, temperature_rise=t.temperature_rise)
    if t.thermal_deviation is not None:
        fields.update(thermal_deviation_pinion=t.thermal_deviation[0], thermal_deviation_gear=t.thermal_deviation[1])
    if t.wear is not None:
        fields.update(wear_pinion=t.wear[0], wear_gear=t.wear[1])
    own = None if result.rating is None else result.rating.own
    if own is not None and own.specific_film.shape == k.u.shape:     # λ = h_min / R_a of the film that ran
        fields["specific_film"] = own.specific_film
    return fields


__all__ = ["along_path"]
