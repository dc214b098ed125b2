"""The pressure map of an LTCA cycle on the 3-D pinion flanks of both helices, and their tessellation (written by :mod:`femgear.edge.io.ltca`).

A single-helical or spur pair has one helix (``LTCAResult.n_helices``): its maps and quads hold that helix alone.

The loaded flank of the pinion's tooth 0 of each helix is tessellated on a (ρ, ζ) grid (ρ the
roll distance over the active flank, ζ the helix's own face coordinate, the groove at ζ = b).
The grid's 3-D points are those of the member body the LTCA solves
(:func:`femgear.physics.mesh.segment.member_body`): on the left helix the helicoid of
:func:`femgear.physics.ltca.flank.flank_points`, on the right helix the same (ρ, ζ) mirrored to
z = 2b + g − ζ and turned by the stagger angle (:meth:`femgear.physics.mesh.segment.HelixFrame.to_right`).

Every contact line of every phase (``LTCAResult.line_load``: helix, line, u, ζ, w) is
interpolated along ζ onto the grid columns it crosses (u = ρ₁ on the line, u(ζ) linear with
slope tan β_b, w linear between the line's points) and dropped on the nearest ρ node.  Each
node then carries ``p_max``, the largest Hertz pressure √(w E′/(2πR)) over the cycle
(:func:`femgear.physics.ltca.halfspace.hertz_pressure`, R the normal relative radius of curvature at u),
and ``w_mean``, the cycle mean of the load per length there [N/m]; Σ w_mean Δζ / cos β_b over a
helix's grid is its cycle-mean load (:meth:`FlankMap.helix_force`), a check that the map holds the
LTCA's loads.

Validity flag.  The Hertz line-contact pressure assumes a contact line far from the edges of the
flank.  Where a contact line ends on the tip edge, the start of the active profile or a face end,
its last short piece can carry many times the mean load per length (up to 30×; on the unmodified
baseline the tip/face-end corner reads 7.2 GPa against a 0.5 GPa median): an edge contact, whose
pressure the Hertz formula does not give (it needs an edge-contact or 3-D half-space solution).
The nodes on the border of the active flank grid carry ``edge`` = 1 (:attr:`FlankMap.edge`), so
such values are flagged, not silently shown as Hertz pressures.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FlankMap:
    """Pressure and load maps on the pinion's loaded flanks, index [helix (0 left, 1 right; one-helix pairs: 0), i_ρ, i_ζ]."""

    rho: np.ndarray      #: roll distance grid [m]
    zeta: np.ndarray     #: face coordinate grid of a helix [m]
    p_max: np.ndarray    #: largest Hertz pressure over the cycle [Pa]
    w_mean: np.ndarray   #: cycle mean of the load per length [N/m]
    beta_b: float        #: base helix angle [rad]

    @property
    def edge(self) -> np.ndarray:
        """(n_ρ, n_ζ) bool: the grid's border, the tip / start-of-active-profile edges and the face ends (Hertz invalid)."""
        e = np.zeros((self.rho.size, self.zeta.size), bool)
        e[[0, -1], :] = True
        e[:, [0, -1]] = True
        return e

    def helix_force(self) -> np.ndarray:
        """Cycle-mean normal load of each helix from the map, Σ w_mean Δζ / cos β_b (trapezoid in ζ) [N]."""
        return np.trapezoid(self.w_mean, self.zeta, axis=2).sum(axis=1) / math.cos(self.beta_b)


def _line_samples(pair, u: np.ndarray, zeta: np.ndarray, w: np.ndarray, dl: np.ndarray, grid_z: np.ndarray):
    """(u, ζ, w) of one contact line at the grid's ζ nodes it covers (its points are segment centres of length Δℓ)."""
    order = np.argsort(zeta)
    u, zeta, w, dl = u[order], zeta[order], w[order], dl[order]
    half = 0.5 * math.cos(pair.beta_b)
    lo, hi = zeta[0] - half * dl[0], zeta[-1] + half * dl[-1]
    z = grid_z[(grid_z >= lo - 1e-12) & (grid_z <= hi + 1e-12)]
    return u[0] + (z - zeta[0]) * math.tan(pair.beta_b), z, np.interp(z, zeta, w)


def flank_pressure_map(result, pair, youngs_modulus: float, poisson_ratio: float, n_rho: int = 40,
                       n_z: int = 60) -> FlankMap:
    """The :class:`FlankMap` of the pinion's helices (both, or the one of ``result.n_helices`` = 1) from
    ``result.line_load`` (keep_lines=True)."""
    from femgear.physics.ltca.flank import roll_range
    from femgear.physics.ltca.halfspace import hertz_pressure, reduced_modulus

    if not result.line_load:
        raise ValueError("result has no line loads: run mesh_cycle(..., keep_lines=True)")
    r0, r1 = roll_range(pair, 1)
    rho = np.linspace(r0, r1, n_rho)
    zeta = np.linspace(0.0, pair.b, n_z)
    n_h = getattr(result, "n_helices", 2)
    pmax = np.zeros((n_h, n_rho, n_z))
    wsum = np.zeros((n_h, n_rho, n_z))
    cb = math.cos(pair.beta_b)
    Ep = reduced_modulus(youngs_modulus, poisson_ratio)
    for arr, dl in zip(result.line_load, result.line_length):
        for h in range(n_h):
            for j in np.unique(arr[arr[:, 0] == h, 1]):
                m = (arr[:, 0] == h) & (arr[:, 1] == j)
                u, z, w = _line_samples(pair, arr[m, 2], arr[m, 3], arr[m, 4], dl[m], zeta)
                R = u * (pair.line_of_action - u) / pair.line_of_action / cb
                i = np.clip(np.rint((u - r0) / (r1 - r0) * (n_rho - 1)).astype(int), 0, n_rho - 1)
                k = np.clip(np.rint(z / pair.b * (n_z - 1)).astype(int), 0, n_z - 1)
                np.maximum.at(pmax[h], (i, k), hertz_pressure(w, R, Ep))
                np.add.at(wsum[h], (i, k), w)
    return FlankMap(rho, zeta, pmax, wsum / len(result.line_load), pair.beta_b)


def helix_flank_quads(pair, member: int, rho: np.ndarray, zeta: np.ndarray, groove: float = 0.0,
                      stagger: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Points (n_h n m, 3) and quads of the loaded flank of ``member``'s tooth 0, every helix of ``pair``
    (n_h = ``pair.n_helices``), on the grid ``rho`` (n,) × ``zeta`` (m,) (index order [helix, i_ρ, i_ζ]): the left
    helix on the helicoid of :func:`femgear.physics.ltca.flank.flank_points`, the right one the same (ρ, ζ) through
    :meth:`femgear.physics.mesh.segment.HelixFrame.to_right` (body frame of the LTCA's member body)."""
    from femgear.physics.ltca.flank import flank_points
    from femgear.physics.mesh.segment import frame_of

    R, Z = np.meshgrid(np.asarray(rho, float), np.asarray(zeta, float), indexing="ij")
    left = flank_points(pair, member, R.ravel(), Z.ravel())
    nr, nz = R.shape
    idx = np.arange(nr * nz).reshape(nr, nz)
    quads = np.column_stack([idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()])
    if pair.n_helices == 1:
        return left.T, quads
    frame = frame_of(pair, member, groove, stagger)
    pts = np.hstack([left, frame.to_right(left)]).T
    return pts, np.vstack([quads, quads + nr * nz])

