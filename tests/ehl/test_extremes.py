"""Stability at the extremes (tier 3): each case converges to a checked answer or raises
ConvergenceError; never NaN, never a silent wrong answer."""

import numpy as np
import pytest

from femgear.contact.film import moes_line_central, nvm_central
from femgear.ehl.grid import Domain
from femgear.ehl.line import solve_line
from femgear.ehl.point import solve_point
from femgear.errors import ConvergenceError

SLOW_POINT_CASES = {
    "high load": (dict(M=1000.0, L=10.0, level=2), 0.10),
    "high L": (dict(M=20.0, L=30.0, level=2), 0.10),
    "very low speed": (dict(M=3000.0, L=5.0, level=2), None),
    "M = 2000 at L = 10 (issue 16: converges or raises)": (dict(M=2000.0, L=10.0, level=2), None),
}
POINT_CASES = {
    "high load, coarse only": (dict(M=1000.0, L=10.0, level=1), None),
    "small domain": (dict(M=20.0, L=10.0, level=2, domain=Domain(-1.6, 1.3, -1.3, 1.3)), None),
    "large domain": (dict(M=20.0, L=10.0, level=2, domain=Domain().scaled(1.6)), 0.06),
    "coarse grid": (dict(M=20.0, L=10.0, level=0, coarse_level=0), None),
    "roelands + DH": (dict(M=50.0, L=10.0, level=2, viscosity="roelands", ph=1.0e9,
                           compressible=True), None),
}


def _check(r, oracle, rel):
    assert np.all(np.isfinite(r.P)) and np.all(np.isfinite(r.H))
    assert r.P.min() >= 0.0 and r.Hmin > 0.0 and r.Hc > 0.0
    assert r.load_error < 1e-4
    if rel is not None:
        assert r.Hc == pytest.approx(oracle, rel=rel)


def _point_case(kw, rel):
    try:
        r = solve_point(**kw)
    except ConvergenceError as exc:
        assert exc.history and len(exc.history["residual"]) > 0
        assert "M=" in str(exc)
        return
    _check(r, float(nvm_central(kw["M"], kw["L"])), rel)


@pytest.mark.parametrize("name", list(POINT_CASES))
def test_point_extremes(name):
    _point_case(*POINT_CASES[name])


@pytest.mark.slow
@pytest.mark.parametrize("name", list(SLOW_POINT_CASES))
def test_point_extremes_slow(name):
    _point_case(*SLOW_POINT_CASES[name])


@pytest.mark.parametrize("kw, rel", [
    (dict(M=2000.0, L=20.0, level=5), None),
    (dict(M=20.0, L=25.0, level=5), 0.08),  # beyond the Moes fit range in L
    (dict(M=20.0, L=10.0, level=5, x0=-1.5), None),
    (dict(M=1.0, L=0.0, level=5, x0=-12.0, x1=4.0), None),
])
def test_line_extremes(kw, rel):
    try:
        r = solve_line(**kw)
    except ConvergenceError as exc:
        assert len(exc.history["residual"]) > 0
        return
    _check(r, float(moes_line_central(kw["M"], kw["L"])), rel)


def test_bad_input_is_rejected():
    with pytest.raises(ValueError):
        solve_point(-1.0, 10.0, level=1)
    with pytest.raises(ValueError):
        solve_line(20.0, 10.0, x0=-0.5)
