"""One-mesh (spur, single-helical) dynamics: mesh mode against the hand formula, the unbalanced axial force,
and the Kahraman–Singh jump of a spur pair with backlash in a speed sweep."""

import math
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels import stiffness as stiffness_levels
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.pem import pem_mesh_stiffness
from femgear.scene import load_scene
from femgear.system.dynamics.one_mesh import (
    MemberData,
    build_one_mesh,
    natural_frequencies,
    simulate_one_mesh,
    static_deflection,
    torsional_mode_hand,
    torsional_sweep,
)

FZG = Path(__file__).resolve().parents[2] / "studies" / "fzg_c14.toml"


@pytest.fixture(scope="module")
def fzg():
    scene = load_scene(FZG, ["physics.stiffness=pem", "stiffness.n_positions=100"])
    return scene, pair_from_scene(scene), stiffness_levels.of(build_case(scene)).k_left


def _members(scene, radial, axial):
    return tuple(MemberData(m.mass, m.inertia, radial, axial, bearing_span=0.1) for m in (scene.pinion, scene.gear))


def test_spur_mesh_mode_is_the_hand_formula_on_rigid_supports(fzg):
    """f = √(k̄ (r_b1²/I1 + r_b2²/I2))/2π when the supports are rigid (1e13 N/m)."""
    scene, pair, k = fzg
    model = build_one_mesh(pair, _members(scene, 1e13, 1e13), k, 200.0)
    hand = torsional_mode_hand(pair, scene.pinion.inertia, scene.gear.inertia, float(k.mean()))
    f = natural_frequencies(model)
    assert f[np.argmin(np.abs(f - hand))] == pytest.approx(hand, rel=1e-3)
    assert f.size == 11   # 12 DOF less the free rotation


def test_single_helical_axial_force_on_thrust_bearings():
    """Static: F = T1/(r_b1 cos β_b) and z_i = ∓F sin β_b / k_ax,i (the unbalanced axial force); spur: z = 0."""
    base = dict(z1=20, z2=40, m_n=3e-3, alpha_n=math.radians(20), b=0.03, x1=0.0, x2=0.0)
    mems = (MemberData(1.0, 1e-3, 5e8, 2e8), MemberData(3.0, 8e-3, 5e8, 4e8))
    for kind, beta in (("single-helical", math.radians(20)), ("spur", 0.0)):
        pair = GearPair.from_parameters(beta=beta, kind=kind, **base)
        model = build_one_mesh(pair, mems, np.full(8, 4e8), 150.0)
        q = static_deflection(model)
        F = model.k_mean * (model.g @ q)
        assert F == pytest.approx(150.0 / (pair.rb1 * math.cos(pair.beta_b)), rel=1e-9)
        Fa = F * math.sin(pair.beta_b)
        assert q[2] == pytest.approx(-Fa / 2e8, abs=1e-15) and q[8] == pytest.approx(Fa / 4e8, abs=1e-15)
        if kind == "spur":
            assert q[2] == 0 and q[8] == 0 and q[4] == 0


def _sweep(pair, k, scene, torque, direction, ratios, backlash=50e-6):
    fn = torsional_mode_hand(pair, scene.pinion.inertia, scene.gear.inertia, float(k.mean()))
    return torsional_sweep(pair, k, scene.pinion.inertia, scene.gear.inertia, torque, ratios * fn, backlash=backlash,
                           direction=direction, cycles=40, measure=10, steps_per_period=48)


def test_kahraman_singh_jump_with_backlash(fzg):
    """Light load (20 N m): the teeth separate near resonance; the down-sweep stays on the upper (impacting)
    branch below f_n where the up-sweep is on the lower one, and the up-sweep jumps (softening hysteresis)."""
    scene, pair, k = fzg
    ratios = np.linspace(0.7, 1.0, 13)
    up, down = (_sweep(pair, k, scene, 20.0, d, ratios) for d in ("up", "down"))
    a_up = up.amplitude[np.argsort(up.mesh_frequency)]
    a_down = down.amplitude[np.argsort(down.mesh_frequency)]
    assert np.max(a_down / a_up) > 1.8                      # two branches at the same speed
    assert np.max(a_up[1:] / a_up[:-1]) > 1.5               # the jump on the way up
    assert np.max(down.contact_loss) > 0.3 and up.contact_loss[0] == 0


