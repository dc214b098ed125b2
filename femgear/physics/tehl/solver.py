"""The ``tehl`` lubrication level in the map signature, and a friction map built from it.

``solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise)`` as every lubrication level
(:mod:`femgear.physics.lubrication.map`): μ is the sliding friction |μ_couette| of
:func:`solve_tehl_line`, the temperature rise is the contact (surface, flash) temperature rise, the larger of the
two bodies' [K]: what the flanks' thermal models and the scuffing ratings read, as Blok's flash temperature of the
other levels.  (The film's own peak, inside it on the outlet pressure spike, steps from one path position to the
next as the spike crosses the cells of the plain grids: up to 8 % of its maximum in second differences along the
baseline's path, against 1 % for the surface temperature; 0.7 % on the spike-resolving grids the path sequences
solve on (``spike=True``; the friction map, which interpolates μ and the surface rise, solves on plain grids); it
stays the film's ``temperature_rise``.)
The isothermal start is shared between the contacts of a sequence that differ only in SRR (the points of a
friction map: one in seven solved; ``isothermal`` of :func:`solve_tehl_line`), and on a map's single level each
such contact's thermal loop starts from the converged temperatures, pressure and film of its slower-sliding
neighbour (continuation in SRR).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.contact.film import moes_line
from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.ehl.fd.line import DEFAULT_TOL, MAX_LEVEL
from femgear.physics.ehl.fd.line_grid import SPIKE_DENSITY, SPIKE_DENSITY_GENTLE
from femgear.physics.lubrication.map import DT_FLOOR, MU_FLOOR, MU_TOLERANCE, FrictionMap
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.path import solids_of
from femgear.physics.lubrication.traction import Solids
from femgear.physics.tehl.energy import ThermalProps
from femgear.physics.tehl.line import DEFAULT_LAYERS, MAX_LAYERS, TEHLResult, ehl_oil_at, solve_tehl_line
from femgear.physics.tehl.reuse import LatestSolve, RecordingSolver

LINE_SECONDS = 0.3    #: rough wall time of one TEHL line solve (announce and progress only) [s]


def map_progress(stage: str, total: int, seconds_each: float):
    """Announce ``total`` solves of ``seconds_each`` (:func:`femgear.perf.announce`, logged at INFO, by default
    when long) and return a :class:`femgear.perf.Progress` called with the number done before each solve."""
    from femgear.perf import Estimate, Progress, announce

    est = Estimate(f"{stage}: {total} contacts", 0, 0.0, total * seconds_each)
    if total > 1:
        announce(est, "physics.lubrication")
    return Progress(stage, total, est.seconds)


def thermal_props(solids: Solids, oil_specific_heat: float, conductivity: float | None = None) -> ThermalProps:
    """Oil conductivity and specific heat [J/(kg K)], solid effusivities of :class:`Solids` and the solids'
    ``conductivity`` [W/(m K)] (both members; None: the high-Péclet Jaeger operator for the solids)."""
    return ThermalProps(k_oil=solids.k_oil, c_oil=oil_specific_heat, B1=solids.B1, B2=solids.B2, k1=conductivity,
                        k2=conductivity)


@dataclass(frozen=True)
class TEHLSetup:
    """The oil, solids and traction parameters of the TEHL solves (:func:`solve_tehl_line`,
    :func:`femgear.physics.tehl.point.solve_tehl_point`)."""

    oil: OilLaw
    """viscosity and density laws of the oil"""
    props: ThermalProps
    """oil conductivity and specific heat, solid effusivities"""
    E_red: float
    """reduced modulus E' [Pa]"""
    tau0: float
    """Eyring stress τ0 [Pa]"""
    limiting_shear: float
    """limiting shear stress coefficient Λ (τ_L = Λ p; 0: none) [-]"""

    @classmethod
    def from_tables(cls, material, oil, reference_temperature: float) -> TEHLSetup:
        """The set-up of a ``[material]`` (one steel, both members) and an ``[oil]`` table whose viscosity
        holds at ``reference_temperature`` [K]."""
        return cls(oil=OilLaw.from_table(oil, reference_temperature),
                   props=thermal_props(solids_of(material, oil), oil.specific_heat, material.conductivity),
                   E_red=reduced_modulus(material.youngs_modulus, material.poisson_ratio), tau0=oil.eyring_stress,
                   limiting_shear=oil.limiting_shear_coeff)

    def kwargs(self) -> dict:
        """The keyword arguments of :func:`solve_tehl_line` and ``solve_tehl_point`` it sets."""
        return {"oil": self.oil, "props": self.props, "E_red": self.E_red, "tau0": self.tau0,
                "limiting_shear": self.limiting_shear}


