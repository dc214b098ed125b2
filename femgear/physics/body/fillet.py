"""Tooth-root (fillet) stress of the 2-D FE gear section: femgear's own figure beside ISO 6336-3.

The member's transverse section (:class:`femgear.physics.body.compliance.ToothFE`: P2, plane strain,
bore clamped, graded mesh) carries the normal load per unit face width ``force`` at path
position ``u`` on the middle tooth's flank, along the line of action.  The stress field
σ = λ tr(ε) I + 2μ ε is evaluated at the quadrature points of the fillet facets of that
tooth; the largest in-plane principal stress there is the root stress (on the loaded side,
in tension).  Reported with its radius and the angle of the fillet tangent to the tooth
centre line at that point (ISO 6336-3 places the critical section at the 30° tangents).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.body.forms import lame
from femgear.physics.geometry.gear import GearPair


@document_fields
@dataclass(frozen=True)
class FilletStress:
    """Largest principal fillet stress of one member under one load (SI)."""

    member: int
    """the member: 1 pinion, 2 gear [-]"""
    u: float
    """load position on the path, measured from T1 [m]"""
    force: float
    """normal load per unit face width [N/m]"""
    max_principal: float
    """largest principal stress in the fillet [Pa]"""
    radius: float
    """radius of the maximum [m]"""
    tangent_angle: float
    """angle of the fillet tangent to the tooth centre line there [rad]"""
    mesh_size: float
    """h of the section mesh (h·refine_ratio near the tooth) [m]"""
    ndofs: int
    """degrees of freedom of the section's FE model [-]"""


def fillet_stress(pair: GearPair, member: int, u: float, force: float, youngs_modulus: float,
                  poisson_ratio: float, bore_radius: float = 0.0, h: float | None = None,
                  n_teeth: int | None = 5, refine_ratio: float = 0.2, support: str = "clamped") -> FilletStress:
    """Max principal stress on the fillet of ``member`` loaded by ``force`` [N/m] at path position ``u`` [m].

    ``support``: the bore's (:class:`femgear.physics.body.compliance.ToothFE`); ``"distributed"`` needs the whole
    gear (``n_teeth=None``): a sector's cut sides would be free."""
    from femgear.physics.body.compliance import ToothFE

    if not (force > 0 and math.isfinite(force)):
        raise ValueError(f"force must be positive and finite, got {force!r}")
    model = ToothFE(pair, member, youngs_modulus, poisson_ratio, h=h or pair.m_n / 5, n_teeth=n_teeth,
                    bore_radius=bore_radius, refine_ratio=refine_ratio, support=support)
    disp, _, _ = model.solve_load(u, force)
    mesh = model.mesh
    z = pair.z1 if member == 1 else pair.z2
    fp = fillet_principal(model, disp, youngs_modulus, poisson_ratio)
    on_tooth = np.abs(fp.polar) < math.pi / z
    k = np.unravel_index(int(np.argmax(np.where(on_tooth, fp.s1, -np.inf))), fp.s1.shape)
    x, y = float(fp.x[k]), float(fp.y[k])
    ends = mesh.p[:, mesh.facets[:, fp.facets[k[0]]]]
    t = ends[:, 1] - ends[:, 0]
    # tooth centre line through (x, y) points along the position vector's direction at the tooth (+Y axis)
    tangent = math.acos(min(1.0, abs(t[1]) / math.hypot(*t)))
    return FilletStress(member=member, u=float(u), force=float(force), max_principal=float(fp.s1[k]),
                        radius=math.hypot(x, y), tangent_angle=tangent, mesh_size=model.h, ndofs=model.ndofs)


@dataclass(frozen=True)
class FilletPrincipal:
    """In-plane principal stresses at the quadrature points of every fillet facet of a section (SI)."""

    facets: np.ndarray   #: fillet facet of each row
    x: np.ndarray        #: (n_facets, n_qp) coordinates [m]
    y: np.ndarray
    polar: np.ndarray    #: polar angle from the loaded tooth's centre line (+y) [rad]
    s1: np.ndarray       #: largest principal stress [Pa]
    s3: np.ndarray       #: smallest principal stress [Pa]


def fillet_principal(model, disp: np.ndarray, youngs_modulus: float, poisson_ratio: float) -> FilletPrincipal:
    """σ₁, σ₃ of the displacement ``disp`` of a :class:`~femgear.physics.body.compliance.ToothFE` on all its fillets
    (plane strain: σ = λ tr(ε) I + 2μ ε)."""
    from skfem import FacetBasis

    mesh = model.mesh
    facets = mesh.boundaries["fillet"]
    fb = FacetBasis(mesh, model.problem.basis.elem, facets=facets)
    grad = fb.interpolate(disp).grad                     # (2, 2, n_facets, n_qp)
    exx, eyy = grad[0, 0], grad[1, 1]
    exy = 0.5 * (grad[0, 1] + grad[1, 0])
    lam, mu = lame(youngs_modulus, poisson_ratio, "strain")
    tr = exx + eyy
    sxx, syy, sxy = lam * tr + 2 * mu * exx, lam * tr + 2 * mu * eyy, 2 * mu * exy
    mean, radius = 0.5 * (sxx + syy), np.sqrt((0.5 * (sxx - syy)) ** 2 + sxy**2)
    X, Y = fb.global_coordinates()
    return FilletPrincipal(facets=facets, x=np.asarray(X), y=np.asarray(Y), polar=np.arctan2(X, Y),
                           s1=mean + radius, s3=mean - radius)
