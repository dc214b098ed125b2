"""Warm-started line paths (issue 16): a sequence of solves with ``start=`` and ``reuse=``
reproduces the cold solves and needs fewer Newton iterations."""

import numpy as np
import pytest

from femgear.ehl.line import solve_line


def _path(n=6, ds=0.025):
    s = ds * np.arange(n)
    return 20.0 * (1.0 + 0.5 * np.sin(np.pi * s)), 10.0 + 2.0 * s


def test_warm_path_reproduces_cold_solves_in_fewer_iterations():
    """Along a smooth (M, L) path at level 5 the warm path (secant predictor, coarse-grid
    correction, LU reuse) gives the cold Hc and Hmin to 1e-8 and the same error estimate,
    and each warm solve after the first takes fewer Newton iterations than its cold one."""
    Ms, Ls = _path()
    prev, reuse = None, {}
    for i, (M, L) in enumerate(zip(Ms, Ls)):
        warm = solve_line(M, L, level=5, start=prev, reuse=reuse)
        cold = solve_line(M, L, level=5)
        assert warm.Hc == pytest.approx(cold.Hc, rel=1e-8)
        assert warm.Hmin == pytest.approx(cold.Hmin, rel=1e-7)
        assert warm.error_estimate["Hc"] == pytest.approx(cold.error_estimate["Hc"], rel=0.05)
        if i:
            assert warm.iterations < cold.iterations, (i, warm.iterations, cold.iterations)
        prev = warm
    assert len(reuse[("line path", -4.5, 1.5)]) == 2


def test_secant_prediction_beats_the_previous_solution():
    """From the third position on, the predicted start is closer to the solution than the
    previous solution is (the predictor works, not only the Newton safeguards)."""
    from femgear.ehl.line import _PathHistory

    Ms, Ls = _path(4)
    prev, reuse = None, {}
    for M, L in zip(Ms[:3], Ls[:3]):
        prev = solve_line(M, L, level=5, start=prev, reuse=reuse)
    hist = _PathHistory.of(reuse, -4.5, 1.5)
    P_pred, H0_pred = hist.predict(prev, Ms[3], Ls[3], 5)
    exact = solve_line(Ms[3], Ls[3], level=5)
    assert abs(H0_pred - exact.H0) < 0.5 * abs(prev.H0 - exact.H0)
    assert np.abs(P_pred - exact.P).mean() < 0.5 * np.abs(prev.P - exact.P).mean()
