"""``femgear info SCENE``: geometry, contact, the ISO ratings (pitting, bending, scuffing, micropitting) beside
femgear's own figures, and the mesh power loss of a scene."""

from __future__ import annotations

import argparse

from femgear.edge.cli.common import add_scene_arguments, emit_json, load_case_arg


def register(sub) -> None:
    p = sub.add_parser("info", help="geometry, contact, ISO safety factors S_H, S_F, S_B, S_intS, S_λ, power loss")
    add_scene_arguments(p)
    p.add_argument("--json", action="store_true", help="print one JSON object as the last line")
    p.set_defaults(func=_info)


def _info(args: argparse.Namespace) -> int:
    from femgear.rate import scene_info
    from femgear.summary import scene_summary

    info = scene_info(load_case_arg(args))
    summary = scene_summary(info.case, info.contact, info.figures, ratings=info.rating)
    if args.json:
        emit_json(summary)
    else:
        _print_tree(summary)
    return 0


#: units of the summary's leaf keys (SI; ``_deg`` keys in degrees); keys not listed are dimensionless
UNITS = {
    "transverse_module": "m", "base_pitch_transverse": "m", "path_of_contact_length": "m", "centre_distance": "m",
    "reference_radius": "m", "base_radius": "m", "tip_radius": "m", "root_radius": "m",
    "working_pitch_radius": "m", "radius": "m", "face_width": "m", "hertz_half_width": "m", "film_central": "m",
    "film_central_dowson_toyoda": "m", "film_minimum_dowson_higginson": "m", "min_film_minimum": "m",
    "max_hertz_pressure_position": "m", "u_B": "m", "u_D": "m",
    "mesh_frequency": "Hz", "normal_force": "N", "tangential_load": "N",
    "load_per_length": "N/m", "line_load": "N/m", "max_line_load": "N/m",
    "hertz_pressure": "Pa", "max_hertz_pressure": "Pa", "sigma_H": "Pa", "sigma_H0": "Pa", "sigma_HP": "Pa",
    "sigma_Hlim": "Pa", "entrainment_speed": "m/s", "max_sliding_speed": "m/s", "pitch_line_velocity": "m/s",
    "input_power": "W", "c_prime_th": "N/m/m", "c_prime": "N/m/m", "c_gamma_alpha": "N/m/m",
    "c_gamma_beta": "N/m/m", "theta_fl_A": "K", "theta_fl_E": "K", "theta_fl_max": "K",
    "theta_fl_max_position": "m", "mean_loss": "W", "energy_per_mesh_cycle": "J", "max_loss_density": "W/m",
    "s_Fn": "m", "rho_F": "m", "h_Fe": "m", "sigma_F0": "Pa", "sigma_F": "Pa", "sigma_Flim": "Pa", "sigma_FP": "Pa",
    "fillet_max_principal": "Pa", "fillet_radius": "m", "oil_temperature": "K", "max_flash_temperature": "K",
    "mean_flash_temperature": "K", "bulk_temperature": "K", "max_contact_temperature": "K",
    "scuffing_temperature": "K", "bulk_temperature_integral": "K", "integral_temperature": "K",
    "permissible_integral_temperature": "K", "max_contact_temperature_position": "m", "min_film": "m",
    "lambda_GFmin_position": "m", "lambda_min_position": "m",
    "iso_max_contact_temperature": "K", "iso_bulk_temperature": "K", "iso_integral_temperature": "K",
    "power_loss": "W", "iso_power_loss": "W", "supply_temperature": "K", "viscosity": "Pa s",
    "pressure_viscosity": "1/Pa", "temperature_viscosity": "1/K", "density": "kg/m^3", "eyring_stress": "Pa",
    "ra": "m", "rq": "m", "sigma": "m",
}


def unit_of(key: str) -> str:
    """The unit of a summary key ('' when dimensionless)."""
    return "deg" if key.endswith("_deg") else UNITS.get(key, "")


def _label(key: str) -> str:
    unit = unit_of(key)
    return f"{key} [{unit}]" if unit else key


def _print_tree(d: dict, indent: int = 0) -> None:
    for key, value in d.items():
        if isinstance(value, dict):
            print(" " * indent + f"{key}:")
            _print_tree(value, indent + 2)
        elif isinstance(value, list):
            print(" " * indent + f"{_label(key)}: " + ", ".join(
                f"{v:.6g}" if isinstance(v, (int, float)) else str(v) for v in value))
        elif isinstance(value, float):
            print(" " * indent + f"{_label(key)}: {value:.6g}")
        else:
            print(" " * indent + f"{_label(key)}: {value}")
