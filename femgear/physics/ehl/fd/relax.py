"""Line relaxation of the FD EHL equations (:mod:`femgear.physics.ehl.fd.operator`), zebra-ordered, vectorised.

Venner & Lubrecht (2000, "Multilevel Methods in Lubrication", sec. 7.3; Venner 1991,
thesis, Twente): where the Poiseuille coefficient dominates (eps/h^2 >= ``XI_SWITCH``)
the Reynolds equation is elliptic and Gauss-Seidel line relaxation along X smooths it;
where it is small (the contact) the equation is an integral equation in P (H through
the deflection), whose error components are smoothed by *distributive* relaxation: a
change delta at node (i, j) is applied as +delta there and -delta/4 at its four
neighbours, so that the change of the film is local (the discrete Laplacian of the
kernel decays like 1/r^3).

Both kinds are solved together, one line at a time implicitly: with the unknowns delta_i
of one line (Y = const) and the actual change of P

    dP_(k,j) = delta_k - (s_(k-1) delta_(k-1) + s_(k+1) delta_(k+1)) / 4,
    dP_(k,j+-1) = -s_k delta_k / 4          (s = 1 at distributive nodes, else 0),

the linearised change of the line's equations is A delta, A = J D_in + J_off D_off, J the
derivative of L along the line (Poiseuille stencil + the upwinded kernel band of
half-width ``bandwidth``, eps and rho frozen) and J_off that to the neighbouring lines.
A is banded: all lines of one colour (red-black, "zebra" ordering) are concatenated into
one banded system (no couplings between lines) and solved by one LAPACK banded solve.
Cavitated nodes (P = 0 with f - L >= 0) keep delta = 0; P is projected onto P >= 0.
The film is recomputed (DC-FFT) before each colour.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from femgear.physics.ehl.fd.operator import FDLevel

MAX_LOG_ETA = 4.0
XI_SWITCH = 0.3  # eps / h^2 below which a node is relaxed distributively (Venner & Lubrecht)


@dataclass(frozen=True)
class RelaxOptions:
    """Under-relaxation of the Gauss-Seidel and the distributive changes, kernel band."""

    omega_gs: float = 0.8
    omega_dist: float = 0.7
    bandwidth: int = 3
    xi_switch: float = XI_SWITCH
    # the change of P per sweep is capped at max_log_eta / alpha_bar (a viscosity factor of
    # e^max_log_eta; see ``HIGH_ALPHA`` for the strongly piezoviscous setting)
    max_log_eta: float = MAX_LOG_ETA


def sweep(lv: FDLevel, P: np.ndarray, H0: float, f: np.ndarray, opts: RelaxOptions) -> float:
    """One zebra line sweep (both colours) in place; returns the rms residual before it."""
    norm = None
    for colour in (0, 1):
        n = relax_colour(lv, P, H0, f, colour, opts)
        norm = n if norm is None else norm
    return norm


def _wedge_coefficients(lv: FDLevel, bw: int) -> dict[int, np.ndarray]:
    """Scalar tables c[dy][d, o] = w_o K[dy, |o - d|] (d = -bw-1..bw+1, o the upwind
    offsets): dD_X(rho H)_i / dP_(i+d, j+dy) = sum_o c[dy][d, o] rho_(i+o)."""
    ww = lv.wedge_weights()
    ds = np.arange(-bw - 1, bw + 2)
    out = {}
    for dy in (0, 1):
        c = np.zeros((ds.size, len(ww)))
        for k, (o, w) in enumerate(ww):
            c[:, k] = w * lv.K[dy, np.abs(o - ds)]
        c[0] = c[-1] = 0.0  # the band of J stops at |d| = bw
        out[dy] = c
    return out


def line_matrix(lv: FDLevel, faces, rho: np.ndarray, rows: np.ndarray, dist: np.ndarray,
                bw: int) -> dict[int, np.ndarray]:
    """A_d (offset d = -(bw+1)..bw+1) of the lines ``rows`` (interior row indices), with
    the face coefficients ``faces`` of those lines:
    A_d = J_d - s_(i+d) (J_(d-1) + J_(d+1) + Joff_d) / 4 (module docstring)."""
    w, e, s, n = faces
    ni = lv.nx - 2
    scalar = not getattr(lv.rheology, "compressible", True)  # rho = 1: scalar kernel parts
    R = [1.0 if scalar else rho[rows + 1][:, np.clip(np.arange(1, ni + 1) + o, 0, ni + 1)]
         for o, _ in lv.wedge_weights()]
    c = _wedge_coefficients(lv, bw)
    c0, c1 = c[0], c[1]
    nd = c0.shape[0]
    sig = dist.astype(float) / 4.0
    pois = {0: -(w + e + s + n), -1: w, 1: e}  # J_0 = -(w+e+s+n), J_(-1) = w, J_1 = e
    A = {}
    for k in range(nd):
        d = k - bw - 1
        # kernel part: J_d = -sum c0[d] R, neighbours J_(d-1) + J_(d+1) + Joff_d
        nb0 = (c0[k - 1] if k > 0 else 0.0) + (c0[k + 1] if k < nd - 1 else 0.0) + 2.0 * c1[k]
        sd = np.zeros_like(sig)
        if d >= 0:
            sd[:, : ni - d] = sig[:, d:]
        else:
            sd[:, -d:] = sig[:, :d]
        if scalar:
            a = sd * nb0.sum() - c0[k].sum()
        else:
            a = sum(-(c0[k, m] - sd * nb0[m]) * R[m] for m in range(len(R)))
        # Poiseuille part (Joff_0 = s + n)
        a = a + pois.get(d, 0.0) - sd * (pois.get(d - 1, 0.0) + pois.get(d + 1, 0.0)
                                         + (s + n if d == 0 else 0.0))
        A[d] = a
    return A


def _solve_lines(A: dict[int, np.ndarray], rhs: np.ndarray, active: np.ndarray) -> np.ndarray:
    """Solve the concatenated banded line systems; rows of ``active`` nodes are identity."""
    nl, ni = rhs.shape
    u = max(A)
    ab = np.zeros((2 * u + 1, nl * ni))
    for d, a in A.items():
        a = np.where(active, 1.0 if d == 0 else 0.0, a)
        band = np.zeros((nl, ni))
        if d >= 0:
            band[:, d:] = a[:, : ni - d]
        else:
            band[:, : ni + d] = a[:, -d:]
        ab[u - d] = band.ravel()
    b = np.where(active, 0.0, rhs).ravel()
    return sla.solve_banded((u, u), ab, b, check_finite=False).reshape(nl, ni)


def relax_colour(lv: FDLevel, P: np.ndarray, H0: float, f: np.ndarray, colour: int,
                 opts: RelaxOptions) -> float:
    """Relax the interior lines ``colour``, ``colour`` + 2, ... in place; the rms residual
    of those lines before."""
    rows = np.arange(colour, lv.ny - 2, 2)
    H = lv.film(P, H0)
    eps, rho = lv.coefficients(P, H)
    faces = lv.faces(eps, rows)
    rl = f[rows] - lv.operator(P, H, eps, rho, rows, faces)
    Pl = P[rows + 1, 1:-1]
    active = (Pl <= 0.0) & (rl >= 0.0)
    norm = float(np.sqrt(np.mean(np.where(active, 0.0, rl) ** 2)))
    dist = (eps[rows + 1, 1:-1] < opts.xi_switch * lv.hx**2) & ~active
    A = line_matrix(lv, faces, rho, rows, dist, opts.bandwidth)
    delta = _solve_lines(A, rl, active)
    delta *= np.where(dist, opts.omega_dist, opts.omega_gs)
    # at most a factor e^MAX_LOG_ETA of viscosity per sweep anywhere (as the Newton step cap)
    cap = min(1.0, opts.max_log_eta / max(lv.rheology.alpha_bar, 1e-12))
    np.clip(delta, -cap, cap, out=delta)
    sd = np.where(dist, delta, 0.0) / 4.0
    dline = delta.copy()
    dline[:, 1:] -= sd[:, :-1]
    dline[:, :-1] -= sd[:, 1:]
    P[rows + 1, 1:-1] += dline
    P[rows, 1:-1] -= sd
    P[rows + 2, 1:-1] -= sd
    P[0], P[-1], P[:, 0], P[:, -1] = 0.0, 0.0, 0.0, 0.0
    np.maximum(P, 0.0, out=P)
    return norm
