"""Structure of the gear-rotor model: half bodies, bearings and shafts (level by level).

- ``lumped``: the halves of a member are tied rigidly (a rigid shaft), integrated in the
  12 rigid-member coordinates (full = T q, T from :func:`femgear.system.dynamics.layout.tie_matrix`);
  bearing springs/dashpots at the stations z_L, z_R on the rigid member.
- ``timoshenko``: per member the bearing nodes and the mesh stations, sorted along z (a
  straddle mounting: bearing-L, half-L, half-R, bearing-R; an overhung one: the station(s) beyond
  both bearings), joined by Timoshenko elements (:mod:`femgear.system.dynamics.timoshenko`),
  bearing springs at the bearing nodes, which are then condensed statically (Guyan) onto the mesh
  stations: the 24 DOF of the four halves of a double-helical pair, the 12 of a spur or
  single-helical pair's two bodies (one mesh station each, in the mid-plane of its face).

Bearing stations (the scene's ``bearing_span`` and ``face_offset``,
:func:`femgear.case.checks.bearing_stations`): z_L, z_R = −face_offset ∓ bearing_span/2 in the member's
frame, whose toothed face is centred at z = 0 (default: symmetric, ±bearing_span/2).

Half bodies: mass m/2, polar inertia I/2, diametral inertia I/4 + (m/2) b²/12 (thin
solid disc of the helix width b) — the scene gives only m and I per member.  Bearings:
the scene's support stiffness and damping per direction (axially ``axial_stiffness`` /
``axial_damping`` where given: the thrust bearings of a single helix), split equally
over the two bearings of a member, the axial part on the ``thrust_bearing`` alone where the
scene names one; they do not restrain θz (the member rotates).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.errors import SceneError
from femgear.physics.geometry import GearPair
from femgear.scene.schema import Material, Member
from femgear.system.dynamics.layout import NDOF, point_jacobian, tie_matrix
from femgear.system.dynamics.timoshenko import ShaftSection, guyan, shaft_element

#: the four bearing stations, in the order of every (4, …) bearing array
STATIONS = ("pinion_L", "pinion_R", "gear_L", "gear_R")


@dataclass(frozen=True)
class Bearings:
    """The four bearing stations (:data:`STATIONS`): a linear spring and dashpot per direction x, y (radial) and
    z (axial) between the shaft and the rigid housing; none restrains a rotation."""

    stiffness: np.ndarray    #: (4, 3) spring per station and direction x, y, z [N/m]
    damping: np.ndarray      #: (4, 3) dashpot per station and direction [N s/m]
    z: np.ndarray            #: (4,) axial station position in its member's frame (face centre at 0) [m]
    centre: np.ndarray       #: (4, 3) the station's point on the shaft axis in the model frame [m]


@dataclass(frozen=True)
class Structure:
    M: np.ndarray            #: reduced mass matrix
    K: np.ndarray            #: reduced structural stiffness (bearings + shafts)
    C: np.ndarray            #: reduced bearing damping
    T: np.ndarray            #: (24, n): full = T @ reduced
    bearing_map: np.ndarray  #: (12, n): displacements of the four bearing stations
    M24: np.ndarray          #: 24×24 diagonal mass of the halves (before any shaft mass)
    bearings: Bearings       #: springs, dashpots and positions of the stations


def require_positive(value: float, key: str) -> float:
    if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
        raise SceneError(key, f"must be positive (got {value!r})")
    return float(value)


def _half_bodies(members: tuple[Member, Member], pair: GearPair) -> np.ndarray:
    """Diagonal 24×24 mass matrix of the four halves."""
    M = np.zeros(NDOF)
    for member, (name, mem) in enumerate(zip(("pinion", "gear"), members)):
        m = require_positive(mem.mass, f"{name}.mass") / 2
        Ip = require_positive(mem.inertia, f"{name}.inertia") / 2
        Id = Ip / 2 + m * pair.b**2 / 12
        for side in range(2):
            b = 6 * (2 * member + side)
            M[b:b + 3] = m
            M[b + 3:b + 5] = Id
            M[b + 5] = Ip
    return np.diag(M)


def _station_springs(members: tuple[Member, Member]) -> tuple[np.ndarray, np.ndarray]:
    """(4, 3) spring and dashpot of each station along x, y, z: half the member's radial support each; the axial
    support on both stations (half each) or on the member's ``thrust_bearing`` alone."""
    K, C = np.zeros((4, 3)), np.zeros((4, 3))
    for member, (name, mem) in enumerate(zip(("pinion", "gear"), members)):
        k = require_positive(mem.support_stiffness, f"{name}.support_stiffness")
        if mem.support_damping < 0:
            raise SceneError(f"{name}.support_damping", "must be non-negative")
        k_ax = getattr(mem, "axial_stiffness", None)           # thrust bearings (single helix), else the radial value
        c_ax = getattr(mem, "axial_damping", None)
        c = mem.support_damping
        share = {"both": (0.5, 0.5), "left": (1.0, 0.0), "right": (0.0, 1.0)}[getattr(mem, "thrust_bearing", "both")]
        for side in range(2):
            j = 2 * member + side
            K[j] = (k / 2, k / 2, (k if k_ax is None else k_ax) * share[side])
            C[j] = (c / 2, c / 2, (c if c_ax is None else c_ax) * share[side])
    return K, C


