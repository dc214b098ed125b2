"""The film of the lubrication level that ran, along the path: central and minimum film, pressure peak.

The friction levels (:mod:`.levels`) return μ and ΔT only; what a user reads as "the film" must
come from the same level, labelled with it.  :func:`level_film` solves the level's own contact
model once per path position, at the run's load per length (the coupled passage mean, or the
static sharing) and the ambient bulk temperature:

| level                     | film                                                                    |
|---------------------------|-------------------------------------------------------------------------|
| none, constant, formula   | isothermal formulas: h_c Moes (1992) line fit, h_min Dowson–Higginson, p Hertz |
| ehl-line                  | FE isothermal line EHL (:func:`femgear.physics.ehl.dimensional.solve_line_dimensional`) |
| tehl                      | thermal line EHL (:func:`femgear.physics.tehl.line.solve_tehl_line`), direct solves |
| tehl-point                | thermal EHL of the crowned flanks' ellipses (:func:`femgear.physics.tehl.point.solve_tehl_point`) |

The direct solves cost what the level costs per position (a few tenths of a second for the line
levels, ~0.4 s for the point level); they run once per run, after the coupling.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.case import Case
from femgear.docfields import document_fields


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
    """maximum film temperature rise at each path position (thermal levels only, else None) [K]"""


def _formula(case: Case, w: np.ndarray, T: float, solver=None) -> LevelFilm:
    from femgear.physics.contact.film import line_film
    from femgear.physics.contact.hertz import hertz_line, reduced_modulus

    k, m, oil = case.path, case.material, case.scene.oil
    E_red = reduced_modulus(m.youngs_modulus, m.poisson_ratio)
    films = line_film(w, k.R, k.ue, E_red, oil.viscosity, oil.pressure_viscosity)
    p = np.array([hertz_line(wi, R, E_red).max_pressure for wi, R in zip(w, k.R)])
    return LevelFilm(level=case.levels.lubrication, method="isothermal formulas (Moes h_c, Dowson-Higginson h_min)",
                     central=films["central_moes"], minimum=films["minimum_dh"], pressure_max=p)


def _ehl_line(case: Case, w: np.ndarray, T: float, solver=None) -> LevelFilm:
    from femgear.physics.contact.hertz import reduced_modulus
    from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional
    from femgear.physics.lubrication.oil import OilLaw

    k, scene = case.path, case.scene
    oil = OilLaw.from_scene(scene)
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    ehl = EHLOil(eta0=float(oil.viscosity(0.0, T)), alpha=oil.alpha, viscosity="roelands", compressible=True)
    out, prev = [], None
    for wi, R, ue in zip(w, k.R, k.ue):
        r = solve_line_dimensional(float(wi), float(R), float(ue), E_red, ehl, level=scene.numerics.ehl_level,
                                   start=prev)
        prev = r.result
        out.append((r.hc, r.hmin, r.pmax))
    hc, hmin, pmax = np.array(out).T
    return LevelFilm(level="ehl-line", method=f"FE isothermal line EHL, grid level {scene.numerics.ehl_level}",
                     central=hc, minimum=hmin, pressure_max=pmax)


def _reused(solver, case: Case, w: np.ndarray, T: float) -> list | None:
    """The results of ``solver``'s latest call when it was at exactly these path inputs (else None)."""
    last = getattr(solver, "last", None)
    if last is None:
        return None
    k = case.path
    inputs = (w, k.R, k.ue, np.abs(k.srr), np.full(w.shape, T))
    same = all(a.shape == b.shape and np.array_equal(a, b) for a, b in zip(last[0], inputs))
    return last[1] if same else None


def _thermal(case: Case, w: np.ndarray, T: float, solver=None) -> LevelFilm:
    k, scene, level = case.path, case.scene, case.levels.lubrication
    if level == "tehl":
        from femgear.physics.tehl.line import solve_tehl_line
        from femgear.physics.tehl.solver import tehl_setup

        setup, grid = tehl_setup(scene), scene.numerics.ehl_level

        def solve(wi, R, ue, srr):
            return solve_tehl_line(wi, R, ue, srr, T, level=grid, **setup)

        method = f"thermal line EHL, grid level {grid}"
    else:
        from femgear.physics.tehl.point_level import POINT_LEVEL, tehl_point_solver

        results: list = []
        point = tehl_point_solver(scene, pair=case.pair, details=results)

        def solve(wi, R, ue, srr):
            point(w=wi, R=R, ue=ue, srr=srr, T=T)
            return results[-1]

        method = f"thermal EHL of the crowned elliptic contacts, grid level {POINT_LEVEL}"
    rs = _reused(solver, case, w, T) or [solve(float(wi), float(R), float(ue), abs(float(s)))
                                           for wi, R, ue, s in zip(w, k.R, k.ue, k.srr)]
    return LevelFilm(level=level, method=method, central=np.array([r.hc for r in rs]),
                     minimum=np.array([r.hmin for r in rs]), pressure_max=np.array([r.pmax for r in rs]),
                     temperature_rise=np.array([r.dT_max for r in rs]))


FILMS = {"none": _formula, "constant": _formula, "formula": _formula, "ehl-line": _ehl_line,
         "tehl": _thermal, "tehl-point": _thermal}


def level_film(case: Case, load_per_length: np.ndarray, temperature: float | None = None, solver=None) -> LevelFilm:
    """The film of ``case``'s lubrication level at the loads ``load_per_length`` [N/m] along the path,
    at the bulk ``temperature`` [K] (default: the ambient temperature).  ``solver``: the run's lubrication
    solver; where it keeps its latest direct solves (``tehl-point``) at these very inputs, they are reused."""
    w = np.broadcast_to(np.asarray(load_per_length, dtype=float), case.path.u.shape)
    T = case.operating.ambient_temperature if temperature is None else temperature
    film = FILMS[case.levels.lubrication](case, w, T, solver)
    for name in ("central", "minimum", "pressure_max"):
        a = getattr(film, name)
        if a.shape != w.shape or not np.all(np.isfinite(a)) or np.any(a <= 0):
            raise FloatingPointError(f"{film.level} film: {name} is not positive and finite along the path")
    return film
