"""A Newton solve that fails says why (issue 16): when its steps are damped by the |dP|
cap, the error names the median damping and the node of the largest Newton component,
and the history carries ``max_dp`` / ``max_dp_at`` per iteration."""

import numpy as np
import pytest

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.core.grid import Grid, prolongation
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.newton import _stall_reason, newton_dense, newton_krylov
from femgear.physics.ehl.point import solve_point


def test_stall_reason_reports_damped_steps_and_their_node():
    h = History(step=[0.01, 0.02, 0.03], max_dp=[3.0, 25.0, 4.0],
                max_dp_at=[[0.1, 0.0], [0.61, 0.23], [0.2, 0.0]])
    msg = _stall_reason(h, 0.2)
    assert "median of 0.02" in msg and "25" in msg and "(0.610, 0.230)" in msg
    # full steps (e.g. an iteration cap reached while converging) are not called a stall
    assert _stall_reason(History(step=[1.0, 1.0, 0.5], max_dp=[1.0] * 3,
                                 max_dp_at=[[0.0, 0.0]] * 3), 0.2) == ""
    assert _stall_reason(History(), 0.2) == ""


def test_history_records_the_largest_newton_component():
    r = solve_point(20.0, 10.0, level=1, method="newton")
    h = r.history
    assert len(h["max_dp"]) == len(h["residual"]) == len(h["max_dp_at"])
    assert all(np.isfinite(h["max_dp"])) and all(len(xy) == 2 for xy in h["max_dp_at"])


def _levels(M, L, top):
    dom = default_domain()
    return [Level(Rheology(pr.point_alpha_bar(M, L)), pr.point_lam_bar(M), pr.POINT_LOAD,
                  grid=Grid.build(dom, k), sd_factor=1.0) for k in range(1, top + 1)]


@pytest.mark.slow
def test_strong_piezoviscosity_failure_points_at_the_outlet_spike():
    """(20, 20) (alpha_bar 19.8) on 129^2 from the prolonged 65^2 solution with the plain
    artificial diffusion: the Newton steps are damped to a few per cent by the |dP| cap
    and the largest Newton component sits at the outlet pressure spike (X ~ 0.3-0.8
    downstream of the centre, near the axis), which is why the nested solver needs its
    stabilisation continuation there (and fails on 257^2; docs/ehl_multigrid.md)."""
    lvs = _levels(20.0, 20.0, 3)
    coarse = solve_point(20.0, 20.0, level=2, method="newton")
    P0 = (prolongation(lvs[1].grid, lvs[2].grid) @ coarse.P.ravel())[lvs[2].interior]
    with pytest.raises(ConvergenceError) as info:
        newton_krylov(lvs, P0, coarse.H0, max_iter=8, tol=1e-5, residual_tol=1e-8)
    msg, h = str(info.value), info.value.history
    assert "steps damped to a median of" in msg and "(X, Y) = (" in msg
    assert np.median(h["step"]) < 0.25 and max(h["max_dp"]) > 5.0
    x, y = h["max_dp_at"][int(np.argmax(h["max_dp"]))]
    assert 0.3 < x < 0.8 and abs(y) < 0.6
    assert all(np.isfinite(h["residual"]))


def test_dense_newton_history_has_the_direction_fields():
    lv = _levels(20.0, 10.0, 1)[0]
    r = solve_point(20.0, 10.0, level=1, method="newton")
    PI = r.P.ravel()[lv.interior]
    _, _, h = newton_dense(lv, PI, r.H0, tol=1e-6)
    assert len(h.max_dp) == len(h.residual) >= 1
