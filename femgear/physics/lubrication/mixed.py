"""Mixed lubrication of rough line contacts: the load-sharing concept with statistical asperity contact.

Rough surfaces (composite roughness σ = √(σ₁² + σ₂²), Gaussian heights) touch through the film where the film
parameter λ = h/σ is small.  The load is shared after Johnson, Greenwood & Poon (Wear 19:91, 1972), as Gelinck &
Schipper (Tribol. Int. 33:175, 2000) use it for Stribeck curves of line contacts and Akbarzadeh & Khonsari
(J. Tribol. 130:021503, 2008) for spur gears: W = W_H + W_C, the fluid carrying W_H = W/γ₁ as a smooth EHL contact
of modulus E'/γ₁, the asperities W_C = W/γ₂ over the Hertz width 2b of the whole load (1/γ₁ + 1/γ₂ = 1), both
at one nominal separation h of the surfaces' mean planes, solved together; the friction is

    μ = (μ_b W_C + μ_EHL W_H) / W

(μ_b the boundary coefficient ``friction.boundary_coefficient``, μ_EHL the thermal Eyring traction of the fluid
part), and the asperities' heat adds Blok's flash temperature to the contact temperature.

The asperity pressure at the separation h (t = h/σ, negative where the mean planes interpenetrate):

- ``"greenwood-tripp"`` (Greenwood & Tripp, Proc. IMechE 185:625, 1970; Akbarzadeh & Khonsari's choice)
  p_C = K E* F_5/2(t),  K = (16√2/15) π (ηβσ)² √(σ/β),  E* = E'/2;
- ``"greenwood-williamson"`` (Greenwood & Williamson, Proc. R. Soc. A 295:300, 1966; Gelinck & Schipper's choice)
  p_C = (4/3) E* ηβσ √(σ/β) F_3/2(t),

with η the asperity density, β the asperity tip radius and F_n(t) = (2π)^−½ ∫_t^∞ (s − t)ⁿ e^(−s²/2) ds, in closed
form Γ(n+1) (2π)^−½ e^(−t²/4) D_−(n+1)(t) with the parabolic cylinder function D (any t, any n).

The fluid's film at the separation h (``fluid_film``):

- ``"mean-gap"`` (default): the mean gap between the rough surfaces, h_T = σ (t Φ(t) + φ(t)) with the standard
  normal Φ, φ (Patir & Cheng, J. Lubr. Technol. 100:12, 1978: the average gap of Gaussian heights), positive at any
  separation, so the surfaces may close below the mean planes: the fluid film tends to 0 only as the asperities
  take the whole load (the boundary limit μ → μ_b);
- ``"separation"``: the film is the separation itself (h ≥ 0), the split femgear had before: the asperity
  pressure cannot exceed its value at h = 0, 0.617 K E* (30 MPa for the default statistics), so at gear pressures
  the asperities never take more than a few per cent of the load, whatever the film.

Or the load share from λ alone (``"zhou-hoeprich"``; Zhou & Hoeprich, J. Tribol. 113:590, 1991, eq. 29, their fit to
the asperity load of measured, run-in ground profiles in a rough-contact analysis): the asperities carry

    W_C/W = exp(−B λ^C),   λ = h_c/σ,

h_c the smooth contact's thermal central film at the whole load (their eq. 30: the isothermal film times the
thermal reduction factor, here :func:`femgear.physics.lubrication.traction.thermal_central_film`), B and C
constants of the surfaces (``roughness.share_b``, ``roughness.share_c``; defaults 1.90, 0.99, the rib contact
of the rougher surfaces, σ 0.24 µm, of Wingertszahn, Koch, Maccioni, Concli & Sauer, Lubricants 11:369, 2023,
Table 2; their raceway, σ 0.16 µm: 2.32, 0.97; Zhou & Hoeprich: the rougher surface keeps asperity load over a
wider range of λ, i.e. a smaller B), and the friction weighted as Wingertszahn et al.'s eq. 36 does it,
μ = φ μ_b + (1 − φ) μ_EHL with φ = W_C/W and μ_EHL the thermal Eyring traction of the smooth contact under the
whole load (its heat weighted alike).  Where the statistical laws give the share from E* and the asperity
statistics at a separation, so that at a given λ it falls as 1/p̄ with the load, this share depends on λ alone.

The share of the statistical laws depends strongly on the asperity statistics ηβσ and σ/β (``roughness.eta_beta_sigma``,
``roughness.sigma_over_beta``; defaults 0.04, 3e-3: K = 4.2e-4); see docs/models/lubrication.md, "Mixed lubrication
on gears".
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

K_GT = 16.0 * math.sqrt(2.0) / 15.0 * math.pi
#: R_a of the flank by finishing process [m] (typical values, docs/rating.md; the ratings' default is ground)
FINISHING_RA = {"ground": 0.4e-6, "honed": 0.3e-6, "shaved": 0.8e-6, "hobbed": 1.6e-6}
#: the asperity contact laws and the fluid films of the load sharing
CONTACT_LAWS = ("greenwood-tripp", "greenwood-williamson", "zhou-hoeprich")
FLUID_FILMS = ("mean-gap", "separation")
#: the bracket of the nominal separation t = h/σ searched by the split [-]: F_5/2(−40) = 1e4, F_n(60) underflows to 0
T_BRACKET = (-40.0, 60.0)


def composite_sigma(ra1: float, ra2: float) -> float:
    """σ = √(Rq1² + Rq2²) [m] of two flanks of arithmetic mean roughness R_a [m], with Rq = √(π/2) R_a of a
    Gaussian height distribution (the one Greenwood–Tripp assume)."""
    return math.sqrt(math.pi / 2) * math.hypot(ra1, ra2)


def gt_function(n: float, t: np.ndarray | float) -> np.ndarray:
    """F_n(t) = (2π)^−½ ∫_t^∞ (s − t)ⁿ e^(−s²/2) ds [-] for any n > −1 and any t (vectorised), by the parabolic
    cylinder function: ∫_0^∞ uⁿ e^(−u²/2 − tu) du = Γ(n+1) e^(t²/4) D_−(n+1)(t) (Abramowitz & Stegun 19.5.3)."""
    t = np.atleast_1d(np.asarray(t, dtype=float))
    d, _ = special.pbdv(np.full(t.shape, -n - 1.0), t)
    return special.gamma(n + 1) / math.sqrt(2 * math.pi) * np.exp(-t * t / 4) * d


def mean_gap(t: np.ndarray | float) -> np.ndarray:
    """Mean gap h_T/σ = t Φ(t) + φ(t) [-] between rough surfaces of Gaussian composite heights at the nominal
    separation t = h/σ of their mean planes (Patir & Cheng 1978): → t for t ≫ 1, → 0 for t → −∞, φ(0) at contact."""
    t = np.asarray(t, dtype=float)
    return t * special.ndtr(t) + np.exp(-t * t / 2) / math.sqrt(2 * math.pi)


@dataclass(frozen=True)
class Roughness:
    """Composite roughness of the two flanks, its asperity statistics and the load-sharing laws."""

    sigma: float                    #: composite Rq √(σ₁² + σ₂²) [m]
    eta_beta_sigma: float = 0.04    #: ηβσ [-] (typical 0.03–0.05)
    sigma_over_beta: float = 3e-3   #: σ/β [-] (typical 1e-3…1e-2; the geometric middle)
    contact: str = "greenwood-tripp"    #: asperity contact law, one of :data:`CONTACT_LAWS`
    fluid_film: str = "mean-gap"        #: the fluid film at a separation, one of :data:`FLUID_FILMS`
    share_b: float = 1.90               #: Zhou–Hoeprich B of W_C/W = exp(−B λ^C) [-]
    share_c: float = 0.99               #: Zhou–Hoeprich C [-]

    def __post_init__(self) -> None:
        if self.contact not in CONTACT_LAWS:
            raise ValueError(f"asperity contact law must be one of {CONTACT_LAWS} (got {self.contact!r})")
        if self.fluid_film not in FLUID_FILMS:
            raise ValueError(f"fluid film must be one of {FLUID_FILMS} (got {self.fluid_film!r})")

    @property
    def K(self) -> float:
        """Greenwood–Tripp K = (16√2/15) π (ηβσ)² √(σ/β) [-]."""
        return K_GT * self.eta_beta_sigma**2 * math.sqrt(self.sigma_over_beta)

    def asperity_pressure(self, h, E_red: float) -> np.ndarray:
        """Mean asperity pressure p_C [Pa] at the nominal separation h [m] of the mean planes (negative:
        interpenetrating; E_red = E' = 2E*)."""
        t = np.asarray(h, dtype=float) / self.sigma
        if self.contact == "greenwood-tripp":
            return self.K * 0.5 * E_red * gt_function(2.5, t)
        return (4 / 3) * 0.5 * E_red * self.eta_beta_sigma * math.sqrt(self.sigma_over_beta) * gt_function(1.5, t)

    def fluid_gap(self, h) -> np.ndarray:
        """The fluid's film [m] at the nominal separation h [m] (``fluid_film``: the mean gap or h itself)."""
        h = np.asarray(h, dtype=float)
        return self.sigma * mean_gap(h / self.sigma) if self.fluid_film == "mean-gap" else h


@dataclass(frozen=True)
class LoadSplit:
    """The load sharing at each contact."""

    gamma1: np.ndarray          #: fluid load W_H = W/γ₁ [-]
    asperity_fraction: np.ndarray   #: W_C / W = 1/γ₂ = 1 − 1/γ₁ [-]
    film: np.ndarray            #: central film of the fluid part [m]
    film_parameter: np.ndarray  #: λ = h_film/σ [-]
    separation: np.ndarray      #: nominal separation of the mean planes over σ, h/σ [-]


def jgp_split(w, R, film, E_red: float, roughness: Roughness, bisections: int = 52) -> LoadSplit:
    """The load sharing W = W_H + W_C per contact, solved for the nominal separation h.

    ``film(w, E_red)`` returns the central film [m] of smooth line contacts of loads per length w [N/m] and
    reduced moduli E_red (arrays of the contacts' shape), their other parameters bound by the caller.  At a
    separation h the asperities carry W_C(h) = p_C(h) 2b (b the Hertz half-width of the whole load), the fluid
    W_H = W − W_C with E' W_H/W, and the split holds where the fluid's film film(W_H, E' W_H/W) equals its gap at h
    (:meth:`Roughness.fluid_gap`).  The mismatch film − gap falls monotonically with h (W_C falls, so the fluid
    carries more at a stiffer E' W_H/W and its film thins, while the gap grows), so all contacts are solved at once
    by bisection in t = h/σ on :data:`T_BRACKET` (``bisections`` halvings: 100/2^52 ≈ 2e-14); the side kept has
    W_C < W, so the fluid always keeps a positive share.  A contact whose smooth film exceeds the gap at the top of
    the bracket is full film (γ₁ = 1, W_C = 0; its ``separation`` is then the film over σ).  A film that is not
    finite at the solution raises :class:`~femgear.errors.ConvergenceError`.
    """
    w, R = np.broadcast_arrays(np.atleast_1d(np.asarray(w, float)), np.atleast_1d(np.asarray(R, float)))
    w, R = w.astype(float), R.astype(float)
    b = np.sqrt(8 * w * R / (math.pi * E_red))
    sigma = roughness.sigma

    def shares(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(W_C/W, fluid film [m]) at the separations t σ (film +inf where the asperities carry it all)."""
        frac = np.reshape(roughness.asperity_pressure(t * sigma, E_red), w.shape) * 2 * b / w
        inv = np.clip(1.0 - frac, 1e-12, 1.0)
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
            h = np.reshape(film(w * inv, E_red * inv), w.shape)
        return frac, np.where(frac < 1.0, h, np.inf)

    def mismatch(t: np.ndarray) -> np.ndarray:
        return shares(t)[1] - np.reshape(roughness.fluid_gap(t * sigma), w.shape)

    lo, hi = np.full(w.shape, T_BRACKET[0]), np.full(w.shape, T_BRACKET[1])
    full = mismatch(hi) >= 0.0
    for _ in range(bisections):
        mid = 0.5 * (lo + hi)
        up = mismatch(mid) > 0
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
    frac, h = shares(hi)
    frac = np.where(full, 0.0, frac)
    h = np.where(full, np.reshape(film(w, np.full(w.shape, E_red)), w.shape), h)
    if not np.all(np.isfinite(h)):
        from femgear.errors import ConvergenceError

        bad = ~np.isfinite(h)
        raise ConvergenceError("jgp_split", "the fluid's film is not finite at the load sharing's solution",
                               {"separation": hi[bad].tolist(), "asperity_fraction": frac[bad].tolist()})
    return LoadSplit(gamma1=1.0 / (1.0 - frac), asperity_fraction=frac, film=h, film_parameter=h / sigma,
                     separation=np.where(full, h / sigma, hi))


def zhou_hoeprich_split(w, R, film, E_red: float, roughness: Roughness) -> LoadSplit:
    """The load share W_C/W = exp(−B λ^C) of Zhou & Hoeprich (1991) at λ = h_c/σ, h_c = ``film(w, E_red)`` the
    smooth contacts' central film at the whole load (``separation`` is λ: the law has no mean planes)."""
    w, R = np.broadcast_arrays(np.atleast_1d(np.asarray(w, float)), np.atleast_1d(np.asarray(R, float)))
    h = np.reshape(film(w.astype(float), np.full(w.shape, E_red)), w.shape)
    if not np.all(np.isfinite(h)) or np.any(h < 0):
        from femgear.errors import ConvergenceError

        raise ConvergenceError("zhou_hoeprich_split", "the smooth film is not finite and positive",
                               {"film": np.asarray(h)[~np.isfinite(h) | (h < 0)].tolist()})
    lam = h / roughness.sigma
    frac = np.exp(-roughness.share_b * lam**roughness.share_c)
    with np.errstate(divide="ignore"):
        gamma1 = 1.0 / (1.0 - frac)
    return LoadSplit(gamma1=gamma1, asperity_fraction=frac, film=h, film_parameter=lam, separation=lam)


def load_split(w, R, film, E_red: float, roughness: Roughness) -> LoadSplit:
    """The load sharing of ``roughness.contact``: :func:`zhou_hoeprich_split` or the JGP split :func:`jgp_split`."""
    if roughness.contact == "zhou-hoeprich":
        return zhou_hoeprich_split(w, R, film, E_red, roughness)
    return jgp_split(w, R, film, E_red, roughness)


def split_table(loads, R, ue, srr, T_bulk: float, oil, E_red: float, solids, roughness: Roughness
                ) -> tuple[np.ndarray, np.ndarray]:
    """(asperity fraction W_a/W, film parameter λ), each (n, m): the JGP split of the thermal central film
    (:func:`femgear.physics.lubrication.traction.thermal_central_film`, as :func:`mixed_line_friction` takes it;
    the split of ``roughness.contact``, :func:`load_split`)
    at the loads per unit length ``loads`` (m,) [N/m] of each of the n contacts of radius ``R``, entrainment
    speed ``ue`` and slide-to-roll ratio ``srr`` (n,), oil at ``T_bulk`` [K]."""
    from femgear.physics.lubrication.traction import thermal_central_film

    loads = np.asarray(loads, float)
    R, ue, srr = (np.atleast_1d(np.asarray(a, float)) for a in (R, ue, srr))
    fraction, lam = np.empty((R.size, loads.size)), np.empty((R.size, loads.size))
    for i in range(R.size):
        def h_of(wf, Ef, i=i):
            return thermal_central_film(np.atleast_1d(wf), R[i], ue[i], abs(srr[i]), T_bulk, oil, Ef, solids)[0]

        s = load_split(loads, R[i], h_of, E_red, roughness)
        fraction[i], lam[i] = s.asperity_fraction, s.film_parameter
    return np.clip(fraction, 0.0, 1.0), lam


def mixed_line_friction(w, R, ue, srr, T_bulk, oil, E_red: float, solids, roughness: Roughness,
                        boundary_coefficient: float, **traction_kw):
    """Friction of rough line contacts: the fluid part plus μ_b W W_C/W on the asperities.  The fluid part
    (thermal Eyring traction, :func:`femgear.physics.lubrication.traction.line_contact_friction`): with the JGP
    split the smooth contact under W/γ₁ with E'/γ₁; with ``"zhou-hoeprich"`` the smooth contact under the whole
    load, weighted by 1 − W_C/W (its traction, flash and film temperature rises alike: the surface temperature is
    linear in the heat flux).  The asperities' frictional heat adds Blok's flash temperature of μ_b W_C/W over the
    Hertz band to the fluid part's surface and film temperature rises (adding the two maxima bounds the peak from
    above, both sources being near-elliptic over the same band).  Returns (TractionResult of the whole load,
    LoadSplit)."""
    from dataclasses import replace

    from femgear.physics.lubrication.flash import line_flash_temperature
    from femgear.physics.lubrication.traction import line_contact_friction, thermal_central_film

    w, R, ue, srr, T_bulk = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float))
                                                  for a in (w, R, ue, srr, T_bulk)))
    def h_of(wf, Ef):
        return thermal_central_film(wf, R, ue, srr, T_bulk, oil, Ef, solids)[0]

    split = load_split(w, R, h_of, E_red, roughness)
    frac = split.asperity_fraction
    if roughness.contact == "zhou-hoeprich":
        fluid = line_contact_friction(w, R, ue, srr, T_bulk, oil, E_red, solids, **traction_kw)
        fluid = replace(fluid, traction=(1 - frac) * fluid.traction, flash_max=(1 - frac) * fluid.flash_max,
                        film_max=(1 - frac) * fluid.film_max)
    else:
        gam = split.gamma1
        fluid = line_contact_friction(w / gam, R, ue, srr, T_bulk, oil, E_red / gam, solids, **traction_kw)
    traction = fluid.traction + boundary_coefficient * w * frac
    boundary = line_flash_temperature(boundary_coefficient * frac, w, R, ue, np.abs(srr), E_red, solids.B1, solids.B2)
    return replace(fluid, mu=traction / w, traction=traction, flash_max=fluid.flash_max + boundary,
                   film_max=fluid.film_max + boundary), split
