"""Every scene key is documented: a description, and a unit on every number (issue 30).

A key added to :mod:`femgear.scene.schema` without a ``description`` (or a number without
its ``[unit]``) fails here, so the generated scene-key page and ``femgear new`` never miss one.
"""

from __future__ import annotations

from pydantic import BaseModel, Field

from femgear.scene.keys import scene_keys, scene_tables, unit_of
from femgear.scene.schema import Scene


def test_every_key_has_a_description_and_every_number_a_unit():
    keys = scene_keys()
    assert len(keys) > 150                                   # the walk reaches the nested tables
    undocumented = [k.key for k in keys if len(k.description) < 10]
    assert not undocumented, f"scene keys without a description: {undocumented}"
    no_unit = [k.key for k in keys if k.numeric and k.unit is None]
    assert not no_unit, f"numeric scene keys without a [unit] in their description: {no_unit}"


def test_every_table_has_a_docstring():
    assert all(len(t.doc) > 10 for t in scene_tables())


def test_the_walk_finds_nested_and_optional_tables():
    keys = {k.key: k for k in scene_keys()}
    assert keys["pair.backlash"].unit == "m" and keys["pair.backlash"].default == 0.0
    assert keys["pair.normal_module"].required and keys["pair.normal_module"].numeric
    assert keys["roughness.peak.amplitude"].required               # required inside an optional table
    assert keys["modifications.pinion.tip_relief"].unit == "m"
    assert keys["rating.roughness_rz"].unit == "m"                 # not the bracketed [R_z1, R_z2]
    assert keys["physics.stiffness"].type == "str" and "ltca" in keys["physics.stiffness"].description
    assert keys["operating.driver"].type == 'one of "pinion", "gear"' and keys["operating.driver"].unit is None
    assert len(keys) == len(scene_keys())                           # no key twice


def test_the_check_fails_for_an_undocumented_key():
    """The checks above can fail: a schema with a bare number is caught."""

    class Bad(BaseModel):
        documented: float = Field(1.0, description="a length [m]")
        bare: float = 2.0
        unitless: float = Field(3.0, description="a number without its unit")

    keys = {k.key: k for k in scene_keys(Bad)}
    assert keys["bare"].description == "" and keys["unitless"].unit is None and keys["documented"].unit == "m"
    assert unit_of("stiffness [N/m per m], ISO") == "N/m per m" and unit_of("[modifications.pinion]: x") is None
    assert Scene.model_fields  # the real schema is the one checked above
