"""Potential energy method (PEM) for the stiffness of one tooth pair of a transverse slice.

Each tooth is a non-uniform cantilever in the transverse plane, clamped on the root
circle and loaded along the line of action.  The stored energy gives the compliances
(per unit face width, so all terms scale with 1/L):

- Hertz:      1/k_h = 4(1−ν²)/(π E L)                      (Yang & Lin 1987)
- bending:    1/k_b = ∫ [(x_P − x) cos α₁ − h_P sin α₁]² / (E' I(x)) dx
- shear:      1/k_s = ∫ 1.2 cos²α₁ / (G A(x)) dx          (Tian 2004)
- axial:      1/k_a = ∫ sin²α₁ / (E' A(x)) dx
- foundation: 1/k_f = cos²α₁/(E L) [L*(u_f/S_f)² + M*(u_f/S_f) + P*(1 + Q* tan²α₁)]
                                                             (Sainsot, Velex & Duverger 2004)

with I = (2h)³L/12, A = 2hL, h(x) the half thickness of the *generated* tooth
(:mod:`femgear.physics.geometry.profile`) integrated from the root circle, so that teeth whose
root circle lies below the base circle get the fillet (transition-curve) part
automatically (Chen & Shao 2011; Ma et al. 2014 integrate the transition curve
separately — here it is the same integral over the real outline).  α₁ is the angle
between the load and the normal to the tooth centre line at the contact point,
α₁ = α(r) − ψ(r) (pressure angle minus half tooth angle).  E' = E/(1−ν²) for wide
teeth (plane strain, the default) or E (plane stress, narrow teeth).

Sainsot's fit is used with h_f = r_f/r_int clamped to [1.4, 6] (outside it P* leaves
the range of the published fit).  A solid gear (bore radius 0) is read as a body
clamped on a shaft of half its root radius, h_f = 2 (DEFAULT_HF); the FE level clamps
the same bore, so the two are compared on the same body.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.profile import ToothProfile, tooth_profile

#: Sainsot et al. 2004, Table 1: rows L*, M*, P*, Q*; columns A, B, C, D, E, F
SAINSOT = {
    "L": (-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045),
    "M": (60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086),
    "P": (-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236),
    "Q": (-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904),
}
HF_RANGE = (1.4, 6.0)
DEFAULT_HF = 2.0


def sainsot_coefficient(name: str, h_f: float, theta_f: float) -> float:
    """X*(h_f, θ_f) = A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F (Sainsot 2004)."""
    A, B, C, D, E, F = SAINSOT[name]
    return A / theta_f**2 + B * h_f**2 + C * h_f / theta_f + D / theta_f + E * h_f + F


@dataclass(frozen=True)
class ToothCompliance:
    """Compliances of one tooth per unit face width [m/N · m] at the given positions."""

    bending: np.ndarray
    shear: np.ndarray
    axial: np.ndarray
    foundation: np.ndarray

    @property
    def total(self) -> np.ndarray:
        return self.bending + self.shear + self.axial + self.foundation


def contact_geometry(pair: GearPair, member: int, u: np.ndarray):
    """Radius r, pressure angle α and roll length ρ of the contact point at path position u."""
    u = np.asarray(u, float)
    if member == 1:
        rho, rb = u, pair.rb1
    else:
        rho, rb = pair.line_of_action - u, pair.rb2
    return np.hypot(rb, rho), np.arctan2(rho, rb), rho


@lru_cache(maxsize=32)
def _profile(pair: GearPair, member: int) -> ToothProfile:
    return tooth_profile(pair, member, n_fillet=120, n_involute=200)


def load_point(pair: GearPair, member: int, u: np.ndarray):
    """Load point in the tooth frame: centre-line coordinate x_P, half thickness h_P, angle α₁."""
    prof = _profile(pair, member)
    r, alpha, _ = contact_geometry(pair, member, u)
    psi = prof.half_angle(r)
    return r * np.cos(psi), r * np.sin(psi), alpha - psi


def tooth_compliance(pair: GearPair, member: int, u: np.ndarray, youngs_modulus: float,
                     poisson_ratio: float, bore_radius: float = 0.0, plane: str = "strain",
                     n_gauss: int = 48) -> ToothCompliance:
    """PEM compliances of the pinion (1) or gear (2) tooth loaded at path positions ``u``."""
    if plane not in ("strain", "stress"):
        raise ValueError(f"plane must be 'strain' or 'stress', got {plane!r}")
    E, nu = youngs_modulus, poisson_ratio
    Ep = E / (1 - nu**2) if plane == "strain" else E
    G = E / (2 * (1 + nu))
    prof = _profile(pair, member)
    keep = prof.part <= 2
    xs, ys = prof.x[keep], prof.y[keep]
    order = np.argsort(xs)
    xs, ys = xs[order], ys[order]
    x0 = xs[0]
    xP, hP, a1 = load_point(pair, member, u)
    t, w = np.polynomial.legendre.leggauss(n_gauss)
    t, w = 0.5 * (t + 1), 0.5 * w
    X = x0 + (xP - x0)[:, None] * t[None, :]              # (positions, nodes)
    J = (xP - x0)[:, None] * w[None, :]
    h = np.interp(X, xs, ys)
    A = 2 * h
    I = (2 * h) ** 3 / 12
    ca, sa = np.cos(a1)[:, None], np.sin(a1)[:, None]
    Mb = (xP[:, None] - X) * ca - hP[:, None] * sa
    c_b = np.sum(J * Mb**2 / (Ep * I), axis=1)
    c_s = np.sum(J * 1.2 * ca**2 / (G * A), axis=1)
    c_a = np.sum(J * sa**2 / (Ep * A), axis=1)
    # Sainsot fillet foundation
    rf = prof.rf
    theta_f = float(np.arctan2(ys[0], xs[0]))
    S_f = 2 * rf * theta_f
    h_f = rf / bore_radius if bore_radius > 0 else DEFAULT_HF
    h_f = min(max(h_f, HF_RANGE[0]), HF_RANGE[1])
    u_f = xP - hP * np.tan(a1) - rf * math.cos(theta_f)
    L_, M_, P_, Q_ = (sainsot_coefficient(k, h_f, theta_f) for k in "LMPQ")
    c_f = np.cos(a1) ** 2 / E * (L_ * (u_f / S_f) ** 2 + M_ * (u_f / S_f) + P_ * (1 + Q_ * np.tan(a1) ** 2))
    return ToothCompliance(bending=c_b, shear=c_s, axial=c_a, foundation=c_f)


def hertz_compliance(youngs_modulus: float, poisson_ratio: float) -> float:
    """Yang–Lin Hertz compliance per unit face width 4(1−ν²)/(π E) [m/N · m] (same material)."""
    return 4 * (1 - poisson_ratio**2) / (math.pi * youngs_modulus)


def pair_stiffness_per_width(pair: GearPair, u: np.ndarray, youngs_modulus: float, poisson_ratio: float,
                             bore_radius: tuple[float, float] = (0.0, 0.0), plane: str = "strain",
                             foundation: bool = True) -> np.ndarray:
    """Transverse stiffness of one tooth pair per unit face width at positions ``u`` [N/m per m]."""
    c = np.full(np.shape(u), hertz_compliance(youngs_modulus, poisson_ratio))
    for member in (1, 2):
        tc = tooth_compliance(pair, member, u, youngs_modulus, poisson_ratio, bore_radius[member - 1], plane)
        c = c + tc.bending + tc.shear + tc.axial + (tc.foundation if foundation else 0.0)
    return 1.0 / c


def pem_mesh_stiffness(pair: GearPair, youngs_modulus: float, poisson_ratio: float, n_positions: int,
                       stagger: float = 0.0, bore_radius: tuple[float, float] = (0.0, 0.0), plane: str = "strain"):
    """The potential-energy mesh stiffness of both helices at ``n_positions`` phases of one mesh period (the
    ``pem`` level, :class:`~femgear.physics.stiffness.tvms.MeshStiffness`): :func:`pair_stiffness_per_width`
    sampled along the path and integrated over every contact line; ``stagger`` in base pitches [-]."""
    import time

    from femgear.physics.stiffness.tvms import integrated_mesh_stiffness, path_samples

    t0 = time.perf_counter()
    u_grid = path_samples(pair)
    k_grid = pair_stiffness_per_width(pair, u_grid, youngs_modulus, poisson_ratio, bore_radius, plane)
    return integrated_mesh_stiffness(pair, u_grid, k_grid, "pem", n_positions, stagger, t0=t0)