def tehl_line_solver(setup: TEHLSetup, level: int | None = None, **options):
    """Direct TEHL solves (one per point, :func:`tehl_path_results`: on one grid level for all) in the map
    signature; ``options`` go to :func:`solve_tehl_line` (e.g. ``tol``, ``min_level``, ``nz``, ``model``);
    the solver's :attr:`~femgear.physics.tehl.reuse.RecordingSolver.latest` holds the inputs and results of the
    latest call (the level's film reuses them)."""

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                 for a in (w, R, ue, srr, T)))
        results = []
        for t in np.unique(T):      # the oil temperatures of the query, one sequence each
            at = T == t
            rs = tehl_path_results(w[at], R[at], ue[at], srr[at], float(t), setup, level=level, **options)
            results += list(zip(np.flatnonzero(at), rs))
        rs = [r for _, r in sorted(results, key=lambda x: x[0])]
        latest = LatestSolve((w.copy(), R.copy(), ue.copy(), srr.copy(), T.copy()), tuple(rs))
        return (np.array([r.mu for r in rs]).reshape(w.shape), np.array([r.dT_surface for r in rs]).reshape(w.shape),
                latest)

    return RecordingSolver(solve)


def tehl_path_results(w, R, ue, srr, T: float, setup: TEHLSetup, *, level: int | None = None,
                      start_level: int | None = None, **options) -> list[TEHLResult]:
    """TEHL line solves at the contacts (arrays ``w``, ``R``, ``ue``, ``srr``; oil at ``T`` [K]) on one grid
    level: ``level``, or the one that the tolerance-driven solve of the contact with the largest Moes M (the
    thinnest film for its width, which needs the finest grid) picks, with its layers across the film (refined for
    its films and its peak temperature rise, :func:`solve_tehl_line`), kept for the others, so that the fields
    of a path or map are smooth to the solver's tolerance (a level that changed from point to point would step
    them by up to that tolerance); when another contact's estimate then exceeds the tolerance, the whole sequence
    is solved once more, finer where that contact's error lies (:func:`_finer`: twice the layers across the film, or
    one level finer along it; from the first contact that exceeds it: the contacts are solved fastest
    sliding first, the hottest, where the estimate grows, so that few solves are discarded; the others are checked
    on their films' estimate, their peak rise's estimate is reported in each result).  ``start_level``: the level a similar sequence ended on (the face slices
    of the previous contact), tried first instead of the probe's choice, with the same check and refinement: the
    answer still meets the tolerance, and a sequence that needs that level is not solved twice.  ``options`` to
    :func:`solve_tehl_line` (``tol``, ``min_level``, ...)."""
    w, R, ue, srr = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, srr)))
    kw = {**setup.kwargs(), **options, "isothermal": {}}   # the contacts that differ only in SRR share their start
    out: list = [None] * w.size
    progress = map_progress("TEHL line solves", w.size, LINE_SECONDS)
    if level is None and start_level is not None:
        level, auto = max(start_level, options.get("min_level") or 0), True
    elif level is None:
        oil = ehl_oil_at(setup.oil, T)
        E = setup.E_red
        M = [moes_line(wi / (E * Ri), oil.eta0 * ui / (E * Ri), oil.alpha * E)[0] for wi, Ri, ui in zip(w, R, ue)]
        first = int(np.argmax(M))
        progress(0)
        out[first] = _one(first, w, R, ue, srr, T, kw)
        level = _level_of_nodes(out[first].nodes)
        if _gentler(out[first], kw):
            return tehl_path_results(w, R, ue, srr, T, setup, **_gentle(options, level, out[first].layers, True))
        options = {**options, "nz": out[first].layers}   # the probe's layers too (refined for its peak rise)
        kw["nz"] = out[first].layers
        auto = True
    else:
        auto = False
    kw.pop("min_level", None)
    tol = kw.get("tol", DEFAULT_TOL)
    # the fastest-sliding (hottest) contacts first: they are the ones whose estimate exceeds the tolerance on the
    # probe's level, and the sequence is abandoned at the first that does (its other solves would be discarded);
    # on a given level the contacts that differ only in SRR one after the other, slowest sliding first, each
    # starting from the last one's temperatures (``isothermal`` of :func:`solve_tehl_line`)
    order = (lambda j: -abs(srr.flat[j]) * ue.flat[j]) if auto else \
        (lambda j: (w.flat[j], R.flat[j], ue.flat[j], abs(srr.flat[j])))
    sequence = sorted(range(w.size), key=order)
    if auto and kw.get("spike"):    # the slowest-sliding contact first, where a steep spike bump stalls (_gentler)
        sequence.insert(0, sequence.pop())
    for done, i in enumerate(sequence):
        if out[i] is None:
            progress(done)
            out[i] = _one(i, w, R, ue, srr, T, {**kw, "level": level})
            if _gentler(out[i], kw):     # a spike grid that failed: the whole sequence on the gentler bump, once
                return tehl_path_results(w, R, ue, srr, T, setup, **_gentle(options, level, kw.get("nz"), auto))
            finer = _finer(out[i], level, options, tol) if auto and _estimate(out[i]) > tol else None
            if finer is not None:   # a position other than the probe needs more: the whole sequence finer, once
                return tehl_path_results(w, R, ue, srr, T, setup, **finer)
    return out


