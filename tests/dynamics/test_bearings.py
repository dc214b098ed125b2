"""Tier 2: bearing forces — hand statics of the mean loads, Newton's law of the dynamic parts, order lines."""

import math

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import build_model, run_dynamics, simulate
from femgear.system.dynamics.bearings import bearing_forces, force_matrices, newton_balance, static_bearing_loads
from femgear.system.dynamics.orders import line_fit, mesh_orders, resolves
from tests.dynamics import hand_statics


def _hand(model, torque):
    h = model.half_spacing
    zb = model.bearings.z.reshape(2, 2)
    if model.pair.n_helices == 2:
        return hand_statics.bearing_loads(model.pair, torque, (-h, h), (1, -1), zb)
    return hand_statics.bearing_loads(model.pair, torque, (0.0,), (1,), zb)


@pytest.mark.parametrize("level", ["lumped", "timoshenko"])
def test_mean_bearing_loads_balance_the_hand_statics(level, baseline_scene):
    """Static loads equal the hand statics (radial to 1e-9); the mean loads of a dynamic run over its recorded
    mesh cycles equal them to 0.5 % (the dynamic mean of the mesh force is the static one)."""
    m = build_model(build_case(baseline_scene), level, stiffness="contact-line", friction=0.0)
    hand = _hand(m, baseline_scene.operating.torque)
    static = static_bearing_loads(m)
    assert np.allclose(static[:, :2], hand[:, :2], rtol=1e-9, atol=1e-9 * np.abs(hand).max())
    assert np.allclose(static[:, 2].reshape(2, 2).sum(axis=1), 0.0, atol=1e-9 * np.abs(hand).max())   # helices cancel
    r = run_dynamics(m, cycles=40, transient_cycles=20)
    mean = r.response.bearings.mean
    radial = np.hypot(hand[:, 0], hand[:, 1])
    assert np.all(np.linalg.norm(mean[:, :2] - hand[:, :2], axis=1) < 5e-3 * radial)


def _recorded(model, cycles=24, transient=12, per=2000):
    sim = simulate(model, cycles * model.mesh_period, model.mesh_period / per, "rk4")
    keep = sim.t >= transient * model.mesh_period - 1e-12
    return sim.t[keep], sim.q[keep], sim.v[keep]


@pytest.mark.parametrize("level", ["lumped", "timoshenko"])
def test_dynamic_bearing_loads_obey_newtons_law(level, baseline_path):
    """m a = mesh force + unbalance − Σ bearing loads − Rayleigh's body damping, per member and direction, over the
    record of an eccentric, unbalanced pair with profile errors; the acceleration is differentiated from the
    recorded velocity (a cubic spline, not the model's equations: so the excitation is smooth, a constant mesh
    stiffness without friction, whose tables jump).  Lumped: the inertia is the scene's member mass times the
    acceleration of its centre."""
    scene = load_scene(baseline_path, ["pinion.eccentricity=20e-6", "gear.unbalance=2e-5", "pinion.unbalance=1e-5",
                                       "errors.profile_error=0.5e-6", "operating.speed_rpm=5000.0"])     # f_m near the 2.7 kHz mode
    m = build_model(build_case(scene), level, stiffness="constant", friction=0.0)
    t, q, v = _recorded(m)
    a = CubicSpline(t, v).derivative()(t)
    terms = newton_balance(m, t, q, v, a)
    if level == "lumped":                                 # the inertia from the scene's masses, independently
        a_full = a @ m.T.T
        for member, name in enumerate(("pinion", "gear")):
            centre = 0.5 * (a_full[:, 12 * member: 12 * member + 3] + a_full[:, 12 * member + 6: 12 * member + 9])
            assert np.allclose(terms["inertia"][:, member], getattr(scene, name).mass * centre, rtol=1e-9, atol=1e-9)
        assert np.abs(terms["guyan_damping"]).max() < 1e-12 * np.abs(terms["bearings"]).max()
    dyn = terms["bearings"] - terms["bearings"].mean(axis=0)
    scale = np.abs(dyn).max(axis=0)                       # (member, direction)
    resid = np.abs(terms["residual"]).max(axis=0)
    radial = scale[:, :2]
    assert np.all(radial > 100.0)                          # a real dynamic load
    inertia = np.abs(terms["inertia"] - terms["inertia"].mean(axis=0)).max(axis=0)[:, :2]
    assert np.all(inertia > 0.5 * radial)                  # near resonance: the inertia is no small correction
    assert np.all(resid[:, :2] < 1e-3 * radial)
    # the balance fails without the Rayleigh stiffness part a1 K_j u̇_j of the bearing load
    KF, CF = force_matrices(m)
    B = m.bearing_map.reshape(4, 3, m.n)
    missing = m.rayleigh[1] * np.einsum("jd,jdn,tn->tjd", m.bearings.stiffness, B, v).reshape(-1, 2, 2, 3).sum(2)
    assert np.all(np.abs(missing).max(axis=0)[:, :2] > 10 * resid[:, :2])


