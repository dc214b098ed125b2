"""Mixed lubrication of rough line contacts: Greenwood–Tripp asperities and the JGP load split.

Rough surfaces (composite roughness σ = √(σ₁² + σ₂²), Gaussian heights) touch through the
film where the film parameter λ = h/σ is small.  Greenwood & Tripp (Proc. IMechE 185:625,
1970) give the mean asperity pressure at a mean separation h

    p_a = K E* F_5/2(h/σ),    K = (16√2/15) π (ηβσ)² √(σ/β),    E* = E'/2,

with η the asperity density, β the asperity tip radius and

    F_n(t) = (2π)^−½ ∫_t^∞ (s − t)ⁿ e^(−s²/2) ds

(closed form of F_5/2 with modified Bessel functions K_ν, F_2 with erfc).  The load is
shared after Johnson, Greenwood & Poon (Wear 19:91, 1972): the fluid carries W/γ₁ as a
smooth EHL contact with modulus E'/γ₁, the asperities W/γ₂ = W (1 − 1/γ₁) as the
Greenwood–Tripp pressure over the Hertz width 2b of the whole load; γ₁ is chosen so that
both agree at the central film of the fluid part.  Friction: the fluid traction of the
fluid part plus μ_b times the asperity load (μ_b the boundary friction coefficient,
``friction.boundary_coefficient``), whose heat adds Blok's flash temperature to the contact
temperature.  λ > 3: full film (γ₁ → 1); λ ≲ 1: a share of the load on the asperities, μ rising
towards μ_b.

The share depends strongly on the asperity statistics ηβσ and σ/β (``roughness.eta_beta_sigma``,
``roughness.sigma_over_beta``): at h = 0 the Greenwood–Tripp pressure is K E* F_5/2(0) = 0.617 K E*,
30 MPa for the defaults (0.04, 3e-3; K = 4.2e-4) but 0.58 GPa for (0.1, 0.03; K = 8.2e-3): with the defaults a
gear contact at 1–2 GPa stays almost all fluid at any λ (docs/models/lubrication.md, "Mixed
lubrication on gears").
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import integrate, special

K_GT = 16.0 * math.sqrt(2.0) / 15.0 * math.pi
#: R_a of the flank by finishing process [m] (typical values, docs/rating.md; the ratings' default is ground)
FINISHING_RA = {"ground": 0.4e-6, "honed": 0.3e-6, "shaved": 0.8e-6, "hobbed": 1.6e-6}


def composite_sigma(ra1: float, ra2: float) -> float:
    """σ = √(Rq1² + Rq2²) [m] of two flanks of arithmetic mean roughness R_a [m], with Rq = √(π/2) R_a of a
    Gaussian height distribution (the one Greenwood–Tripp assume)."""
    return math.sqrt(math.pi / 2) * math.hypot(ra1, ra2)


def gt_function(n: float, t: np.ndarray | float) -> np.ndarray:
    """F_n(t) = (2π)^−½ ∫_t^∞ (s − t)ⁿ e^(−s²/2) ds for n = 2 or 5/2 (closed forms, vectorised; for n = 5/2 below
    t = 0.05, where the Bessel form loses precision, and for any other n: quadrature)."""
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if n == 2:
        return 0.5 * (t**2 + 1) * special.erfc(t / math.sqrt(2)) - t * np.exp(-t**2 / 2) / math.sqrt(2 * math.pi)
    out = np.empty_like(t)
    closed = (t >= 0.05) if n == 2.5 else np.zeros(t.shape, bool)
    if np.any(closed):
        tc = t[closed]
        x = tc**2 / 4
        out[closed] = (tc**1.5 * np.exp(-x) * ((2 * tc**2 + 3) * special.kv(0.75, x) - (2 * tc**2 + 5) * special.kv(0.25, x))
                       / (8 * math.sqrt(math.pi)))
    for i in zip(*np.nonzero(~closed)):
        ti = t[i]
        out[i] = integrate.quad(lambda s: (s - ti) ** n * math.exp(-s * s / 2), ti, np.inf)[0] / math.sqrt(2 * math.pi)
    return out


@dataclass(frozen=True)
class Roughness:
    """Composite roughness of the two flanks and its asperity statistics."""

    sigma: float                    #: composite Rq √(σ₁² + σ₂²) [m]
    eta_beta_sigma: float = 0.04    #: ηβσ [-] (typical 0.03–0.05)
    sigma_over_beta: float = 3e-3   #: σ/β [-] (typical 1e-3…1e-2; the geometric middle)

    @property
    def K(self) -> float:
        return K_GT * self.eta_beta_sigma**2 * math.sqrt(self.sigma_over_beta)

    def asperity_pressure(self, h, E_red: float) -> np.ndarray:
        """Mean asperity pressure p_a [Pa] at the mean separation h [m] (E_red = E')."""
        return self.K * 0.5 * E_red * gt_function(2.5, np.maximum(np.asarray(h, dtype=float), 0.0) / self.sigma)


@dataclass(frozen=True)
class LoadSplit:
    """The JGP split at each contact."""

    gamma1: np.ndarray          #: fluid load = W/γ₁
    asperity_fraction: np.ndarray   #: W_a / W = 1 − 1/γ₁
    film: np.ndarray            #: central film of the fluid part [m]
    film_parameter: np.ndarray  #: λ = h/σ


def jgp_split(w, R, film, E_red: float, roughness: Roughness, bisections: int = 48) -> LoadSplit:
    """γ₁ per contact with p_a(h(W/γ₁, E'/γ₁)) 2b = W (1 − 1/γ₁).

    ``film(w, E_red)`` returns the central film [m] of smooth line contacts of loads per length w [N/m] and
    reduced moduli E_red (arrays of the contacts' shape), their other parameters bound by the caller.  The
    excess p_a 2b/W − (1 − 1/γ₁) grows monotonically with 1/γ₁ ∈ (0, 1], so all contacts are solved at once
    by bisection on [1e-6, 1] (``bisections`` halvings: 1/γ₁ to 2^−48 ≈ 4e-15).
    """
    w, R = np.broadcast_arrays(np.atleast_1d(np.asarray(w, float)), np.atleast_1d(np.asarray(R, float)))
    w, R = w.astype(float), R.astype(float)
    b = np.sqrt(8 * w * R / (math.pi * E_red))

    def excess(inv_g: np.ndarray) -> np.ndarray:      # asperity load − its share, in units of W
        h = np.reshape(film(w * inv_g, E_red * inv_g), w.shape)
        return np.reshape(roughness.asperity_pressure(h, E_red), w.shape) * 2 * b / w - (1 - inv_g)

    mixed = excess(np.ones(w.shape)) > 0.0            # elsewhere full film at the whole load: 1/γ₁ = 1
    lo, hi = np.full(w.shape, 1e-6), np.ones(w.shape)
    for _ in range(bisections if np.any(mixed) else 0):
        mid = 0.5 * (lo + hi)
        up = excess(mid) > 0
        hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
    inv = np.where(mixed, 0.5 * (lo + hi), 1.0)
    h = np.reshape(film(w * inv, E_red * inv), w.shape)
    g1 = 1.0 / inv
    return LoadSplit(gamma1=g1, asperity_fraction=1 - 1 / g1, film=h, film_parameter=h / roughness.sigma)


def split_table(loads, R, ue, srr, T_bulk: float, oil, E_red: float, solids, roughness: Roughness
                ) -> tuple[np.ndarray, np.ndarray]:
    """(asperity fraction W_a/W, film parameter λ), each (n, m): the JGP split of the thermal central film
    (:func:`femgear.physics.lubrication.traction.thermal_central_film`, as :func:`mixed_line_friction` takes it)
    at the loads per unit length ``loads`` (m,) [N/m] of each of the n contacts of radius ``R``, entrainment
    speed ``ue`` and slide-to-roll ratio ``srr`` (n,), oil at ``T_bulk`` [K]."""
    from femgear.physics.lubrication.traction import thermal_central_film

    loads = np.asarray(loads, float)
    R, ue, srr = (np.atleast_1d(np.asarray(a, float)) for a in (R, ue, srr))
    fraction, lam = np.empty((R.size, loads.size)), np.empty((R.size, loads.size))
    for i in range(R.size):
        def h_of(wf, Ef, i=i):
            return thermal_central_film(np.atleast_1d(wf), R[i], ue[i], abs(srr[i]), T_bulk, oil, Ef, solids)[0]

        s = jgp_split(loads, R[i], h_of, E_red, roughness)
        fraction[i], lam[i] = s.asperity_fraction, s.film_parameter
    return np.clip(fraction, 0.0, 1.0), lam


def mixed_line_friction(w, R, ue, srr, T_bulk, oil, E_red: float, solids, roughness: Roughness,
                        boundary_coefficient: float, **traction_kw):
    """Friction of rough line contacts: the fluid part (thermal Eyring traction of the smooth
    contact under W/γ₁ with E'/γ₁, :func:`femgear.physics.lubrication.traction.line_contact_friction`)
    plus μ_b W (1 − 1/γ₁) on the asperities.  The asperities' frictional heat adds Blok's flash temperature of
    μ_b (1 − 1/γ₁) over the Hertz band to the fluid part's surface and film temperature rises (the surface
    temperature is linear in the heat flux; adding the two maxima bounds the peak from above, both sources being
    near-elliptic over the same band).  Returns (TractionResult of the whole load, LoadSplit)."""
    from dataclasses import replace

    from femgear.physics.lubrication.flash import line_flash_temperature
    from femgear.physics.lubrication.traction import line_contact_friction, thermal_central_film

    w, R, ue, srr, T_bulk = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                  for a in (w, R, ue, srr, T_bulk)))
    def h_of(wf, Ef):
        return thermal_central_film(wf, R, ue, srr, T_bulk, oil, Ef, solids)[0]

    split = jgp_split(w, R, h_of, E_red, roughness)
    gam = split.gamma1
    fluid = line_contact_friction(w / gam, R, ue, srr, T_bulk, oil, E_red / gam, solids, **traction_kw)
    traction = fluid.traction + boundary_coefficient * w * split.asperity_fraction
    boundary = line_flash_temperature(boundary_coefficient * split.asperity_fraction, w, R, ue, np.abs(srr), E_red,
                                      solids.B1, solids.B2)
    return replace(fluid, mu=traction / w, traction=traction, flash_max=fluid.flash_max + boundary,
                   film_max=fluid.film_max + boundary), split
