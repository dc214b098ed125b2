"""Thermal levels (the ``[physics] thermal`` key): the flank deviation from tooth growth.

Each level is a function of the pair and numbers, ζ_T(u) along the normal line of action
(:data:`PAIR_LEVELS`, dispatched for a bare pair by :func:`flank_deviation`); the registered
factory of a level returns the case's :class:`femgear.physics.body.thermal_units.ThermalUnits`
(ζ_T of both members for a unit flank and a unit shaft rise; the conduction and thermo-elastic
problems are linear), or None for ``none`` (no thermal growth).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from femgear.levels.registry import Registry

if TYPE_CHECKING:
    from femgear.case import Case
    from femgear.physics.body.thermal_units import ThermalUnits
    from femgear.physics.geometry import GearPair

REGISTRY = Registry("thermal")


def _none(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
          **_: Any) -> np.ndarray:
    return np.zeros(np.shape(np.asarray(u, float)))


def _analytic(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
              poisson_ratio: float = 0.3, bore_radius: float = 0.0, **_: Any) -> np.ndarray:
    from femgear.physics.body.thermal import analytic_flank_deviation

    return analytic_flank_deviation(pair, member, u, dT_flank, dT_shaft, expansion, poisson_ratio, bore_radius)


def _fe(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
        youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, conductivity: float = 46.0,
        bore_radius: float = 0.0, h: float | None = None, **_: Any) -> np.ndarray:
    from femgear.physics.body.thermal import fe_flank_deviation

    return fe_flank_deviation(pair, member, u, dT_flank, dT_shaft, expansion, youngs_modulus, poisson_ratio,
                              conductivity, bore_radius, h)


def _fe3d(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
          youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, bore_radius: float = 0.0, groove: float = 0.0,
          stagger: float = 0.0, body_level: int = 1, **_: Any) -> np.ndarray:
    from femgear.physics.ltca.thermal import fe3d_flank_deviation

    return fe3d_flank_deviation(pair, member, u, dT_flank, dT_shaft, expansion, youngs_modulus, poisson_ratio,
                                bore_radius, groove, stagger, body_level)


#: level name -> ζ_T(u) of one member for a bare pair (the keywords of :func:`flank_deviation`)
PAIR_LEVELS: dict[str, Callable[..., np.ndarray]] = {"none": _none, "analytic": _analytic, "fe": _fe, "fe3d": _fe3d}


def flank_deviation(pair: GearPair, member: int, u, level: str, dT_flank: float, dT_shaft: float,
                    expansion: float, youngs_modulus: float = 210e9, poisson_ratio: float = 0.3,
                    conductivity: float = 46.0, bore_radius: float = 0.0, h: float | None = None,
                    groove: float = 0.0, stagger: float = 0.0, body_level: int = 1) -> np.ndarray:
    """Thermal flank deviation ζ_T along the normal line of action at path positions ``u`` [m].

    ``level``: ``none`` (zeros), ``analytic``, ``fe`` or ``fe3d`` (:mod:`femgear.physics.body.thermal`; ``h``
    is the 2-D mesh size, ``groove`` and ``stagger`` shape the 3-D body, ``body_level`` its resolution).
    """
    build = PAIR_LEVELS.get(level)
    if build is None:
        raise ValueError(f"level must be 'none', 'analytic', 'fe' or 'fe3d', got {level!r}")
    return build(pair, member, u, dT_flank, dT_shaft, expansion, youngs_modulus=youngs_modulus,
                 poisson_ratio=poisson_ratio, conductivity=conductivity, bore_radius=bore_radius, h=h, groove=groove,
                 stagger=stagger, body_level=body_level)


def case_arguments(case: Case, member: int) -> dict:
    """The keywords of :func:`flank_deviation` of ``member`` (1 pinion, 2 gear) from the case: the material,
    the member's bore, ``thermal.mesh_size``, the groove, the stagger and the fe3d bodies' level (``numerics.body_level``)."""
    m = case.material
    return dict(expansion=m.thermal_expansion, youngs_modulus=m.youngs_modulus, poisson_ratio=m.poisson_ratio,
                conductivity=m.conductivity, bore_radius=case.bore_radii[member - 1], h=case.thermal.mesh_size,
                groove=case.groove_width, stagger=case.stagger, body_level=case.numerics.level_of("fe3d"))


def flank_deviation_of(case: Case, member: int, u, level: str | None = None, h: float | None = None) -> np.ndarray:
    """:func:`flank_deviation` of ``member`` with the case's pair, material, bores and ``[thermal]`` rises.

    ``level`` defaults to ``physics.thermal``; the flank rise is ``thermal.flank_temperature_rise`` (a
    lubrication model may pass its own through :func:`flank_deviation`).
    """
    args = case_arguments(case, member)
    if h is not None:
        args["h"] = h
    expansion = args.pop("expansion")
    return flank_deviation(case.pair, member, u, level or case.levels.thermal, case.thermal.flank_temperature_rise,
                           case.thermal.shaft_temperature_rise, expansion, **args)


def _path_units(name: str) -> Callable[..., ThermalUnits]:
    """The factory of a level whose unit responses are ζ_T(u) along the case's path (``analytic``, ``fe``)."""
    def factory(case: Case, **_: Any) -> ThermalUnits:
        from femgear.physics.body.thermal_units import ThermalUnits

        def unit(member: int, flank: float, shaft: float) -> np.ndarray:
            args = case_arguments(case, member)
            expansion = args.pop("expansion")
            return PAIR_LEVELS[name](case.pair, member, case.path.u, flank, shaft, expansion, **args)

        return ThermalUnits(flank=np.array([unit(j, 1.0, 0.0) for j in (1, 2)]),
                            shaft=np.array([unit(j, 0.0, 1.0) for j in (1, 2)]))
    factory.__doc__ = f"The ``{name}`` unit responses ζ_T(u) of both members along the case's path."
    return factory


