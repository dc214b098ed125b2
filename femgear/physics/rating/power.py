"""Mesh (tooth-friction) power loss and efficiency along the path of contact.

At path position u the flank friction μ(u) w(u) per unit contact-line length slides at
v_s(u) = v1 − v2.  A flank point at face position ζ passes u once per mesh period, so the
time-mean loss of one helix is the path integral

    P_V = b / (p_bt cos β_b) ∫_A^E μ(u) w̄(u) |v_s(u)| du,

with w̄ the face-width mean load of :mod:`femgear.physics.contact.sharing` (the same weighting
gives b/(p_bt cos β_b) ∫ w̄ du = F_n).  ``density`` is the integrand times the number of
helices [W per m of path].  Efficiency η = 1 − P_V / (T1 ω1).

For constant μ and a spur pair with ideal load sharing (F/2 in the double-contact
zones, F in B–D) the integral is Ohlendorf's tooth loss factor, P_V = μ P_in H_V with
H_V = π (u + 1)/(z1 u cos β_b) (1 − ε_α + ε_1² + ε_2²)  (Ohlendorf 1958; ISO/TR 14179-2:2001
eq. 38; ε_1, ε_2 the addendum contact ratios of pinion and gear) — the test of this module.
Discontinuities of w̄ (B, D of a spur pair) are integrated exactly when the grid holds
both sides of the jump (:func:`femgear.physics.contact.path.zone_grid`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import trapezoid

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair


@document_fields
@dataclass(frozen=True)
class MeshPowerLoss:
    """Mesh power loss along the path and per mesh cycle (SI)."""

    u: np.ndarray
    """path positions [m]"""
    friction_coefficient: np.ndarray
    """μ(u) [-]"""
    line_load: np.ndarray
    """w̄(u) [N/m]"""
    sliding_speed: np.ndarray
    """|v_s(u)| [m/s]"""
    density: np.ndarray
    """time-mean loss per unit path length, all helices [W/m]"""
    mean_loss: float
    """P_V [W]"""
    input_power: float
    """T1 ω1 [W]"""
    energy_per_mesh_cycle: float
    """P_V / f_m [J]"""
    ohlendorf_HV: float
    """H_V of the geometry (reference for constant μ) [-]"""

    @property
    def efficiency(self) -> float:
        """η = 1 − P_V / P_in [-]."""
        return 1.0 - self.mean_loss / self.input_power

    @property
    def equivalent_mu(self) -> float:
        """The constant μ for which Ohlendorf's P_V = μ P_in H_V gives the same loss [-]."""
        return self.mean_loss / (self.input_power * self.ohlendorf_HV)


def ohlendorf_loss_factor(pair: GearPair) -> float:
    """H_V = π (u + 1)/(z1 u cos β_b) (1 − ε_α + ε_1² + ε_2²) (Ohlendorf; ISO/TR 14179-2)."""
    e1 = (pair.u_end - pair.u_pitch) / pair.p_bt
    e2 = (pair.u_pitch - pair.u_start) / pair.p_bt
    return math.pi * (pair.u + 1) / (pair.z1 * pair.u * math.cos(pair.beta_b)) * (1 - pair.eps_alpha + e1**2 + e2**2)


def mesh_power_loss(pair: GearPair, u: np.ndarray, mu: np.ndarray, line_load: np.ndarray, sliding_speed: np.ndarray,
                    pinion_torque: float, omega1: float) -> MeshPowerLoss:
    """Loss of ``pair`` from μ(u), w̄(u) [N/m], v_s(u) [m/s] on increasing positions ``u`` [m]."""
    u, mu, w, vs = (np.asarray(a, float) for a in (u, mu, line_load, sliding_speed))
    if not (u.shape == mu.shape == w.shape == vs.shape and u.ndim == 1 and u.size >= 2):
        raise ValueError("u, mu, line_load and sliding_speed must be 1-D arrays of one length ≥ 2")
    if np.any(np.diff(u) < 0):
        raise ValueError("u must be non-decreasing")
    if not (pinion_torque > 0 and omega1 > 0):
        raise ValueError(f"pinion_torque and omega1 must be positive, got {pinion_torque!r}, {omega1!r}")
    density = pair.n_helices * pair.b / (pair.p_bt * math.cos(pair.beta_b)) * mu * w * np.abs(vs)
    loss = float(trapezoid(density, u))
    f_mesh = pair.z1 * omega1 / (2 * math.pi)
    return MeshPowerLoss(u=u, friction_coefficient=mu, line_load=w, sliding_speed=np.abs(vs), density=density,
                         mean_loss=loss, input_power=pinion_torque * omega1, energy_per_mesh_cycle=loss / f_mesh,
                         ohlendorf_HV=ohlendorf_loss_factor(pair))
