"""Pair kinds from the model's structure: a shaft holding two opposite-hand halves is a double-helical
member; one helix is single-helical; β = 0 is spur.  Also the scene file's comments and head."""

from __future__ import annotations

import json
import tomllib

import pytest

from femgear.rexs.importer import read_stage, scene_from_rexs


def herringbone(*, stages: int = 2, u_gear=(50.0, 150.0), beta: float = 20.0, mass: float | None = 40.0) -> str:
    """Pinion halves 11/12 on shaft 1 (u 50, 150 mm), gear halves 21/22 on shaft 2; 80 mm per half."""
    def gear(cid, name, z, b, u):
        m = f'<attribute id="mass_of_component" unit="kg">{mass}</attribute>' if mass else ""
        return (f'<component id="{cid}" name="{name}" type="cylindrical_gear">'
                f'<attribute id="normal_module" unit="mm">5</attribute>'
                f'<attribute id="number_of_teeth" unit="none">{z}</attribute>'
                f'<attribute id="helix_angle_reference_diameter" unit="deg">{b}</attribute>'
                f'<attribute id="face_width" unit="mm">80</attribute>'
                f'<attribute id="u_coordinate_on_shaft" unit="mm">{u}</attribute>{m}</component>')
    comps = [gear(11, "P left", 25, beta, 50.0), gear(12, "P right", 25, -beta, 150.0),
             gear(21, "G left", 83, -beta, u_gear[0]), gear(22, "G right", 83, beta, u_gear[1]),
             '<component id="1" name="Pinion shaft" type="shaft"/>', '<component id="2" name="Gear shaft" type="shaft"/>']
    rels = [f'<relation id="{i}" type="assembly"><ref id="{s}" role="assembly" hint="shaft"/>'
            f'<ref id="{g}" role="part" hint="cylindrical_gear"/></relation>'
            for i, (s, g) in enumerate([(1, 11), (1, 12), (2, 21), (2, 22)], start=1)]
    for k, (g1, g2) in enumerate([(11, 21), (12, 22)][:stages]):
        comps.append(f'<component id="{100 + k}" name="Helix {k}" type="cylindrical_stage"/>')
        rels.append(f'<relation id="{10 + k}" type="stage"><ref id="{100 + k}" role="stage" hint="cylindrical_stage"/>'
                    f'<ref id="{g1}" role="gear_1" hint="cylindrical_gear"/>'
                    f'<ref id="{g2}" role="gear_2" hint="cylindrical_gear"/></relation>')
    return (f'<model applicationId="hand" version="1.4"><relations>{"".join(rels)}</relations>'
            f'<components>{"".join(comps)}</components></model>')


@pytest.mark.parametrize("stages", [1, 2])
def test_two_opposite_hand_halves_on_a_shaft_are_double_helical(stages, two_stage, cli):
    path = two_stage(herringbone(stages=stages))
    scene = scene_from_rexs(path, 100, warn=False)
    assert scene.pair.kind == "double-helical"
    assert scene.pair.face_width == pytest.approx(0.08)
    assert scene.pair.groove_width == pytest.approx(0.02)          # (150 − 50) − 80 mm
    assert scene.pinion.mass == pytest.approx(80.0)                 # both halves
    rc, out, err = cli("rexs", path)
    assert rc == 0 and "double-helical" in out
    if stages == 2:
        assert scene_from_rexs(path, 101, warn=False).pair == scene.pair
        assert "halves in stages 100, 101" in out


def test_one_helix_is_single_helical_and_zero_helix_is_spur(two_stage, two_stage_text):
    assert scene_from_rexs(two_stage(), 10, warn=False).pair.kind == "single-helical"
    text = two_stage_text.replace('unit="deg">15<', 'unit="deg">0<').replace('unit="deg">-15<', 'unit="deg">0<')
    text = text.replace('<attribute id="tip_diameter" unit="mm">89.0541</attribute>', "")  # they were for 15°
    spur = two_stage(text.replace('<attribute id="root_diameter" unit="mm">229.3841</attribute>', ""))
    assert scene_from_rexs(spur, 10, warn=False).pair.kind == "spur"


def test_halves_with_different_grooves_are_refused(two_stage, cli):
    rc, _, err = cli("rexs", two_stage(herringbone(u_gear=(50.0, 160.0))), "--stage", 100)
    assert rc == 2 and "attribute u_coordinate_on_shaft" in err and "groove" in err


