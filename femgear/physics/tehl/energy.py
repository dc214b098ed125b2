"""Energy equation of a line-contact film between two moving semi-infinite solids.

Film (reduced form, documented): ``nz`` layers across the film (mapped coordinate
ζ = z/h, body 1 at z = 0 moving at v1, body 2 at z = h moving at v2) on ``nt`` cells
along x; conservative finite volumes, upwind in x and across the layers (upwinding of the
energy equation, notes §7.6), conduction across the film, conduction along x neglected (high
Péclet number).  The convected face temperatures are second order: the upwind cell's value
plus a limited linear reconstruction (MUSCL with van Leer's limiter: van Leer 1979,
*J. Comput. Phys.* 32:101; the reconstruction is bounded by the neighbours, so no new extrema),
applied as a deferred correction: the matrix is the first-order upwind one, and the
reconstruction's part of the face fluxes, from the temperatures the viscosities are frozen
at, goes to the right-hand side, so that it is exact at the thermal loop's fixed point
(:func:`convection_correction`).  Measured at the VG 32, 40 °C, 60 m/s, 2.5 GPa rolling corner,
the film's peak rise 114.4 / 117.1 / 118.1 K on 513 / 1025 / 2049 nodes (16 layers) with first-order
upwinding, 117.3 / 119.3 / 119.7 K with the reconstruction; across the film (1025 nodes) 111.2 /
117.1 / 118.9 / 119.4 K on 8 / 16 / 32 / 64 layers, 113.5 / 119.3 / 120.4 / 120.6 K with it.

Shear heating per layer from the layer shear rates (Ree–Eyring or Newtonian, the shear stress
τ_c constant across the film, so that τ_c = τ0 asinh(η_e γ̇/τ0) with η_e the harmonic cross-film
mean viscosity — Johnson & Tevaarwerk 1977).  Advection by the flow of the reduced Reynolds equation: the linear
Couette profile plus the Poiseuille parabola at the film-mean viscosity.  (Advecting
with the layer shear-rate profile made the flow split depend on every layer's
temperature; in the inlet back-flow a layer with almost no flow along x then took its
temperature from the sign of a tiny cross-layer flux, itself a difference of those
splits, and the thermal fixed point chattered cell to cell at p_h >= 1 GPa, SRR 1.)
The layer mass fluxes are the local flow split times the constant
Reynolds mass flux ρ h u at the pressure maximum, so that discrete continuity holds
exactly (the cross-layer fluxes close at the walls) and the scheme conserves energy to
round-off: heat generated = heat into the solids + heat convected out (tested).

Heat sources: viscous dissipation of the Couette (τ_c γ̇_k) and Poiseuille
((z − h/2)² p'² / η_k) flows; compression heating ε' T u p' (ε' = −(1/ρ)∂ρ/∂T of the
thermally expanding Dowson–Higginson density), implicit in T.

Solids: moving semi-infinite bodies at high Péclet number, exact Jaeger/Carslaw & Jaeger
moving-heat-source solution as a boundary operator (Carslaw & Jaeger, *Conduction of
Heat in Solids*, 2nd ed. 1959, §10.7; Jaeger 1942): the surface temperature rise of body j is
θ_j(x) = ∫ q_j(ξ)/√(x − ξ) dξ / (B_j √(π |v_j|)), B_j = √(k ρ c), upstream side first
(the Abel matrix of :mod:`femgear.physics.lubrication.flash`).  q_j = 2 k_f (θ_wall cell − θ_j)/Δz.
All relations are linear in the temperature once viscosities are frozen: one linear
solve per thermal iteration (:func:`linear_solve`: the film with the near part of the
Jaeger operators factorised, their dense far field by iterative refinement).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from femgear.errors import ConvergenceError
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import shear_stress


@dataclass(frozen=True)
class ThermalProps:
    """Thermal data: oil conductivity k_f [W/(m K)], oil specific heat c_f [J/(kg K)],
    solid effusivities B1, B2 = √(kρc) [W s^½/(m² K)] and, for the solids' exact moving-source
    operator at any Péclet number, their conductivities k1, k2 [W/(m K)] (None: the high-Péclet
    Jaeger operator, :func:`surface_matrix`)."""

    k_oil: float
    c_oil: float
    B1: float
    B2: float
    k1: float | None = None
    k2: float | None = None


@dataclass(frozen=True)
class EnergyState:
    """Temperatures and heat flows of one energy solve (cells along x)."""

    theta: np.ndarray        #: film temperature rise (nt, nz) [K]
    surface1: np.ndarray     #: surface temperature rise of body 1 (nt,) [K]
    surface2: np.ndarray     #: surface temperature rise of body 2 (nt,) [K]
    tau_couette: np.ndarray  #: Couette shear stress (nt,) [Pa], sign of v2 − v1
    tau_poiseuille: np.ndarray  #: Poiseuille wall stress magnitude h p'/2 (nt,) [Pa]
    heat: dict               #: W/m: generated, shear, compression, solid1, solid2, convected, balance_error


#: a surface at rest (or nearly so) is given the speed whose diffusion length 2 κ / |v| is this many
#: contact half-lengths of the band (no steady temperature exists in a semi-infinite body at rest)
REST_DEPTH = 20.0


def surface_matrix(x_faces: np.ndarray, v: float, B: float, k: float | None = None) -> np.ndarray:
    """θ = G q: surface temperature rise [K] at the cell centres of a semi-infinite solid moving at ``v``
    [m/s] along x under a heat flux q [W/m²] constant on the cells of ``x_faces`` (any spacing).

    ``k`` None: Jaeger's high-Péclet operator (Jaeger 1942; Carslaw & Jaeger 1959 §10.7),
    θ(x) = ∫ q(ξ) / √(x − ξ) dξ / (B √(π |v|)) over the upstream side, cell integrals
    2 (√(x − a) − √(x − b)).  ``k`` given (the conductivity; κ = (k/B)²): the exact 2-D moving
    line source at any Péclet number (Carslaw & Jaeger 1959 §10.7, the quasi-steady line source),
    θ(x) = (1/(π k)) ∫ q(ξ) e^(u s) K0(|u s|) dξ, s = x − ξ, u = v/(2κ), whose cell integrals are
    closed: with Φ(τ) = ∫_0^τ e^t K0(|t|) dt = τ e^τ (K0(τ) + K1(τ)) − 1 for τ > 0 and
    −[σ e^−σ (K0(σ) − K1(σ)) + 1] for τ = −σ < 0 (differentiate to check), G_ij =
    [Φ(u (x_i − a_j)) − Φ(u (x_i − b_j))] / (π k u); at high u the Jaeger form is its limit.  A
    surface at rest has no steady temperature; its speed is raised to the one whose diffusion
    length 2κ/|v| is :data:`REST_DEPTH` times the band length (a documented regularisation)."""
    xf = np.asarray(x_faces, dtype=float)
    xc = 0.5 * (xf[:-1] + xf[1:])
    x = xc[:, None]
    if k is None:
        if abs(v) <= 0.0:
            raise ConvergenceError("tehl energy", "a surface at rest: the steady temperature of a stationary "
                                   "semi-infinite body under a line source is unbounded (pure sliding)")
        S = np.sqrt(np.clip((x - xf[None, :]) * math.copysign(1.0, v), 0.0, None))
        G = 2.0 * (S[:, :-1] - S[:, 1:]) if v > 0 else 2.0 * (S[:, 1:] - S[:, :-1])
        return G / (B * math.sqrt(math.pi * abs(v)))
    kappa = (k / B) ** 2
    u_min = 1.0 / (REST_DEPTH * (xf[-1] - xf[0]))
    u = v / (2.0 * kappa)
    u = math.copysign(max(abs(u), u_min), v if v != 0.0 else 1.0)
    F = _phi(u * (x - xf[None, :]))          # at every face once: each inner face bounds two cells
    return (F[:, :-1] - F[:, 1:]) / (math.pi * k * u)


def _phi(t: np.ndarray) -> np.ndarray:
    """Φ(τ) = ∫_0^τ e^t K0(|t|) dt (:func:`surface_matrix`), by the scaled Bessel functions."""
    from scipy.special import k0e, k1e

    out = np.zeros_like(t)
    pos, neg, far = (t > 0) & (t < PHI_ASYMPTOTIC), (t < 0) & (t >= -PHI_FAR), t >= PHI_ASYMPTOTIC
    tp = t[pos]
    out[pos] = tp * (k0e(tp) + k1e(tp)) - 1.0
    out[far] = _phi_far(t[far])
    sn = -t[neg]
    out[neg] = -(sn * np.exp(-2.0 * sn) * (k0e(sn) - k1e(sn)) + 1.0)
    out[t < -PHI_FAR] = -1.0
    return out


def _phi_far(t: np.ndarray) -> np.ndarray:
    """Φ(τ) at τ ≥ :data:`PHI_ASYMPTOTIC` by the asymptotic series, Horner's rule in place (numpy's polyval
    allocates an array per term: 14 ms against 8.5 ms on the half million far entries of a 1024-cell operator, the same values)."""
    r = 1.0 / t
    acc = np.full_like(t, _PHI_SERIES[-1])
    for a in _PHI_SERIES[-2::-1]:
        acc *= r
        acc += a
    np.multiply(t, 0.5 * math.pi, out=r)
    acc *= np.sqrt(r, out=r)
    acc -= 1.0
    return acc


def _bessel_series(nu: int, terms: int) -> np.ndarray:
    """The coefficients a_k of e^x K_ν(x) ~ √(π / 2x) Σ a_k x^−k, a_k = Π_{j ≤ k} (4ν² − (2j − 1)²) / (k! 8^k)
    (Abramowitz & Stegun 1964, 9.7.2)."""
    a = np.ones(terms)
    for k in range(1, terms):
        a[k] = a[k - 1] * (4 * nu * nu - (2 * k - 1) ** 2) / (8.0 * k)
    return a


#: upstream beyond this distance (τ ≥ PHI_ASYMPTOTIC) Φ is taken from the asymptotic series of K0 + K1 (its 14 terms
#: at τ ≥ 50: truncation below 1e-17 relative, the 14th term about 1e-18; agrees with the Bessel functions to 1e-15
#: relative) instead of the Bessel functions (about 0.1 µs an entry each: 8x the series on a turbo contact's cells)
PHI_ASYMPTOTIC = 50.0
_PHI_SERIES = _bessel_series(0, 14) + _bessel_series(1, 14)

#: beyond this distance downstream (τ < −PHI_FAR) Φ is −1 to round-off: its other term, σ e^−2σ (K1 − K0)(σ) e^σ ≈
#: e^−2σ √(π / 2σ) / 2, is below 1e-18 there; the Bessel functions are not evaluated (half the matrix at high Péclet)
PHI_FAR = 20.0


def jaeger_matrix(nt: int, length: float, B: float, v: float) -> np.ndarray:
    """θ = J q for a solid moving at ``v`` under a heat flux q on ``nt`` equal cells of a band of total
    ``length`` [m] (:func:`surface_matrix` with the high-Péclet operator)."""
    return surface_matrix(np.linspace(0.0, length, nt + 1), v, B)


def poiseuille_weights(nz: int) -> np.ndarray:
    """The share of each of ``nz`` equal layers in a parabolic (Poiseuille) profile's flux:
    ∫ 6 ζ (1 − ζ) dζ over the layer."""
    z = np.linspace(0.0, 1.0, nz + 1)
    F = 3.0 * z**2 - 2.0 * z**3
    return np.diff(F)


def solve_energy(x_faces: np.ndarray, p_faces: np.ndarray, h_cells: np.ndarray, v1: float, v2: float,
                 T_bulk: float, theta: np.ndarray, oil: OilLaw, props: ThermalProps, J1: np.ndarray,
                 J2: np.ndarray, *, model: str = "eyring", tau0: float = 5e6, limiting_shear: float = 0.0,
                 heat: bool = True, h_faces: np.ndarray | None = None, mass_flux: float | None = None,
                 cache: dict | None = None) -> EnergyState:
    """One linear energy solve with viscosities frozen at the previous film temperatures
    ``T_bulk + theta`` (nt, nz).  Arrays in SI units; ``x_faces`` (nt + 1,) increasing, any spacing;
    ``J1``, ``J2`` the solids' surface operators (:func:`surface_matrix`).

    Flow (the convection): the Couette profile plus a Poiseuille parabola whose flux is set by
    continuity, q_P = m/ρ − u_e h at every face, m the Reynolds mass flux per unit width
    (``mass_flux``; default :func:`_mass_flux`), so that every column
    carries exactly m (the layer fluxes close at both walls) and the split never degenerates where the
    inlet back-flow nearly cancels the entrainment (an earlier split by the column's own Couette plus
    Poiseuille flux, from p' differenced on the cells, turned negative there on heavy or hot contacts
    and needed a switch).  ``h_faces``: the film at the faces (default: interpolated); ``cache``: the
    factors kept across the solves of a thermal loop (:func:`linear_solve`)."""
    nt, nz = theta.shape
    xf = np.asarray(x_faces, dtype=float)
    dx = np.diff(xf)
    p = 0.5 * (p_faces[:-1] + p_faces[1:])
    dpdx = np.diff(p_faces) / dx
    h = h_cells
    hf = _faces_of(h) if h_faces is None else h_faces
    dz = h / nz
    T_old = T_bulk + theta
    eta = oil.viscosity(p[:, None], T_old)                       # (nt, nz)
    eta_e = nz / np.sum(1.0 / eta, axis=1)                       # harmonic mean
    du = v2 - v1
    ue = 0.5 * (v1 + v2)
    tau_c = shear_stress(eta_e, du / h, model, tau0)
    if limiting_shear > 0:
        tau_c = np.sign(tau_c) * np.minimum(np.abs(tau_c), limiting_shear * p)
    if model == "eyring":
        rate = (tau0 / eta) * np.sinh(tau_c / tau0)[:, None]
    else:
        rate = tau_c[:, None] / eta
    S = np.sum(rate, axis=1) * dz
    rate = np.where(np.abs(S)[:, None] > 0, rate * (du / np.where(S == 0, 1.0, S))[:, None], 0.0)
    # layer fluxes [m²/s]: Couette (linear) + Poiseuille (parabola) with the flux continuity sets
    T_f = T_bulk + _faces_of(theta.mean(axis=1))
    rho_f = oil.density(p_faces, T_f)
    m_tot = _mass_flux(xf, p_faces, hf, rho_f, oil.viscosity(p_faces, T_f), ue) if mass_flux is None \
        else float(mass_flux)
    if not math.isfinite(m_tot) or (v1 * v2 >= 0 and not m_tot > 0):   # any sign when the surfaces move apart
        raise ConvergenceError("tehl energy", "non-positive mass flux (no entrainment)")
    zeta = np.linspace(0.0, 1.0, nz + 1)
    wc = v1 * np.diff(zeta) + du * np.diff(zeta**2) / 2.0        # Couette flux / h per layer
    wp = poiseuille_weights(nz)
    phi_f = hf[:, None] * wc[None, :] + (m_tot / rho_f - ue * hf)[:, None] * wp[None, :]
    m = rho_f[:, None] * phi_f                                   # (nt+1, nz) kg/(m s): rows sum to m_tot
    m += wp[None, :] * (m_tot - m.sum(axis=1))[:, None]          # exact to round-off (any sign of m_tot)
    phi = 0.5 * (phi_f[:-1] + phi_f[1:])
    G = np.zeros((nt, nz + 1))                                   # upward mass flux between layers
    G[:, 1:] = np.cumsum(m[:-1] - m[1:], axis=1)
    G[:, -1] = 0.0                                               # exact up to round-off
    zf = dz[:, None] * np.arange(nz + 1)[None, :]
    za, zb = zf[:, :-1], zf[:, 1:]
    # sources [W/m per cell]
    layer_sq = ((zb - h[:, None] / 2) ** 3 - (za - h[:, None] / 2) ** 3) / 3
    src_shear = (tau_c[:, None] * rate * dz[:, None] + dpdx[:, None] ** 2 * layer_sq / eta) * dx[:, None]
    eps_t = oil.expansion / np.maximum(1.0 - oil.expansion * (T_old - oil.T0), 1e-3)
    a_comp = eps_t * phi * dpdx[:, None] * dx[:, None]            # compression power = a (T_b + θ)
    if not heat:
        src_shear = np.zeros_like(src_shear)
        a_comp = np.zeros_like(a_comp)
    c = props.c_oil
    args = (m, G, a_comp, dx, dz, c, props.k_oil, J1, J2)
    rhs = np.zeros(nt * (nz + 2))
    rhs[:nt * nz] = (src_shear + a_comp * T_bulk - c * convection_correction(theta, m, G, xf)).ravel()
    sol = linear_solve(args, rhs, nt * nz, cache)
    if not np.all(np.isfinite(sol)):
        raise ConvergenceError("tehl energy", "non-finite temperatures")
    th = sol[:nt * nz].reshape(nt, nz)
    q1, q2 = sol[nt * nz:nt * (nz + 1)], sol[nt * (nz + 1):]
    gen_shear = float(src_shear.sum())
    gen_comp = float(np.sum(a_comp * (T_bulk + th)))
    conv = float(c * (np.sum(np.maximum(m[-1], 0) * th[-1]) - np.sum(np.minimum(m[0], 0) * th[0])))
    s1, s2 = float(q1 @ dx), float(q2 @ dx)
    gen = gen_shear + gen_comp
    scale = max(abs(gen_shear), abs(s1) + abs(s2) + abs(conv), 1e-300)
    heat_d = {"generated": gen, "shear": gen_shear, "compression": gen_comp, "solid1": s1, "solid2": s2,
              "convected": conv, "balance_error": (gen - s1 - s2 - conv) / scale}
    return EnergyState(theta=th, surface1=J1 @ q1, surface2=J2 @ q2, tau_couette=tau_c,
                       tau_poiseuille=0.5 * h * dpdx, heat=heat_d)


def convection_correction(theta: np.ndarray, m: np.ndarray, G: np.ndarray, x_faces: np.ndarray) -> np.ndarray:
    """The second-order part of the convected heat per cell (nt, nz) [kg/(m s) K; times c: W/m], the net outflow
    Σ_faces F (T_face − T_upwind) of a MUSCL reconstruction (:func:`_limited_outflow`) along x (face fluxes ``m``,
    (nt + 1, nz)) and across the layers (``G``, (nt, nz + 1), uniform in the mapped coordinate), for the film
    temperatures ``theta``.  Interior faces only: the boundary faces stay first order, so the correction sums to
    zero over the film and the energy balance of the upwind scheme holds as before."""
    xc = 0.5 * (x_faces[:-1] + x_faces[1:])
    along = _limited_outflow(theta, m, xc, x_faces)
    zc = np.arange(theta.shape[1]) + 0.5
    across = _limited_outflow(theta.T, G.T, zc, np.arange(theta.shape[1] + 1.0)).T
    return along + across


def _limited_outflow(theta: np.ndarray, flux: np.ndarray, centres: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Along axis 0 of ``theta`` (n, ...), cells at ``centres`` between ``faces`` (n + 1,), with the face fluxes
    ``flux`` (n + 1, ...): the net outflow of each cell of the difference between the reconstructed face value,
    T_up + (x_f − x_up) s_up with van Leer's limited slope s = 2 s_b s_f / (s_b + s_f) where the one-sided slopes
    s_b, s_f agree in sign (else 0; the end cells 0), and the upwind value T_up."""
    n = theta.shape[0]
    out = np.zeros_like(theta)
    if n < 3:
        return out
    shape = (-1,) + (1,) * (theta.ndim - 1)
    s = np.diff(theta, axis=0) / np.diff(centres).reshape(shape)
    sb, sf = s[:-1], s[1:]
    prod = sb * sf
    slope = np.zeros_like(theta)
    slope[1:-1] = np.where(prod > 0.0, 2.0 * prod / np.where(prod > 0.0, sb + sf, 1.0), 0.0)
    f = flux[1:-1]
    xf = faces[1:-1]
    from_left = (xf - centres[:-1]).reshape(shape) * slope[:-1]     # face f from cell f − 1 (flow along +x)
    from_right = (xf - centres[1:]).reshape(shape) * slope[1:]      # from cell f (flow along −x)
    dF = f * np.where(f > 0.0, from_left, from_right)
    out[:-1] += dF
    out[1:] -= dF
    return out


