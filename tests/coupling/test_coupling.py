"""The bidirectional loop: excitation tables, convergence with history, failure with history."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.errors import ConvergenceError
from femgear.physics.geometry import path_positions
from femgear.scene import load_scene
from femgear.system.coupling import CouplingSetup, coupling_iterations, run_coupled
from femgear.system.coupling.profile import mesh_deviation, phase_table

FAST = ['physics.dynamics="lumped"', "numerics.dynamics_cycles=40", "numerics.transient_cycles=20"]


def test_uniform_wear_is_drive_only_and_expansion_is_both_flanks(baseline_pair):
    """Uniform wear w (h1 + h2) moves the drive tables by w and leaves the coast tables; a uniform
    expansion ζ (ζ_T1 + ζ_T2) closes both by ζ; no deviation gives no tables."""
    u = path_positions(baseline_pair, 81)
    d = mesh_deviation(baseline_pair, u, np.full(u.size, 3e-6), np.full(u.size, 1e-6), stagger=0.3, n_phase=64)
    assert np.allclose(d.drive, 2e-6, rtol=1e-12) and np.allclose(d.coast, -1e-6, rtol=1e-12)
    assert mesh_deviation(baseline_pair, u, np.zeros(u.size), np.zeros(u.size)) is None


def test_tables_are_the_contact_line_mean(baseline_pair):
    p = baseline_pair
    u = path_positions(p, 401)
    linear = 1e-6 * (u - p.u_pitch) / p.g_alpha
    table = phase_table(p, u, linear, 32)
    # the contact lines sweep the whole path in one period: the phase mean of the table
    # equals the mean of the deviation weighted by how often each position is loaded
    assert abs(table.mean() - np.average(linear)) < 0.1 * np.ptp(linear)
    assert np.ptp(table) > 0          # and it varies over the mesh period


def test_spur_tables_are_the_mean_over_the_pairs_in_contact(baseline_path):
    """Spur pair (zero line extent): at phase φ the pairs sit at u_A + (φ + k) p_bt; the table of
    h(u) is the mean of h over them (found by the zoo: a spur scene with a thermal level failed)."""

    p = pair_from_scene(load_scene(baseline_path, ['pair.kind="spur"', "pair.helix_angle_deg=0.0"]))
    u = path_positions(p, 201)
    h = 1e-6 * ((u - p.u_start) / p.g_alpha) ** 2
    n = 16
    table = phase_table(p, u, h, n)
    for i in range(n):
        at = p.u_start + (i / n + np.arange(-1, 4)) * p.p_bt
        at = at[(at >= p.u_start) & (at <= p.u_end)]
        assert table[i] == pytest.approx(np.mean(np.interp(at, u, h)), rel=1e-12)


@pytest.fixture(scope="module")
def setup(baseline_path):
    scene = load_scene(baseline_path, FAST + ['physics.thermal="analytic"', 'physics.wear="archard"',
                                              "wear.cycles=1e6", 'physics.coupling="bidirectional"'])
    return CouplingSetup.from_case(build_case(scene), n_phase=64)


def test_the_loop_converges_to_the_papers_tolerance_with_a_history(setup):
    result = run_coupled(setup, tol_force=1e-6, tol_mu=1e-6, max_iter=12)
    h = result.history
    assert result.converged and result.state.iteration <= 8
    assert h.mesh_force_change[-1] < 1e-6 and h.mu_change[-1] < 1e-6
    changes = h.mesh_force_change[1:]
    assert changes[-1] < changes[0] * 1e-3          # contraction, not a lucky stop
    st = result.state
    assert np.all(np.isfinite(st.mu)) and st.wear.max() > 1e-6 and st.thermal_deviation.max() > 0
    # the dynamic mesh force carries the static load on average
    assert st.mesh_force.mean() == pytest.approx(setup.static_force, rel=0.02)


def test_a_loop_that_cannot_converge_raises_with_its_history(setup):
    with pytest.raises(ConvergenceError) as info:
        run_coupled(setup, tol_force=1e-14, tol_mu=1e-14, max_iter=2)
    assert len(info.value.history["mesh_force_change"]) == 3
    assert "coupling" in str(info.value)


def test_one_way_is_the_first_pass_of_the_bidirectional_loop(setup):
    one = run_coupled(setup, one_way=True).state
    first = next(s for s in coupling_iterations(setup) if s.iteration == 1)
    assert np.array_equal(one.mesh_force, first.mesh_force)


def test_bad_relaxation_is_refused(setup):
    with pytest.raises(ValueError, match="relax"):
        next(coupling_iterations(setup, relax=0.0))


def test_bidirectional_without_dynamics_is_a_scene_error(baseline_path):
    from femgear.errors import SceneError

    with pytest.raises(SceneError, match="physics.coupling"):
        load_scene(baseline_path, ['physics.coupling="bidirectional"', 'physics.dynamics="none"'])


def test_excitation_table_is_exact_for_piecewise_linear_deviations(baseline_pair):
    """Exact integration over the contact lines: a linear deviation gives the same table on
    any grid (no steps at the grid spacing, which the dynamics would feel as excitation)."""
    p = baseline_pair
    linear = lambda u: 1e-6 * (u - p.u_pitch) / p.g_alpha  # noqa: E731
    coarse, fine = path_positions(p, 7), path_positions(p, 601)
    t_coarse = phase_table(p, coarse, linear(coarse), 512)
    t_fine = phase_table(p, fine, linear(fine), 512)
    assert np.max(np.abs(t_coarse - t_fine)) < 1e-12 * np.ptp(t_fine) + 1e-20
    assert np.ptp(t_coarse) > 0


def test_harmonic_fit_recovers_a_trigonometric_polynomial():
    """Identity: a table that is a trigonometric polynomial of degree ≤ m is fitted exactly."""
    from femgear.system.coupling.profile import harmonic_fit

    phi = np.arange(64) / 64
    e = 0.3 + np.cos(2 * np.pi * phi) + 0.2 * np.sin(2 * np.pi * 3 * phi)
    fit, amps = harmonic_fit(e, 5)
    assert np.allclose(fit, e) and np.allclose(amps[:4], [0.3, 1.0, 0.0, 0.2], atol=1e-12)
