"""The harmonic-balance equations of :mod:`femgear.system.dynamics.harmonic`, batched over models that share their
structure (one :class:`~femgear.system.dynamics.family.SpeedFamily`: the same matrices, mesh tables and flank
deviations, at different speeds).

Every array carries a leading batch axis B (the models); the families' carriers ν are the same for all (ν = ±1/z_i
does not depend on speed).  One numpy call then solves the same step for every speed of a sweep.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.system.dynamics.model import GearRotorModel


def periodic_coefficients(samples: np.ndarray, orders: int) -> np.ndarray:
    """Fourier coefficients c_m, m = −orders … orders, of the periodic linear interpolant of ``samples`` (…, n)
    taken at the phases i/n (:func:`femgear.system.dynamics.mesh.periodic_interp`), exactly:
    c_m = DFT_m/n · sinc²(m/n) (the interpolant is the samples convolved with a hat of width 1/n)."""
    x = np.asarray(samples, dtype=float)
    n = x.shape[-1]
    m = np.arange(-orders, orders + 1)
    return (np.fft.fft(x, axis=-1) / n)[..., m % n] * np.sinc(m / n) ** 2


def _profile_coefficients(model: GearRotorModel, orders: int) -> np.ndarray:
    """(2, 2·orders+1) coefficients of the profile-error harmonics a Σ_i sin(2π i (φ + φ₀) + φ_p)."""
    out = np.zeros((2, 2 * orders + 1), dtype=complex)
    for s, pe in enumerate(model.profile_errors):
        for i in range(1, min(pe.orders, orders) + 1):
            c = pe.amplitude * np.exp(1j * (2 * math.pi * i * pe.mesh_offset + pe.phase)) / 2j
            out[s, orders + i] += c
            out[s, orders - i] += np.conj(c)
    return out


SHARED = ("M", "K", "C", "T", "G", "H0", "H1", "mesh_damping", "backlash")


def check_shared(models: list[GearRotorModel]) -> None:
    """ValueError unless ``models`` share what the batch assumes (matrices, mesh tables, deviations, errors' shape)."""
    a = models[0]
    for b in models[1:]:
        same = all(np.array_equal(getattr(a, k), getattr(b, k)) for k in SHARED)
        same = same and np.array_equal(a.stiffness.k_left, b.stiffness.k_left) and np.array_equal(
            a.stiffness.k_right, b.stiffness.k_right) and a.n == b.n and (a.mu > 0) == (b.mu > 0)
        same = same and (a.deviation is None) == (b.deviation is None) and (
            a.deviation is None or np.array_equal(a.deviation.drive, b.deviation.drive)
            and np.array_equal(a.deviation.coast, b.deviation.coast))
        same = same and [(p.amplitude, p.orders, p.phase, p.mesh_offset) for p in a.profile_errors] == [
            (p.amplitude, p.orders, p.phase, p.mesh_offset) for p in b.profile_errors]
        same = same and [(e.amplitude, e.phase, u.unbalance, u.phase) for e, u in zip(a.eccentricities, a.unbalances)] \
            == [(e.amplitude, e.phase, u.unbalance, u.phase) for e, u in zip(b.eccentricities, b.unbalances)]
        if not same:
            raise ValueError("harmonic balance: a batch of models must differ in speed only (one SpeedFamily)")


@dataclass(frozen=True)
class Family:
    """One excitation family: carrier ν (mesh orders) and its harmonics k = −H … H, for B models."""

    name: str
    nu: float
    force: np.ndarray       #: (B, 2H+1, n) external force [N, N m]
    error: np.ndarray       #: (2, 2H+1) transmission error e_s of this family [m]
    gap: np.ndarray         #: (2, 2H+1) e_s + b̄_s: the mesh coordinate where N_s = 0 [m]
    excitation: np.ndarray  #: (B, 2, 2H+1) P_s = k_s (e_s + b̄_s) + c_s ė_s [N]


def mesh_family(models: list[GearRotorModel], H: int) -> Family:
    """ν = 0: torques, backlash and flank deviations on the stiffness; profile errors."""
    model = models[0]
    L = max(2 * H, 64)
    kappa = periodic_coefficients(np.array([model.stiffness.k_left, model.stiffness.k_right]), 2 * L)
    e = np.zeros((2, 2 * L + 1), dtype=complex)
    b = np.zeros((2, 2 * L + 1), dtype=complex)
    b[:, L] = model.backlash
    if model.deviation is not None:
        e += periodic_coefficients(model.deviation.shift, L)
        b += periodic_coefficients(model.deviation.opening, L)
    e += _profile_coefficients(model, L)
    sl = slice(L - H, L + H + 1)
    P0 = np.array([np.convolve(kappa[s], e[s] + b[s])[2 * L: 4 * L + 1] for s in range(2)])[:, sl]
    wm = 2 * math.pi * np.array([m.mesh_frequency for m in models])
    k = np.arange(-H, H + 1)
    P = P0[None] + wm[:, None, None] * (model.mesh_damping[:, None] * 1j * k * e[:, sl])[None]
    force = np.zeros((len(models), 2 * H + 1, model.n), dtype=complex)
    force[:, H] = np.array([m.torque_full for m in models]) @ model.T
    return Family("mesh", 0.0, force, e[:, sl], (e + b)[:, sl], P)


def _half(phase: float) -> np.ndarray:
    """(cos θ, sin θ) = 2 Re[(1, −i) e^{iθ}/2]: the phasor of the carrier e^{iΩt} [-]."""
    return 0.5 * np.exp(1j * phase) * np.array([1.0, -1j])


def member_families(models: list[GearRotorModel], H: int, kappa: np.ndarray) -> list[Family]:
    """ν = Ω_i/ω_m: eccentricity (a bodily centre offset seen by both meshes) and unbalance of member i."""
    model, out = models[0], []
    wm = 2 * math.pi * np.array([m.mesh_frequency for m in models])
    for i, (ecc, unb) in enumerate(zip(model.eccentricities, model.unbalances)):
        if ecc.amplitude == 0.0 and unb.unbalance == 0.0:
            continue
        omega = np.array([m.eccentricities[i].omega for m in models])
        nu = float(omega[0] / wm[0])
        if not np.allclose(omega / wm, nu, rtol=1e-12):
            raise ValueError("harmonic balance: the members' speed ratio differs within the batch")
        sign = -1.0 if i == 0 else 1.0                                   # e_s = −(r_pinion − r_gear)·g_s
        eps = sign * ecc.amplitude * (model._g_translation @ _half(ecc.phase))   # (2,) e_s phasor
        P = np.broadcast_to(kappa[:, H:3 * H + 1] * eps[:, None], (len(models), 2, 2 * H + 1)).copy()
        P[:, :, H] += (nu * wm)[:, None] * (model.mesh_damping * 1j * eps)[None]
        err = np.zeros((2, 2 * H + 1), dtype=complex)
        err[:, H] = eps
        full = np.zeros((len(models), 2 * H + 1, 24), dtype=complex)
        for side in range(2):
            d = 6 * (2 * i + side)
            full[:, H, d:d + 2] = 0.5 * unb.unbalance * (omega**2)[:, None] * _half(unb.phase)[None]
        out.append(Family(("pinion", "gear")[i], nu, full @ model.T, err, err.copy(), P))
    return out


@dataclass(frozen=True)
class Operators:
    """What every family of the batch shares: mean springs, rigid modes, κ, and the friction coefficients per model."""

    K: np.ndarray           #: K + Σ k̄_s G_sᵀG_s [N/m, N m/rad]
    C: np.ndarray           #: C + Σ c_s G_sᵀG_s [N s/m, N m s/rad]
    rigid: np.ndarray       #: (n, r) mass-normalised rigid-body modes of K̃ (the free rotation of the train)
    shift: float            #: ω_ref² of the rigid-mode shift at zero frequency [1/s²]
    kappa: np.ndarray       #: (2, 4H+1) κ_{s,m}, m = −2H … 2H [N/m]
    friction: np.ndarray | None  #: (B, 2, 2, 4H+1) μ Â_{s,m}, μ B̂_{s,m} (helix, A/B, order) [-, m]; None: none


def operators(models: list[GearRotorModel], H: int) -> Operators:
    from scipy.linalg import eigh

    model = models[0]
    G, kbar = model.G, np.array(model.stiffness.mean)
    K = model.K + (kbar[:, None] * G).T @ G
    C = model.C + (model.mesh_damping[:, None] * G).T @ G
    w2, phi = eigh(K, model.M)
    rigid = w2 <= 1e-6 * w2.max()
    flex = w2[~rigid]
    kappa = periodic_coefficients(np.array([model.stiffness.k_left, model.stiffness.k_right]), 2 * H)
    W = None
    if model.mu > 0 and model.friction is not None:
        tables = np.array([[m.friction.A, m.friction.B] for m in models]).transpose(0, 2, 1, 3)   # (B, s, A/B, n)
        W = np.array([m.mu for m in models])[:, None, None, None] * periodic_coefficients(tables, 2 * H)
    return Operators(K=K, C=C, rigid=phi[:, rigid], shift=float(flex.min()) if flex.size else 1.0, kappa=kappa,
                     friction=W)


def _toeplitz(coef: np.ndarray, H: int) -> np.ndarray:
    """(…, K, K) Toeplitz matrices c_{k−j} of coefficient rows (…, 4H+1) (orders −2H … 2H), K = 2H+1."""
    k = np.arange(2 * H + 1)
    return coef[..., k[:, None] - k[None, :] + 2 * H]


def solve_family(models: list[GearRotorModel], ops: Operators, fam: Family, H: int):
    """(Y, N, Q) of one family: mesh coordinates (B, 2, K), mesh forces (B, 2, K), states (B, K, n); K = 2H+1."""
    model = models[0]
    B, n, K = len(models), model.n, 2 * H + 1
    G, M = model.G, model.M
    w = (fam.nu + np.arange(-H, H + 1))[None] * (2 * math.pi * np.array([m.mesh_frequency for m in models]))[:, None]
    D = ops.K - (w**2)[..., None, None] * M + 1j * w[..., None, None] * ops.C          # (B, K, n, n)
    if fam.nu == 0.0 and ops.rigid.shape[1]:
        Mr = M @ ops.rigid
        D[:, H] += ops.shift * Mr @ Mr.T
    cols = np.broadcast_to(np.hstack([G.T, model.H0.T, model.H1.T]), (B, K, n, 6))
    X = np.linalg.solve(D, np.concatenate([cols, fam.force[..., None]], axis=-1))
    XG, XH0, XH1, XF = X[..., 0:2], X[..., 2:4], X[..., 4:6], X[..., 6]
    Ts = _toeplitz(ops.kappa, H)                                                     # (2, K, K)
    kbar = np.array(model.stiffness.mean)
    Tt = Ts - kbar[:, None, None] * np.eye(K)
    damp = 1j * w[:, None, :] * model.mesh_damping[None, :, None]                   # (B, 2, K)
    R = np.einsum("sa,bkar->bksr", G, XG)                                           # (B, K, 2 s', 2 s)
    # I + R (T − k̄): R block-diagonal in k, T block-diagonal in the helix → R[k, r, s] (T_s − k̄_s)[k, j]
    A = (R.transpose(0, 2, 1, 3)[..., None] * Tt.transpose(1, 0, 2)[None, None]).reshape(B, 2 * K, 2 * K)
    A += np.eye(2 * K)
    P = fam.excitation
    rhs = np.einsum("sa,bka->bsk", G, XF) + np.einsum("bkrs,bsk->brk", R, P)
    Tc = Ts[None] + damp[..., None] * np.eye(K)                                     # (B, 2, K, K)
    if ops.friction is not None:
        FA, FB = _toeplitz(ops.friction[:, :, 0], H), _toeplitz(ops.friction[:, :, 1], H)    # (B, 2, K, K)
        g0, g1 = np.einsum("sa,bkar->bksr", G, XH0), np.einsum("sa,bkar->bksr", G, XH1)   # (B, K, r, s)
        # V (T + iΩc) with V[(r,k),(s,j)] = g0[k,r,s] FA_s[k,j] + g1[k,r,s] FB_s[k,j]
        A += (g0.transpose(0, 2, 1, 3)[..., None] * (FA @ Tc).transpose(0, 2, 1, 3)[:, None]
              + g1.transpose(0, 2, 1, 3)[..., None] * (FB @ Tc).transpose(0, 2, 1, 3)[:, None]).reshape(B, 2 * K, 2 * K)
        fa, fb = np.einsum("bskj,bsj->bsk", FA, P), np.einsum("bskj,bsj->bsk", FB, P)
        rhs = rhs + np.einsum("bkrs,bsk->brk", g0, fa) + np.einsum("bkrs,bsk->brk", g1, fb)
    Y = np.linalg.solve(A, rhs.reshape(B, 2 * K, 1))[..., 0].reshape(B, 2, K)
    N = np.einsum("bskj,bsj->bsk", Tc, Y) - P
    Nt = np.einsum("skj,bsj->bsk", Tt, Y) - P
    Q = XF - np.einsum("bkas,bsk->bka", XG, Nt)
    if ops.friction is not None:
        fa, fb = np.einsum("bskj,bsj->bsk", FA, N), np.einsum("bskj,bsj->bsk", FB, N)
        Q = Q - np.einsum("bkas,bsk->bka", XH0, fa) - np.einsum("bkas,bsk->bka", XH1, fb)
    if fam.nu == 0.0 and ops.rigid.shape[1]:
        Q[:, H] -= (ops.rigid @ (ops.rigid.T @ (M @ Q[:, H].T))).T
    return Y, N, Q
