"""Craig–Bampton: the 4-DOF chain of the literature exactly, statics exact, and the FE housing's frequencies to 1 %."""

import numpy as np
import pytest
import scipy.sparse as sp

from femgear.physics.housing.reduction import craig_bampton, lowest_frequencies, natural_frequencies


def chain():
    """K = tridiag(−1, 2, −1) with K₄₄ = 1, M = diag(2, 2, 2, 1) (the JuliaFEM ModelReduction.jl example)."""
    K = 2 * np.eye(4) - np.eye(4, k=1) - np.eye(4, k=-1)
    K[3, 3] = 1.0
    return K, np.diag([2.0, 2.0, 2.0, 1.0])


@pytest.mark.parametrize("sparse", [False, True])
def test_four_dof_chain_reproduces_the_published_matrices(sparse):
    """Boundary DOF 4, one fixed-interface mode: M_red = [[2.75, −1.20711], [−1.20711, 1]], K_red = [[0.25, 0],
    [0, 0.292893]] (JuliaFEM ModelReduction.jl; the mode's sign is arbitrary, so the coupling term is compared
    in magnitude).  Exact: 0.25 = 1 − 3/4, 0.292893 = 1 − 1/√2, 2.75 = 1 + 2·14/16, 1.20711 = (1 + √2)/2."""
    K, M = chain()
    r = craig_bampton(sp.csr_matrix(K) if sparse else K, sp.csr_matrix(M) if sparse else M, [3], 1)
    assert np.allclose(r.K, [[0.25, 0.0], [0.0, 1 - 1 / np.sqrt(2)]], atol=1e-12)
    assert np.isclose(r.M[0, 0], 2.75, atol=1e-12) and np.isclose(r.M[1, 1], 1.0, atol=1e-12)
    assert np.isclose(abs(r.M[0, 1]), (1 + np.sqrt(2)) / 2, atol=1e-12) and np.isclose(r.M[0, 1], r.M[1, 0])
    assert np.round(r.K[1, 1], 6) == 0.292893 and np.round(abs(r.M[0, 1]), 5) == 1.20711


def test_all_modes_kept_is_exact_and_statics_always_exact():
    """With every fixed-interface mode the reduction is a change of basis (same frequencies); with none, K_red is
    the exact static condensation (the boundary compliance of the full structure)."""
    rng = np.random.default_rng(1)
    A = rng.normal(size=(8, 8))
    K = A @ A.T + 8 * np.eye(8)
    M = np.diag(rng.uniform(1, 2, 8))
    b = [1, 5]
    full = craig_bampton(K, M, b, 6)
    assert np.allclose(full.frequencies(), natural_frequencies(K, M), rtol=1e-10)
    static = craig_bampton(K, M, b, 0)
    assert np.allclose(np.linalg.inv(static.K), np.linalg.inv(K)[np.ix_(b, b)], rtol=1e-10)


def test_refuses_more_modes_than_the_interior_holds():
    K, M = chain()
    with pytest.raises(ValueError, match="fixed-interface modes"):
        craig_bampton(K, M, [3], 4)


def test_fe_housing_frequencies_within_one_percent_in_the_retained_band(structure, reduced):
    """The Craig–Bampton housing's natural frequencies (seats free, feet clamped) against the unreduced FE housing's,
    in the retained band (0.4 × the highest retained fixed-interface frequency): within 1 %."""
    from femgear.levels.housing import RETAINED_BAND, reduction_check

    band = RETAINED_BAND * reduced.fixed_interface_hz.max()
    f_red = reduced.frequencies()
    f_red = f_red[f_red <= band]
    f_full = lowest_frequencies(structure.K, structure.M, f_red.size)
    assert f_red.size >= 4
    err = np.abs(f_red - f_full) / f_full
    assert err.max() < 0.01, err
    assert np.all(f_red >= f_full * (1 - 1e-9))            # a reduction is a constraint: never below the full model
    check = reduction_check(reduced, structure)             # the run's own check says the same
    assert check.full.size == f_red.size and np.isclose(check.max_error, err.max())
