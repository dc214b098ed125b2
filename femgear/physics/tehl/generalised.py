"""The generalised Reynolds equation of a thermal line film: its cross-film integrals.

With the viscosity η(z) and density ρ(z) varying across the film (0 ≤ z ≤ h, surface 1 at z = 0
moving at u_a = v1, surface 2 at z = h at u_b = v2), the thin-film momentum balance
∂/∂z(η ∂u/∂z) = p' integrates to

    u(z) = u_a + A F0(z) + p' F1(z),   F0(z) = ∫_0^z dz'/η,   F1(z) = ∫_0^z z' dz'/η,
    A = (u_b − u_a − p' F1(h)) / F0(h),

and continuity, d/dx ∫_0^h ρ u dz = 0 (steady), gives the generalised Reynolds equation of Yang & Wen
(1990, *J. Tribol.* 112:631, "A generalized Reynolds equation for non-Newtonian thermal
elastohydrodynamic lubrication"; the same integrals as Najji, Bou-Saïd & Berthe 1989, *J. Tribol.*
111:29):

    d/dx [ε p'] = d/dx [q_c],
    ε   = F1(h) I0 / F0(h) − I1                 (= (ρ/η)_e h³ / 12 in Yang & Wen's notation),
    q_c = u_a ∫_0^h ρ dz + (u_b − u_a) I0 / F0(h) (= ρ* u_e h),
    I0 = ∫_0^h ρ F0 dz,   I1 = ∫_0^h ρ F1 dz,

the mass flux per unit width being m = q_c − ε p'.  (Derived here from the momentum balance; Yang &
Wen's paper is not in the stored library, so its symbols η_e, η_e', ρ_e, ρ_e' are named only in these
equivalences: ε = h³ (ρ_e'/2 − ρ_e'')/η_e' with ρ_e' = (η_e/h²) I0, ρ_e'' = (η_e'/h³) I1, η_e = h/F0(h),
η_e' = h²/(2 F1(h)).)  For a film isoviscous and of uniform density across its thickness, F0 = z/η,
F1 = z²/(2η), ε = ρ h³/(12 η) and q_c = ρ h (u_a + u_b)/2: the reduced Reynolds equation exactly.

The profiles are piecewise constant on the energy solve's ``nz`` equal layers (its layer temperatures),
and the integrals above are exact for them (F0 piecewise linear, F1 piecewise quadratic).  With a
viscosity that falls across the film towards the faster surface's colder side, q_c varies along x even at
u_e = 0: the temperature-viscosity wedge that carries the load of opposite sliding (Yang, Cui, Kaneta &
Kyogoku 2001, *J. Tribol.* 123:36: "On the theory of thermal elastohydrodynamic lubrication at high
slide-roll ratios — line contact solution"; the central dimple of Kaneta's interferometry).

The Eyring fluid: with the shear stress of the Couette flow constant across the film (the energy solve's
assumption, Johnson & Tevaarwerk 1977), the equivalent viscosity η* = τ/γ̇ of each layer is its Newtonian
viscosity times a factor common to the column, which cancels from q_c; the Poiseuille coefficient ε keeps
the Newtonian layer viscosities (the pressure flow is not shear-thinned: the reduced model's assumption).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CrossFilm:
    """The generalised Reynolds coefficients of the cells (SI, per unit width of the contact line)."""

    eps: np.ndarray     #: Poiseuille coefficient ε = F1(h) I0/F0(h) − I1 [m s] (ρ h³/(12 η) for a uniform film)
    rho_h: np.ndarray   #: ∫ ρ dz [kg/m²]
    rho_f0: np.ndarray  #: I0 / F0(h) [kg/m²]: the share of the surfaces' speed difference carried

    def couette(self, v1: float, v2: float) -> np.ndarray:
        """q_c = v1 ∫ρ dz + (v2 − v1) I0/F0(h) [kg/(m s)]."""
        return v1 * self.rho_h + (v2 - v1) * self.rho_f0

    def mass_flux(self, v1: float, v2: float, dpdx: np.ndarray) -> np.ndarray:
        """m = q_c − ε p' [kg/(m s)] with the pressure gradient ``dpdx`` [Pa/m] of the cells."""
        return self.couette(v1, v2) - self.eps * dpdx


