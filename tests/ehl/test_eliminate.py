"""Nonlinear elimination of the outlet spike (femgear.physics.ehl.fd.eliminate; Cai & Li 2011): the
local Jacobian against finite differences, and the local Newton solve restoring a
perturbed solution on its set while leaving every other node alone."""

import numpy as np
import pytest

from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.fd.eliminate import SpikeElimination
from femgear.physics.ehl.fd.point import FasPoint
from femgear.physics.ehl.point import solve_point


@pytest.fixture(scope="module")
def solved65():
    """(20, 10) on 65^2 by the multigrid (~1 s) and its FD level."""
    r = solve_point(20.0, 10.0, level=2, method="fas")
    fp = FasPoint(20.0, 10.0, ratio=1.0, dom=default_domain(1.0), rigid=False, case="t",
                  rheology=dict(viscosity="barus", ph=None, z=0.68, compressible=False))
    lv = fp.level(2 - fp.coarsest)
    assert lv.nx == r.P.shape[1]
    return lv, r.P.copy(), r.H0


def _outlet_box(lv, P):
    """Interior nodes of the outlet region 0.3 < X < 0.9, |Y| < 0.5 (the spike and the
    cavitation boundary behind it)."""
    X, Y = lv.X[1:-1, 1:-1], lv.Y[1:-1, 1:-1]
    return (X > 0.3) & (X < 0.9) & (np.abs(Y) < 0.5)


def test_local_jacobian_matches_finite_differences(solved65):
    lv, P, H0 = solved65
    mask = _outlet_box(lv, P)
    el = SpikeElimination(lv, mask)
    H = lv.film(P, H0)
    J = el.jacobian(P, H)
    f = np.zeros((lv.ny - 2, lv.nx - 2))
    L0 = f - lv.residual(P, H0, f)[0]
    for q in (0, el.rows.size // 3, el.rows.size - 1):
        e = 1e-7
        Pt = P.copy()
        Pt[el.jj[q] + 1, el.ii[q] + 1] += e
        fd = ((f - lv.residual(Pt, H0, f)[0]) - L0)[el.jj, el.ii] / e
        assert np.abs(fd - J[:, q]).max() < 1e-4 * max(np.abs(J[:, q]).max(), 1.0)


def test_elimination_restores_the_local_solution(solved65):
    """Perturb the converged pressure by 20 % on the set: the local Newton solve brings
    the set back to the solution (|F_S| < 1e-9), nodes outside the set untouched."""
    lv, P0, H0 = solved65
    mask = _outlet_box(lv, P0)
    f = np.zeros((lv.ny - 2, lv.nx - 2))
    P = P0.copy()
    inner = P[1:-1, 1:-1]
    inner[mask] *= 1.2
    el = SpikeElimination(lv, mask)
    hist = el.solve(P, H0, f)
    assert hist[0] > 1e-2 and hist[-1] < 1e-9 and len(hist) <= 16  # chord steps: linear rate
    outside = np.ones(P.shape, bool)
    outside[1:-1, 1:-1] = ~mask
    assert np.array_equal(P[outside], P0[outside])
    # the multigrid's own solution is the local problem's: its residual on the set is
    # the multigrid's algebraic error, so the restored pressure is close to it
    assert np.abs(P - P0).max() < 2e-3 * P0.max()


def test_empty_set_is_a_no_op(solved65):
    lv, P0, H0 = solved65
    P = P0.copy()
    el = SpikeElimination(lv, np.zeros((lv.ny - 2, lv.nx - 2), bool))
    assert el.solve(P, H0, np.zeros((lv.ny - 2, lv.nx - 2))) == [0.0]
    assert np.array_equal(P, P0)
