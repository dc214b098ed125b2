"""Summary figures of a scene (geometry, quasi-static contact, ISO 6336-2 rating, mesh power loss), as plain dicts.

This module binds a scene to the pure rating functions of :mod:`femgear.physics.rating`
(``[rating]`` table, operating point, lubrication level) and is used by ``femgear info``
and by the ``femgear run`` summary.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from femgear.case import operating_point
from femgear.physics.contact.path import ContactPath
from femgear.physics.geometry import GearPair, mesh_frequency
from femgear.physics.rating import MeshPowerLoss, PittingRating, mesh_power_loss
from femgear.physics.rating.suite import PairRating
from femgear.physics.rating.summary import pair_rating_summary
from femgear.rate import scene_rating


def geometry_summary(pair: GearPair, pinion_rpm: float) -> dict[str, Any]:
    """Dimensions and contact ratios of one helix, SI units, angles in degrees."""
    return {
        "transverse_module": pair.m_t,
        "transverse_pressure_angle_deg": math.degrees(pair.alpha_t),
        "working_pressure_angle_deg": math.degrees(pair.alpha_wt),
        "base_helix_angle_deg": math.degrees(pair.beta_b),
        "centre_distance": pair.a_w,
        "reference_radius": [pair.r1, pair.r2],
        "base_radius": [pair.rb1, pair.rb2],
        "tip_radius": [pair.ra1, pair.ra2],
        "root_radius": [pair.rf1, pair.rf2],
        "working_pitch_radius": [pair.rw1, pair.rw2],
        "base_pitch_transverse": pair.p_bt,
        "path_of_contact_length": pair.g_alpha,
        "eps_alpha": pair.eps_alpha,
        "eps_beta": pair.eps_beta,
        "eps_gamma": pair.eps_gamma,
        "mesh_frequency": mesh_frequency(pair, pinion_rpm),
        "kind": pair.kind,
        "face_width": pair.b,
    }


def contact_summary(result: ContactPath) -> dict[str, Any]:
    """Pitch-point and along-path extremes of the quasi-static contact pass."""
    i = result.pitch_index
    out = {
        "normal_force": result.normal_force,
        "load_per_length": result.load_per_length,
        "pitch": {
            "hertz_pressure": result.hertz_pressure[i],
            "hertz_half_width": result.hertz_half_width[i],
            "radius": result.kin.R[i],
            "entrainment_speed": result.kin.ue[i],
            "film_central": result.film_central[i],
            "film_central_dowson_toyoda": result.film_central_dt[i],
            "film_minimum_dowson_higginson": result.film_minimum[i],
            "moes_M": result.moes_M[i],
            "moes_L": result.moes_L[i],
        },
        "path": {
            "max_hertz_pressure": float(np.max(result.hertz_pressure)),
            "min_film_minimum": float(np.min(result.film_minimum)),
            "max_sliding_speed": float(np.max(np.abs(result.kin.vs))),
            "max_slide_to_roll": float(np.max(np.abs(result.kin.srr))),
        },
    }
    if result.line_load is not None:
        out["pitch"]["line_load"] = result.line_load[i]
        out["path"]["max_line_load"] = float(np.max(result.line_load))
        out["path"]["max_hertz_pressure_position"] = float(result.kin.s[int(np.argmax(result.hertz_pressure))])
        out["single_contact"] = _single_contact(result)
    return out


def _single_contact(result: ContactPath) -> dict[str, Any]:
    """Hertz figures at the inner points of single contact B and D (spur pairs; NaN-free)."""
    out: dict[str, Any] = {"u_B": result.single_contact[0], "u_D": result.single_contact[1]}
    for name, u in zip(("B", "D"), result.single_contact, strict=True):
        j = result.at(u)
        if abs(result.kin.u[j] - u) < 1e-9 * max(abs(u), 1e-3):
            out[name] = {"hertz_pressure": result.hertz_pressure[j], "hertz_half_width": result.hertz_half_width[j],
                         "line_load": result.line_load[j], "film_minimum_dowson_higginson": result.film_minimum[j]}
    return out


def rating_summary(rating: PittingRating) -> dict[str, Any]:
    s, f = rating.stress, rating.stress.factors
    return {
        "method": "ISO 6336-2:2019 method B",
        "tangential_load": s.F_t, "virtual_teeth": list(s.z_n),
        "Z_H": s.Z_H, "Z_E": s.Z_E, "Z_eps": s.Z_eps, "Z_beta": s.Z_beta, "Z_B": s.Z_B, "Z_D": s.Z_D,
        "K_A": f.K_A, "K_v": f.K_v, "K_Hbeta": f.K_Hbeta, "K_Halpha": f.K_Halpha,
        "sigma_H0": s.sigma_H0, "sigma_H": list(s.sigma_H),
        "pitch_line_velocity": rating.pitch_line_velocity,
        "load_cycles": None if rating.N_L is None else list(rating.N_L),
        "Z_NT": list(rating.Z_NT), "Z_L": rating.Z_L, "Z_v": rating.Z_v, "Z_R": rating.Z_R,
        "Z_W": rating.limits.Z_W, "Z_X": rating.limits.Z_X, "sigma_Hlim": rating.limits.sigma_Hlim,
        "sigma_HP": list(rating.sigma_HP), "S_H": list(rating.S_H), "S_Hmin": rating.limits.S_Hmin,
        "safe": rating.safe,
    }


def path_friction(scene, pair: GearPair, contact: ContactPath) -> tuple[np.ndarray, str]:
    """μ along ``contact`` at the oil temperature, of the scene's lubrication level (levels beyond
    ``formula``, FE EHL and TEHL, are summarised with ``formula``; the returned level says which)."""
    from femgear.case import build_case
    from femgear.levels.lubrication import lubrication_solver, summary_level

    level = summary_level(scene.physics.lubrication)
    k = contact.kin
    w = contact.line_load if contact.line_load is not None else np.full(k.u.shape, contact.load_per_length)
    solver = lubrication_solver(build_case(scene, pair), level)
    mu, _ = solver(w=w, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=np.full(k.u.shape, scene.operating.ambient_temperature))
    return np.asarray(mu, float), level


def scene_power_loss(scene, pair: GearPair, contact: ContactPath) -> tuple[MeshPowerLoss, str]:
    """Mesh power loss on the positions of ``contact`` with μ of the scene's lubrication level
    (:func:`path_friction`); ``femgear run`` carries the level's own μ."""
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.physics.contact.path import zone_grid

    if pair.beta_b == 0 and not np.all(np.isin(contact.single_contact, contact.kin.u)):
        # the load jumps at B and D must lie on the grid for an exact path integral
        contact = contact_pass(build_case(scene, pair), u=zone_grid(pair, contact.kin.u.size))
    k = contact.kin
    w = contact.line_load if contact.line_load is not None else np.full(k.u.shape, contact.load_per_length)
    mu, level = path_friction(scene, pair, contact)
    omega1 = scene.pinion_rpm * 2 * math.pi / 60
    return mesh_power_loss(pair, k.u, mu, w, k.vs, operating_point(scene, pair).pinion_torque, omega1), level


