"""Kinematics along the path of contact and contact lines of a double-helical pair."""

import math

import numpy as np
import pytest

from femgear.physics.geometry import contact_lines, double_helical_contact, kinematics, mesh_frequency, path_positions


def test_sliding_vanishes_at_the_pitch_point_and_changes_sign(baseline_pair):
    p = baseline_pair
    omega1 = 500 * 2 * math.pi / 60
    k = kinematics(p, np.array([p.u_start, p.u_pitch, p.u_end]), omega1)
    assert abs(k.vs[1]) < 1e-12 * k.ue[1]
    assert k.srr[1] == pytest.approx(0.0, abs=1e-12)
    assert k.vs[0] < 0 < k.vs[2]          # pinion root: gear faster; pinion tip: pinion faster
    # at the pitch point both surfaces roll with ω r_w sin α_wt
    assert k.v1[1] == pytest.approx(omega1 * p.rw1 * math.sin(p.alpha_wt), rel=1e-12)


def test_radii_of_curvature_and_contact_radii(baseline_pair):
    p = baseline_pair
    k = kinematics(p, path_positions(p, 11), 1.0)
    assert np.allclose(k.rho1 + k.rho2, p.line_of_action)
    assert np.allclose(k.R1, k.rho1 / math.cos(p.beta_b))
    assert np.allclose(1 / k.R, 1 / k.R1 + 1 / k.R2)
    assert k.r1[0] == pytest.approx(math.hypot(p.rb1, p.u_start))
    assert k.r1[-1] == pytest.approx(p.ra1, rel=1e-12)       # contact ends at the pinion tip
    assert k.r2[0] == pytest.approx(p.ra2, rel=1e-12)        # and starts at the gear tip


def test_mesh_frequency(baseline_pair):
    assert mesh_frequency(baseline_pair, 500) == pytest.approx(31 * 500 / 60)


def test_mean_contact_length_equals_eps_alpha_b_over_cos_beta_b(baseline_pair):
    p = baseline_pair
    phases = np.linspace(0, 1, 2000, endpoint=False)
    lengths = [contact_lines(p, ph).total_length for ph in phases]
    assert np.mean(lengths) == pytest.approx(p.mean_contact_length, rel=1e-3)


def test_contact_lines_are_periodic_in_the_base_pitch(baseline_pair):
    a = contact_lines(baseline_pair, 0.3)
    b = contact_lines(baseline_pair, 1.3)
    assert a.total_length == pytest.approx(b.total_length)
    assert a.count == b.count


def test_integer_overlap_gives_constant_contact_length(baseline_pair):
    # ε_β = 1 exactly: b = π m_n / sin β
    from dataclasses import replace

    p = replace(baseline_pair, b=math.pi * baseline_pair.m_n / math.sin(baseline_pair.beta))
    L = double_helical_contact(p, np.linspace(0, 1, 200, endpoint=False))["length_left"]
    assert np.ptp(L) < 1e-9 * L.mean()


def test_half_pitch_stagger_shifts_the_right_helix(baseline_pair):
    phases = np.linspace(0, 1, 400, endpoint=False)
    inphase = double_helical_contact(baseline_pair, phases, stagger=0.0)
    half = double_helical_contact(baseline_pair, phases, stagger=0.5)
    assert np.allclose(inphase["length_left"], inphase["length_right"])
    assert np.allclose(half["length_right"], np.roll(half["length_left"], -200))
    # staggering halves the total ripple for this pair (it cancels the fundamental)
    assert np.ptp(half["length_total"]) < np.ptp(inphase["length_total"])


def test_spur_limit_has_whole_face_lines():
    from femgear.physics.geometry import GearPair

    p = GearPair.from_parameters(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014,
                                 x1=0.1817, x2=0.1715)
    counts = {contact_lines(p, ph).count for ph in np.linspace(0, 1, 101)}
    assert counts == {1, 2}
