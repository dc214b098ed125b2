"""The LTCA of a single-helical (and spur) pair: one helix of the real face width (issue 37 item 1).

Before, every pair was solved as a double helix: the industrial zoo stage (m_n 4, z 21/86, β 15°, b 80 mm)
came out as two helices of 80 mm on a V body, a 50/50 share, a stiffness 46–54 % above PEM, FE and ISO
6336 and half the load per length.  Coarse bodies here (P1, level 0, 3 teeth, 5 × 5 grid, disk-cached);
the default bodies' figures are in docs/models/ltca.md.
"""

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from femgear.errors import SceneError

ROOT = Path(__file__).resolve().parents[2]
INDUSTRIAL = ROOT / "studies" / "zoo" / "industrial.toml"
COARSE = dict(level=0, order=1, n_rho=5, n_z=5, n_teeth=3)


@pytest.fixture(scope="module")
def case():
    from femgear.case import build_case
    from femgear.scene import load_scene

    return build_case(load_scene(INDUSTRIAL, ["modifications.crowning=0.0"]))


@pytest.fixture(scope="module")
def model(case):
    from femgear.levels.stiffness import body_options
    from femgear.physics.ltca.analysis import build_model

    body = {k: v for k, v in body_options(case).items() if k != "stagger"}
    return build_model(case.pair, case.material.youngs_modulus, case.material.poisson_ratio, **COARSE, **body)


@pytest.fixture(scope="module")
def cycle(model, case):
    from femgear.physics.ltca.analysis import mesh_cycle

    return mesh_cycle(model, case.operating.normal_force, n_phases=16)


def test_the_body_and_the_contact_lines_are_one_helix_of_the_face_width(model, case):
    from femgear.physics.ltca.contact import phase_points
    from femgear.physics.mesh.segment import default_spec, member_body

    pair = case.pair
    assert pair.kind == "single-helical" and pair.n_helices == 1
    spec = default_spec(pair, 1, 0, n_teeth=3, r_bore=0.03)
    body = member_body(pair, 1, spec)
    assert body.p[2].min() == pytest.approx(0.0, abs=1e-12) and body.p[2].max() == pytest.approx(pair.b, rel=1e-12)
    assert "loaded_flank_right" not in body.boundaries
    assert model.kernels[1].cross is None and model.kernels[2].cross is None
    for phase in (0.0, 0.3, 0.7):
        pts = phase_points(pair, phase, 0.0, 16)
        assert np.all(pts.helix == 0) and pts.zeta.min() >= 0 and pts.zeta.max() <= pair.b


def test_the_one_helix_carries_the_normal_force_to_1e_6(cycle, case):
    """All of F_n = T/(r_b1 cos β_b) on the helix at every phase, the line loads summing to it to 1e-6."""
    pair = case.pair
    F = case.operating.pinion_torque / pair.rb1 / math.cos(pair.beta_b)
    assert cycle.force == pytest.approx(F, rel=1e-12) and cycle.n_helices == 1
    assert np.max(np.abs(cycle.force_left - F)) <= 1e-6 * F
    assert np.all(cycle.force_right == 0) and np.all(cycle.k_secant_right == 0)
    assert cycle.load_error.max() < 1e-6
    for i in range(cycle.phase.size):
        lines = cycle.loads_per_line(i)
        assert all(h == "left" for h, _ in lines)
        assert sum(lines.values()) == pytest.approx(F, rel=1e-6)


def test_no_load_share_and_no_right_helix_fields_in_the_te_summary(cycle, case):
    from femgear.edge.io.ltca import te_curves, te_summary
    from femgear.physics.ltca.te import analyse_cycle

    m = case.material
    a = analyse_cycle(cycle, case.pair, m.youngs_modulus, m.poisson_ratio, case.operating.pinion_torque)
    assert a.share_left is None and a.share_right is None and a.n_helices == 1
    summary = te_summary(a, math.cos(case.pair.beta_b))
    assert summary["helices"] == 1
    assert not any("share_left" in k or "right" in k for k in summary)
    assert "force_right" not in te_curves(a) and "lte_left" not in te_curves(a)
    assert a.pressure.helix == "left" and a.pressure.where in ("interior", "pinion tip", "gear tip", "face end")


