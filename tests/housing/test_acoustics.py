"""ERP and the ISO/TS 7849 arithmetic against the worked examples they are published with."""

import numpy as np

from femgear.physics.housing import acoustics as ac

BANDS = np.array([125.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0])


def test_iso_ts_7849_worked_example_to_its_printed_digits():
    """The phonometry project's ISO/TS 7849-2 example report (github.com/jmrplens/phonometry,
    docs/devices/emission/vibration-sound-power.md, 'EXAMPLE-7849': a 1.6 m² steel gearbox casing, octave bands
    125 Hz – 4 kHz, L_v = 78/82/85/83/79/74 dB re 5e-8 m/s, radiation factor 0.20/0.45/0.75/0.95/1.00/1.00):
    L_W = 73.2/80.7/85.9/84.9/81.2/76.2 dB, L_WA = 88.7 dB(A), total 90.0 dB re 1 pW."""
    lv = np.array([78.0, 82.0, 85.0, 83.0, 79.0, 74.0])
    sigma = np.array([0.20, 0.45, 0.75, 0.95, 1.00, 1.00])
    lw = ac.sound_power_level(lv, 1.6, sigma)
    assert np.round(lw, 1).tolist() == [73.2, 80.7, 85.9, 84.9, 81.2, 76.2]
    a = np.array([ac.A_WEIGHTING_OCTAVES[f] for f in BANDS])
    assert round(float(ac.total_level(lw + a)), 1) == 88.7
    assert round(float(ac.total_level(lw)), 1) == 90.0


def test_iso_ts_7849_calibration_example():
    """ISO/TS 7849-1's calibration example (quoted by the same source): 9.81 m/s² at 100 Hz is L_v = 106.9 dB."""
    assert round(ac.velocity_level_from_acceleration(9.81, 100.0), 1) == 106.9


def test_erp_is_the_iso_level_with_unit_radiation_efficiency():
    """ERP = ½ Z_c Σ A |v̂|² gives L_W = 10 lg(ERP/1 pW) = L_v + 10 lg S + 10 lg(Z_c/400) of the area-weighted mean
    square velocity (σ = 1) for any surface."""
    rng = np.random.default_rng(3)
    area = rng.uniform(1e-4, 1e-3, 200)
    v = rng.normal(size=200) + 1j * rng.normal(size=200)
    v *= 1e-4
    erp = ac.equivalent_radiated_power(area, v, 411.0)
    mean_square = np.sum(area * 0.5 * np.abs(v) ** 2) / area.sum()
    assert np.isclose(ac.power_level(erp), ac.sound_power_level(ac.velocity_level(mean_square), area.sum()), atol=1e-10)


def test_a_weighting_closed_form_matches_the_octave_table():
    """IEC 61672-1: its closed form at the exact base-10 octave mid-band frequencies 1000·10^(3k/10) Hz rounds to
    the standard's one-decimal table (within 0.05 dB)."""
    f = 1000.0 * 10.0 ** (0.3 * np.arange(-5, 5))
    assert np.allclose(ac.a_weighting(f), list(ac.A_WEIGHTING_OCTAVES.values()), atol=0.05)
    assert abs(ac.a_weighting(np.array([1000.0]))[0]) < 1e-2
