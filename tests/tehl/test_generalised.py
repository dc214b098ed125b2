"""The generalised Reynolds equation of the line TEHL (femgear.physics.tehl.generalised) and opposite sliding at zero
entrainment (femgear.physics.tehl.opposite).

Validation: the cross-film integrals against an independent quadrature of their definitions; the reduction to the
reduced Reynolds equation of a film uniform across its thickness; at u_e = 0 the temperature-viscosity wedge carries
a positive, symmetric film with the central dimple (the film thickest at the centre, the surfaces concave there), and
the dimple shallows as the surface speed rises (Yang, Cui, Kaneta & Kyogoku 2001, J. Tribol. 123:36, line contacts up
to infinite slide-roll ratio: "the contact surfaces take a shape of concave in the middle, and the concavity ...
decreases with increasing surface velocity")."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from femgear.physics.tehl import generalised as gf
from femgear.physics.tehl.energy import _mass_flux
from femgear.physics.tehl.opposite import solve_tehl_opposite

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)


def test_cross_film_integrals_against_quadrature():
    """η = e^(a ζ) across a unit film, ρ = 1 + ζ: ε and I0/F0(h) from the layers (exact for piecewise-constant
    profiles) converge to scipy's quadrature of the definitions F0, F1, I0, I1 at second order."""
    a = 3.0
    F0 = lambda z: (1.0 - np.exp(-a * z)) / a                      # noqa: E731
    F1 = lambda z: (1.0 - np.exp(-a * z) * (1.0 + a * z)) / a**2    # noqa: E731
    I0 = quad(lambda z: (1 + z) * F0(z), 0, 1)[0]
    I1 = quad(lambda z: (1 + z) * F1(z), 0, 1)[0]
    eps, share = F1(1.0) * I0 / F0(1.0) - I1, I0 / F0(1.0)
    errs = []
    for nz in (200, 400):
        z = (np.arange(nz) + 0.5) / nz
        cf = gf.cross_film(np.exp(a * z)[None, :], (1 + z)[None, :], np.array([1.0]))
        errs.append(abs(cf.eps[0] / eps - 1) + abs(cf.rho_f0[0] / share - 1))
    assert errs[1] < 1e-5 and 3.5 < errs[0] / errs[1] < 4.5


def test_uniform_film_reduces_to_the_reduced_equation():
    """Temperatures uniform across the film: ε = ρ h³/(12 η), q_c = ρ h u_e and the mass flux equal the reduced
    Reynolds equation's (the energy solve's own estimate) to 1e-12, at the baseline oil's EHL pressures."""
    p = np.linspace(0.0, 1.2e9, 41)
    h = np.linspace(2e-7, 5e-7, 41)
    T = 313.0 + 40.0 * np.sin(np.linspace(0, 3, 41))
    layers = np.repeat(T[:, None], 16, axis=1)
    gen, red = gf.of_film(case.OIL, p, h, layers), gf.reduced_of(case.OIL, p, h, T)
    for f in ("eps", "rho_h", "rho_f0"):
        assert np.allclose(getattr(gen, f), getattr(red, f), rtol=1e-12, atol=0)
    x = np.linspace(-4e-4, 2e-4, 41)
    v1, v2 = 12.0, 8.0
    m_red = _mass_flux(x, p, h, case.OIL.density(p, T), case.OIL.viscosity(p, T), 0.5 * (v1 + v2))
    assert gf.mass_flux(x, p, h, layers, case.OIL, v1, v2) == pytest.approx(m_red, rel=1e-12)


def test_colder_layer_carries_the_couette_flux():
    """A film more viscous by surface 1 moves with surface 1: q_c > ρ h u_e for v1 > v2 (the thermal wedge's
    cause); with the profile mirrored across the film, q_c is mirrored about ρ h u_e."""
    z = (np.arange(16) + 0.5) / 16
    eta = np.exp(2.0 * (1 - z))[None, :]
    cf = gf.cross_film(eta, np.ones_like(eta), np.array([1.0]))
    mirror = gf.cross_film(eta[:, ::-1], np.ones_like(eta), np.array([1.0]))
    q, qm = cf.couette(1.0, -1.0)[0], mirror.couette(1.0, -1.0)[0]
    assert q > 0.1 and qm == pytest.approx(-q, rel=1e-12)


def _dimple(r):
    """(h_c, the smaller of the two rims' minima, their positions / b): the film's dimple."""
    X = r.x / r.b
    left, right = (X < 0) & (X > -1), (X > 0) & (X < 1)
    il, ir = np.argmin(np.where(left, r.h, np.inf)), np.argmin(np.where(right, r.h, np.inf))
    return r.hc, min(r.h[il], r.h[ir]), X[il], X[ir]


def test_opposite_sliding_at_zero_entrainment_shows_the_dimple():
    """v1 = 5, v2 = −5 m/s (u_e = 0) on the baseline's mid-path contact: converges to its tolerance, the heat
    balances, the film is positive and symmetric, and it is thickest at the centre, with a rim minimum on either
    side (the dimple: measured h_c 884 nm, rims 652 nm at ±0.74 b, peak film rise 167 K)."""
    r = solve_tehl_opposite(case.W, case.R, 5.0, -5.0, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0)
    assert all(e is not None and e <= 0.01 for e in r.error_estimate.values())
    assert abs(r.heat["balance_error"]) < 1e-6 and r.heat["generated"] > 0
    hc, rim, xl, xr = _dimple(r)
    assert r.hmin > 0 and hc > 1.2 * rim and r.hmin == pytest.approx(rim, rel=1e-12)
    assert -1.0 < xl < -0.3 and xr == pytest.approx(-xl, abs=0.02)
    mirror = np.interp(-r.x[::-1], r.x, r.p)[::-1]
    assert np.max(np.abs(mirror - r.p)) < 0.01 * r.p.max()
    assert r.mu > 0 and r.pmax > r.ph        # the wedge concentrates the load at the centre


@pytest.mark.slow
def test_the_dimple_deepens_with_load_and_shallows_with_speed():
    """Yang et al. (2001): the concavity increases with increasing load and decreases with increasing surface
    velocity (u_e = 0; measured depth h_c − rim 232 nm at 5 m/s each way, 461 nm at twice the load, 53 nm at
    10 m/s)."""
    def depth(w, U):
        r = solve_tehl_opposite(w, case.R, U, -U, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0)
        hc, rim, *_ = _dimple(r)
        return hc - rim

    base = depth(case.W, 5.0)
    assert depth(2.0 * case.W, 5.0) > 1.5 * base and 0 < depth(case.W, 10.0) < 0.5 * base


@pytest.mark.slow
def test_opposite_sliding_mirrors_with_the_bodies():
    """Surface 2 forward (v2 > 0 > v1) is the same contact with the bodies swapped: the same film, the surfaces'
    temperatures and heat exchanged, μ_couette reversed, the layers mirrored across the film."""
    a = solve_tehl_opposite(case.W, case.R, 5.5, -4.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0)
    b = solve_tehl_opposite(case.W, case.R, -4.5, 5.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0)
    assert a.hc > 0 and a.hc == pytest.approx(b.hc, rel=1e-9) and a.mu_couette == pytest.approx(-b.mu_couette)
    assert np.allclose(a.T_surface1, b.T_surface2) and a.heat["solid1"] == pytest.approx(b.heat["solid2"])
    assert np.allclose(a.T_film, b.T_film[:, ::-1])
