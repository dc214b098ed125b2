"""Excitation sources: rates are derivatives, random errors are seeded and bounded, gap function."""

import numpy as np

from femgear.physics.excitation import (
    Eccentricity,
    ProfileError,
    RandomError,
    Unbalance,
    contact_indicator,
    gap_function,
)


def _fd(f, t, h=1e-7):
    return (f(t + h) - f(t - h)) / (2 * h)


def test_rates_are_time_derivatives():
    t = np.linspace(0.001, 0.02, 37)
    p = ProfileError(1e-6, 258.3, orders=4, phase=0.3, mesh_offset=0.25)
    assert np.allclose(p.rate(t), _fd(p.value, t), rtol=1e-6, atol=1e-9)
    e = Eccentricity(2e-5, -47.7, 0.4)
    assert np.allclose(e.offset_rate(t), _fd(e.offset, t), rtol=1e-6, atol=1e-12)
    r = RandomError(1e-6, 258.3, 31, 34, seed=3)
    tm = (np.arange(20) + 0.37) / 258.3                       # away from the kinks at whole mesh cycles
    assert np.allclose(r.rate(tm), _fd(r.value, tm), rtol=1e-5, atol=1e-12)


def test_random_error_seeded_bounded_and_periodic_in_the_hunting_period():
    a = RandomError(2e-6, 100.0, 31, 34, seed=7)
    b = RandomError(2e-6, 100.0, 31, 34, seed=7)
    c = RandomError(2e-6, 100.0, 31, 34, seed=8)
    t = np.linspace(0, 0.5, 1001)
    assert np.array_equal(a.value(t), b.value(t)) and not np.array_equal(a.value(t), c.value(t))
    assert np.all(np.abs(a.value(t)) <= 4e-6) and np.max(np.abs(a.value(t))) > 2e-6   # pair: sum of two teeth
    # at whole mesh cycles the pair error is the sum of the two teeth's deviations (not their mean)
    k = np.arange(40)
    assert np.allclose(a.value(k / 100.0), 2e-6 * (a._dev1[k % 31] + a._dev2[k % 34]), rtol=1e-9, atol=1e-18)
    hunting = 31 * 34 / 100.0                                  # z1 z2 mesh cycles (gcd 1)
    assert np.allclose(a.value(t), a.value(t + hunting), atol=1e-15)


def test_unbalance_force_magnitude():
    u = Unbalance(1e-4, 52.36)
    F = u.force(np.linspace(0, 0.1, 11))
    assert np.allclose(np.linalg.norm(F, axis=-1), 1e-4 * 52.36**2)


def test_gap_function_dead_zone():
    d = np.array([-3.0, -1.0, 0.0, 0.5, 1.0, 2.5])
    assert np.allclose(gap_function(d, 1.0), [-2.0, 0.0, 0.0, 0.0, 0.0, 1.5])
    assert np.allclose(contact_indicator(d, 1.0), [1, 0, 0, 0, 0, 1])