def flash_summary(scene, pair: GearPair, contact: ContactPath) -> dict[str, Any]:
    """Blok's maximum flash temperature (:func:`femgear.physics.lubrication.flash.blok_flash_temperature`)
    along the path, with the line load of the load sharing and μ of :func:`path_friction`: at the
    start A and the end E of contact (the largest sliding) and its maximum."""
    from femgear.physics.lubrication.flash import blok_flash_temperature, thermal_effusivity

    mu, level = path_friction(scene, pair, contact)
    k, m = contact.kin, scene.material
    w = contact.line_load if contact.line_load is not None else np.full(k.u.shape, contact.load_per_length)
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    theta = np.asarray(blok_flash_temperature(mu, w, k.vs, contact.hertz_half_width, k.v1, k.v2, B, B), float)
    j = int(np.argmax(theta))
    return {"friction_level": level, "theta_fl_A": float(theta[0]), "theta_fl_E": float(theta[-1]),
            "theta_fl_max": float(theta[j]), "theta_fl_max_position": float(k.s[j])}


def stiffness_summary(scene, pair: GearPair) -> dict[str, Any]:
    """ISO 6336-1:2019 method B single and mesh stiffness per unit face width (SI: N/m per m), at the
    scene's load F_t K_A / b (below 100 N/mm the standard reduces c')."""
    from femgear.physics.stiffness.iso6336 import iso6336_stiffness

    F_t = operating_point(scene, pair).pinion_torque / pair.r1
    line_load = F_t * scene.rating.application_factor / (pair.b * pair.n_helices)
    iso = iso6336_stiffness(pair, line_load=line_load, youngs_modulus=scene.material.youngs_modulus)
    unit = 1e9  # N/(mm µm) -> N/m per m
    return {"method": "ISO 6336-1:2019 method B", "c_prime_th": iso.c_th * unit, "c_prime": iso.c_prime * unit,
            "c_gamma_alpha": iso.c_gamma_alpha * unit, "c_gamma_beta": iso.c_gamma_beta * unit}


def power_loss_summary(loss: MeshPowerLoss, level: str) -> dict[str, Any]:
    return {
        "friction_level": level, "mean_loss": loss.mean_loss, "input_power": loss.input_power,
        "efficiency": loss.efficiency, "energy_per_mesh_cycle": loss.energy_per_mesh_cycle,
        "ohlendorf_HV": loss.ohlendorf_HV, "equivalent_mu": loss.equivalent_mu,
        "max_loss_density": float(np.max(loss.density)),
        "mean_friction_coefficient": float(np.mean(loss.friction_coefficient)),
    }


def scene_summary(scene, pair: GearPair, contact: ContactPath, power_loss: bool = True,
                  ratings: PairRating | None = None) -> dict[str, Any]:
    """Geometry, contact, ISO 6336-2 rating and (``power_loss``) mesh power loss of a scene; with ``ratings``
    (computed by the driver, :func:`femgear.rate.rate_case`) also bending, scuffing, micropitting and the
    safety factors, each with femgear's own figures beside them."""
    out = {
        "scene": scene.meta.name,
        "geometry": geometry_summary(pair, scene.pinion_rpm),
        "contact": contact_summary(contact),
        "rating": rating_summary(scene_rating(scene, pair) if ratings is None else ratings.pitting),
        "stiffness_iso6336": stiffness_summary(scene, pair),
        "flash_temperature": flash_summary(scene, pair, contact),
    }
    if ratings is not None:
        out.update(pair_rating_summary(ratings))
    if power_loss:
        out["power_loss"] = power_loss_summary(*scene_power_loss(scene, pair, contact))
    return out
