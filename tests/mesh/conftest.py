"""Shared fixtures of the mesh tests: a small helical pair and the volume of a mesh."""

import math

import pytest

from femgear.physics.geometry.gear import GearPair


@pytest.fixture(scope="module")
def pair():
    return GearPair.from_parameters(z1=24, z2=30, m_n=4e-3, alpha_n=math.radians(20), beta=math.radians(25),
                                    b=12e-3, x1=0.0, x2=0.0)


@pytest.fixture(scope="session")
def volume():
    """Volume (3-D) or area (2-D) of a P1 mesh, by quadrature of 1."""
    from skfem import Basis, ElementTetP1, ElementTriP1, Functional

    @Functional
    def one(w):
        return 1.0 + 0 * w.x[0]

    def measure(mesh):
        el = ElementTetP1() if mesh.p.shape[0] == 3 else ElementTriP1()
        return one.assemble(Basis(mesh, el))

    return measure
