"""Tier 3: linearised modal analysis against time-domain resonances."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import build_model
from femgear.system.dynamics.modal import modal_analysis
from femgear.system.dynamics.sweep import peak_frequency, speed_sweep


def test_modal_energy_fractions(lumped, timoshenko):
    for m in (lumped, timoshenko):
        r = modal_analysis(m)
        assert r.frequencies[0] < 1e-3 * r.frequencies[1]            # the free rotation of the train
        kinetic = sum(v for k, v in r.energy.items() if k != "mesh")
        assert np.allclose(kinetic, 1.0, atol=1e-9)                   # fractions add up
        assert np.all((r.energy["mesh"] >= -1e-12) & (r.energy["mesh"] <= 1 + 1e-12))
        assert r.shapes.shape[0] == 24
    # flexible shafts lower the natural frequencies
    assert modal_analysis(timoshenko).frequencies[1] < modal_analysis(lumped).frequencies[1]


def _mesh_modes(model):
    r = modal_analysis(model)
    return r.frequencies[(r.frequencies > 0) & (r.energy["mesh"] > 0.1)]


def test_first_mesh_mode_is_the_resonance_of_a_speed_sweep(baseline_path):
    """DTE RMS over mesh frequency (contact-line TVMS + one profile-error harmonic) peaks within 2 % of
    the first mean-stiffness natural frequency with mesh strain energy."""
    scene = load_scene(baseline_path, ["errors.profile_error=1e-6", "errors.profile_error_orders=1"])
    kw = dict(level="lumped", stiffness="contact-line", friction=0.0)
    f1 = _mesh_modes(build_model(build_case(scene), **kw))[0]
    rpm = np.linspace(0.85, 1.15, 13) * f1 * 60 / scene.pinion.teeth
    sw = speed_sweep(build_case(scene), rpm, cycles=80, measure=30, method="rk4", steps_per_cycle=40, **kw)
    assert abs(peak_frequency(sw.mesh_frequency, sw.dte_rms) / f1 - 1) < 0.02


@pytest.mark.slow
def test_broad_speed_sweep_peaks_at_mesh_modes(baseline_path):
    scene = load_scene(baseline_path, ["errors.profile_error=1e-6", "errors.profile_error_orders=1"])
    kw = dict(level="lumped", stiffness="contact-line", friction=0.0)
    modes = _mesh_modes(build_model(build_case(scene), **kw))
    fm = np.linspace(1500, 8500, 71)
    sw = speed_sweep(build_case(scene), fm * 60 / scene.pinion.teeth, cycles=100, measure=40, method="rk4",
                     steps_per_cycle=40, **kw)
    y = sw.dte_rms
    peaks = [i for i in range(1, y.size - 1) if y[i] > y[i - 1] and y[i] > y[i + 1] and y[i] > 0.2 * y.max()]
    assert len(peaks) >= 2
    for i in peaks:
        f = peak_frequency(sw.mesh_frequency[i - 1:i + 2], y[i - 1:i + 2])
        assert np.min(np.abs(modes - f) / modes) < 0.03, (f, modes)
