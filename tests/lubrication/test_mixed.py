"""Mixed lubrication: the Greenwood–Tripp / Greenwood–Williamson functions, the load sharing of Johnson, Greenwood
& Poon (1972) with its limits and balance, the smooth limit."""

import math

import numpy as np
import pytest
from scipy import integrate, special

from femgear.physics.lubrication.flash import line_flash_temperature
from femgear.physics.lubrication.mixed import Roughness, gt_function, jgp_split, mean_gap, mixed_line_friction
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, line_contact_friction, thermal_central_film

OIL = OilLaw(eta0=0.08, alpha=2.2e-8, beta_t=0.03, T0=313.0, rho0=870.0, expansion=6.5e-4)
SOLIDS = Solids(B1=1.2e4, B2=1.2e4, k_oil=0.13)
E_RED = 2.3e11
CASE = dict(w=9.2e4, R=0.0123, ue=1.09, srr=0.3, T_bulk=313.0)


@pytest.mark.parametrize("n", [1.5, 2, 2.5])
def test_greenwood_tripp_functions_against_quadrature(n):
    """F_n(t) by the parabolic cylinder function against the defining integral, t on both sides of the mean plane;
    F_2 also against its erfc closed form, and the tabulated F_3/2(0) = 0.4300, F_5/2(0) = 0.6166."""
    for t in (-6.0, -1.5, -0.2, 0.0, 0.02, 0.3, 1.0, 2.0, 3.5):
        q = integrate.quad(lambda s: (s - t) ** n * math.exp(-s * s / 2), t, np.inf, epsabs=0, epsrel=1e-12,
                           limit=200)[0] / math.sqrt(2 * math.pi)
        assert gt_function(n, t)[0] == pytest.approx(q, rel=1e-9)
    t = np.linspace(-5, 8, 27)
    erfc_form = 0.5 * (t**2 + 1) * special.erfc(t / math.sqrt(2)) - t * np.exp(-t**2 / 2) / math.sqrt(2 * math.pi)
    np.testing.assert_allclose(gt_function(2, t), erfc_form, rtol=1e-9)
    assert gt_function(1.5, 0.0)[0] == pytest.approx(0.4300, abs=5e-5)
    assert gt_function(2.5, 0.0)[0] == pytest.approx(0.6166, abs=5e-5)


def test_mean_gap_of_gaussian_heights():
    """Patir & Cheng's mean gap E[max(t + δ, 0)], δ ~ N(0, 1), against quadrature; → t for t ≫ 1, → 0 below."""
    for t in (-3.0, -0.5, 0.0, 0.7, 2.0):
        q = integrate.quad(lambda d: (t + d) * math.exp(-d * d / 2) / math.sqrt(2 * math.pi), -t, np.inf,
                           epsabs=0, epsrel=1e-12)[0]
        assert mean_gap(t) == pytest.approx(q, rel=1e-10)
    assert mean_gap(6.0) == pytest.approx(6.0, rel=1e-9) and mean_gap(-8.0) < 1e-15


def _film(case):
    def film(w, E):
        return thermal_central_film(np.atleast_1d(w), case["R"], case["ue"], case["srr"], case["T_bulk"], OIL, E,
                                    SOLIDS)[0]
    return film


LAWS = [(c, f) for c in ("greenwood-tripp", "greenwood-williamson") for f in ("mean-gap", "separation")]


