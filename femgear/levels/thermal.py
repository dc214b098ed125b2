"""Thermal levels (the ``[physics] thermal`` key): the flank deviation from tooth growth.

The registered factory of a level returns the case's
:class:`femgear.physics.body.thermal_units.ThermalUnits` (ζ_T(u) of both members along the case's path for a
unit flank and a unit shaft rise; the conduction and thermo-elastic problems are linear), or None for
``none`` (no thermal growth).  ζ_T at other positions or rises is the physics' own function of the pair
(:func:`femgear.physics.body.thermal.analytic_flank_deviation`,
:func:`~femgear.physics.body.thermal.fe_flank_deviation`,
:func:`femgear.physics.ltca.thermal.fe3d_flank_deviation`), with the case's numbers of :func:`case_arguments`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from femgear.case import Case
from femgear.levels.registry import Registry
from femgear.physics.body.thermal import analytic_flank_deviation, fe_flank_deviation
from femgear.physics.body.thermal_units import ThermalUnits, roll_distances
from femgear.physics.ltca.thermal import check_thermal_memory, thermal_units_3d

REGISTRY = Registry("thermal")


def case_arguments(case: Case, member: int) -> dict:
    """The case's numbers for a flank deviation of ``member`` (1 pinion, 2 gear): the material, the member's bore,
    ``thermal.mesh_size``, the groove, the stagger and the fe3d bodies' level (``numerics.body_level``)."""
    m = case.material
    return dict(expansion=m.thermal_expansion, youngs_modulus=m.youngs_modulus, poisson_ratio=m.poisson_ratio,
                conductivity=m.conductivity, bore_radius=case.bore_radii[member - 1], h=case.thermal.mesh_size,
                groove=case.groove_width, stagger=case.stagger, body_level=case.numerics.level_of("fe3d"))


def _unit_responses(unit: Callable[[int, float, float], np.ndarray]) -> ThermalUnits:
    """``ThermalUnits`` of ``unit(member, flank rise, shaft rise)`` (ζ_T along the case's path) for unit rises."""
    return ThermalUnits(flank=np.array([unit(j, 1.0, 0.0) for j in (1, 2)]),
                        shaft=np.array([unit(j, 0.0, 1.0) for j in (1, 2)]))


REGISTRY.register("none")(lambda case, **_: None)


@REGISTRY.register("analytic")
def _analytic(case: Case, **_: Any) -> ThermalUnits:
    """The free thermal expansion of the tooth sections along the case's path."""
    m = case.material
    return _unit_responses(lambda j, flank, shaft: analytic_flank_deviation(
        case.pair, j, case.path.u, flank, shaft, m.thermal_expansion, m.poisson_ratio, case.bore_radii[j - 1]))


@REGISTRY.register("fe")
def _fe(case: Case, **_: Any) -> ThermalUnits:
    """The 2-D FE conduction and thermo-elasticity of the tooth sections along the case's path."""
    m = case.material
    return _unit_responses(lambda j, flank, shaft: fe_flank_deviation(
        case.pair, j, case.path.u, flank, shaft, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio,
        m.conductivity, case.bore_radii[j - 1], case.thermal.mesh_size))


def check_fe3d(case: Case) -> None:
    """Refuse up front (naming ``numerics.body_level`` and the level that fits) ``fe3d`` bodies that, not cached,
    need more memory than the budget (:func:`femgear.physics.ltca.thermal.check_thermal_memory`)."""
    m = case.material
    check_thermal_memory(case.pair, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, case.bore_radii,
                         case.groove_width, case.stagger, case.numerics.level_of("fe3d"))


@REGISTRY.register("fe3d", check=check_fe3d)
def _fe3d(case: Case, **_: Any) -> ThermalUnits:
    """The members' 3-D unit solutions and their face means along the path (the values of
    :func:`femgear.physics.ltca.thermal.fe3d_flank_deviation`, which reads the same cached solutions)."""
    m = case.material
    check_fe3d(case)
    bodies = tuple(thermal_units_3d(case.pair, j, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, b,
                                    case.groove_width, case.stagger, level=case.numerics.level_of("fe3d"))
                   for j, b in zip((1, 2), case.bore_radii))
    return ThermalUnits.from_bodies(bodies, roll_distances(case.pair, case.path.u))


def of(case: Case) -> ThermalUnits | None:
    """The unit responses of the case's ``physics.thermal`` level (None for ``none``)."""
    return REGISTRY.build(case.levels.thermal, case)
