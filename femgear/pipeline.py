"""``femgear run``: run what a case's ``[physics]`` asks for (pure), then write it (edge).

Always: the quasi-static geometry and contact pass along the path of contact (Hertz
pressure, film thickness, sliding) and the mesh stiffness of the ``stiffness`` level.

Without dynamics (``dynamics = "none"``), the sub-models run once at the static load:
friction and contact temperature from the ``lubrication`` level (the registry of
:mod:`femgear.levels.lubrication`), the thermal flank deviation (``thermal``) for
``thermal.flank_temperature_rise`` and the wear depth after ``wear.cycles``.

With dynamics, everything goes through the coupling loop of :mod:`femgear.system.coupling`:
``coupling = "one-way"`` stops after the first dynamic pass, ``"bidirectional"``
iterates to convergence.

:func:`run_case` computes and returns a frozen :class:`femgear.results.RunResult` and writes
nothing; :func:`femgear.edge.run.run_scene` binds a scene, runs it and writes the files.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import numpy as np

from femgear.case import Case
from femgear.case.checks import contact_warnings
from femgear.levels import check_case
from femgear.levels import housing as housing_levels
from femgear.levels import stiffness as stiffness_levels
from femgear.levels import wear as wear_levels
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import Lubrication, bulk_temperature, friction_along_path, lubrication_solver
from femgear.physics.contact.path import ContactPath
from femgear.physics.stiffness.tvms import MeshStiffness
from femgear.results import RunResult, Tribology
from femgear.stages import derived_fields
from femgear.system.coupling.loop import run_coupled
from femgear.system.coupling.setup import CouplingSetup, line_stiffness, ltca_face_reference, ltca_reference
from femgear.system.coupling.state import CouplingState
from femgear.system.coupling.thermal import ThermalUnits, roll_distances, thermal_units


def run_case(case: Case, progress: Callable[[CouplingState], None] | None = None,
             wear_checkpoint: Path | None = None) -> RunResult:
    """Run ``case``; ``progress`` receives every coupling state; wear resumes from ``wear_checkpoint``.

    The checks of the case's levels run first (:func:`femgear.levels.check_case`: the TEHL levels' speed envelope,
    the FE bodies' memory), before anything costly."""
    t0 = time.perf_counter()
    check_case(case)
    housing_levels.of(case)        # the housing first (built once, cached): its bad input fails before any work
    stiffness = stiffness_levels.of(case)
    contact = contact_pass(case, stiffness=stiffness)
    contact_warnings(case, float(contact.hertz_pressure.max()))     # the scene's plausibility, on the run's pass
    te = transmission_error(case, stiffness)
    if not case.levels.spec("dynamics").is_dynamic:
        lubrication = lubrication_solver(case)
        tribology = static_tribology(case, contact, stiffness, wear_checkpoint, lubrication)
        tribology = replace(tribology, film=lubrication.film(tribology.load_per_length,
                                                             bulk_temperature(case, tribology.flank_temperature_rise)))
        return derived_fields(RunResult(case, contact, stiffness, tribology, seconds=time.perf_counter() - t0,
                                        transmission_error=te, rating=case_rating(case, contact, tribology,
                                                                                  stiffness)))
    setup = CouplingSetup.from_case(case, stiffness=stiffness)
    coupled = run_coupled(setup, one_way=not case.levels.spec("coupling").iterates, progress=progress)
    st = coupled.state
    worn, lubricated = setup.wear is not None, setup.lubrication.friction
    tribology = Tribology(
        load_per_length=st.load_per_length,
        friction_coefficient=st.mu if lubricated else None,
        temperature_rise=st.temperature_rise if lubricated else None,
        flank_temperature_rise=st.flank_temperature_rise,
        thermal_deviation=st.thermal_deviation if setup.thermal is not None else None,
        wear=st.wear if worn else None, wear_cycles=case.wear.cycles,
        **wear_regime(setup.wear if worn else None, st.load_per_length),
        **face_fields(case, setup.thermal, st.flank_temperature_rise, None if setup.face is None else setup.face.grid,
                      st.wear_face if worn else None, st.thermal_face),
        film=setup.lubrication.film(st.load_per_length, bulk_temperature(case, st.flank_temperature_rise)),
        friction_map_error=setup.lubrication.map_error)
    return derived_fields(RunResult(case, contact, stiffness, tribology, coupled, seconds=time.perf_counter() - t0,
                                    transmission_error=te,
                                    rating=case_rating(case, contact, tribology, stiffness, st.amplitudes or None)))


def transmission_error(case: Case, stiffness: MeshStiffness, n_harmonics: int = 5):
    """The :class:`femgear.physics.ltca.te.TEAnalysis` of the ``ltca`` level's cycle at the pinion torque (None for
    other levels)."""
    ltca = None if stiffness.ltca is None else stiffness.ltca.result
    if ltca is None or not ltca.line_load:
        return None
    from femgear.physics.ltca.te import analyse_cycle

    m = case.material
    return analyse_cycle(ltca, case.pair, m.youngs_modulus, m.poisson_ratio, case.operating.pinion_torque, n_harmonics)