@pytest.mark.parametrize(("contact", "fluid_film"), LAWS)
def test_load_sharing_balances_the_load(contact, fluid_film):
    """The split is one state: the asperity load p_C(h) 2b at the reported separation plus the fluid's W/γ₁ is W
    to 1e-9, and the fluid's film at W/γ₁, E'/γ₁ is its gap at that separation to 1e-9 σ."""
    r = Roughness(sigma=0.6e-6, contact=contact, fluid_film=fluid_film)
    film = _film(CASE)
    s = jgp_split(CASE["w"], CASE["R"], film, E_RED, r)
    b = math.sqrt(8 * CASE["w"] * CASE["R"] / (math.pi * E_RED))
    W_C = r.asperity_pressure(s.separation * r.sigma, E_RED)[0] * 2 * b
    assert 0 < s.asperity_fraction[0] < 0.9
    assert abs(W_C + CASE["w"] / s.gamma1[0] - CASE["w"]) < 1e-9 * CASE["w"]
    h_fluid = film(CASE["w"] / s.gamma1[0], E_RED / s.gamma1[0])[0]
    assert abs(h_fluid - r.fluid_gap(s.separation[0] * r.sigma)) < 1e-9 * r.sigma
    assert s.film[0] == pytest.approx(h_fluid, rel=1e-12) and s.film_parameter[0] == pytest.approx(s.film[0] / 0.6e-6)


@pytest.mark.parametrize("contact", ["greenwood-tripp", "greenwood-williamson"])
def test_load_sharing_limits(contact):
    """Thick film (fast, λ ≈ 40): W_C → 0 and μ → μ_EHL of the whole load; vanishing film (u_e 10 µm/s): with the
    mean gap the asperities carry the load, μ → μ_b; with the separation as the film they cannot carry more than
    p_C(0) 2b, the old split's bound.  (The fluid's mean gap does not vanish: it tends to the gap at the separation
    where the asperities alone carry W, oil at rest between them.)"""
    mu_b = 0.1
    fast = dict(CASE, ue=60.0, srr=0.05)
    r = Roughness(sigma=0.05e-6, contact=contact)
    res, split = mixed_line_friction(fast["w"], fast["R"], fast["ue"], fast["srr"], fast["T_bulk"], OIL, E_RED, SOLIDS,
                                     r, mu_b)
    ehl = line_contact_friction(fast["w"], fast["R"], fast["ue"], fast["srr"], fast["T_bulk"], OIL, E_RED, SOLIDS)
    assert split.film_parameter[0] > 10 and split.asperity_fraction[0] < 1e-9
    assert res.mu[0] == pytest.approx(ehl.mu[0], rel=1e-6)
    slow = dict(CASE, ue=1e-7)
    r = Roughness(sigma=0.6e-6, contact=contact)
    res, split = mixed_line_friction(slow["w"], slow["R"], slow["ue"], slow["srr"], slow["T_bulk"], OIL, E_RED, SOLIDS,
                                     r, mu_b)
    b = math.sqrt(8 * CASE["w"] * CASE["R"] / (math.pi * E_RED))
    assert split.asperity_fraction[0] > 0.9999 and res.mu[0] == pytest.approx(mu_b, rel=1e-4)
    all_asperity = r.asperity_pressure(split.separation * r.sigma, E_RED)[0] * 2 * b
    assert all_asperity == pytest.approx(CASE["w"], rel=1e-4)
    old = Roughness(sigma=0.6e-6, contact=contact, fluid_film="separation")
    _, split = mixed_line_friction(slow["w"], slow["R"], slow["ue"], slow["srr"], slow["T_bulk"], OIL, E_RED, SOLIDS,
                                   old, mu_b)
    bound = old.asperity_pressure(0.0, E_RED)[0] * 2 * b / CASE["w"]
    assert split.asperity_fraction[0] == pytest.approx(bound, rel=1e-3) and bound < 0.9


def test_smooth_limit_is_the_full_film_traction_and_roughness_raises_mu():
    """σ → 0: γ₁ = 1 and μ is the smooth contact's exactly; rougher flanks carry more load on the
    asperities and μ rises monotonically toward μ_b."""
    smooth = line_contact_friction(CASE["w"], CASE["R"], CASE["ue"], CASE["srr"], CASE["T_bulk"], OIL, E_RED, SOLIDS)
    mus, shares = [], []
    for sigma in (1e-9, 0.3e-6, 0.6e-6, 1.2e-6):
        res, split = mixed_line_friction(CASE["w"], CASE["R"], CASE["ue"], CASE["srr"], CASE["T_bulk"], OIL, E_RED,
                                         SOLIDS, Roughness(sigma), 0.1)
        mus.append(res.mu[0])
        shares.append(split.asperity_fraction[0])
    assert shares[0] == 0.0 and mus[0] == pytest.approx(smooth.mu[0], rel=1e-12)
    assert np.all(np.diff(shares) > 0) and np.all(np.diff(mus) > 0) and mus[-1] < 0.1


