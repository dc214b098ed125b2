"""Coupling levels (the ``[physics] coupling`` key).

Each level's factory returns its catalogue spec (:class:`femgear.scene.levels.CouplingLevel`): whether
the outer loop between dynamics and tribology iterates to convergence or stops after the first dynamic
pass.
"""

from __future__ import annotations

from typing import Any

from femgear.case import Case
from femgear.levels.registry import Registry
from femgear.scene.levels import CouplingLevel

REGISTRY = Registry("coupling")


def _spec_of(name: str):
    def factory(case: Case | None = None, **_: Any) -> CouplingLevel:
        return REGISTRY.catalogue.spec(name)
    factory.__doc__ = f"The ``{name}`` level's :class:`~femgear.scene.levels.CouplingLevel`."
    return factory


for _name in REGISTRY.catalogue.available:
    REGISTRY.register(_name)(_spec_of(_name))
