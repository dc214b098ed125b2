"""The contact-line integral and the double-helical sum: identities against the contact-line geometry."""

import math
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels import stiffness as stiffness_levels
from femgear.physics.geometry import double_helical_contact
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness import uniform_mesh_stiffness
from femgear.physics.stiffness.pem import hertz_compliance, pem_mesh_stiffness
from femgear.physics.stiffness.tvms import MeshStiffness, helix_stiffness, iso6336_helix_stiffness


def constant(pair, c: float) -> tuple[np.ndarray, np.ndarray]:
    """k'(u) = c along the path, as samples."""
    u = np.linspace(pair.u_start, pair.u_end, 5)
    return u, np.full(u.shape, c)


def test_constant_unit_stiffness_gives_contact_length(baseline_pair):
    """With k'(u) = c the stiffness is c·(contact-line length)/cos β_b per helix, exactly (the contact-line
    integral has no slicing error)."""
    p = baseline_pair
    c = 1.0e10
    phases = np.linspace(0, 1, 37, endpoint=False)
    k = helix_stiffness(p, *constant(p, c), phases)
    geo = double_helical_contact(p, phases, stagger=0.3)
    np.testing.assert_allclose(k, c * geo["length_left"] / math.cos(p.beta_b), rtol=1e-12)
    kr = helix_stiffness(p, *constant(p, c), phases, offset=0.3)
    np.testing.assert_allclose(kr, c * geo["length_right"] / math.cos(p.beta_b), rtol=1e-12)


def test_integer_overlap_ratio_gives_constant_stiffness():
    # ε_β = 1 exactly: every instant has the same contact-line length
    mn, beta = 3e-3, math.radians(25)
    b = math.pi * mn / math.sin(beta)
    p = GearPair.from_parameters(z1=31, z2=34, m_n=mn, alpha_n=math.radians(20), beta=beta, b=b, x1=0, x2=0)
    k = helix_stiffness(p, *constant(p, 1e10), np.linspace(0, 1, 50, endpoint=False))
    assert (k.max() - k.min()) / k.mean() < 1e-12


def test_stiffness_is_continuous_on_a_wide_face():
    """The marine pair (ε_β = 3.2, 2 × 120 mm): the table has no steps or notches.  Between neighbouring phases
    (1/2000 of a mesh period) the PEM stiffness moves by at most its largest slope times the phase step; the
    midpoint sum over 100 slices used before jumped by k'(u_A) Δb ≈ 0.6 % within one step."""
    from femgear.case.pair import pair_from_scene
    from femgear.scene import load_scene

    pair = pair_from_scene(load_scene(Path(__file__).resolve().parents[2] / "studies" / "zoo" / "marine.toml"))
    ms = pem_mesh_stiffness(pair, 210e9, 0.3, 2000)
    k = ms.k_left
    steps = np.abs(np.diff(np.append(k, k[0])))
    # the slope dk/dφ is bounded by the entering and leaving lines: ≤ (k'(u_A) + k'(u_E)) p_bt / tan β_b / cos² β_b
    k_ends = ms.k_pair_per_width[0] + ms.k_pair_per_width[-1]
    slope = k_ends * pair.p_bt / math.tan(pair.beta_b) / math.cos(pair.beta_b) ** 2
    assert steps.max() <= 1.01 * slope / 2000
    assert steps.max() < 1e-3 * k.mean()


def test_a_spur_line_sees_one_position():
    """Spur (β = 0): every line is one path position, k = k'(u) b for each pair in contact."""
    p = GearPair.from_parameters(z1=20, z2=40, m_n=4e-3, alpha_n=math.radians(20), beta=0.0, b=0.03, x1=0, x2=0)
    u = np.linspace(p.u_start, p.u_end, 9)
    ks = 1e10 * (1 + 0.3 * (u - u[0]) / (u[-1] - u[0]))           # a linear k'(u): the spline reproduces it
    phases = np.array([0.1, 0.6])
    k = helix_stiffness(p, u, ks, phases)
    for phi, value in zip(phases, k):
        pos = p.u_start + phi * p.p_bt + np.arange(-1, 4) * p.p_bt
        pos = pos[(pos >= p.u_start) & (pos <= p.u_end)]
        assert value == pytest.approx(np.sum(np.interp(pos, u, ks)) * p.b, rel=1e-12)


def test_double_helical_stagger_period_and_ripple(baseline_pair):
    p = baseline_pair
    half = pem_mesh_stiffness(p, 210e9, 0.3, 200, stagger=0.5)
    zero = pem_mesh_stiffness(p, 210e9, 0.3, 200, stagger=0.0)
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
    ms = pem_mesh_stiffness(baseline_pair, 210e9, 0.3, 64, stagger=0.25)
    assert isinstance(ms, MeshStiffness)
    np.testing.assert_allclose(ms.at(ms.phase, "left"), ms.k_left)
    np.testing.assert_allclose(ms.at(ms.phase + 3.0, "right"), ms.k_right)
    kl, kr = ms(0.4)
    assert kr == pytest.approx(float(ms.at(0.65, "left")), rel=2e-3)
    with pytest.raises(AttributeError):
        ms.level = "x"


def test_levels_and_bad_arguments(baseline_pair, baseline_scene):

    k, record = iso6336_helix_stiffness(baseline_pair)
    iso = uniform_mesh_stiffness(baseline_pair, k, "iso6336", 8, iso=record)
    assert iso.ripple() == 0 and iso.mean > 0
    const = stiffness_levels.of(build_case(baseline_scene), level="constant", n_positions=8)
    assert const.mean_left == pytest.approx(baseline_scene.stiffness.mesh_stiffness_per_width * baseline_pair.b)
    with pytest.raises(ValueError, match="physics.stiffness.*unknown level 'weber'"):
        stiffness_levels.of(build_case(baseline_scene), level="weber")
    with pytest.raises(ValueError, match="stagger"):
        pem_mesh_stiffness(baseline_pair, 210e9, 0.3, 200, stagger=1.2)


def test_fe_level_mean_close_to_pem(baseline_pair, baseline_scene):
    case = build_case(baseline_scene)
    fe = stiffness_levels.of(case, level="fe", n_positions=40,
                             fe_options={"n_fe": 3, "h": baseline_pair.m_n / 2.5, "refine_ratio": 0.5})
    pem = stiffness_levels.of(case, level="pem", n_positions=40)
    assert fe.mean == pytest.approx(pem.mean, rel=0.10)
    assert fe.fe.k.shape == (3,) and all(n > 3000 for n in fe.fe.ndofs)   # graded whole gears
    assert np.allclose(fe.fe.k, 1 / (fe.fe.compliance[0] + fe.fe.compliance[1] + hertz_compliance(210e9, 0.3)))
    assert fe.ltca is None and fe.iso is None and fe.k_pair_per_width.shape == fe.u.shape
