"""Round trip: every zoo scene and the paper's baseline → ``femgear rexs --export`` → import gives back
the same scene (geometry, material, oil, operating point, modifications) to 1e-9 relative, in XML,
JSON and zipped form and through the commented scene file; the exported file carries only REXS 1.4
ids and units (femgear's shipped table) or femgear's declared custom attributes.

The zoo folder is globbed, so scenes added to it later are covered.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest

from femgear.case.pair import pair_from_scene
from femgear.rexs.database import id_problems
from femgear.rexs.importer import scene_from_rexs
from femgear.rexs.read import read_model
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
SCENES = sorted((ROOT / "studies" / "zoo").glob("*.toml")) + [ROOT / "studies" / "paper_baseline.toml"]
MARINE = ROOT / "studies" / "zoo" / "marine.toml"

#: other gears than the two scenes: kinds, shifts, modifications, driver, temperatures (on the marine pair)
VARIANTS = {
    "modified": ["modifications.tip_relief=20e-6", "modifications.tip_relief_length=3e-3",
                 'modifications.tip_relief_shape="parabolic"', "modifications.root_relief=8e-6",
                 "modifications.root_relief_length=2e-3", "modifications.crowning=8e-6", "modifications.end_relief=10e-6",
                 "modifications.end_relief_length=5e-3", "modifications.helix_slope_deviation_left=5e-6",
                 "modifications.helix_slope_deviation_right=-3e-6"],
    "per-member": ["modifications.pinion.tip_relief=15e-6", "modifications.pinion.tip_relief_length=2.5e-3",
                   "modifications.gear.crowning=6e-6"],
    "single-helical": ['pair.kind="single-helical"', "pinion.axial_stiffness=1e9", "gear.axial_stiffness=2e9",
                       "pinion.axial_damping=300.0"],
    "spur": ['pair.kind="spur"', "pair.helix_angle_deg=0.0"],
    "shifted": ['operating.driver="gear"', "oil.reference_temperature=313.0", "pinion.profile_shift=0.3",
                "gear.profile_shift=-0.1", "pinion.face_width=0.125", "pinion.bore_radius=0.02", "pinion.eccentricity=1e-5",
                "pinion.eccentricity_phase_deg=30.0", "pinion.unbalance=1e-3", "pair.stagger=0.25",
                "operating.loop_stiffness=1e5", 'pair.basic_rack="B"', "pair.addendum_coeff=1.0",
                "oil.limiting_shear_coeff=0.08", "material.hardness=6.5e9"],
    "centre-distance": ["pair.centre_distance=0.4375", "pinion.profile_shift=0.1"],
}


def _numbers_equal(a, b, path: str) -> None:
    if isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for key in a:
            _numbers_equal(a[key], b[key], f"{path}.{key}")
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _numbers_equal(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and not isinstance(b, bool):
        assert math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-15), f"{path}: {a!r} != {b!r}"
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"


def essence(scene) -> dict:
    """What the round trip must keep: the resolved pair geometry and the scene's physical tables."""
    pair = pair_from_scene(scene)
    geometry = {f.name: getattr(pair, f.name) for f in dataclasses.fields(pair)}
    geometry.update(a_w=pair.a_w, ra1=pair.ra1, ra2=pair.ra2, rf1=pair.rf1, rf2=pair.rf2)
    members = {}
    for name in ("pinion", "gear"):
        m = getattr(scene, name)
        members[name] = m.model_dump(exclude={"tip_diameter", "profile_shift", "face_width"})
        members[name]["width"] = m.face_width or scene.pair.face_width
    oil = scene.oil.model_dump()
    oil["reference_temperature"] = scene.oil_reference_temperature
    mods = scene.modifications
    return {"geometry": geometry, "pair": scene.pair.model_dump(include={"groove_width", "backlash", "stagger"}),
            "members": members, "material": scene.material.model_dump(), "oil": oil,
            "operating": scene.operating.model_dump(),
            "modifications": [mods.member(1).model_dump(), mods.member(2).model_dump(),
                              mods.helix_slope_deviation_left, mods.helix_slope_deviation_right]}


def _export(cli, scene_path: Path, out: Path, overrides=()) -> None:
    rc, _, err = cli("rexs", "--export", scene_path, "-o", out, *[x for o in overrides for x in ("--set", o)])
    assert rc == 0, err


@pytest.mark.parametrize("suffix", [".rexs", ".rexsj", ".rexsz"])
@pytest.mark.parametrize("scene_path", SCENES, ids=lambda p: p.stem)
def test_scene_export_import_is_the_same_scene(scene_path, suffix, cli, tmp_path):
    out = tmp_path / f"pair{suffix}"
    _export(cli, scene_path, out)
    original, back = load_scene(scene_path), scene_from_rexs(out, warn=False)
    _numbers_equal(essence(original), essence(back), scene_path.stem)
    assert back.meta.name == original.meta.name