def cross_film(eta: np.ndarray, rho: np.ndarray, h: np.ndarray) -> CrossFilm:
    """The integrals of the module docstring for ``nz`` equal layers: ``eta`` [Pa s] and ``rho`` [kg/m³] of shape
    (nt, nz) (layer 0 on surface 1), ``h`` (nt,) [m].  In the mapped coordinate ζ = z/h: F0 = h f0(ζ),
    F1 = h² f1(ζ), so ε = h³ (f1(1) i0/f0(1) − i1) with i0 = ∫ρ f0 dζ, i1 = ∫ρ f1 dζ."""
    eta = np.asarray(eta, dtype=float)
    rho = np.asarray(rho, dtype=float)
    nz = eta.shape[1]
    d = 1.0 / nz
    zf = np.arange(nz + 1) * d                             # layer faces in ζ
    inv = 1.0 / eta
    f0 = np.zeros((eta.shape[0], nz + 1))
    f0[:, 1:] = np.cumsum(inv * d, axis=1)                 # f0 at the faces
    f1 = np.zeros_like(f0)
    f1[:, 1:] = np.cumsum(inv * (zf[1:] ** 2 - zf[:-1] ** 2) / 2.0, axis=1)
    i0 = np.sum(rho * d * 0.5 * (f0[:, :-1] + f0[:, 1:]), axis=1)
    # ∫ over layer k of f1 = d f1(ζ_k) + [(ζ_(k+1)^3 − ζ_k^3)/3 − ζ_k^2 d] / (2 η_k)
    cubic = (zf[1:] ** 3 - zf[:-1] ** 3) / 3.0 - zf[:-1] ** 2 * d
    i1 = np.sum(rho * (d * f1[:, :-1] + inv * cubic / 2.0), axis=1)
    h = np.asarray(h, dtype=float)
    return CrossFilm(eps=h**3 * (f1[:, -1] * i0 / f0[:, -1] - i1), rho_h=h * np.sum(rho * d, axis=1),
                     rho_f0=h * i0 / f0[:, -1])


def reduced(eta_mean: np.ndarray, rho_mean: np.ndarray, h: np.ndarray) -> CrossFilm:
    """The reduced equation's coefficients at one viscosity and density per cell (ρ h³/(12 η), ρ h, ρ h/2)."""
    return CrossFilm(eps=rho_mean * h**3 / (12.0 * eta_mean), rho_h=rho_mean * h, rho_f0=0.5 * rho_mean * h)


def of_film(oil, p: np.ndarray, h: np.ndarray, T: np.ndarray, compressible: bool = True) -> CrossFilm:
    """:func:`cross_film` of an oil (:class:`femgear.physics.lubrication.oil.OilLaw`) at the pressures ``p`` [Pa]
    and films ``h`` [m] of the cells (or faces) and the layer temperatures ``T`` [K] (n, nz); ``compressible``
    False: a uniform density (the Reynolds equation's when the Dowson–Higginson law is off)."""
    eta = oil.viscosity(p[:, None], T)
    rho = oil.density(p[:, None], T) if compressible else np.ones_like(eta)
    return cross_film(eta, rho, h)


def reduced_of(oil, p: np.ndarray, h: np.ndarray, T_mean: np.ndarray, compressible: bool = True) -> CrossFilm:
    """:func:`reduced` of an oil at the film-mean temperatures ``T_mean`` [K] (the reduced equation's)."""
    eta = oil.viscosity(p, T_mean)
    rho = oil.density(p, T_mean) if compressible else np.ones_like(eta)
    return reduced(eta, rho, h)


def mass_flux(xf: np.ndarray, p: np.ndarray, h: np.ndarray, T_layers: np.ndarray, oil, v1: float, v2: float) -> float:
    """The Reynolds mass flux per unit width [kg/(m s)] of the generalised equation, m = q_c − ε p' at the faces
    ``xf`` [m] (pressures ``p`` [Pa], films ``h`` [m], layer temperatures ``T_layers`` (n, nz) [K]), averaged
    with the weights p² as :func:`femgear.physics.tehl.energy._mass_flux` averages the reduced one (which it
    equals, to round-off, for temperatures uniform across the film).  Any sign where the surfaces move apart (at
    zero entrainment the flux of a symmetric contact vanishes)."""
    cf = of_film(oil, p, h, T_layers)
    q = cf.mass_flux(v1, v2, np.gradient(p, xf))
    wgt = p**2
    if not wgt.sum() > 0:
        return float(np.max(cf.couette(v1, v2)))
    m = float(wgt @ q / wgt.sum())
    # an under-resolved film (a coarse grid of a nanometre film) can make the Poiseuille share meaningless
    return m if (m > 0 or v1 * v2 < 0) else float(wgt @ cf.couette(v1, v2) / wgt.sum())
