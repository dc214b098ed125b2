"""FE tooth compliance (``fe`` level) against the potential energy method."""

from pathlib import Path

import numpy as np
import pytest

from femgear.case.pair import pair_from_scene
from femgear.physics.body.compliance import ToothFE, fe_pair_stiffness_per_width
from femgear.physics.mesh.section import gear_section
from femgear.physics.stiffness.pem import pair_stiffness_per_width

BASELINE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"


@pytest.fixture(scope="module")
def pair():
    from femgear.scene import load_scene

    return pair_from_scene(load_scene(BASELINE))


def test_pem_within_10_percent_of_fe_in_single_pair_zone(pair):
    u0, u1 = pair.u_end - pair.p_bt, pair.u_start + pair.p_bt
    u = np.linspace(u0, u1, 3)
    k_fe, info = fe_pair_stiffness_per_width(pair, u, 210e9, 0.3, h=pair.m_n / 2.5, refine_ratio=0.3)
    k_pem = pair_stiffness_per_width(pair, u, 210e9, 0.3)
    dev = k_pem / k_fe - 1
    assert np.all(np.abs(dev) < 0.10), dev


def test_graded_far_field_keeps_the_compliance_with_fewer_dof(pair):
    """The far field coarsened by distance (module units) changes the pitch-point compliance by < 1 %."""
    graded = ToothFE(pair, 1, 210e9, 0.3, h=pair.m_n / 2.5, refine_ratio=0.5)
    uniform = ToothFE(pair, 1, 210e9, 0.3, h=pair.m_n / 2.5, refine_ratio=0.5, grade=None)
    assert graded.ndofs < 0.8 * uniform.ndofs
    c_g, c_u = graded.compliance(pair.u_pitch), uniform.compliance(pair.u_pitch)
    assert c_g == pytest.approx(c_u, rel=0.01)


def test_section_size_in_module_units():
    """Similar gears (all lengths × 2) get the same 2-D mesh: the sizes follow the module."""
    from femgear.physics.body.compliance import section_size
    from femgear.scene import load_scene

    a = pair_from_scene(load_scene(BASELINE))
    b = pair_from_scene(load_scene(BASELINE, ["pair.normal_module=6e-3", "pair.face_width=35e-3"]))
    ma, mb = ToothFE(a, 1, 210e9, 0.3, n_teeth=3).mesh, ToothFE(b, 1, 210e9, 0.3, n_teeth=3).mesh
    assert section_size(b) == pytest.approx(2 * section_size(a))
    assert abs(mb.p.shape[1] - ma.p.shape[1]) <= 0.02 * ma.p.shape[1]


def test_compliance_linear_in_load_and_grows_to_tip(pair):
    m = ToothFE(pair, 1, 210e9, 0.3, h=pair.m_n / 2.5, refine_ratio=0.5)
    c1 = m.compliance(pair.u_pitch, force=1e4)
    c2 = m.compliance(pair.u_pitch, force=3e5)
    assert c1 == pytest.approx(c2, rel=1e-9)
    c_root, c_tip = m.compliance(pair.u_start), m.compliance(pair.u_end)
    assert c_root < c1 < c_tip


def test_a_coarse_mesh_refines_the_tip_and_a_thin_rim_is_named(pair):
    """h = m_n puts fewer than two elements across the tip: the tip circle gets its own size (issue 39); a rim of
    one module (0.44 h_t, under ISO 6336-3's 0.5 h_t) is refused naming the bore."""
    import numpy as np

    sec = gear_section(pair, 1, h=pair.m_n, n_teeth=3)
    tip = sec.boundaries["tip"]
    width = pair.tip_thickness(1)
    assert np.linalg.norm(sec.p[:, sec.facets[0, tip]] - sec.p[:, sec.facets[1, tip]], axis=0).max() <= 0.5 * width
    with pytest.raises(ValueError, match="mesh size h"):
        gear_section(pair, 1, h=-1.0, n_teeth=3)
    with pytest.raises(ValueError, match="bore_radius"):
        gear_section(pair, 1, h=pair.m_n / 3, n_teeth=3, bore_radius=pair.rf1 - pair.m_n)


@pytest.mark.slow
def test_fe_compliance_converges_under_refinement(pair):
    """Self-convergence of the pitch-point compliance (P2, fixed load patch)."""
    cs = []
    for h in (pair.m_n / 2.5, pair.m_n / 4, pair.m_n / 6.5):
        cs.append(ToothFE(pair, 1, 210e9, 0.3, h=h, refine_ratio=0.5).compliance(pair.u_pitch))
    assert abs(cs[2] - cs[1]) < 0.01 * cs[2]
    assert abs(cs[1] - cs[0]) < 0.03 * cs[2]
