"""The uniform-grid Q1/P1 assembly equals scikit-fem's assembly of the same forms."""

import numpy as np
import pytest
from skfem import Basis, BilinearForm, ElementLineP1, ElementQuad1, LinearForm, MeshLine, MeshQuad, asm
from skfem.helpers import dot, grad

from femgear.physics.ehl.core.grid import Domain, Grid
from femgear.physics.ehl.fe.stencil import UniformElements


@BilinearForm
def _diffusion(u, v, w):
    return w["c"] * dot(grad(u), grad(v))


@BilinearForm
def _coef_grad(u, v, w):
    return u * sum(w[f"a{d}"] * v.grad[d] for d in range(v.grad.shape[0]))


@BilinearForm
def _streamline(u, v, w):
    return w["c"] * u.grad[0] * v.grad[0]


@LinearForm
def _unit(v, w):
    return v


def _skfem(kind):
    if kind == "quad":
        g = Grid.build(Domain(), 0, n0=12)
        X, Y = g.coords()
        ii, jj = np.meshgrid(np.arange(g.nx - 1), np.arange(g.ny - 1))
        n0 = (jj * g.nx + ii).ravel()
        mesh = MeshQuad(np.vstack([X, Y]), np.vstack([n0, n0 + 1, n0 + 1 + g.nx, n0 + g.nx]))
        return Basis(mesh, ElementQuad1(), intorder=2), UniformElements.quad(g.nx, g.ny, g.h)
    x = np.linspace(-4.5, 1.5, 41)
    return Basis(MeshLine(x), ElementLineP1(), intorder=2), UniformElements.line(x.size, x[1] - x[0])


@pytest.mark.parametrize("kind", ["quad", "line"])
def test_assembly_matches_skfem(kind):
    basis, el = _skfem(kind)
    rng = np.random.default_rng(1)
    u = rng.random(el.n)
    assert np.allclose(np.asarray(basis.interpolate(u)), el.interpolate(u), rtol=0, atol=1e-14)
    c = rng.random((el.ne, el.phi.shape[0])) + 0.5
    a = [rng.standard_normal(c.shape) for _ in el.grad]
    pairs = [
        (asm(_diffusion, basis, c=c), el.matrix(el.weighted(c, el.stiffness))),
        (asm(_streamline, basis, c=c), el.matrix(el.weighted(c, el.streamline))),
        (asm(_coef_grad, basis, **{f"a{d}": ad for d, ad in enumerate(a)}),
         el.matrix(el.coef_grad(*a))),
    ]
    for ref, new in pairs:
        assert abs(ref - new).max() <= 1e-13 * abs(ref).max()
    assert np.allclose(asm(_unit, basis), el.load(), rtol=1e-14, atol=0)


@pytest.mark.parametrize("sd", [0.0, 1.0])
def test_residual_alone_equals_the_linearisation_residual(sd):
    from femgear.physics.ehl.core import params as pr
    from femgear.physics.ehl.core.rheology import Rheology
    from femgear.physics.ehl.fe.level import Level

    lv = Level(Rheology(9.9, viscosity="roelands", ph=1e9, compressible=True),
               pr.point_lam_bar(20.0), pr.POINT_LOAD, grid=Grid.build(Domain(), 1), sd_factor=sd)
    PI = np.sqrt(np.maximum(1 - lv.X**2 - lv.Y**2, 0))[lv.interior] + 0.01
    P, H = lv.film(PI, 0.3)
    R = lv.reynolds.linearize(P, H).R
    assert np.allclose(lv.reynolds_residual(PI, 0.3), R, rtol=0, atol=1e-13 * np.abs(R).max())
