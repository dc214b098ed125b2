"""Coupling levels (the ``[physics] coupling`` key).

Each level's factory returns its :class:`CouplingSpec`: whether the outer loop between
dynamics and tribology iterates to convergence or stops after the first dynamic pass.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from femgear.levels.registry import Registry

REGISTRY = Registry("coupling")


@dataclass(frozen=True)
class CouplingSpec:
    """What a coupling level asks of the coupling loop."""

    name: str
    iterates: bool      #: True: iterate dynamics ↔ tribology to convergence; False: one dynamic pass


@REGISTRY.register("one-way", "one dynamic pass with the static sub-model results")
def _one_way(case: Any = None) -> CouplingSpec:
    return CouplingSpec("one-way", iterates=False)


@REGISTRY.register("bidirectional", "the outer loop iterated to convergence between dynamics and tribology")
def _bidirectional(case: Any = None) -> CouplingSpec:
    return CouplingSpec("bidirectional", iterates=True)


def spec(name: str) -> CouplingSpec:
    """The :class:`CouplingSpec` of level ``name`` (:class:`femgear.errors.SceneError` for an unknown one)."""
    return REGISTRY.build(name, None)
