"""Dimensional entry: SI in, metres/pascals out, consistent with Hertz and NVM."""

import numpy as np
import pytest

from femgear.physics.contact.film import moes_to_h, nvm_central
from femgear.physics.contact.hertz import hertz_point
from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional, solve_point_dimensional

F, R, UM, E = 500.0, 0.02, 2.0, 2.2e11
OIL = EHLOil(eta0=0.08, alpha=22e-9)  # seed paper table 2 oil


def test_point_dimensional_scales():
    r = solve_point_dimensional(F, R, None, UM, E, OIL, level=2)
    hz = hertz_point(F, R, R, E)
    assert r.a == pytest.approx(hz.a, rel=1e-12)
    assert r.ph == pytest.approx(hz.max_pressure, rel=1e-12)
    U = OIL.eta0 * UM / (E * R)
    assert r.hc == pytest.approx(float(moes_to_h(nvm_central(r.M, r.L), U, R)), rel=0.05)
    assert 0 < r.hmin < r.hc < 5e-6
    assert r.p.max() == pytest.approx(r.pmax) and r.h.min() == pytest.approx(r.hmin)


def test_roelands_dh_thinner_than_barus():
    """Roelands (z < 1) lowers the inlet viscosity rise: a thinner film than Barus."""
    barus = solve_point_dimensional(F, R, None, UM, E, OIL, level=1)
    roel = solve_point_dimensional(F, R, None, UM, E, EHLOil(0.08, 22e-9, "roelands",
                                                             compressible=True), level=1)
    assert roel.hc < barus.hc


def test_line_dimensional_hertz_width():
    r = solve_line_dimensional(2.0e5, R, UM, E, OIL, level=5)
    Wl = 2.0e5 / (E * R)
    assert r.a == pytest.approx(R * (8 * Wl / 3.141592653589793) ** 0.5, rel=1e-12)
    assert r.pmax > 0.8 * r.ph  # (a low-M case: the outlet spike reaches ~2 p_h)
    assert np.trapezoid(r.p, r.x) == pytest.approx(2.0e5, rel=1e-6)  # load balance in N/m (graded grid: trapezoid)
    assert 0 < r.hmin < r.hc
