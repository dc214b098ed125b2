"""Bad REXS models: each ends in exit 2 with one line naming the component and attribute (or, for a
file that is not a model at all, the file and what is wrong), and no scene file is written."""

from __future__ import annotations

import io
import json
import struct
import zipfile

import pytest

import femgear.rexs.read as rexs_read

GEAR11_MODULE = '<attribute id="normal_module" unit="mm">4</attribute>\n      <attribute id="number_of_teeth" unit="none">19'
BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE model [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"><!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">]>
<model version="1.4"><components><component id="1" name="&d;" type="gear_unit"/></components></model>"""
XXE = """<?xml version="1.0"?>
<!DOCTYPE model [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>
<model version="1.4"><components><component id="1" name="&xxe;" type="gear_unit"/></components></model>"""
PLANETARY = '<component id="90" name="Planetary stage" type="planetary_stage"/>\n    <component id="10"'


def _zip(members: dict[str, bytes]) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for name, data in members.items():
            archive.writestr(name, data)
    return buffer.getvalue()


def _forged_size(data: bytes) -> bytes:
    """A zip whose central directory understates the member's inflated size (100 bytes)."""
    at = data.rindex(b"PK\x01\x02")
    return data[:at + 24] + struct.pack("<I", 100) + data[at + 28:]


#: id -> (edit of the hand model: replacements, or a function of its text giving bytes/str; file name;
#:        stage; words the one line must contain)
CASES = {
    "wrong unit": ([(GEAR11_MODULE, GEAR11_MODULE.replace('unit="mm"', 'unit="deg"'))], "m.rexs", 10,
                   ['component 11 "Pinion 1"', "attribute normal_module", "not a length unit"]),
    "unknown unit": ([('<attribute id="face_width" unit="mm">40', '<attribute id="face_width" unit="furlong">40')],
                     "m.rexs", 10, ["component 11", "attribute face_width", "unknown unit 'furlong'"]),
    "missing module": ([(GEAR11_MODULE, GEAR11_MODULE.split("\n")[1].strip()),
                        ('<attribute id="normal_module" unit="mm">4</attribute>', "")], "m.rexs", 10,
                       ["component 11", "attribute normal_module", "missing"]),
    "negative teeth": ([('unit="none">58<', 'unit="none">-58<')], "m.rexs", 10,
                       ['component 12 "Wheel 1"', "attribute number_of_teeth", "must be positive"]),
    "too few teeth": ([('unit="none">19<', 'unit="none">3<')], "m.rexs", 10,
                      ["component 11", "attribute number_of_teeth", "femgear key pinion.teeth"]),
    "teeth not an integer": ([('unit="none">19<', 'unit="none">nineteen<')], "m.rexs", 10,
                             ["component 11", "attribute number_of_teeth", "not a valid integer"]),
    "mixed hands": ([('unit="deg">-15<', 'unit="deg">15<')], "m.rexs", 10,
                    ["component 12", "attribute helix_angle_reference_diameter", "mixed hands"]),
    "planetary stage": ([('<component id="10"', PLANETARY)], "m.rexs", 90,
                        ['component 90 "Planetary stage" (planetary_stage)', "planetary stage: not supported"]),
    "unknown stage": ([], "m.rexs", 99, ["--stage 99", "no such stage", "10 (cylindrical_stage)"]),
    "truncated file": (lambda text: text[: len(text) // 2], "m.rexs", 10, ["m.rexs", "not well-formed XML"]),
    "zip without a model": (lambda text: _zip({"readme.txt": b"hello"}), "m.rexsz", 10,
                            ["m.rexsz", "no REXS model", "readme.txt"]),
    "JSON of another schema": (lambda text: json.dumps({"gearbox": {"stages": []}}), "m.rexsj", 10,
                               ["m.rexsj", 'JSON of another schema: no "model" object']),
    "JSON attribute of the wrong type": (lambda text: json.dumps({"model": {"version": "1.4", "relations": [],
                                         "components": [{"id": 11, "type": "cylindrical_gear", "name": "G",
                                                         "attributes": [{"id": "number_of_teeth", "unit": "none",
                                                                         "string": "19"}]}]}}),
                                         "m.rexsj", 10, ['component 11 "G"', "attribute number_of_teeth",
                                                         "no integer value"]),
    "entity expansion": (lambda text: BILLION_LAUGHS, "m.rexs", 10, ["m.rexs", "refused", "entit"]),
    "external entity (XXE)": (lambda text: XXE, "m.rexs", 10, ["m.rexs", "refused", "entit"]),
    "zip bomb": (lambda text: _zip({"m.rexs": b"\0" * ((2 << 20) + 1)}), "m.rexsz", 10,
                 ["m.rexsz:m.rexs", "over the limit", "zip bomb"]),
    "zip bomb, forged size": (lambda text: _forged_size(_zip({"m.rexs": b"<" * (2 << 20)})), "m.rexsz", 10,
                              ["m.rexsz:m.rexs", "cannot inflate"]),
    "tip diameter vs profile shift": ([("89.0541", "95.0")], "m.rexs", 10,
                                      ["component 11", "attribute tip_diameter", "does not match profile shift",
                                       "component 21", "attribute addendum_modification_coefficient"]),
    "centre distance vs shifts": ([('unit="mm">245<', 'unit="mm">247<')], "m.rexs", 30,
                                  ['component 30 "Output stage"', "attribute center_distance", "x1 + x2",
                                   "component 25", "component 27", "addendum_modification_coefficient"]),
    "flanks with different shifts": ([('unit="none">0.3</attribute></component>\n    <component id="23"',
                                       'unit="none">0.35</attribute></component>\n    <component id="23"')], "m.rexs",
                                     10, ["component 22", "attribute addendum_modification_coefficient", "differs",
                                          "component 21"]),
    "oil viscosities reversed": ([('unit="mm^2 / s">19<', 'unit="mm^2 / s">250<')], "m.rexs", 10,
                                 ['component 60 "ISO VG 220"', "attribute viscosity_at_100_degree_celsius"]),
    "unsupported version": ([('version="1.4"', 'version="2.0"')], "m.rexs", 10, ["m.rexs", "'2.0' is not supported"]),
}


def _write(tmp_path, text: str, edit, name: str):
    if callable(edit):
        data = edit(text)
    else:
        data = text
        for old, new in edit:
            assert old in data, old
            data = data.replace(old, new, 1)
    path = tmp_path / name
    path.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8"))
    return path


@pytest.mark.parametrize("case", CASES)
def test_bad_model_ends_in_one_line_exit_2(case, two_stage_text, tmp_path, cli, monkeypatch):
    monkeypatch.setattr(rexs_read, "MAX_MODEL_BYTES", 2 << 20)   # the zip-bomb cap, small for the test
    edit, name, stage, words = CASES[case]
    path = _write(tmp_path, two_stage_text, edit, name)
    out = tmp_path / "scene.toml"
    rc, stdout, err = cli("rexs", path, "--stage", stage, "-o", out)
    lines = err.strip().splitlines()
    assert rc == 2, (stdout, err)
    assert len(lines) == 1 and "Traceback" not in err, err
    for word in words:
        assert word in lines[0], f"{word!r} not in: {lines[0]}"
    assert not out.exists()


def test_there_are_at_least_twelve_cases():
    assert len(CASES) >= 12


@pytest.mark.parametrize("command", ["info", "run"])
def test_info_and_run_report_the_same_line(command, two_stage_text, tmp_path, cli):
    path = _write(tmp_path, two_stage_text, [("89.0541", "95.0")], "m.rexs")
    rc, _, err = cli(command, path, "--stage", 10, *(["--out", tmp_path / "o"] if command == "run" else []))
    assert rc == 2
    assert "component 11" in err and "attribute tip_diameter" in err and len(err.strip().splitlines()) == 1


def test_a_failed_conversion_leaves_an_existing_scene_untouched(two_stage_text, tmp_path, cli):
    path = _write(tmp_path, two_stage_text, [('unit="none">58<', 'unit="none">-58<')], "m.rexs")
    out = tmp_path / "scene.toml"
    out.write_text("# mine\n")
    rc, _, _ = cli("rexs", path, "--stage", 10, "-o", out)
    assert rc == 2 and out.read_text() == "# mine\n"


def test_a_lone_opposite_hand_half_is_refused(two_stage_text, tmp_path, cli):
    """A shaft with two opposite-hand halves whose mate has one gear only: neither single nor double."""
    twin = ('<component id="13" name="Pinion 1 twin" type="cylindrical_gear">'
            '<attribute id="normal_module" unit="mm">4</attribute><attribute id="number_of_teeth" unit="none">19'
            '</attribute><attribute id="helix_angle_reference_diameter" unit="deg">-15</attribute>'
            '<attribute id="face_width" unit="mm">40</attribute></component>\n    <component id="10"')
    rel = ('<relation id="99" type="assembly"><ref hint="shaft" id="41" role="assembly"/>'
           '<ref hint="cylindrical_gear" id="13" role="part"/></relation>\n  </relations>')
    path = _write(tmp_path, two_stage_text, [('<component id="10"', twin), ("</relations>", rel)], "m.rexs")
    rc, _, err = cli("rexs", path, "--stage", 10)
    assert rc == 2 and "component 11" in err and "opposite-hand half (gear 13)" in err


def test_stage_only_with_a_rexs_file(cli, tmp_path):
    from pathlib import Path

    base = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
    rc, _, err = cli("info", base, "--stage", 3)
    assert rc == 2 and "--stage" in err
