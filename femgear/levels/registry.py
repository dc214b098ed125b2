"""One registry per sub-model: ``{level name: factory}``, the names and specs read from the catalogue.

The catalogue (:mod:`femgear.scene.levels`) is the one source of level names and of what callers
branch on; a registry holds the factories that compute them, above the Case: each registered with
the decorator as ``factory(case, **options) -> product``, optionally with a ``check(case)`` that
refuses the case before anything costly runs (:func:`femgear.levels.check_case`, which
:func:`femgear.pipeline.run_case` calls first).  A name the catalogue does not list as available
cannot be registered; a test holds the registered names equal to the catalogue's.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from femgear.case import Case
from femgear.scene.levels import CATALOGUE, LevelSpec, SubModel


@dataclass(frozen=True)
class Level:
    """One level of a sub-model: its catalogue spec, its factory and its up-front check."""

    spec: LevelSpec
    factory: Callable[..., Any]                        #: ``factory(case, **options) -> product``
    check: Callable[[Case], None] | None = None        #: ``check(case)``: raise before anything costly runs

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def summary(self) -> str:
        return self.spec.summary


class Registry(Mapping[str, Level]):
    """The factories of one sub-model, in the catalogue's order (cheapest first)."""

    def __init__(self, submodel: str) -> None:
        self.catalogue: SubModel = CATALOGUE[submodel]
        self.submodel = submodel
        self.key = self.catalogue.key              #: the scene key that names the level (in error messages)
        self._levels: dict[str, Level] = {}

    @property
    def planned(self) -> tuple[str, ...]:
        """Names of the design not built yet (refused as such)."""
        return self.catalogue.planned

    def register(self, name: str, check: Callable[[Case], None] | None = None
                 ) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
        """Decorator: register ``factory`` as level ``name`` (an available level of the catalogue), with the
        up-front ``check(case)`` if given."""
        if name in self._levels:
            raise ValueError(f"{self.submodel}: level {name!r} registered twice")
        spec = self.catalogue.spec(name)

        def decorate(factory: Callable[..., Any]) -> Callable[..., Any]:
            self._levels[name] = Level(spec, factory, check)
            return factory
        return decorate

    def register_specs(self) -> None:
        """Register every available level of the catalogue with a factory that returns its own spec: the
        sub-models whose product is what they ask of the driver (``dynamics``, ``coupling``)."""
        for name in self.catalogue.available:
            spec = self.catalogue.spec(name)
            self.register(name)(lambda case=None, _spec=spec, **_: _spec)

    def __getitem__(self, name: str) -> Level:
        self.catalogue.spec(name)                  # an unknown or planned level raises, naming the key
        return self._levels[name]

    def problem(self, name: str) -> str | None:
        """Why ``<key> = name`` cannot run, or None when it is an available level."""
        return self.catalogue.problem(name)

    def __iter__(self) -> Iterator[str]:
        return iter(s for s in self.catalogue.available if s in self._levels)

    def __len__(self) -> int:
        return len(self._levels)

    def names(self) -> tuple[str, ...]:
        return tuple(self)

    def build(self, name: str, case: Case, **options: Any) -> Any:
        """The product of level ``name`` for ``case``."""
        return self[name].factory(case, **options)

    def check(self, name: str, case: Case) -> None:
        """Run level ``name``'s up-front check on ``case`` (nothing where it has none)."""
        level = self[name]
        if level.check is not None:
            level.check(case)