def test_no_jump_without_backlash(fzg):
    """Control: the same sweep without backlash is a linear parametric system: up and down sweeps agree."""
    scene, pair, k = fzg
    ratios = np.linspace(0.7, 1.0, 7)
    up, down = (_sweep(pair, k, scene, 20.0, d, ratios, backlash=0.0) for d in ("up", "down"))
    np.testing.assert_allclose(up.amplitude[np.argsort(up.mesh_frequency)],
                               down.amplitude[np.argsort(down.mesh_frequency)], rtol=0.02)


def test_bad_input(fzg):
    scene, pair, k = fzg
    double = GearPair.from_parameters(z1=20, z2=40, m_n=3e-3, alpha_n=0.35, beta=0.3, b=0.02, x1=0, x2=0)
    with pytest.raises(ValueError, match="one mesh"):
        build_one_mesh(double, _members(scene, 1e9, 1e9), k, 100.0)
    with pytest.raises(ValueError, match="positive"):
        build_one_mesh(pair, _members(scene, 1e9, 1e9), -k, 100.0)
    with pytest.raises(ValueError, match="direction"):
        torsional_sweep(pair, k, 1e-3, 1e-3, 10.0, np.array([100.0]), 0.0, direction="sideways")


@pytest.mark.parametrize("kind", ["single-helical", "spur"])
def test_dynamic_run_axial_force_and_mean_mesh_force(kind):
    """Time response with PEM TVMS below the first mode: mean mesh force = F_bn (momentum balance); the single
    helix's pinion rides at z = −F_bn sin β_b / k_ax on its thrust bearing; a spur pair never moves axially."""
    base = dict(z1=20, z2=40, m_n=3e-3, alpha_n=math.radians(20), b=0.03, x1=0.0, x2=0.0)
    pair = GearPair.from_parameters(beta=math.radians(20) if kind != "spur" else 0.0, kind=kind, **base)
    mems = (MemberData(1.0, 1e-3, 5e8, 2e8, 500.0, 300.0), MemberData(3.0, 8e-3, 5e8, 4e8, 500.0, 300.0))
    k = pem_mesh_stiffness(pair, 210e9, 0.3, 60).k_left
    model = build_one_mesh(pair, mems, k, 150.0)
    fm = 0.8 * natural_frequencies(model)[0]
    r = simulate_one_mesh(model, fm, periods=30, record=10)
    F0 = 150.0 / (pair.rb1 * math.cos(pair.beta_b))
    assert r.mesh_force.mean() == pytest.approx(F0, rel=1e-3)
    assert r.axial(0).mean() == pytest.approx(-F0 * math.sin(pair.beta_b) / 2e8, rel=1e-3, abs=1e-15)
    if kind == "spur":
        assert not np.any(r.axial(0)) and not np.any(r.axial(1))
    else:
        assert np.ptp(r.axial(0)) > 0          # the TVMS shuttles the pinion axially


def test_simulation_refuses_unstable_step(fzg):
    scene, pair, k = fzg
    model = build_one_mesh(pair, _members(scene, 1e13, 1e13), k, 200.0)
    with pytest.raises(ValueError, match="stability limit") as info:
        simulate_one_mesh(model, 500.0, steps_per_period=10)
    needed = int(str(info.value).rsplit("≥ ", 1)[1])
    simulate_one_mesh(model, 500.0, periods=1, record=1, steps_per_period=needed)   # the advice is enough


def test_model_from_an_fzg_case():
    """The FZG C14 scene's case binds to the 12-DOF model; its static mesh force is F_bn."""
    from femgear.case import build_case
    from femgear.system.dynamics.one_mesh import one_mesh_from_case, simulate_case

    case = build_case(load_scene(FZG, ["numerics.dynamics_cycles=12", "numerics.transient_cycles=8",
                                       "numerics.steps_per_mesh_period=120"]))
    model = one_mesh_from_case(case)
    q = static_deflection(model)
    assert model.k_mean * (model.g @ q) == pytest.approx(case.operating.normal_force, rel=1e-9)
    r = simulate_case(case)
    assert r.mesh_force.mean() == pytest.approx(case.operating.normal_force, rel=0.02)
    assert r.t.size == 4 * 120
