"""Plane elasticity: identities (symmetry, rigid-body kernel) and a Timoshenko cantilever."""

import math

import numpy as np
import pytest

from femgear.physics.body.elastic import ElasticProblem, rigid_body_modes
from femgear.physics.body.forms import lame, thermal_modulus
from femgear.physics.geometry.gear import GearPair
from femgear.physics.mesh.section import gear_section

E, NU = 210e9, 0.3


@pytest.fixture(scope="module")
def section():
    p = GearPair.from_parameters(z1=20, z2=30, m_n=4e-3, alpha_n=math.radians(20), beta=0.1, b=0.02, x1=0.0, x2=0.0)
    return gear_section(p, 1, h=1e-3, n_teeth=3)


@pytest.mark.parametrize("plane", ["stress", "strain"])
def test_stiffness_symmetric_with_rigid_body_kernel(section, plane):
    prob = ElasticProblem(section, E, NU, plane)
    K = prob.K
    assert abs(K - K.T).max() <= 1e-10 * abs(K).max()
    B = rigid_body_modes(prob.basis)
    scale = abs(K).max() * np.abs(B).max(axis=0)
    assert np.all(np.abs(K @ B).max(axis=0) <= 1e-9 * scale)
    # a non-rigid field is not in the kernel
    v = prob.basis.doflocs[0] ** 2
    assert np.abs(K @ v).max() > 1e-6 * abs(K).max() * np.abs(v).max()


def test_named_boundaries(section):
    assert set(section.boundaries) == {"flank", "fillet", "tip", "bore", "sides"}
    for facets in section.boundaries.values():
        assert facets.size > 0
    all_b = np.concatenate(list(section.boundaries.values()))
    assert np.unique(all_b).size == all_b.size == section.boundary_facets().size


def test_lame_and_thermal_moduli():
    lam, mu = lame(E, NU, "stress")
    assert 2 * (lam + mu) == pytest.approx(E / (1 - NU))
    assert thermal_modulus(E, NU, 1e-5, "strain") == pytest.approx(E * 1e-5 / (1 - 2 * NU))
    with pytest.raises(ValueError, match="plane"):
        lame(E, NU, "axisymmetric")


def test_cantilever_matches_timoshenko_beam():
    """Tooth-like beam (L/h = 3): tip deflection vs PL³/(3EI) + PL/(κGA), κ = 5/6, within 3 %."""
    from skfem import FacetBasis, MeshTri

    from femgear.physics.body.forms import traction

    L, c = 9e-3, 1.5e-3
    mesh = MeshTri.init_tensor(np.linspace(0, L, 61), np.linspace(-c, c, 21)).with_boundaries(
        {"clamp": lambda x: x[0] < 1e-12, "end": lambda x: x[0] > L - 1e-12})
    prob = ElasticProblem(mesh, E, NU, "stress", order=2)
    prob.fix(prob.basis.get_dofs(mesh.boundaries["clamp"]).flatten(), 0.0)
    P = 1e5  # N per metre of width
    fb = FacetBasis(mesh, prob.basis.elem, facets=mesh.boundaries["end"])
    y = fb.global_coordinates()[1]
    f = traction.assemble(fb, tx=0.0 * y, ty=-P * 3 / (4 * c) * (1 - (y / c) ** 2))   # parabolic shear
    u, info = prob.solve(f)
    tip = -u[prob.nearest_dof((L, 0.0), "y")]
    I, A = (2 * c) ** 3 / 12, 2 * c
    G = E / (2 * (1 + NU))
    timo = P * L**3 / (3 * E * I) + P * L / (5 / 6 * G * A)
    assert tip == pytest.approx(timo, rel=0.03)
    assert info.iterations < 100


def test_a_thin_part_is_its_thickness_times_plane_stress():
    """``thin`` = (mask, t): the masked elements get t times the plane-stress stiffness (a disc t of the face width
    thick), the others keep theirs; a wrong mask or thickness is refused."""
    from skfem import MeshTri

    mesh = MeshTri.init_tensor(np.linspace(0, 4e-3, 9), np.linspace(0, 1e-3, 3))
    every = np.ones(mesh.t.shape[1], bool)
    stress = ElasticProblem(mesh, E, NU, "stress", order=1).K
    thin = ElasticProblem(mesh, E, NU, "strain", order=1, thin=(every, 0.25)).K
    assert abs(thin - 0.25 * stress).max() <= 1e-12 * abs(stress).max()
    none = ElasticProblem(mesh, E, NU, "strain", order=1, thin=(~every, 0.25)).K
    assert abs(none - ElasticProblem(mesh, E, NU, "strain", order=1).K).max() == 0.0
    with pytest.raises(ValueError, match="one entry per element"):
        ElasticProblem(mesh, E, NU, "strain", order=1, thin=(every[:-1], 0.25))
    with pytest.raises(ValueError, match="relative thickness"):
        ElasticProblem(mesh, E, NU, "strain", order=1, thin=(every, 1.5))