def test_zhou_hoeprich_share_is_exp_of_lambda_and_weights_the_friction():
    """Zhou & Hoeprich (J. Tribol. 113:590, 1991, eq. 29): W_C/W = exp(−B λ^C) at λ = h_c/σ, h_c the smooth contact's
    thermal central film at the whole load (their eq. 30); the friction weighted as Wingertszahn et al.
    (Lubricants 11:369, 2023, eq. 36) do, μ = φ μ_b + (1 − φ) μ_EHL(W), the fluid's heat by 1 − φ, the asperities'
    by Blok's flash temperature of μ_b φ."""
    from femgear.physics.lubrication.mixed import load_split

    mu_b, ue = 0.1, np.array([0.02, 0.3, 1.09, 8.0])
    r = Roughness(sigma=0.6e-6, contact="zhou-hoeprich", share_b=1.9, share_c=0.99)
    w, R, srr, T = CASE["w"], CASE["R"], CASE["srr"], CASE["T_bulk"]
    res, split = mixed_line_friction(w, R, ue, srr, T, OIL, E_RED, SOLIDS, r, mu_b)
    h = thermal_central_film(w, R, ue, srr, T, OIL, E_RED, SOLIDS)[0]
    phi = np.exp(-1.9 * (h / 0.6e-6) ** 0.99)
    np.testing.assert_allclose(split.film_parameter, h / 0.6e-6, rtol=1e-12)
    np.testing.assert_allclose(split.asperity_fraction, phi, rtol=1e-12)
    ehl = line_contact_friction(w, R, ue, srr, T, OIL, E_RED, SOLIDS)
    np.testing.assert_allclose(res.mu, phi * mu_b + (1 - phi) * ehl.mu, rtol=1e-12)
    blok = line_flash_temperature(mu_b * phi, w, R, ue, srr, E_RED, SOLIDS.B1, SOLIDS.B2)
    np.testing.assert_allclose(res.flash_max, (1 - phi) * ehl.flash_max + blok, rtol=1e-12)
    assert np.all(np.diff(split.asperity_fraction) < 0) and np.all(np.diff(res.mu) < 0)   # μ falls as λ rises
    one = load_split(w, R, _film(CASE), E_RED, r)
    assert one.asperity_fraction[0] == pytest.approx(np.exp(-1.9 * (_film(CASE)(w, E_RED)[0] / 0.6e-6) ** 0.99))


def test_zhou_hoeprich_limits():
    """Thick film (λ > 10): the share below 1e-8 and μ the smooth μ_EHL; vanishing film (u_e 0.1 µm/s): μ → μ_b."""
    mu_b = 0.1
    r = Roughness(sigma=0.05e-6, contact="zhou-hoeprich")
    fast = dict(CASE, ue=60.0, srr=0.05)
    res, split = mixed_line_friction(fast["w"], fast["R"], fast["ue"], fast["srr"], fast["T_bulk"], OIL, E_RED, SOLIDS,
                                     r, mu_b)
    ehl = line_contact_friction(fast["w"], fast["R"], fast["ue"], fast["srr"], fast["T_bulk"], OIL, E_RED, SOLIDS)
    assert split.film_parameter[0] > 10 and split.asperity_fraction[0] < 1e-8
    assert res.mu[0] == pytest.approx(ehl.mu[0], rel=1e-6)
    slow = Roughness(sigma=0.6e-6, contact="zhou-hoeprich")
    res, split = mixed_line_friction(CASE["w"], CASE["R"], 1e-7, CASE["srr"], CASE["T_bulk"], OIL, E_RED, SOLIDS, slow,
                                     mu_b)
    assert split.asperity_fraction[0] > 0.999 and res.mu[0] == pytest.approx(mu_b, rel=2e-3)
