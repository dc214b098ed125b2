"""The result schema: every key of the ``summary`` of ``results.json``, what kind of value it holds, and when.

The summary is written by :func:`femgear.edge.io.run.run_summary` (the scene part by
:func:`femgear.summary.scene_summary`, as ``femgear info --json`` prints it); this table states its
layout as data, so that a consumer can check a key before anything runs: ``femgear sweep`` refuses an
``outputs`` entry that names no column of ``results.csv`` before its first case
(:func:`femgear.edge.sweep.check.check_outputs`).  ``tests/io/test_summary_schema.py`` checks the table
against real summaries (every zoo scene's, a static and a coupled run), both ways: no key of a summary
is missing here, and each has the kind given here.

Kinds: ``number`` (int or float; ``None`` where noted optional), ``pair`` (two numbers: pinion and gear,
or left and right helix; ``results.csv`` has them as ``key.0`` and ``key.1``), ``list`` (a longer or
variable list), ``text``, ``flag`` (true/false), ``table`` (a dict of named entries, e.g. ``units``).
Each section is present only where the case computes it (:data:`SECTIONS`: its condition on the scene).
A ``*`` in a key stands for any name (the dynamics' amplitudes by body, axis and helix).
"""

from __future__ import annotations

import fnmatch
from collections.abc import Callable
from dataclasses import dataclass

NUMBER, PAIR, LIST, TEXT, FLAG, TABLE = "number", "pair", "list", "text", "flag", "table"


def _keys(prefix: str, kind: str, names: str, optional: bool = False) -> dict[str, tuple[str, bool]]:
    return {f"{prefix}.{n}" if prefix else n: (kind, optional) for n in names.split()}


def _dynamic(scene) -> bool:
    return scene.physics.spec("dynamics").is_dynamic


def _lubricated(scene) -> bool:
    return scene.physics.spec("lubrication").friction


@dataclass(frozen=True)
class Section:
    """One top-level section of the summary: its keys with their kinds, and when a case has it."""

    keys: dict[str, tuple[str, bool]]       #: key -> (kind, may be None)
    present: Callable[[object], bool] = lambda scene: True    #: whether a case of this scene writes it
    when: str = "always"                    #: the condition, in words (for messages)


