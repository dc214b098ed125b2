"""Degrees of freedom, frames and rigid-body kinematics of the double-helical pair.

Frame (SI): shafts parallel to the global z axis; the pinion's bearing axis is the z
axis, the gear's is at (a_w, 0) — the line of centres is the +x axis.  The pinion
turns counter-clockwise (+z) and drives; the gear turns clockwise.  All rotations
θx, θy, θz are right-handed about the global axes (not per member), so the paper's
"R_p θ_p + R_g θ_g" appears here as r_b1 θz1 + r_b2 θz2 because the line of action
is taken on the side where both terms carry a + sign.

Bodies (full model, 24 DOF), each (x, y, z, θx, θy, θz):
    0 pinion-L, 1 pinion-R, 2 gear-L, 3 gear-R.
The left helix sits at z = −s/2, the right at +s/2 (s = b + groove, the distance of
the helix centres); left has hand sign σ = +1, right σ = −1.
"""

from __future__ import annotations

import numpy as np

BODIES = ("pinion_L", "pinion_R", "gear_L", "gear_R")
DIRECTIONS = ("x", "y", "z", "rx", "ry", "rz")
NDOF = 24


def dof(body: str | int, direction: str) -> int:
    """Index of ``direction`` of ``body`` in the full 24-DOF vector."""
    b = BODIES.index(body) if isinstance(body, str) else int(body)
    return 6 * b + DIRECTIONS.index(direction)


def skew(r: np.ndarray) -> np.ndarray:
    """Matrix [r]× with [r]× a = r × a."""
    x, y, z = r
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def point_jacobian(r: np.ndarray) -> np.ndarray:
    """3×6 map of a body's (d, θ) to the displacement d + θ × r of a point at offset r."""
    return np.hstack([np.eye(3), -skew(np.asarray(r, dtype=float))])


def tie_matrix(half_spacing: float) -> np.ndarray:
    """24×12 map of two rigid members (6 DOF each, at their centres) to the four halves.

    Each member is rigid: its halves at z = ∓ half_spacing move as points of one body
    (rotations equal, translations d + θ × (0, 0, ∓h)).  This is the ``lumped``
    level's rigid shaft between the halves.
    """
    T = np.zeros((NDOF, 12))
    for member in range(2):
        for side, zc in enumerate((-half_spacing, +half_spacing)):
            rows = slice(6 * (2 * member + side), 6 * (2 * member + side) + 6)
            block = np.zeros((6, 6))
            block[:3] = point_jacobian(np.array([0.0, 0.0, zc]))
            block[3:, 3:] = np.eye(3)
            T[rows, 6 * member: 6 * member + 6] = block
    return T