def _mass_flux(xf: np.ndarray, p: np.ndarray, h: np.ndarray, rho: np.ndarray, eta: np.ndarray, ue: float) -> float:
    """The Reynolds mass flux per unit width [kg/(m s)], ρ (h u_e − h³ p'/(12 η)) averaged over the faces with
    the weights p²: in the pressurised zone, where the flux is constant to the discretisation error and the
    Poiseuille part is small, and a continuous function of the fields.  (ρ h u_e at the node of the pressure
    maximum, the earlier choice, jumped when the maximum moved between the central plateau and the outlet spike,
    and the thermal loop of a 172 m/s turbo contact cycled with period 3 between 1 and 2.4 K.)"""
    dp = np.gradient(p, xf)
    q = rho * (h * ue - h**3 * dp / (12.0 * eta))
    wgt = p**2
    if not wgt.sum() > 0:
        return float(np.max(rho * h) * ue)
    m = float(wgt @ q / wgt.sum())
    # an under-resolved film (a coarse grid of a nanometre film) can make the Poiseuille share of the average
    # meaningless: then the Couette flux alone, averaged alike
    return m if m > 0 else float(wgt @ (rho * h * ue) / wgt.sum())


def _faces_of(c: np.ndarray) -> np.ndarray:
    """Cell values at the nt + 1 faces: the mean of the two neighbours, the end cells at the ends."""
    return np.concatenate([c[:1], 0.5 * (c[:-1] + c[1:]), c[-1:]])


