"""The O(n log^2 n) path of the FD line EHL (``femgear.physics.ehl.fd.line_hodlr`` and ``line_fast``): its kernel
entries, its HODLR deflection and Jacobian factorisation against the dense ones, and its converged films against
the dense path's (issue 43 item 1).  Its speed is measured by ``studies/benchmarks/line_scaling.py``, not here."""

from __future__ import annotations

import numpy as np
import pytest

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.elastic import line_hat_kernel
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fd import line as fdl
from femgear.physics.ehl.fd.line_fast import JacobianSolver
from femgear.physics.ehl.fd.line_grid import expected_film, hertz_start, line_domain
from femgear.physics.ehl.fd.line_hodlr import HKernel, hat_kernel
from femgear.physics.ehl.fd.line_operator import FDLine


def _grid(level: int, M: float = 1000.0, L: float = 4.3) -> np.ndarray:
    return line_domain(expected_film(M, L)).nodes(level)


def test_kernel_entries_equal_the_closed_form_and_a_fine_quadrature():
    """hat_kernel: on a uniform grid of 65 nodes (where the closed form loses little) it equals line_hat_kernel
    to 1e-12 of max|K| (the round-off of the closed form); on the 16385-node graded grid its far entries equal a 64-point Gauss-Legendre
    integration of each half hat to 1e-15 of max|K| (the closed form is off there by up to ~1e-10)."""
    X = np.linspace(-4.5, 1.5, 65)
    cols = np.arange(1, X.size - 1)
    K = hat_kernel(X, np.arange(X.size), cols)
    assert np.max(np.abs(K - line_hat_kernel(X, cols=cols))) < 1e-12 * np.max(np.abs(K))
    X = _grid(10)
    rows, cols = np.array([0, 3, 8000, 16384]), np.arange(100, 16000, 397)
    t, w = np.polynomial.legendre.leggauss(64)
    t, w = 0.5 * (t + 1.0), 0.5 * w
    ref = np.zeros((rows.size, cols.size))
    for side in (-1, 1):
        a, b = (X[cols - 1], X[cols]) if side < 0 else (X[cols], X[cols + 1])
        s = a[None, :, None] + (b - a)[None, :, None] * t
        shape = t if side < 0 else 1.0 - t
        ref += (b - a) * (np.log(np.abs(X[rows][:, None, None] - s)) @ (shape * w))
    ref *= -1.0 / np.pi
    K = hat_kernel(X, rows, cols)
    assert np.max(np.abs(K - ref)) < 1e-15 * max(np.max(np.abs(line_hat_kernel(X, rows=rows[:1], cols=cols))), 1e-3)


def test_hodlr_deflection_equals_the_dense_kernel():
    """HKernel @ v (all nodes, interior pressures) against the dense matrix of hat_kernel on a 2049-node graded
    grid: 1e-11 of the deflection's maximum; its rows exact; every off-diagonal block compressed (rank <= 40)."""
    X = _grid(7)
    H = HKernel(X)
    cols = np.arange(1, X.size - 1)
    Kd = hat_kernel(X, np.arange(X.size), cols)
    rng = np.random.default_rng(1)
    v = hertz_start(X)[1:-1] + 0.1 * rng.random(X.size - 2)
    y = H @ v
    assert np.max(np.abs(y - Kd @ v)) < 1e-11 * np.max(np.abs(Kd @ v))
    assert np.array_equal(H.row(700), Kd[700])
    assert max(H.ranks) <= 40 and len(H.ranks) == 2 * (2**4 - 1)


def test_hodlr_factorisation_solves_the_bordered_jacobian():
    """JacobianSolver (the HODLR factorisation of T + B K bordered by the H0 column and the load row) against
    LAPACK on the dense Jacobian at a perturbed Hertz state with cavitated rows (Roelands, Dowson-Higginson,
    1025 nodes): the same Newton direction to 1e-8."""
    M, L = 200.0, 8.0
    X = _grid(6, M, L)
    lv = FDLine(X, Rheology(pr.line_alpha_bar(M, L), viscosity="roelands", ph=1e9, compressible=True),
                pr.line_lam_bar(M), pr.LINE_LOAD, kernel=HKernel(X))
    rng = np.random.default_rng(0)
    PI = hertz_start(X)[1:-1] * (1.0 + 0.05 * rng.random(X.size - 2))
    F, state, _, s, act = lv.evaluate(PI, -0.2)
    assert act.any() and not act.all()
    jac = lv.jacobian(state, s, act)
    dense = FDLine(X, lv.rheology, lv.lam_bar, lv.load, kernel=hat_kernel(X, np.arange(X.size), lv.interior))
    x_ref = np.linalg.solve(dense.dense(jac), -F)
    x = JacobianSolver(lv.K, jac, lv.dual).solve(-F)
    assert np.max(np.abs(x - x_ref)) < 1e-8 * np.max(np.abs(x_ref))
    v = rng.random(F.size)
    assert np.allclose(lv.matvec(jac, v), dense.dense(jac) @ v, rtol=0, atol=1e-10 * np.max(np.abs(dense.dense(jac) @ v)))


@pytest.mark.parametrize("M, L, kw", [
    (1000.0, 4.3, {}),
    (23.0, 13.9, {"viscosity": "roelands", "compressible": True, "ph": 0.6e9}),
    (1.0, 1.0, {}),
    (300.0, 4.0, {"viscosity": "roelands", "ph": 1.2e9}),
])
def test_fast_and_dense_paths_give_the_same_films(M, L, kw):
    """Issue 43 item 1: wherever the dense path converges, the HODLR path gives the same Hc and Hmin on every
    level of the nested solve, to 1e-9 relative (Newton's step tolerance is 1e-8; measured 1e-11 at (1000, 4.3))."""
    dense = fdl.solve_line_fd(M, L, level=6, tol=None, fast=False, **kw)
    fast = fdl.solve_line_fd(M, L, level=6, tol=None, fast=True, **kw)
    for a, b in zip(dense.levels, fast.levels, strict=True):
        assert b["Hc"] == pytest.approx(a["Hc"], rel=1e-9) and b["Hmin"] == pytest.approx(a["Hmin"], rel=1e-9)
    assert np.all(np.isfinite(fast.P)) and fast.error_estimate == pytest.approx(dense.error_estimate, rel=1e-6)


def test_the_solver_picks_dense_or_hodlr_by_size_and_the_default_is_unchanged():
    """Dense up to DENSE_NODES, HODLR above; the default solve at (1000, 4.3) ends where the dense path ends, with
    the same films and estimate."""
    dom = line_domain(expected_film(1000.0, 4.3))
    assert isinstance(fdl._kernel(dom, 5), np.ndarray) and 16 * 2**5 + 1 <= fdl.DENSE_NODES
    assert isinstance(fdl._kernel(dom, 6), HKernel)
    auto, dense = fdl.solve_line_fd(1000.0, 4.3), fdl.solve_line_fd(1000.0, 4.3, fast=False)
    assert auto.nodes == dense.nodes and auto.Hc == pytest.approx(dense.Hc, rel=1e-9)
    assert auto.error_estimate == pytest.approx(dense.error_estimate, rel=1e-6) and not auto.flags


def test_fast_path_failure_raises_with_history():
    """A Newton that cannot converge on the HODLR path raises ConvergenceError carrying its residual history."""
    with pytest.raises(ConvergenceError) as err:
        fdl.solve_line_fd(1000.0, 4.3, level=6, tol=None, fast=True, max_iter=1)
    assert err.value.history["residual"] and all(np.isfinite(err.value.history["residual"]))
