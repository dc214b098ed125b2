"""Lubrication levels (the ``[physics] lubrication`` key): friction, contact temperature and the film.

Every level's factory returns a :class:`Lubrication`: a contact solver with the map signature
``solver(w=, R=, ue=, srr=, T=) -> (μ, ΔT)`` (load per unit contact length [N/m], radius [m],
entrainment speed [m/s], |slide-to-roll| [-], bulk temperature [K]), so that a
:class:`femgear.physics.lubrication.map.FrictionMap` can stand in for any expensive level, and
the film of the same level (:meth:`Lubrication.film`):

| level      | solver                                                        | film                                  |
|------------|---------------------------------------------------------------|---------------------------------------|
| none       | μ = 0, no heating                                             | isothermal formulas (Moes h_c,        |
| constant   | μ = ``friction.coefficient``, Blok's flash temperature        | Dowson–Higginson h_min, Hertz p)      |
| formula    | thermal Eyring traction of the Hertzian film                  |   "                                   |
| ehl-line   | line EHL (FD, graded grids) with Eyring traction, Blok flash  | isothermal line EHL, to a tolerance   |
| tehl       | thermal EHL line solves; ``repeated``: a friction map of them | thermal line EHL, direct solves       |
| tehl-point | thermal EHL of the crowned flanks' elliptic contacts          | the same solves (reused when they ran |
|            |                                                               | at these inputs)                      |

The factories read the Case's typed parts and build the physics' own typed objects from its tables
(:func:`oil_law`, :func:`line_friction`, :func:`tehl_setup`); the physics never sees the scene.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from femgear.case import Case
from femgear.docfields import document_fields
from femgear.levels.contact import contact_pass, reduced_modulus_of
from femgear.levels.registry import Registry
from femgear.physics.contact.crowning import CrownedContact, crowned_contact
from femgear.physics.contact.film import line_film
from femgear.physics.contact.hertz import hertz_line
from femgear.physics.contact.path import ContactPath
from femgear.physics.ehl.dimensional import DimensionalEHL
from femgear.physics.ehl.fd.line import spike_resolved
from femgear.physics.ehl.path import ehl_line_solver, line_ehl_path
from femgear.physics.lubrication.flash import line_flash_temperature
from femgear.physics.lubrication.map import MapError, hertz_level_solver
from femgear.physics.lubrication.mixed import Roughness
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.path import LineFriction, solids_of
from femgear.physics.tehl.inlet import inlet_figures
from femgear.physics.tehl.line import TEHLResult
from femgear.physics.tehl.path import tehl_path_results
from femgear.physics.tehl.point_level import POINT_LEVEL
from femgear.physics.tehl.point_level import tehl_point_solver as point_solver
from femgear.physics.tehl.reuse import RecordingSolver
from femgear.physics.tehl.slice_map import all_slender, slice_map_axes, slice_map_solver
from femgear.physics.tehl.slices import SliceGeometry, SliceResult
from femgear.physics.tehl.solver import TEHLSetup, check_envelope, tehl_line_solver, tehl_map_axes, tehl_map_solver

log = logging.getLogger("femgear.physics.lubrication")

Solver = Callable[..., tuple[np.ndarray, np.ndarray]]
"""solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise) — the signature of friction maps."""

REGISTRY = Registry("lubrication")


@document_fields
@dataclass(frozen=True)
class LevelFilm:
    """Film along the path of one lubrication level (arrays over the case's path positions)."""

    level: str
    """the ``physics.lubrication`` level that computed it [-]"""
    method: str
    """the film model, in words (e.g. "isothermal formulas (Moes h_c, Dowson-Higginson h_min)") [-]"""
    central: np.ndarray
    """central film thickness h_c [m]"""
    minimum: np.ndarray
    """minimum film thickness h_min [m]"""
    pressure_max: np.ndarray
    """pressure peak at each path position (the Hertz p_0 for the formula films, the EHL pressure spike or peak for the
    numerical levels) [Pa]"""
    temperature_rise: np.ndarray | None = None
    """the film's peak temperature rise at each path position, its walls included, so never below the flash
    (surface) rise ``thermal["flash_tehl"]`` (:func:`femgear.physics.tehl.line.film_peaks`; thermal levels only,
    else None) [K]"""
    error_estimate: np.ndarray | None = None
    """relative discretisation error of each position's films, the larger of h_c's and h_min's two-level
    Richardson estimates (the numerical levels; None for the formula films) [-]"""
    central_isothermal: np.ndarray | None = None
    """central film of the isothermal solve beside the thermal one (thermal levels only) [m]"""
    temperature_error_estimate: np.ndarray | None = None
    """Richardson estimate of each position's ``temperature_rise`` error over the thermal levels (the line TEHL
    solves, :attr:`femgear.physics.tehl.line.TEHLResult.temperature_estimate`; None where a position's solve has
    none) [K]"""
    spike_unresolved: np.ndarray | None = None
    """per path position: True where the grid does not resolve the outlet pressure spike (the numerical line levels'
    solves and face slices, :func:`femgear.physics.ehl.fd.line.spike_resolved`; None for the formula films and the
    elliptic point solves): its ``pressure_max`` and ``temperature_rise`` are then the unresolved spike's, low by
    an amount the ``error_estimate`` of the films does not measure [-]"""
    thermal: dict | None = None
    """per-position thermal figures of the thermal levels (None elsewhere): ``thermal_loading`` L_th =
    β η0 u_e²/k_f, the inlet factors ``phi_murch_wilson`` and ``phi_gupta``, ``phi_tehl`` = h_c/h_c,iso, and the
    flash temperatures ``flash_tehl`` (the TEHL surface temperature rise) and ``flash_blok`` (Blok's for the same
    μ) in K [-]"""


FilmOf = Callable[[str, np.ndarray, float, Solver], LevelFilm]


@dataclass(frozen=True)
class Lubrication:
    """The product of a lubrication level: its contact solver (call it like one) and its film."""

    level: str
    """the ``physics.lubrication`` level"""
    solve: Solver = field(repr=False)
    """``solve(w=, R=, ue=, srr=, T=) -> (μ, ΔT)``"""
    film_of: FilmOf = field(repr=False)
    """``film_of(level, w, T, solve) -> LevelFilm`` at the path positions (w broadcast to them)"""
    path_shape: tuple[int, ...]
    """shape of the case's path positions"""
    ambient_temperature: float
    """bulk temperature of the films by default [K]"""
    friction: bool = True
    """False for the ``none`` level: μ = 0 and no contact heating to report"""
    uniform: float | None = None
    """μ of every contact where the level has one number (none, constant); None where μ varies [-]"""
    heats: bool = True
    """whether the level computes a contact temperature rise (False for ``none``: no friction, no heat)"""

    def __call__(self, w, R, ue, srr, T) -> tuple[np.ndarray, np.ndarray]:
        return self.solve(w=w, R=R, ue=ue, srr=srr, T=T)

    @property
    def map_error(self) -> MapError | None:
        """The measured error of the friction map that stands in for the level's solves (``tehl`` in the
        coupling loop), once built; None for direct solves."""
        fmap = self.solve.friction_map() if hasattr(self.solve, "friction_map") else None
        return None if fmap is None else fmap.error

    def film(self, load_per_length, temperature: float | None = None) -> LevelFilm:
        """The film of this level at the loads ``load_per_length`` [N/m] along the path, at the bulk
        ``temperature`` [K] (default: the ambient temperature).  Where the solver keeps its latest direct
        solves (``tehl-point``) at these very inputs, they are reused."""
        w = np.broadcast_to(np.asarray(load_per_length, dtype=float), self.path_shape)
        T = self.ambient_temperature if temperature is None else temperature
        film = self.film_of(self.level, w, T, self.solve)
        for name in ("central", "minimum", "pressure_max"):
            a = getattr(film, name)
            if a.shape != w.shape or not np.all(np.isfinite(a)) or np.any(a <= 0):
                raise FloatingPointError(f"{film.level} film: {name} is not positive and finite along the path")
        return film


def _product(case: Case, level: str, solve: Solver, film_of: FilmOf, **flags) -> Lubrication:
    return Lubrication(level=level, solve=solve, film_of=film_of, path_shape=case.path.u.shape,
                       ambient_temperature=case.operating.ambient_temperature, **flags)


# ---------------------------------------------------------------- typed parts from the case's tables
def oil_law(case: Case) -> OilLaw:
    """The oil's viscosity and density laws (Roelands), referred to the supply temperature (``case.oil``)."""
    return OilLaw.from_table(case.oil, case.oil_reference_temperature)


def flank_asperities(rough, sigma: float) -> Roughness:
    """The load-sharing :class:`Roughness` of composite σ [m] with the ``[roughness]`` table's laws and statistics."""
    return Roughness(sigma, rough.eta_beta_sigma, rough.sigma_over_beta, rough.contact, rough.fluid_film,
                     rough.share_b, rough.share_c)


def line_friction(case: Case) -> LineFriction:
    """The ``formula`` level's line-contact friction with the case's oil, steel, traction and roughness."""
    rough, flanks = case.roughness, case.flanks
    mixed = flanks.model == "greenwood-tripp" and flanks.sigma > 0
    return LineFriction(oil=oil_law(case), E_red=reduced_modulus_of(case), solids=solids_of(case.material, case.oil),
                        tau0=case.oil.eyring_stress, limiting_shear=case.oil.limiting_shear_coeff,
                        roughness=flank_asperities(rough, flanks.sigma) if mixed else None, boundary_coefficient=case.friction.boundary_coefficient)


def tehl_setup(case: Case) -> TEHLSetup:
    """Oil, solids and traction of the case's TEHL solves."""
    return TEHLSetup.from_tables(case.material, case.oil, case.oil_reference_temperature)


def crowning(case: Case) -> tuple[float, float]:
    """Lead crowning C_β of pinion and gear [m]."""
    mods = case.modifications
    return mods.member(1).crowning, mods.member(2).crowning


def envelope_contact(case: Case, n: int = 21) -> ContactPath:
    """The contact pass at ``n`` positions plus the pitch point that friction-map envelopes span (kinematics
    and the mean load per length only: the load is not shared by the stiffness level)."""
    return contact_pass(case, n=n, shared=False)


def tehl_axes(case: Case) -> dict[str, np.ndarray]:
    """The ``tehl`` friction map's axes over the case's path (:func:`femgear.physics.tehl.solver.tehl_map_axes`)."""
    return tehl_map_axes(envelope_contact(case), case.operating.ambient_temperature)


# ---------------------------------------------------------------- films
def _formula_film(case: Case) -> FilmOf:
    def film(level: str, w: np.ndarray, T: float, solve: Solver) -> LevelFilm:
        k, oil, E_red = case.path, oil_law(case), reduced_modulus_of(case)
        films = line_film(w, k.R, k.ue, E_red, float(oil.viscosity(0.0, T)), float(oil.pressure_viscosity(T)))
        p = np.array([hertz_line(wi, R, E_red).max_pressure for wi, R in zip(w, k.R)])
        return LevelFilm(level=level, method="isothermal formulas (Moes h_c, Dowson-Higginson h_min)",
                         central=films.central_moes, minimum=films.minimum_dh, pressure_max=p)

    return film


def _ehl_line_film(case: Case) -> FilmOf:
    def film(level: str, w: np.ndarray, T: float, solve: Solver) -> LevelFilm:
        n = case.numerics
        f = line_ehl_path(w, case.path.R, case.path.ue, T, oil_law(case), reduced_modulus_of(case), tol=n.ehl_tol,
                          min_level=n.ehl_level)
        return LevelFilm(level=level, method=f"isothermal line EHL (FD, graded grid level {f.level}, "
                         f"tolerance {100 * n.ehl_tol:g} %)", central=f.central, minimum=f.minimum,
                         pressure_max=f.pressure_max, error_estimate=f.error_estimate,
                         spike_unresolved=spikes_unresolved(level, f.results))

    return film


def spikes_unresolved(level: str, results) -> np.ndarray | None:
    """Per path position (``results``: a film's line solves, :class:`~femgear.physics.tehl.line.TEHLResult`,
    :class:`~femgear.physics.ehl.dimensional.DimensionalEHL` or face slices, any of whose slices counts): whether
    the outlet spike is unresolved (:func:`femgear.physics.ehl.fd.line.spike_resolved`); logged as one warning
    naming ``level`` and the count.  None where no result is a line solve (the elliptic point solves)."""
    def one(r):
        if isinstance(r, SliceResult):
            return any(one(x) for x in r.results)
        if isinstance(r, TEHLResult):
            return not spike_resolved(r.x / r.b, r.p / r.ph)
        if isinstance(r, DimensionalEHL):
            return not spike_resolved(r.x / r.a, r.p / r.ph)
        return None
    flags = [one(r) for r in results]
    if all(f is None for f in flags):
        return None
    out = np.array([bool(f) for f in flags])
    if out.any():
        log.warning("%s film: the outlet pressure spike is not resolved at %d of %d path positions (a heavy contact "
                    "whose Hertzian dome is higher than the spike, or a spike grid that failed): their peak pressure "
                    "and film peak temperature are low by an amount the film's error estimate does not measure "
                    "(summary film.spike_unresolved)", level, int(out.sum()), out.size)
    return out


def _reused(solve: Solver, case: Case, w: np.ndarray, T: float) -> tuple | None:
    """The results of ``solve``'s latest call when it was at exactly these path inputs (else None: a solver that
    keeps no record, or other inputs)."""
    latest = solve.latest if isinstance(solve, RecordingSolver) else None
    if latest is None:
        return None
    k = case.path
    return latest.at(w, k.R, k.ue, np.abs(k.srr), np.full(w.shape, T))


def _thermal_film(case: Case, method: str, solve_path: Callable) -> FilmOf:
    """The film of a thermal level: ``solve_path(w, T)`` (the results at the path positions), or the solver's own
    latest solves at these inputs."""
    def film(level: str, w: np.ndarray, T: float, solve: Solver) -> LevelFilm:
        rs = _reused(solve, case, w, T) or solve_path(w, T)
        hot = [i for i, r in enumerate(rs) if r.dT_surface > r.dT_max]
        if hot:     # the film's peak includes its walls: a surface above it is a bug, never a figure to report
            raise FloatingPointError(f"{level} film: the surface temperature rise exceeds the film's peak at path "
                                     f"positions {hot}")
        est = [max((e for e in getattr(r, "error_estimate", {}).values() if e is not None), default=None) for r in rs]
        t_est = [getattr(r, "temperature_estimate", None) for r in rs]
        return LevelFilm(level=level, method=method, central=np.array([r.hc for r in rs]),
                         minimum=np.array([r.hmin for r in rs]), pressure_max=np.array([r.pmax for r in rs]),
                         temperature_rise=np.array([r.dT_max for r in rs]),
                         error_estimate=None if None in est else np.array(est, dtype=float),
                         central_isothermal=np.array([r.hc_isothermal for r in rs]),
                         temperature_error_estimate=None if None in t_est else np.array(t_est, dtype=float),
                         spike_unresolved=spikes_unresolved(level, rs), thermal=_thermal_figures(case, w, T, rs))

    return film


def _thermal_figures(case: Case, w: np.ndarray, T: float, results: list) -> dict:
    """L_th, the two inlet factors, the TEHL and Blok flash temperatures at the path positions."""
    k = case.path
    return inlet_figures(results, w, k.R, k.ue, np.abs(k.srr), T, oil_law(case), reduced_modulus_of(case),
                         tehl_setup(case).props)


# ---------------------------------------------------------------- the TEHL options
def tehl_path_options(case: Case) -> dict:
    """The options of the line TEHL path sequences (:func:`femgear.physics.tehl.solver.tehl_path_results`) of the
    ``tehl`` level's path and of the ``tehl-point`` level's face slices: the case's EHL tolerance and first grid
    level, on spike-resolving grids (``spike=True``: the outlet spike's peak pressure and the film's peak
    temperature on it step from contact to contact on the plain grids, 7 % in second differences along the
    baseline's path; where a spike grid fails, :func:`~femgear.physics.tehl.solver.tehl_path_results` solves that
    contact on the plain grid of its level)."""
    n = case.numerics
    return {"tol": n.ehl_tol, "min_level": n.ehl_level, "spike": True}


def tehl_map_options(case: Case) -> dict:
    """The options of the line TEHL friction map of the ``tehl`` level: :func:`tehl_path_options` on the plain
    grids, since a map interpolates μ and the surface rise, integrals that the spike's grid does not move."""
    return {**tehl_path_options(case), "spike": False}


# ---------------------------------------------------------------- ranges checked up front
def check_tehl_envelope(case: Case) -> None:
    """Refuse a TEHL level up front above the pitch-line speed where its thermal loop does not settle
    (:func:`femgear.physics.tehl.solver.check_envelope`, a :class:`SceneError` naming ``physics.lubrication``)."""
    check_envelope(float(np.max(case.path.ue)), case.levels.lubrication)


# ---------------------------------------------------------------- the levels
def _uniform(case: Case, mu0: float) -> Solver:
    """μ = ``mu0`` everywhere and, for μ > 0, Blok's flash temperature of the Hertzian band with it (the heat a
    constant friction coefficient generates; 0 for μ = 0)."""
    E_red, solids = reduced_modulus_of(case), solids_of(case.material, case.oil)

    def constant(w, R, ue, srr, T):
        shape = np.broadcast(w, R, ue, srr, T).shape
        if mu0 == 0:
            return np.zeros(shape), np.zeros(shape)
        dT = line_flash_temperature(mu0, w, R, ue, np.abs(srr), E_red, solids.B1, solids.B2)
        return np.full(shape, mu0), np.broadcast_to(np.asarray(dT, dtype=float), shape).copy()

    return constant


@REGISTRY.register("none")
def _none(case: Case, repeated: bool = False) -> Lubrication:
    return _product(case, "none", _uniform(case, 0.0), _formula_film(case), friction=False, uniform=0.0, heats=False)


@REGISTRY.register("constant")
def _constant(case: Case, repeated: bool = False) -> Lubrication:
    """μ = ``friction.coefficient`` everywhere; the contact temperature rise is Blok's flash temperature with it,
    so the bulk flank temperature and the thermal growth follow the constant μ as they follow the other levels'."""
    mu0 = case.friction.coefficient
    return _product(case, "constant", _uniform(case, mu0), _formula_film(case), uniform=mu0)


@REGISTRY.register("formula")
def _formula(case: Case, repeated: bool = False) -> Lubrication:
    return _product(case, "formula", hertz_level_solver(line_friction(case)), _formula_film(case))


@REGISTRY.register("ehl-line")
def _ehl_line(case: Case, repeated: bool = False) -> Lubrication:
    solve = ehl_line_solver(oil_law(case), reduced_modulus_of(case), solids_of(case.material, case.oil),
                            case.oil.eyring_stress, tol=case.numerics.ehl_tol, min_level=case.numerics.ehl_level)
    return _product(case, "ehl-line", solve, _ehl_line_film(case))


@REGISTRY.register("tehl", check=check_tehl_envelope)
def _tehl(case: Case, repeated: bool = False) -> Lubrication:
    """``repeated``: the solver will be queried many times (the coupling loop): a friction map of the direct
    solves, built on first use."""
    setup, n = tehl_setup(case), case.numerics
    opts = tehl_path_options(case)
    solve = tehl_map_solver(setup, tehl_axes(case), **tehl_map_options(case)) if repeated else \
        tehl_line_solver(setup, **opts)

    def path(w, T):
        k = case.path
        return tehl_path_results(w, k.R, k.ue, np.abs(k.srr), T, setup, **opts)

    method = f"thermal line EHL (FD, graded grids, tolerance {100 * n.ehl_tol:g} %)"
    return _product(case, "tehl", solve, _thermal_film(case, method, path))


@REGISTRY.register("tehl-point", check=check_tehl_envelope)
def _tehl_point(case: Case, repeated: bool = False) -> Lubrication:
    """``repeated`` (the coupling loop): direct solves where any contact is an elliptic point contact (a friction
    map of point solves would cost ~170 of them; the path's 21+ direct solves are cheaper); where every contact is
    a line contact in face slices (an uncrowned pair, or ellipses all too slender for the point solver), the slices
    read off a line TEHL friction map over their envelope (:mod:`femgear.physics.tehl.slice_map`: ≈ 170 solves
    once, instead of seven per contact in every pass).  The film is solved directly either way."""
    solve, details = tehl_point_solver(case), []
    point = tehl_point_solver(case, details=details)
    if repeated:
        solve = slice_map_solver_of(case) or solve

    def path(w, T):
        k = case.path
        details.clear()
        point(w=w, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=np.full(w.shape, T))
        return list(details)

    method = f"thermal EHL of the crowned elliptic contacts, grid level {POINT_LEVEL}"
    return _product(case, "tehl-point", solve, _thermal_film(case, method, path))


def point_geometry(case: Case) -> tuple[CrownedContact, SliceGeometry]:
    """The case's crowned contact (its ``kappa`` 0 for an uncrowned pair: a line contact along the whole line) and
    the kinematics of its face slices."""
    pair = case.pair
    if sum(crowning(case)) > 0:
        geo = crowned_contact(pair, crowning(case))
    else:
        geo = CrownedContact(kappa=0.0, beta_b=pair.beta_b,
                             contact_length=pair.b / math.cos(pair.beta_b) * pair.eps_alpha / pair.eps_gamma)
    omega1 = 2.0 * math.pi * case.operating.pinion_rpm / 60.0
    slices = SliceGeometry(omega1=omega1, omega2=omega1 * pair.z1 / pair.z2, beta_b=pair.beta_b,
                           contact_length=geo.contact_length, kappa=geo.kappa)
    return geo, slices


def tehl_point_solver(case: Case, level: int | None = None, details: list | None = None, **options) -> Solver:
    """The ``tehl-point`` direct solver of the case (:func:`femgear.physics.tehl.point_level.tehl_point_solver`):
    its crowned contact, TEHL set-up and stationary roughness; ``level`` the point grid (default
    :data:`~femgear.physics.tehl.point_level.POINT_LEVEL`), ``details`` receives each contact's result."""
    rough = case.roughness
    geo, slices = point_geometry(case)
    return point_solver(geo, tehl_setup(case), tehl_path_options(case),
                        roughness=rough if (rough.peak or rough.synthetic) else None, level=level, details=details,
                        slices=slices, **options)


def slice_map_solver_of(case: Case) -> Solver | None:
    """The face slices of every contact read off a line TEHL friction map (:func:`femgear.physics.tehl.slice_map.
    slice_map_solver`, on the plain grids of :func:`tehl_map_options`) where every contact of the envelope is handed
    over to face slices; None where some are elliptic point contacts."""
    geo, slices = point_geometry(case)
    contact = envelope_contact(case)
    if not all_slender(geo, np.r_[contact.kin.R, case.path.R.ravel()]):
        return None
    setup = tehl_setup(case)
    axes = slice_map_axes(contact, geo, slices, setup.E_red, case.operating.ambient_temperature)
    return slice_map_solver(geo, slices, setup, axes, **tehl_map_options(case))


# ---------------------------------------------------------------- the case's lubrication
def lubrication_solver(case: Case, level: str | None = None, *, repeated: bool = False) -> Lubrication:
    """The :class:`Lubrication` of ``level`` (default: the case's ``physics.lubrication``).

    ``repeated``: the solver will be queried many times (the coupling loop): levels with
    a costly direct solve return a friction map of it instead (``tehl``).
    """
    return REGISTRY.build(level or case.levels.lubrication, case, repeated=repeated)


def bulk_temperature(case: Case, flank_rise: float = 0.0) -> float:
    """The bulk temperature the contacts' inlet and surfaces see [K]: the oil supply temperature
    (``operating.ambient_temperature``) plus the flanks' bulk rise ``flank_rise`` [K] where the run defines one
    (``thermal.flank_temperature_rise``, or the coupling loop's estimate of it); the oil laws carry η0, α and ρ
    there from the supply temperature."""
    return case.operating.ambient_temperature + float(flank_rise)


def friction_along_path(case: Case, w: np.ndarray, solver: Solver | None = None,
                        T: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """μ and the contact temperature rise at the case's path positions for loads ``w`` [N/m]."""
    k = case.path
    solver = solver or lubrication_solver(case)
    T = np.full(k.u.shape, case.operating.ambient_temperature) if T is None else T
    mu, dT = solver(w=np.broadcast_to(w, k.u.shape), R=k.R, ue=k.ue, srr=np.abs(k.srr), T=T)
    return np.asarray(mu, dtype=float), np.asarray(dT, dtype=float)


def static_friction(case: Case, line_load: np.ndarray | None = None) -> float | Callable[[np.ndarray], np.ndarray]:
    """μ for the dynamics without coupling: the level's one number where it has one (0 for ``none``,
    ``friction.coefficient`` for ``constant``), else μ(u) of the lubrication level at the static line load
    of the contact pass (load shared between the tooth pairs in contact,
    :func:`femgear.levels.contact.contact_pass`; U-shaped, zero at the pitch point), interpolated along the
    path.  ``line_load``: that pass's line load [N/m] when already known (it does not depend on the speed:
    a speed sweep computes it once)."""
    lubrication = lubrication_solver(case)
    if lubrication.uniform is not None:
        return lubrication.uniform
    u = case.path.u
    mu = friction_along_path(case, contact_pass(case).line_load if line_load is None else line_load, lubrication)[0]
    return lambda x: np.interp(x, u, mu)


def summary_level(level: str) -> str:
    """The level a scene summary computes μ with for the case's ``level``: itself where the catalogue marks it
    ``summarised`` (cheap: none, constant, formula), else ``formula`` (``femgear run`` carries every level's own
    μ)."""
    return level if REGISTRY.catalogue.spec(level).summarised else "formula"
