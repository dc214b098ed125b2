"""Tier 3: sidebands f_m ± k f_s of a once-per-revolution pitch error and of eccentricity against the analytic
modulation of the excitation, in the small-amplitude linear case (frequency-domain solutions of the same model)."""

import math
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.physics.excitation import CumulativePitchError
from femgear.scene import load_scene
from femgear.system.dynamics import build_model, run_dynamics
from femgear.system.dynamics.mesh import StiffnessTable
from femgear.system.dynamics.orders import line_fit

BASE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
UPPER, LOWER = 3, 1            # columns of j = +1, −1 in the sideband table (sides −2 … 2)


def _dynamic_stiffness(m, w):
    """Z(ω) = K + iωC − ω²M + Σ_s (k̄_s + iω c_s) G_sᵀ G_s: the linear model with both flanks in contact."""
    Z = m.K + 1j * w * m.C - w**2 * m.M
    for s in range(2):
        Z = Z + (m.stiffness.mean[s] + 1j * w * m.mesh_damping[s]) * np.outer(m.G[s], m.G[s])
    return Z


def _mesh_force(m, w, e):
    """Complex mesh forces N̂_s and state q̂ of the linear model under transmission errors ê_s at ω [rad/s]:
    Z q̂ = Σ_s (k̄_s + iω c_s) G_sᵀ ê_s, N̂_s = (k̄_s + iω c_s)(G_s q̂ − ê_s)."""
    kc = np.array(m.stiffness.mean) + 1j * w * m.mesh_damping
    q = np.linalg.solve(_dynamic_stiffness(m, w), (kc * e) @ m.G)
    return kc * (m.G @ q - e), q


def test_tooth_by_tooth_sinusoid_has_the_hold_spectrum():
    """The pitch error's signal against its analytic lines A sinc²(π(k + 1/z)) (first-order hold of a sampled
    sinusoid), read by a line fit over two revolutions: equal to 1e-3."""
    e = CumulativePitchError(2e-6, 300.0, 17, 0.4, 0.3)
    t = np.arange(2 * 17 * 64) / (300.0 * 64)
    ks = (0, 1, -1, 2, -2)
    _, X = line_fit(e.value(t), t, [e.line(k)[0] for k in ks])
    assert np.allclose(X, [e.line(k)[1] for k in ks], rtol=1e-3, atol=1e-3 * abs(e.line(1)[1]))


def test_pitch_error_sidebands_match_the_modulated_excitation():
    """Constant mesh stiffness (a linear time-invariant model), a 1 µm once-per-revolution pitch error of the
    pinion at 3000 rpm: the dynamic mesh force's shaft-order line and its sidebands at f_m ± f_s equal the model's
    frequency response to the excitation's analytic lines to 2 %."""
    case = build_case(load_scene(BASE, ["pinion.cumulative_pitch_error=1e-6", "operating.speed_rpm=3000.0"]))
    m = build_model(case, "lumped", stiffness="constant", friction=0.0)
    r = run_dynamics(m, cycles=102, transient_cycles=40)                  # 62 periods: two pinion revolutions
    pinion = r.response.sidebands[0]
    assert pinion.member == "pinion" and pinion.revolutions == 2
    assert r.amplitudes["contact_loss_fraction.L"] == 0
    for k, reported in ((1, pinion.lines["mesh_force_L"][0, UPPER]), (-1, pinion.lines["mesh_force_L"][0, LOWER]),
                        (0, pinion.shaft_orders["mesh_force_L"][0])):
        f = m.pitch_errors[0][0].line(k)[0]
        N, _ = _mesh_force(m, 2 * math.pi * f, np.array([m.pitch_errors[s][0].line(k)[1] for s in range(2)]))
        assert reported == pytest.approx(abs(N[0]), rel=0.02), k


def test_eccentricity_sidebands_are_the_stiffness_modulated_by_the_shaft_order_deflection():
    """A mesh stiffness k̄(1 + κ cos 2πφ), κ = 0.05, and a 10 µm pinion eccentricity on a power loop at 3000 rpm:
    the excitation k(t)(δ − e) carries the sidebands ½ κ k̄ D at ω_m ± Ω, D the shaft-order mesh deflection
    (amplitude modulation of the stiffness harmonic); to first order in κ the mesh force's sidebands are
    N± = (k̄ + iω± c)G q± + ½ κ k̄ D±, Z(ω±) q± = −Σ Gᵀ ½ κ k̄ D± (the next terms are O(κ²) relative): the
    time-domain run's sidebands equal them to 2 %."""
    case = build_case(load_scene(BASE, ["pinion.eccentricity=10e-6", "operating.speed_rpm=3000.0"]))
    kappa, k0, phase = 0.05, 3.0e8, np.arange(256) / 256
    table = StiffnessTable(k0 * (1 + kappa * np.cos(2 * np.pi * phase)), k0 * (1 + kappa * np.cos(2 * np.pi * phase)))
    m = build_model(case, "lumped", stiffness=table, friction=0.0, load_stiffness=1e4)
    r = run_dynamics(m, cycles=102, transient_cycles=40)
    assert r.amplitudes["contact_loss_fraction.L"] == 0
    pinion = r.response.sidebands[0]
    omega, wm, g = m.omega[0], 2 * math.pi * m.mesh_frequency, m.geometry.g
    e_hat = np.array([-10e-6 * (g[s, 6 * s] - 1j * g[s, 6 * s + 1]) for s in range(2)])   # −r(t)·g_x, pinion ahead
    N0, q0 = _mesh_force(m, omega, e_hat)
    assert pinion.shaft_orders["mesh_force_L"][0] == pytest.approx(abs(N0[0]), rel=0.02)
    D, kbar = m.G @ q0 - e_hat, np.array(m.stiffness.mean)
    for sign, column in ((1, UPPER), (-1, LOWER)):
        w = wm + sign * omega
        excitation = 0.5 * kappa * kbar * (D if sign > 0 else np.conj(D))
        q = np.linalg.solve(_dynamic_stiffness(m, w), -(excitation @ m.G))
        N = (kbar + 1j * w * m.mesh_damping) * (m.G @ q) + excitation
        assert pinion.lines["mesh_force_L"][0, column] == pytest.approx(abs(N[0]), rel=0.02), sign
    # without the stiffness ripple the eccentricity leaves no sidebands
    flat = build_model(case, "lumped", stiffness=StiffnessTable(np.array([k0]), np.array([k0])), friction=0.0,
                       load_stiffness=1e4)
    lines = run_dynamics(flat, cycles=102, transient_cycles=40).response.sidebands[0].lines["mesh_force_L"]
    assert lines[0, UPPER] < 1e-3 * pinion.lines["mesh_force_L"][0, UPPER]


def test_a_record_shorter_than_a_revolution_reports_nothing(lumped):
    from femgear.edge.io.dynamics import dynamics_summary

    r = run_dynamics(lumped, cycles=30, transient_cycles=10)              # 20 periods < z1 = 31
    sb = dynamics_summary(r)["sidebands"]
    assert sb["pinion"]["resolved"] is False and sb["pinion"]["needs_mesh_periods"] == lumped.pair.z1
    assert "lines" not in sb["pinion"]
