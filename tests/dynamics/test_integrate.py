"""Tier 1/2: integrators — RK4 order, energy conservation, fast integrator vs fine RK4."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import MeshDeviation, build_model, simulate, with_deviation
from femgear.system.dynamics.integrate import expo_step
from femgear.system.dynamics.response import analyse


def energy(model, q, v):
    """Kinetic + structural + mesh potential − work potential of the constant torques [J]."""
    from femgear.physics.excitation import gap_function

    kin = 0.5 * np.einsum("ti,ij,tj->t", v, model.M, v)
    pot = 0.5 * np.einsum("ti,ij,tj->t", q, model.K, q)
    delta = q @ model.G.T
    k = np.array(model.stiffness.mean)
    mesh = 0.5 * (k * gap_function(delta, model.backlash) ** 2).sum(axis=1)
    work = q @ (model.torque_full @ model.T)
    return kin + pot + mesh - work


@pytest.fixture(scope="module")
def conservative(baseline_path):
    scene = load_scene(baseline_path, ["pinion.support_damping=0", "gear.support_damping=0"])
    return build_model(build_case(scene), "lumped", stiffness="constant", rayleigh_ratio=0.0, mesh_damping_ratio=0.0,
                       friction=0.0)


def kicked(model, speed=0.05):
    q0 = model.static_state()
    rng = np.random.default_rng(1)
    v0 = rng.normal(size=model.n) * speed / np.sqrt(np.diag(model.M) / np.diag(model.M).mean())
    return q0, v0


def test_rk4_is_fourth_order_on_a_linear_case(conservative):
    """Free vibration of the undamped linear model (flanks in contact): global error ∝ dt⁴."""
    m = conservative
    q0, v0 = kicked(m, speed=0.01)
    T = 3 / m.mesh_frequency
    ref = simulate(m, T, T / 32768, "rk4", q0=q0, v0=v0).q[-1]
    steps = np.array([1024, 2048, 4096])
    err = [np.abs(simulate(m, T, T / s, "rk4", q0=q0, v0=v0).q[-1] - ref).max() for s in steps]
    slope = -np.polyfit(np.log(steps), np.log(err), 1)[0]
    assert 3.8 < slope < 4.3, (err, slope)


def _drift(m, method, dt, q0, v0, periods=10):
    s = simulate(m, periods / m.mesh_frequency, dt, method, q0=q0, v0=v0)
    E = energy(m, s.q, s.v)
    return np.abs(E - E[0]).max() / (0.5 * v0 @ m.M @ v0)


def test_energy_is_conserved_without_damping_and_excitation(conservative):
    """Newmark (α = 0) and expo conserve the energy of the linear undamped model to round-off;
    RK4's (slightly dissipative) drift vanishes with its truncation error, ∝ dt⁵ per unit time."""
    m = conservative
    q0, v0 = kicked(m)
    assert _drift(m, "newmark", 2e-5, q0, v0) < 1e-10
    assert _drift(m, "expo", 2e-5, q0, v0) < 1e-9
    d1, d2 = _drift(m, "rk4", 5e-6, q0, v0), _drift(m, "rk4", 2.5e-6, q0, v0)
    assert d2 < 1e-3 and d1 / d2 > 25, (d1, d2)


def test_energy_conserved_through_contact_loss(conservative):
    """A kick large enough to open the backlash: the piecewise-quadratic energy still holds (RK4)."""
    m = conservative
    q0, v0 = kicked(m, speed=2.0)
    s = simulate(m, 5 / m.mesh_frequency, 2.5e-6, "rk4", q0=q0, v0=v0)
    delta = s.q @ m.G.T
    assert np.any(np.abs(delta) <= m.backlash)               # the flanks did separate
    E = energy(m, s.q, s.v)
    assert np.abs(E - E[0]).max() / (0.5 * v0 @ m.M @ v0) < 1e-3


def test_fast_integrator_matches_fine_rk4(baseline_path):
    """``expo`` at 200 steps per mesh period vs RK4 at 800: amplitudes (each from its own samples,
    extremes refined) within 0.5 %."""
    scene = load_scene(baseline_path, ["errors.profile_error=1e-6", "pinion.eccentricity=20e-6"])
    m = build_model(build_case(scene), "lumped", stiffness="contact-line")
    T = 60 * m.mesh_period
    dt, per = expo_step(m, m.mesh_period / 200)
    fast = analyse(simulate(m, T, dt, "expo"), transient_cycles=30).amplitudes
    ref = analyse(simulate(m, T, m.mesh_period / 800, "rk4"), transient_cycles=30).amplitudes
    keys = [f"{mem}.{kind}.{ax}" for mem in ("pinion", "gear") for kind in ("displacement", "velocity") for ax in "xy"]
    keys += ["mesh_force.L.amplitude", "mesh_force.R.amplitude"]
    for k in keys:
        assert abs(fast[k] / ref[k] - 1) < 5e-3, (k, fast[k], ref[k])


