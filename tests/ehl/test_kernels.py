"""Exactness of the deflection kernels and the rheology derivatives (tier 1/3)."""

import numpy as np
import pytest
from scipy.integrate import dblquad

from femgear.physics.ehl.core.elastic import PointDeflection, cell_influence, line_influence
from femgear.physics.ehl.core.rheology import Rheology


def test_cell_influence_matches_quadrature():
    h = 0.3
    for dx, dy in [(0.7, -0.4), (0.0, 0.9), (1.2, 0.0)]:
        q = dblquad(lambda y, x: 1 / np.hypot(dx - x, dy - y), -h / 2, h / 2, -h / 2, h / 2)[0]
        assert cell_influence(np.array(dx), np.array(dy), h) == pytest.approx(2 / np.pi**2 * q, rel=1e-9)
    # self influence: (2/pi^2) 4 h asinh(1)
    assert cell_influence(np.array(0.0), np.array(0.0), h) == pytest.approx(
        2 / np.pi**2 * 4 * h * np.arcsinh(1.0), rel=1e-12)


def test_dcfft_equals_direct_summation():
    rng = np.random.default_rng(1)
    nx, ny, h = 13, 9, 0.2
    op = PointDeflection(nx, ny, h)
    P = rng.random((ny, nx))
    idx = np.arange(nx * ny)
    direct = op.dense(idx) @ P.ravel()
    assert np.allclose(op.apply(P).ravel(), direct, rtol=0, atol=1e-13)


def test_point_deflection_of_hertz_pressure():
    """(2/pi^2) iint sqrt(1-r'^2)/|r-r'| = 1 - r^2/2 inside the contact (Johnson 1985)."""
    n = 129
    x = np.linspace(-2, 2, n)
    X, Y = np.meshgrid(x, x)
    P = np.sqrt(np.maximum(1 - X**2 - Y**2, 0))
    D = PointDeflection(n, n, x[1] - x[0]).apply(P)
    r2 = X**2 + Y**2
    inside = r2 < 0.81
    assert np.abs(D[inside] - (1 - r2[inside] / 2)).max() < 2e-3


def test_line_deflection_of_hertz_pressure():
    """-(1/pi) int ln|x-s| sqrt(1-s^2) ds = -x^2/2 + const for |x| < 1."""
    x = np.linspace(-3, 3, 801)
    P = np.sqrt(np.maximum(1 - x**2, 0))
    D = line_influence(x, x[1] - x[0]) @ P
    inside = np.abs(x) < 0.9
    assert np.ptp(D[inside] + x[inside] ** 2 / 2) < 1e-4  # O(h^2) cell quadrature


@pytest.mark.parametrize("rheo", [
    Rheology(8.0),
    Rheology(8.0, viscosity="roelands", ph=1.0e9, z=0.6),
    Rheology(8.0, viscosity="roelands", ph=0.5e9, compressible=True),
])
def test_rheology_derivatives(rheo):
    P = np.linspace(0.05, 2.0, 7)
    H = np.linspace(0.1, 0.5, 7)
    e = 1e-7
    le, dle = rheo.log_eta(P)
    assert np.allclose((rheo.log_eta(P + e)[0] - le) / e, dle, rtol=1e-5)
    rho, drho = rheo.density(P)
    assert np.allclose((rheo.density(P + e)[0] - rho) / e, drho, rtol=1e-4, atol=1e-9)
    eps, dP, dH = rheo.epsilon(P, H, 0.3)
    assert np.allclose((rheo.epsilon(P + e, H, 0.3)[0] - eps) / e, dP, rtol=1e-4)
    assert np.allclose((rheo.epsilon(P, H + e, 0.3)[0] - eps) / e, dH, rtol=1e-4)


def test_roelands_has_barus_slope_at_zero_pressure():
    r = Rheology(10.0, viscosity="roelands", ph=1e9, z=0.68)
    _, d = r.log_eta(np.array([1e-9]))
    assert d[0] == pytest.approx(10.0, rel=1e-6)
    # and is below Barus at high pressure (z < 1)
    assert r.log_eta(np.array([2.0]))[0][0] < 20.0


def test_dowson_higginson_limit():
    r = Rheology(1.0, ph=1e12, compressible=True)
    rho, _ = r.density(np.array([0.0, 1.0]))
    assert rho[0] == 1.0
    assert rho[1] == pytest.approx(1.34, rel=1e-3)  # p -> infinity: 1.34
