"""Kinematics along the path of contact and contact lines of a double-helical pair.

Positions on the path are given by ``u``, the distance from T1 (the tangent point on
the pinion's base circle) along the transverse line of action [m].

Surface velocities.  The plane of action is tangent to both base cylinders; at a
contact point both flanks move with ω r_b inside that plane (no relative motion) and
with ω_i ρ_i across it, where ρ_i is the transverse radius of curvature.  That
direction lies in the common tangent plane and is perpendicular to the contact line,
so rolling and sliding act perpendicular to the contact line with the *transverse*
speeds v_i = ω_i ρ_i, while the flank curvature across the contact line is that of the
normal section, ρ_n = ρ / cos β_b (Niemann & Winter II §21.5; ISO/TR 6336-22).  The
paper (its eq. for R1, R2) divides by cos β instead of cos β_b; femgear uses β_b.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair


@document_fields
@dataclass(frozen=True)
class PathKinematics:
    """Quantities at positions ``u`` along the path of contact (arrays of equal shape)."""

    u: np.ndarray
    """distance of each position from T1 (the pinion's base tangent point) along the transverse line of action; the
    pitch point is at pair.u_pitch = T1C [m]"""
    s: np.ndarray
    """signed distance from the pitch point, u − T1C, + towards the pinion tip [m]"""
    r1: np.ndarray
    """radius of the contact point on the pinion [m]"""
    r2: np.ndarray
    """radius of the contact point on the gear [m]"""
    rho1: np.ndarray
    """transverse radius of curvature of the pinion flank, ρ1 = u [m]"""
    rho2: np.ndarray
    """transverse radius of curvature of the gear flank, ρ2 = T1T2 − u [m]"""
    R1: np.ndarray
    """normal-section radius of curvature of the pinion flank, ρ1 / cos β_b [m]"""
    R2: np.ndarray
    """normal-section radius of curvature of the gear flank, ρ2 / cos β_b [m]"""
    R: np.ndarray
    """equivalent radius R1 R2/(R1 + R2) [m]"""
    v1: np.ndarray
    """rolling (surface) speed of the pinion flank across the contact line, ω1 ρ1 [m/s]"""
    v2: np.ndarray
    """rolling (surface) speed of the gear flank across the contact line, ω2 ρ2 [m/s]"""
    ue: np.ndarray
    """entrainment speed (v1 + v2)/2 [m/s]"""
    vs: np.ndarray
    """sliding speed v1 − v2 [m/s]"""
    srr: np.ndarray
    """slide-to-roll ratio vs/ue [-]"""


def path_positions(pair: GearPair, n: int) -> np.ndarray:
    """``n`` equally spaced positions from the start A to the end E of the path [m]."""
    return np.linspace(pair.u_start, pair.u_end, n)


def kinematics(pair: GearPair, u: np.ndarray, omega1: float) -> PathKinematics:
    """Radii and velocities at positions ``u`` for pinion speed ``omega1`` [rad/s]."""
    u = np.asarray(u, dtype=float)
    omega2 = omega1 * pair.z1 / pair.z2
    rho1 = u
    rho2 = pair.line_of_action - u
    cb = math.cos(pair.beta_b)
    R1, R2 = rho1 / cb, rho2 / cb
    with np.errstate(divide="ignore", invalid="ignore"):
        R = np.where(R1 + R2 > 0, R1 * R2 / (R1 + R2), 0.0)
    v1, v2 = omega1 * rho1, omega2 * rho2
    ue = 0.5 * (v1 + v2)
    vs = v1 - v2
    with np.errstate(divide="ignore", invalid="ignore"):
        srr = np.where(ue > 0, vs / ue, 0.0)
    return PathKinematics(
        u=u, s=u - pair.u_pitch,
        r1=np.hypot(pair.rb1, rho1), r2=np.hypot(pair.rb2, rho2),
        rho1=rho1, rho2=rho2, R1=R1, R2=R2, R=R, v1=v1, v2=v2, ue=ue, vs=vs, srr=srr,
    )


def mesh_frequency(pair: GearPair, pinion_rpm: float) -> float:
    """Mesh frequency f_m = z1 n1 / 60 [Hz]."""
    return pair.z1 * pinion_rpm / 60.0


@dataclass(frozen=True)
class ContactLines:
    """Contact lines of one helix at one instant.

    ``u_lo``/``u_hi`` give the transverse extent of each line on the path of contact,
    ``length`` its length in the plane of action [m].
    """

    u_lo: np.ndarray
    u_hi: np.ndarray
    length: np.ndarray

    @property
    def count(self) -> int:
        return int(self.length.size)

    @property
    def total_length(self) -> float:
        return float(self.length.sum())


def contact_lines(pair: GearPair, phase: float, offset: float = 0.0) -> ContactLines:
    """Contact lines of one helix when the mesh has advanced by ``phase`` base pitches.

    In the plane of action a contact line runs at β_b to the axis: its transverse
    position is u(ζ) = u0 + ζ tan β_b for axial coordinate ζ ∈ [0, b], and the lines
    are p_bt apart.  ``offset`` (in base pitches) shifts this helix against the other,
    the left/right stagger of a double-helical pair.  A line of the opposite hand is
    the mirror ζ → b − ζ: its lengths and extents are the same, so one function serves
    both helices.
    """
    tb = math.tan(pair.beta_b)
    span = pair.b * tb                       # transverse extent of one line
    shift = ((phase + offset) % 1.0) * pair.p_bt
    # lines whose front (ζ = b) has passed A, indexed so that u0 = u_start - span + shift + k p_bt
    k_max = int(math.ceil((pair.g_alpha + span) / pair.p_bt)) + 1
    u0 = pair.u_start - span + shift + pair.p_bt * np.arange(-1, k_max + 1)
    if tb == 0:  # spur limit: each line covers the whole face width at one position
        inside = (u0 >= pair.u_start) & (u0 <= pair.u_end)
        return ContactLines(u_lo=u0[inside], u_hi=u0[inside], length=np.full(int(inside.sum()), pair.b))
    lo = np.maximum(u0, pair.u_start)
    hi = np.minimum(u0 + span, pair.u_end)
    keep = hi > lo + 1e-15 * pair.p_bt
    lo, hi = lo[keep], hi[keep]
    length = (hi - lo) / tb / math.cos(pair.beta_b)
    return ContactLines(u_lo=lo, u_hi=hi, length=length)


def double_helical_contact(pair: GearPair, phases: np.ndarray, stagger: float = 0.0) -> dict[str, np.ndarray]:
    """Number and total length of contact lines per helix over mesh ``phases`` [base pitches].

    Returns arrays ``count_left``, ``count_right``, ``length_left``, ``length_right``
    and ``length_total`` [m], one value per phase.
    """
    phases = np.asarray(phases, dtype=float)
    out = {k: np.empty(phases.shape) for k in ("count_left", "count_right", "length_left", "length_right")}
    for i, ph in enumerate(phases.flat):
        left = contact_lines(pair, ph)
        right = contact_lines(pair, ph, offset=stagger)
        out["count_left"].flat[i], out["length_left"].flat[i] = left.count, left.total_length
        out["count_right"].flat[i], out["length_right"].flat[i] = right.count, right.total_length
    out["length_total"] = out["length_left"] + out["length_right"]
    return out
