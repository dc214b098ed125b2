"""Load sharing over the contact lines for any overlap ratio (issue 25): spur to ε_β = 4.

The force balance is checked against an integral written independently of
:mod:`femgear.physics.geometry.lines`: each contact line of :func:`femgear.physics.geometry.contact_lines`
integrates the linear interpolant of the grid loads exactly (trapezoid on the grid nodes
inside the line plus its two ends), dl = du / sin β_b, summed over all lines of the helix.
With several lines covering one u (ε_β > 1) every line carries its own load; the old
boolean coverage counted each u once and made the loads ε_β times too high.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from femgear.physics.contact.sharing import load_sharing, spur_sharing
from femgear.physics.geometry import GearPair, contact_lines, path_positions
from femgear.physics.geometry.lines import line_weights
from femgear.physics.wear.load_sharing import distribute, load_map

EPS_BETA = [0.0, 0.5, 0.93, 1.0, 1.5, 2.65, 4.0]
FORCE = 2.0e4   # N, one helix


def _pair(eps_beta: float, z1: int = 31, z2: int = 34) -> GearPair:
    beta = 0.0 if eps_beta == 0 else math.radians(30.0)
    m_n = 3e-3
    b = 17.5e-3 if eps_beta == 0 else eps_beta * math.pi * m_n / math.sin(beta)
    kind = "spur" if eps_beta == 0 else "double-helical"
    return GearPair.from_parameters(z1=z1, z2=z2, m_n=m_n, alpha_n=math.radians(20.0), beta=beta, b=b,
                                    x1=0.0, x2=0.0, kind=kind)


def _line_integral(u: np.ndarray, w: np.ndarray, lo: float, hi: float) -> float:
    """∫_lo^hi of the linear interpolant of w on u, exactly (the interpolant is linear between the nodes)."""
    x = np.concatenate([[lo], u[(u > lo) & (u < hi)], [hi]])
    return float(np.trapezoid(np.interp(x, u, w), x))


def _carried(pair: GearPair, u: np.ndarray, w: np.ndarray, phase: float) -> float:
    lines = contact_lines(pair, phase)
    return sum(_line_integral(u, w, lo, hi) for lo, hi in zip(lines.u_lo, lines.u_hi)) / math.sin(pair.beta_b)


@pytest.mark.parametrize("eps_beta", [e for e in EPS_BETA if e > 0])
def test_every_line_carries_its_load_and_the_lines_carry_the_helix_force(eps_beta):
    """Σ_lines ∫ w' dl = F at every phase to 1e-9, with a local stiffness that varies along the path and a
    flank deviation (a wear bump) that unloads part of the lines."""
    pair = _pair(eps_beta)
    assert pair.eps_beta == pytest.approx(eps_beta)
    u = path_positions(pair, 61)
    phases = np.arange(32) / 32
    c_l = 1e10 * (1.0 - 0.25 * ((u - pair.u_pitch) / pair.g_alpha * 2) ** 2)
    bump = 2e-6 * np.exp(-(((u - pair.u_pitch) / (0.15 * pair.g_alpha)) ** 2))
    for deviation in (np.zeros(u.size), bump):
        w = distribute(np.full(phases.size, FORCE), line_weights(pair, u, phases), deviation, c_l,
                       math.sin(pair.beta_b))
        assert np.all(np.isfinite(w)) and np.all(w >= 0)
        errors = [abs(_carried(pair, u, w[i], ph) - FORCE) / FORCE for i, ph in enumerate(phases)]
        assert max(errors) < 1e-9


def test_the_spur_limit_balances_the_pairs_in_contact():
    """ε_β = 0: the pairs at u + j p_bt inside the path carry F/b between them, at every position."""
    pair = _pair(0.0)
    u = path_positions(pair, 101)
    share = spur_sharing(pair, u, FORCE)
    for ui in u[1:-1]:
        partners = ui + np.arange(-3, 4) * pair.p_bt
        partners = partners[(partners > pair.u_start) & (partners < pair.u_end)]
        total = sum(spur_sharing(pair, np.array([x]), FORCE).line_load[0] for x in partners) * pair.b
        assert total == pytest.approx(FORCE, rel=1e-9)
    assert np.all(share.line_load > 0)


@pytest.mark.parametrize("eps_beta", EPS_BETA)
def test_the_coupled_load_map_equals_the_static_sharing_for_any_overlap(eps_beta):
    """The coupling's load map (Winkler layer, uniform stiffness, no deviation) and the static contact-line
    sharing of :mod:`femgear.physics.contact.sharing` are two discretisations of the same ISO 6336 load w' = F/L(φ):
    their phase-mean load at the pitch point agrees within 2 % for every overlap (it was ε_β times too high
    for ε_β > 1), and never exceeds the force over the shortest contact length."""
    pair = _pair(eps_beta)
    u = path_positions(pair, 121)
    static = load_sharing(pair, u, FORCE).line_load
    coupled = load_map(pair, u, FORCE, np.zeros(u.size), 1e10, n_phase=64).mean_load
    i = int(np.argmin(np.abs(u - pair.u_pitch)))
    assert coupled[i] == pytest.approx(static[i], rel=0.02)
    if eps_beta > 0:
        shortest = min(contact_lines(pair, ph).total_length for ph in np.arange(64) / 64)
        assert coupled.max() <= FORCE / shortest * (1 + 1e-9)
