"""The default step set by the response (issue 26): its accuracy against a small-step reference,
the exactness of its pieces (band-exact stiffness staircase, φ-function propagators), and
stability at extreme speeds."""

import math

import numpy as np
import pytest
from scipy.linalg import expm

from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import build_model, run_dynamics, simulate
from femgear.system.dynamics.expo import _substeps, band_exact_staircase, clear_propagator_cache, default_substeps
from femgear.system.dynamics.modal import mesh_mode_limit
from femgear.system.dynamics.response import analyse
from femgear.system.dynamics.run import STEPS_PER_MODE_PERIOD, step_plan


def _model(baseline_path, rpm):
    return build_model(build_case(load_scene(baseline_path, [f"operating.speed_rpm={rpm!r}"])))


def test_staircase_keeps_the_mesh_orders_below_half_its_steps():
    """Tier 1: the n-step staircase of a piecewise-linear table has the table's Fourier coefficients
    at every order |m| < n/2 (ŝ_m = K̃_m e^{−iπm/n} sinc(πm/n), from its DFT), to round-off."""
    rng = np.random.default_rng(3)
    table = 1e9 * (1 + 0.2 * rng.random(37))            # 37 knots: orders reach all of the band
    n_tab, n = table.size, 150

    def k(ph):
        x = np.mod(ph, 1.0) * n_tab
        i = np.floor(x).astype(int) % n_tab
        return table[i] * (1 - (x - np.floor(x))) + table[(i + 1) % n_tab] * (x - np.floor(x))

    stair = band_exact_staircase(k, n)
    m = np.arange(1, (n - 1) // 2 + 1)
    s_hat = np.fft.fft(stair)[m] / n * np.exp(-1j * np.pi * m / n) * np.sin(np.pi * m / n) / (np.pi * m / n)
    # exact coefficients of the linear interpolant: table DFT × sinc²(πm/n_tab)
    T = np.fft.fft(table) / n_tab
    c_hat = T[m % n_tab] * (np.sin(np.pi * m / n_tab) / (np.pi * m / n_tab)) ** 2
    assert np.abs(s_hat - c_hat).max() < 1e-3 * np.abs(c_hat).max()   # aliasing of the 16n dense samples
    assert abs(np.mean(stair) / table.mean() - 1) < 1e-6          # the mean (of a linear interpolant: the knots')


@pytest.mark.parametrize("h", [2e-6, 3e-4])
def test_taylor_propagators_equal_the_block_exponential(baseline_path, h):
    """Φ = e^{Ah} and Γ_p = ∫e^{A(h−τ)}(τ/h)^p dτ from the Taylor series (with scaling and doubling
    for the long step, ‖Ah‖ ≫ 1) equal Van Loan's block exponential (scipy) to 1e-12."""
    m = _model(baseline_path, 500.0)
    n = m.n
    k = np.array([[1.1 * m.stiffness.mean[0], 0.9 * m.stiffness.mean[1]]])
    Minv = np.linalg.inv(m.M)
    K = m.K + sum(k[0, s] * np.outer(m.G[s], m.G[s]) for s in range(2))
    C = m.C + sum(m.mesh_damping[s] * np.outer(m.G[s], m.G[s]) for s in range(2))
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    mm = 2 * n
    Z = np.zeros((4 * mm, 4 * mm))
    Z[:mm, :mm] = A
    for b in range(3):
        Z[b * mm:(b + 1) * mm, (b + 1) * mm:(b + 2) * mm] = np.eye(mm)
    E = expm(Z * h)
    ref = (E[:mm, :mm], E[:mm, mm:2 * mm], E[:mm, 2 * mm:3 * mm] / h, 2 * E[:mm, 3 * mm:] / h**2)
    got = [x[0] for x in _substeps(m, k, (1, 1), h)]
    for g, r in zip(got, ref):
        assert np.abs(g - r).max() < 1e-12 * np.abs(r).max()


def test_step_follows_the_reached_modes_not_the_speed_floor(baseline_path):
    """The recording step samples the highest mode the mesh reaches 8 times; the transient keeps the
    mesh-excitation floor (200 per mesh period) and divides the recording count; the stiffness
    sub-steps give ≥ 24 samples of that mode's period (and ≥ 800 per mesh period)."""
    for rpm in (100.0, 3000.0):
        m = _model(baseline_path, rpm)
        f_r = mesh_mode_limit(m)
        assert f_r == pytest.approx(max(m.flexible_modes_hz))          # the baseline's top mode loads the mesh
        per, per_t = step_plan(m)
        order = f_r / m.mesh_frequency
        assert per >= STEPS_PER_MODE_PERIOD * order and per >= 200 and per % per_t == 0 and per_t >= 200
        assert per < STEPS_PER_MODE_PERIOD * order + per // per_t + 200 * (order < 25)
        sub = default_substeps(m, per)
        assert per * sub >= max(800, 24 * order)
    assert step_plan(_model(baseline_path, 100.0))[0] < 1300     # the rule before: 3200


def _reference(model, cycles, transient, per):
    """RK4 at 4× the default's recording steps with the linear-interpolated stiffness at its stages
    (no staircase, no Hermite-limited step): an independent small-step answer."""
    sim = simulate(model, cycles * model.mesh_period, model.mesh_period / (4 * per), "rk4")
    return analyse(sim, transient).amplitudes


@pytest.mark.parametrize("rpm", [pytest.param(100.0, marks=pytest.mark.slow), 500.0])
def test_default_step_matches_a_small_step_reference(baseline_path, rpm):
    """Issue 26: the default plan (coarse transient, 8 samples of the top mode while recording) against
    RK4 at 4× the recording steps over the same 12 mesh periods (6 dropped): gear v_y and the other member
    velocity/displacement amplitudes within 1 %, DTE RMS within 0.2 %, mesh-force amplitudes within 1 %
    (measured: ≤ 0.12 %, 0.01 %, 0.33 %).  The plan without its reading floor (200 steps per mesh period,
    ``STEPS_PER_MODE_PERIOD = 0``) is 18 % off gear v_y at 100 rpm and 2.9 % off the mesh-force
    amplitude at 500 rpm; the rule before took 3200 steps per mesh period at 100 rpm."""
    m = _model(baseline_path, rpm)
    cycles, transient = 12.0, 6.0
    run = run_dynamics(m, cycles=cycles, transient_cycles=transient)
    per = step_plan(m)[0]
    assert run.simulation.info["steps_per_mesh_period"] == per
    ref = _reference(m, cycles, transient, per)
    got = run.amplitudes
    assert abs(got["gear.velocity.y"] / ref["gear.velocity.y"] - 1) < 0.01
    for key in [f"{mem}.{k}.{a}" for mem in ("pinion", "gear") for k in ("displacement", "velocity") for a in "xy"]:
        assert abs(got[key] / ref[key] - 1) < 0.01, key
    assert abs(got["dte_rms"] / ref["dte_rms"] - 1) < 0.002
    for side in "LR":
        key = f"mesh_force.{side}.amplitude"
        assert abs(got[key] / ref[key] - 1) < 0.01, key
    clear_propagator_cache()


@pytest.mark.parametrize("rpm, cycles", [pytest.param(10.0, 4.0, marks=pytest.mark.slow), (15000.0, 60.0)])
def test_extreme_speeds_stay_finite_and_static_at_low_speed(baseline_path, rpm, cycles):
    """10 rpm (mesh order of the top mode 1610: 12928 steps per mesh period while recording) and
    15000 rpm (mesh frequency 7.75 kHz, above most modes): no NaN, bounded response; at 10 rpm the
    mean mesh force is the static one (torque / base radius / cos β_b per helix, within 0.5 %)."""
    m = _model(baseline_path, rpm)
    run = run_dynamics(m, cycles=cycles, transient_cycles=cycles / 2)
    a = run.amplitudes
    assert all(math.isfinite(v) for v in a.values())
    assert np.all(np.isfinite(run.simulation.q)) and np.all(np.isfinite(run.simulation.v))
    assert a["dte_rms"] < 1e-5
    if rpm < 100:
        pair = m.pair
        static = 200.0 / pair.rb1 / 2 / math.cos(pair.beta_b)
        assert a["mesh_force.L.mean"] == pytest.approx(static, rel=5e-3)
        assert run.simulation.info["steps_per_mesh_period"] > 10000
    clear_propagator_cache()
