"""Tier 1: the assembled model — symmetry, action = reaction, kinematics, statics."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from femgear.case import build_case
from femgear.physics.geometry import kinematics
from femgear.system.dynamics.layout import BODIES, dof


@pytest.mark.parametrize("which", ["lumped", "timoshenko"])
def test_matrices_symmetric_positive(which, request):
    m = request.getfixturevalue(which)
    assert m.n == (12 if which == "lumped" else 24)
    for A in (m.M, m.K, m.C):
        assert np.allclose(A, A.T, rtol=1e-12, atol=1e-9 * np.abs(A).max())
    assert np.all(np.linalg.eigvalsh(m.M) > 0)
    Km = m.mean_stiffness_matrix()
    w = np.linalg.eigvalsh(Km)
    assert np.sum(np.abs(w) < 1e-9 * w.max()) == 1          # only the free rotation of the gear train


def test_mesh_vector_matches_the_deflection_formula(lumped):
    """g_s = the notes' δ_s with β_b, ψ = α_wt and the tilt arm r_w (layout docstring)."""
    from femgear.system.dynamics.mesh import mesh_geometry

    pair = lumped.pair
    geo = mesh_geometry(pair, 0.01)
    a, bb = pair.alpha_wt, pair.beta_b
    for s, sigma in enumerate((1, -1)):
        g = geo.g[s]
        p, q = 6 * s, 6 * (2 + s)
        assert np.allclose(g[p:p + 6], [math.sin(a) * math.cos(bb), math.cos(a) * math.cos(bb), sigma * math.sin(bb),
                                        0.0, -sigma * pair.rw1 * math.sin(bb), pair.rb1 * math.cos(bb)], atol=1e-14)
        assert np.allclose(g[q:q + 6], [-math.sin(a) * math.cos(bb), -math.cos(a) * math.cos(bb), -sigma * math.sin(bb),
                                        0.0, -sigma * pair.rw2 * math.sin(bb), pair.rb2 * math.cos(bb)], atol=1e-14)


def test_action_equals_reaction(lumped):
    """Mesh forces sum to zero force and zero moment about any point (in the full space)."""
    from femgear.system.dynamics.mesh import mesh_geometry

    geo = mesh_geometry(lumped.pair, lumped.half_spacing)
    for s in range(2):
        for vec in (geo.g[s], geo.h0[s], geo.h1[s]):
            force = sum(vec[6 * b: 6 * b + 3] for b in range(4))
            assert np.allclose(force, 0.0, atol=1e-14)
            # moment about the pinion axis origin: r_b × F + M_b, body centres at (0/a_w, 0, ±h)
            h = lumped.half_spacing
            centres = [np.array([0, 0, -h]), np.array([0, 0, h]), np.array([lumped.pair.a_w, 0, -h]),
                       np.array([lumped.pair.a_w, 0, h])]
            moment = sum(np.cross(centres[b], vec[6 * b: 6 * b + 3]) + vec[6 * b + 3: 6 * b + 6] for b in range(4))
            assert np.allclose(moment, 0.0, atol=1e-14)


def test_rigid_rotation_leaves_mesh_undeformed_and_gives_the_sliding_speed(lumped, baseline_scene):
    pair = lumped.pair
    qdot = np.zeros(24)
    for side in range(2):
        qdot[dof(BODIES[side], "rz")] = lumped.omega[0]
        qdot[dof(BODIES[2 + side], "rz")] = lumped.omega[1]
    from femgear.system.dynamics.mesh import mesh_geometry

    geo = mesh_geometry(pair, lumped.half_spacing)
    assert np.allclose(geo.g @ qdot, 0.0, atol=1e-12)
    u = np.linspace(pair.u_start, pair.u_end, 7)
    kin = kinematics(pair, u, abs(lumped.omega[0]))
    for s in range(2):
        w = geo.h0[s] @ qdot + (u - pair.u_pitch) * (geo.h1[s] @ qdot)
        assert np.allclose(w, -kin.vs, rtol=1e-10, atol=1e-12)   # pinion relative to gear along t


