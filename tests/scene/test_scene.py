"""Scene loading, overrides and the one-line errors that name the key."""

import tomllib

import pydantic
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.scene import load_scene, scene_from_dict
from femgear.scene.levels import AVAILABLE, LEVELS


def raw(baseline_path):
    return tomllib.loads(baseline_path.read_text())


def test_baseline_holds_the_papers_tables(baseline_scene):
    s = baseline_scene
    assert (s.pinion.teeth, s.gear.teeth) == (31, 34)
    assert s.pair.normal_module == 3e-3 and s.pair.helix_angle_deg == 30 and s.pair.normal_pressure_angle_deg == 20
    assert 2 * s.pair.face_width == pytest.approx(0.035)
    assert s.pair.backlash == pytest.approx(50e-6)
    assert (s.pinion.mass, s.gear.mass, s.pinion.inertia, s.gear.inertia) == (1.28, 1.62, 0.0027, 0.0041)
    assert s.operating.speed_rpm == 500 and s.operating.torque == 200
    assert s.oil.viscosity == 0.08 and s.oil.pressure_viscosity == pytest.approx(22e-9)
    assert s.operating.ambient_temperature == 313 and s.oil_reference_temperature == 313


def test_scene_models_are_frozen(baseline_scene):
    with pytest.raises(pydantic.ValidationError, match="frozen"):
        baseline_scene.pair.normal_module = 1.0


def test_overrides_take_toml_values(baseline_path):
    s = load_scene(baseline_path, ["operating.torque=150", "meta.name=case 2", "pair.stagger=0.5"])
    assert s.operating.torque == 150.0 and s.meta.name == "case 2" and s.pair.stagger == 0.5


@pytest.mark.parametrize(
    "change,key",
    [
        (lambda d: d["pair"].pop("normal_module"), "pair.normal_module"),
        (lambda d: d["pinion"].__setitem__("teeth", "many"), "pinion.teeth"),
        (lambda d: d["pair"].__setitem__("normal_module", -3e-3), "pair.normal_module"),
        (lambda d: d["oil"].__setitem__("viscosty", 1.0), "oil.viscosty"),
        (lambda d: d["pair"].__setitem__("addendum_coeff", 0.5), "pair.addendum_coeff"),
        (lambda d: d["pinion"].__setitem__("teeth", 6), "pinion.profile_shift"),
        (lambda d: d.pop("oil"), "oil"),
    ],
)
def test_bad_scenes_name_the_key(baseline_path, change, key):
    data = raw(baseline_path)
    change(data)
    with pytest.raises(SceneError) as info:    # the pair's feasibility: when the case is bound
        build_case(scene_from_dict(data))
    assert info.value.key == key
    assert "\n" not in str(info.value)


def test_physics_levels_known_but_not_available_say_so(baseline_path):
    missing = [(sub, lv) for sub, levels in LEVELS.items() for lv in levels if lv not in AVAILABLE[sub]]
    for sub, lv in missing:
        with pytest.raises(SceneError, match="not available yet") as info:
            load_scene(baseline_path, [f"physics.{sub}={lv}"])
        assert info.value.key == f"physics.{sub}"
    with pytest.raises(SceneError, match="unknown level"):
        load_scene(baseline_path, ["physics.wear=magic"])


def test_bad_override_syntax(baseline_path):
    with pytest.raises(SceneError, match="KEY=VALUE"):
        load_scene(baseline_path, ["operating.torque"])
    with pytest.raises(SceneError, match="operating.torque"):
        load_scene(baseline_path, ["operating.torque.x=1"])


def test_missing_file_is_a_scene_error(tmp_path):
    with pytest.raises(SceneError, match="not found"):
        load_scene(tmp_path / "nope.toml")


def test_presets_fill_in_levels_and_explicit_keys_win(baseline_path):
    data = raw(baseline_path)
    data["physics"] = {"preset": "accurate", "wear": "none", "thermal": "analytic"}
    s = scene_from_dict(data)
    assert (s.physics.stiffness, s.physics.lubrication, s.physics.dynamics) == ("fe", "ehl-line", "timoshenko")
    assert s.physics.thermal == "analytic" and s.numerics.steps_per_mesh_period == 400
    fast = scene_from_dict(data, ['physics.preset="fast"', "numerics.path_points=33"])
    assert fast.physics.stiffness == "pem" and fast.numerics.path_points == 33


def test_unknown_preset_names_the_key(baseline_path):
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, ['physics.preset="turbo"'])
    assert info.value.key == "physics.preset"


def test_a_removed_key_says_what_to_do(baseline_path):
    """``stiffness.n_slices`` (the midpoint sum over face slices, replaced by the exact contact-line integral):
    named, with what changed, not just "unknown key"."""
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, ["stiffness.n_slices=100"])
    assert info.value.key == "stiffness.n_slices"
    assert "removed" in str(info.value) and "delete the key" in str(info.value)
