"""Taylor test of the Newton Jacobian (exact derivative of the discrete residual)."""

import numpy as np
import pytest

from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.grid import Domain, Grid
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fe.level import Level


@pytest.mark.parametrize("kwargs", [
    dict(rheo=Rheology(5.0)),
    dict(rheo=Rheology(5.0, viscosity="roelands", ph=1e9, compressible=True)),
])
def test_point_jacobian_taylor(kwargs):
    M = 20.0
    lv = Level(kwargs["rheo"], pr.point_lam_bar(M), pr.POINT_LOAD,
               grid=Grid.build(Domain(), 0, n0=24), sd_factor=1.0)
    rng = np.random.default_rng(0)
    # strictly positive pressure: the min-NCP kink is not crossed by the perturbation
    P = (np.sqrt(np.maximum(1 - lv.X**2 - lv.Y**2, 0)) + 0.2)[lv.interior]
    P += 0.01 * rng.random(P.size)
    H0 = 0.3
    F, lin, H, s, act = lv.evaluate(P, H0)
    assert not act.any()
    J = lv.dense_jacobian(lin, s, act, lv.dense_kernel())
    v = rng.standard_normal(P.size + 1)
    errs = []
    for e in (1e-3, 1e-4, 1e-5):
        Fe = lv.evaluate(P + e * v[:-1], H0 + e * v[-1], s)[0]
        errs.append(np.linalg.norm(Fe - F - e * J @ v))
    # second-order Taylor remainder: error drops ~100x per decade of e
    assert errs[1] < errs[0] / 30 and errs[2] < errs[1] / 30


def test_line_jacobian_taylor():
    M = 20.0
    x = np.linspace(-4.5, 1.5, 97)
    lv = Level(Rheology(6.0), pr.line_lam_bar(M), pr.LINE_LOAD, x=x, sd_factor=1.0)
    P = (np.sqrt(np.maximum(1 - lv.X**2, 0)) + 0.2)[lv.interior]
    F, lin, H, s, act = lv.evaluate(P, 0.2)
    J = lv.dense_jacobian(lin, s, act, lv.dense_kernel())
    v = np.random.default_rng(3).standard_normal(P.size + 1)
    errs = [np.linalg.norm(lv.evaluate(P + e * v[:-1], 0.2 + e * v[-1], s)[0] - F - e * J @ v)
            for e in (1e-3, 1e-4, 1e-5)]
    assert errs[1] < errs[0] / 30 and errs[2] < errs[1] / 30
