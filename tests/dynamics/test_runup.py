"""Tier 2: run-up — the ramp's kinematics, its prescribed inputs, order tracking, and a slow ramp against the
stepped steady state (issue 42 item 4)."""

import math

import numpy as np
import pytest

from femgear.case import build_case
from femgear.system.dynamics.family import SpeedFamily
from femgear.system.dynamics.harmonic import harmonic_response
from femgear.system.dynamics.modal import modal_analysis, resonance_marks
from femgear.system.dynamics.runup import Ramp, RampInputs, RunUp, order_track, simulate_runup
from femgear.system.dynamics.simulation import inputs


@pytest.mark.parametrize("args", [(0.0, 10.0, 1.0), (100.0, 90.0, 1.0), (100.0, 100.0, 1.0), (100.0, 200.0, 0.0),
                                  (100.0, math.inf, 1.0)])
def test_ramp_refuses_what_is_not_a_run_up(args):
    with pytest.raises(ValueError):
        Ramp(*args)


def test_ramp_revolutions_integrate_the_speed():
    r = Ramp(600.0, 1800.0, 2.0)
    ts = 0.1
    t = np.linspace(0.0, 2.5, 101)
    rev = r.revolutions(t, ts)
    assert math.isclose(r.revolutions(np.array(ts + 2.0), ts), (600 * ts + 0.5 * (600 + 1800) * 2.0) / 60)
    mid = 0.5 * (t[1:] + t[:-1])                          # the kinks (0.1 s, 2.1 s) lie on the grid
    assert np.allclose(np.diff(rev) / np.diff(t) * 60, r.speed(mid, ts), rtol=1e-12)


@pytest.fixture(scope="module")
def family(baseline_scene):
    return SpeedFamily(build_case(baseline_scene))


def test_ramp_inputs_are_the_model_inputs_at_constant_speed(family):
    """A ramp of 1e-9 relative speed change reads, at every time, the inputs of the model at that speed."""
    ramp = Ramp(1200.0, 1200.0 * (1 + 1e-9), 0.05)
    inp = RampInputs(family, ramp)
    t = np.linspace(0.0, 0.05, 77)
    got, ref = inp(t), inputs(inp.ref, t) + (inp.ref.backlash_at(t),)
    for a, b in zip(got, ref):
        assert np.allclose(a, b, rtol=1e-6, atol=1e-6 * np.abs(b).max())


def test_order_tracking_reads_a_chirp_at_its_order():
    """A signal of a fixed pinion order with an amplitude growing with speed is read on its bin at the blocks'
    speeds (Hanning window, amplitude-corrected), and nothing at other orders."""
    z1, ts, ramp = 17, 0.0, Ramp(600.0, 1200.0, 3.0, settle_cycles=0.0)
    t = np.arange(0.0, 3.0, 2e-5)
    rev = ramp.revolutions(t, ts)
    speed = ramp.speed(t, ts)
    run = RunUp(t=t, speed=speed, pinion_revolutions=rev, mesh_force=np.zeros((t.size, 2)), dte=np.zeros(t.size),
                bearing_force=np.zeros((t.size, 4, 3)), settle_time=ts, ramp_end=3.0, teeth=z1, dt=2e-5, steps=t.size,
                seconds=0.0)
    x = (speed / 1000.0) * np.cos(2 * np.pi * 2 * z1 * rev) + 0.3 * np.sin(2 * np.pi * 3.5 * rev)
    m = order_track(run, x, revolutions=4)
    assert np.allclose(m.cuts[:, 1], m.speed / 1000.0, rtol=2e-3)         # mesh order 2 = pinion order 2 z1
    assert np.all(m.cuts[:, [0, 2, 3]] < 1e-3)
    k = np.argmin(np.abs(m.orders - 3.5))
    assert np.allclose(m.amplitude[:, k], 0.3, rtol=2e-3)


def test_slow_ramp_matches_the_stepped_steady_state(family):
    """A slow run-up (1150 → 1300 rpm in 0.8 s, baseline, away from the 2.85 kHz mode's order-2…4 resonances at
    1379, 1839 and 2759 rpm) gives, on every block, mesh orders 1-4 of the mesh force and of the bearing loads within
    5 % of the harmonic balance at the block's speed."""
    model = family.at(1150.0)
    mo = modal_analysis(model)
    rpm_per_hz = 1150.0 / model.mesh_frequency
    near = [f * rpm_per_hz for f, _, _ in resonance_marks(mo.frequencies, mo.energy["mesh"], 0.0, 1e5)]
    assert min(abs(r - x) for r in near for x in (1150.0, 1300.0)) > 70.0
    run = simulate_runup(family, Ramp(1150.0, 1300.0, 0.8))
    force, bearing = order_track(run, run.mesh_force), order_track(run, run.bearing_force)
    assert force.speed.size >= 4
    k = np.arange(1, 5)
    for i, rpm in enumerate(force.speed):
        hb = harmonic_response(family.at(rpm))
        steady = hb.order_amplitudes(hb.mesh_force, k)                        # (2, 4)
        assert np.allclose(force.cuts[i].T, steady, rtol=0.05)
        sb = hb.order_amplitudes(hb.bearing_force, k)                         # (4, 3, 4)
        big = sb > 0.05 * sb.max()
        assert np.allclose(np.moveaxis(bearing.cuts[i], 0, -1)[big], sb[big], rtol=0.05)
