"""Shared pieces of the REXS tests: a two-stage helical gearbox written by hand, and a CLI runner.

The model follows the REXS 1.4 layout (components with typed attributes and declared units;
``stage``, ``flank``, ``assembly``, ``reference``, ``stage_gear_data`` and ``side`` relations):

- stage 10: gears 11 (z 19, +15°, 40 mm, x 0.3, d_a 89.0541 mm) and 12 (z 58, −15°, 38 mm, x −0.1,
  d_f 229.3841 mm), m_n 4 mm, α_n 20°, no centre distance (femgear computes it);
- stage 30: gears 31 (z 23, −12°, 60 mm, x 0.25) and 32 (z 71, +12°, 60 mm, x 0.763697), m_n 5 mm,
  centre distance 245 mm (the shifts were chosen by hand to give it);
- shafts 41 (gear 11), 42 (gears 12 and 31: same hand, different teeth: not a herringbone),
  43 (gear 32); one material, one lubricant (ν40 220, ν100 19 mm²/s), oil at 60 °C; the input shaft
  turns at 1480 rpm, gear 11 drives with 500 N m.
"""

from __future__ import annotations

import pytest

from femgear.edge.cli import main

TWO_STAGE = """<?xml version="1.0" encoding="UTF-8"?>
<model applicationId="hand" applicationVersion="1" date="2026-11-27T00:00:00+00:00" version="1.4">
  <relations>
    <relation id="1" type="stage"><ref hint="cylindrical_stage" id="10" role="stage"/>
      <ref hint="cylindrical_gear" id="11" role="gear_1"/><ref hint="cylindrical_gear" id="12" role="gear_2"/></relation>
    <relation id="2" type="stage"><ref hint="cylindrical_stage" id="30" role="stage"/>
      <ref hint="cylindrical_gear" id="31" role="gear_1"/><ref hint="cylindrical_gear" id="32" role="gear_2"/></relation>
    <relation id="3" type="flank"><ref hint="cylindrical_gear" id="11" role="gear"/>
      <ref hint="cylindrical_gear_flank" id="21" role="left"/><ref hint="cylindrical_gear_flank" id="22" role="right"/></relation>
    <relation id="4" type="flank"><ref hint="cylindrical_gear" id="12" role="gear"/>
      <ref hint="cylindrical_gear_flank" id="23" role="left"/><ref hint="cylindrical_gear_flank" id="24" role="right"/></relation>
    <relation id="5" type="flank"><ref hint="cylindrical_gear" id="31" role="gear"/>
      <ref hint="cylindrical_gear_flank" id="25" role="left"/><ref hint="cylindrical_gear_flank" id="26" role="right"/></relation>
    <relation id="6" type="flank"><ref hint="cylindrical_gear" id="32" role="gear"/>
      <ref hint="cylindrical_gear_flank" id="27" role="left"/><ref hint="cylindrical_gear_flank" id="28" role="right"/></relation>
    <relation id="7" type="assembly"><ref hint="shaft" id="41" role="assembly"/><ref hint="cylindrical_gear" id="11" role="part"/></relation>
    <relation id="8" type="assembly"><ref hint="shaft" id="42" role="assembly"/><ref hint="cylindrical_gear" id="12" role="part"/></relation>
    <relation id="9" type="assembly"><ref hint="shaft" id="42" role="assembly"/><ref hint="cylindrical_gear" id="31" role="part"/></relation>
    <relation id="10" type="assembly"><ref hint="shaft" id="43" role="assembly"/><ref hint="cylindrical_gear" id="32" role="part"/></relation>
    <relation id="11" type="reference"><ref hint="shaft" id="41" role="origin"/><ref hint="material" id="50" role="referenced"/></relation>
    <relation id="12" type="reference"><ref hint="shaft" id="42" role="origin"/><ref hint="material" id="50" role="referenced"/></relation>
    <relation id="13" type="reference"><ref hint="shaft" id="43" role="origin"/><ref hint="material" id="50" role="referenced"/></relation>
    <relation id="14" type="reference"><ref hint="gear_casing" id="70" role="origin"/><ref hint="lubricant" id="60" role="referenced"/></relation>
    <relation id="15" type="stage_gear_data"><ref hint="cylindrical_stage" id="10" role="stage"/>
      <ref hint="cylindrical_gear" id="11" role="gear"/><ref hint="cylindrical_stage_gear_data" id="81" role="stage_gear_data"/></relation>
    <relation id="16" type="stage_gear_data"><ref hint="cylindrical_stage" id="30" role="stage"/>
      <ref hint="cylindrical_gear" id="31" role="gear"/><ref hint="cylindrical_stage_gear_data" id="82" role="stage_gear_data"/></relation>
  </relations>
  <components>
    <component id="10" name="Input stage" type="cylindrical_stage"/>
    <component id="30" name="Output stage" type="cylindrical_stage">
      <attribute id="center_distance" unit="mm">245</attribute>
    </component>
    <component id="11" name="Pinion 1" type="cylindrical_gear">
      <attribute id="normal_module" unit="mm">4</attribute>
      <attribute id="number_of_teeth" unit="none">19</attribute>
      <attribute id="helix_angle_reference_diameter" unit="deg">15</attribute>
      <attribute id="face_width" unit="mm">40</attribute>
      <attribute id="tip_diameter" unit="mm">89.0541</attribute>
    </component>
    <component id="12" name="Wheel 1" type="cylindrical_gear">
      <attribute id="normal_module" unit="mm">4</attribute>
      <attribute id="number_of_teeth" unit="none">58</attribute>
      <attribute id="helix_angle_reference_diameter" unit="deg">-15</attribute>
      <attribute id="face_width" unit="mm">38</attribute>
      <attribute id="root_diameter" unit="mm">229.3841</attribute>
    </component>
    <component id="31" name="Pinion 2" type="cylindrical_gear">
      <attribute id="normal_module" unit="mm">5</attribute>
      <attribute id="number_of_teeth" unit="none">23</attribute>
      <attribute id="helix_angle_reference_diameter" unit="deg">-12</attribute>
      <attribute id="face_width" unit="mm">60</attribute>
    </component>
    <component id="32" name="Wheel 2" type="cylindrical_gear">
      <attribute id="normal_module" unit="mm">5</attribute>
      <attribute id="number_of_teeth" unit="none">71</attribute>
      <attribute id="helix_angle_reference_diameter" unit="deg">12</attribute>
      <attribute id="face_width" unit="mm">60</attribute>
    </component>
    <component id="21" name="Pinion 1 left" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.3</attribute></component>
    <component id="22" name="Pinion 1 right" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.3</attribute></component>
    <component id="23" name="Wheel 1 left" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">-0.1</attribute></component>
    <component id="24" name="Wheel 1 right" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">-0.1</attribute></component>
    <component id="25" name="Pinion 2 left" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.25</attribute></component>
    <component id="26" name="Pinion 2 right" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.25</attribute></component>
    <component id="27" name="Wheel 2 left" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.763697</attribute></component>
    <component id="28" name="Wheel 2 right" type="cylindrical_gear_flank">
      <attribute id="normal_pressure_angle" unit="deg">20</attribute>
      <attribute id="addendum_modification_coefficient" unit="none">0.763697</attribute></component>
    <component id="41" name="Input shaft" type="shaft">
      <attribute id="rotational_speed" unit="1 / min">1480</attribute></component>
    <component id="42" name="Intermediate shaft" type="shaft"/>
    <component id="43" name="Output shaft" type="shaft"/>
    <component id="50" name="18CrNiMo7-6" type="material">
      <attribute id="elastic_modulus" unit="N / mm^2">206000</attribute>
      <attribute id="poisson_ratio" unit="none">0.3</attribute>
      <attribute id="density" unit="kg / dm^3">7.83</attribute>
      <attribute id="thermal_expansion_coefficient_plus" unit="1e-6 / C">11.5</attribute>
    </component>
    <component id="60" name="ISO VG 220" type="lubricant">
      <attribute id="viscosity_at_40_degree_celsius" unit="mm^2 / s">220</attribute>
      <attribute id="viscosity_at_100_degree_celsius" unit="mm^2 / s">19</attribute>
      <attribute id="density_at_15_degree_celsius" unit="kg / dm^3">0.895</attribute>
      <attribute id="pressure_viscosity_coefficient_at_38_degrees_celsius" unit="mm^2 / N">0.018</attribute>
    </component>
    <component id="70" name="Casing" type="gear_casing">
      <attribute id="temperature_lubricant" unit="C">60</attribute></component>
    <component id="81" name="Pinion 1 in stage 1" type="cylindrical_stage_gear_data">
      <attribute id="torque" unit="N m">500</attribute>
      <attribute id="is_driving_gear" unit="none">true</attribute></component>
    <component id="82" name="Pinion 2 in stage 2" type="cylindrical_stage_gear_data">
      <attribute id="torque" unit="N m">1526.3158</attribute>
      <attribute id="is_driving_gear" unit="none">true</attribute></component>
  </components>
</model>
"""


@pytest.fixture
def two_stage_text() -> str:
    return TWO_STAGE


@pytest.fixture
def two_stage(tmp_path):
    """Write the hand-written two-stage model (optionally edited) and return its path."""
    def write(text: str = TWO_STAGE, name: str = "gearbox.rexs", replace: tuple[tuple[str, str], ...] = ()):
        for old, new in replace:
            assert old in text, old
            text = text.replace(old, new, 1)
        path = tmp_path / name
        path.write_text(text, encoding="utf-8") if isinstance(text, str) else path.write_bytes(text)
        return path
    return write


@pytest.fixture
def cli(capsys):
    """Run ``femgear argv``: (exit code, stdout, stderr)."""
    def run(*argv) -> tuple[int, str, str]:
        try:
            rc = main([str(a) for a in argv])
        except SystemExit as exc:
            rc = exc.code
        out, err = capsys.readouterr()
        return rc, out, err
    return run
