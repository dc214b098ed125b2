"""Slender elliptic contacts: rectangular-cell kernel, stretched grids, Hertz ellipse, NVM.

Reference values: /work/shared/notes/ehl_extensions.md ("Verification tests" 1-4), the
Love (1929) rectangle integral checked against brute-force quadrature here."""

import numpy as np
import pytest
from scipy.integrate import quad

from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core.domain import default_domain, hertz_ellipse
from femgear.physics.ehl.core.elastic import PointDeflection, cell_influence
from femgear.physics.ehl.core.grid import Domain, Grid
from femgear.physics.ehl.point import solve_point


def _quad(dx, dy, hx, hy):
    """(2/pi^2) iint 1/r over the hx x hy cell centred at (dx, dy) by quadrature: the inner
    integral over y in closed form (asinh), the outer one by adaptive quadrature (split at
    the singular line x = 0 when the cell holds it). Independent of Love's corner formula."""
    y0, y1 = dy - hy / 2, dy + hy / 2

    def inner(x):
        ax = max(abs(x), 1e-300)
        return np.arcsinh(y1 / ax) - np.arcsinh(y0 / ax)

    x0, x1 = dx - hx / 2, dx + hx / 2
    pts = [0.0] if x0 < 0.0 < x1 else None
    val = quad(inner, x0, x1, points=pts, epsabs=1e-15, epsrel=1e-13, limit=400)[0]
    return 2.0 / np.pi**2 * val


@pytest.mark.parametrize("dx, dy, hx, hy, love", [
    (0.0, 0.0, 1.0, 1.0, 3.525494),   # 4 ln(1 + sqrt 2)
    (1.0, 0.0, 1.0, 5.0, 3.389623),
    (3.0, 7.0, 1.0, 12.0, 1.847045),
])
def test_rectangular_cell_matches_love_and_quadrature(dx, dy, hx, hy, love):
    k = float(cell_influence(np.array(dx), np.array(dy), hx, hy))
    assert k / (2.0 / np.pi**2) == pytest.approx(love, abs=6e-7)  # the notes give 6 decimals
    assert k == pytest.approx(_quad(dx, dy, hx, hy), rel=1e-9)


def test_rectangular_cells_brute_force_grid():
    rng = np.random.default_rng(1)
    for _ in range(6):
        hx, hy = 0.1, 0.1 * rng.uniform(0.125, 12.0)
        dx, dy = hx * rng.integers(0, 5), hy * rng.integers(0, 5)
        assert float(cell_influence(np.array(dx), np.array(dy), hx, hy)) == pytest.approx(
            _quad(dx, dy, hx, hy), rel=1e-9)


def test_square_cells_bit_identical():
    """hy omitted (square cells) and hy = h give the same bits; the default grid/domain of
    the circular contact are unchanged."""
    dx, dy = np.meshgrid(np.arange(5) * 0.1, np.arange(4) * 0.1)
    assert np.array_equal(cell_influence(dx, dy, 0.1), cell_influence(dx, dy, 0.1, 0.1))
    assert np.array_equal(PointDeflection(9, 7, 0.2).K, PointDeflection(9, 7, 0.2, None).K)
    assert default_domain(1.0) == Domain(-4.5, 1.5, -3.0, 3.0)
    g = Grid.build(Domain(), 2)
    assert g.hy is None and g.dy == g.h and np.array_equal(g.y, Grid.build(Domain(), 2, aspect=None).y)


def test_hertz_ellipse_table():
    for lam, a, b, ph in ((0.5, 0.886, 1.404, 0.804), (0.1, 0.648, 2.918, 0.529),
                          (0.02, 0.471, 5.688, 0.373)):
        ea, eb, eph = hertz_ellipse(lam)
        assert (ea, eb, eph) == pytest.approx((a, b, ph), abs=6e-4)
    assert hertz_ellipse(1.0) == (1.0, 1.0, 1.0)


@pytest.mark.parametrize("n, centre", [(129, 0.43436)])
def test_dry_elliptic_hertz_deflection(n, centre):
    """lambda = 0.02 on hy/hx = b/a = 12.07: the Hertz pressure gives the Hertz approach
    (exact 0.43451) and a flat gap inside the contact (second order)."""
    lam = 0.02
    a, b, ph = hertz_ellipse(lam)
    x, y = np.linspace(-1.6 * a, 1.6 * a, n), np.linspace(-1.6 * b, 1.6 * b, n)
    X, Y = np.meshgrid(x, y)
    P = ph * np.sqrt(np.maximum(1 - (X / a) ** 2 - (Y / b) ** 2, 0))
    D = PointDeflection(n, n, x[1] - x[0], y[1] - y[0]).apply(P)
    assert D[n // 2, n // 2] == pytest.approx(centre, abs=2e-5)
    gap = (X**2 / 2 + lam * Y**2 / 2 + D)[(X / a) ** 2 + (Y / b) ** 2 < 0.81]
    assert gap.max() - gap.min() < 4e-4
    assert P.sum() * (x[1] - x[0]) * (y[1] - y[0]) == pytest.approx(2 * np.pi / 3, rel=3e-4)


def test_stretched_grid_follows_ellipse():
    lam = 0.1
    a, b, _ = hertz_ellipse(lam)
    g = Grid.build(default_domain(lam), 3)
    assert g.dy / g.h == pytest.approx(b / a)
    # as many nodes across the contact in Y as in X
    assert np.sum(np.abs(g.y) < b) == pytest.approx(np.sum(np.abs(g.x) < a), abs=2)


def test_elliptic_hc_against_nvm():
    """Validation: lambda = 0.2 at (M, L) = (100, 10) on 65^2 nodes, inside NVM's range."""
    r = solve_point(100.0, 10.0, ratio=0.2, level=2)
    assert r.Hc == pytest.approx(float(nvm_central(100.0, 10.0, 0.2)), rel=0.05)
