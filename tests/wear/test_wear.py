"""Archard wear: identities, linearity, step independence, resume."""

import math
from dataclasses import replace

import numpy as np
import pytest

from femgear.physics.geometry import kinematics, path_positions
from femgear.physics.wear import WearSetup, WearState, load_map, run_wear, wear_rates, wear_steps


@pytest.fixture(scope="module")
def setup(baseline_scene, baseline_pair):
    p = baseline_pair
    u = np.unique(np.append(path_positions(p, 61), p.u_pitch))
    kin = kinematics(p, u, 500 * 2 * math.pi / 60)
    return WearSetup.from_scene(baseline_scene, kin, p, n_phase=48)


def test_unworn_load_sharing_is_uniform_and_in_equilibrium(setup):
    p = setup.pair
    lm = load_map(p, setup.kin.u, setup.force, np.zeros(setup.kin.u.size), setup.c_l, 48)
    inner = lm.loaded_fraction > 0.2
    # uniform ISO distribution: w' = F / L(φ), whose passage mean is near F / L̄
    assert np.ptp(lm.mean_load[inner]) < 0.03 * lm.mean_load[inner].mean()
    assert lm.mean_load[inner].mean() == pytest.approx(setup.force / p.mean_contact_length, rel=0.03)


def test_worn_region_carries_less_load(setup):
    u = setup.kin.u
    bump = 1e-6 * np.exp(-(((u - u.mean()) / (0.1 * np.ptp(u))) ** 2))
    lm0 = load_map(setup.pair, u, setup.force, np.zeros(u.size), setup.c_l, 48)
    lm1 = load_map(setup.pair, u, setup.force, bump, setup.c_l, 48)
    mid = np.argmin(abs(u - u.mean()))
    assert lm1.mean_load[mid] < lm0.mean_load[mid]


def test_no_wear_at_the_pitch_point(setup):
    state = run_wear(setup, 1e6)
    i = np.argmin(abs(setup.kin.u - setup.pair.u_pitch))
    assert state.h1[i] < 1e-12 * state.h1.max() and state.h2[i] < 1e-12 * state.h2.max()
    # most wear at the ends of the path (largest sliding), on the pinion's dedendum
    assert np.argmax(state.h1) == 0


def test_wear_is_linear_in_coefficient_and_cycles_while_small(setup):
    small = replace(setup, coefficient=1e-9)
    base = run_wear(small, 1e5)
    double_k = run_wear(replace(small, coefficient=2e-9), 1e5)
    double_n = run_wear(small, 2e5)
    assert np.allclose(double_k.h1, 2 * base.h1, rtol=1e-3, atol=1e-15)
    assert np.allclose(double_n.h1, 2 * base.h1, rtol=1e-3, atol=1e-15)


def test_magnitude_matches_archard_by_hand(setup):
    r1, r2, w = wear_rates(setup, WearState.zero(setup.kin.u.size))
    k = setup.kin
    hand = setup.coefficient / setup.hardness * w[0] * abs(k.vs[0]) / k.v1[0]
    assert r1[0] == pytest.approx(hand, rel=1e-12)


def test_result_is_independent_of_the_update_step(setup):
    coarse = run_wear(setup, 2e6, max_relative_change=0.10)
    fine = run_wear(setup, 2e6, max_relative_change=0.05)
    assert fine.steps > coarse.steps
    assert np.max(np.abs(fine.h1 - coarse.h1)) < 0.02 * fine.h1.max()


def test_interrupted_run_resumes_from_its_checkpoint(setup, tmp_path):
    ck = tmp_path / "wear.npz"
    steps = wear_steps(setup, 1e6)
    for _ in range(3):      # "interrupt" after three update steps, saving as run_wear does
        state = next(steps)
    from femgear.physics.wear.archard import save_state

    save_state(state, ck, setup.kin.u)
    resumed = run_wear(setup, 1e6, checkpoint=ck)
    direct = run_wear(setup, 1e6)
    assert resumed.steps == direct.steps
    assert np.allclose(resumed.h1, direct.h1, rtol=1e-10)


def test_bad_step_rule_is_refused(setup):
    with pytest.raises(ValueError, match="max_relative_change"):
        next(wear_steps(setup, 1e6, max_relative_change=0.0))


def test_run_with_archard_wear_reports_depths(baseline_path, tmp_path):
    from femgear.edge.run import run_scene
    from femgear.scene import load_scene

    scene = load_scene(baseline_path, ['physics.wear="archard"', "wear.cycles=2e5", 'physics.dynamics="none"',
                                       'physics.coupling="one-way"'])
    summary = run_scene(scene, tmp_path, plots=False).summary
    assert summary["wear"]["cycles"] == pytest.approx(2e5)
    assert 0 < summary["wear"]["max_depth_pinion"] < 1e-5
    assert (tmp_path / "wear_checkpoint.npz").exists()


def test_load_follows_the_local_pair_stiffness():
    """Identity of the Winkler layer: without deviations the load per unit length is
    proportional to the local stiffness c_l(u) and sums to the force; a uniform c_l gives
    the uniform ISO distribution."""
    from femgear.physics.wear.load_sharing import distribute

    u = np.linspace(0.0, 1e-2, 21)
    du = np.full((1, u.size), u[1] - u[0])
    c = 1e10 * (1.0 - 0.25 * ((u - u.mean()) / np.ptp(u) * 2) ** 2)     # 25 % softer at the ends
    w = distribute(np.array([1000.0]), du, np.zeros(u.size), c, 0.5)[0]
    assert np.allclose(w / c, w[0] / c[0], rtol=1e-9)
    assert np.sum(w * du[0] / 0.5) == pytest.approx(1000.0, rel=1e-9)
    flat = distribute(np.array([1000.0]), du, np.zeros(u.size), 1e10, 0.5)[0]
    assert np.allclose(flat, flat[0], rtol=1e-9)
