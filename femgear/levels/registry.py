"""One registry per sub-model: ``{level name: factory}`` with a one-line summary each.

The registries are the one source of level names: the scene schema validates
``[physics]`` against them, the CLI lists them, the docs print them, and the driver
dispatches through them (no string comparisons of level names elsewhere).

A factory takes the bound case (and keyword options) and returns the sub-model's typed
product; it imports its physics lazily, so that importing a registry (as the scene
schema does) stays cheap.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from femgear.errors import SceneError


@dataclass(frozen=True)
class Level:
    """One level of a sub-model: its name, what it computes, and its factory."""

    name: str
    summary: str                                   #: one line: what the level computes
    factory: Callable[..., Any]                    #: ``factory(case, **options) -> product``


class Registry(Mapping[str, Level]):
    """The levels of one sub-model, cheapest first (the order of registration)."""

    def __init__(self, submodel: str, planned: tuple[str, ...] = (), key: str | None = None) -> None:
        self.submodel = submodel
        self.key = key or f"physics.{submodel}"    #: the scene key that names the level (in error messages)
        self.planned = planned                     #: names of the design not built yet (refused as such)
        self._levels: dict[str, Level] = {}

    def register(self, name: str, summary: str) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
        """Decorator: register ``factory`` as level ``name``."""
        if name in self._levels:
            raise ValueError(f"{self.submodel}: level {name!r} registered twice")

        def decorate(factory: Callable[..., Any]) -> Callable[..., Any]:
            self._levels[name] = Level(name, summary, factory)
            return factory
        return decorate

    def __getitem__(self, name: str) -> Level:
        try:
            return self._levels[name]
        except KeyError:
            raise SceneError(self.key, self.problem(name)) from None

    def problem(self, name: str) -> str | None:
        """Why ``<key> = name`` (``physics.<submodel>`` unless the registry names another key) cannot run, or None
        when it is a registered level."""
        if name in self._levels:
            return None
        have = ", ".join(self._levels)
        if name in self.planned:
            return f"level {name!r} is not available yet (available now: {have})"
        return f"unknown level {name!r}; choose one of {have}"

    def __iter__(self) -> Iterator[str]:
        return iter(self._levels)

    def __len__(self) -> int:
        return len(self._levels)

    def names(self) -> tuple[str, ...]:
        return tuple(self._levels)

    def build(self, name: str, case: Any, **options: Any) -> Any:
        """The product of level ``name`` for ``case``."""
        return self[name].factory(case, **options)
