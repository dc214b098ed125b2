"""Hand statics of a gear pair on two bearings per member (independent of femgear's dynamics model).

Each helix h transmits the tangential force F_t,h = T_1/(r_w1 n_h) at its pitch point (r_w1, 0, z_h) of the
pinion frame (gear axis at (a_w, 0)), with the radial force F_r = F_t tan α_wt and the axial force
F_a = F_t tan β_w (tan β_w = tan β r_w/r, ISO 21771).  On the pinion they act along −x (away from the gear),
−y (against its counter-clockwise rotation) and −σ_h z (σ = +1 left-hand helix); the gear takes the opposite.
The two radial bearings of a member at z_A, z_B on its axis carry no moment: their radial loads follow from
the force and moment balance of the shaft (statically determinate whatever the shaft's stiffness), with the
moment of the axial force at the pitch radius r_w included; the axial loads sum to the axial force.
"""

from __future__ import annotations

import math

import numpy as np


def mesh_force_on_pinion(pair, torque: float, sigma: int) -> np.ndarray:
    """(F_x, F_y, F_z) of one helix on the pinion [N] (``torque``: the pinion torque T_1 [N m])."""
    Ft = torque / (pair.rw1 * pair.n_helices)
    tan_bw = math.tan(pair.beta) * pair.rw1 / pair.r1
    return np.array([-Ft * math.tan(pair.alpha_wt), -Ft, -sigma * Ft * tan_bw])


def bearing_loads(pair, torque: float, helix_z, sigmas, bearing_z) -> np.ndarray:
    """(4, 3) loads on the bearings (pinion A, B, gear A, B; x, y radial, z the member's axial total split
    equally over its two bearings) [N].  ``helix_z``: the helix centres in each member's frame, ``bearing_z``:
    ((pinion z_A, z_B), (gear z_A, z_B)) [m]."""
    out = np.zeros((4, 3))
    for member, (sign, r_w) in enumerate(((1.0, pair.rw1), (-1.0, -pair.rw2))):   # pitch point at x = ±r_w
        zA, zB = bearing_z[member]
        Fx = Fy = Mx = My = Fz = 0.0
        for zh, sigma in zip(helix_z, sigmas):
            F = sign * mesh_force_on_pinion(pair, torque, sigma)
            Fx, Fy, Fz = Fx + F[0], Fy + F[1], Fz + F[2]
            My += zh * F[0] - r_w * F[2]          # (r × F)_y, r = (r_w, 0, z_h)
            Mx += -zh * F[1]                      # (r × F)_x
        A = np.array([[1.0, 1.0], [zA, zB]])
        Lx = np.linalg.solve(A, [Fx, My])         # Σ L_x = F_x, Σ z L_x = M_y
        Ly = np.linalg.solve(A, [Fy, -Mx])        # Σ L_y = F_y, −Σ z L_y = M_x
        out[2 * member: 2 * member + 2, 0] = Lx
        out[2 * member: 2 * member + 2, 1] = Ly
        out[2 * member: 2 * member + 2, 2] = Fz / 2
    return out