def _finer(r: TEHLResult, level: int, options: dict, tol: float) -> dict | None:
    """The options of a sequence one step finer than the one whose contact ``r`` (on ``level``) missed ``tol``:
    twice the layers across the film where the contact's isothermal start met the tolerance on this level, else
    one level finer along the film; None when neither can be refined.  The thermal levels below the top one halve
    the layers with the cells (:meth:`femgear.physics.tehl.line._Run.layers`), so the estimate covers both
    directions; a finer level along x keeps the layers, and where the isothermal film (no layers) is resolved on
    the level, the excess is the cross-film error, which only more layers reduce.  Measured on the turbo zoo pair's
    path (position 21, 1025 nodes, 16 layers: estimate 1.34 %): 2049 nodes moved h_c by 0.11 % and left the
    estimate at 1.26 %; 16 → 32 → 64 layers at the VG 32, 40 °C, 60 m/s, 2.5 GPa corner moved it 1.0 and 0.2 %."""
    nz = options.get("nz", DEFAULT_LAYERS)
    if r.isothermal_estimate is not None and r.isothermal_estimate <= tol and nz < MAX_LAYERS:
        return {**options, "level": level, "nz": 2 * nz}
    if level < MAX_LEVEL:
        return {**options, "level": level + 1}
    return None


