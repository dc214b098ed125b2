"""Thermal traction of a Hertzian EHL line contact: the cheap ("formula") friction level.

The film is taken as the EHL plateau: Hertz pressure p(x) = p_H √(1 − x²/b²) across
the band and a uniform film of the central thickness h_c (film formula times the
thermal inlet factor of Gupta et al.).  The sliding (Couette) shear stress follows a
Newtonian or Ree–Eyring law,

    τ = η γ̇            or   τ = τ0 asinh(η γ̇ / τ0),    γ̇ = |v1 − v2| / h,

optionally capped by a limiting shear stress Λ p.  The viscosity η(p, T) is taken at
the mean film temperature T = T_bulk + ΔT_s(x) + τ γ̇ h²/(12 k_f): the surface flash
temperature of :mod:`.flash` for the heat flux q = τ |v1 − v2| plus the mean rise of a
film sheared uniformly and cooled through both walls (parabolic profile, mid-film
rise τ γ̇ h²/(8 k_f)).  The temperature–traction fixed point is solved for all positions
at once.  μ = ∫τ dx / w'.  Rolling (Poiseuille) traction vanishes for a uniform film;
the FE (T)EHL levels compute it from their fields.

Sources: Johnson & Tevaarwerk, Proc. R. Soc. A 356 (1977) 215 (Eyring traction);
Crook (1961), Johnson & Greenwood (1980) for the thermal film; Gupta, Cheng, Zhu,
Forster & Schrand, J. Tribol. 114 (1992) 609 (thermal reduction factor).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.lubrication.flash import abel_matrix, band_flash_temperature
from femgear.physics.lubrication.oil import OilLaw


def gupta_thermal_factor(p_h, E_red: float, srr, ue, eta0: float, beta_t: float, k_f: float):
    """Thermal reduction of the central film, φ_T (Gupta et al. 1992).

    φ_T = [1 − 13.2 (p_h/E') L*^0.42] / [1 + 0.213 (1 + 2.23 |SRR|^0.83) L*^0.64],
    L* = β_T η0 u_e² / k_f (the thermal loading parameter).  The fit's numerator changes
    sign at extreme load and speed (13.2 (p_h/E') L*^0.42 ≥ 1: far outside the data it
    was fitted to); there φ_T is floored at :data:`GUPTA_FLOOR` (a film of a tenth of
    the isothermal one) and :func:`gupta_out_of_range` says where.
    """
    L_star = beta_t * eta0 * np.asarray(ue) ** 2 / k_f
    num = 1 - 13.2 * np.asarray(p_h) / E_red * L_star**0.42
    den = 1 + 0.213 * (1 + 2.23 * np.abs(srr) ** 0.83) * L_star**0.64
    return np.maximum(num / den, GUPTA_FLOOR)


#: smallest thermal film factor used (the fit turns negative beyond its range)
GUPTA_FLOOR = 0.1


def gupta_out_of_range(p_h, E_red: float, ue, eta0: float, beta_t: float, k_f: float) -> np.ndarray:
    """True where Gupta's fit would give φ_T ≤ :data:`GUPTA_FLOOR` (its numerator ≤ 0.1)."""
    L_star = beta_t * eta0 * np.asarray(ue) ** 2 / k_f
    return 1 - 13.2 * np.asarray(p_h) / E_red * L_star**0.42 <= GUPTA_FLOOR


@dataclass(frozen=True)
class Solids:
    """Thermal effusivities B = √(kρc) of pinion and gear [W s^½/(m² K)] and the oil conductivity."""

    B1: float
    B2: float
    k_oil: float


@dataclass(frozen=True)
class TractionResult:
    """Traction and temperatures at each contact (arrays over positions)."""

    mu: np.ndarray              #: friction coefficient (Couette) [-]
    traction: np.ndarray        #: sliding traction per unit length [N/m]
    flash_max: np.ndarray       #: max surface temperature rise [K]
    film_max: np.ndarray        #: max mean-film temperature rise over the bulk [K]
    film_thickness: np.ndarray  #: film used [m]
    iterations: int


def shear_stress(eta, rate, model: str, tau0: float):
    """Newtonian or Ree–Eyring shear stress [Pa]."""
    if model == "newtonian":
        return eta * rate
    if model == "eyring":
        return tau0 * np.arcsinh(eta * rate / tau0)
    raise ValueError(f"traction model must be 'newtonian' or 'eyring' (got {model!r})")


def hertz_traction(w, b, p_h, h, v1, v2, T_bulk, oil: OilLaw, solids: Solids, model: str = "eyring",
                   tau0: float = 5e6, limiting_shear: float = 0.0, n: int = 48, tol: float = 1e-6,
                   max_iter: int = 300) -> TractionResult:
    """Sliding traction of Hertzian EHL line contacts (arrays over contacts).

    ``w`` load per length [N/m], ``b`` Hertz half-width [m], ``p_h`` Hertz pressure [Pa],
    ``h`` film [m], ``v1``, ``v2`` surface speeds [m/s], ``T_bulk`` oil inlet/bulk temperature [K].
    """
    w, b, p_h, h, v1, v2, T_bulk = np.broadcast_arrays(
        *(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, b, p_h, h, v1, v2, T_bulk)))
    T_bulk = T_bulk[:, None]
    if np.any(h <= 0) or np.any(b <= 0):
        raise ValueError("film thickness and half-width must be positive")
    xi = -1 + (2 * np.arange(n) + 1) / n                      # cell centres on [−1, 1]
    p = p_h[:, None] * np.sqrt(1 - xi[None, :] ** 2)
    vs = np.abs(v1 - v2)[:, None]
    rate = vs / h[:, None]
    A = abel_matrix(n)
    T = np.broadcast_to(T_bulk, p.shape).copy()
    dT_surface = np.zeros(p.shape)
    for it in range(1, max_iter + 1):  # noqa: B007 — the count is reported after the loop
        tau = shear_stress(oil.viscosity(p, T), rate, model, tau0)
        if limiting_shear > 0:
            tau = np.minimum(tau, limiting_shear * p)
        q = tau * vs
        dT_surface = band_flash_temperature(q, b, v1, v2, solids.B1, solids.B2, A)
        dT_film = q * h[:, None] / (12 * solids.k_oil)        # τ γ̇ h²/12k = q h/12k
        T_new = T_bulk + dT_surface + dT_film
        change = float(np.max(np.abs(T_new - T)))
        T = 0.5 * (T + T_new)
        if change < tol:
            break
    else:
        raise ConvergenceError("hertz_traction", "temperature-traction fixed point did not converge",
                               {"max_temperature_change": [change]})
    traction = tau.sum(axis=1) * (2 * b / n)
    mu = traction / w
    if not np.all(np.isfinite(mu)):
        raise ConvergenceError("hertz_traction", "non-finite traction", {"iterations": [it]})
    return TractionResult(mu=mu, traction=traction, flash_max=dT_surface.max(axis=1),
                          film_max=(T - T_bulk).max(axis=1), film_thickness=h, iterations=it)


def line_contact_friction(w, R, ue, srr, T_bulk, oil: OilLaw, E_red: float, solids: Solids, model: str = "eyring",
                          tau0: float = 5e6, limiting_shear: float = 0.0, n: int = 48) -> TractionResult:
    """Friction of EHL line contacts from operating data alone (arrays broadcast).

    ``w`` load per length [N/m], ``R`` reduced radius [m], ``ue`` entrainment speed [m/s],
    ``srr`` slide-to-roll ratio (v1 − v2)/ue [-], ``T_bulk`` [K].  Hertz half-width and
    pressure, the Moes (1992) central film at the inlet viscosity η(0, T_bulk) times
    Gupta's thermal factor, then :func:`hertz_traction`.
    """
    w, R, ue, srr, T_bulk = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, srr, T_bulk)))
    if np.any(w <= 0) or np.any(R <= 0) or np.any(ue <= 0):
        raise ValueError("load, radius and entrainment speed must be positive")
    h, b, p_h = thermal_central_film(w, R, ue, srr, T_bulk, oil, E_red, solids)
    return hertz_traction(w, b, p_h, h, ue * (1 + srr / 2), ue * (1 - srr / 2), T_bulk, oil, solids,
                          model=model, tau0=tau0, limiting_shear=limiting_shear, n=n)


def thermal_central_film(w, R, ue, srr, T_bulk, oil: OilLaw, E_red, solids: Solids):
    """(h_c, b, p_h): the Moes (1992) central film at the inlet viscosity η(0, T_bulk) and α(T_bulk) times
    Gupta's thermal factor, and the Hertz half-width and pressure (arrays broadcast; E_red
    may be an array, as in the JGP split of :mod:`femgear.physics.lubrication.mixed`)."""
    from femgear.physics.contact.film import line_film

    b = np.sqrt(8 * w * R / (np.pi * E_red))
    p_h = 2 * w / (np.pi * b)
    eta_in = oil.viscosity(0.0, T_bulk)
    h = line_film(w, R, ue, E_red, eta_in, oil.pressure_viscosity(T_bulk)).central_moes
    return h * gupta_thermal_factor(p_h, E_red, srr, ue, eta_in, oil.temperature_viscosity(T_bulk), solids.k_oil), b, p_h