SECTIONS: dict[str, Section] = {
    "scene": Section(_keys("", TEXT, "scene")),
    "geometry": Section({
        **_keys("geometry", NUMBER, "transverse_module transverse_pressure_angle_deg working_pressure_angle_deg "
                                    "base_helix_angle_deg centre_distance base_pitch_transverse path_of_contact_length "
                                    "eps_alpha eps_beta eps_gamma mesh_frequency face_width"),
        **_keys("geometry", PAIR, "reference_radius base_radius tip_radius root_radius working_pitch_radius"),
        **_keys("geometry", TEXT, "kind")}),
    "contact": Section({
        **_keys("contact", NUMBER, "normal_force load_per_length"),
        **_keys("contact.pitch", NUMBER, "hertz_pressure hertz_half_width radius entrainment_speed film_central "
                                         "film_central_dowson_toyoda film_minimum_dowson_higginson moes_M moes_L "
                                         "line_load"),
        **_keys("contact.path", NUMBER, "max_hertz_pressure min_film_minimum max_sliding_speed max_slide_to_roll "
                                        "max_line_load max_hertz_pressure_position"),
        **_keys("contact.single_contact", NUMBER, "u_B u_D"),
        **_keys("contact.single_contact.*", NUMBER, "hertz_pressure hertz_half_width line_load "
                                                    "film_minimum_dowson_higginson")}),
    "rating": Section({
        **_keys("rating", NUMBER, "tangential_load Z_H Z_E Z_eps Z_beta Z_B Z_D K_A K_v K_Hbeta K_Halpha sigma_H0 "
                                  "pitch_line_velocity Z_L Z_v Z_R Z_W Z_X sigma_Hlim S_Hmin"),
        **_keys("rating", PAIR, "virtual_teeth sigma_H Z_NT sigma_HP S_H"),
        **_keys("rating", PAIR, "load_cycles", optional=True),
        **_keys("rating", TEXT, "method"), **_keys("rating", FLAG, "safe")}),
    "stiffness_iso6336": Section({**_keys("stiffness_iso6336", NUMBER, "c_prime_th c_prime c_gamma_alpha c_gamma_beta"),
                                  **_keys("stiffness_iso6336", TEXT, "method")}),
    "flash_temperature": Section({**_keys("flash_temperature", NUMBER, "theta_fl_A theta_fl_E theta_fl_max "
                                                                       "theta_fl_max_position"),
                                  **_keys("flash_temperature", TEXT, "friction_level")}),
    "safety_factors": Section({**_keys("safety_factors", NUMBER, "S_B S_intS S_lambda"),
                               **_keys("safety_factors", PAIR, "S_H S_F"),
                               **_keys("safety_factors", LIST, "flagged flags defaults")},
                              when="where the ISO ratings could be computed"),
    "bending": Section({
        **_keys("bending", NUMBER, "tangential_load Y_beta Y_DT K_Fbeta Y_X sigma_Flim"),
        **_keys("bending", PAIR, "s_Fn rho_F h_Fe Y_F Y_S Y_B sigma_F0 sigma_F Y_NT Y_deltarelT Y_RrelT sigma_FP S_F"),
        **_keys("bending", TEXT, "method"),
        **_keys("bending.femgear", PAIR, "fillet_max_principal ratio_to_sigma_F0 fillet_radius "
                                         "fillet_tangent_angle_deg"),
        **_keys("bending.femgear", TEXT, "method")}, when="where the ISO ratings could be computed"),
    "scuffing": Section({
        **_keys("scuffing", NUMBER, "fzg_load_stage mu_m oil_temperature max_flash_temperature mean_flash_temperature "
                                    "bulk_temperature max_contact_temperature scuffing_temperature S_B "
                                    "bulk_temperature_integral integral_temperature permissible_integral_temperature "
                                    "S_intS"),
        **_keys("scuffing", TEXT, "method"),
        **_keys("scuffing.femgear", NUMBER, "max_contact_temperature max_contact_temperature_position"),
        **_keys("scuffing.femgear", TEXT, "lubrication_level")}, when="where the ISO ratings could be computed"),
    "micropitting": Section({
        **_keys("micropitting", NUMBER, "load_stage bulk_temperature min_film lambda_GFmin lambda_GFmin_position "
                                        "lambda_GFT lambda_GFP S_lambda"),
        **_keys("micropitting", TEXT, "method"),
        **_keys("micropitting.femgear", NUMBER, "min_film lambda_min lambda_min_position"),
        **_keys("micropitting.femgear", TEXT, "film")}, when="where the ISO ratings could be computed"),
    "load_factors": Section({
        **_keys("load_factors.*", NUMBER, "value iso"), **_keys("load_factors.*", NUMBER, "femgear", optional=True),
        **_keys("load_factors.*", TEXT, "source iso_method note"),
        **_keys("load_factors.K_v", LIST, "helices"),
        **_keys("load_factors.K_v", NUMBER, "resonance_ratio resonance_speed_rpm N_S B_p B_f B_k tip_relief"),
        **_keys("load_factors.K_v", TEXT, "regime"),
        **_keys("load_factors.K_Hbeta", NUMBER, "F_beta_x F_beta_y y_beta crowning c_gamma_beta"),
        **_keys("load_factors.accuracy_grade", NUMBER, "grade f_pb"),
        **_keys("load_factors.accuracy_grade", PAIR, "f_pt f_falpha f_Hbeta")},
        when="where the ISO ratings could be computed"),
    "beside_iso": Section({
        **_keys("beside_iso", NUMBER, "mu_mean mu_path_mean iso_mu_mC mu_ratio oil_temperature max_contact_temperature "
                                      "iso_bulk_temperature iso_max_contact_temperature iso_integral_temperature "
                                      "power_loss iso_power_loss efficiency iso_efficiency"),
        **_keys("beside_iso", TEXT, "friction_level temperature_level")},
        when="where the ISO ratings could be computed"),
    "oil": Section({
        **_keys("oil", TEXT, "name", optional=True),
        **_keys("oil", NUMBER, "supply_temperature viscosity pressure_viscosity temperature_viscosity density "
                               "eyring_stress limiting_shear_coeff"),
        **_keys("oil.sources", TEXT, "viscosity pressure_viscosity density thermal traction", optional=True),
        **_keys("oil", LIST, "unsourced")}),
    "roughness": Section({
        **_keys("roughness", PAIR, "ra rq"), **_keys("roughness", NUMBER, "sigma"),
        **_keys("roughness", TEXT, "model source state contact fluid_film"), **_keys("roughness", TEXT, "finishing", optional=True),
        **_keys("roughness", NUMBER, "run_in_factor share_b share_c")}),
    "inlet_heating": Section({
        **_keys("inlet_heating.pitch", NUMBER, "thermal_loading phi_murch_wilson phi_gupta position"),
        **_keys("inlet_heating.max", NUMBER, "thermal_loading phi_murch_wilson phi_gupta position")}),
    "power_loss": Section({**_keys("power_loss", NUMBER, "mean_loss input_power efficiency energy_per_mesh_cycle "
                                                         "ohlendorf_HV equivalent_mu max_loss_density "
                                                         "mean_friction_coefficient"),
                           **_keys("power_loss", TEXT, "friction_level")}),
    # ---- what only `femgear run` writes (not `femgear info`)
    "physics": Section({**_keys("physics", TEXT, "stiffness lubrication thermal wear dynamics coupling"),
                        **_keys("physics", TEXT, "preset", optional=True)}, when="in every run"),
    "stiffness": Section({**_keys("stiffness", NUMBER, "mean_total ripple_total body_level seconds"),
                          **_keys("stiffness", PAIR, "mean_per_helix"),
                          **_keys("stiffness", TEXT, "level body_elements")}, when="in every run"),
    "friction": Section({**_keys("friction", NUMBER, "mu_pitch mu_min mu_max mu_mean max_temperature_rise"),
                         **_keys("friction", TEXT, "level"),
                         # where a friction map stood in for the level's solves (tehl with dynamics): its own error
                         **_keys("friction", NUMBER, "map_samples map_mu_error map_mu_tolerance map_temperature_error "
                                                     "map_temperature_tolerance"),
                         **_keys("friction", FLAG, "map_within_tolerance"), **_keys("friction", TEXT, "map_error")}, _lubricated, 'with a lubrication level other than "none"'),
    "thermal": Section(_keys("thermal", NUMBER, "flank_temperature_rise deviation_pitch_pinion deviation_pitch_gear "
                                                "max_deviation"),
                       lambda scene: scene.physics.spec("thermal").grows, 'with a thermal level other than "none"'),
    "wear": Section({**_keys("wear", NUMBER, "cycles max_depth_pinion max_depth_gear steps"),
                     **_keys("wear", NUMBER, "film_parameter_min asperity_share_max", optional=True),
                     **_keys("wear", TEXT, "load"), **_keys("wear", LIST, "warnings")},
                    lambda scene: scene.physics.spec("wear").wears, 'with a wear level other than "none"'),
    "film": Section({**_keys("film", NUMBER, "central_pitch minimum minimum_position pressure_max"),
                     **_keys("film", TEXT, "level method"),
                     # the numerical levels' error estimate; the thermal levels' films beside the isothermal and
                     # formula ones (femgear.edge.io.run.film_summary): present only where the level computes them
                     **_keys("film", NUMBER, "error_estimate_max central_isothermal_pitch thermal_loading_max "
                                             "phi_tehl_pitch phi_murch_wilson_pitch phi_gupta_pitch flash_tehl_max "
                                             "flash_blok_max temperature_rise_max temperature_error_estimate_max "
                                             "spike_unresolved")}, when="in every run"),
    "transmission_error": Section({
        **_keys("transmission_error", NUMBER, "torque force lte_peak_to_peak lte_mean lte_transverse_peak_to_peak "
                                              "nlte_peak_to_peak nlte_max stiffness_mean stiffness_ripple "
                                              "load_share_left load_share_right load_balance_error max_pressure "
                                              "max_pressure_interior max_pressure_phase "
                                              "max_pressure_u max_pressure_zeta resolved_orders helices"),
        **_keys("transmission_error", NUMBER, "lte_peak_to_peak_refined lte_left_peak_to_peak lte_right_peak_to_peak "
                                              "lte_peak_to_peak_deviated", optional=True),
        **_keys("transmission_error", LIST, "lte_harmonics lte_harmonics_orders"),
        **_keys("transmission_error", LIST, "lte_harmonics_refined lte_harmonics_change interior_load_share_min",
                optional=True),
        **_keys("transmission_error", TEXT, "max_pressure_where max_pressure_helix"), **_keys("transmission_error", FLAG, "edge_contact"),
        **_keys("transmission_error", TABLE, "units")},
        lambda scene: scene.physics.spec("stiffness").contact_lines, 'with physics.stiffness = "ltca"'),
    "dynamics": Section({
        **_keys("dynamics", NUMBER, "dt steps seconds mesh_frequency friction_factor"),
        **_keys("dynamics", PAIR, "mean_mesh_stiffness rayleigh mesh_damping"),
        **_keys("dynamics", LIST, "natural_frequencies_hz modes"),
        **_keys("dynamics", TEXT, "level method stiffness"),
        **_keys("dynamics.amplitudes", NUMBER, "*"),
        **_keys("dynamics.bearing_forces", LIST, "axes"), **_keys("dynamics.bearing_forces", TEXT, "units"),
        **_keys("dynamics.bearing_forces.*", LIST, "mean peak_to_peak mesh_orders"),
        **_keys("dynamics.bearing_forces.*", NUMBER, "radial_mean"),
        **_keys("dynamics.sidebands.*", NUMBER, "shaft_frequency_hz revolutions"),
        **_keys("dynamics.sidebands.*", NUMBER, "needs_mesh_periods recorded_mesh_periods", optional=True),
        **_keys("dynamics.sidebands.*", FLAG, "resolved"),
        **_keys("dynamics.sidebands.*", LIST, "mesh_orders sides"),
        **_keys("dynamics.sidebands.*.lines", LIST, "*"),
        **_keys("dynamics.sidebands.*.shaft_orders", LIST, "*")}, _dynamic, "with a dynamics level"),
    "bearing_forces_static": Section({
        **_keys("bearing_forces_static", LIST, "axes"), **_keys("bearing_forces_static", TEXT, "units"),
        **_keys("bearing_forces_static.*", LIST, "mean"), **_keys("bearing_forces_static.*", NUMBER, "radial_mean")},
        lambda scene: not _dynamic(scene), "without a dynamics level (the static loads of the bearing stations)"),
    "coupling": Section({
        **_keys("coupling", NUMBER, "iterations seconds"),
        **_keys("coupling.alternation", NUMBER, "mesh_force_change mu_change"),
        **_keys("coupling", TEXT, "mode"), **_keys("coupling", FLAG, "converged"),
        **_keys("coupling", TABLE, "alternation", optional=True),
        **_keys("coupling.history", LIST, "iteration mesh_force_change mu_change seconds")}, _dynamic,
        "with a dynamics level"),
    "housing": Section({
        **_keys("housing", TEXT, "model coupling"), **_keys("housing", FLAG, "linear_valid"),
        **_keys("housing", LIST, "sensors rigid_natural_frequencies ignored_inputs natural_frequencies "
                                 "housing_frequencies sensor_points sensor_directions"),
        **_keys("housing", NUMBER, "fixed_interface_modes fixed_interface_max_hz full_dofs housing_mass "
                                   "surface_area"),
        **_keys("housing.operating", NUMBER, "pinion_rpm sound_power_level_total sound_power_level_a "
                                             "sweep_max_sound_power_level sweep_max_sound_power_level_speed"),
        **_keys("housing.operating", TEXT, "source"),
        **_keys("housing.operating", LIST, "frequency sensor_acceleration bearing_force_radial sound_power_level"),
        **_keys("housing.sweep", PAIR, "pinion_rpm"), **_keys("housing.sweep", NUMBER, "points orders lines_valid"),
        **_keys("housing.sweep", LIST, "max_sensor_acceleration max_sensor_acceleration_rpm"),
        **_keys("housing.force_change.*", NUMBER, "median p90 max"),
        **_keys("housing.reduction_check", NUMBER, "band_hz modes_in_band max_error"),
        **_keys("housing.reduction_check", FLAG, "flagged")},
        lambda scene: scene.housing is not None, "with a [housing] table"),
    "outputs": Section(_keys("outputs", TEXT, "*"), when="in every run (the files written; not in results.csv)"),
}


def kind_of(key: str) -> tuple[str, str, bool] | None:
    """(section, kind, may be None) of a summary key (a dotted path), or None when the schema has no such key."""
    section = key.split(".", 1)[0]
    entry = SECTIONS.get(section)
    if entry is None:
        return None
    if key in entry.keys:
        return (section, *entry.keys[key])
    for pattern, (kind, optional) in entry.keys.items():
        if "*" in pattern and fnmatch.fnmatchcase(key, pattern):
            return section, kind, optional
    return None


def columns(section: str | None = None) -> list[str]:
    """The ``results.csv`` column names the schema knows (numbers, flags and both halves of pairs; no wildcards)."""
    out = []
    for name, entry in SECTIONS.items():
        if section is not None and name != section:
            continue
        for key, (kind, _) in entry.keys.items():
            if "*" in key:
                continue
            if kind in (NUMBER, FLAG):
                out.append(key)
            elif kind == PAIR:
                out += [f"{key}.0", f"{key}.1"]
    return out


__all__ = ["FLAG", "LIST", "NUMBER", "PAIR", "SECTIONS", "TABLE", "TEXT", "Section", "columns", "kind_of"]
