"""Bind a scene's ``[rating]`` table to the four ISO ratings and femgear's own figures (driver level).

:func:`rate_case` is called by the driver (``femgear run``: :func:`femgear.pipeline.run_case`;
``femgear info``) and returns the frozen :class:`femgear.physics.rating.suite.PairRating` that the
writers only read.  Keys of ``[rating]`` left out take the defaults documented in the schema
(and docs/rating.md); one log line names them.  Inputs outside a method's range give one
line each (key and limit) and flag the factor (``PairRating.flags``), printed by ``femgear info``.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from femgear.case import Case, build_case, operating_point
from femgear.docfields import document_fields
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import bulk_temperature, lubrication_solver
from femgear.physics.contact.path import ContactPath, zone_grid
from femgear.physics.geometry import GearPair
from femgear.physics.lubrication.flash import blok_flash_temperature, thermal_effusivity
from femgear.physics.rating import (
    LoadFactors,
    MaterialLimits,
    MeshPowerLoss,
    PittingRating,
    contact_stress,
    mesh_power_loss,
)
from femgear.physics.rating import pitting_rating as _pitting_rating
from femgear.physics.rating.bending import BendingInputs
from femgear.physics.rating.scuffing import OIL_FACTOR, ScuffingInputs
from femgear.physics.rating.suite import OwnFigures, PairRating, rate_pair
from femgear.physics.stiffness.iso6336 import iso6336_stiffness
from femgear.results import ContactFigures

log = logging.getLogger("femgear.physics.rating")

DEFAULTS = {"bending_stress_limit": 5.0e8, "root_roughness_rz": [1.0e-5, 1.0e-5],
            "oil_type": "mineral", "scuffing_load_stage": 12.0, "micropitting_load_stage": 8.0}


def _value(r, key: str, used: list[str]):
    v = getattr(r, key)
    if v is None:
        used.append(f"rating.{key}={DEFAULTS[key]}")
        return DEFAULTS[key]
    return v


def contact_figures(case: Case, contact: ContactPath, mu: np.ndarray | None, mu_u: np.ndarray, level: str,
                    rating: PairRating | None = None) -> ContactFigures:
    """ISO 6336-2 pitting (``rating.pitting`` when given), ISO 6336-1 stiffness, Blok's flash temperature and the
    mesh power loss at the contact pass's line load, with μ(``mu_u``) = ``mu`` of the lubrication ``level`` (the
    run's own; None: dry, μ = 0), interpolated onto the contact pass's positions."""
    scene, pair = case.scene, case.pair
    k = contact.kin
    w = contact.line_loads()
    mu_at = _friction_at(mu, mu_u)
    m = case.material
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    theta = np.asarray(blok_flash_temperature(mu_at(k.u), w, k.vs, contact.hertz_half_width, k.v1, k.v2, B, B), float)
    T1 = case.operating.pinion_torque
    line_load = T1 / pair.r1 * scene.rating.application_factor / (pair.b * pair.n_helices)
    iso = iso6336_stiffness(pair, line_load=line_load, youngs_modulus=m.youngs_modulus)
    iso_loss = None
    if rating is not None:
        mu_mC = rating.scuffing.path.mu_m
        iso_loss = power_loss(case, contact, lambda u: np.full(np.shape(u), mu_mC))
    return ContactFigures(pitting=scene_rating(scene, pair, T1) if rating is None else rating.pitting,
                          iso_stiffness=iso, iso_line_load=line_load, friction_level=level,
                          flash_position=np.asarray(k.s, float), flash_temperature=theta,
                          power_loss=power_loss(case, contact, mu_at), power_loss_iso=iso_loss)


def _friction_at(mu: np.ndarray | None, mu_u: np.ndarray):
    """μ(u) by linear interpolation of ``mu`` given at ``mu_u`` (None: 0)."""
    if mu is None:
        return lambda u: np.zeros(np.shape(u))
    mu, mu_u = np.asarray(mu, float), np.asarray(mu_u, float)
    return lambda u: np.interp(u, mu_u, mu)


def power_loss(case: Case, contact: ContactPath, mu_at) -> MeshPowerLoss:
    """Mesh power loss on the positions of ``contact`` with μ(u) = ``mu_at(u)`` (a spur pair's contact pass is
    redone on a grid through the inner points of single contact B and D, where the load jumps, for an exact path
    integral)."""
    pair, op = case.pair, case.operating
    if pair.beta_b == 0 and not np.all(np.isin(contact.single_contact, contact.kin.u)):
        contact = contact_pass(case, u=zone_grid(pair, contact.kin.u.size))
    k = contact.kin
    w = contact.line_loads()
    return mesh_power_loss(pair, k.u, mu_at(k.u), w, k.vs, op.pinion_torque, op.pinion_speed)


@document_fields
@dataclass(frozen=True)
class SceneInfo:
    """What ``femgear info`` shows of a scene at its static load (:func:`scene_info`)."""

    case: Case
    """the bound :class:`femgear.case.Case` [-]"""
    contact: ContactPath
    """the quasi-static contact pass on a grid through the zone boundaries (spur: B and D) [-]"""
    rating: PairRating | None
    """the four ISO ratings (None when an input is outside what the standards compute, logged) [-]"""
    figures: ContactFigures
    """pitting, ISO stiffness, flash temperature and power loss with μ of the scene's level at the static load [-]"""


