"""The contact fast path run whole mesh periods at once (femgear.system.dynamics.expo_scan) is the step-by-step
loop reassociated: the same states to round-off, with friction, through contact loss and back."""

import numpy as np
import pytest

import femgear.system.dynamics.expo as expo_mod
from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import build_model, simulate


@pytest.fixture(scope="module")
def friction_model(baseline_path):
    """The scene's model at 100 rpm with its friction (the main job's dynamics)."""
    return build_model(build_case(load_scene(baseline_path, ["operating.speed_rpm=100.0"])))


def _both(model, cycles, **kw):
    T = model.mesh_period
    out = {}
    for scan in (False, True):
        expo_mod.SCAN = scan
        try:
            out[scan] = simulate(model, cycles * T, T / 430, "expo", substeps=3, **kw)
        finally:
            expo_mod.SCAN = True
    return out[False], out[True]


def _close(a, b, rtol=1e-9):
    for x, y in ((a.q, b.q), (a.v, b.v)):
        assert x.shape == y.shape
        assert np.max(np.abs(x - y)) <= rtol * np.max(np.abs(x)), np.max(np.abs(x - y)) / np.max(np.abs(x))


def test_scan_equals_step_by_step_with_friction(friction_model):
    assert friction_model.mu > 0
    step, scan = _both(friction_model, 6.5, record_from=2 * friction_model.mesh_period)
    assert step.info["scanned_steps"] == 0 and scan.info["scanned_steps"] == 6 * 430   # the tail by steps
    assert scan.info["contact_switches"] == step.info["contact_switches"] == 0
    _close(step, scan)


def test_scan_hands_over_at_contact_loss_and_back(friction_model):
    """A kick that opens the backlash in the first periods: the scan stops at the first open step, the loop
    steps through the impacts, and the scan takes over again once contact holds (same states as stepping)."""
    m = friction_model
    q0 = m.static_state()
    v0 = np.random.default_rng(1).normal(size=m.n) * 2.0 / np.sqrt(np.diag(m.M) / np.diag(m.M).mean())
    step, scan = _both(m, 12.0, q0=q0, v0=v0)
    assert step.info["contact_switches"] > 0
    assert scan.info["contact_switches"] == step.info["contact_switches"]
    assert 0 < scan.info["scanned_steps"] < 12 * 430
    _close(step, scan, rtol=1e-7)   # each impact amplifies the reassociation's round-off (1.2e-8 measured)
