"""Pressure and load maps of an LTCA cycle on the loaded flanks of both members, placed in mesh.

Each member's flank (tooth 0, both helices; the one helix of a single-helical or spur pair) is the surface of its LTCA member body
(:func:`femgear.physics.ltca.flank_map.helix_flank_quads`), turned about the member's own axis into its
meshing position (:func:`mesh_rotation`): the mesh frame has the pinion axis at the origin and
the gear axis at (a_w, 0), both along z (the body frames' z: left helix 0 … b, the right helix
b + g … 2b + g), and the two flanks touch along the contact line through the pitch point at
mid-face of the left helix (its point at ρ₁ = r_b1 tan α_wt, ζ = b/2 lies at (r_w1, 0, b/2)).
A body is only turned, never mirrored: the involutes of both members unwind in the same sense
about their axes, so one rotation per member brings every point of a contact line onto both
flanks with opposite normals (``tests/ltca/test_ltca_tool.py``).

Fields (per node of a (ρ, ζ) grid per helix, :func:`femgear.physics.ltca.flank_map.flank_pressure_map`; the
same contact-line loads on both members, at ρ₁ on the pinion and ρ₂ = T₁T₂ − ρ₁ on the gear):
``p_max`` the largest Hertz pressure over the cycle [Pa], ``w_mean`` the cycle mean of the load
per length [N/m], ``w_worst`` the load per length at the phase of the largest pressure [N/m],
``edge`` the border of the active flank, ``edge_contact`` a loaded node on it (the Hertz pressure
is not valid there: an edge contact).  Σ w_mean Δζ / cos β_b over a helix's grid is its
cycle-mean load (:meth:`LoadMaps.helix_force`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair


def mesh_rotation(pair: GearPair, member: int) -> float:
    """Angle [rad] that turns ``member``'s LTCA body frame about its axis into its meshing position."""
    from femgear.physics.ltca.flank import flank_points

    u = pair.rb1 * math.tan(pair.alpha_wt)
    rho = u if member == 1 else pair.line_of_action - u
    p = flank_points(pair, member, np.array([rho]), np.array([0.5 * pair.b]))[:, 0]
    target = 0.0 if member == 1 else math.pi        # the pitch point seen from the pinion / the gear axis
    return target - math.atan2(p[1], p[0])


def to_mesh(pair: GearPair, member: int, points: np.ndarray) -> np.ndarray:
    """Body-frame points (n, 3) of ``member`` in the mesh frame (turned by :func:`mesh_rotation`, the gear's
    axis moved to (a_w, 0))."""
    a = mesh_rotation(pair, member)
    c, s = math.cos(a), math.sin(a)
    p = np.asarray(points, float)
    out = np.column_stack([c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1], p[:, 2]])
    if member == 2:
        out[:, 0] += pair.a_w
    return out


@document_fields
@dataclass(frozen=True)
class MemberMap:
    """One member's flank surface in mesh with its fields per point (index order [helix, i_ρ, i_ζ])."""

    member: int
    """1 pinion, 2 gear [-]"""
    points: np.ndarray
    """(n, 3) in the mesh frame [m]"""
    quads: np.ndarray
    """(m, 4) point indices of the flank quadrilaterals [-]"""
    fields: dict
    """name -> (n,) array at the points: p_max [Pa]; w_mean, w_worst [N/m]; rho, zeta, u [m]; helix, edge,
    edge_contact [-] [Pa, N/m, m or -: by name]"""


@document_fields
@dataclass(frozen=True)
class LoadMaps:
    """The maps of both members at one torque."""

    torque: float
    """the pinion torque of the maps [N m]"""
    worst_phase: float
    """phase of ``w_worst`` [base pitches]"""
    rho: np.ndarray
    """pinion roll distance grid [m]"""
    zeta: np.ndarray
    """face grid of a helix [m]"""
    beta_b: float
    """base helix angle of the pair [rad]"""
    members: tuple[MemberMap, MemberMap]
    """pinion and gear maps [-]"""

    def helix_force(self, member: int) -> np.ndarray:
        """(left, right) cycle-mean normal load from ``member``'s map, Σ w_mean Δζ / cos β_b [N] ((left,) for a
        one-helix pair)."""
        w = self.members[member - 1].fields["w_mean"].reshape(-1, self.rho.size, self.zeta.size)
        return np.trapezoid(w, self.zeta, axis=2).sum(axis=1) / math.cos(self.beta_b)


def load_maps(result, pair: GearPair, youngs_modulus: float, poisson_ratio: float, torque: float, worst: int,
              groove: float = 0.0, stagger: float = 0.0, n_rho: int = 40, n_z: int = 60) -> LoadMaps:
    """:class:`LoadMaps` of the cycle ``result`` (keep_lines=True); ``worst`` the phase index of ``w_worst``."""
    from femgear.physics.ltca.flank_map import flank_pressure_map, helix_flank_quads
    from femgear.physics.ltca.te import one_phase

    fmap = flank_pressure_map(result, pair, youngs_modulus, poisson_ratio, n_rho, n_z)
    snap = flank_pressure_map(one_phase(result, worst), pair, youngs_modulus, poisson_ratio, n_rho, n_z)
    R, Z = np.meshgrid(fmap.rho, fmap.zeta, indexing="ij")
    n_h = fmap.p_max.shape[0]
    edge = np.tile(fmap.edge.ravel(), n_h)
    p_max = fmap.p_max.reshape(-1)
    members = []
    for member in (1, 2):
        rho = fmap.rho if member == 1 else pair.line_of_action - fmap.rho
        pts, quads = helix_flank_quads(pair, member, rho, fmap.zeta, groove, stagger)
        fields = {"p_max": p_max, "w_mean": fmap.w_mean.reshape(-1), "w_worst": snap.w_mean.reshape(-1),
                  "rho": np.tile((R if member == 1 else pair.line_of_action - R).ravel(), n_h),
                  "u": np.tile(R.ravel(), n_h), "zeta": np.tile(Z.ravel(), n_h),
                  "helix": np.repeat(np.arange(n_h), R.size).astype(np.int32), "edge": edge.astype(np.int32),
                  "edge_contact": (edge & (p_max > 0)).astype(np.int32)}
        members.append(MemberMap(member, to_mesh(pair, member, pts), quads, fields))
    return LoadMaps(float(torque), float(result.phase[worst]), fmap.rho, fmap.zeta, pair.beta_b, tuple(members))


__all__ = ["LoadMaps", "MemberMap", "load_maps", "mesh_rotation", "to_mesh"]
