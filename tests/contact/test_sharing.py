"""Load sharing along the path: FZG C14 against a hand calculation, identities of the sharing model."""

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import trapezoid

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.contact import contact_pass
from femgear.physics.contact.sharing import load_sharing, single_contact_bounds
from femgear.physics.geometry.gear import GearPair
from femgear.scene import load_scene

STUDIES = Path(__file__).resolve().parents[2] / "studies"


@pytest.fixture(scope="module")
def fzg_c14():
    return load_scene(STUDIES / "fzg_c14.toml")


def _hand_fzg_c14(torque: float):
    """FZG C14 by hand, from the drawing data only (m 4.5, z 16/24, x 0.1817/0.1715, a 91.5 mm,
    d_a 82.456/118.364 mm, b 14 mm, E 206 GPa, ν 0.3): single-pair load F_bn/b at the pitch
    point C and at the inner point of single contact B (Niemann & Winter II §21; Johnson 4.45)."""
    m, z1, z2, a_w, b = 4.5e-3, 16, 24, 91.5e-3, 14e-3
    alpha = math.radians(20)
    rb1 = z1 * m / 2 * math.cos(alpha)
    alpha_w = math.acos((z1 + z2) * m / 2 * math.cos(alpha) / a_w)
    T1T2 = a_w * math.sin(alpha_w)
    T1E = math.sqrt((82.456e-3 / 2) ** 2 - rb1**2)
    p_b = math.pi * m * math.cos(alpha)
    E_red = 206e9 / (1 - 0.3**2)
    w = torque / rb1 / b
    out = {}
    for name, rho1 in (("C", rb1 * math.tan(alpha_w)), ("B", T1E - p_b)):
        R = rho1 * (T1T2 - rho1) / T1T2
        half = math.sqrt(8 * w * R / (math.pi * E_red))
        out[name] = (rho1, 2 * w / (math.pi * half), half)
    return out


def test_fzg_c14_single_pair_hertz_against_hand(fzg_c14):
    """FZG C14, 200 N m: p_H and b_H at C and at B within 1 % of the single-pair hand calculation."""
    hand = _hand_fzg_c14(200.0)
    pair = pair_from_scene(fzg_c14)
    u_B, _ = single_contact_bounds(pair)
    c = contact_pass(build_case(fzg_c14), u=np.array([u_B, pair.u_pitch]))
    for i, name in enumerate(("B", "C")):
        rho1, p_hand, b_hand = hand[name]
        assert c.kin.u[i] == pytest.approx(rho1, rel=1e-3)
        assert c.hertz_pressure[i] == pytest.approx(p_hand, rel=0.01)
        assert c.hertz_half_width[i] == pytest.approx(b_hand, rel=0.01)
    # the time-mean load of the old pass would be ε_α^(-1/2) ≈ 17 % low at the pitch point
    p_mean = c.hertz_pressure[1] * math.sqrt(c.load_per_length / c.line_load[1])
    assert p_mean / hand["C"][1] == pytest.approx(pair.eps_alpha ** -0.5, rel=1e-3)
    assert p_mean < 0.9 * hand["C"][1]


def test_fzg_c14_default_grid_pitch_point(fzg_c14):
    c = contact_pass(build_case(fzg_c14))
    assert c.hertz_pressure[c.pitch_index] == pytest.approx(_hand_fzg_c14(200.0)["C"][1], rel=0.01)
    assert c.n_helices == 1


def _spur(**kw):
    base = dict(z1=20, z2=40, m_n=3e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=0.0, x2=0.0, kind="spur")
    base.update(kw)
    return GearPair.from_parameters(**base)


def test_spur_uniform_stiffness_zones():
    """Uniform pair stiffness: F/(2b) in the double-contact zones, F/b between B and D (inclusive)."""
    p = _spur()
    u_B, u_D = single_contact_bounds(p)
    u = np.array([p.u_start, 0.5 * (p.u_start + u_B), u_B, p.u_pitch, u_D, 0.5 * (u_D + p.u_end), p.u_end])
    s = load_sharing(p, u, 1000.0)
    np.testing.assert_allclose(s.line_load * p.b, [500, 500, 1000, 1000, 1000, 500, 500], rtol=1e-12)


def test_spur_pem_sharing_follows_stiffness():
    """With PEM stiffness the pair near the pitch point carries more than half in the double zone's
    middle only if stiffer; shares of the two pairs in contact sum to one."""
    from femgear.physics.stiffness.pem import pair_stiffness_per_width

    p = _spur()
    k = lambda x: pair_stiffness_per_width(p, x, 206e9, 0.3)  # noqa: E731
    u = np.linspace(p.u_start + 1e-6, single_contact_bounds(p)[0] - 1e-6, 7)
    own = load_sharing(p, u, 1000.0, k).fraction
    partner = load_sharing(p, u + p.p_bt, 1000.0, k).fraction
    np.testing.assert_allclose(own + partner, 1.0, rtol=1e-12)
    np.testing.assert_allclose(own, k(u) / (k(u) + k(u + p.p_bt)), rtol=1e-9)


@pytest.mark.parametrize("kind", ["spur", "single-helical"])
def test_time_mean_force_balance(kind):
    """(b/(p_bt cos β_b)) ∫ w̄ du = F_n: the time mean of the load carried equals the force (PEM stiffness)."""
    from femgear.physics.stiffness.pem import pair_stiffness_per_width

    beta = 0.0 if kind == "spur" else math.radians(17)
    from femgear.physics.stiffness.tvms import tabulated

    p = _spur(beta=beta, kind=kind, b=0.025)
    grid = np.linspace(p.u_start, p.u_end, 81)
    k = tabulated(p, grid, pair_stiffness_per_width(p, grid, 206e9, 0.3))
    u = np.linspace(p.u_start, p.u_end, 4001)
    s = load_sharing(p, u, 1000.0, k)
    total = p.b / (p.p_bt * math.cos(p.beta_b)) * trapezoid(s.line_load, u)
    assert total == pytest.approx(1000.0, rel=2e-3)


def test_helical_integer_overlap_uniform_load():
    """ε_β = 1 and uniform stiffness: constant contact-line length, so w = F/L̄ everywhere (ISO's uniform load)."""
    beta = math.radians(20)
    b = math.pi * 3e-3 / math.sin(beta)
    p = _spur(beta=beta, kind="single-helical", b=b)
    assert p.eps_beta == pytest.approx(1.0)
    u = np.linspace(p.u_start, p.u_end, 9)
    s = load_sharing(p, u, 1000.0)
    np.testing.assert_allclose(s.line_load, 1000.0 / p.mean_contact_length, rtol=2e-3)


def test_bad_force():
    with pytest.raises(ValueError, match="force"):
        load_sharing(_spur(), np.array([0.01]), -1.0)