#: cells of the solids' surface operators kept in the preconditioner, either side of the diagonal: one keeps the
#: band of N at the film's own (nz + 2; two cells doubled it): on a turbo contact's 1024 x 16 cells the banded LU
#: then takes 21 ms against 130 ms and a solve 2.3 ms against 11 ms, GMRES the same 10 iterations (issue 43)
JAEGER_BAND = 1
KRYLOV_TOL = 1e-10   # relative residual of the energy solve (temperatures then equal a direct solve's to ~1e-12 K)


def linear_solve(args: tuple, rhs: np.ndarray, n_theta: int, cache: dict | None = None) -> np.ndarray:
    """The energy system of :func:`_energy_matrix` (``args``) for ``rhs``: the ``n_theta``
    film temperatures, then the wall fluxes of body 1 and body 2.

    The matrix is split A = N + F: N, the film with the solids' surface operators cut to
    ``JAEGER_BAND`` cells about the diagonal, is factorised (with the unknowns cell by cell,
    :func:`_cell_order`, N is banded, both half-widths nz + 2 with one cell kept: LAPACK's banded LU, 0.5 ms
    at 192 x 8 cells with two kept, against 0.9-1.2 ms for SuperLU with minimum degree on N + N^T and 24 ms for
    the sparse LU of A with its 207k entries; measured on the line TEHL, issue 16); F, the far
    field of the surface kernels, is applied as two dense products.  A is solved by GMRES
    preconditioned from the right by N^-1 (:func:`femgear.physics.ehl.fe.krylov.gmres_right`) to the
    relative residual :data:`KRYLOV_TOL`.  With ``cache`` the banded factors of an earlier solve of the loop
    precondition the next solves while GMRES converges on them within :data:`STALE` iterations of what their own
    solve took (the band's entries, the film's flows, sources and conductances, move with the temperatures and
    film from one iteration to the next, but by less and less as the loop settles), and the previous solution
    starts GMRES (the stopping test stays |b - A x| <= tol |b|): on the turbo pair's map contacts the banded LU
    then runs in one solve in five (24 for 115 solves of two SRR groups of seven) instead of each.  Where that
    does not converge in :data:`QUICK` iterations
    (slow or resting surfaces under a thin film: conduction across the film then dwarfs the convection
    along it, the wall temperatures are set by the whole, slowly decaying surface operator, and on the
    graded cells its far field is neither small nor of low rank), A is factorised by SuperLU, and with
    ``cache`` (a dict the caller keeps across the solves of one thermal loop, whose matrices change
    little from one iteration to the next) those factors precondition GMRES in the next solves and are
    renewed only when it needs more than :data:`QUICK` iterations.  Before the whole of A, the solids' near field
    (the cells closer than :data:`NEAR` of the band, sparse) is factorised instead and GMRES given
    :data:`NEAR_KRYLOV` iterations on it (a 1024 x 16-cell system with a surface at rest: factor 0.26 s and ~50
    iterations, against 1.7 s for the sparse LU of A with its 2.2 M entries)."""
    from femgear.physics.ehl.fe.krylov import gmres_right

    nt, nz = args[2].shape
    cache = {} if cache is None else cache
    lu = cache.get("lu")
    if lu is not None and lu.shape[0] == rhs.size:
        A = _energy_matrix(*args)
        x, _, ok = gmres_right(lambda v: A @ v, lu.solve, rhs, KRYLOV_TOL, cache.get("its", QUICK))
        if ok:
            return x
    elif not cache.get("direct"):
        if "order" not in cache:
            perm = _cell_order(nt, nz)
            pos = np.empty_like(perm)
            pos[perm] = np.arange(perm.size)
            cache["order"] = perm, pos
        perm, pos = cache["order"]
        near = _energy_matrix(*args, band=JAEGER_BAND, order=pos)  # unknowns cell by cell: banded
        far = _jaeger_far(args[-2], args[-1], 2 * args[6] / args[4], n_theta, cache)
        x0 = cache.get("x")
        matvec = lambda v: (near @ v[perm])[pos] + far(v)   # noqa: E731
        r0 = rhs if x0 is None or x0.size != rhs.size else rhs - matvec(x0)
        x0 = np.zeros_like(rhs) if r0 is rhs else x0
        target = KRYLOV_TOL * float(np.linalg.norm(rhs)) / max(float(np.linalg.norm(r0)), 1e-300)
        kept = cache.get("band")
        if kept is not None:   # the factors of an earlier solve of this loop
            dx, its, ok = gmres_right(matvec, kept[0], r0, target, kept[1] + STALE)
            if ok:
                cache["x"] = x0 + dx
                return cache["x"]
        solve = _banded_lu(near)
        if solve is not None:
            precond = lambda r: solve(r[perm])[pos]   # noqa: E731
            dx, its, ok = gmres_right(matvec, precond, r0, target, QUICK)
            if ok:
                cache.update(band=(precond, its), x=x0 + dx)
                return cache["x"]
        cache["direct"] = True
    A = _energy_matrix(*args)
    near = spla.splu(_energy_matrix(*args, band=_near_mask(args[3])), permc_spec="MMD_AT_PLUS_A")
    x, _, ok = gmres_right(lambda v: A @ v, near.solve, rhs, KRYLOV_TOL, NEAR_KRYLOV)
    if ok:
        cache.update(lu=near, its=NEAR_KRYLOV)
        return x
    cache.update(lu=spla.splu(A, permc_spec="MMD_AT_PLUS_A"), its=QUICK)
    return cache["lu"].solve(rhs)