def test_bearing_force_is_linear_in_the_state(lumped):
    q = np.random.default_rng(1).normal(size=(5, lumped.n)) * 1e-6
    v = np.random.default_rng(2).normal(size=(5, lumped.n)) * 1e-3
    KF, CF = force_matrices(lumped)
    F = bearing_forces(lumped, q, v)
    assert F.shape == (5, 4, 3)
    assert np.allclose(F, np.einsum("jdn,tn->tjd", KF, q) + np.einsum("jdn,tn->tjd", CF, v), rtol=1e-12)
    # lumped: each station moves as a point of its rigid member (d + θ × r at z = ±span/2)
    zb = lumped.bearings.z
    x = q[0] @ lumped.T.T
    centre = 0.5 * (x[0:6] + x[6:12])
    expected = centre[:3] + np.cross(centre[3:], [0.0, 0.0, zb[0]])
    assert np.allclose(lumped.bearing_map[:3] @ q[0], expected, rtol=1e-12)


def test_line_fit_reads_lines_exactly_and_refuses_unresolved_ones():
    fm, t = 250.0, np.arange(0, 0.2, 1 / 9000)
    x = 3.0 + 2.0 * np.cos(2 * np.pi * fm * t + 0.3) + 0.5 * np.sin(2 * np.pi * (fm + 10) * t) \
        + 0.2 * np.cos(2 * np.pi * 2 * fm * t - 1.0)
    mean, X = line_fit(x, t, [fm, fm + 10, 2 * fm])
    assert np.isclose(mean, 3.0) and np.allclose(np.abs(X), [2.0, 0.5, 0.2], rtol=1e-10)
    assert np.isclose(np.angle(X[0]), 0.3) and np.isclose(np.angle(X[2]), -1.0) and np.isclose(np.angle(X[1]), -np.pi / 2)
    assert not resolves(t[:450], [fm, fm + 10])          # 50 ms < 1/10 Hz: unresolved, refused
    with pytest.raises(ValueError, match="does not resolve"):
        line_fit(x[:450], t[:450], [fm, fm + 10])
    orders = mesh_orders(x[:, None] * [1.0, -2.0], t, fm, orders=3)
    assert orders.shape == (3, 2) and np.isclose(orders[0, 1], 4.0, rtol=0.02)


def test_run_reports_bearing_forces_in_the_summary(lumped):
    from femgear.edge.io.dynamics import dynamics_summary

    r = run_dynamics(lumped, cycles=12, transient_cycles=6)
    bf = dynamics_summary(r)["bearing_forces"]
    assert set(bf) >= {"pinion_L", "pinion_R", "gear_L", "gear_R", "units"}
    for name in ("pinion_L", "gear_R"):
        assert len(bf[name]["mean"]) == 3 and len(bf[name]["mesh_orders"]) == 6
        assert bf[name]["radial_mean"] > 1000 and all(map(math.isfinite, bf[name]["peak_to_peak"]))


def test_a_run_without_dynamics_reports_the_static_bearing_loads():
    """dynamics = "none" (the FZG C pair): results' static bearing loads are the hand statics (1e-9)."""
    from pathlib import Path

    from femgear.edge.io.run import run_summary
    from femgear.pipeline import run_case

    path = Path(__file__).resolve().parents[2] / "studies" / "fzg_c14.toml"
    case = build_case(load_scene(path, ['physics.lubrication="constant"', "numerics.path_points=11"]))
    assert case.levels.dynamics == "none"
    result = run_case(case)
    span = [m.bearing_span for m in case.members]
    hand = hand_statics.bearing_loads(case.pair, case.operating.pinion_torque, (0.0,), (1,),
                                      np.array([[-s / 2, s / 2] for s in span]))
    assert np.allclose(result.static_bearing_loads, hand, rtol=1e-9, atol=1e-9 * np.abs(hand).max())
    static = run_summary(result)["bearing_forces_static"]
    assert static["gear_R"]["mean"] == pytest.approx(list(hand[3]), rel=1e-9, abs=1e-6)
