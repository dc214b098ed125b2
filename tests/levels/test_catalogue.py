"""The catalogue of levels (:mod:`femgear.scene.levels`) and the registries of factories (:mod:`femgear.levels`):
one set of names, specs read instead of names, checks run up front."""

import pytest

from femgear.errors import SceneError
from femgear.levels import REGISTRIES, check_case
from femgear.levels import housing as housing_levels
from femgear.levels.registry import Registry
from femgear.scene.levels import CATALOGUE, PHYSICS, StiffnessLevel


def test_every_available_level_has_one_factory_and_no_factory_lacks_a_spec():
    registries = {**REGISTRIES, "housing": housing_levels.REGISTRY}
    assert set(registries) == set(CATALOGUE) and set(REGISTRIES) == set(PHYSICS)
    for sub, registry in registries.items():
        assert registry.names() == CATALOGUE[sub].available, sub
        for name in registry.names():
            assert registry[name].spec is CATALOGUE[sub].spec(name)


def test_a_planned_or_unknown_level_is_refused_naming_its_key():
    with pytest.raises(SceneError, match="physics.lubrication.*not available yet"):
        REGISTRIES["lubrication"]["ehl-point"]
    with pytest.raises(SceneError, match="housing.model.*unknown level 'weber'"):
        housing_levels.REGISTRY["weber"]
    registry = Registry("stiffness")
    with pytest.raises(SceneError, match="unknown level 'weber'"):
        registry.register("weber")
    registry.register("pem")(lambda case: None)
    with pytest.raises(ValueError, match="registered twice"):
        registry.register("pem")


def test_the_specs_say_what_callers_branch_on(baseline_scene):
    stiffness = CATALOGUE["stiffness"]
    assert [s.name for s in stiffness.levels if s.uniform_along_path] == ["constant", "iso6336"]
    assert [s.name for s in stiffness.levels if s.contact_lines] == ["ltca"]
    assert all(isinstance(s, StiffnessLevel) for s in stiffness.levels)
    assert [s.name for s in CATALOGUE["thermal"].levels if s.sections] == ["fe"]
    assert [s.name for s in CATALOGUE["lubrication"].levels if s.summarised] == ["none", "constant", "formula"]
    assert not CATALOGUE["dynamics"].spec("none").is_dynamic and CATALOGUE["dynamics"].spec("timoshenko").shaft_elements
    assert CATALOGUE["coupling"].spec("bidirectional").iterates
    assert baseline_scene.physics.spec("stiffness") is stiffness.spec(baseline_scene.physics.stiffness)


def test_run_case_checks_refuse_before_any_work(baseline_scene):
    """The ``tehl`` level's check (a factory's ``check``) refuses a pitch-line speed above its envelope; the case
    itself binds (the check is the level's, run by :func:`femgear.levels.check_case` before anything costly)."""
    from femgear.case import build_case
    from femgear.pipeline import run_case

    fast = baseline_scene.model_copy(update={
        "physics": baseline_scene.physics.model_copy(update={"lubrication": "tehl"}),
        "operating": baseline_scene.operating.model_copy(update={"speed_rpm": 60000.0})})
    case = build_case(fast, warn=False)
    with pytest.raises(SceneError, match="physics.lubrication"):
        check_case(case)
    with pytest.raises(SceneError, match="physics.lubrication"):
        run_case(case)