def test_static_mesh_force_carries_the_torque(baseline_scene):
    from femgear.system.dynamics import build_model

    m = build_model(build_case(baseline_scene), "lumped", stiffness="constant", friction=0.0)
    q0 = m.static_state()
    delta, N, Q = m.mesh_forces(np.array(0.0), q0, np.zeros(m.n))
    expected = baseline_scene.operating.torque / (2 * m.pair.rb1 * math.cos(m.pair.beta_b))
    assert np.allclose(N, expected, rtol=1e-10)
    assert np.allclose(delta, m.backlash + expected / m.stiffness.mean[0], rtol=1e-10)
    resid = m.external_force(np.array(0.0)) + Q - m.K @ q0
    assert np.max(np.abs(resid)) < 1e-8 * np.max(np.abs(m.torque_full))


def test_contact_line_stiffness_mean_and_stagger(baseline_pair):
    from femgear.system.dynamics.mesh import constant_stiffness, contact_line_stiffness

    k = contact_line_stiffness(baseline_pair, 2e10, stagger=0.5, samples=512)
    kc = constant_stiffness(baseline_pair, 2e10)
    assert np.allclose(k.mean, kc.mean, rtol=5e-3)           # same time mean as the constant level
    kl, kr = k(np.array([0.1]))
    kl2, _ = k(np.array([0.6]))
    assert np.isclose(kr[0], kl2[0], rtol=1e-6)               # right = left shifted by the stagger


def test_external_tvms_table_plugs_in(baseline_scene):
    from femgear.system.dynamics import build_model

    class Ripple:                                             # any callable phase -> (k_L, k_R)
        level = "test"

        def __call__(self, phase):
            k = 3e8 * (1 + 0.1 * np.cos(2 * np.pi * phase))
            return k, k

    m = build_model(build_case(baseline_scene), "lumped", stiffness=Ripple())
    assert m.stiffness.label == "test"
    assert np.isclose(m.stiffness.mean[0], 3e8, rtol=1e-9)


def test_eccentricity_is_absorbed_by_the_free_rotation_but_not_by_a_power_loop(baseline_path):
    """Eccentricity is a shaft-order transmission error: with prescribed torques the gear train
    follows it by a rigid relative rotation (mesh force unchanged); a torsional power loop resists
    that rotation and the shaft-order mesh force ≈ k_loop/r_b2² · e appears."""
    from femgear.scene import load_scene
    from femgear.system.dynamics import build_model, simulate
    from femgear.system.dynamics.response import analyse

    amp = {}
    for kloop in (0.0, 1e4):
        for e in (0.0, 30e-6):
            scene = load_scene(baseline_path, [f"pinion.eccentricity={e}", f"gear.eccentricity={e}"])
            m = build_model(build_case(scene), "lumped", stiffness="contact-line", load_stiffness=kloop)
            assert np.sum(np.abs(np.linalg.eigvalsh(m.mean_stiffness_matrix())) < 1e-3) == 1  # train still free
            res = analyse(simulate(m, 40 * m.mesh_period, 2e-5, "rk4"), transient_cycles=8)
            amp[kloop, e] = res.amplitudes["mesh_force.L.amplitude"]
    assert abs(amp[0.0, 30e-6] / amp[0.0, 0.0] - 1) < 0.1
    assert amp[1e4, 30e-6] > 3 * amp[1e4, 0.0]


def test_stagger_drives_axial_shuttling(baseline_path):
    """Apex-aligned helices: axial mesh forces cancel, no axial motion.  Half-pitch stagger: the
    left/right stiffness ripples are out of phase and the pinion shuttles axially (notes §5)."""
    from femgear.scene import load_scene
    from femgear.system.dynamics import build_model, simulate
    from femgear.system.dynamics.response import analyse

    z = {}
    for stagger in (0.0, 0.5):
        scene = load_scene(baseline_path, [f"pair.stagger={stagger}"])
        m = build_model(build_case(scene), "lumped", stiffness="contact-line")
        res = analyse(simulate(m, 30 * m.mesh_period, m.mesh_period / 200, "rk4"), transient_cycles=15)
        z[stagger] = res.amplitudes["pinion.displacement.z"]
    assert z[0.0] < 1e-15
    assert z[0.5] > 1e-9


