"""Structure of the gear-rotor model: half bodies, bearings and shafts (level by level).

- ``lumped``: the halves of a member are tied rigidly (a rigid shaft), integrated in the
  12 rigid-member coordinates (full = T q, T from :func:`femgear.system.dynamics.layout.tie_matrix`);
  bearing springs/dashpots at z = ±bearing_span/2 on the rigid member.
- ``timoshenko``: per member the nodes bearing-L, half-L, half-R, bearing-R joined by
  three Timoshenko elements (:mod:`femgear.system.dynamics.timoshenko`), bearing springs at the
  bearing nodes, which are then condensed statically (Guyan) onto the 24 DOF of the halves.

Half bodies: mass m/2, polar inertia I/2, diametral inertia I/4 + (m/2) b²/12 (thin
solid disc of the helix width b) — the scene gives only m and I per member.  Bearings:
the scene's support stiffness and damping per direction (axially ``axial_stiffness`` /
``axial_damping`` where given: the thrust bearings of a single helix), split equally
over the two bearings of a member; they do not restrain θz (the member rotates).
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


def assemble_structure(members: tuple[Member, Member], material: Material, pair: GearPair, shaft_elements: bool,
                       bearing_span: tuple[float, float], shaft_diameter: tuple[float, float],
                       half: float) -> Structure:
    """The structure with Timoshenko ``shaft_elements`` between helix halves and bearings (the ``timoshenko``
    level) or without (``lumped``: the halves tied rigidly per member); ``half`` = z of the helix centres.

    ``members``: the scene's ``[pinion]``, ``[gear]`` tables; ``bearing_span`` and
    ``shaft_diameter`` are (pinion, gear) values [m].
    """
    M24 = _half_bodies(members, pair)
    Kb_list, Cb_list = [], []          # per bearing station, directions x, y, z
    for name, mem in zip(("pinion", "gear"), members):
        k = require_positive(mem.support_stiffness, f"{name}.support_stiffness")
        if mem.support_damping < 0:
            raise SceneError(f"{name}.support_damping", "must be non-negative")
        k_ax = getattr(mem, "axial_stiffness", None)           # thrust bearings (single helix), else the radial value
        c_ax = getattr(mem, "axial_damping", None)
        Kb_list.append(np.diag([k, k, k if k_ax is None else k_ax]) / 2)
        c = mem.support_damping
        Cb_list.append(np.diag([c, c, c if c_ax is None else c_ax]) / 2)

    if not shaft_elements:
        T = tie_matrix(half)
        M = T.T @ M24 @ T
        K = np.zeros((12, 12))
        Cb = np.zeros((12, 12))
        bearing_map = np.zeros((12, 12))
        for member in range(2):
            sl = slice(6 * member, 6 * member + 6)
            zb = bearing_span[member] / 2
            for j, z in enumerate((-zb, zb)):
                J = point_jacobian(np.array([0.0, 0.0, z]))
                K[sl, sl] += J.T @ Kb_list[member] @ J
                Cb[sl, sl] += J.T @ Cb_list[member] @ J
                row = 3 * (2 * member + j)
                bearing_map[row:row + 3, sl] = J
    else:
        # per member nodes: bearing_L, half_L, half_R, bearing_R → 4 × 6 DOF
        Kfull = np.zeros((48, 48))
        Mfull = np.zeros((48, 48))
        Cfull = np.zeros((48, 48))
        keep, bearing_nodes = [], []
        for member in range(2):             # pinion, gear
            sec = ShaftSection(require_positive(shaft_diameter[member], "shaft_diameter"), material.youngs_modulus,
                               material.poisson_ratio, material.density)
            zb = bearing_span[member] / 2
            zs = (-zb, -half, half, zb)
            base = 24 * member
            for e in range(3):
                Ke, Me = shaft_element(sec, zs[e + 1] - zs[e])
                idx = np.arange(base + 6 * e, base + 6 * e + 12)
                Kfull[np.ix_(idx, idx)] += Ke
                Mfull[np.ix_(idx, idx)] += Me
            for side in range(2):
                node = base + 6 * (1 + side)
                body = 6 * (2 * member + side)
                Mfull[node:node + 6, node:node + 6] += M24[body:body + 6, body:body + 6]
                keep.extend(range(node, node + 6))
            for node in (base, base + 18):
                for d in range(3):
                    Kfull[node + d, node + d] += Kb_list[member][d, d]
                    Cfull[node + d, node + d] += Cb_list[member][d, d]
                bearing_nodes.append(node)
        K, M, Tg = guyan(Kfull, Mfull, np.array(keep))
        Cb = Tg.T @ Cfull @ Tg
        T = np.eye(NDOF)
        bearing_map = np.vstack([Tg[node:node + 3] for node in bearing_nodes])
    zb = np.array([[-bearing_span[m] / 2, bearing_span[m] / 2] for m in range(2)]).ravel()
    bearings = Bearings(stiffness=np.array([np.diag(Kb_list[j // 2]) for j in range(4)]),
                        damping=np.array([np.diag(Cb_list[j // 2]) for j in range(4)]), z=zb,
                        centre=np.column_stack([[0.0, 0.0, pair.a_w, pair.a_w], np.zeros(4), zb]))
    return Structure(M=M, K=K, C=Cb, T=T, bearing_map=bearing_map, M24=M24, bearings=bearings)