def scene_info(case: Case) -> SceneInfo:
    """The figures of ``femgear info``: the contact pass, the ratings, and μ at the contact pass's static line load
    and the oil temperature for the flash temperature and the power loss, of the case's lubrication level where it
    is a closed form (``none``, ``constant``, ``formula``) and of ``formula`` beyond it (the EHL and TEHL
    levels solve for seconds to minutes; ``femgear run`` carries their own μ): ``figures.friction_level`` says which.
    The contacts see the flanks' bulk temperature (the supply temperature plus ``thermal.flank_temperature_rise``,
    :func:`femgear.levels.lubrication.bulk_temperature`)."""
    from femgear.case.checks import contact_warnings
    from femgear.levels.lubrication import summary_level

    pair = case.pair
    contact = contact_pass(case, u=zone_grid(pair, case.numerics.path_points))
    contact_warnings(case, float(contact.hertz_pressure.max()))
    rating = rate_case(case.scene, pair, contact, case=case)
    k = contact.kin
    w = contact.line_loads()
    level = summary_level(case.levels.lubrication)
    T = bulk_temperature(case, case.thermal.flank_temperature_rise)
    mu, _ = lubrication_solver(case, level)(w=w, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=np.full(k.u.shape, T))
    figures = contact_figures(case, contact, np.asarray(mu, float), k.u, level, rating)
    return SceneInfo(case=case, contact=contact, rating=rating, figures=figures)


def oil_laws(case: Case):
    """(η(T) [Pa s], α(T) [1/Pa]) at ambient pressure: the case's oil law (Roelands, the oil bound at the supply
    temperature, :func:`femgear.case.oil.oil_at`), which the ratings' films and μ_mC read."""
    from femgear.levels.lubrication import oil_law

    law = oil_law(case)
    return (lambda T: float(law.viscosity(0.0, T))), (lambda T: float(law.pressure_viscosity(T)))


def own_figures(case, contact: ContactPath, Ra: float, temperature_rise: np.ndarray | None,
                level: str | None, film=None) -> OwnFigures:
    """femgear's film, λ and contact temperature along the contact pass's path (``temperature_rise``: ΔT of the
    lubrication level ``level`` on the same positions; None: computed with the ``formula`` level; ``film``: the
    :class:`femgear.levels.lubrication.LevelFilm` of the level that ran, else the contact pass's h_min)."""
    scene = case.scene
    bulk = bulk_temperature(case, scene.thermal.flank_temperature_rise)
    k = contact.kin
    if temperature_rise is None or level is None or not lubrication_solver(case, level).heats:
        w = contact.line_loads()
        solver = lubrication_solver(case, "formula")
        _, temperature_rise = solver(w=w, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=np.full(k.u.shape, bulk))
        level = "formula"
    if film is not None and np.shape(film.minimum) == np.shape(contact.kin.u):
        h, label = np.asarray(film.minimum, float), f"{film.level}: h_min of {film.method}"
    elif bulk == case.operating.ambient_temperature:
        h, label = np.asarray(contact.film_minimum, float), "contact pass: Dowson–Higginson h_min of the shared line load"
    else:
        from femgear.levels.contact import reduced_modulus_of
        from femgear.levels.lubrication import oil_law
        from femgear.physics.contact.film import line_film

        law = oil_law(case)
        h = line_film(contact.line_loads(), k.R, k.ue, reduced_modulus_of(case), float(law.viscosity(0.0, bulk)),
                      float(law.pressure_viscosity(bulk))).minimum_dh
        label = "contact pass: Dowson–Higginson h_min of the shared line load at the bulk temperature"
    return OwnFigures(u=np.asarray(contact.kin.u, float), film=h, film_level=label, specific_film=h / Ra,
                      temperature=bulk + np.asarray(temperature_rise, float), temperature_level=level)


def _fillets(case):
    from femgear.physics.body.fillet import fillet_stress

    scene, pair = case.scene, case.pair
    force = case.operating.pinion_torque / pair.r1 / pair.n_helices / (pair.b * math.cos(pair.alpha_wt))
    points = (pair.u_start + pair.p_bt, pair.u_end - pair.p_bt)   # outer single contact of pinion, gear
    if pair.eps_alpha >= 2:
        points = (pair.u_end, pair.u_start)
    # clamped at the bore or 6 m_n below the root circle, whichever is outer: the rim deeper down does not
    # change the root stress (turbo gear, z 181: clamp at 6 m_n or at r = 0.3 m, 0.6 % apart) and a long
    # thin sector of a large gear is ill-conditioned
    clamp = (max(scene.pinion.bore_radius, pair.rf1 - 6 * pair.m_n), max(scene.gear.bore_radius, pair.rf2 - 6 * pair.m_n))
    return tuple(fillet_stress(pair, m, points[m - 1], force, scene.material.youngs_modulus,
                               scene.material.poisson_ratio, bore_radius=clamp[m - 1]) for m in (1, 2))