@pytest.mark.slow
def test_stiffness_per_helix_is_the_double_helical_ones(model, cycle, case):
    """The same helix in a grooved double-helical body is 7–18 % stiffer per helix (its axial forces balance,
    the single helix's tilts its body, and the rim goes on under the groove), and carries half the load each:
    the single-helical pair is one helix of it, not two (the old model gave a ratio of 0.5)."""
    from femgear.levels.stiffness import body_options
    from femgear.physics.ltca.analysis import build_model, mesh_cycle

    pair = case.pair
    double = dataclasses.replace(pair, kind="double-helical")
    md = build_model(double, case.material.youngs_modulus, case.material.poisson_ratio, groove_width=pair.b, **COARSE,
                     bore_radius=body_options(case)["bore_radius"])
    rd = mesh_cycle(md, 2 * case.operating.normal_force, n_phases=16)
    ratio = rd.mean_stiffness() / (2 * cycle.mean_stiffness())
    assert 1.0 < ratio < 1.25
    assert np.mean(rd.force_left) / rd.force == pytest.approx(0.5, abs=1e-9)


def test_mean_stiffness_lies_near_pem_and_fe(cycle, case):
    """Between PEM and the 2-D FE sections within ±20 %, a regression band (coarse P1 bodies: −8 % from PEM; the
    default p2-bending bodies −15 %).  The slice levels are stiff: their Yang–Lin Hertz term and their uncoupled
    teeth; against the 2-D FE of the whole sections with every tooth pair loaded at once the default bodies are
    −5 % (tests/ltca/test_tooth_coupling.py, docs/models/ltca.md).  The old two-helix model of this pair was twice as
    stiff on these bodies (+96 % from PEM)."""
    from femgear.levels import stiffness as levels

    pem = float(np.mean(levels.of(case, "pem").k_total))
    fe = float(np.mean(levels.of(case, "fe").k_total))
    k = cycle.mean_stiffness()
    assert 0.8 * min(pem, fe) <= k <= 1.2 * max(pem, fe)


def test_maps_hold_one_helix(cycle, case, tmp_path):
    import meshio

    from femgear.edge.io.ltca import write_flank_pressure, write_maps_vtu
    from femgear.physics.ltca.maps import load_maps

    m = case.material
    maps = load_maps(cycle, case.pair, m.youngs_modulus, m.poisson_ratio, case.operating.pinion_torque, 0)
    assert maps.helix_force(1).shape == (1,)
    assert maps.helix_force(1)[0] == pytest.approx(np.mean(cycle.force_left), rel=0.03)
    mesh = meshio.read(write_maps_vtu(tmp_path / "m.vtu", maps))
    assert set(np.unique(mesh.point_data["helix"])) == {0}
    flank = meshio.read(write_flank_pressure(tmp_path / "f.vtu", cycle, case.pair, m.youngs_modulus, m.poisson_ratio))
    assert flank.points.shape[0] == 40 * 60 and flank.points[:, 2].max() <= case.pair.b * (1 + 1e-9)


def test_a_spur_pair_has_its_lines_across_the_face_without_dividing_by_tan_beta_b():
    from femgear.case.pair import pair_from_scene
    from femgear.physics.ltca.contact import phase_points
    from femgear.scene import load_scene

    pair = pair_from_scene(load_scene(ROOT / "studies" / "zoo" / "fzg_c14.toml"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for phase in (0.0, 0.25, 0.6):
            pts = phase_points(pair, phase, 0.0, 8)
            assert np.all(pts.helix == 0)
            for j in np.unique(pts.line):
                on = pts.line == j
                assert np.ptp(pts.u[on]) == 0 and pts.length[on].sum() == pytest.approx(pair.b, rel=1e-12)
            assert np.all((pts.u >= pair.u_start) & (pts.u < pair.u_end))


@pytest.mark.parametrize("key, value", [("pair.stagger", "0.5"), ("modifications.helix_slope_deviation_right", "5e-6")])
def test_a_second_helix_key_is_refused_for_one_helix(key, value):
    from femgear.case import build_case
    from femgear.scene import load_scene

    with pytest.raises(SceneError) as err:
        build_case(load_scene(INDUSTRIAL, [f"{key}={value}"]))
    assert err.value.key == key
