"""Slicing and the double-helical sum: identities against the contact-line geometry."""

import math

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels import stiffness as stiffness_levels
from femgear.levels.stiffness import mesh_stiffness
from femgear.physics.geometry import double_helical_contact
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.pem import hertz_compliance
from femgear.physics.stiffness.tvms import MeshStiffness, helix_stiffness


def test_constant_unit_stiffness_gives_contact_length(baseline_pair):
    """With k'(u) = c the sliced stiffness is c·(contact-line length)/cos β_b, per helix."""
    p = baseline_pair
    c = 1.0e10
    phases = np.linspace(0, 1, 37, endpoint=False)
    k = helix_stiffness(p, lambda u: np.full(u.shape, c), phases, n_slices=2000)
    geo = double_helical_contact(p, phases, stagger=0.3)
    np.testing.assert_allclose(k, c * geo["length_left"] / math.cos(p.beta_b), rtol=2e-3)
    kr = helix_stiffness(p, lambda u: np.full(u.shape, c), phases, n_slices=2000, offset=0.3)
    np.testing.assert_allclose(kr, c * geo["length_right"] / math.cos(p.beta_b), rtol=2e-3)


def test_integer_overlap_ratio_gives_constant_stiffness():
    # ε_β = 1 exactly: every instant has the same contact-line length
    mn, beta = 3e-3, math.radians(25)
    b = math.pi * mn / math.sin(beta)
    p = GearPair.from_parameters(z1=31, z2=34, m_n=mn, alpha_n=math.radians(20), beta=beta, b=b, x1=0, x2=0)
    k = helix_stiffness(p, lambda u: np.full(u.shape, 1e10), np.linspace(0, 1, 50, endpoint=False), n_slices=1000)
    assert (k.max() - k.min()) / k.mean() < 3e-3


def test_double_helical_stagger_period_and_ripple(baseline_pair):
    p = baseline_pair
    half = mesh_stiffness(p, "pem", n_positions=200, stagger=0.5, n_slices=80)
    zero = mesh_stiffness(p, "pem", n_positions=200, stagger=0.0, n_slices=80)
    # stagger 0: the sum is twice one helix; stagger ½: period halves, odd harmonics cancel
    np.testing.assert_allclose(zero.k_total, 2 * zero.k_left, rtol=1e-12)
    np.testing.assert_allclose(half.k_total[:100], half.k_total[100:], rtol=1e-9)
    F = np.abs(np.fft.rfft(half.k_total)) / 200
    FL = np.abs(np.fft.rfft(half.k_left)) / 200
    assert F[1] < 1e-9 * F[0] and F[3] < 1e-9 * F[0]
    assert F[2] == pytest.approx(2 * FL[2], rel=1e-6)
    assert half.ripple("total") < zero.ripple("total")
    assert half.mean == pytest.approx(zero.mean, rel=1e-9)


def test_interpolation_periodic(baseline_pair):
    ms = mesh_stiffness(baseline_pair, "pem", n_positions=64, stagger=0.25, n_slices=40)
    assert isinstance(ms, MeshStiffness)
    np.testing.assert_allclose(ms.at(ms.phase, "left"), ms.k_left)
    np.testing.assert_allclose(ms.at(ms.phase + 3.0, "right"), ms.k_right)
    kl, kr = ms(0.4)
    assert kr == pytest.approx(float(ms.at(0.65, "left")), rel=2e-3)
    with pytest.raises(AttributeError):
        ms.level = "x"


def test_levels_and_bad_arguments(baseline_pair, baseline_scene):

    iso = mesh_stiffness(baseline_pair, "iso6336", n_positions=8)
    assert iso.ripple() == 0 and iso.mean > 0
    const = stiffness_levels.of(build_case(baseline_scene), level="constant", n_positions=8)
    assert const.mean_left == pytest.approx(baseline_scene.stiffness.mesh_stiffness_per_width * baseline_pair.b)
    with pytest.raises(ValueError, match="level"):
        mesh_stiffness(baseline_pair, "weber")
    with pytest.raises(ValueError, match="stagger"):
        mesh_stiffness(baseline_pair, "pem", stagger=1.2)
    with pytest.raises(ValueError, match="n_slices"):
        helix_stiffness(baseline_pair, lambda u: u, np.zeros(2), n_slices=0)


def test_fe_level_mean_close_to_pem(baseline_pair):
    fe = mesh_stiffness(baseline_pair, "fe", n_positions=40, n_slices=40,
                        fe_options={"n_fe": 3, "h": baseline_pair.m_n / 2.5, "refine_ratio": 0.5})
    pem = mesh_stiffness(baseline_pair, "pem", n_positions=40, n_slices=40)
    assert fe.mean == pytest.approx(pem.mean, rel=0.10)
    assert fe.fe.k.shape == (3,) and all(n > 3000 for n in fe.fe.ndofs)   # graded whole gears
    assert np.allclose(fe.fe.k, 1 / (fe.fe.compliance[0] + fe.fe.compliance[1] + hertz_compliance(210e9, 0.3)))
    assert fe.ltca is None and fe.iso is None and fe.k_pair_per_width.shape == fe.u.shape
