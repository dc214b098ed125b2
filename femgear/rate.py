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

from femgear.case import Case
from femgear.case.checks import contact_warnings
from femgear.docfields import document_fields
from femgear.levels.contact import contact_pass, reduced_modulus_of
from femgear.levels.lubrication import bulk_temperature, lubrication_solver, oil_law, summary_level
from femgear.physics.contact.film import line_film
from femgear.physics.contact.path import ContactPath, zone_grid
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
from femgear.physics.rating.load_factors import DynamicFactorCurve, RatingFactor, RatingFactors
from femgear.physics.rating.scuffing import OIL_FACTOR, ScuffingInputs
from femgear.physics.rating.suite import OwnFigures, PairRating, rate_pair
from femgear.physics.stiffness.iso6336 import iso6336_stiffness
from femgear.results import ContactFigures, Tribology

log = logging.getLogger("femgear.physics.rating")

def contact_figures(case: Case, contact: ContactPath, mu: np.ndarray | None, mu_u: np.ndarray, level: str,
                    rating: PairRating | None = None) -> ContactFigures:
    """ISO 6336-2 pitting (``rating.pitting`` when given), ISO 6336-1 stiffness, Blok's flash temperature and the
    mesh power loss at the contact pass's line load, with μ(``mu_u``) = ``mu`` of the lubrication ``level`` (the
    run's own; None: dry, μ = 0), interpolated onto the contact pass's positions."""
    pair = case.pair
    k = contact.kin
    w = contact.line_loads()
    mu_at = _friction_at(mu, mu_u)
    m = case.material
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    theta = np.asarray(blok_flash_temperature(mu_at(k.u), w, k.vs, contact.hertz_half_width, k.v1, k.v2, B, B), float)
    T1 = case.operating.pinion_torque
    line_load = T1 / pair.r1 * case.scene.rating.application_factor / (pair.b * pair.n_helices)
    iso = iso6336_stiffness(pair, line_load=line_load, youngs_modulus=m.youngs_modulus)
    iso_loss = None
    if rating is not None:
        mu_mC = rating.scuffing.path.mu_m
        iso_loss = power_loss(case, contact, lambda u: np.full(np.shape(u), mu_mC))
    return ContactFigures(pitting=pitting_of(case) if rating is None else rating.pitting,
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
    pair = case.pair
    contact = contact_pass(case, u=zone_grid(pair, case.numerics.path_points))
    contact_warnings(case, float(contact.hertz_pressure.max()))
    rating = rate_case(case, contact)
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


def rate_case(case: Case, contact: ContactPath, tribology: Tribology | None = None,
              physics: dict | None = None) -> PairRating:
    """The four ratings of the case's pair at its operating point, with femgear's own figures beside them on the
    ``contact`` pass: the contact temperature and film of the run's ``tribology`` (its lubrication level's; None:
    the ``formula`` level's and the contact pass's film); ``physics``: what the run's physics gives the load
    factors, ``amplitudes`` of its dynamics and its LTCA ``cycle`` (:func:`rating_factors`).

    The defaults line and the range flags are logged at INFO (``-v``) and carried in the result
    (``defaults``, ``flags``), which ``femgear info`` prints and results.json holds; stderr keeps the
    CLI's one-line-per-problem contract (``tests/cli/test_bad_input.py``)."""
    from dataclasses import replace

    scene, pair = case.scene, case.pair
    r = scene.rating
    used = r.defaulted(("bending_stress_limit", "root_roughness_rz"))
    Ra = case.flanks.ra
    if case.flanks.finishing is not None and "(default)" in case.flanks.source:
        used.append(f"roughness.finishing={case.flanks.finishing}")
    used += r.defaulted(("oil_type", "scuffing_load_stage", "micropitting_load_stage", "accuracy_grade"))
    sigma_Flim, root_rz, oil_type = r.value("bending_stress_limit"), r.value("root_roughness_rz"), r.value("oil_type")
    stage_s, stage_m, grade = (r.value(k) for k in ("scuffing_load_stage", "micropitting_load_stage", "accuracy_grade"))
    if used:
        log.info("rating: defaults used for %s (docs/rating.md)", ", ".join(used))
    factors = rating_factors(case, grade, **(physics or {}))
    rims = []
    for m, member in ((1, scene.pinion), (2, scene.gear)):
        rf, ra = (pair.rf1, pair.ra1) if m == 1 else (pair.rf2, pair.ra2)
        rims.append((rf - member.bore_radius) / (ra - rf) if member.bore_radius > 0 else math.inf)
    kv, khb, kha = factors.K_v.value, factors.K_Hbeta.value, factors.K_Halpha.value
    K = r.application_factor * kv * khb * kha
    bending = BendingInputs(sigma_Flim=sigma_Flim, S_Fmin=r.bending_min_safety_factor, K_A=r.application_factor,
                            K_v=kv, K_Hbeta=khb, K_Falpha=kha,
                            life_hours=r.life_hours, root_Rz=tuple(root_rz), rim_ratio=tuple(rims))
    eta, alpha = oil_laws(case)
    mat = scene.material
    theta_oil = scene.operating.ambient_temperature
    scuff = ScuffingInputs(oil_temperature=theta_oil, oil_viscosity=eta(theta_oil), youngs_modulus=mat.youngs_modulus,
                           poisson_ratio=mat.poisson_ratio,
                           effusivity=thermal_effusivity(mat.conductivity, mat.density, mat.specific_heat),
                           Ra=Ra, X_L=OIL_FACTOR[oil_type], K=K, X_S=1.2 if r.lubrication_method == "spray" else 1.0,
                           X_W=r.structural_factor)
    t = tribology
    own = own_figures(case, contact, 0.5 * (Ra[0] + Ra[1]), None if t is None else t.temperature_rise,
                      None if t is None else case.levels.lubrication, None if t is None else t.film)
    T1 = case.operating.pinion_torque
    rating = rate_pair(pair, pitting_of(case, load_factors(r, factors)), T1, scene.pinion_rpm, bending,
                       scuff, float(stage_s), float(stage_m), eta, alpha, own=own, defaults=tuple(used))
    rating = replace(rating, factors=factors)
    for flag in rating.flags:
        log.info("rating: %s; the factor is flagged", flag)
    if r.fillet_fe:
        rating = replace(rating, own=replace(own, fillet=_fillets(case)))
    return rating


def pitting_of(case: Case, factors: LoadFactors | None = None) -> PittingRating:
    """ISO 6336-2 method B rating of the case's pair at its operating point (the pinion torque) and ``[rating]``
    table; ``factors``: the load factors (None: ISO 6336-1's methods, :func:`rating_factors` without the run's
    physics, where the scene does not give them)."""
    scene, pair, r = case.scene, case.pair, case.scene.rating
    if factors is None:
        factors = load_factors(r, rating_factors(case, r.value("accuracy_grade")))
    T1 = case.operating.pinion_torque
    stress = contact_stress(pair, T1, scene.material.youngs_modulus, scene.material.poisson_ratio, factors)
    limits = MaterialLimits(sigma_Hlim=r.contact_stress_limit, S_Hmin=r.min_safety_factor, life_hours=r.life_hours,
                            nu40=r.oil_viscosity_40, Rz=None if r.roughness_rz is None else tuple(r.roughness_rz),
                            Z_W=r.work_hardening_factor, Z_X=r.size_factor)
    return _pitting_rating(pair, stress, scene.pinion_rpm, limits)


def load_factors(r, factors: RatingFactors) -> LoadFactors:
    """The ISO 6336-2 :class:`LoadFactors` of ``[rating]`` ``r`` (its K_A) and the chosen ``factors``."""
    return LoadFactors(K_A=r.application_factor, K_v=factors.K_v.value, K_Hbeta=factors.K_Hbeta.value,
                       K_Halpha=factors.K_Halpha.value)


def _tip_relief(case) -> float:
    """The larger member tip relief of ``[modifications]``, on the transverse base tangent [m] (ISO's C_a)."""
    mods = case.modifications
    return max(mods.member(m).tip_relief for m in (1, 2)) / math.cos(case.pair.beta_b)


def _misalignment(case, tolerances) -> tuple[float, str]:
    """(F_βx [m], its origin): the scene's helix slope deviation (the larger helix; on the transverse base
    tangent, as ISO's F_β), else the accuracy grade's f_Hβ (ISO 1328-1), the manufacturing part f_ma of ISO's
    F_βx.  The mesh's share of the shaft and bearing deflections (f_sh) is not in it: the dynamics levels do
    not provide the static deflection of the shafts along the face yet."""
    mods = case.modifications
    f = max(abs(mods.helix_slope_deviation_left), abs(mods.helix_slope_deviation_right))
    if f > 0:
        return f / math.cos(case.pair.beta_b), f"modifications.helix_slope_deviation ({f * 1e6:.3g} µm)"
    return max(tolerances.f_Hbeta), f"f_Hβ of accuracy grade {tolerances.grade} (no helix slope deviation given)"


def dynamics_K_v(amplitudes) -> tuple[float, ...]:
    """femgear's K_v per loaded helix: the largest dynamic mesh force over its mean (the static force), from the
    response's ``mesh_force.<L|R>.max`` and ``.mean`` (:func:`femgear.system.dynamics.response.analyse`)."""
    out = []
    for side in ("L", "R"):
        mean = amplitudes.get(f"mesh_force.{side}.mean", 0.0)
        if mean > 0 and f"mesh_force.{side}.max" in amplitudes:
            out.append(float(amplitudes[f"mesh_force.{side}.max"]) / mean)
    return tuple(out)


def rating_factors(case, grade: int, amplitudes=None, cycle=None) -> RatingFactors:
    """K_v, K_Hβ, K_Hα of ``case``'s rating with their sources and ISO 6336-1's values beside (docs/rating.md).

    A factor the scene gives (``rating.dynamic_factor`` …) is used as given ("scene"); else, with
    ``rating.load_factors = "femgear"``, K_v comes from the run's dynamics ``amplitudes`` (:func:`dynamics_K_v`,
    the largest helix) and K_Hβ, K_Hα from the LTCA ``cycle`` (:func:`femgear.physics.ltca.factors.ltca_load_factors`)
    where the run computed them; otherwise ISO 6336-1: K_v method B, K_Hβ method C, K_Hα method B at the
    accuracy ``grade`` (ISO 1328-1).  ISO's chain keeps the standard's order: K_Hβ at F_t K_A K_v, K_Hα at
    F_t K_A K_v K_Hβ, each with the factors chosen before it."""
    from femgear.physics.rating.contact_stress import contact_ratio_factor
    from femgear.physics.rating.load_factors import (
        dynamic_factor_b,
        face_load_factor_c,
        grade_tolerances,
        transverse_load_factor_b,
    )

    scene, pair, r = case.scene, case.pair, case.scene.rating
    own = r.load_factors == "femgear"
    F_t = case.operating.pinion_torque / pair.r1 / pair.n_helices          # one helix
    K_A, m = r.application_factor, case.material
    iso = iso6336_stiffness(pair, line_load=F_t * K_A / pair.b, youngs_modulus=m.youngs_modulus)
    tol = grade_tolerances(pair, int(grade))
    kvb = dynamic_factor_b(pair, scene.pinion_rpm, F_t, K_A, iso.c_prime * 1e9, iso.c_gamma_alpha * 1e9, tol,
                           m.density, _tip_relief(case), r.contact_stress_limit, case.bore_radii)
    helices = dynamics_K_v(amplitudes) if own and amplitudes is not None else ()
    method_b = "ISO 6336-1 method B"
    K_v = _chosen(r.dynamic_factor, max(helices) if helices else None, "femgear dynamics", kvb.K_v, method_b,
                  f"max over the helices of the largest dynamic over the static mesh force, at {scene.pinion_rpm:g} "
                  f"rpm (N = {kvb.N:.3g})" if helices else f"N = {kvb.N:.3g}, {kvb.regime}")
    ltca = None
    if own and cycle is not None and cycle.result.line_load:
        from femgear.physics.ltca.factors import ltca_load_factors

        ltca = ltca_load_factors(cycle.result, pair)
    F_bx, origin = _misalignment(case, tol)
    crown = sum(case.modifications.member(k).crowning for k in (1, 2)) / math.cos(pair.beta_b)
    face = face_load_factor_c(pair.b, F_t * K_A * K_v.value / pair.b, iso.c_gamma_beta * 1e9, F_bx, crown)
    if ltca is not None:
        seen = origin if origin.startswith("modifications") else "none (an aligned mesh: give " \
            "modifications.helix_slope_deviation_left for the manufacturing and deflection misalignment)"
        note = f"LTCA face load distribution at the operating torque, peak at ζ = {ltca.peak_zeta * 1e3:.3g} mm; " \
               f"misalignment {seen}; ISO's F_βx = {F_bx * 1e6:.3g} µm"
    else:
        note = f"F_βx = {F_bx * 1e6:.3g} µm: {origin}"
    K_Hb = _chosen(r.face_load_factor, None if ltca is None else ltca.K_Hbeta, "femgear LTCA", face.K_Hbeta,
                   "ISO 6336-1 method C", note)
    z_eps = contact_ratio_factor(pair.eps_alpha, pair.eps_beta)
    kha, _ = transverse_load_factor_b(pair, iso.c_gamma_alpha * 1e9, tol.f_pb,
                                      F_t * K_A * K_v.value * K_Hb.value / pair.b, z_eps)
    K_Ha = _chosen(r.transverse_load_factor, None if ltca is None else max(1.0, ltca.K_Halpha), "femgear LTCA", kha,
                   method_b, "LTCA sharing between the tooth pairs in contact, worst phase "
                   f"{ltca.worst_phase:.3f}" if ltca is not None else f"f_pb = {tol.f_pb * 1e6:.3g} µm (grade {tol.grade})")
    return RatingFactors(K_v=K_v, K_Hbeta=K_Hb, K_Halpha=K_Ha, tolerances=tol, dynamic_b=kvb, face_c=face,
                         K_v_helices=helices)


def _chosen(given: float | None, femgear: float | None, source: str, iso: float, iso_method: str,
            note: str) -> RatingFactor:
    """The factor of one K: the scene's value if given, else femgear's where computed, else ISO's."""
    if given is not None:
        return RatingFactor(float(given), "scene", iso, iso_method, femgear, "rating key given in the scene")
    if femgear is not None:
        return RatingFactor(float(femgear), source, iso, iso_method, femgear, note)
    return RatingFactor(float(iso), iso_method, iso, iso_method, None, note)


def dynamic_factor_curve(case, speed_rpm, amplitudes: dict, driver_speed: bool = True) -> DynamicFactorCurve:
    """femgear's K_v per helix over a speed sweep (``amplitudes``: key -> array over the speeds, of
    :func:`femgear.system.dynamics.sweep.speed_sweep`) beside ISO 6336-1 method B at each speed, at the case's
    torque and accuracy grade (``rating.accuracy_grade``, default 6).  ``speed_rpm``: the sweep's driver speeds
    (``driver_speed``), turned into pinion speeds."""
    from femgear.physics.rating.load_factors import dynamic_factor_b, grade_tolerances

    scene, pair, r, m = case.scene, case.pair, case.scene.rating, case.material
    speeds = np.asarray(speed_rpm, float)
    if driver_speed and scene.operating.driver == "gear":
        speeds = speeds * pair.z2 / pair.z1
    F_t = case.operating.pinion_torque / pair.r1 / pair.n_helices
    iso = iso6336_stiffness(pair, line_load=F_t * r.application_factor / pair.b, youngs_modulus=m.youngs_modulus)
    tol = grade_tolerances(pair, r.value("accuracy_grade"))
    b = [dynamic_factor_b(pair, n, F_t, r.application_factor, iso.c_prime * 1e9, iso.c_gamma_alpha * 1e9, tol,
                          m.density, _tip_relief(case), r.contact_stress_limit, case.bore_radii) for n in speeds]
    helices = []
    for side in ("L", "R")[:pair.n_helices]:
        mean, peak = np.asarray(amplitudes[f"mesh_force.{side}.mean"]), np.asarray(amplitudes[f"mesh_force.{side}.max"])
        helices.append(np.where(mean > 0, peak / np.where(mean > 0, mean, 1.0), np.nan))
    return DynamicFactorCurve(speed_rpm=speeds, femgear=np.array(helices), iso=np.array([k.K_v for k in b]),
                              N=np.array([k.N for k in b]), n_E1=b[0].n_E1, N_S=b[0].N_S)
