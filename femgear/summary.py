"""Summary figures of a scene (geometry and quasi-static contact), as plain dicts."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from femgear.contact.path import ContactPath, pinion_speed
from femgear.geometry import GearPair, mesh_frequency


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
    }


def contact_summary(result: ContactPath) -> dict[str, Any]:
    """Pitch-point and along-path extremes of the quasi-static contact pass."""
    i = result.pitch_index
    return {
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


def scene_summary(scene, pair: GearPair, contact: ContactPath) -> dict[str, Any]:
    return {
        "scene": scene.meta.name,
        "geometry": geometry_summary(pair, pinion_speed(scene)),
        "contact": contact_summary(contact),
    }
