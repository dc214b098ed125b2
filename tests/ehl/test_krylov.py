"""Right-preconditioned GMRES (femgear.physics.ehl.fe.krylov): its stopping test is the true residual."""

import numpy as np
import scipy.linalg as sla

from femgear.physics.ehl.fe.krylov import gmres_right


def _system(n=60, seed=1):
    rng = np.random.default_rng(seed)
    A = np.eye(n) * 4.0 + rng.normal(size=(n, n)) / np.sqrt(n)
    A[-1] *= 1e-3  # a badly scaled row (as the load row of the EHL Jacobian)
    return A, rng.normal(size=n)


def test_converged_answer_meets_the_true_residual_tolerance():
    A, b = _system()
    stale = A + 0.05 * np.random.default_rng(2).normal(size=A.shape) / np.sqrt(A.shape[0])
    stale[-1] = A[-1]
    lu = sla.lu_factor(stale)
    x, its, ok = gmres_right(lambda v: A @ v, lambda r: sla.lu_solve(lu, r), b, 1e-10, 30)
    assert ok and its < 15
    assert np.linalg.norm(b - A @ x) <= 1e-10 * np.linalg.norm(b) * 1.01
    np.testing.assert_allclose(x, np.linalg.solve(A, b), rtol=1e-8, atol=1e-10)


def test_exact_preconditioner_takes_one_iteration_and_too_few_iterations_fail():
    A, b = _system()
    lu = sla.lu_factor(A)
    x, its, ok = gmres_right(lambda v: A @ v, lambda r: sla.lu_solve(lu, r), b, 1e-12, 5)
    assert ok and its == 1
    x, its, ok = gmres_right(lambda v: A @ v, lambda r: r, b, 1e-12, 3)  # no preconditioner
    assert not ok and its == 3 and np.all(np.isfinite(x))
    assert np.linalg.norm(b - A @ x) < np.linalg.norm(b)  # the best of the Krylov space
    assert gmres_right(lambda v: A @ v, lambda r: r, np.zeros(b.size), 1e-8, 3)[2]
