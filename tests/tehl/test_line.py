"""Line-contact TEHL: exact isothermal recovery, the thermal hook, global energy balance,
Jaeger operator vs Blok, thermal film reduction vs Gupta et al. (1992)."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse.linalg

from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.dimensional import solve_line_dimensional
from femgear.physics.ehl.fe.level import Level
from femgear.physics.lubrication.flash import blok_flash_temperature
from femgear.physics.lubrication.traction import gupta_thermal_factor
from femgear.physics.tehl import solve_tehl_line
from femgear.physics.tehl.energy import jaeger_matrix
from femgear.physics.tehl.line import ehl_oil_at
from femgear.physics.tehl.rheology import ThermalRheology

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)


def _solve(srr, level=4, **kw):
    return solve_tehl_line(case.W, case.R, kw.pop("ue", case.UE), srr, kw.pop("T", case.T0), case.OIL, case.E_RED,
                           case.PROPS, tau0=case.TAU0, level=level, **kw)


def test_heat_off_recovers_isothermal_exactly():
    """Isothermal limit (issue 43: to 0.5 %): with the heat sources off the TEHL returns the isothermal FD line
    solution on the same grid bit for bit (the loop sees zero temperature change and never re-solves)."""
    r = _solve(0.5, level=4, heat=False)
    # the TEHL start keeps its LU factors for the thermal loop (reuse=): the same solve
    iso = solve_line_dimensional(case.W, case.R, case.UE, case.E_RED, ehl_oil_at(case.OIL, case.T0), level=4,
                                 reuse={})
    assert np.array_equal(r.p, iso.p) and np.array_equal(r.h, iso.h)
    assert r.hc == iso.hc == r.hc_isothermal and r.dT_max == 0.0 and np.all(r.T_film == case.T0)
    plain = solve_line_dimensional(case.W, case.R, case.UE, case.E_RED, ehl_oil_at(case.OIL, case.T0), level=4)
    assert np.allclose(r.p, plain.p, rtol=0, atol=1e-9 * plain.p.max()) and r.hc == pytest.approx(plain.hc, rel=1e-9)


def test_thermal_rheology_hook_is_exact_at_bulk_and_active_otherwise():
    iso = solve_line_dimensional(case.W, case.R, case.UE, case.E_RED, ehl_oil_at(case.OIL, case.T0), level=3)
    res = iso.result
    oil = ehl_oil_at(case.OIL, case.T0)
    args = (pr.line_alpha_bar(res.M, res.L),)
    kw = dict(viscosity="roelands", ph=iso.ph, z=oil.z, compressible=True)
    X = np.linspace(-4.5, 1.5, 16 * 2**3 + 1)
    plain = Level(Rheology(*args, **kw), pr.line_lam_bar(res.M), pr.LINE_LOAD, x=X, sd_factor=1.0)
    th = ThermalRheology(*args, **kw, T_bulk=case.T0, s0=case.OIL.s0, expansion=case.OIL.expansion,
                         T_ref=case.OIL.T0)
    hot = Level(th, pr.line_lam_bar(res.M), pr.LINE_LOAD, x=X, sd_factor=1.0)
    T = np.full(X.size, case.T0)
    th.state.update(node=T, quad=np.asarray(hot.reynolds.basis.interpolate(T)))
    PI = res.P[plain.interior]
    F0, F1 = plain.evaluate(PI, res.H0)[0], hot.evaluate(PI, res.H0)[0]
    assert np.array_equal(F0, F1)
    T = case.T0 + 20.0 * np.exp(-X**2)
    th.state.update(node=T, quad=np.asarray(hot.reynolds.basis.interpolate(T)))
    assert np.max(np.abs(hot.evaluate(PI, res.H0)[0][:-1] - F0[:-1])) > 1e-3 * np.max(np.abs(PI))


@pytest.mark.parametrize("srr", [0.0, 0.6])
def test_global_energy_balance(srr):
    r = _solve(srr)
    q = r.heat
    assert abs(q["balance_error"]) < 0.01
    assert q["generated"] > 0 and q["solid1"] > 0 and q["solid2"] > 0
    assert q["convected"] > 0.002 * q["generated"]     # the film does carry heat out
    assert r.dT_max > 0 and np.all(np.isfinite(r.T_film))


def test_jaeger_operator_reproduces_blok_for_a_semielliptic_source():
    n, b, v1, v2, B = 400, 2e-4, 3.0, 1.0, case.PROPS.B1
    x = -1 + (2 * np.arange(n) + 1) / n
    mu, w, vs = 0.05, 1e5, abs(v1 - v2)
    q = 2 * mu * w * vs / (np.pi * b) * np.sqrt(1 - x**2)
    J1, J2 = jaeger_matrix(n, 2 * b, B, v1), jaeger_matrix(n, 2 * b, B, v2)
    share = B * np.sqrt(v1) / (B * np.sqrt(v1) + B * np.sqrt(v2))   # Blok's equal-temperature partition
    t1, t2 = J1 @ (share * q), J2 @ ((1 - share) * q)
    assert np.allclose(t1, t2, rtol=1e-10)
    blok = blok_flash_temperature(mu, w, vs, b, v1, v2, B, B)
    assert t1.max() == pytest.approx(blok, rel=0.02)


def test_flash_temperature_against_blok():
    """The frictional part of the surface temperature (minus the rolling one) against Blok
    with femgear's μ: same order, higher because the Eyring heat peaks near the outlet
    (measured ratio ≈ 1.5)."""
    base = _solve(0.0).dT_surface
    for srr in (0.3, 1.0):
        r = _solve(srr)
        v1, v2 = case.UE * (1 + srr / 2), case.UE * (1 - srr / 2)
        blok = float(blok_flash_temperature(r.mu, case.W, abs(v1 - v2), r.b, v1, v2, case.PROPS.B1, case.PROPS.B2))
        assert 0.8 < (r.dT_surface - base) / blok < 2.2


def test_thermal_film_reduction_against_gupta():
    """φ_T = h_c / h_c,iso at u_e = 3 and 10 m/s, rolling: within 10 % of Gupta et al. (1992)."""
    for ue in (3.0, 10.0):
        r = _solve(0.0, ue=ue)
        g = float(gupta_thermal_factor(r.ph, case.E_RED, 0.0, ue, case.OIL.viscosity(0.0, case.T0),
                                       case.OIL.beta_t, case.PROPS.k_oil))
        phi = r.hc / r.hc_isothermal
        assert phi < 0.97 and abs(phi / g - 1) < 0.1


@pytest.mark.parametrize("srr", [0.0, 0.3, 1.0])
def test_thermal_levels_carry_their_richardson_estimate(srr):
    """The thermal solve on the level below and on the isothermal solve's level give the two-level estimate of
    h_c and h_min; at the tolerance-driven default it is within the tolerance (1 %), and the films of the two
    levels agree within three times it."""
    r = _solve(srr, level=None)
    assert len(r.levels) >= 2 and all(e is not None and e <= 0.01 for e in r.error_estimate.values())
    fine, coarse = r.levels[-1], r.levels[-2]
    assert fine["nodes"] == 2 * coarse["nodes"] - 1
    assert abs(fine["Hc"] / coarse["Hc"] - 1) <= 0.03 and r.hc == pytest.approx(fine["Hc"])


def test_surface_operator_exact_moving_source_and_its_jaeger_limit():
    """The solids' operator at any Péclet number (the 2-D moving line source, Carslaw & Jaeger 1959 §10.7): its
    closed-form cell integrals equal quadrature of (1/(π k)) e^(u s) K0(|u s|), and at high Péclet number it
    tends to Jaeger's 1/√ kernel (within 1 % at u b = 2e3 on the contact's cells); a reversed surface mirrors it."""
    from scipy.integrate import quad
    from scipy.special import k0

    from femgear.physics.tehl.energy import surface_matrix

    B, k = case.PROPS.B1, 45.0
    kappa = (k / B) ** 2
    xf = np.sort(np.r_[-4.5, 1.5, np.random.default_rng(1).uniform(-4.5, 1.5, 38)]) * 2e-4
    v = 0.02
    G = surface_matrix(xf, v, B, k)
    u = v / (2 * kappa)
    xc = 0.5 * (xf[:-1] + xf[1:])
    for i, j in ((3, 3), (10, 4), (4, 10), (30, 2)):
        g = lambda xi, x=xc[i]: np.exp(u * (x - xi)) * k0(abs(u * (x - xi))) / (np.pi * k)  # noqa: E731
        ref = quad(g, xf[j], xf[j + 1], points=[xc[i]] if xf[j] < xc[i] < xf[j + 1] else None, limit=500,
                   epsabs=0.0, epsrel=1e-12)[0]
        assert G[i, j] == pytest.approx(ref, rel=1e-10)
    fast = 2e3 * 2 * kappa / 2e-4
    Gf, Ja = surface_matrix(xf, fast, B, k), surface_matrix(xf, fast, B)
    q = np.sqrt(np.clip(1 - (xc / 2e-4) ** 2, 0, None))
    assert np.max(np.abs(Gf @ q - Ja @ q)) < 0.01 * np.max(Ja @ q)
    assert np.allclose(surface_matrix(xf, -fast, B), surface_matrix(-xf[::-1], fast, B)[::-1, ::-1])


@pytest.mark.parametrize("ue, srr", [(40.0, 0.5), (0.05, 2.0)])
def test_energy_solve_equals_the_direct_solve(monkeypatch, ue, srr):
    """The energy solve (GMRES on the banded film with the solids' near band, or on the factors kept from an
    earlier solve of the loop) gives the temperatures and wall fluxes of the direct sparse solve of the whole
    matrix (to 1e-6 K, 1e-7 relative), at turbo speed and with a surface at rest under a thin film."""
    import femgear.physics.tehl.energy as energy

    seen = []
    solve = energy.linear_solve

    def spy(args, rhs, n_theta, cache=None):
        seen.append((args, rhs, n_theta))
        return solve(args, rhs, n_theta, cache)

    monkeypatch.setattr(energy, "linear_solve", spy)
    _solve(srr, level=4, ue=ue)
    args, rhs, n_theta = seen[-1]
    x = solve(args, rhs, n_theta)
    ref = scipy.sparse.linalg.spsolve(energy._energy_matrix(*args).tocsc(), rhs)
    assert np.max(np.abs(x[:n_theta] - ref[:n_theta])) < 1e-6 * max(1.0, np.max(np.abs(ref[:n_theta])))
    assert np.max(np.abs(x[n_theta:] - ref[n_theta:])) < 1e-7 * np.max(np.abs(ref[n_theta:]))


def test_the_films_peak_temperature_bounds_its_walls():
    """The film's peak temperature rise is over the film with its walls: never below the surface (flash) rise, at
    rolling and with sliding (a zoo cell once read a surface 0.2 K above the film's layer-centre peak)."""
    for srr in (0.0, 1.0):
        r = _solve(srr)
        assert r.dT_max >= r.dT_surface > 0


def test_every_summary_names_one_film_peak_with_its_walls():
    """The result and each thermal level report the same quantity, the film's peak with its walls (``film_peaks``):
    the finest level's summary equals the result's, every level reads its surface (flash) peak beside it and never
    above it.  (The level summaries once read the layer-centre peak alone, below the result's on the same level.)"""
    r = _solve(1.0, level=None)
    fine = r.levels[-1]
    assert fine["dT_max"] == r.dT_max and fine["dT_surface"] == r.dT_surface
    assert all(lv["dT_max"] >= lv["dT_surface"] > 0 for lv in r.levels)
    assert r.dT_max >= float(np.max(r.T_film - case.T0)) - 1e-12
