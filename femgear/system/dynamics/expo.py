"""Exponential integrator for the periodic, piecewise-linear gear-rotor structure (``expo``).

The step is set to an integer fraction of the mesh period (:func:`expo_step`), so the
mesh stiffness seen in step j repeats every period.  For each phase j and contact state
(each flank in contact or open) the linear system of that step — mesh stiffness
piecewise constant over ``substeps`` sub-steps — is propagated exactly: Φ_j = e^{A_j h}.
Known inputs (external forces, transmission errors, the backlash offset) enter with a
quadratic hold through t_n, t_n+h/2, t_n+h (the mesh force is a small difference of k·e
and k·Gq, so a linear hold's O(h²) error would be amplified); the friction force — the
only state-dependent remainder — with μ|N| extrapolated linearly from the last two
steps (exponential time differencing, Cox & Matthews, J. Comput. Phys. 176:430, 2002).
The stiffness over the sub-steps is the band-exact staircase (:func:`band_exact_staircase`:
the mesh orders below half the sub-step count are the table's), and its sub-step count
follows the highest mode the mesh reaches (:func:`default_substeps`).  Φ_j and the hold
integrals Γ_p = h p! φ_{p+1}(A h) come from the Taylor series of the φ-functions with
scaling and doubling, batched over all phases (:func:`_substeps`; equal to Van Loan's
block exponential, IEEE TAC 23:395, 1978, to round-off), cached per structure and step
(:func:`_propagator_cache`).  While both drive flanks are in contact (the usual state)
the known inputs of every step are precomputed and a step is one product of
[Φ_j | W_fr,j; Gz Φ_j | Gz W_fr,j] with (y, friction inputs), which also gives the mesh
deflections the next step's contact check needs.  Exact for the linear time-invariant
case; stable far above the RK4 limit.  The step itself is chosen in
:func:`femgear.system.dynamics.run.step_plan` (docs/dynamics_step.md).
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.errors import ConvergenceError
from femgear.system.dynamics.expo_scan import CHUNK_STEPS, ContactScan
from femgear.system.dynamics.modal import mesh_mode_limit
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.simulation import Simulation, inputs, record_plan


def _phi_taylor(X: np.ndarray) -> tuple[np.ndarray, ...]:
    """e^X and φ_1, φ_2, φ_3 of a stack of matrices X (φ_j(X) = Σ_k X^k/(k+j)!), by Horner's
    rule on the series of φ_3, for ‖X‖₁ ≤ 1 (callers scale).

    Terms: the fewest with ‖X‖₁^(K+3)/(K+3)! < 1e-17 (at most 20: ≈ 3e-16 at ‖X‖₁ = 2); on
    the 2n×2n state matrices instead of the 8n×8n block exponential (Van Loan).
    """
    norm = float(np.abs(X).sum(axis=-2).max()) if X.size else 0.0
    terms = 1
    while terms < 20 and norm ** (terms + 3) / math.factorial(terms + 3) > 1e-17:
        terms += 1
    diag = (..., *np.diag_indices(X.shape[-1]))
    p3 = np.zeros_like(X)
    p3[diag] = 1.0 / math.factorial(terms + 2)
    for k in range(terms - 2, -1, -1):
        p3 = X @ p3
        p3[diag] += 1.0 / math.factorial(k + 3)
    p2 = X @ p3
    p2[diag] += 0.5
    p1 = X @ p2
    p1[diag] += 1.0
    E = X @ p1
    E[diag] += 1.0
    return E, p1, p2, p3


def _substeps(model: GearRotorModel, k: np.ndarray, chi, h: float):
    """Φ and Γ_p = ∫₀ʰ e^{A(h−τ)} (τ/h)^p dτ, p = 0, 1, 2, of a stack of sub-steps of length h
    with mesh springs k (stack, 2) on the flanks with chi = 1.

    Γ_p = h p! φ_{p+1}(Ah) (expand e^{A(h−τ)} and integrate the Beta integrals term by
    term): from the Taylor series of h/2^s, 2^s the power of two that brings ‖Ah‖₁ to ≤ 1,
    doubled s times.  The state is balanced as (q, v/ω_s), ω_s from the stiffest stiffness
    of the stack."""
    n = model.n
    Minv = np.linalg.inv(model.M)
    K0 = Minv @ model.K
    GG = [Minv @ np.outer(model.G[s], model.G[s]) for s in range(2)]
    C = Minv @ (model.C + sum(chi[s] * model.mesh_damping[s] * np.outer(model.G[s], model.G[s]) for s in range(2)))
    kc = k * np.asarray(chi, dtype=float)
    MK = K0 + kc[:, 0, None, None] * GG[0] + kc[:, 1, None, None] * GG[1]
    ws = math.sqrt(max(float(np.abs(MK).sum(axis=-1).max()), 1.0))
    A = np.zeros((k.shape[0], 2 * n, 2 * n))
    A[:, :n, n:] = ws * np.eye(n)
    A[:, n:, :n] = -MK / ws
    A[:, n:, n:] = -C
    d = np.concatenate([np.ones(n), np.full(n, ws)])
    scale = d[:, None] / d[None, :]          # D X D⁻¹
    # scaling and doubling: Γ_p over [0, 2h] from those over [0, h] (split the integral at h):
    # Γ0 ← EΓ0 + Γ0,  Γ1 ← (EΓ1 + Γ0 + Γ1)/2,  Γ2 ← (EΓ2 + Γ0 + 2Γ1 + Γ2)/4,  E ← E²
    norm = float(np.abs(A).sum(axis=-2).max()) * h
    sq = max(0, math.ceil(math.log2(norm))) if norm > 1.0 else 0
    hh = h / 2**sq
    E, p1, p2, p3 = _phi_taylor(A * hh)
    G0, G1, G2 = hh * p1, hh * p2, 2 * hh * p3
    for _ in range(sq):
        G0, G1, G2 = E @ G0 + G0, 0.5 * (E @ G1 + G0 + G1), 0.25 * (E @ G2 + G0 + 2 * G1 + G2)
        E = E @ E
    return E * scale, G0 * scale, G1 * scale, G2 * scale


def _expo_matrices(model: GearRotorModel, ks: np.ndarray, chi, h: float):
    """Propagators of a stack of steps, each with M sub-steps of piecewise-constant mesh stiffness.

    ``ks``: (stack, M, 2) — (k_L, k_R) of each of the M equal sub-steps of each step.
    Inputs are held quadratically through t_n, t_n + h/2, t_n + h.  Returns stacks
    (Φ, W0, Wh, W1, U) with

        y_{n+1} = Φ y_n + W0 F0 + Wh Fh + W1 F1 + U [u_L0, u_Lh, u_L1, u_R0, u_Rh, u_R1]

    where F is a general first-order input (external forces, mesh damping of ė,
    friction) and u_s = e_s + (±b) the displacement input of mesh s, which acts
    through the sub-step's own stiffness as the force G_sᵀ k_s(t) u_s.
    """
    ks = np.asarray(ks, dtype=float)
    S, M = ks.shape[:2]
    hs = h / M
    n = model.n
    m2 = 2 * n
    Minv = np.linalg.inv(model.M)
    bvec = np.stack([np.concatenate([np.zeros(n), Minv @ model.G[s]]) for s in range(2)])   # (2, m2)
    Phi = np.broadcast_to(np.eye(m2), (S, m2, m2)).copy()
    P = [np.zeros((S, m2, m2)) for _ in range(3)]  # responses to the hold coefficients c0, c1, c2 (in s = τ/h)
    Q = np.zeros((S, 2, m2, 3))                    # the same for the displacement inputs u_s
    for j in range(M):
        F, g0, g1, g2 = _substeps(model, ks[:, j], chi, hs)
        # on sub-step j, s = (j + σ)/M:  1 → g0;  s → (j g0 + g1)/M;  s² → (j² g0 + 2 j g1 + g2)/M²
        w = [g0, (j * g0 + g1) / M, (j * j * g0 + 2 * j * g1 + g2) / M**2]
        P = [F @ P[c] + w[c] for c in range(3)]
        wb = np.stack([w[c] @ bvec.T for c in range(3)], axis=-1)          # (S, m2, 2 sides, 3)
        kc = ks[:, j] * np.asarray(chi, dtype=float)                           # (S, 2)
        Q = np.einsum("sij,sdjc->sdic", F, Q) + np.moveaxis(wb, 2, 1) * kc[:, :, None, None]
        Phi = F @ Phi
    # c0 = F0, c1 = −3F0 + 4Fh − F1, c2 = 2F0 − 4Fh + 2F1
    to_nodes = np.array([[1.0, 0.0, 0.0], [-3.0, 4.0, -1.0], [2.0, -4.0, 2.0]])
    W0, Wh, W1 = (sum(to_nodes[c, node] * P[c] for c in range(3)) for node in range(3))
    U = np.concatenate([Q[:, sd] @ to_nodes for sd in range(2)], axis=-1)
    return Phi, W0, Wh, W1, U


_PROPAGATORS: dict = {}


def _propagator_cache(model: GearRotorModel, dt: float, substeps: int) -> dict:
    """The propagators of (model, dt, substeps), kept for the last few models (a pure memo).

    Keyed by a hash of every array the propagators depend on, so runs that differ only
    in their excitation (eccentricity, errors, torque at equal stiffness) share them.
    """
    import hashlib

    h = hashlib.sha1()
    for a in (model.M, model.K, model.C, model.G, model.mesh_damping, model.stiffness.k_left, model.stiffness.k_right,
              np.array([dt, model.mesh_frequency, substeps])):
        h.update(np.ascontiguousarray(a, dtype=float).tobytes())
    key = h.hexdigest()
    if key not in _PROPAGATORS:
        while len(_PROPAGATORS) >= 4:
            _PROPAGATORS.pop(next(iter(_PROPAGATORS)))
        _PROPAGATORS[key] = {}
    return _PROPAGATORS[key]


def clear_propagator_cache() -> None:
    """Forget all cached propagators (benchmarks time the set-up from scratch)."""
    _PROPAGATORS.clear()


#: stiffness sub-steps per period of the highest mode that the mesh excitation reaches
SUBSTEPS_PER_MODE_PERIOD = 24
#: and at least this many per mesh period
MIN_STIFFNESS_SAMPLES = 800


def default_substeps(model: GearRotorModel, per: int) -> int:
    """Stiffness sub-steps per step: per·substeps ≥ max(800, 24 f_r/f_m) samples per mesh period.

    f_r: the highest mode the mesh excitation reaches
    (:func:`femgear.system.dynamics.modal.mesh_mode_limit`).  The band-exact staircase
    (:func:`band_exact_staircase`) gets the stiffness's mesh orders below n/2 right; what it
    adds is its sawtooth against the true k(t), of fundamental order n, which drives the
    structure above its modes: a velocity ripple ∝ (dk/dφ) δ̄ /(n² f_m).  Measured at
    100 rpm on the baseline (1000 steps per mesh period): gear v_y −1.8 %, −0.40 %,
    −0.22 %, −0.13 % at n = 1000, 2000, 3000, 4000 — so 24 samples of the period of f_r
    (n = 3866 at 100 rpm) for ≲ 0.15 %.  Sub-steps cost set-up (a batch of small
    Taylor series per phase, once per structure and step), not work per step.
    """
    f_r = mesh_mode_limit(model)
    n = max(MIN_STIFFNESS_SAMPLES, math.ceil(SUBSTEPS_PER_MODE_PERIOD * f_r / model.mesh_frequency - 1e-9))
    return max(1, math.ceil(n / per))


def expo_step(model: GearRotorModel, dt: float) -> tuple[float, int]:
    """The ``expo`` step: the integer fraction of the mesh period nearest to ``dt`` (step, steps per period)."""
    per = max(1, int(round(model.mesh_period / dt)))
    return model.mesh_period / per, per


#: dense samples per stiffness sub-step from which the staircase's mesh orders are taken
_DENSE = 16


def band_exact_staircase(k_of_phase, n: int) -> np.ndarray:
    """Values k̃_0 … k̃_{n−1} of the n-step staircase over one mesh period whose mesh orders
    |m| < n/2 equal those of the stiffness k(φ) (``k_of_phase``: phases → values, periodic).

    A staircase holding k̃_j on [j/n, (j+1)/n) has the Fourier coefficients
    ŝ_m = K̃_m e^{−iπm/n} sinc(πm/n), K̃ the DFT of k̃: the hold delays every order by half a
    sub-step and damps it by sinc (the sub-step mean held, as before, damps it by sinc² —
    at n = 1000 and the 8.3 kHz mode at 100 rpm, order 161, by 8 %, which the mode's
    resonant response inherits).  Choosing K̃_m = ĉ_m e^{iπm/n}/sinc(πm/n) for |m| < n/2
    makes ŝ_m = ĉ_m there; the images above n/2 (orders n − m …) drive the structure far
    above its modes, quasi-statically.  ĉ_m from _DENSE·n samples of k (aliasing ∝ the
    stiffness's content above ~16n orders).  Falls back to the sub-step means where the
    correction would make a stiffness non-positive (a table with jumps at a coarse n).
    """
    dense = _DENSE * n
    ph = np.arange(dense) / dense
    k = np.asarray(k_of_phase(ph), dtype=float)
    c = np.fft.rfft(k, axis=-1) / dense
    m = np.arange(n // 2 + 1)
    keep = m < n / 2
    x = np.pi * m[keep] / n
    w = np.ones_like(x)
    w[1:] = x[1:] / np.sin(x[1:])
    Y = np.zeros(k.shape[:-1] + (n // 2 + 1,), dtype=complex)
    Y[..., keep] = c[..., m[keep]] * w * np.exp(1j * x) * n
    stair = np.fft.irfft(Y, n=n, axis=-1)
    means = k.reshape(k.shape[:-1] + (n, _DENSE)).mean(axis=-1)
    bad = np.any(stair <= 0, axis=-1) & np.all(k > 0, axis=-1)
    stair[bad] = means[bad]
    stair[np.all(k == 0, axis=-1)] = 0.0          # an absent mesh (one-mesh pairs) stays absent
    return stair


def _phase_stiffness(model: GearRotorModel, per: int, substeps: int) -> np.ndarray:
    """(per, substeps, 2): mesh stiffness (k_L, k_R) of each phase slot over its ``substeps`` sub-steps,
    the band-exact staircase of :func:`band_exact_staircase` with per·substeps steps per mesh period."""
    stair = band_exact_staircase(lambda ph: np.stack(model.stiffness(ph)), per * substeps)
    return np.moveaxis(stair.reshape(2, per, substeps), 0, -1)


#: run whole mesh periods of the contact fast path at once (:mod:`femgear.system.dynamics.expo_scan`); False: every
#: step one at a time (the reference of ``tests/dynamics/test_expo_scan.py``)
SCAN = True

#: phases whose propagators are built in one batch (bounds the temporaries to ~ 30 MB)
_BATCH = 512


def _contact_propagators(model: GearRotorModel, cache: dict, kstep: np.ndarray, dt: float) -> tuple:
    """The propagators (Φ, W0, Wh, W1, U) of the all-in-contact state of every phase, stacked
    (per, ...), built in batches of :data:`_BATCH` phases and cached under "contact"."""
    if "contact" not in cache:
        parts = [_expo_matrices(model, kstep[lo:lo + _BATCH], (1, 1), dt) for lo in range(0, kstep.shape[0], _BATCH)]
        cache["contact"] = tuple(np.concatenate([p[k] for p in parts]) for k in range(5))
    return cache["contact"]


def _channels(model: GearRotorModel, Minv: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Gz (mesh deflections and rates from the state) and Bw (input channels: mesh damping of ė,
    force +G_s c ė_s; friction μ|N|A, μ|N|B per side)."""
    n = model.n
    Gz = np.zeros((4, 2 * n))
    Gz[0:2, :n] = model.G
    Gz[2:4, n:] = model.G
    Bw = np.zeros((2 * n, 6))
    Bw[n:] = Minv @ np.vstack([model.G[0], model.G[1], -model.H0[0], -model.H1[0], -model.H0[1], -model.H1[1]]).T
    return Gz, Bw


def _fast_path_inputs(mats: tuple, steps: int, Fe, ecols, dcols, Bw, Gz, AB):
    """The fast path (both drive flanks in contact), augmented by the mesh deflections and rates
    of the new state (rows Gz·):

    - ``MJ``: (per, 2n+4, 2n[+12]) [Φ_j | W_fr,j; Gz Φ_j | Gz W_fr,j] per phase j, W_fr,j the
      friction inputs μ|N_s| A_s, μ|N_s| B_s (s = 0, 1) at the three hold nodes (without friction,
      ``AB`` None: Φ_j alone);
    - ``known``: (steps, 2n+4) the known inputs of every step (external forces, c ė_s, u_s = e_s + b_s);
    - ``ABn``: (steps, 12) A_s, B_s at the three nodes of every step (``AB``: A, B on the half-step
      grid), or None.
    """
    Ph, W0, Wh, W1, U = mats
    per, m = Ph.shape[0], Bw.shape[0]
    aug = np.vstack([np.eye(m), Gz])
    Fd = Fe + dcols @ Bw[:, :2].T
    cyc = -(-steps // per)                    # whole mesh periods of steps, the last one padded
    ec = np.empty((2 * steps + 1, 6))         # u_s at the nodes, in U's column order (s = 0 at 0, ½, 1; then s = 1)
    for o in range(3):
        ec[:2 * steps + 1 - o, o] = ecols[o:, 0]
        ec[:2 * steps + 1 - o, 3 + o] = ecols[o:, 1]
    known = np.zeros((cyc * per, m + 4))
    for W, X in ((W0, Fd[0:2 * steps:2]), (Wh, Fd[1:2 * steps:2]), (W1, Fd[2:2 * steps + 1:2]), (U, ec[0:2 * steps:2])):
        P = np.zeros((cyc * per, X.shape[1]))
        P[:steps] = X                          # step i = c·per + j of the period c at phase j
        known += np.einsum("jab,cjb->cja", aug @ W, P.reshape(cyc, per, -1), optimize=True).reshape(cyc * per, -1)
    known = known[:steps]
    if AB is None:
        return aug @ Ph, known, None
    A, B = AB
    Wfr = np.concatenate([aug @ W @ Bw[:, 2:] for W in (W0, Wh, W1)], axis=-1)
    ABn = np.stack([X[s][o:o + 2 * steps:2] for o in range(3) for s in range(2) for X in (A, B)], axis=1)
    return np.concatenate([aug @ Ph, Wfr], axis=-1), known, ABn


def _general_step(model, cache, j, ks, side, dt, y, i2, data, Nn, N_prev):
    """One step in any contact state: known inputs at t_n, t_n+h/2, t_n+h: u_s = e_s ± b (through
    the sub-steps' stiffness), c ė_s; friction: μ|N| extrapolated linearly from the last two
    steps, A and B at the nodes."""
    Fe, Bw, cm, eed, AA, BB, ee, bb = data
    chi = (int(side[0] != 0), int(side[1] != 0))
    mats = cache.get((j, chi))
    if mats is None and chi == (1, 1):
        mats = tuple(a[j] for a in cache["contact"])
    if mats is None:
        mats = cache[(j, chi)] = tuple(a[0] for a in _expo_matrices(model, ks[None], chi, dt))
    Phi, W0, Wh, W1, U = mats
    c0, c1 = chi[0] * cm[0], chi[1] * cm[1]
    F = []
    for o, w in ((0, 0.0), (1, 0.5), (2, 1.0)):
        ii = i2 + o
        a0 = Nn[0] + w * (Nn[0] - N_prev[0])
        a1 = Nn[1] + w * (Nn[1] - N_prev[1])
        F.append(Fe[ii] + Bw @ (c0 * eed[0][ii], c1 * eed[1][ii], a0 * AA[0][ii], a0 * BB[0][ii],
                                a1 * AA[1][ii], a1 * BB[1][ii]))
    u = tuple(ee[s][i2 + o] + side[s] * bb[s][i2 + o] for s in range(2) for o in range(3))
    return Phi @ y + W0 @ F[0] + Wh @ F[1] + W1 @ F[2] + U @ u


def expo(model: GearRotorModel, steps: int, dt: float, q: np.ndarray, v: np.ndarray, record_every: int,
         record_from: float, substeps: int | None = None, t_start: float = 0.0) -> Simulation:
    """``steps`` steps of about ``dt`` from the state (q, v) at ``t_start`` (a whole number of mesh periods)."""
    duration = steps * dt
    dt, per = expo_step(model, dt)
    steps = int(round(duration / dt))
    cycles0 = t_start * model.mesh_frequency
    if abs(cycles0 - round(cycles0)) > 1e-9 * max(1.0, cycles0):
        raise ValueError(f"expo: t_start must be a whole number of mesh periods (got {cycles0:.6g})")
    if substeps is None:
        substeps = default_substeps(model, per)
    n = model.n
    n2 = 2 * n
    Minv = np.linalg.inv(model.M)
    kstep = _phase_stiffness(model, per, substeps)
    cache = _propagator_cache(model, dt, substeps)
    Gz, Bw = _channels(model, Minv)
    tt = t_start + np.arange(2 * steps + 1) * (dt / 2)          # half-step grid (quadratic hold)
    kL, kR, e, ed, f, A, B = inputs(model, tt)
    Fe = np.zeros((tt.size, n2))
    Fe[:, n:] = f @ Minv.T
    mu = model.mu
    bt = model.backlash_at(tt)                          # (2, n): half-width of each helix's dead zone
    cm = (float(model.mesh_damping[0]), float(model.mesh_damping[1]))
    t_setup = time.perf_counter()
    contact = _contact_propagators(model, cache, kstep, dt)     # all-in-contact, up front
    k0 = kstep[:, 0].tolist()                # the stiffness at the start of each phase slot (friction's |N|)
    ecols = np.stack([e[0] + bt[0], e[1] + bt[1]], axis=1)    # u_s = e_s + b_s(t) on the drive flank
    dcols = np.stack([cm[0] * ed[0], cm[1] * ed[1]], axis=1)
    MJ, known, ABn = _fast_path_inputs(contact, steps, Fe, ecols, dcols, Bw, Gz, (A, B) if mu > 0.0 else None)
    setup = time.perf_counter() - t_setup

    rec = record_plan(steps, dt, record_every, record_from - t_start)
    z = np.zeros(MJ.shape[-1])               # fast-path state (y, friction inputs at the three nodes)
    z[:n2] = np.concatenate([q, v])
    def static():           # the step loop's per-step data as Python lists (built when it first runs)
        ee, eed, AA, BB, bb = ((x[0].tolist(), x[1].tolist()) for x in (e, ed, A, B, bt))
        return (model, cache, kstep, dt, per, n2, mu, cm, k0, ee, eed, bb, MJ, known, ABn,
                (Fe, Bw, cm, eed, AA, BB, ee, bb), rec, Gz)

    loop = _Loop(static=static, z=z, out=np.empty((rec.size, n2)), rec=rec)
    t0 = time.perf_counter()
    scan = ContactScan(MJ, known, ABn, Gz, e, ed, bt, kstep[:, 0], cm, mu) if SCAN and steps >= per else None
    i, wait = 0, 0
    while i < steps:
        if scan is not None and wait == 0 and i % per == 0 and steps - i >= per:
            periods = min((steps - i) // per, max(1, CHUNK_STEPS // per))
            done = _scan_periods(loop, scan, i, periods)
            i += done
            loop.scanned += done
            if done == periods * per:
                continue
            loop.backoff = 2 * loop.backoff          # a contact event: step by step for 1, 2, 4, … periods
            wait = loop.backoff
        nxt = min(steps, (i // per + 1) * per)
        _step_loop(loop, i, nxt)
        i, wait = nxt, max(wait - 1, 0)
    if loop.ri < rec.size and rec[loop.ri] == steps:
        loop.out[loop.ri] = z[:n2]
    out, switches = loop.out, loop.switches
    seconds = time.perf_counter() - t0
    if not np.all(np.isfinite(out)):
        raise ConvergenceError("expo", "the solution became non-finite", {"dt": [dt]})
    return Simulation(model=model, method="expo", dt=dt, t=t_start + rec * dt, q=out[:, :n].copy(), v=out[:, n:].copy(),
                      seconds=seconds, steps=steps,
                      info={"contact_switches": switches, "steps_per_mesh_period": per, "cached_propagators": per + len(cache) - 1,
                            "setup_seconds": setup, "substeps": substeps, "scanned_steps": loop.scanned})


class _Loop:
    """The step loop's state between its step-by-step stretches and its scans."""

    def __init__(self, static, z, out, rec):
        self.make_static, self.static, self.z, self.out, self.rec = static, None, z, out, rec
        self.N_prev, self.side_prev, self.switches, self.ri, self.backoff = (0.0, 0.0), None, 0, 0, 1
        self.scanned = 0


def _scan_periods(loop: _Loop, scan: ContactScan, i: int, periods: int) -> int:
    """``periods`` whole mesh periods of the contact fast path from step ``i`` at once
    (:class:`femgear.system.dynamics.expo_scan.ContactScan`); the steps done (up to the first that leaves it)."""
    n2, rec, fast = scan.n2, loop.rec, (1, 1)
    y0 = loop.z[:n2].copy()
    if not np.all(scan.Gz[0:2] @ y0 - scan.e[i] > scan.b[i]):      # not on both drive flanks now: no scan
        return 0
    x0 = y0
    if scan.friction:
        a = scan.normal_force(i, y0)
        x0 = np.concatenate([y0, a if loop.side_prev != fast else loop.N_prev])
    x, done = scan.run(i, periods, x0)
    if done == 0:
        return 0
    if loop.side_prev != fast and loop.side_prev is not None:
        loop.switches += 1
    r1 = int(np.searchsorted(rec, i + done))
    loop.out[loop.ri:r1] = x[rec[loop.ri:r1] - i, :n2]
    loop.ri = r1
    loop.z[:n2] = x[done, :n2]
    if scan.friction:
        loop.N_prev = (float(x[done, n2]), float(x[done, n2 + 1]))
    loop.side_prev = fast
    return done


def _step_loop(loop: _Loop, i_from: int, i_to: int) -> None:
    """Steps ``i_from`` … ``i_to`` − 1 one at a time, in any contact state, recording as planned."""
    if loop.static is None:
        loop.static = loop.make_static()
    (model, cache, kstep, dt, per, n2, mu, cm, k0, ee, eed, bb, MJ, known, ABn, data, rec, Gz) = loop.static
    z, out = loop.z, loop.out
    zf = z[n2:]
    N_prev, side_prev, switches, ri = loop.N_prev, loop.side_prev, loop.switches, loop.ri
    next_rec = rec[ri] if ri < rec.size else -1
    fast = (1, 1)
    g = (Gz @ z[:n2]).tolist()
    for i in range(i_from, i_to):
        if i == next_rec:
            out[ri] = z[:n2]
            ri += 1
            next_rec = rec[ri] if ri < rec.size else -1
        j = i % per
        i2 = 2 * i
        gq0, gq1, gv0, gv1 = g
        d0 = gq0 - ee[0][i2]
        d1 = gq1 - ee[1][i2]
        b0 = bb[0][i2]
        b1 = bb[1][i2]
        side = (1 if d0 > b0 else (-1 if d0 < -b0 else 0), 1 if d1 > b1 else (-1 if d1 < -b1 else 0))
        if mu > 0.0:
            kj = k0[j]
            Nn = (mu * abs(kj[0] * (d0 - side[0] * b0) + cm[0] * (gv0 - eed[0][i2])) if side[0] else 0.0,
                  mu * abs(kj[1] * (d1 - side[1] * b1) + cm[1] * (gv1 - eed[1][i2])) if side[1] else 0.0)
        else:
            Nn = (0.0, 0.0)
        if side != side_prev:
            if side_prev is not None:
                switches += 1
            N_prev = Nn
            side_prev = side
        if side == fast:
            if mu > 0.0:
                a0, a1 = Nn
                e0, e1 = a0 - N_prev[0], a1 - N_prev[1]
                h0, h1, f0, f1 = a0 + 0.5 * e0, a1 + 0.5 * e1, a0 + e0, a1 + e1
                np.multiply(ABn[i], (a0, a0, a1, a1, h0, h0, h1, h1, f0, f0, f1, f1), out=zf)
            r = MJ[j] @ z
            r += known[i]
            z[:n2] = r[:n2]
            g = r[n2:].tolist()
            N_prev = Nn
            continue
        z[:n2] = _general_step(model, cache, j, kstep[j], side, dt, z[:n2], i2, data, Nn, N_prev)
        g = (Gz @ z[:n2]).tolist()
        N_prev = Nn
    loop.N_prev, loop.side_prev, loop.switches, loop.ri = N_prev, side_prev, switches, ri
