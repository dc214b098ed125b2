"""Warm-started point paths by full multigrid (issue 16): a sequence of solves with
``start=`` and ``reuse=`` (secant predictor, one or two V-cycles per grid) reproduces the
cold solves well within their error estimates, and the predictor does the work."""

import numpy as np
import pytest

from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.fd.point import FasPoint, _PointPath
from femgear.physics.ehl.point import solve_point


def _loads(n: int) -> np.ndarray:
    """The first positions of the benchmark path M = 20 (1 + 0.5 sin(pi s)), s step 1/40
    (its steepest part: M grows by ~4 % a position)."""
    return 20.0 * (1.0 + 0.5 * np.sin(np.pi * np.arange(n) / 40.0))


@pytest.fixture(scope="module")
def paths():
    Ms = _loads(5)
    prev, reuse, warm = None, {}, []
    for M in Ms:
        prev = solve_point(M, 10.0, level=3, method="fas", start=prev, reuse=reuse)
        warm.append(prev)
    cold = [solve_point(M, 10.0, level=3, method="fas") for M in Ms]
    return Ms, warm, cold, reuse


def test_warm_path_agrees_with_cold_solves(paths):
    """At every position the warm films equal the cold ones to 1e-3 relative (a tenth of
    their ~1 % error estimates; measured <= 4e-4 along the 41-position path), the warm
    results carry a (two-level) estimate that agrees with the cold one to 25 %, the load
    balance holds to 1e-4 and nothing is flagged."""
    _, warm, cold, _ = paths
    for w, c in zip(warm, cold):
        assert w.Hc == pytest.approx(c.Hc, rel=1e-3)
        assert w.Hmin == pytest.approx(c.Hmin, rel=1e-3)
        for key in ("Hc", "Hmin"):
            assert w.error_estimate[key] == pytest.approx(c.error_estimate[key], rel=0.25)
        assert w.load_error < 1e-4 and not w.flags
        assert [lv["nodes"] for lv in w.levels][-1] == 129**2


def test_warm_solves_take_one_or_two_cycles_per_grid(paths):
    """From the third position on (two entries in the history: the secant predictor) each
    warm solve takes at most two V-cycles on 129^2 and on 65^2, against five and four of
    the cold full multigrid."""
    _, warm, cold, _ = paths
    for w in warm[2:]:
        assert [lv["nodes"] for lv in w.levels] == [65**2, 129**2]
        assert max(lv["iterations"] for lv in w.levels) <= 2
    assert cold[-1].levels[-1]["iterations"] >= 4
    assert all(w.iterations < c.iterations / 2 for w, c in zip(warm[2:], cold[2:]))


def test_secant_prediction_beats_the_previous_solution(paths):
    """The predicted 129^2 state for the next position is closer to its solution than the
    previous solution is (the predictor works, not only the cycles)."""
    Ms, warm, _, reuse = paths
    M_next = float(_loads(6)[-1])
    fp = FasPoint(M_next, 10.0, ratio=1.0, dom=default_domain(1.0, None), rheology={}, rigid=False,
                  case="test")
    path = _PointPath.of(reuse, default_domain(1.0, None), 1.0)
    P_pred, H0_pred = path.predict(warm[-1], M_next, 10.0, 3, fp.nvm_hertz)
    exact = solve_point(M_next, 10.0, level=3, method="fas")
    assert abs(H0_pred - exact.H0) < 0.3 * abs(warm[-1].H0 - exact.H0)
    assert np.abs(P_pred - exact.P).mean() < 0.5 * np.abs(warm[-1].P - exact.P).mean()


def test_without_history_the_start_alone_still_warm_starts(paths):
    """A start that is not the last entry of the history (or no ``reuse``): the
    interpolated start and the final tolerances, the same answer."""
    Ms, warm, cold, _ = paths
    r = solve_point(Ms[3], 10.0, level=3, method="fas", start=warm[1], reuse={})
    assert r.Hc == pytest.approx(cold[3].Hc, rel=1e-3)
    assert r.Hmin == pytest.approx(cold[3].Hmin, rel=1e-3)