def _mesh_force_at(model, x: float) -> np.ndarray:
    """Elastic mesh forces (at rest, phase 0) for the mesh approach G q = x on both helices."""
    q = np.linalg.pinv(model.G) @ np.array([x, x])
    return model.mesh_forces(np.array(0.0), q, np.zeros(model.n))[1]


def test_drive_wear_moves_only_the_drive_threshold_and_expansion_closes_both(baseline_path):
    """Each deviation enters once: a uniform wear depth w on the drive flanks moves the drive
    contact threshold from b to b + w and leaves the coast one at −b; a uniform thermal
    expansion ζ moves them to b − ζ and −(b − ζ) (exact identities of the dead zone)."""
    case = build_case(load_scene(baseline_path))
    base = build_model(case, "lumped", stiffness="constant", friction=0.0)
    b, k = base.backlash, base.stiffness.mean[0]
    w, zeta, n = 7e-6, 4e-6, 16
    worn = with_deviation(base, MeshDeviation(drive=np.full((2, n), w), coast=np.zeros((2, n))))
    warm = with_deviation(base, MeshDeviation(drive=np.full((2, n), -zeta), coast=np.full((2, n), -zeta)))
    for model, drive, coast in ((base, b, b), (worn, b + w, b), (warm, b - zeta, b - zeta)):
        for x in (drive + 1e-9, drive + 3e-6, -coast - 2e-6):
            expected = k * (x - drive) if x > 0 else k * (x + coast)
            assert np.allclose(_mesh_force_at(model, x), expected, rtol=1e-9, atol=1e-9 * k * 1e-6)
        for x in (drive - 1e-9, -coast + 1e-9):
            assert np.all(_mesh_force_at(model, x) == 0.0)


def test_an_antisymmetric_flank_deviation_is_a_transmission_error(baseline_path):
    """d_D = −d_C = e(φ) shifts the dead zone without opening it: the same response as the
    profile-error harmonic e(t) of the scene; all three integrators agree on a drive-only
    deviation table; a deviation ripple larger than the static deflection opens the contact."""
    scene = load_scene(baseline_path, ["errors.profile_error=1e-6", "errors.profile_error_orders=1"])
    plain = build_case(load_scene(baseline_path))
    ph = np.arange(2048) / 2048
    table = 1e-6 * np.sin(2 * np.pi * ph)
    kw = dict(level="lumped", stiffness="constant", friction=0.0)
    m_ref = build_model(build_case(scene), **kw)
    m_tab = build_model(plain, deviation=MeshDeviation(drive=np.array([table, table]),
                                                       coast=-np.array([table, table])), **kw)
    m_drive = build_model(plain, deviation=MeshDeviation(drive=np.array([table, table]), coast=np.zeros((2, 2048))),
                          **kw)
    T, dt = 30 * m_ref.mesh_period, m_ref.mesh_period / 200
    ref = analyse(simulate(m_ref, T, dt, "rk4"), 15).amplitudes
    tab = analyse(simulate(m_tab, T, dt, "rk4"), 15).amplitudes
    for key in ("mesh_force.L.amplitude", "gear.displacement.y", "pinion.displacement.x"):
        assert abs(tab[key] / ref[key] - 1) < 5e-3, key
    # (velocities are left out: the kinks of a piecewise-linear table excite the high modes a little)
    drive = {m: analyse(simulate(m_drive, T, dt, m), 15).amplitudes for m in ("rk4", "expo", "newmark")}
    for method in ("expo", "newmark"):
        for key in ("gear.displacement.y", "pinion.displacement.x"):
            assert abs(drive[method][key] / drive["rk4"][key] - 1) < 5e-3, (method, key)
    # on the drive flank only the drive threshold matters: the same response as the shift alone
    for key in ("gear.displacement.y", "pinion.displacement.x"):
        assert abs(drive["rk4"][key] / tab[key] - 1) < 5e-3, key
    d0 = m_ref.static_state() @ m_ref.G[0] - m_ref.backlash
    ripple = 2 * d0 * (1 + np.sin(2 * np.pi * 10 * ph))
    m_open = build_model(plain, deviation=MeshDeviation(drive=np.array([ripple, ripple]), coast=np.zeros((2, 2048))),
                         **kw)
    res = analyse(simulate(m_open, T, dt / 4, "rk4"), 15)
    assert 0.02 < res.amplitudes["contact_loss_fraction.L"] < 0.9


def test_record_plan_keeps_the_last_state_of_a_transient_ending_at_record_from():
    """A transient of ``switch`` whole mesh periods at T/n records its last state although n·(T/n)
    rounds below ``switch``·T (100 rpm rig condition, n = 350: the default plan's switch read an
    empty array before)."""
    from femgear.system.dynamics.simulation import record_plan

    for n_per, switch in ((350, 49), (351, 49), (1777, 99), (6000, 99)):
        T = 60.0 / (31 * 100.0)
        dt = T / n_per
        steps = int(round(switch * T / dt))
        assert steps * dt < switch * T or n_per not in (350, 351)     # the rounding this guards against
        assert list(record_plan(steps, dt, 1, switch * T)) == [steps]
    assert list(record_plan(10, 0.1, 1, 0.55)) == [6, 7, 8, 9, 10]   # not a grid point: strictly after
