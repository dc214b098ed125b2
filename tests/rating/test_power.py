"""Mesh power loss: Ohlendorf's tooth loss factor (analytic limit) and the input checks."""

import math

import numpy as np
import pytest

from femgear.physics.contact.path import zone_grid
from femgear.physics.contact.sharing import load_sharing
from femgear.physics.geometry import kinematics
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating import mesh_power_loss, ohlendorf_loss_factor


def _pair(**kw):
    base = dict(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014, x1=0.1817, x2=0.1715,
                kind="spur")
    base.update(kw)
    return GearPair.from_parameters(**base)


@pytest.mark.parametrize("n", [41, 401])
def test_spur_constant_mu_is_ohlendorf(n):
    """Spur, constant μ, ideal load sharing: P_V = μ P_in H_V (Ohlendorf; ISO/TR 14179-2) on the zone grid."""
    p = _pair()
    T1, omega1, mu = 200.0, 2175 * 2 * math.pi / 60, 0.05
    u = zone_grid(p, n)
    kin = kinematics(p, u, omega1)
    w = load_sharing(p, u, T1 / p.rb1).line_load
    loss = mesh_power_loss(p, u, np.full(u.size, mu), w, kin.vs, T1, omega1)
    expected = mu * T1 * omega1 * ohlendorf_loss_factor(p)
    assert loss.mean_loss == pytest.approx(expected, rel=1e-6)   # piecewise linear integrand: trapezoid exact up to the 1e-7 p_bt jump width
    assert loss.equivalent_mu == pytest.approx(mu, rel=1e-6)
    assert 0.99 < loss.efficiency < 1
    assert loss.energy_per_mesh_cycle == pytest.approx(loss.mean_loss / (16 * 2175 / 60))


def test_ohlendorf_fzg_c_value():
    """FZG C: H_V = π(u+1)/(z1 u)(1 − ε_α + ε1² + ε2²) from the addendum contact ratios, by hand
    from the GEARpie radii (r_a 41.228/59.182 mm, r_b 33.829/50.743 mm, a_w sin α_wt)."""
    p = _pair()
    e1 = (p.u_end - p.u_pitch) / p.p_bt
    e2 = (p.u_pitch - p.u_start) / p.p_bt
    assert e1 + e2 == pytest.approx(p.eps_alpha)
    assert ohlendorf_loss_factor(p) == pytest.approx(math.pi * 2.5 / 24 * (1 - p.eps_alpha + e1**2 + e2**2))
    rb1, rb2, ra1, ra2 = 33.8289e-3, 50.7434e-3, 41.228e-3, 59.182e-3
    T1T2 = 91.5e-3 * math.sin(math.acos((rb1 + rb2) / 91.5e-3))
    T1A, T1E = T1T2 - math.sqrt(ra2**2 - rb2**2), math.sqrt(ra1**2 - rb1**2)
    pb, T1C = math.pi * 4.5e-3 * math.cos(math.radians(20)), rb1 * T1T2 / (rb1 + rb2)
    hand = math.pi * 2.5 / 24 * (1 - (T1E - T1A) / pb + ((T1E - T1C) / pb) ** 2 + ((T1C - T1A) / pb) ** 2)
    assert ohlendorf_loss_factor(p) == pytest.approx(hand, rel=1e-3)


def test_helical_double_counts_helices():
    """A double-helical pair has twice the loss density of one helix under the same per-helix load."""
    kw = dict(beta=math.radians(20), b=0.02)
    single, double = _pair(kind="single-helical", **kw), _pair(kind="double-helical", **kw)
    u = np.linspace(single.u_start, single.u_end, 11)
    ones = np.ones(u.size)
    a = mesh_power_loss(single, u, ones, ones, ones, 1.0, 1.0)
    b = mesh_power_loss(double, u, ones, ones, ones, 1.0, 1.0)
    assert b.mean_loss == pytest.approx(2 * a.mean_loss)


def test_bad_input():
    p = _pair()
    with pytest.raises(ValueError, match="1-D"):
        mesh_power_loss(p, np.zeros(3), np.zeros(2), np.zeros(3), np.zeros(3), 1.0, 1.0)
    with pytest.raises(ValueError, match="non-decreasing"):
        mesh_power_loss(p, np.array([1.0, 0.0]), np.zeros(2), np.zeros(2), np.zeros(2), 1.0, 1.0)