NEAR_KRYLOV = 80    #: GMRES iterations allowed on the near-field factors (measured 44-51 on a slow surface's thin film)
NEAR = 0.03   #: the near field of the solids' operators in the sparse preconditioner: cells closer than this
#: fraction of the band's length (or within JAEGER_BAND cells)


def _near_mask(dx: np.ndarray) -> np.ndarray:
    """The entries of the surface operators between cells closer than :data:`NEAR` times the band's length: the
    part that a slow surface's slowly decaying kernel makes near-singular on the graded cells, whose far field
    is then smooth enough for GMRES."""
    xc = np.cumsum(dx) - 0.5 * dx
    i = np.arange(dx.size)
    return (np.abs(xc[:, None] - xc[None, :]) <= NEAR * dx.sum()) | (np.abs(i[:, None] - i[None, :]) <= JAEGER_BAND)


QUICK = 20           # GMRES iterations allowed on a preconditioner before the system is factorised (anew)
#: GMRES iterations allowed on the banded factors of an earlier solve of the loop beyond those their own solve took,
#: before they are renewed (an iteration costs about a third of the banded LU on a turbo contact's 1024 x 16 cells)
STALE = 3


def _banded_lu(A: sp.spmatrix):
    """r -> A^-1 r by LAPACK's banded LU with partial pivoting (dgbtrf/dgbtrs, Anderson et
    al., *LAPACK Users' Guide*, 3rd ed., 1999, §2.4.2) of the sparse ``A``; None when singular."""
    C = A.tocoo()
    kl, ku = int(max(np.max(C.row - C.col), 0)), int(max(np.max(C.col - C.row), 0))
    ab = np.zeros((2 * kl + ku + 1, A.shape[0]))
    ab[kl + ku + C.row - C.col, C.col] = C.data
    lub, piv, info = sla.lapack.dgbtrf(ab, kl, ku)
    if info != 0:
        return None
    return lambda r: sla.lapack.dgbtrs(lub, kl, ku, r, piv)[0]