def test_timoshenko_level_runs_and_carries_the_torque(timoshenko, baseline_scene):
    from femgear.system.dynamics import simulate, stability_limit
    from femgear.system.dynamics.response import analyse

    assert stability_limit(timoshenko) > 1e-5                     # the paper's step is admissible
    res = analyse(simulate(timoshenko, 20 * timoshenko.mesh_period, 1e-5, "rk4"), transient_cycles=10)
    expected = baseline_scene.operating.torque / (2 * timoshenko.pair.rb1 * math.cos(timoshenko.pair.beta_b))
    assert abs(res.amplitudes["mesh_force.L.mean"] / expected - 1) < 0.02   # friction shifts it slightly
    assert np.isfinite(res.displacement).all()


def test_rayleigh_damping_leaves_the_free_rotation_undamped(lumped):
    """Identity: the rigid rotation of the gear train (kernel of the mean stiffness) feels no
    damping force (bearing dashpots do not act on θz, the Rayleigh mass term is projected off it),
    while every flexible mode keeps its modal damping a0 + a1 ω² (mass-normalised)."""
    from scipy.linalg import eigh

    w2, phi = eigh(lumped.mean_stiffness_matrix(), lumped.M)
    rigid = phi[:, w2 <= 1e-6 * w2.max()]
    assert rigid.shape[1] == 1
    assert np.linalg.norm(lumped.C @ rigid) < 1e-12 * np.linalg.norm(lumped.C)
    a0, _ = lumped.rayleigh
    flex = phi[:, w2 > 1e-6 * w2.max()]
    c_modal = np.diag(flex.T @ lumped.C @ flex)
    assert np.all(c_modal >= a0 * (1 - 1e-9))                 # mass term a0 on every flexible mode (+ K, bearings)


def test_ltca_excitation_enters_as_the_drive_flank_deviation(baseline_scene):
    """An ``ltca`` stiffness carries e_s = LTE − F_s/k_s: the model's drive threshold moves by
    e_s(φ) (N = k_s (G q − b − e_s)), and coupling deviations add to it, not replace it."""
    from femgear.system.dynamics import MeshDeviation, build_model, with_deviation

    n = 64
    ph = np.arange(n) / n
    k = 4e8 * (1 + 0.1 * np.cos(2 * np.pi * ph))
    e = 2e-6 * np.sin(2 * np.pi * ph) ** 2

    class FakeLTCA:                 # the MeshStiffness interface the ltca level returns
        level = "ltca"
        ltca = SimpleNamespace(excitation={"e_left": e, "e_right": e, "k_secant_left": k, "k_secant_right": k},
                               resolved_orders=None)

        def __call__(self, phase):
            from femgear.system.dynamics.mesh import periodic_interp

            kk = periodic_interp(k, np.asarray(phase))
            return kk, kk

    m = build_model(build_case(baseline_scene), "lumped", stiffness=FakeLTCA(), friction=0.0)
    # the tables are resampled by FFT onto a finer grid (k and e here are trigonometric: exact)
    nf = m.deviation.drive.shape[1]
    ef = 2e-6 * np.sin(2 * np.pi * np.arange(nf) / nf) ** 2
    assert nf >= n and np.allclose(m.deviation.drive, [ef, ef], atol=1e-15) and np.allclose(m.deviation.coast, [ef, ef])
    assert np.allclose(m.stiffness.k_left, 4e8 * (1 + 0.1 * np.cos(2 * np.pi * np.arange(nf) / nf)), rtol=1e-12)
    i = 16                                            # φ = 1/4: e = 2 µm
    x = m.backlash + e[i] + 1e-6
    q = np.linalg.pinv(m.G) @ np.array([x, x])
    N = m.mesh_forces(np.array(i / n / m.mesh_frequency), q, np.zeros(m.n))[1]
    assert np.allclose(N, m.stiffness(np.array(i / n))[0] * 1e-6, rtol=1e-6)
    worn = with_deviation(m, MeshDeviation(drive=np.full((2, n), 1e-6), coast=np.zeros((2, n))))
    assert np.allclose(worn.deviation.drive, [ef + 1e-6, ef + 1e-6]) and np.allclose(worn.deviation.coast, [ef, ef])
