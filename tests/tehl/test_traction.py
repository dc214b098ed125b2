"""Traction μ(SRR) of the TEHL line contact and the extremes (converge or fail clearly)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from femgear.errors import ConvergenceError
from femgear.physics.tehl import solve_tehl_line

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)


def _solve(srr, level=4, T=case.T0, **kw):
    return solve_tehl_line(case.W, case.R, case.UE, srr, T, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                           level=level, **kw)


def test_traction_curve_linear_then_saturating():
    mu = {s: _solve(s).mu for s in (0.0005, 0.001, 0.05, 0.3, 1.0)}
    assert mu[0.001] / mu[0.0005] == pytest.approx(2.0, rel=0.05)      # linear (Newtonian) start
    assert mu[1.0] / mu[0.3] < 1.25                                    # saturated (Eyring, thermal)
    assert mu[0.3] > mu[0.05]
    for s in (0.05, 0.3, 1.0):
        assert 0.01 <= mu[s] <= 0.1                                     # the paper's oil


def test_newtonian_traction_exceeds_eyring_and_parts_are_separate():
    e, n = _solve(0.3), _solve(0.3, model="newtonian")
    assert n.mu > e.mu
    assert 0 < e.mu_poiseuille < 0.1 * e.mu                            # rolling part, reported apart
    assert e.mu == abs(e.mu_couette)


def test_zero_and_reversing_sliding():
    zero = _solve(0.0)
    assert zero.mu == 0.0 and zero.mu_poiseuille > 0 and np.isfinite(zero.dT_max)
    fwd, rev = _solve(0.3), _solve(-0.3)
    assert np.sign(fwd.mu_couette) == -np.sign(rev.mu_couette)
    assert rev.mu == pytest.approx(fwd.mu, rel=0.05)


def test_very_high_srr_and_a_surface_at_rest_converge():
    """SRR 1.9 and 2 (pure sliding, surface 2 at rest: its steady temperature is bounded by the rest
    regularisation of femgear.physics.tehl.energy.surface_matrix) converge and heat more than SRR 1; without the
    solids' conductivity (Jaeger's high-Péclet operator only) a surface at rest still fails clearly."""
    from dataclasses import replace

    r, one = _solve(1.9), _solve(1.0)
    assert np.isfinite(r.mu) and r.dT_max > one.dT_max
    rest = _solve(2.0)
    assert np.isfinite(rest.mu) and rest.dT_max > one.dT_max and abs(rest.heat["balance_error"]) < 0.01
    with pytest.raises(ConvergenceError, match="at rest"):
        solve_tehl_line(case.W, case.R, case.UE, 2.0, case.T0, case.OIL, case.E_RED, replace(case.PROPS, k2=None),
                        tau0=case.TAU0, level=4)


@pytest.mark.parametrize("T", [263.0, 283.0, 373.0])
def test_cold_and_hot_oil(T):
    """263 K (η_b ≈ 1.2 Pa s) failed with plain relaxation; Anderson: 14 iterations, ΔT 64 K, μ 0.035."""
    r = _solve(0.3, T=T)
    assert np.isfinite(r.mu) and 0.005 < r.mu < 0.1 and abs(r.heat["balance_error"]) < 0.01


def test_runaway_fails_with_convergence_error_not_nan():
    with pytest.raises(ConvergenceError):
        solve_tehl_line(case.W, case.R, 10.0, 1.0, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=4, max_rise=50.0)
