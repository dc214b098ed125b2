"""Line-contact EHL against Moes (1992) and Dowson-Higginson (tier 3)."""

import numpy as np
import pytest

from femgear.physics.contact.film import dowson_higginson_minimum, moes_line_central
from femgear.physics.ehl.fe.line import solve_line

TWO_U = 1.0e-11  # Dowson-Higginson is not a function of (M, L) alone: fix U


def _dh_min_moes(M, L):
    U = TWO_U / 2
    W = M * TWO_U**0.5
    G = L * TWO_U**-0.25
    return dowson_higginson_minimum(U, G, W) * TWO_U**-0.5


@pytest.mark.parametrize("M, L", [(20.0, 10.0), (50.0, 10.0), (10.0, 5.0)])
def test_moes_line_formula(M, L):
    r = solve_line(M, L, level=6)
    assert r.Hc == pytest.approx(float(moes_line_central(M, L)), rel=0.04)
    assert r.load_error < 1e-6
    assert r.P.min() >= 0.0 and np.all(np.isfinite(r.H))
    # Dowson-Higginson minimum film: published accuracy ~10 % in its fit range
    assert r.Hmin == pytest.approx(float(_dh_min_moes(M, L)), rel=0.10)


def test_line_grid_convergence():
    r = solve_line(20.0, 10.0, level=7)
    hc = [lv["Hc"] for lv in r.levels]
    assert abs(hc[-1] / hc[-2] - 1) < 0.002


def test_line_dry_limit():
    """At high load the pressure approaches the Hertz half-ellipse sqrt(1 - X^2)."""
    r = solve_line(500.0, 10.0, level=6)
    inside = np.abs(r.x) < 0.8
    assert np.abs(r.P[inside] - np.sqrt(1 - r.x[inside] ** 2)).max() < 0.05
    assert r.Hc == pytest.approx(float(moes_line_central(500.0, 10.0)), rel=0.05)


def test_warm_start_gives_the_cold_answer_with_fewer_iterations():
    """A neighbouring solution (M, L) = (20, 10) warm-starts (22, 10.5): the same films
    (to the Newton tolerance) and estimate, in fewer Newton iterations; the LU factors
    kept in ``reuse`` serve as GMRES preconditioners."""
    first = solve_line(20.0, 10.0, level=5)
    cold = solve_line(22.0, 10.5, level=5)
    reuse = {}
    warm = solve_line(22.0, 10.5, level=5, start=first, reuse=reuse)
    assert warm.Hc == pytest.approx(cold.Hc, rel=1e-7)
    assert warm.Hmin == pytest.approx(cold.Hmin, rel=1e-6)
    assert warm.iterations < cold.iterations
    assert warm.error_estimate["Hc"] == pytest.approx(cold.error_estimate["Hc"], rel=0.05)
    assert any(k[0] == "dense" for k in reuse)
    with pytest.raises(ValueError):
        solve_line(22.0, 10.5, level=5, start=solve_point_result())


def solve_point_result():
    from femgear.physics.ehl.point import solve_point

    return solve_point(20.0, 10.0, level=0, coarse_level=0)
