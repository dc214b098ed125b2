"""Post-processing, friction power, results files and the command line."""

import json
import os
import subprocess
import sys

import numpy as np

from femgear.case import build_case
from femgear.system.dynamics.response import half_peak_to_peak, spectrum


def test_spectrum_and_amplitude_of_a_sine():
    dt, f0 = 1e-4, 250.0
    t = np.arange(4000) * dt
    x = 3.0 + 2e-6 * np.sin(2 * np.pi * f0 * t)
    sp = spectrum(x, dt, mesh_frequency=125.0)
    i = np.argmax(sp.amplitude)
    assert np.isclose(sp.frequency[i], f0) and np.isclose(sp.order[i], 2.0)
    assert np.isclose(sp.amplitude[i], 2e-6, rtol=2e-2)
    assert np.isclose(half_peak_to_peak(x), 2e-6, rtol=1e-3)


def test_friction_dissipates_power_on_average(baseline_scene):
    """The friction power on the nominal rotation is −μ N ⟨|v_s|⟩ at every mesh phase, ⟨|v_s|⟩
    the mean |sliding speed| over the helix's contact lines computed independently from the
    kinematics (v_s = ω1 ρ1 − ω2 ρ2); the tanh regularisation and the 64-point line quadrature
    of the tables are the only differences (< 1e-3)."""
    from femgear.physics.geometry import contact_lines, kinematics
    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.layout import BODIES, dof

    m = build_model(build_case(baseline_scene), "lumped", stiffness="contact-line", friction=0.05)
    qdot = np.zeros(24)
    for side in range(2):
        qdot[dof(BODIES[side], "rz")] = m.omega[0]
        qdot[dof(BODIES[2 + side], "rz")] = m.omega[1]
    qd = np.linalg.lstsq(m.T, qdot, rcond=None)[0]
    phases = np.arange(256) / 256
    A, B = m.friction(phases)
    N = 2000.0
    power = -m.mu * N * (A * (m.H0 @ qd)[:, None] + B * (m.H1 @ qd)[:, None])   # (helix, phase)
    pair, xi = m.pair, (np.arange(4000) + 0.5) / 4000
    for s, offset in enumerate((0.0, m.stagger)):
        ref = np.empty(phases.size)
        for i, ph in enumerate(phases):
            lines = contact_lines(pair, ph, offset)
            u = lines.u_lo[:, None] + (lines.u_hi - lines.u_lo)[:, None] * xi
            vs = kinematics(pair, u.ravel(), abs(m.omega[0])).vs.reshape(u.shape)
            ref[i] = np.sum(lines.length[:, None] * np.abs(vs)) / xi.size / lines.total_length
        assert np.allclose(power[s], -m.mu * N * ref, rtol=1e-3)


def test_run_dynamics_writes_results_and_plots(lumped, tmp_path):
    from femgear.edge.io.dynamics import write_dynamics
    from femgear.system.dynamics.run import run_dynamics

    r = run_dynamics(lumped, method="rk4", dt=2e-5, cycles=20, transient_cycles=10)
    files = write_dynamics(r, tmp_path)
    for key in ("json", "npz", "time_histories", "mesh_force", "phase_planes", "spectra"):
        assert files[key].exists() and files[key].stat().st_size > 0
    data = json.loads(files["json"].read_text())
    assert data["amplitudes"]["gear.displacement.y"] > 0
    assert np.isfinite(r.response.displacement).all()


def test_cli_prints_json_last(baseline_path, tmp_path):
    out = subprocess.run([sys.executable, "-m", "femgear.edge.cli", "dynamics", str(baseline_path), "--stiffness",
                          "contact-line", "--cycles", "12", "--transient", "6", "--dt", "2e-4", "--no-plots", "--out", str(tmp_path),
                          "--json"], capture_output=True, text=True, check=True,
                         env={**os.environ, "OPENBLAS_NUM_THREADS": "1"}).stdout
    payload = json.loads(out.strip().splitlines()[-1])
    assert payload["level"] == "lumped" and payload["method"] == "expo"
    bad = subprocess.run([sys.executable, "-m", "femgear.edge.cli", "dynamics", str(baseline_path), "--set",
                          "pinion.mass=-1"], capture_output=True, text=True)
    assert bad.returncode == 2 and "pinion.mass" in bad.stderr


def test_formula_friction_along_the_path(baseline_scene):
    """μ(u) from the friction package (U-shaped, zero at the pitch point) folded into the tables."""
    from femgear.system.dynamics import build_model

    m = build_model(build_case(baseline_scene), "lumped", stiffness="contact-line")   # the formula level's μ(u)
    c = build_model(build_case(baseline_scene), "lumped", stiffness="contact-line", friction=0.05)
    assert m.mu == 1.0
    assert np.abs(m.friction.A).max() < 0.06 and np.abs(m.friction.B).max() < 0.06 * np.abs(c.friction.B).max() / 0.05 * 1.5
    assert np.abs(m.friction.B).max() > 0


def test_hermite_amplitude_of_a_coarsely_sampled_sine():
    from femgear.system.dynamics.response import hermite_half_peak_to_peak

    w = 2 * np.pi / 8                                          # 8 samples per period, arbitrary phase
    for phase in np.linspace(0, 1, 5):
        k = np.arange(100)
        x, dx = 3e-6 * np.sin(w * k + phase), 3e-6 * w * np.cos(w * k + phase)
        assert abs(hermite_half_peak_to_peak(x, dx, 1.0) / 3e-6 - 1) < 3e-3


def test_hermite_extremes_are_exact_on_each_cubic():
    """Identity: the amplitude is that of the piecewise cubic Hermite interpolant itself (its
    extremes found analytically), checked against a dense evaluation of the same cubics."""
    from femgear.system.dynamics.response import hermite_half_peak_to_peak

    rng = np.random.default_rng(0)
    X, D = rng.normal(size=(40, 3)), rng.normal(size=(40, 3))
    s = np.linspace(0, 1, 20001)[:, None, None]
    h = (2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2)
    f = (h[0] * X[None, :-1] + h[1] * D[None, :-1] + h[2] * X[None, 1:] + h[3] * D[None, 1:]).reshape(-1, 3)
    assert np.allclose(hermite_half_peak_to_peak(X, D, 1.0), 0.5 * (f.max(0) - f.min(0)), rtol=1e-7)
