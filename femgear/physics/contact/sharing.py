"""Quasi-static load sharing between the tooth pairs in contact, along the path of contact.

Rigid gear bodies, no errors: at mesh phase φ every contact point has the same
transverse approach δ_t(φ), so a point at path position u carries the load per unit
contact-line length

    w(u, φ) = k'(u) δ_t(φ),     δ_t(φ) = F_t / K_t(φ),     K_t(φ) = Σ_lines ∫ k'(u(ζ)) dζ,

where k'(u) is the transverse stiffness of one tooth pair per unit face width (of the
mesh-stiffness level: uniform for ``constant``/``iso6336``, the PEM or FE curve
otherwise) and F_t = F_n cos β_b the transverse force of one helix (so that
w = k' F_n cos β_b / K_t is a normal load per unit line length: dF_n = dF_t/cos β_b on
dl = dζ/cos β_b).  With uniform k' this is ISO 6336's assumption of a load uniform
along the contact lines, w = F_n / L(φ).

- Spur (β_b = 0): one position u is one phase; the pairs in contact are u + j p_bt
  inside the path, and w(u) = F_n k'(u) / (b Σ_j k'(u + j p_bt)).  In the single-contact
  zone B–D the pair carries the whole load F_n/b.  At the zone bounds B and D the pair
  leaving (entering) at the tip E (A) is counted as unloaded, so B and D get the
  single-pair load (ISO 6336-2's Z_B/Z_D points).
- Helical: the flank point at face position ζ passes path position u at the phase
  φ(u, ζ) = [(u − u_A + b tan β_b − ζ tan β_b)/p_bt] mod 1.  ``line_load`` is the mean
  of w(u, φ(u, ζ)) over the face width ζ ∈ [0, b] (the value that the time-mean Hertz,
  film, friction and power-loss figures take), ``line_load_max`` its maximum.  Then
  (b / (p_bt cos β_b)) ∫_A^E w̄ du = F_n exactly: the time mean of the transmitted force.

Sources: Niemann & Winter, *Maschinenelemente* II §21.4 (load sharing of spur gears,
single-contact points B, D); ISO 6336-1:2019 (uniform load along the contact lines).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from femgear.physics.geometry import GearPair

StiffnessPerWidth = Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class LoadSharing:
    """Load per unit contact-line length at path positions ``u`` (one helix)."""

    u: np.ndarray             #: path positions [m]
    line_load: np.ndarray     #: w̄(u), mean over the phases in which u is in contact [N/m]
    line_load_max: np.ndarray  #: max over those phases [N/m]
    fraction: np.ndarray      #: share of the helix's normal force F_n carried by the line through u, w̄ b_c / F_n [-]
    mean_line_load: float     #: F_n / L̄, the time mean over the whole path [N/m]
    method: str               #: "spur" or "helical"


def _uniform(u: np.ndarray) -> np.ndarray:
    return np.ones_like(np.asarray(u, float))


def _evaluate(k_unit: StiffnessPerWidth, x: np.ndarray) -> np.ndarray:
    """k'(x) for an array of any shape (stiffness curves take 1-D arrays)."""
    return np.asarray(k_unit(x.ravel()), float).reshape(x.shape)


def single_contact_bounds(pair: GearPair) -> tuple[float, float]:
    """(u_B, u_D): the inner points of single contact, B = E − p_bt and D = A + p_bt [m]."""
    return pair.u_end - pair.p_bt, pair.u_start + pair.p_bt


def spur_sharing(pair: GearPair, u: np.ndarray, force: float, k_unit: StiffnessPerWidth | None = None) -> LoadSharing:
    """Load sharing of a spur pair (or one transverse slice) at positions ``u`` for normal force ``force`` [N]."""
    u = np.asarray(u, float)
    k_unit = k_unit or _uniform
    tol = 1e-9 * pair.p_bt
    j = np.arange(-3, 4)
    partners = u[:, None] + j[None, :] * pair.p_bt
    own = j[None, :] == 0
    inside = (partners > pair.u_start + tol) & (partners < pair.u_end - tol)
    inside |= own
    k = np.where(inside, _evaluate(k_unit, np.clip(partners, pair.u_start, pair.u_end)), 0.0)
    share = k[:, 3] / k.sum(axis=1)
    w = force * share / pair.b
    return LoadSharing(u=u, line_load=w, line_load_max=w.copy(), fraction=share,
                       mean_line_load=force / (pair.eps_alpha * pair.b), method="spur")


def helical_sharing(pair: GearPair, u: np.ndarray, force: float, k_unit: StiffnessPerWidth | None = None,
                    n_phases: int = 400, n_slices: int = 200) -> LoadSharing:
    """Load sharing of one helix (contact-line sharing) at positions ``u`` for normal force ``force`` [N]."""
    u = np.asarray(u, float)
    k_unit = k_unit or _uniform
    tb, cb = math.tan(pair.beta_b), math.cos(pair.beta_b)
    span = pair.b * tb
    phases = np.arange(n_phases) / n_phases
    db = pair.b / n_slices
    zeta = (np.arange(n_slices) + 0.5) * db
    kk = np.arange(-1, int(math.ceil((pair.g_alpha + span) / pair.p_bt)) + 2)
    pts = (pair.u_start - span + phases[:, None, None] * pair.p_bt + kk[None, :, None] * pair.p_bt
           + zeta[None, None, :] * tb)
    on = (pts >= pair.u_start) & (pts <= pair.u_end)
    K_t = np.where(on, _evaluate(k_unit, np.clip(pts, pair.u_start, pair.u_end)), 0.0).sum(axis=(1, 2)) * db
    F_t = force * cb
    phi = np.mod((u[:, None] - pair.u_start + span - zeta[None, :] * tb) / pair.p_bt, 1.0)
    inv_K = np.interp(phi, np.append(phases, 1.0), np.append(1.0 / K_t, 1.0 / K_t[0]))
    k_u = _evaluate(k_unit, u)
    w_mean = k_u * F_t * inv_K.mean(axis=1)
    w_max = k_u * F_t * inv_K.max(axis=1)
    return LoadSharing(u=u, line_load=w_mean, line_load_max=w_max, fraction=w_mean * pair.b / cb / force,
                       mean_line_load=force / pair.mean_contact_length, method="helical")


def load_sharing(pair: GearPair, u: np.ndarray, force: float, k_unit: StiffnessPerWidth | None = None,
                 **options) -> LoadSharing:
    """Spur or helical load sharing of one helix of ``pair`` carrying normal force ``force`` [N]."""
    if force <= 0 or not math.isfinite(force):
        raise ValueError(f"force must be positive and finite, got {force!r}")
    if pair.beta_b == 0:
        return spur_sharing(pair, u, force, k_unit)
    return helical_sharing(pair, u, force, k_unit, **options)
