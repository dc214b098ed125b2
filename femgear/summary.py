"""Summary figures of a case (geometry, quasi-static contact, ISO 6336-2 rating, ISO 6336-1 stiffness, flash
temperature, mesh power loss), as plain dicts: formatting only.

Every figure is computed by the driver (:func:`femgear.rate.contact_figures`, :func:`femgear.rate.rate_case`,
carried as ``RunResult.figures`` and ``RunResult.rating``); this module only arranges them for
``femgear info`` and the ``summary`` of ``results.json``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from femgear.physics.contact.path import ContactPath
from femgear.physics.geometry import GearPair
from femgear.physics.rating import MeshPowerLoss, PittingRating
from femgear.physics.rating.suite import PairRating
from femgear.physics.rating.summary import pair_rating_summary
from femgear.results import ContactFigures


def geometry_summary(pair: GearPair, mesh_frequency: float) -> dict[str, Any]:
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
        "mesh_frequency": mesh_frequency,
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


def flash_summary(f: ContactFigures) -> dict[str, Any]:
    """Blok's maximum flash temperature along the path (:func:`femgear.rate.contact_figures`): at the start A and
    the end E of contact (the largest sliding) and its maximum, labelled with the level of its μ."""
    theta = f.flash_temperature
    j = int(np.argmax(theta))
    return {"friction_level": f.friction_level, "theta_fl_A": float(theta[0]), "theta_fl_E": float(theta[-1]),
            "theta_fl_max": float(theta[j]), "theta_fl_max_position": float(f.flash_position[j])}


def stiffness_summary(f: ContactFigures) -> dict[str, Any]:
    """ISO 6336-1:2019 method B single and mesh stiffness per unit face width (SI: N/m per m), at the
    scene's load F_t K_A / b (below 100 N/mm the standard reduces c')."""
    iso, unit = f.iso_stiffness, 1e9  # N/(mm µm) -> N/m per m
    return {"method": "ISO 6336-1:2019 method B", "c_prime_th": iso.c_th * unit, "c_prime": iso.c_prime * unit,
            "c_gamma_alpha": iso.c_gamma_alpha * unit, "c_gamma_beta": iso.c_gamma_beta * unit}


def power_loss_summary(loss: MeshPowerLoss, level: str) -> dict[str, Any]:
    """The mesh power loss; ``friction_level`` names the level of its μ (the μ itself is ``summary.friction``)."""
    return {
        "friction_level": level, "mean_loss": loss.mean_loss, "input_power": loss.input_power,
        "efficiency": loss.efficiency, "energy_per_mesh_cycle": loss.energy_per_mesh_cycle,
        "ohlendorf_HV": loss.ohlendorf_HV, "equivalent_mu": loss.equivalent_mu,
        "max_loss_density": float(np.max(loss.density)),
        "mean_friction_coefficient": float(np.mean(loss.friction_coefficient)),
    }


def inlet_heating_summary(case, contact: ContactPath) -> dict[str, Any]:
    """The thermal loading L_th = β η0 u_e²/k_f of the contact pass (oil at the supply temperature) and the two
    inlet-heating factors of the isothermal film at the pitch point and where L_th is largest
    (:mod:`femgear.physics.tehl.inlet`: Murch & Wilson 1975, Gupta et al. 1992): what the thermal film is read
    against before a TEHL run."""
    from femgear.levels.contact import reduced_modulus_of
    from femgear.levels.lubrication import oil_law
    from femgear.physics.lubrication.traction import gupta_thermal_factor
    from femgear.physics.tehl.inlet import murch_wilson_factor, thermal_loading

    k, oil, T = contact.kin, oil_law(case), case.operating.ambient_temperature
    Lth = np.asarray(thermal_loading(k.ue, T, oil, case.oil.conductivity), float)
    out: dict[str, Any] = {}
    for name, i in (("pitch", contact.pitch_index), ("max", int(np.argmax(Lth)))):
        g = gupta_thermal_factor(contact.hertz_pressure[i], reduced_modulus_of(case), k.srr[i], k.ue[i],
                                 float(oil.viscosity(0.0, T)), float(oil.temperature_viscosity(T)),
                                 case.oil.conductivity)
        out[name] = {"thermal_loading": float(Lth[i]), "phi_murch_wilson": float(murch_wilson_factor(Lth[i])),
                     "phi_gupta": float(g), "position": float(k.s[i])}
    return out


def oil_summary(case) -> dict[str, Any]:
    """The oil as the run used it: at the supply temperature (η0, α, β_T, ρ0 there, :func:`femgear.case.oil.oil_at`),
    its library name and the source of each data group; ``unsourced`` lists the groups resting on no published
    source (:func:`femgear.scene.oils.oil_provenance`)."""
    from femgear.scene.oils import oil_provenance

    oil = case.oil
    return {**oil_provenance(case.scene.oil), "supply_temperature": oil.reference_temperature,
            "viscosity": oil.viscosity, "pressure_viscosity": oil.pressure_viscosity,
            "temperature_viscosity": oil.temperature_viscosity, "density": oil.density,
            "eyring_stress": oil.eyring_stress, "limiting_shear_coeff": oil.limiting_shear_coeff}


def roughness_summary(case) -> dict[str, Any]:
    """The flanks' roughness both the ratings and the tribology read (:func:`femgear.scene.roughness.flank_roughness`)."""
    f, r = case.flanks, case.roughness
    return {"ra": list(f.ra), "rq": list(f.rq), "sigma": f.sigma, "model": f.model, "source": f.source,
            "finishing": f.finishing, "state": f.state, "run_in_factor": f.run_in_factor, "contact": r.contact,
            "fluid_film": r.fluid_film, "share_b": r.share_b, "share_c": r.share_c}