def rate_case(scene, pair: GearPair, contact: ContactPath, temperature_rise: np.ndarray | None = None,
              level: str | None = None, film=None, case=None) -> PairRating:
    """The four ratings of a scene's pair at its operating point, with femgear's own figures beside them
    (``case``: the run's bound case, else bound here from ``scene`` and ``pair``).

    The defaults line and the range flags are logged at INFO (``-v``) and carried in the result
    (``defaults``, ``flags``), which ``femgear info`` prints and results.json holds; stderr keeps the
    CLI's one-line-per-problem contract (``tests/cli/test_bad_input.py``)."""
    from dataclasses import replace

    case = case if case is not None else build_case(scene, pair)
    r, used = scene.rating, []
    sigma_Flim = _value(r, "bending_stress_limit", used)
    root_rz = _value(r, "root_roughness_rz", used)
    Ra = case.flanks.ra
    if case.flanks.finishing is not None and "(default)" in case.flanks.source:
        used.append(f"roughness.finishing={case.flanks.finishing}")
    oil_type = _value(r, "oil_type", used)
    stage_s = _value(r, "scuffing_load_stage", used)
    stage_m = _value(r, "micropitting_load_stage", used)
    if used:
        log.info("rating: defaults used for %s (docs/rating.md)", ", ".join(used))
    rims = []
    for m, member in ((1, scene.pinion), (2, scene.gear)):
        rf, ra = (pair.rf1, pair.ra1) if m == 1 else (pair.rf2, pair.ra2)
        rims.append((rf - member.bore_radius) / (ra - rf) if member.bore_radius > 0 else math.inf)
    K = r.application_factor * r.dynamic_factor * r.face_load_factor * r.transverse_load_factor
    bending = BendingInputs(sigma_Flim=sigma_Flim, S_Fmin=r.bending_min_safety_factor, K_A=r.application_factor,
                            K_v=r.dynamic_factor, K_Hbeta=r.face_load_factor, K_Falpha=r.transverse_load_factor,
                            life_hours=r.life_hours, root_Rz=tuple(root_rz), rim_ratio=tuple(rims))
    eta, alpha = oil_laws(case)
    mat = scene.material
    theta_oil = scene.operating.ambient_temperature
    scuff = ScuffingInputs(oil_temperature=theta_oil, oil_viscosity=eta(theta_oil), youngs_modulus=mat.youngs_modulus,
                           poisson_ratio=mat.poisson_ratio,
                           effusivity=thermal_effusivity(mat.conductivity, mat.density, mat.specific_heat),
                           Ra=Ra, X_L=OIL_FACTOR[oil_type], K=K, X_S=1.2 if r.lubrication_method == "spray" else 1.0,
                           X_W=r.structural_factor)
    own = own_figures(case, contact, 0.5 * (Ra[0] + Ra[1]), temperature_rise, level, film)
    T1 = case.operating.pinion_torque
    rating = rate_pair(pair, scene_rating(scene, pair, T1), T1, scene.pinion_rpm, bending, scuff,
                       float(stage_s), float(stage_m), eta, alpha, own=own, defaults=tuple(used))
    for flag in rating.flags:
        log.info("rating: %s; the factor is flagged", flag)
    if r.fillet_fe:
        rating = replace(rating, own=replace(own, fillet=_fillets(case)))
    return rating


def scene_rating(scene, pair: GearPair, pinion_torque: float | None = None) -> PittingRating:
    """ISO 6336-2 method B rating of a scene's pair at its operating point (``pinion_torque`` [N m]: the bound
    case's, else derived here) and ``[rating]`` table."""
    r = scene.rating
    factors = LoadFactors(K_A=r.application_factor, K_v=r.dynamic_factor, K_Hbeta=r.face_load_factor,
                          K_Halpha=r.transverse_load_factor)
    T1 = operating_point(scene, pair).pinion_torque if pinion_torque is None else pinion_torque
    stress = contact_stress(pair, T1, scene.material.youngs_modulus, scene.material.poisson_ratio, factors)
    limits = MaterialLimits(sigma_Hlim=r.contact_stress_limit, S_Hmin=r.min_safety_factor, life_hours=r.life_hours,
                            nu40=r.oil_viscosity_40, Rz=None if r.roughness_rz is None else tuple(r.roughness_rz),
                            Z_W=r.work_hardening_factor, Z_X=r.size_factor)
    return _pitting_rating(pair, stress, scene.pinion_rpm, limits)
