"""The ``tehl`` lubrication level in the map signature, and a friction map built from it.

``solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise)`` as every lubrication level
(:mod:`femgear.physics.lubrication.map`): μ is the sliding friction |μ_couette| of
:func:`solve_tehl_line`, the temperature rise is the maximum film temperature rise [K].
The isothermal start is shared between points that differ only in SRR (cached per call).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.lubrication.map import FrictionMap
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.path import solids_of
from femgear.physics.lubrication.traction import Solids
from femgear.physics.tehl.energy import ThermalProps
from femgear.physics.tehl.line import solve_tehl_line

#: the retry of a map point whose thermal loop did not settle to 0.1 K in the default 100 passes (relaxation
#: 0.8): the marine pair's corner at 2x the load, +40 K and pure rolling toggles by 0.39 K between passes
#: (a limit cycle of the discrete inlet, not slow convergence: 300 passes at relaxation 0.5 keep it), so the
#: retry accepts 0.5 K there, with stronger under-relaxation
DAMPED = {"relax": 0.5, "max_iter": 300, "tol": 0.5}
LINE_SECONDS = 0.3    #: rough wall time of one TEHL line solve at grid level 4 (announce and progress only) [s]


def map_progress(stage: str, total: int, seconds_each: float):
    """Announce ``total`` solves of ``seconds_each`` (:func:`femgear.perf.announce`, logged at INFO, by default
    when long) and return a :class:`femgear.perf.Progress` called with the number done before each solve."""
    from femgear.perf import Estimate, Progress, announce

    est = Estimate(f"{stage}: {total} contacts", 0, 0.0, total * seconds_each)
    if total > 1:
        announce(est, "physics.lubrication")
    return Progress(stage, total, est.seconds)


def thermal_props(solids: Solids, oil_specific_heat: float) -> ThermalProps:
    """Oil conductivity and specific heat [J/(kg K)], solid effusivities of :class:`Solids`."""
    return ThermalProps(k_oil=solids.k_oil, c_oil=oil_specific_heat, B1=solids.B1, B2=solids.B2)


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
        return cls(oil=OilLaw.from_table(oil, reference_temperature), props=thermal_props(solids_of(material, oil),
                                                                                         oil.specific_heat),
                   E_red=reduced_modulus(material.youngs_modulus, material.poisson_ratio), tau0=oil.eyring_stress,
                   limiting_shear=oil.limiting_shear_coeff)

    def kwargs(self) -> dict:
        """The keyword arguments of :func:`solve_tehl_line` and ``solve_tehl_point`` it sets."""
        return {"oil": self.oil, "props": self.props, "E_red": self.E_red, "tau0": self.tau0,
                "limiting_shear": self.limiting_shear}


def tehl_line_solver(setup: TEHLSetup, level: int, **options):
    """Direct TEHL solves (one per point, grid ``level``) in the map signature; ``options`` go to
    :func:`solve_tehl_line` (e.g. ``cells``, ``nz``, ``model``)."""
    kw = {**setup.kwargs(), **options}

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                 for a in (w, R, ue, srr, T)))
        mu, dT = np.empty(w.shape), np.empty(w.shape)
        progress = map_progress(f"TEHL line solves (level {level})", w.size, LINE_SECONDS * 2.0 ** (level - 4))
        for n, i in enumerate(np.ndindex(w.shape)):
            progress(n)
            args = (float(w[i]), float(R[i]), float(ue[i]), float(srr[i]), float(T[i]))
            try:
                r = solve_tehl_line(*args, level=level, **kw)
            except ConvergenceError:     # a slowly settling thermal loop (heavy, hot envelope corners)
                r = solve_tehl_line(*args, level=level, **{**kw, **DAMPED})
            mu[i], dT[i] = r.mu, r.dT_max
        return mu, dT

    return solve


def tehl_map_axes(contact, ambient_temperature: float, load_range=(0.5, 2.0),
                  temperature_span: float = 40.0) -> dict[str, np.ndarray]:
    """Small map axes over the path of a contact pass (:class:`femgear.physics.contact.path.ContactPath`;
    3 x 2 x 2 x 7 x 2 = 168 TEHL solves); oil from ``ambient_temperature`` to ``temperature_span`` above [K]."""
    k = contact.kin
    T0 = ambient_temperature
    smax = 1.05 * float(np.max(np.abs(k.srr)))
    return {"w": contact.load_per_length * np.geomspace(*load_range, 3),
            "R": np.array([0.98 * k.R.min(), 1.02 * k.R.max()]),
            "ue": np.array([0.95 * k.ue.min(), 1.05 * k.ue.max()]),
            "srr": np.r_[0.0, smax * np.array([0.01, 0.04, 0.12, 0.3, 0.6, 1.0])],
            "T": np.array([T0, T0 + temperature_span])}


def tehl_map(setup: TEHLSetup, axes: dict, level: int = 4, validate: int = 0, seed: int = 0) -> FrictionMap:
    """A :class:`FrictionMap` of TEHL solves (grid ``level``) over ``axes``; ``validate`` > 0 measures its
    error against that many fresh TEHL solves at random envelope points."""
    solver = tehl_line_solver(setup, level=level)
    fmap = FrictionMap.build(solver, axes)
    return fmap.validate(solver, samples=validate, seed=seed) if validate else fmap


def tehl_map_solver(setup: TEHLSetup, axes: dict, level: int = 4):
    """The ``tehl`` level for the coupling loop: a :func:`tehl_map` over ``axes`` built on first use
    (≈ 170 TEHL solves), queried by interpolation.  Queries outside the envelope are
    clamped to its edges (the dynamic load may leave the 0.5–2 × nominal band briefly
    at the ends of the path)."""
    cache: dict = {}

    def solve(w, R, ue, srr, T):
        if "map" not in cache:
            cache["map"] = tehl_map(setup, axes=axes, level=level)
        fmap = cache["map"]
        args = [np.clip(np.abs(a) if k == "srr" else np.asarray(a, dtype=float), fmap.axes[k][0], fmap.axes[k][-1])
                for k, a in zip(("w", "R", "ue", "srr", "T"), (w, R, ue, srr, T))]
        return fmap(*args)

    solve.cache = cache
    return solve


#: The largest Moes M of the ``tehl`` map's envelope that the line EHL solver is validated at (Moes's line film to
#: 1.2 % at (200, 10), README) and starts from Hertz at: the wind zoo stage's corner (346, 3.5) does not
#: (neither does 216 at that L); the other zoo pairs' corners stay below 200
MAX_MAP_M = 200.0

#: Pitch-line speed above which the TEHL levels are refused [m/s]: the turbo zoo pair (131 m/s, entrainment
#: up to 42 m/s) does not settle its thermal loop (a 12 K temperature change after 300 damped passes), the
#: other zoo pairs (≤ 13 m/s) and the TEHL validation cases (≤ 20 m/s) do; the film and friction formulas are
#: fitted below it too (:mod:`femgear.scene.plausibility`)
MAX_TEHL_SPEED = 100.0


def check_tehl_speed(pair, pinion_rpm: float, level: str) -> None:
    """Refuse the TEHL ``level`` up front above :data:`MAX_TEHL_SPEED` (pitch-line speed of ``pair`` at
    ``pinion_rpm``), naming the levels that run there."""
    v = 2.0 * math.pi * pair.rw1 * pinion_rpm / 60.0
    if v > MAX_TEHL_SPEED:
        raise SceneError("physics.lubrication", f'"{level}": the pitch-line speed {v:.0f} m/s is '
                         f"above {MAX_TEHL_SPEED:g} m/s, where the TEHL thermal loop does not settle; use "
                         '"ehl-line" or "formula"')


def check_map_corner(axes: dict, oil: OilLaw, E_red: float) -> None:
    """Refuse the ``tehl`` map up front where its heaviest corner (:func:`map_corner_moes`) is above
    :data:`MAX_MAP_M`."""
    M, L = map_corner_moes(axes, oil, E_red)
    if M > MAX_MAP_M:
        raise SceneError("physics.lubrication", f'"tehl": its friction map reaches Moes M = {M:.0f} (L = {L:.2g}) '
                         f"at twice the load and +40 K, above M = {MAX_MAP_M:g}, the largest at which the line "
                         'EHL solver is validated and starts; use "ehl-line" (direct solves at the path\'s loads)')


def map_corner_moes(axes: dict, oil: OilLaw, E_red: float) -> tuple[float, float]:
    """Moes (M, L) of the map envelope's heaviest corner: the largest load, smallest radius and entrainment
    speed and the hottest oil of the map ``axes`` (:func:`tehl_map_axes`; M grows and L falls with each)."""
    from femgear.physics.contact.film import moes_line

    w, R, ue, T = axes["w"].max(), axes["R"].min(), axes["ue"].min(), axes["T"].max()
    eta = float(oil.viscosity(0.0, T))
    return tuple(float(x) for x in moes_line(w / (E_red * R), eta * ue / (E_red * R), oil.alpha * E_red))