def test_missing_mass_is_a_listed_disc_estimate(two_stage):
    """Without mass_of_component: a steel disc of the reference diameter, listed as a default."""
    conv = read_stage(two_stage(herringbone(mass=None)), 100)
    d = 25 * 5e-3 / 0.9396926207859084                              # z m_n / cos 20°
    assert conv.data["pinion"]["mass"] == pytest.approx(7850 * 3.141592653589793 / 4 * d**2 * 0.16, rel=1e-12)
    assert "pinion.mass" in conv.defaults and "inertia" in conv.defaults["pinion.inertia"]


def test_scene_file_comments_every_value_and_lists_the_defaults(two_stage, cli, tmp_path):
    out = tmp_path / "scene.toml"
    rc, _, err = cli("rexs", two_stage(), "--stage", 10, "-o", out, "--set", "operating.torque=400.0")
    assert rc == 0, err
    text = out.read_text()
    head, _, body = text.partition("\n[")
    assert "# not in the model: default used" in head
    assert "#   pinion.inertia = " in head and "#   physics.stiffness = " in head
    values = [line for line in ("[" + body).splitlines() if line and not line.startswith(("[", "#"))]
    assert values and all("  # " in line for line in values)
    assert any(line.startswith("teeth = 19  # REXS component 11 attribute number_of_teeth") for line in values)
    assert any(line.startswith("torque = 400.0  # set on the command line") for line in values)
    scene = tomllib.loads(text)
    assert scene["pinion"]["profile_shift"] == 0.3 and scene["operating"]["torque"] == 400.0


def test_listing_as_json(two_stage, cli):
    rc, out, _ = cli("rexs", two_stage(), "--json")
    data = json.loads(out.strip().splitlines()[-1])
    assert rc == 0 and [s["id"] for s in data["stages"]] == [10, 30]
    assert data["stages"][1]["centre_distance"] == pytest.approx(0.245)


def test_missing_backlash_is_half_the_iso_tr_10064_2_minimum(two_stage):
    """j_bn,min = 2/3 (0.06 mm + 0.0005 a + 0.03 m_n), ISO/TR 10064-2 (stage 30: a = 245 mm, m_n = 5 mm);
    pair.backlash is half the total normal backlash (the dead zone |δ| ≤ b0)."""
    conv = read_stage(two_stage(), 30)
    j_bn = 2 / 3 * (0.06 + 0.0005 * 245 + 0.03 * 5) * 1e-3
    assert conv.data["pair"]["backlash"] == pytest.approx(j_bn / 2, rel=1e-12)
    assert "pair.backlash" in conv.defaults


def test_load_case_picks_the_operating_point(two_stage, two_stage_text, cli):
    """The load spectrum's case overrides the component's value; --load-case chooses the case."""
    spectrum = ('</components>\n  <load_spectrum id="1">'
                '<load_case id="1"><component id="41" name="Input shaft" type="shaft">'
                '<attribute id="rotational_speed" unit="1 / min">1000</attribute></component></load_case>'
                '<load_case id="2"><component id="41" name="Input shaft" type="shaft">'
                '<attribute id="rotational_speed" unit="rad / s">100</attribute></component>'
                '<component id="81" name="x" type="cylindrical_stage_gear_data">'
                '<attribute id="torque" unit="N m">-650</attribute></component></load_case></load_spectrum>')
    path = two_stage(two_stage_text.replace("</components>", spectrum))
    assert scene_from_rexs(path, 10, warn=False).operating.speed_rpm == 1000
    second = scene_from_rexs(path, 10, load_case=2, warn=False).operating
    assert second.speed_rpm == pytest.approx(3000 / 3.141592653589793) and second.torque == 650
    rc, _, err = cli("rexs", path, "--stage", 10, "--load-case", 3)
    assert rc == 2 and "--load-case 3" in err and "1, 2" in err


def test_deeply_nested_json_is_one_line(two_stage, cli):
    rc, _, err = cli("rexs", two_stage("[" * 100000 + "]" * 100000, name="deep.rexsj"))
    assert rc == 2 and len(err.strip().splitlines()) == 1 and "JSON" in err


def test_stage_is_needed_only_when_the_model_has_several_pairs(two_stage, cli):
    rc, _, err = cli("info", two_stage(), "-q")
    assert rc == 2 and "give --stage ID" in err and "10 (cylindrical_stage), 30 (cylindrical_stage)" in err
    rc, out, err = cli("info", two_stage(herringbone(stages=2)), "--json", "-q")   # two stages, one pair
    assert rc == 0, err
    assert json.loads(out.strip().splitlines()[-1])["geometry"]["kind"] == "double-helical"
