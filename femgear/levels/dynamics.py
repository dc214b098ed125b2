"""Dynamics levels (the ``[physics] dynamics`` key).

Each level's factory returns its :class:`DynamicsSpec`, the attributes the driver and the
model builder read instead of comparing level names: whether the run is dynamic at all
(``none`` is quasi-static) and whether the helix halves are joined by shaft elements
(``timoshenko``) or tied rigidly per member (``lumped``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from femgear.levels.registry import Registry

REGISTRY = Registry("dynamics")


@dataclass(frozen=True)
class DynamicsSpec:
    """What a dynamics level asks of the driver and of the rotor model."""

    name: str
    is_dynamic: bool         #: False: the sub-models run once at the static load (no rotor model)
    shaft_elements: bool     #: True: Timoshenko shaft elements between helix halves and bearings; False: rigid members


@REGISTRY.register("none", "quasi-static: the sub-models run once at the static load")
def _none(case: Any = None) -> DynamicsSpec:
    return DynamicsSpec("none", is_dynamic=False, shaft_elements=False)


@REGISTRY.register("lumped", "the four helical halves tied rigidly per member on their bearings "
                             "(12 rigid-member coordinates)")
def _lumped(case: Any = None) -> DynamicsSpec:
    return DynamicsSpec("lumped", is_dynamic=True, shaft_elements=False)


@REGISTRY.register("timoshenko", "helical halves and bearing stations joined by Timoshenko shaft elements "
                                 "(stations condensed)")
def _timoshenko(case: Any = None) -> DynamicsSpec:
    return DynamicsSpec("timoshenko", is_dynamic=True, shaft_elements=True)


def spec(name: str) -> DynamicsSpec:
    """The :class:`DynamicsSpec` of level ``name`` (:class:`femgear.errors.SceneError` for an unknown one)."""
    return REGISTRY.build(name, None)


def model_level(name: str | None, default: str) -> DynamicsSpec:
    """The rotor model's level: ``name`` if given, else ``default`` (``physics.dynamics``) when that is a
    dynamic level, else ``lumped`` (a quasi-static case asking for a model gets the cheapest one)."""
    if name is not None:
        return spec(name)
    chosen = spec(default)
    return chosen if chosen.is_dynamic else spec("lumped")
