"""The loaded flank of a meshed helix segment as an analytic involute helicoid.

A flank point is addressed by its roll distance ρ (distance from the base-circle tangent
point along the transverse line of action, ρ = √(r² − r_b²)) and the face coordinate z of
the segment mesh.  The +X flank of tooth k at section z is the involute of the tooth
frame's y < 0 half, r(cos ψ(r), −sin ψ(r)) with ψ the half angular thickness
(:func:`femgear.physics.geometry.profile.involute_half_angle`), turned by π/2 + k·2π/z_teeth +
θ(z), θ(z) = hand · z tan β / r_ref (the twist of :mod:`femgear.physics.mesh.segment`).

Contact lines on that flank.  The base-tangent point of the involute point at roll t =
ρ/r_b lies at polar angle φ₀ + t (the +X flank unwinds counter-clockwise), so a fixed
plane of action meets section z where φ₀ + ρ/r_b + θ(z) is constant:
dρ/dz = −hand · r_b tan β / r_ref = −hand · tan β_b.  The flank normals along such a
line are parallel (tested).  Neighbouring teeth meet the same plane of action at
ρ_k = ρ_0 − k p_bt (tooth k counter-clockwise of tooth 0).
"""

from __future__ import annotations

import math

import numpy as np

from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.profile import involute_half_angle
from femgear.physics.mesh.segment import HAND


def base_radius(pair: GearPair, member: int) -> float:
    return pair.rb1 if member == 1 else pair.rb2


def roll_range(pair: GearPair, member: int) -> tuple[float, float]:
    """Active roll distances [ρ at the start of active profile, ρ at the tip] of ``member`` [m]."""
    if member == 1:
        return pair.u_start, pair.u_end
    return pair.line_of_action - pair.u_end, pair.line_of_action - pair.u_start


def flank_points(pair: GearPair, member: int, rho: np.ndarray, z: np.ndarray, tooth: int = 0) -> np.ndarray:
    """Points (3, n) of the loaded flank of ``tooth`` at roll distances ``rho`` and face coordinates ``z`` [m]."""
    rho, z = np.broadcast_arrays(np.asarray(rho, float), np.asarray(z, float))
    rb = base_radius(pair, member)
    nteeth = pair.z1 if member == 1 else pair.z2
    r = np.sqrt(rho**2 + rb**2)
    psi = involute_half_angle(pair, member, r)
    r_ref = nteeth * pair.m_t / 2
    turn = math.pi / 2 + tooth * 2 * math.pi / nteeth + HAND[member] * z * math.tan(pair.beta) / r_ref
    ang = turn - psi
    return np.vstack([(r * np.cos(ang)).ravel(), (r * np.sin(ang)).ravel(), z.ravel()])


def flank_normals(pair: GearPair, member: int, rho: np.ndarray, z: np.ndarray, tooth: int = 0) -> np.ndarray:
    """Outward unit normals (3, n) of the loaded flank (central differences of :func:`flank_points`)."""
    rho, z = np.broadcast_arrays(np.asarray(rho, float), np.asarray(z, float))
    e = 1e-6 * pair.m_n
    dr = flank_points(pair, member, rho + e, z, tooth) - flank_points(pair, member, rho - e, z, tooth)
    dz = flank_points(pair, member, rho, z + e, tooth) - flank_points(pair, member, rho, z - e, tooth)
    n = np.cross(dr.T, dz.T).T
    n /= np.linalg.norm(n, axis=0)
    p = flank_points(pair, member, rho, z, tooth)
    nteeth = pair.z1 if member == 1 else pair.z2
    r_ref = nteeth * pair.m_t / 2
    centre = math.pi / 2 + tooth * 2 * math.pi / nteeth + HAND[member] * z.ravel() * math.tan(pair.beta) / r_ref
    away = p[:2] - np.hypot(p[0], p[1]) * np.vstack([np.cos(centre), np.sin(centre)])
    sign = np.sign(np.sum(n[:2] * away, axis=0))
    return n * np.where(sign == 0, 1.0, sign)


def contact_line_slope(member: int, pair: GearPair) -> float:
    """dρ/dz of a contact line on the loaded flank of the meshed helix (−hand · tan β_b)."""
    return -HAND[member] * math.tan(pair.beta_b)


def half_thickness(pair: GearPair, member: int, rho: np.ndarray) -> np.ndarray:
    """Half transverse tooth thickness r ψ(r) at roll distance ρ [m]."""
    rb = base_radius(pair, member)
    r = np.sqrt(np.asarray(rho, float) ** 2 + rb**2)
    return r * involute_half_angle(pair, member, r)