@pytest.mark.parametrize("name", VARIANTS)
def test_other_gears_round_trip(name, cli, tmp_path):
    overrides = VARIANTS[name]
    out = tmp_path / "pair.rexs"
    _export(cli, MARINE, out, overrides)
    original = load_scene(MARINE, overrides)
    back = scene_from_rexs(out, warn=False)
    _numbers_equal(essence(original), essence(back), name)
    assert back.pair.kind == original.pair.kind


@pytest.mark.parametrize("scene_path", SCENES, ids=lambda p: p.stem)
def test_round_trip_through_the_commented_scene_file(scene_path, cli, tmp_path):
    out, toml = tmp_path / "pair.rexs", tmp_path / "back.toml"
    _export(cli, scene_path, out)
    rc, listing, err = cli("rexs", out)
    assert rc == 0, err
    stage = int(listing.splitlines()[2].split()[0])
    rc, _, err = cli("rexs", out, "--stage", stage, "-o", toml)
    assert rc == 0, err
    _numbers_equal(essence(load_scene(scene_path)), essence(load_scene(toml)), scene_path.stem)


@pytest.mark.parametrize("suffix", [".rexs", ".rexsj", ".rexsz"])
@pytest.mark.parametrize("variant", [None, "modified", "single-helical"])
def test_exported_file_has_only_rexs_14_ids_and_units(variant, suffix, cli, tmp_path):
    out = tmp_path / f"pair{suffix}"
    _export(cli, MARINE, out, VARIANTS.get(variant, ()))
    model = read_model(out)
    assert model.version == "1.4"
    assert id_problems(model) == []
    types = {c.type for c in model.components.values()}
    assert {"cylindrical_stage", "cylindrical_gear", "cylindrical_gear_flank", "material", "lubricant"} <= types
    if variant == "modified":
        assert {"tip_relief", "root_relief", "helix_crowning", "helix_slope", "end_relief_datum_face"} <= types


def test_the_id_check_finds_a_wrong_unit_and_an_unknown_id(cli, tmp_path):
    """The validation can fail: a unit and an id that REXS 1.4 does not have are reported."""
    out = tmp_path / "pair.rexs"
    _export(cli, MARINE, out)
    text = out.read_text().replace('<attribute id="normal_module" unit="mm">', '<attribute id="normal_module" unit="m">', 1)
    text = text.replace('id="face_width"', 'id="facewidth"', 1)
    out.write_text(text)
    problems = id_problems(read_model(out))
    assert any("normal_module: unit 'm', 1.4 has 'mm'" in p for p in problems)
    assert any("'facewidth' is not in the 1.4 table" in p for p in problems)


def test_exported_figures_are_femgears(cli, tmp_path):
    """The stage carries femgear's centre distance and contact ratios, the gears their diameters."""
    out = tmp_path / "pair.rexs"
    _export(cli, MARINE, out)
    model = read_model(out)
    pair = pair_from_scene(load_scene(MARINE))
    stage = model.of_type("cylindrical_stage")[0]
    assert model.value(stage, "center_distance") == pytest.approx(pair.a_w, rel=1e-12)
    assert model.value(stage, "overlap_contact_ratio") == pytest.approx(pair.eps_beta, rel=1e-12)
    assert model.value(stage, "radial_contact_ratio") == pytest.approx(pair.eps_alpha, rel=1e-12)
    tips = sorted(model.value(g, "tip_diameter") for g in model.of_type("cylindrical_gear"))
    assert tips[0] == pytest.approx(2 * pair.ra1, rel=1e-12) and tips[-1] == pytest.approx(2 * pair.ra2, rel=1e-12)
    # REXS's normal backlash is the total j_bn: twice femgear's half backlash pair.backlash (the dead zone |δ| ≤ b0)
    j_bn = model.value(stage, "minimum_normal_backlash")
    assert j_bn == pytest.approx(2 * load_scene(MARINE).pair.backlash, rel=1e-12)


def test_a_root_diameter_off_the_rack_tool_names_both(cli, tmp_path):
    """Exported model with one gear's root diameter moved by 0.1 m_n: the dedendum disagrees with the hob."""
    out = tmp_path / "pair.rexs"
    _export(cli, MARINE, out)
    model = read_model(out)
    gear = model.of_type("cylindrical_gear")[0]
    d_f = gear.attributes["root_diameter"].value
    text = out.read_text().replace(f'unit="mm">{d_f!r}<', f'unit="mm">{d_f - 1.2!r}<')  # both halves
    out.write_text(text)
    rc, _, err = cli("rexs", out, "--stage", 2)
    assert rc == 2 and f"component {gear.id}" in err and "attribute root_diameter" in err
    assert "attribute addendum_coefficient_reference_profile" in err and len(err.strip().splitlines()) == 1