def _gentler(r: TEHLResult, kw: dict) -> bool:
    """Whether contact ``r`` of a sequence solved with the options ``kw`` lost its spike grid in the thermal solve
    (:func:`_one`: solved on the plain grid instead) and the sequence's bump is steeper than
    :data:`~femgear.physics.ehl.fd.line_grid.SPIKE_DENSITY_GENTLE`.  On the steep bump (:data:`SPIKE_DENSITY`), cells
    down to 0.0003 b at the spike, the thermal loop of a heavy contact near rolling can stall: on the marine zoo
    pair (M 16, L 11.7, 1025 nodes) the change per iteration stays at 0.3-2 K at the wall cells just downstream of
    the spike, at 15 of 62 path positions (|SRR| < 0.17), against a tolerance of 0.1 K; on the gentle bump all
    settle in 30-45 iterations.  A bump whose isothermal start failed (its coarse levels' Newton; said in the
    result's ``history["spike"]``, the thermal solve then on the plain domain) does not count: the gentle bump's
    fewer nodes across the spike would not resolve a light contact's spike on the level the sequence is on (the
    baseline's first face slices, M 3.6, L 15.1: 5-10 nodes across on 513 nodes, the peak pressure 9 % low)."""
    if not kw.get("spike") or kw.get("spike_density", SPIKE_DENSITY) <= SPIKE_DENSITY_GENTLE:
        return False
    return any(str(c.get("reason", "")).startswith(SPIKE_LOST) for c in r.history.get("continuation", ()))


def _gentle(options: dict, level: int, nz: int | None, auto: bool) -> dict:
    """``options`` of a sequence on :data:`~femgear.physics.ehl.fd.line_grid.SPIKE_DENSITY_GENTLE` (:func:`_gentler`):
    the ``level`` and layers ``nz`` the sequence had reached, still refined for the tolerance where the level was
    the solver's choice (``auto``: as ``start_level``)."""
    return {**options, ("start_level" if auto else "level"): level, **({"nz": nz} if nz else {}),
            "spike_density": SPIKE_DENSITY_GENTLE}


def _estimate(r) -> float:
    return max((e for e in r.error_estimate.values() if e is not None), default=0.0)


SPIKE_LOST = "spike grid failed, solved on the plain grid"
"""the ``continuation`` reason of a contact whose spike grid failed (:func:`_one`, read by :func:`_gentler`)"""


def _one(i: int, w, R, ue, srr, T, kw) -> TEHLResult:
    """One contact of a sequence.  A spike-resolving grid whose solve fails (its bump packs the nodes where the
    Newton steps of a heavy, fast-sliding contact are largest) hands the contact to the plain grid of the same
    level, said in the result's history (a ``"continuation"`` entry); the plain grid's failure raises with both
    histories."""
    args = (float(w[i]), float(R[i]), float(ue[i]), float(srr[i]), T)
    try:
        return solve_tehl_line(*args, **kw)
    except ConvergenceError as exc:
        if not kw.get("spike"):
            raise ConvergenceError(f"tehl path position {i}", str(exc), exc.history) from exc
        first = exc
    try:
        r = solve_tehl_line(*args, **{**kw, "spike": False})
    except ConvergenceError as exc:
        raise ConvergenceError(f"tehl path position {i}", f"{first}; on the plain grid: {exc}",
                               {**{f"spike {k}": v for k, v in first.history.items()},
                                **{f"plain {k}": v for k, v in exc.history.items()}}) from exc
    r.history.setdefault("continuation", []).append(
        {"level": _level_of_nodes(r.nodes), "reason": f"{SPIKE_LOST}: {str(first)[:160]}"})
    return r


def _level_of_nodes(nodes: int) -> int:
    return int(round(math.log2((nodes - 1) / 16)))


def tehl_map_axes(contact, ambient_temperature: float, load_range=(0.5, 2.0),
                  temperature_span: float = 40.0) -> dict[str, np.ndarray]:
    """Small map axes over the path of a contact pass (:class:`femgear.physics.contact.path.ContactPath`;
    3 x 2 x 2 x 7 x 2 = 168 TEHL solves); oil from ``ambient_temperature`` to ``temperature_span`` above [K]."""
    k = contact.kin
    return envelope_axes(contact.load_per_length * np.geomspace(*load_range, 3), k.R, k.ue, k.srr,
                         ambient_temperature, temperature_span)


