"""A two-stage helical gearbox written by hand (conftest.TWO_STAGE): both stages import, and
``femgear info`` gives the centre distance and contact ratios of a hand ISO 21771 calculation.

The hand calculation below is written out from ISO 21771:2007 §§4–5 (no femgear function):
tan α_t = tan α_n / cos β; inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2); a_w = a cos α_t / cos α_wt;
k = (a_w − a)/m_n − (x1 + x2); d_a = d + 2 m_n (h_aP + x + k); p_bt = π m_t cos α_t;
ε_α = [√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w sin α_wt] / p_bt; ε_β = b sin β / (π m_n).
"""

from __future__ import annotations

import json
import math

import pytest

from femgear.rexs.importer import scene_from_rexs


def _inv_inverse(value: float) -> float:
    alpha = 0.5
    for _ in range(60):  # Newton on tan a − a − value (derivative tan² a)
        alpha -= (math.tan(alpha) - alpha - value) / math.tan(alpha) ** 2
    return alpha


def iso21771(z1, z2, m_n, beta_deg, x1, x2, b, alpha_n_deg=20.0, h_aP=1.0):
    beta, alpha_n = math.radians(beta_deg), math.radians(alpha_n_deg)
    alpha_t = math.atan(math.tan(alpha_n) / math.cos(beta))
    m_t = m_n / math.cos(beta)
    d1, d2 = z1 * m_t, z2 * m_t
    a = (d1 + d2) / 2
    alpha_wt = _inv_inverse(math.tan(alpha_t) - alpha_t + 2 * math.tan(alpha_n) * (x1 + x2) / (z1 + z2))
    a_w = a * math.cos(alpha_t) / math.cos(alpha_wt)
    k = (a_w - a) / m_n - (x1 + x2)
    ra1, ra2 = d1 / 2 + m_n * (h_aP + x1 + k), d2 / 2 + m_n * (h_aP + x2 + k)
    rb1, rb2 = d1 / 2 * math.cos(alpha_t), d2 / 2 * math.cos(alpha_t)
    p_bt = math.pi * m_t * math.cos(alpha_t)
    eps_a = (math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - a_w * math.sin(alpha_wt)) / p_bt
    eps_b = b * math.sin(beta) / (math.pi * m_n)
    return {"centre_distance": a_w, "eps_alpha": eps_a, "eps_beta": eps_b, "eps_gamma": eps_a + eps_b}


HAND = {10: iso21771(19, 58, 4e-3, 15, 0.3, -0.1, 38e-3), 30: iso21771(23, 71, 5e-3, 12, 0.25, 0.763697, 60e-3)}


def test_the_hand_figures_are_those_of_the_model():
    """The hand model's numbers: stage 30's shifts were chosen for a 245 mm centre distance."""
    assert HAND[30]["centre_distance"] == pytest.approx(0.245, rel=1e-8)
    assert HAND[10]["centre_distance"] == pytest.approx(0.1602191, rel=1e-6)   # x1 + x2 = 0.2 opens a by 0.48 mm
    assert 1.0 < HAND[10]["eps_alpha"] < 2.0 and 0.5 < HAND[30]["eps_beta"] < 1.0


def test_listing_shows_both_stages(two_stage, cli):
    rc, out, err = cli("rexs", two_stage())
    assert rc == 0, err
    lines = out.splitlines()
    assert "2 stages" in lines[0]
    assert any(line.split()[:2] == ["10", "19/58"] and "single-helical" in line for line in lines)
    assert any(line.split()[:2] == ["30", "23/71"] and line.split()[5] == "245" for line in lines)


@pytest.mark.parametrize("stage", [10, 30])
def test_info_gives_the_hand_iso21771_figures(stage, two_stage, cli):
    rc, out, err = cli("info", two_stage(), "--stage", stage, "--json", "-q")
    assert rc == 0, err
    geometry = json.loads(out.strip().splitlines()[-1])["geometry"]
    for key, value in HAND[stage].items():
        assert geometry[key] == pytest.approx(value, rel=1e-9), key
    assert geometry["kind"] == "single-helical"


def test_both_stages_import_with_their_data(two_stage):
    path = two_stage()
    first, second = scene_from_rexs(path, 10, warn=False), scene_from_rexs(path, 30, warn=False)
    assert (first.pinion.teeth, first.gear.teeth, second.pinion.teeth, second.gear.teeth) == (19, 58, 23, 71)
    assert first.pair.face_width == pytest.approx(38e-3) and first.pinion.face_width == pytest.approx(40e-3)
    assert first.pinion.tip_diameter == pytest.approx(89.0541e-3)
    assert first.pair.dedendum_coeff == pytest.approx(1.25, abs=1e-5)   # from the root diameter (given to 0.1 µm)
    assert second.pair.centre_distance == pytest.approx(0.245)
    assert first.material.youngs_modulus == pytest.approx(206e9) and first.material.density == pytest.approx(7830)
    assert first.operating.speed_rpm == 1480 and first.operating.torque == 500
    assert first.operating.ambient_temperature == pytest.approx(333.15)
    # α is given at 38 °C, the scene's holds at the 60 °C oil: the oil's own (Roelands) law carries it there
    from femgear.physics.lubrication.oil import OilLaw

    law = OilLaw.from_table(first.oil, first.oil_reference_temperature)
    slope = float(law.log_viscosity_ratio(1e3, 311.15) - law.log_viscosity_ratio(0.0, 311.15)) / 1e3
    assert slope == pytest.approx(18e-9, rel=1e-4) and first.oil.pressure_viscosity < 18e-9
    assert first.rating.oil_viscosity_40 == pytest.approx(220)


def test_oil_viscosity_follows_astm_d341_at_the_oil_temperature(two_stage):
    """60 °C between the data sheet points: η = ν(60 °C) ρ(60 °C), ν from log log(ν+0.7) linear in log T."""
    scene = scene_from_rexs(two_stage(), 10, warn=False)
    w = [math.log10(math.log10(nu + 0.7)) for nu in (220, 19)]
    slope = (w[0] - w[1]) / (math.log10(313.15) - math.log10(373.15))
    nu60 = 10 ** 10 ** (w[0] + slope * (math.log10(333.15) - math.log10(313.15))) - 0.7
    rho60 = 895 / (1 - 6.5e-4 * (288.15 - 333.15))
    assert scene.oil.density == pytest.approx(rho60, rel=1e-12)
    assert scene.oil.viscosity == pytest.approx(nu60 * 1e-6 * rho60, rel=1e-9)
    assert 60 < nu60 < 110


def test_json_and_older_versions_give_the_same_scene(two_stage, two_stage_text, tmp_path):
    """The same model as REXS 1.1 (flank_geometry, stage_gear_data, the unit °) and as JSON."""
    from femgear.rexs.read import read_model
    from femgear.rexs.write import to_json

    ref = scene_from_rexs(two_stage(), 30, warn=False)
    old_text = (two_stage_text.replace('version="1.4"', 'version="1.1"')
                .replace("cylindrical_gear_flank", "flank_geometry")
                .replace("cylindrical_stage_gear_data", "stage_gear_data").replace('unit="deg"', 'unit="°"'))
    old = two_stage(old_text, name="old.rexs")
    assert scene_from_rexs(old, 30, warn=False).model_copy(update={"meta": ref.meta}) == ref
    as_json = tmp_path / "gearbox.rexsj"
    as_json.write_text(to_json(read_model(two_stage())))
    assert scene_from_rexs(as_json, 30, warn=False).model_copy(update={"meta": ref.meta}) == ref

