"""The LTCA tables as the dynamics sees them: band-limited resampling and the resolved mesh orders."""

import math

import numpy as np
import pytest

from femgear.physics.ltca.cycle import LTCACycle


def test_band_limited_reproduces_a_trigonometric_polynomial_and_adds_no_orders():
    from femgear.system.dynamics.build import band_limited

    def f(ph):
        return 3.0 + 0.5 * np.cos(2 * np.pi * ph + 0.3) + 0.1 * np.sin(2 * np.pi * 7 * ph) + 0.01 * np.cos(2 * np.pi * 20 * ph)

    m, n = 64, 512
    fine = band_limited(f(np.arange(m) / m), n)
    assert np.allclose(fine, f(np.arange(n) / n), atol=1e-12)
    cut = band_limited(f(np.arange(m) / m), n, orders=10)      # order 20 dropped, 0-10 kept exactly
    assert np.allclose(cut, f(np.arange(n) / n) - 0.01 * np.cos(2 * np.pi * 20 * np.arange(n) / n), atol=1e-12)
    spec = np.abs(np.fft.rfft(cut)) / n
    assert spec[11:].max() < 1e-13
    with pytest.raises(ValueError, match="n = 32"):
        band_limited(np.ones(64), 32)


def test_resolved_orders_and_band_limited_ltca_tables(coarse_model, baseline_force):
    """The tables keep the LTCA's harmonics up to the resolved order H and nothing above; e_s likewise."""
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.physics.ltca.level import RESOLUTION_TOLERANCE, resolved_orders
    from femgear.scene.schema import Modifications
    from femgear.system.dynamics.build import ltca_table, tooth_contact_deviation

    mods = Modifications(tip_relief=3e-6, tip_relief_length=2.5e-3, crowning=5e-6)
    H, change = resolved_orders(coarse_model, baseline_force, mods, n_line=8, n_phases=32)
    assert 1 <= H <= 15 and change.size == 15
    assert all(np.median(change[max(0, i - 1):i + 2]) <= RESOLUTION_TOLERANCE for i in range(H - 1))
    res = mesh_cycle(coarse_model, baseline_force, mods, n_phases=32, n_line=8, keep_lines=False)

    class Source:
        ltca = LTCACycle.from_result(res, resolved_orders=H)

    table, dev = ltca_table(Source), tooth_contact_deviation(Source)
    n = table.k_left.size
    for fine, coarse in ((table.k_left, res.k_secant_left), (dev.drive[1], res.excitation()["e_right"])):
        a, b = np.fft.rfft(fine) / n, np.fft.rfft(coarse) / coarse.size
        assert np.allclose(a[:H + 1], b[:H + 1], rtol=1e-9, atol=1e-12 * abs(b[0]) + 1e-30)
        assert np.abs(a[H + 1:]).max() <= 1e-12 * abs(a[0]) + 1e-30
    assert ltca_table(object()) is None and tooth_contact_deviation(object()) is None


def test_rig_measure_is_the_largest_spectral_line_along_the_line_of_action():
    """Two mesh harmonics along the sensor axis plus a component across it: the FFT figure is the larger
    line (zero-to-peak), below the time peaks; the 5 kHz Butterworth passes both lines (≤ 600 Hz)."""
    from studies.paper.rig_conditions import rig_measures

    fm, fs = 258.3, 51_660.0
    t = np.arange(0, 60 / fm, 1 / fs)
    d = np.array([math.sin(0.4), math.cos(0.4), 0.0])
    across = np.array([math.cos(0.4), -math.sin(0.4), 0.0])
    sig = 0.8 * np.sin(2 * np.pi * fm * t) + 0.5 * np.sin(2 * np.pi * 2 * fm * t + 1.0)
    acc = np.zeros((t.size, 4, 3))
    for j in range(4):
        acc[:, j] = np.outer(sig * (1 + 0.1 * j), d) + np.outer(0.3 * np.cos(2 * np.pi * 3 * fm * t), across)
    m = rig_measures(t, acc, d, fm)
    assert m["fft1"] == pytest.approx(0.8 * 1.1, rel=0.01)       # the larger station of point 1
    assert m["fft2"] == pytest.approx(0.8 * 1.3, rel=0.01)
    assert m["peak2"] > m["fft2"] and m["radial2"] >= m["peak2"]


def test_observed_order_recovers_the_order_of_a_power_law():
    """Three levels of f(h) = f* + C h^p with uneven spacing give back p (Roache's observed order)."""
    from studies.ltca.ltca_study import observed_order

    h = [1.0, 0.75, 0.6]
    for p in (0.8, 2.0, 3.1):
        assert observed_order(h, [5.0 + 0.3 * x**p for x in h]) == pytest.approx(p, rel=1e-6)
    assert math.isnan(observed_order(h, [1.0, 1.2, 1.1]))       # oscillating: no asymptotic range


def test_too_few_resolved_orders_refine_the_contact_lines(coarse_model, baseline_pair, baseline_force, monkeypatch):
    """Fewer than MIN_RESOLVED_ORDERS resolved orders double the points per contact line (the rig's test gear at
    150 N m resolved 1 order with 16 points and 18 with 32); the cycle and its resolution check use the finer lines."""
    import femgear.physics.ltca.analysis as analysis
    import femgear.physics.ltca.level as level
    from femgear.scene.schema import Modifications

    mods = Modifications(tip_relief=3e-6, tip_relief_length=2.5e-3, crowning=5e-6)
    monkeypatch.setattr(analysis, "build_model", lambda *a, **k: coarse_model)
    h4, _ = level.resolved_orders(coarse_model, baseline_force, mods, n_line=4)
    h8, _ = level.resolved_orders(coarse_model, baseline_force, mods, n_line=8)
    monkeypatch.setattr(level, "MIN_RESOLVED_ORDERS", h4 + 1)
    cycle = level.ltca_cycle(baseline_pair, baseline_force, mods, n_line=4)
    assert cycle.n_line >= 8 and cycle.resolved_orders >= min(h8, h4 + 1)
    assert cycle.result.k_secant.size == 64 and cycle.result.n_line == cycle.n_line
    monkeypatch.setattr(level, "MIN_RESOLVED_ORDERS", 1)
    cycle = level.ltca_cycle(baseline_pair, baseline_force, mods, n_line=4)
    assert cycle.n_line == 4 and cycle.resolved_orders == h4
