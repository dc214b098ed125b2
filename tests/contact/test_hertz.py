"""Hertz contact against closed forms (tier 3) and elliptic-integral tables (tier 4)."""

import math

import pytest
from scipy import integrate
from scipy.special import ellipe, ellipk

from femgear.physics.contact import (
    ellipticity_exact,
    ellipticity_hamrock_brewe,
    hertz_line,
    hertz_point,
    reduced_modulus,
)

E_STEEL = reduced_modulus(210e9, 0.3)


def test_reduced_modulus():
    assert E_STEEL == pytest.approx(210e9 / (1 - 0.09), rel=1e-15)
    assert reduced_modulus(200e9, 0.3, 70e9, 0.33) == pytest.approx(2 / (0.91 / 200e9 + (1 - 0.33**2) / 70e9))


def test_line_contact_closed_form():
    w, R = 84332.0, 0.0123
    h = hertz_line(w, R, E_STEEL)
    b = math.sqrt(8 * w * R / (math.pi * E_STEEL))
    assert h.half_width == pytest.approx(b, rel=1e-12)
    assert h.max_pressure == pytest.approx(E_STEEL * math.sqrt(w / (E_STEEL * R) / (2 * math.pi)), rel=1e-12)
    # the semi-elliptical pressure carries the load
    assert math.pi * h.max_pressure * h.half_width / 2 == pytest.approx(w, rel=1e-12)


def test_circular_contact_closed_form():
    F, R = 100.0, 0.01
    h = hertz_point(F, R, None, E_STEEL)
    a = (3 * F * R / (2 * E_STEEL)) ** (1 / 3)
    assert h.a == pytest.approx(a, rel=1e-6) and h.b == pytest.approx(a, rel=1e-6)
    assert h.max_pressure == pytest.approx(3 * F / (2 * math.pi * a * a), rel=1e-6)
    assert h.approach == pytest.approx(a * a / R, rel=1e-6)


def test_tabulated_complete_elliptic_integrals():
    """Abramowitz & Stegun, Table 17.1 (parameter m)."""
    assert ellipk(0.5) == pytest.approx(1.854074677301372, rel=1e-14)
    assert ellipe(0.5) == pytest.approx(1.350643881047675, rel=1e-14)
    assert ellipk(0.9) == pytest.approx(2.578092113348173, rel=1e-14)
    assert ellipe(0.9) == pytest.approx(1.104774732704073, rel=1e-14)


def test_ellipticity_for_m_one_half():
    """k = √2 (m = 1/2): R_M/R_m = (2E − K)/(K − E) with the tabulated K(0.5), E(0.5)."""
    K, E = 1.854074677301372, 1.350643881047675
    ratio = (2 * E - K) / (K - E)
    assert ellipticity_exact(ratio) == pytest.approx(math.sqrt(2), rel=1e-10)


@pytest.mark.parametrize("ratio", [1.5, 4.0, 10.0, 25.0])  # the fit's stated range k ≤ 10
def test_hamrock_brewe_fit_is_a_few_percent_from_exact(ratio):
    assert ellipticity_hamrock_brewe(1.0, ratio) == pytest.approx(ellipticity_exact(ratio), rel=0.03)


def test_elliptical_contact_satisfies_boussinesq_displacement():
    """The surface displacement of the Hertz pressure equals δ − x²/2R_x − y²/2R_y inside the ellipse.

    (2/(πE')) ∬ p/r dA is integrated in polar coordinates around each field point
    (no singularity), independently of the closed-form sizes.
    """
    F, Rx, Ry = 200.0, 0.01, 0.04
    h = hertz_point(F, Rx, Ry, E_STEEL)
    a, b, ph = h.a, h.b, h.max_pressure
    assert h.ellipticity > 1

    def displacement(x0, y0):
        def radial(theta):
            c, s = math.cos(theta), math.sin(theta)
            # solve (x0 + r c)²/a² + (y0 + r s)²/b² = 1 for r > 0
            A = c * c / a**2 + s * s / b**2
            B = 2 * (x0 * c / a**2 + y0 * s / b**2)
            C = x0**2 / a**2 + y0**2 / b**2 - 1
            rmax = (-B + math.sqrt(B * B - 4 * A * C)) / (2 * A)
            def f(r):
                return ph * math.sqrt(max(0.0, 1 - (x0 + r * c) ** 2 / a**2 - (y0 + r * s) ** 2 / b**2))

            return integrate.quad(f, 0, rmax, epsabs=0, epsrel=1e-10, limit=200)[0]

        total = integrate.quad(radial, 0, 2 * math.pi, epsabs=0, epsrel=1e-10, limit=200)[0]
        return 2 / (math.pi * E_STEEL) * total

    for x0, y0 in [(0.0, 0.0), (0.4 * a, 0.0), (0.0, 0.5 * b), (0.3 * a, -0.6 * b)]:
        expected = h.approach - x0**2 / (2 * Rx) - y0**2 / (2 * Ry)
        assert displacement(x0, y0) == pytest.approx(expected, rel=1e-6)


def test_elliptical_load_balance_and_symmetry():
    h1 = hertz_point(150.0, 0.01, 0.03, E_STEEL)
    h2 = hertz_point(150.0, 0.03, 0.01, E_STEEL)
    assert (h1.a, h1.b) == pytest.approx((h2.b, h2.a), rel=1e-12)
    assert 2 * math.pi * h1.a * h1.b * h1.max_pressure / 3 == pytest.approx(150.0, rel=1e-12)


@pytest.mark.parametrize("bad", [dict(F=0.0), dict(F=-1.0), dict(Rx=float("nan"))])
def test_bad_input_is_refused(bad):
    args = dict(F=1.0, Rx=0.01, Ry=None, E_red=E_STEEL) | bad
    with pytest.raises(ValueError, match=next(iter(bad))):
        hertz_point(**args)