def assemble_structure(members: tuple[Member, Member], material: Material, pair: GearPair, shaft_elements: bool,
                       stations: tuple[tuple[float, float], tuple[float, float]], shaft_diameter: tuple[float, float],
                       half: float) -> Structure:
    """The structure with Timoshenko ``shaft_elements`` between the mesh stations and the bearings (the
    ``timoshenko`` level) or without (``lumped``: the halves tied rigidly per member).

    ``members``: the scene's ``[pinion]``, ``[gear]`` tables; ``stations``: (z_L, z_R) of each member's
    bearings in its frame (:func:`femgear.case.checks.bearing_stations`), ``shaft_diameter`` (pinion, gear) [m];
    ``half``: z of the helix centres (±half; 0 for a pair with one mesh, whose two halves are one body at
    its mesh station).
    """
    M24 = _half_bodies(members, pair)
    Kb, Cb = _station_springs(members)
    zb = np.array(stations, dtype=float).ravel()
    if not shaft_elements:
        T, M, K, C, bearing_map = _rigid_members(M24, Kb, Cb, zb, half)
    else:
        sections = [ShaftSection(require_positive(d, f"{name}.shaft_diameter"), material.youngs_modulus,
                                 material.poisson_ratio, material.density)
                    for name, d in zip(("pinion", "gear"), shaft_diameter)]
        T, M, K, C, bearing_map = _shaft_members(M24, Kb, Cb, zb, half, sections)
    bearings = Bearings(stiffness=Kb, damping=Cb, z=zb,
                        centre=np.column_stack([[0.0, 0.0, pair.a_w, pair.a_w], np.zeros(4), zb]))
    return Structure(M=M, K=K, C=C, T=T, bearing_map=bearing_map, M24=M24, bearings=bearings)


def _rigid_members(M24, Kb, Cb, zb, half):
    """``lumped``: 12 rigid-member coordinates, the bearing stations points of the rigid members at ``zb``."""
    T = tie_matrix(half)
    M = T.T @ M24 @ T
    K, C, bearing_map = np.zeros((12, 12)), np.zeros((12, 12)), np.zeros((12, 12))
    for j in range(4):
        sl = slice(6 * (j // 2), 6 * (j // 2) + 6)
        J = point_jacobian(np.array([0.0, 0.0, zb[j]]))
        K[sl, sl] += J.T @ np.diag(Kb[j]) @ J
        C[sl, sl] += J.T @ np.diag(Cb[j]) @ J
        bearing_map[3 * j: 3 * j + 3, sl] = J
    return T, M, K, C, bearing_map


def _shaft_members(M24, Kb, Cb, zb, half, sections):
    """``timoshenko``: per member one Timoshenko element between neighbouring nodes (the bearings and the mesh
    stations, sorted along z), the bodies' mass at the mesh stations, bearing springs at the bearing nodes,
    which are condensed (Guyan) onto the mesh stations: the 24 DOF of the four halves (two stations per
    member), or the 12 of the two one-mesh bodies (one station each, full = tie(0) reduced)."""
    two = half > 0
    mesh_z = (-half, half) if two else (0.0,)
    per_member = 2 + len(mesh_z)                   # nodes
    nd = 6 * per_member * 2
    Kfull, Mfull, Cfull = np.zeros((nd, nd)), np.zeros((nd, nd)), np.zeros((nd, nd))
    keep, bearing_nodes = [], []
    for member, sec in enumerate(sections):
        zs = [(zb[2 * member], "L"), (zb[2 * member + 1], "R")] + [(z, s) for s, z in enumerate(mesh_z)]
        order = sorted(range(per_member), key=lambda i: zs[i][0])
        base = 6 * per_member * member
        node = {zs[i][1]: base + 6 * k for k, i in enumerate(order)}        # label → first DOF of its node
        for e in range(per_member - 1):
            Ke, Me = shaft_element(sec, zs[order[e + 1]][0] - zs[order[e]][0])
            idx = np.arange(base + 6 * e, base + 6 * e + 12)
            Kfull[np.ix_(idx, idx)] += Ke
            Mfull[np.ix_(idx, idx)] += Me
        for s in range(len(mesh_z)):
            n0 = node[s]
            bodies = (2 * member + s,) if two else (2 * member, 2 * member + 1)   # one station: both halves
            for body in bodies:
                Mfull[n0:n0 + 6, n0:n0 + 6] += M24[6 * body:6 * body + 6, 6 * body:6 * body + 6]
            keep.extend(range(n0, n0 + 6))
        for side, label in enumerate("LR"):
            n0, j = node[label], 2 * member + side
            Kfull[n0:n0 + 3, n0:n0 + 3] += np.diag(Kb[j])
            Cfull[n0:n0 + 3, n0:n0 + 3] += np.diag(Cb[j])
            bearing_nodes.append(n0)
    K, M, Tg = guyan(Kfull, Mfull, np.array(keep))
    T = np.eye(NDOF) if two else tie_matrix(0.0)
    return T, M, K, Tg.T @ Cfull @ Tg, np.vstack([Tg[n0:n0 + 3] for n0 in bearing_nodes])