def _cell_order(nt: int, nz: int) -> np.ndarray:
    """The unknowns of :func:`_energy_matrix` cell by cell (the cell's nz film temperatures,
    then its two wall fluxes): with the Jaeger operators cut to a band, the matrix is then
    banded (half-widths nz + 2 with one cell kept) and factorises without a fill-reducing ordering."""
    cells = np.arange(nt)[:, None]
    return np.concatenate([cells * nz + np.arange(nz)[None, :], nt * nz + cells, nt * (nz + 1) + cells],
                          axis=1).ravel()


def _jaeger_far(J1: np.ndarray, J2: np.ndarray, g: np.ndarray, n_theta: int, cache: dict | None = None):
    """x -> F x: the Jaeger entries more than ``JAEGER_BAND`` cells off the diagonal, rows
    of the wall fluxes (g J q): the dense product J q less its band (no masked copy of J); the band's diagonals
    kept in ``cache`` (the operators are those of one level's cells and speeds)."""
    nt = J1.shape[0]
    bands = None if cache is None else cache.get("far_bands")
    if bands is None:
        bands = [([(k, np.diagonal(J, k)) for k in range(-JAEGER_BAND, JAEGER_BAND + 1) if abs(k) < nt],
                  _row_blocks(J)) for J in (J1, J2)]
        if cache is not None:
            cache["far_bands"] = bands

    def far(J, band, q):
        diags, blocks = band
        y = np.zeros(nt)
        for r0, r1, c0, c1 in blocks:
            y[r0:r1] = J[r0:r1, c0:c1] @ q[c0:c1]
        for k, d in diags:
            if k >= 0:
                y[:nt - k] -= d * q[k:]
            else:
                y[-k:] -= d * q[:nt + k]
        return g * y

    def apply(x):
        out = np.zeros_like(x)
        out[n_theta:n_theta + nt] = far(J1, bands[0], x[n_theta:n_theta + nt])
        out[n_theta + nt:] = far(J2, bands[1], x[n_theta + nt:])
        return out
    return apply