def scene_summary(case, contact: ContactPath, figures: ContactFigures, ratings: PairRating | None = None
                  ) -> dict[str, Any]:
    """Geometry, contact, ISO 6336-2 rating, ISO 6336-1 stiffness, flash temperature and mesh power loss of a case
    (``figures``: computed by the driver, :func:`femgear.rate.contact_figures`); with ``ratings``
    (:func:`femgear.rate.rate_case`) also bending, scuffing, micropitting and the safety factors, each with
    femgear's own figures beside them."""
    out = {
        "scene": case.name,
        "geometry": geometry_summary(case.pair, case.operating.mesh_frequency),
        "contact": contact_summary(contact),
        "rating": rating_summary(figures.pitting),
        "stiffness_iso6336": stiffness_summary(figures),
        "flash_temperature": flash_summary(figures),
        "inlet_heating": inlet_heating_summary(case, contact),
        "oil": oil_summary(case),
        "roughness": roughness_summary(case),
    }
    if ratings is not None:
        out.update(pair_rating_summary(ratings))
    out["power_loss"] = power_loss_summary(figures.power_loss, figures.friction_level)
    if ratings is not None and figures.power_loss_iso is not None:
        out["beside_iso"] = beside_iso_summary(figures, ratings)
    return out


def beside_iso_summary(figures: ContactFigures, ratings: PairRating) -> dict[str, Any]:
    """femgear's own friction, contact temperature and mesh power loss beside ISO/TS 6336-20/21's (docs/rating.md,
    "Beside ISO"): μ̄ (the constant μ with femgear's mesh loss, Ohlendorf's H_V) beside μ_mC; the maximum contact
    temperature beside ISO's flash-method θ_B,max, its bulk θ_M and the integral temperature θ_int; the loss with
    femgear's μ(u) beside the loss with μ_mC on the same load and sliding."""
    loss, iso, s, own = figures.power_loss, figures.power_loss_iso, ratings.scuffing, ratings.own
    mu = loss.equivalent_mu
    return {
        "friction_level": figures.friction_level,
        "mu_mean": mu, "mu_path_mean": float(np.mean(loss.friction_coefficient)), "iso_mu_mC": s.path.mu_m,
        "mu_ratio": mu / s.path.mu_m,
        "max_contact_temperature": None if own is None else own.max_temperature,
        "temperature_level": None if own is None else own.temperature_level,
        "iso_max_contact_temperature": s.max_contact_temperature, "iso_bulk_temperature": s.theta_M,
        "iso_integral_temperature": s.theta_int, "oil_temperature": s.theta_oil,
        "power_loss": loss.mean_loss, "iso_power_loss": iso.mean_loss,
        "efficiency": loss.efficiency, "iso_efficiency": iso.efficiency,
    }
