"""The fields of a thermo-elastic section at its vertices and triangles (what the writers show).

:func:`section_fields` reduces a :class:`femgear.physics.body.thermal.ThermoElasticResult` to plain
arrays: the temperature rise and the displacement at the mesh vertices (the P2 fields' nodal values)
and the element-mean von Mises stress.  File output: :func:`femgear.edge.io.fields.body_mesh`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields


@document_fields
@dataclass(frozen=True)
class BodySection:
    """One member's FE gear section with its fields, in the member's own frame (axis at the origin)."""

    member: int
    """1 pinion, 2 gear [-]"""
    points: np.ndarray
    """(n, 2) vertex coordinates of the section [m]"""
    triangles: np.ndarray
    """(m, 3) vertex indices of the linear triangles [-]"""
    temperature_rise: np.ndarray
    """(n,) temperature rise at the vertices [K]"""
    displacement: np.ndarray
    """(n, 2) thermo-elastic displacement at the vertices [m]"""
    von_mises: np.ndarray
    """(m,) element-mean von Mises stress [Pa]"""


def section_fields(result, member: int, youngs_modulus: float, poisson_ratio: float,
                   expansion: float) -> BodySection:
    """The :class:`BodySection` of ``result`` (:class:`femgear.physics.body.thermal.ThermoElasticResult`)."""
    mesh = result.mesh
    nv = mesh.p.shape[1]
    dofs_T = result.basis_T.nodal_dofs
    T = result.T[dofs_T[0]] if dofs_T.shape[0] == 1 else result.T[:nv]
    u = result.u[result.basis_u.nodal_dofs]
    return BodySection(member=member, points=np.asarray(mesh.p.T, float), triangles=np.asarray(mesh.t.T),
                       temperature_rise=np.asarray(T, float), displacement=np.column_stack([u[0], u[1]]),
                       von_mises=np.asarray(result.von_mises(youngs_modulus, poisson_ratio, expansion), float))


__all__ = ["BodySection", "section_fields"]