#: rows of a surface operator per block of its far-field product (:func:`_row_blocks`)
FAR_BLOCK = 64


def _row_blocks(J: np.ndarray) -> list[tuple[int, int, int, int]]:
    """(r0, r1, c0, c1): the blocks of :data:`FAR_BLOCK` rows of ``J`` with the span of columns holding their
    non-zero entries.  A moving surface's operator is zero downstream to round-off (Jaeger's exactly, the
    exact one beyond :data:`PHI_FAR`), so at a contact's high Péclet numbers about half of J: its product
    reads only the rest (0.18 against 0.30 ms on 1024 graded cells at 5 and 50 m/s)."""
    out = []
    for r0 in range(0, J.shape[0], FAR_BLOCK):
        cols = np.flatnonzero(np.any(J[r0:r0 + FAR_BLOCK] != 0.0, axis=0))
        if cols.size:
            out.append((r0, min(r0 + FAR_BLOCK, J.shape[0]), int(cols[0]), int(cols[-1]) + 1))
    return out


def _energy_matrix(m, G, a_comp, dx: np.ndarray, dz, c: float, k_f: float, J1, J2, band=None,
                   order: np.ndarray | None = None):
    """Upwind finite-volume matrix (CSC) of the film energy equation with the two Jaeger
    walls: unknowns theta (nt, nz) cell by cell, then the wall fluxes q1 and q2 per cell;
    ``band``: the Jaeger operators cut to that many cells about the diagonal, or to the entries of a boolean
    (nt, nt) mask (None: all);
    ``order``: unknown i is row and column ``order[i]`` (default: as listed)."""
    nt, nz = a_comp.shape
    N = nt * (nz + 2)
    idx = np.arange(nt * nz).reshape(nt, nz)                     # theta unknowns
    iq1, iq2 = nt * nz + np.arange(nt), nt * (nz + 1) + np.arange(nt)
    rows, cols, vals = [], [], []

    def add(r, cc, v):
        r, cc, v = np.broadcast_arrays(r, cc, v)
        rows.append(r.ravel()), cols.append(cc.ravel()), vals.append(v.ravel())

    diag = np.zeros((nt, nz))
    # horizontal advection: face f between cell f-1 and f
    mr = m[1:]                                                   # right faces of cells
    ml = m[:-1]                                                  # left faces
    diag += c * np.maximum(mr, 0) - c * np.minimum(ml, 0)
    add(idx[:-1], idx[1:], c * np.minimum(mr[:-1], 0))          # inflow from the right neighbour
    add(idx[1:], idx[:-1], -c * np.maximum(ml[1:], 0))          # inflow from the left neighbour
    # vertical advection
    Gt, Gb = G[:, 1:], G[:, :-1]
    diag += c * np.maximum(Gt, 0) - c * np.minimum(Gb, 0)
    add(idx[:, :-1], idx[:, 1:], c * np.minimum(Gt[:, :-1], 0))
    add(idx[:, 1:], idx[:, :-1], -c * np.maximum(Gb[:, 1:], 0))
    # conduction between layers
    Cz = (k_f * dx / dz)[:, None] * np.ones((1, max(nz - 1, 0)))  # dx per cell (nt,)
    diag[:, :-1] += Cz
    diag[:, 1:] += Cz
    add(idx[:, :-1], idx[:, 1:], -Cz)
    add(idx[:, 1:], idx[:, :-1], -Cz)
    diag -= a_comp
    add(idx, idx, diag)
    # walls: heat leaving the film into the solids, and q_j = g (theta_edge - J_j q_j)
    g = 2 * k_f / dz
    add(idx[:, 0], iq1, dx)                                      # dx per cell
    add(idx[:, -1], iq2, dx)
    if band is None:
        r, cc = np.nonzero(np.ones((nt, nt), dtype=bool) if nt else np.zeros((0, 0), dtype=bool))
    elif isinstance(band, np.ndarray):       # a mask of the entries kept
        r, cc = np.nonzero(band)
    else:
        r = np.repeat(np.arange(nt), 2 * band + 1)
        cc = r + np.tile(np.arange(-band, band + 1), nt)
        keep = (cc >= 0) & (cc < nt)
        r, cc = r[keep], cc[keep]
    for iq, J, edge in ((iq1, J1, idx[:, 0]), (iq2, J2, idx[:, -1])):
        v = g[r] * J[r, cc] + (r == cc)
        nz_ = v != 0.0
        add(iq[r[nz_]], iq[cc[nz_]], v[nz_])
        add(iq, edge, -g)
    rows, cols = np.concatenate(rows), np.concatenate(cols)
    if order is not None:
        rows, cols = order[rows], order[cols]
    return sp.csc_matrix((np.concatenate(vals), (rows, cols)), shape=(N, N))
