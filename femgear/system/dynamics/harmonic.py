"""Steady-state whine per order by harmonic balance: the gear-rotor model in the frequency domain.

While the drive flanks of both helices stay in contact, the mesh law of
:class:`~femgear.system.dynamics.model.GearRotorModel`,
N_s = k_s(t) f_gap(δ_s; b̄_s) + c_s δ̇_s with δ_s = G_s q − e_s(t), is linear in the state:
N_s = k_s(t) (G_s q − e_s − b̄_s) + c_s (G_s q̇ − ė_s).  About the loaded static state the equations
of motion are then *exactly* linear with mesh-periodic coefficients (the stiffness k_s(t) the
parametric term, the friction direction w_s(t) = μ (A_s H0_s + B_s H1_s) a second one):

    M q̈ + C q̇ + K q + Σ_s (G_sᵀ + w_s(t)) N_s = f(t).

Excitations, split into families by their carrier frequency ν ω_m (ω_m = 2π f_m):

- ``mesh`` (ν = 0): the torques, the stiffness variation acting on the static deflection and the
  backlash (the loaded transmission error), profile-error harmonics and flank deviations
  (wear, thermal, the LTCA's unloaded TE);
- ``pinion`` / ``gear`` (ν = Ω_i/ω_m = ±1/z_i): the eccentricity and unbalance of that member,
  whose response lies at the sidebands (ν + k) f_m of the mesh orders.

The families superpose (the system is linear); random pitch errors repeat only over the hunting
period and are left to the time integration (:func:`applies`).  Per family the response is
q(t) = Σ_{k=−H}^{H} Q_k e^{i(ν+k)ω_m t} (the physical one 2 Re of it for ν ≠ 0); the
harmonics couple through the Fourier coefficients κ_{s,m} of k_s (Hill's method, the parametric
coupling kept to ±2H orders).  With the mean mesh springs put into the dynamic stiffness
D̃_k = K + Σ k̄_s G_sᵀG_s − ω_k² M + iω_k (C + Σ c_s G_sᵀG_s) the unknowns condense onto the two
mesh coordinates Y_s,k = G_s Q_k:

    [I + R (T − k̄) + V (T + iΩ c)] Y = Y⁰ + (R + V) P,     R_k = G D̃_k⁻¹ Gᵀ,  Y⁰_k = G D̃_k⁻¹ F_k,

T the block-Toeplitz matrix of κ, V_{k,j} = G D̃_k⁻¹ Ŵ_{k−j} the friction's, P_s the harmonics of
k_s (e_s + b̄_s) + c_s ė_s: a dense system of 2(2H+1) unknowns per family (one solve, no
iteration), after which Q_k, the mesh forces and the bearing stations follow.  The coefficients
of the piecewise-linear tables are exact (:func:`periodic_coefficients`), so the truncation at H
harmonics is the only approximation.  The free rotation of the train (a zero of D̃_0 without a
power loop) carries no mesh or bearing load and is projected out of the mean.

Contact: the solution is linear only while δ_s − b̄_s > 0 (and N_s > 0 with friction, whose
sign |N_s| takes).  :attr:`HarmonicSolution.contact_margin` is a lower bound of min_t(δ_s − b̄_s)
over all families together (the mesh family on a dense phase grid minus the envelopes of the
others); a solution with a margin ≤ 0 is flagged (``contact_kept`` False) and must not be used
as the answer (:mod:`femgear.system.dynamics.harmonic_sweep` hands those speeds to the time
integration).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.system.dynamics.bearings import force_matrices
from femgear.system.dynamics.model import GearRotorModel

#: mesh harmonics per family to start with (:func:`harmonic_response` doubles them until converged)
HARMONICS = 24
#: ... at most
MAX_HARMONICS = 384
#: relative change of the lines allowed between H/2 and H harmonics (the truncation estimate)
TRUNCATION_TOL = 1e-3
#: phase samples per mesh period of the contact check (at least; and 8 per harmonic)
CONTACT_SAMPLES = 2048


def periodic_coefficients(samples: np.ndarray, orders: int) -> np.ndarray:
    """Fourier coefficients c_m, m = −orders … orders, of the periodic linear interpolant of ``samples``
    taken at the phases i/n (:func:`femgear.system.dynamics.mesh.periodic_interp`), exactly:
    c_m = DFT_m/n · sinc²(m/n) (the interpolant is the samples convolved with a hat of width 1/n)."""
    x = np.asarray(samples, dtype=float)
    n = x.size
    m = np.arange(-orders, orders + 1)
    return (np.fft.fft(x) / n)[m % n] * np.sinc(m / n) ** 2


def _profile_coefficients(model: GearRotorModel, orders: int) -> np.ndarray:
    """(2, 2·orders+1) coefficients of the profile-error harmonics a Σ_i sin(2π i (φ + φ₀) + φ_p)."""
    out = np.zeros((2, 2 * orders + 1), dtype=complex)
    for s, pe in enumerate(model.profile_errors):
        for i in range(1, min(pe.orders, orders) + 1):
            c = pe.amplitude * np.exp(1j * (2 * math.pi * i * pe.mesh_offset + pe.phase)) / 2j
            out[s, orders + i] += c
            out[s, orders - i] += np.conj(c)
    return out


def applies(model: GearRotorModel) -> str | None:
    """None when the harmonic balance models every excitation of ``model``; else why not (one line)."""
    if any(r.amplitude != 0.0 for r in model.random_errors):
        return "random pitch errors (errors.random) repeat over the hunting period, not the mesh period"
    if any(k <= 0 for k in model.stiffness.mean[: model.pair.n_helices]):
        return "a mesh without stiffness"
    return None


@dataclass(frozen=True)
class _Family:
    """One excitation family: carrier ν (mesh orders) and its harmonics k = −H … H."""

    name: str
    nu: float
    force: np.ndarray       #: (2H+1, n) external force [N, N m]
    error: np.ndarray       #: (2, 2H+1) transmission error e_s of this family [m]
    gap: np.ndarray         #: (2, 2H+1) e_s + b̄_s: the mesh coordinate where N_s = 0 [m]
    excitation: np.ndarray  #: (2, 2H+1) P_s = k_s (e_s + b̄_s) + c_s ė_s [N]


def _mesh_family(model: GearRotorModel, H: int, kappa_long: np.ndarray, L: int) -> _Family:
    """ν = 0: torques, backlash and flank deviations on the stiffness; profile errors."""
    n, wm = model.n, 2 * math.pi * model.mesh_frequency
    e = np.zeros((2, 2 * L + 1), dtype=complex)
    b = np.zeros((2, 2 * L + 1), dtype=complex)
    b[:, L] = model.backlash
    if model.deviation is not None:
        for s in range(2):
            e[s] += periodic_coefficients(model.deviation.shift[s], L)
            b[s] += periodic_coefficients(model.deviation.opening[s], L)
    prof = _profile_coefficients(model, L)
    e += prof
    m = np.arange(-L, L + 1)
    P = np.array([np.convolve(kappa_long[s], e[s] + b[s])[2 * L: 4 * L + 1] for s in range(2)])
    P += model.mesh_damping[:, None] * 1j * wm * m * e
    sl = slice(L - H, L + H + 1)
    force = np.zeros((2 * H + 1, n), dtype=complex)
    force[H] = model.torque_full @ model.T
    return _Family("mesh", 0.0, force, e[:, sl], (e + b)[:, sl], P[:, sl])


def _member_families(model: GearRotorModel, H: int, kappa: np.ndarray) -> list[_Family]:
    """ν = Ω_i/ω_m: eccentricity (a bodily centre offset seen by both meshes) and unbalance of member i."""
    out = []
    wm = 2 * math.pi * model.mesh_frequency
    gx = model._g_translation
    for i, (ecc, unb) in enumerate(zip(model.eccentricities, model.unbalances)):
        if ecc.amplitude == 0.0 and unb.unbalance == 0.0:
            continue
        nu = ecc.omega / wm

        def half(phase: float) -> np.ndarray:   # (cos θ, sin θ) = 2 Re[(1, −i) e^{iθ}/2]: the phasor of e^{iΩt}
            return 0.5 * np.exp(1j * phase) * np.array([1.0, -1j])

        sign = -1.0 if i == 0 else 1.0          # e_s = −(r_pinion − r_gear)·g_s
        eps = sign * ecc.amplitude * (gx @ half(ecc.phase))            # (2,) e_s phasor
        P = kappa[:, H:3 * H + 1] * eps[:, None]                       # κ_m ε_s at k = m
        P[:, H] += model.mesh_damping * 1j * nu * wm * eps
        err = np.zeros((2, 2 * H + 1), dtype=complex)
        err[:, H] = eps
        full = np.zeros((2 * H + 1, 24), dtype=complex)
        if unb.unbalance != 0.0:
            F = unb.unbalance * unb.omega**2 * half(unb.phase)
            for side in range(2):
                b = 6 * (2 * i + side)
                full[H, b:b + 2] = 0.5 * F
        out.append(_Family(("pinion", "gear")[i], nu, full @ model.T, err, err.copy(), P))
    return out


@dataclass(frozen=True)
class _Operators:
    """What every family of one model shares: mean springs, rigid modes, κ and friction coefficients."""

    K: np.ndarray           #: K + Σ k̄_s G_sᵀG_s [N/m, N m/rad]
    C: np.ndarray           #: C + Σ c_s G_sᵀG_s [N s/m, N m s/rad]
    rigid: np.ndarray       #: (n, r) mass-normalised rigid-body modes of K̃ (the free rotation of the train)
    shift: float            #: ω_ref² of the rigid-mode shift at zero frequency [1/s²]
    kappa: np.ndarray       #: (2, 4H+1) κ_{s,m}, m = −2H … 2H [N/m]
    friction: np.ndarray | None  #: (2, 2, 4H+1) μ Â_{s,m}, μ B̂_{s,m} (helix, A/B, order) [-, m]; None: no friction


def _operators(model: GearRotorModel, H: int) -> _Operators:
    from scipy.linalg import eigh

    G, kbar = model.G, np.array(model.stiffness.mean)
    K = model.K + (kbar[:, None] * G).T @ G
    C = model.C + (model.mesh_damping[:, None] * G).T @ G
    w2, phi = eigh(K, model.M)
    rigid = w2 <= 1e-6 * w2.max()
    flex = w2[~rigid]
    kappa = np.array([periodic_coefficients(k, 2 * H) for k in (model.stiffness.k_left, model.stiffness.k_right)])
    W = None
    if model.mu > 0 and model.friction is not None:
        W = model.mu * np.array([[periodic_coefficients(t[s], 2 * H) for t in (model.friction.A, model.friction.B)]
                                 for s in range(2)])
    return _Operators(K=K, C=C, rigid=phi[:, rigid], shift=float(flex.min()) if flex.size else 1.0, kappa=kappa,
                      friction=W)


def _block_toeplitz(coef: np.ndarray, H: int) -> np.ndarray:
    """(…, K, K) Toeplitz matrices c_{k−j} of coefficient rows (…, 4H+1) (orders −2H … 2H), K = 2H+1."""
    k = np.arange(2 * H + 1)
    return coef[..., k[:, None] - k[None, :] + 2 * H]


def _solve_family(model: GearRotorModel, ops: _Operators, fam: _Family, H: int):
    """(Y, N, Q) of one family: mesh coordinates (2, K), mesh forces (2, K), states (K, n); K = 2H+1."""
    n, K = model.n, 2 * H + 1
    G, M = model.G, model.M
    w = (fam.nu + np.arange(-H, H + 1)) * 2 * math.pi * model.mesh_frequency
    D = ops.K[None] - w[:, None, None] ** 2 * M + 1j * w[:, None, None] * ops.C
    if fam.nu == 0.0 and ops.rigid.shape[1]:
        Mr = M @ ops.rigid
        D[H] = D[H] + ops.shift * Mr @ Mr.T
    cols = [G.T, model.H0.T, model.H1.T]                      # D⁻¹ of the mesh and friction directions
    X = np.linalg.solve(D, np.concatenate([np.broadcast_to(np.hstack(cols), (K, n, 6)), fam.force[:, :, None]], 2))
    XG, XH0, XH1, XF = X[:, :, 0:2], X[:, :, 2:4], X[:, :, 4:6], X[:, :, 6]
    T = np.zeros((2 * K, 2 * K), dtype=complex)
    for s in range(2):
        T[s * K:(s + 1) * K, s * K:(s + 1) * K] = _block_toeplitz(ops.kappa[s], H)
    damping = np.concatenate([1j * w * c for c in model.mesh_damping])
    Tt = T - np.diag(np.repeat(np.array(model.stiffness.mean), K))
    Tc = T + np.diag(damping)

    def blocks(per_k: np.ndarray) -> np.ndarray:        # (K, 2, 2) → block-diagonal in k, (r, k) × (s, k)
        out = np.zeros((2, K, 2, K), dtype=complex)
        idx = np.arange(K)
        out[:, idx, :, idx] = per_k
        return out.reshape(2 * K, 2 * K)

    Rb = blocks(G @ XG)
    P = fam.excitation.ravel()
    A = np.eye(2 * K) + Rb @ Tt
    rhs = (G @ XF[:, :, None])[:, :, 0].T.ravel() + Rb @ P
    if ops.friction is not None:
        FA, FB = _block_toeplitz(ops.friction[:, 0], H), _block_toeplitz(ops.friction[:, 1], H)   # (2, K, K)
        g0, g1 = G @ XH0, G @ XH1                              # (K, 2 r, 2 s)
        Vb = (g0.transpose(1, 0, 2)[:, :, :, None] * FA.transpose(1, 0, 2)[None]
              + g1.transpose(1, 0, 2)[:, :, :, None] * FB.transpose(1, 0, 2)[None]).reshape(2 * K, 2 * K)
        A = A + Vb @ Tc
        rhs = rhs + Vb @ P
    Y = np.linalg.solve(A, rhs)
    N = (Tc @ Y - P).reshape(2, K)
    Nt = (Tt @ Y - P).reshape(2, K)
    Q = XF - np.einsum("kas,sk->ka", XG, Nt)
    if ops.friction is not None:
        fa, fb = np.einsum("skj,sj->sk", FA, N), np.einsum("skj,sj->sk", FB, N)
        Q = Q - np.einsum("kas,sk->ka", XH0, fa) - np.einsum("kas,sk->ka", XH1, fb)
    if fam.nu == 0.0 and ops.rigid.shape[1]:
        Q[H] = Q[H] - ops.rigid @ (ops.rigid.T @ (M @ Q[H]))
    return Y.reshape(2, K), N, Q


@document_fields
@dataclass(frozen=True)
class HarmonicSolution:
    """The steady state of one model by harmonic balance: lines (orders) with complex amplitudes.

    A signal is x(t) = mean + Σ_l Re[X_l e^{2πi f_l t}]: ``|X_l|`` is the single-sided (peak) amplitude
    of line l, as the Hanning spectra of :func:`femgear.system.dynamics.response.spectrum` read it.
    """

    mesh_frequency: float
    """mesh frequency f_m [Hz]"""
    harmonics: int
    """H: mesh harmonics kept per family (the parametric coupling spans ±2H orders; lines up to order H/2 are
    reported) [-]"""
    families: tuple[str, ...]
    """the excitation families solved (``mesh``, ``pinion``, ``gear``) [-]"""
    frequency: np.ndarray
    """(L,) line frequencies, ascending: the mesh orders k f_m and the sidebands k f_m ± f_shaft [Hz]"""
    mesh_force: np.ndarray
    """(2, L) complex amplitude of the dynamic mesh force N_s per helix (left, right) [N]"""
    mesh_force_mean: np.ndarray
    """(2,) mean mesh force per helix [N]"""
    dte: np.ndarray
    """(L,) complex amplitude of the dynamic transmission error (mean of δ_L, δ_R) [m]"""
    displacement: np.ndarray
    """(24, L) complex amplitude of the full DOFs (the four helix halves) [m, rad]"""
    displacement_mean: np.ndarray
    """(24,) mean displacement of the full DOFs (the free rotation of the train removed) [m, rad]"""
    contact_margin: np.ndarray
    """(2,) lower bound of min over time of δ_s − b̄_s, the drive-flank overlap (≤ 0: the flanks may separate and
    the linear answer does not hold) [m]"""
    normal_force_min: np.ndarray
    """(2,) lower bound of min over time of N_s (friction takes its sign) [N]"""
    truncation: float
    """the truncation estimate: largest change of the mesh-force and DTE lines of orders ≤ H/4 between H/2 and H
    harmonics, relative to the largest line [-]"""
    bearing_force: np.ndarray
    """(4, 3, L) complex amplitude of the bearing-station loads (pinion-L/R, gear-L/R; x, y, z), the force of the
    shaft on the bearing (:func:`femgear.system.dynamics.bearings.force_matrices`) [N]"""
    bearing_force_mean: np.ndarray
    """(4, 3) mean bearing-station loads [N]"""

    @property
    def order(self) -> np.ndarray:
        """Line frequencies in mesh orders f/f_m [-]."""
        return self.frequency / self.mesh_frequency

    @property
    def contact_kept(self) -> bool:
        """Both loaded flanks stay in contact throughout (the linear answer holds)."""
        return bool(np.all(self.contact_margin > 0) and np.all(self.normal_force_min >= 0))

    @property
    def dte_rms(self) -> float:
        """RMS of the dynamic transmission error over the steady state [m]."""
        return float(np.sqrt(0.5 * np.sum(np.abs(self.dte) ** 2)))

    def line(self, order: float) -> int:
        """Index of the line at ``order`` mesh orders (KeyError if there is none)."""
        hit = np.flatnonzero(np.abs(self.order - order) <= 1e-9 * max(1.0, abs(order)))
        if not hit.size:
            raise KeyError(f"no line at mesh order {order!r}")
        return int(hit[0])

    def order_amplitudes(self, values: np.ndarray, orders) -> np.ndarray:
        """|values| at the mesh orders ``orders`` (last axis = lines), 0 where a line is absent [unit]."""
        out = []
        for o in orders:
            try:
                out.append(np.abs(values[..., self.line(o)]))
            except KeyError:
                out.append(np.zeros(values.shape[:-1]))
        return np.stack(out, axis=-1)


def _lines(fams: list[_Family], values: list[tuple[np.ndarray, ...]], H: int, fm: float):
    """Line frequencies and complex amplitudes of per-family harmonics ``values`` (each (…, 2H+1)): the lines of every
    family summed where they coincide, conjugate lines (f < 0) folded onto f > 0, the mean (f = 0) left out."""
    orders, picks = [], []
    for fam in fams:
        o = fam.nu + np.arange(-H, H + 1)
        keep = o > 0 if fam.nu == 0.0 else np.ones(o.size, bool)
        orders.append(o[keep])
        picks.append(keep)
    o = np.concatenate(orders)
    key = np.round(np.abs(o) * 1e9).astype(np.int64)
    uniq, inv = np.unique(key, return_inverse=True)
    out = []
    for q in range(len(values[0])):
        x = np.concatenate([2 * vals[q][..., keep] for vals, keep in zip(values, picks)], axis=-1)
        x = np.where(o < 0, np.conj(x), x)
        summed = np.zeros(x.shape[:-1] + (uniq.size,), dtype=complex)
        np.add.at(np.moveaxis(summed, -1, 0), inv, np.moveaxis(x, -1, 0))
        out.append(summed)
    return uniq / 1e9 * fm, out


def _on_grid(X: np.ndarray, m: int) -> np.ndarray:
    """Σ_{k=−H}^{H} X_k e^{2πikj/m} at j = 0 … m−1 (rows of X (…, 2H+1)), by an inverse FFT."""
    H = (X.shape[-1] - 1) // 2
    padded = np.zeros(X.shape[:-1] + (m,), dtype=complex)
    padded[..., np.arange(-H, H + 1) % m] = X
    return np.fft.ifft(padded, axis=-1) * m


def _contact(model: GearRotorModel, fams, sols, H: int) -> tuple[np.ndarray, np.ndarray]:
    """Lower bounds of min_t (δ_s − b̄_s) and of min_t N_s: the mesh family on a phase grid minus the envelopes
    |Σ_k X_k e^{2πikφ}| of the other families (their carriers take every phase over the shaft revolutions)."""
    m = max(CONTACT_SAMPLES, 8 * (2 * H + 1), 4 * model.stiffness.k_left.size)
    margin = np.zeros((2, m))
    force = np.zeros((2, m))
    for fam, (Y, N, _) in zip(fams, sols):
        g, f = _on_grid(Y - fam.gap, m), _on_grid(N, m)
        if fam.nu == 0.0:
            margin += g.real
            force += f.real
        else:
            margin -= 2 * np.abs(g)
            force -= 2 * np.abs(f)
    meshes = np.array(model.stiffness.mean) > 0
    return np.where(meshes, margin.min(axis=1), np.inf), np.where(meshes, force.min(axis=1), np.inf)


def _solve(model: GearRotorModel, H: int):
    """Families, their solutions (Y, N, Q) and the lines (frequency, (mesh force, DTE, reduced states)) at H."""
    ops = _operators(model, H)
    L = max(2 * H, 64)
    kappa_long = np.array([periodic_coefficients(k, 2 * L) for k in (model.stiffness.k_left, model.stiffness.k_right)])
    fams = [_mesh_family(model, H, kappa_long, L)] + _member_families(model, H, ops.kappa)
    sols = [_solve_family(model, ops, fam, H) for fam in fams]
    KF, CF = force_matrices(model)
    values = []
    for fam, (Y, N, Q) in zip(fams, sols):
        w = (fam.nu + np.arange(-H, H + 1)) * 2 * math.pi * model.mesh_frequency
        bearing = np.einsum("jdn,kn->jdk", KF, Q) + 1j * w * np.einsum("jdn,kn->jdk", CF, Q)
        values.append((N, 0.5 * (Y - fam.error).sum(axis=0), Q.T, bearing))
    return fams, sols, _lines(fams, values, H, model.mesh_frequency)


def _upto(lines, order: float, fm: float):
    """The lines of order ≤ ``order``."""
    f, vals = lines
    keep = f <= order * fm * (1 + 1e-12)
    return f[keep], [v[..., keep] for v in vals]


def _truncation(coarse, fine, order: float, fm: float) -> float:
    """Largest change of the mesh-force and DTE lines of order ≤ ``order`` from ``coarse`` to ``fine``, relative to the
    largest line of each quantity [-]."""
    (fc, vc), (ff, vf) = _upto(coarse, order, fm), _upto(fine, order, fm)
    if fc.shape != ff.shape or not np.allclose(fc, ff):     # both hold every line of order ≤ H/4
        raise AssertionError("harmonic balance: the line sets of H/2 and H harmonics differ")
    err = 0.0
    for a, b in zip(vc[:2], vf[:2]):
        scale = np.abs(b).max(initial=0.0)
        if scale > 0:
            err = max(err, float(np.abs(b - a).max() / scale))
    return err


def harmonic_response(model: GearRotorModel, harmonics: int | None = None,
                      tol: float = TRUNCATION_TOL) -> HarmonicSolution:
    """The steady state of ``model`` by harmonic balance; raises ValueError where :func:`applies` says it does not
    model an excitation.

    ``harmonics``: H mesh harmonics per family, fixed; default: :data:`HARMONICS`, doubled (up to
    :data:`MAX_HARMONICS`) until the lines of orders ≤ H/4 of H/2 harmonics agree with those of H within ``tol``
    (relative to the largest line): :attr:`HarmonicSolution.truncation`.  The lines of orders ≤ H/2 are
    returned (the upper half of the harmonics carries the parametric coupling of the lower).  The answer is the linear one of the
    loaded flanks in contact: read :attr:`HarmonicSolution.contact_kept` before using it
    (:mod:`femgear.system.dynamics.harmonic_sweep` does)."""
    why = applies(model)
    if why is not None:
        raise ValueError(f"harmonic balance does not apply: {why}")
    if harmonics is not None and int(harmonics) < 2:
        raise ValueError(f"harmonics must be ≥ 2 (got {harmonics!r})")
    H = HARMONICS if harmonics is None else int(harmonics)
    fm = model.mesh_frequency
    coarse = _solve(model, H // 2)[2]
    while True:
        fams, sols, fine = _solve(model, H)
        err = _truncation(coarse, fine, H // 4, fm)
        if harmonics is not None or err <= tol or 2 * H > MAX_HARMONICS:
            break
        H, coarse = 2 * H, fine
    freq, (force, dte, q, bearing) = _upto(fine, H // 2, fm)
    margin, nmin = _contact(model, fams, sols, H)
    return HarmonicSolution(
        mesh_frequency=model.mesh_frequency, harmonics=H, families=tuple(f.name for f in fams), frequency=freq,
        mesh_force=force, mesh_force_mean=sols[0][1][:, H].real, dte=dte, displacement=model.T @ q,
        displacement_mean=model.T @ sols[0][2][H].real, contact_margin=margin, normal_force_min=nmin,
        truncation=err, bearing_force=bearing, bearing_force_mean=force_matrices(model)[0] @ sols[0][2][H].real)