def envelope_axes(w, R, ue, srr, ambient_temperature: float, temperature_span: float = 40.0) -> dict[str, np.ndarray]:
    """Map axes over contacts of radii ``R``, entrainment speeds ``ue`` and SRR ``srr`` (arrays, any sign): the
    load axis ``w`` as given, two radii and two speeds just beyond the contacts' extremes, seven SRR from rolling to
    just beyond the fastest sliding (denser at low sliding, where μ rises steeply), two oil temperatures
    (``ambient_temperature`` and ``temperature_span`` above) [K]."""
    smax = 1.05 * float(np.max(np.abs(srr)))
    T0 = ambient_temperature
    return {"w": np.asarray(w, dtype=float),
            "R": np.array([0.98 * np.min(R), 1.02 * np.max(R)]),
            "ue": np.array([0.95 * np.min(ue), 1.05 * np.max(ue)]),
            "srr": np.r_[0.0, smax * np.array([0.01, 0.04, 0.12, 0.3, 0.6, 1.0])],
            "T": np.array([T0, T0 + temperature_span])}


def tehl_map(setup: TEHLSetup, axes: dict, level: int | None = None, validate: int = 0, seed: int = 0,
             **options) -> FrictionMap:
    """A :class:`FrictionMap` of TEHL solves over ``axes`` (grid ``level``; None: :func:`map_level`, kept for all
    points; ``options`` to :func:`solve_tehl_line`);
    ``validate`` > 0 measures its error against that many fresh TEHL solves at random envelope points."""
    if level is None:
        level = map_level(setup, axes, **options)
    options.pop("min_level", None)
    solver = tehl_line_solver(setup, level=level, estimate=False, **options)
    fmap = FrictionMap.build(solver, axes)
    return fmap.validate(solver, samples=validate, seed=seed) if validate else fmap


#: the largest difference of μ (relative to max(μ, 0.005)) and of the surface rise (relative to max(ΔT, 1 K)) between
#: two grid levels at the probes of :func:`map_level` for which a map is built on the coarser one: half the map's
#: interpolation tolerance :data:`~femgear.physics.lubrication.map.MU_TOLERANCE`
GRID_TOLERANCE = 0.5 * MU_TOLERANCE
MIN_MAP_LEVEL = 4   #: the coarsest level a map is built on (257 nodes)


def map_level(setup: TEHLSetup, axes: dict, **options) -> int:
    """The grid level of a friction map over ``axes``: the level that the heaviest corner's tolerance-driven solve
    picks for its films (``options`` to :func:`solve_tehl_line`), or one level coarser where μ and the surface
    rise, the two fields a map holds, agree between the two levels to :data:`GRID_TOLERANCE` at 8 probes (the
    envelope's extreme loads and radii, a small and the largest SRR, at the fastest entrainment and the supply
    temperature, where the levels differ most on the turbo and baseline maps; solved until one misses).  The films come
    from the path's direct solves, so the level they need does not bind the map where its own fields are
    resolved: the turbo zoo pair's map on 513 nodes is within 1.3 % of μ and 0.13 K of the map on 2049 nodes, its
    films' 1025 within 0.35 %; the baseline's light-load, slow-sliding μ, which converges at first order (a
    Newtonian μ from the spike's viscosity), keeps its films' 513 nodes (within 6 % of 2049 nodes' μ there)."""
    film = _level_of_nodes(solve_tehl_line(*_corner(axes), **setup.kwargs(), **options).nodes)
    coarse = film - 1
    if coarse < max(options.get("min_level") or 0, MIN_MAP_LEVEL):
        return film
    kw = {k: v for k, v in options.items() if k != "min_level"}
    coarse_solve = tehl_line_solver(setup, level=coarse, estimate=False, **kw)
    film_solve = tehl_line_solver(setup, level=film, estimate=False, **kw)
    for w, srr, R in itertools.product(axes["w"][[0, -1]], axes["srr"][[2, -1]], axes["R"][[0, -1]]):
        probe = dict(w=w, R=R, ue=axes["ue"][-1], srr=srr, T=axes["T"][0])   # the likeliest misses first
        try:
            mu_c, dT_c = coarse_solve(**probe)
        except ConvergenceError:
            return film
        mu, dT = film_solve(**probe)
        err = max(float(np.max(np.abs(mu_c - mu) / np.maximum(mu, MU_FLOOR))),
                  float(np.max(np.abs(dT_c - dT) / np.maximum(dT, DT_FLOOR))))
        if err > GRID_TOLERANCE:
            return film
    return coarse