REGISTRY.register("none", "no thermal growth")(lambda case, **_: None)
REGISTRY.register("analytic", "free thermal expansion of the tooth from the bulk rise")(_path_units("analytic"))
REGISTRY.register("fe", "2-D FE heat conduction and thermo-elasticity of the tooth section")(_path_units("fe"))


@REGISTRY.register("fe3d", "3-D FE heat conduction and thermo-elasticity of the member bodies")
def _fe3d_units(case: Case, **_: Any) -> ThermalUnits:
    """The members' 3-D unit solutions and their face means along the path (the values of the ``fe3d``
    :func:`flank_deviation`, which reads the same cached solutions)."""
    from femgear.physics.body.thermal_units import ThermalUnits, roll_distances
    from femgear.physics.ltca.thermal import check_thermal_memory, thermal_units_3d

    m = case.material
    check_thermal_memory(case.pair, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, case.bore_radii,
                         case.groove_width, case.stagger, case.numerics.level_of("fe3d"))
    bodies = tuple(thermal_units_3d(case.pair, j, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, b,
                                    case.groove_width, case.stagger, level=case.numerics.level_of("fe3d"))
                   for j, b in zip((1, 2), case.bore_radii))
    return ThermalUnits.from_bodies(bodies, roll_distances(case.pair, case.path.u))


def check_resources(case: Case) -> None:
    """Refuse up front (naming ``numerics.body_level`` and the level that fits) ``fe3d`` bodies that, not cached,
    need more memory than the budget (:func:`femgear.physics.ltca.thermal.check_thermal_memory`)."""
    if case.levels.thermal != "fe3d":
        return
    from femgear.physics.ltca.thermal import check_thermal_memory

    m = case.material
    check_thermal_memory(case.pair, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, case.bore_radii,
                         case.groove_width, case.stagger, case.numerics.level_of("fe3d"))


def of(case: Case) -> ThermalUnits | None:
    """The unit responses of the case's ``physics.thermal`` level (None for ``none``)."""
    return REGISTRY.build(case.levels.thermal, case)


#: the levels that solve the 2-D tooth sections, whose body fields the ParaView set shows
SECTION_LEVELS = frozenset({"fe"})


def has_sections(level: str) -> bool:
    """Whether thermal level ``level`` solves the 2-D tooth sections (its temperature and displacement fields)."""
    REGISTRY[level]     # an unknown level raises, naming physics.thermal
    return level in SECTION_LEVELS
