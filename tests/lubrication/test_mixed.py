"""Mixed lubrication: Greenwood–Tripp functions, the JGP load split, the smooth limit."""

import math

import numpy as np
import pytest
from scipy import integrate

from femgear.physics.lubrication.mixed import Roughness, gt_function, jgp_split, mixed_line_friction
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, line_contact_friction, thermal_central_film

OIL = OilLaw(eta0=0.08, alpha=2.2e-8, beta_t=0.03, T0=313.0, rho0=870.0, expansion=6.5e-4)
SOLIDS = Solids(B1=1.2e4, B2=1.2e4, k_oil=0.13)
E_RED = 2.3e11
CASE = dict(w=9.2e4, R=0.0123, ue=1.09, srr=0.3, T_bulk=313.0)


@pytest.mark.parametrize("n", [2, 2.5])
def test_greenwood_tripp_functions_against_quadrature(n):
    for t in (0.0, 0.02, 0.3, 1.0, 2.0, 3.5):
        q = integrate.quad(lambda s: (s - t) ** n * math.exp(-s * s / 2), t, np.inf)[0] / math.sqrt(2 * math.pi)
        assert gt_function(n, t)[0] == pytest.approx(q, rel=1e-6, abs=1e-15)


def _film(case):
    def film(w, E):
        return thermal_central_film(np.atleast_1d(w), case["R"], case["ue"], case["srr"], case["T_bulk"], OIL, E,
                                    SOLIDS)[0]
    return film


def test_jgp_split_balances_the_load():
    """Identity of the split: the asperity load p_a(h) 2b is the share W (1 − 1/γ₁) it solves for."""
    r = Roughness(sigma=0.6e-6)
    s = jgp_split(CASE["w"], CASE["R"], _film(CASE), E_RED, r)
    b = math.sqrt(8 * CASE["w"] * CASE["R"] / (math.pi * E_RED))
    W_a = r.asperity_pressure(s.film, E_RED)[0] * 2 * b
    assert 0 < s.asperity_fraction[0] < 0.5
    assert W_a == pytest.approx(CASE["w"] * s.asperity_fraction[0], rel=1e-6)
    assert s.film_parameter[0] == pytest.approx(s.film[0] / 0.6e-6)


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