#: fresh TEHL solves at random envelope points that measure the ``tehl`` level's friction map (about 7 % of its
#: 168 solves): its error goes into the run's summary beside its tolerance, flagged above it
MAP_VALIDATION = 12


def tehl_map_solver(setup: TEHLSetup, axes: dict, level: int | None = None, validate: int = MAP_VALIDATION,
                    **options):
    """The ``tehl`` level for the coupling loop: a :func:`tehl_map` over ``axes`` built on first use
    (≈ 170 TEHL solves) and measured against ``validate`` fresh solves, queried by interpolation; the
    solver's ``friction_map()`` is the map (None before the first query).  Queries outside the envelope are
    clamped to its edges (the dynamic load may leave the 0.5–2 × nominal band briefly
    at the ends of the path)."""
    cache: dict = {}

    def solve(w, R, ue, srr, T):
        if "map" not in cache:
            cache["map"] = tehl_map(setup, axes=axes, level=level, validate=validate, **options)
        fmap = cache["map"]
        args = [np.clip(np.abs(a) if k == "srr" else np.asarray(a, dtype=float), fmap.axes[k][0], fmap.axes[k][-1])
                for k, a in zip(("w", "R", "ue", "srr", "T"), (w, R, ue, srr, T))]
        return fmap(*args)

    solve.cache = cache
    solve.friction_map = lambda: cache.get("map")
    return solve


#: The TEHL envelope's entrainment speed [m/s]: the line TEHL converges and is checked to here
#: (studies/benchmarks/tehl_envelope.py; issue 43 asked for 60 m/s, the turbo zoo pair reaches 57 m/s and pairs of
#: 200 m/s pitch-line speed about 85 m/s)
MAX_ENTRAINMENT = 100.0


def _corner(axes: dict) -> tuple[float, float, float, float, float]:
    """(w, R, ue, srr, T) of the map envelope's heaviest corner: the largest load, smallest radius and
    entrainment speed, rolling, the hottest oil (M grows and L falls with each)."""
    return (float(axes["w"].max()), float(axes["R"].min()), float(axes["ue"].min()), 0.0, float(axes["T"].max()))


def check_envelope(ue_max: float, level: str) -> None:
    """Refuse the TEHL ``level`` up front where the path's largest entrainment speed ``ue_max`` [m/s] is beyond
    :data:`MAX_ENTRAINMENT`, naming the levels that run there."""
    if ue_max > MAX_ENTRAINMENT:
        raise SceneError("physics.lubrication", f'"{level}": the entrainment speed reaches {ue_max:.0f} m/s, above '
                         f"the {MAX_ENTRAINMENT:g} m/s of the TEHL envelope (converged and validated to there); use "
                         '"ehl-line" or "formula"')


def map_corner_moes(axes: dict, oil: OilLaw, E_red: float) -> tuple[float, float]:
    """Moes (M, L) of the map envelope's heaviest corner (:func:`_corner`)."""
    from femgear.physics.contact.film import moes_line

    w, R, ue, _, T = _corner(axes)
    eta = float(oil.viscosity(0.0, T))
    return tuple(float(x) for x in moes_line(w / (E_red * R), eta * ue / (E_red * R), oil.alpha * E_red))