def case_rating(case: Case, contact: ContactPath, tribology: Tribology, stiffness: MeshStiffness | None = None,
                amplitudes=None):
    """The four ISO ratings with femgear's contact temperature and film of the run's lubrication level beside them
    (defaults and range flags in results.json, logged at INFO), their K_v from the dynamics' ``amplitudes`` and
    K_Hβ, K_Hα from the ``stiffness`` level's LTCA cycle where the run computed them (:func:`femgear.rate.rating_factors`);
    None (logged) when a rating input is outside what the standards can compute (e.g. a rim too thin)."""
    from femgear.rate import rate_case

    physics = {"amplitudes": amplitudes, "cycle": None if stiffness is None else stiffness.ltca}
    try:
        return rate_case(case, contact, tribology, physics=physics)
    except ValueError as exc:
        logging.getLogger("femgear.physics.rating").warning("rating: not computed: %s", exc)
        return None


def static_tribology(case: Case, contact: ContactPath, stiffness: MeshStiffness | None = None,
                     wear_checkpoint: Path | None = None, lubrication: Lubrication | None = None) -> Tribology:
    """Friction, thermal deviation and wear once, at the static load: friction at the contact
    pass's shared line load w(u) (:mod:`femgear.physics.contact.sharing`) and the flanks' bulk temperature
    (the supply temperature plus ``thermal.flank_temperature_rise``), wear with the load shared
    along the contact lines by the local pair stiffness (:func:`line_stiffness`), with ``ltca`` as the
    LTCA cycle shares it (:func:`ltca_reference`); ``lubrication``: the case's level (default: built here)."""
    w = np.asarray(contact.line_load, dtype=float)      # load sharing between the pairs in contact
    mu = dT = zeta = wear = None
    lubrication = lubrication or lubrication_solver(case)
    if lubrication.friction:
        T = np.full(case.path.u.shape, bulk_temperature(case, case.thermal.flank_temperature_rise))
        mu, dT = friction_along_path(case, w, lubrication, T)
    units = thermal_units(case)
    if units is not None:
        zeta = units.deviation(case.thermal.flank_temperature_rise, case.thermal.shaft_temperature_rise)
    cycles, steps, faces = 0.0, 0, {}
    wear_model = wear_levels.of(case)
    if wear_model is not None:
        pair = case.pair
        k_mean = float(np.mean(stiffness.k_left)) if stiffness is not None else \
            case.stiffness.mesh_stiffness_per_width * pair.b
        cycle = None if stiffness is None else stiffness.ltca
        ref = ltca_reference(pair, case.path.u, cycle, np.zeros(case.path.u.size)) \
            if cycle is not None and pair.beta_b > 0 else None     # spur: the Winkler sharing (see coupling.loop)
        setup = wear_model.setup(pair, case.path, case.operating.normal_force / pair.n_helices,
                                 line_stiffness(case, k_mean, stiffness), reference=ref)
        if wear_model.face and ref is not None:     # face-resolved (femgear.physics.wear.face); no checkpoint
            from femgear.physics.wear.face import run_face_wear

            face = ltca_face_reference(pair, case.path.u, cycle, np.zeros(case.path.u.size),
                                       n_zeta=wear_model.face_points)
            state = run_face_wear(setup, face, wear_model.cycles)
            wear = state.path_mean(face.grid)
            faces = {"grid": face.grid, "wear_face": np.array([state.h1, state.h2])}
        else:
            from femgear.physics.wear import run_wear

            state = run_wear(setup, wear_model.cycles, checkpoint=wear_checkpoint)
            wear = np.array([state.h1, state.h2])
        cycles, steps = state.cycles, state.steps
    return Tribology(load_per_length=w, friction_coefficient=mu, temperature_rise=dT,
                     flank_temperature_rise=case.thermal.flank_temperature_rise, thermal_deviation=zeta, wear=wear,
                     wear_cycles=cycles, wear_steps=steps, **wear_regime(wear_model, w),
                     **face_fields(case, units, case.thermal.flank_temperature_rise, **faces))


def wear_regime(wear_model, load_per_length: np.ndarray) -> dict:
    """The :class:`Tribology` wear-regime fields of ``wear_model`` (an ``ArchardWear`` or None) at the run's load
    ``load_per_length``; its warnings are logged."""
    if wear_model is None:
        return {}
    r = wear_model.regime(load_per_length)
    warnings = wear_model.warnings(load_per_length)
    for text in warnings:
        logging.getLogger("femgear.physics.wear").warning(text)
    return {"wear_load": wear_model.load, "wear_film_parameter": None if r is None else r.film_parameter_min,
            "wear_asperity_share": None if r is None else r.share_max, "wear_warnings": warnings}


def face_fields(case: Case, units: ThermalUnits | None, rise: float, grid: np.ndarray | None = None,
                wear_face: np.ndarray | None = None, thermal_face: np.ndarray | None = None) -> dict:
    """The :class:`Tribology` face fields: ``wear_face`` as given, ``thermal_face`` as given or, with 3-D thermal
    units (``fe3d``), ζ_T at the bulk ``rise`` on ``grid`` (default: ``wear.face_points`` over the face); {} when
    neither exists."""
    if thermal_face is None and units is not None and units.bodies is not None:
        grid = np.linspace(0.0, case.pair.b, case.wear.face_points) if grid is None else grid
        thermal_face = units.face(roll_distances(case.pair, case.path.u), grid, rise,
                                  case.thermal.shaft_temperature_rise)
    if wear_face is None and thermal_face is None:
        return {}
    return {"face_grid": grid, "wear_face": wear_face, "thermal_face": thermal_face}


__all__ = ["MeshStiffness", "RunResult", "run_case", "static_tribology"]
