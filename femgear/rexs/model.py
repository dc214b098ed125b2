"""A REXS model in memory: components with typed attributes, relations, load cases.

Component types and units are stored in their REXS 1.4 spelling (:mod:`femgear.rexs.database`
maps older names when a file is read).  :class:`RexsError` is the one error of the package: a
:class:`femgear.errors.SceneError` whose key names the file, the component (id, name, type) and the
attribute, so that the CLI prints one line and exits with 2.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from femgear.errors import SceneError
from femgear.rexs.database import ATTRIBUTES, CUSTOM
from femgear.rexs.units import UnitMismatch, to_scene_unit


class RexsError(SceneError):
    """A REXS model cannot become a scene; ``key`` names the file, component and attribute."""


@dataclass(frozen=True)
class Attribute:
    id: str
    unit: str | None   #: declared unit (1.4 spelling), None where the file declares none
    value: Any         #: float, int, bool, str, or the raw text/list of a value femgear does not read


@dataclass(frozen=True, eq=False)
class Component:
    """One component; equal only to itself (ids are unique in a model)."""

    id: int
    type: str
    name: str
    attributes: dict[str, Attribute] = field(default_factory=dict)

    def label(self) -> str:
        """``component 15 "Gear 1" (cylindrical_gear)``: how errors and comments name it."""
        return f'component {self.id} "{self.name}" ({self.type})'


@dataclass(frozen=True)
class Ref:
    id: int
    role: str
    hint: str = ""


@dataclass(frozen=True)
class Relation:
    id: int
    type: str
    refs: tuple[Ref, ...]
    order: int | None = None

    def role(self, role: str) -> list[int]:
        """Ids of the components this relation gives ``role``."""
        return [r.id for r in self.refs if r.role == role]


@dataclass(frozen=True)
class Model:
    """A whole REXS model; ``load_case`` holds the attributes of the chosen load case per component id."""

    source: str                       #: the file, for messages
    version: str
    application: str
    components: dict[int, Component]
    relations: tuple[Relation, ...]
    load_cases: tuple[int, ...] = ()
    load_case: dict[int, dict[str, Attribute]] = field(default_factory=dict)

    def error(self, component: Component | None, attribute: str | None, message: str) -> RexsError:
        """The one-line error naming this file, ``component`` and ``attribute``."""
        where = [self.source]
        if component is not None:
            where.append(component.label())
        if attribute is not None:
            where.append(f"attribute {attribute}")
        return RexsError(", ".join(where), message)

    def of_type(self, *types: str) -> list[Component]:
        return [c for c in self.components.values() if c.type in types]

    def attribute(self, component: Component, attr: str) -> Attribute | None:
        """The attribute of the chosen load case, else of the component, else None."""
        case = self.load_case.get(component.id, {})
        return case.get(attr, component.attributes.get(attr))

    def value(self, component: Component, attr: str, *, required: bool = False) -> Any:
        """The attribute's value in the scene's unit (SI, degrees, rev/min), or None when absent.

        Numbers are checked finite; the declared unit is checked against the 1.4 unit of the
        attribute and converted from (:func:`femgear.rexs.units.to_scene_unit`).
        """
        found = self.attribute(component, attr)
        if found is None:
            if required:
                raise self.error(component, attr, "missing (femgear needs it)")
            return None
        unit, kind = _spec(component.type, attr)
        value = found.value
        if kind == "integer":
            if isinstance(value, bool) or not isinstance(value, int):
                raise self.error(component, attr, f"not an integer: {value!r}")
            self._convert(component, attr, 1.0, found.unit, unit)  # the unit must be dimensionless
            return value
        if kind == "floating_point":
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise self.error(component, attr, f"not a number: {value!r}")
            if value != value or value in (float("inf"), float("-inf")):
                raise self.error(component, attr, f"not a finite number: {value!r}")
            return self._convert(component, attr, float(value), found.unit, unit)
        if kind == "boolean" and not isinstance(value, bool):
            raise self.error(component, attr, f"not a boolean: {value!r}")
        if kind in ("enum", "string") and not isinstance(value, str):
            raise self.error(component, attr, f"not a text value: {value!r}")
        return value

    def _convert(self, component: Component, attr: str, value: float, declared: str | None, expected: str) -> float:
        try:
            return to_scene_unit(value, declared, expected)
        except UnitMismatch as exc:
            raise self.error(component, attr, str(exc)) from None

    def related(self, relation_type: str, role: str, component_id: int, other_role: str) -> list[int]:
        """Ids in ``other_role`` of every ``relation_type`` relation giving ``component_id`` the ``role``."""
        out = []
        for rel in self.relations:
            if rel.type == relation_type and component_id in rel.role(role):
                out.extend(rel.role(other_role))
        return out

    def component(self, cid: int, near: Component | None = None, what: str = "") -> Component:
        """The component with id ``cid``; a relation naming a missing one is an error."""
        if cid not in self.components:
            raise self.error(near, None, f"a relation names {what or 'component'} {cid}, which the model does not hold")
        return self.components[cid]


def _spec(component_type: str, attr: str) -> tuple[str, str]:
    key = (component_type, attr)
    if key in ATTRIBUTES:
        return ATTRIBUTES[key][:2]
    return CUSTOM[key]


def value_kind(component_type: str, attr: str) -> str | None:
    """REXS value type of an attribute femgear maps, None for any other attribute."""
    key = (component_type, attr)
    if key in ATTRIBUTES:
        return ATTRIBUTES[key][1]
    if key in CUSTOM:
        return CUSTOM[key][1]
    return None
