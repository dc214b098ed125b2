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
Φ_j and the hold integrals come from one block matrix exponential (Van Loan, IEEE TAC
23:395, 1978), cached per (phase, contact state) and across runs of the same structure
and step (:func:`_propagator_cache`).  While both drive flanks are in contact (the
usual state) the known inputs of every step are precomputed per phase, so a step costs
two small mat-vecs.  Exact for the linear time-invariant case; stable far above the
RK4 limit.
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.dynamics.model import GearRotorModel
from femgear.dynamics.simulation import Simulation, inputs, record_plan
from femgear.errors import ConvergenceError


def _expm(Z: np.ndarray) -> np.ndarray:
    """Matrix exponential by scaling and squaring of a degree-14 Taylor polynomial.

    Used for the many small propagators of ``expo`` (72×72 for 12 DOF), where it is
    several times faster than scipy.linalg.expm's Padé; after scaling ‖Z‖₁ ≤ 1/2 the
    truncation error is below 0.5^15/15! ≈ 2e-17.
    """
    norm = np.abs(Z).sum(axis=0).max()
    sq = max(0, int(math.ceil(math.log2(norm / 0.5)))) if norm > 0.5 else 0
    X = Z / 2.0**sq
    n = Z.shape[0]
    E = np.eye(n) + X / 14.0
    for k in range(13, 0, -1):
        E = np.eye(n) + (X @ E) / k
    for _ in range(sq):
        E = E @ E
    return E


def _expo_substep(model: GearRotorModel, k, chi, h: float):
    """Φ and Γ_p = ∫₀ʰ e^{A(h−τ)} (τ/h)^p dτ, p = 0, 1, 2, for mesh springs k on the flanks with chi = 1."""
    n = model.n
    K = model.K + sum(chi[s] * k[s] * np.outer(model.G[s], model.G[s]) for s in range(2))
    C = model.C + sum(chi[s] * model.mesh_damping[s] * np.outer(model.G[s], model.G[s]) for s in range(2))
    Minv = np.linalg.inv(model.M)
    MK = Minv @ K
    # balance q and v by the stiffest frequency ω_s: state (q, v/ω_s)
    ws = math.sqrt(max(np.abs(MK).sum(axis=1).max(), 1.0))
    A = np.block([[np.zeros((n, n)), ws * np.eye(n)], [-MK / ws, -Minv @ C]])
    m = 2 * n
    Z = np.zeros((4 * m, 4 * m))
    Z[:m, :m] = A
    for blk in range(3):
        Z[blk * m:(blk + 1) * m, (blk + 1) * m:(blk + 2) * m] = np.eye(m)
    E = _expm(Z * h)
    d = np.concatenate([np.ones(n), np.full(n, ws)])
    scale = d[:, None] / d[None, :]          # D X D⁻¹
    return (E[:m, :m] * scale, E[:m, m:2 * m] * scale, E[:m, 2 * m:3 * m] * scale / h,
            2 * E[:m, 3 * m:] * scale / h**2)


def _expo_matrices(model: GearRotorModel, ks, chi, h: float):
    """Propagator of one step with M sub-steps of piecewise-constant mesh stiffness.

    ``ks``: (k_L, k_R) of each of the M equal sub-steps.  Inputs are held
    quadratically through t_n, t_n + h/2, t_n + h.  Returns (Φ, W0, Wh, W1, U) with

        y_{n+1} = Φ y_n + W0 F0 + Wh Fh + W1 F1 + U [u_L0, u_Lh, u_L1, u_R0, u_Rh, u_R1]

    where F is a general first-order input (external forces, mesh damping of ė,
    friction) and u_s = e_s + (±b) the displacement input of mesh s, which acts
    through the sub-step's own stiffness as the force G_sᵀ k_s(t) u_s.
    """
    M = len(ks)
    hs = h / M
    n = model.n
    m2 = 2 * n
    Minv = np.linalg.inv(model.M)
    bvec = [np.concatenate([np.zeros(n), Minv @ model.G[s]]) for s in range(2)]
    Phi = np.eye(m2)
    P = [np.zeros((m2, m2)) for _ in range(3)]   # responses to the hold coefficients c0, c1, c2 (in s = τ/h)
    Q = [np.zeros((m2, 3)) for _ in range(2)]    # the same for the displacement inputs u_s
    for j, k in enumerate(ks):
        F, g0, g1, g2 = _expo_substep(model, k, chi, hs)
        # on sub-step j, s = (j + σ)/M:  1 → g0;  s → (j g0 + g1)/M;  s² → (j² g0 + 2 j g1 + g2)/M²
        w = [g0, (j * g0 + g1) / M, (j * j * g0 + 2 * j * g1 + g2) / M**2]
        P = [F @ P[c] + w[c] for c in range(3)]
        for sd in range(2):
            Q[sd] = F @ Q[sd] + chi[sd] * k[sd] * np.stack([w[c] @ bvec[sd] for c in range(3)], axis=1)
        Phi = F @ Phi
    # c0 = F0, c1 = −3F0 + 4Fh − F1, c2 = 2F0 − 4Fh + 2F1
    to_nodes = np.array([[1.0, 0.0, 0.0], [-3.0, 4.0, -1.0], [2.0, -4.0, 2.0]])
    W0, Wh, W1 = (sum(to_nodes[c, node] * P[c] for c in range(3)) for node in range(3))
    U = np.hstack([Q[sd] @ to_nodes for sd in range(2)])
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


def expo_step(model: GearRotorModel, dt: float) -> tuple[float, int]:
    """The ``expo`` step: the integer fraction of the mesh period nearest to ``dt`` (step, steps per period)."""
    per = max(1, int(round(model.mesh_period / dt)))
    return model.mesh_period / per, per


def _phase_stiffness(model: GearRotorModel, per: int, substeps: int) -> list[tuple]:
    """Mesh stiffness of each phase slot: averages over ``substeps`` sub-steps (4-point midpoint rule each)."""
    sub = (np.arange(per)[:, None, None] + (np.arange(substeps)[None, :, None]
                                            + (np.arange(4)[None, None, :] + 0.5) / 4) / substeps) / per
    kLs, kRs = model.stiffness(sub)
    kL_sub, kR_sub = kLs.mean(axis=2), kRs.mean(axis=2)
    return [tuple(zip(kL_sub[j].tolist(), kR_sub[j].tolist())) for j in range(per)]


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


def _fast_path_inputs(cache: dict, per: int, steps: int, Fe, ecols, dcols, Bw):
    """The known inputs of every step while both drive flanks are in contact, per phase, and the
    friction input matrices (n2, 12) at the three hold nodes."""
    known = np.empty((steps, Bw.shape[0]))
    Wfr = []
    for j in range(min(per, steps)):
        Phi, W0, Wh, W1, U = cache[(j, (1, 1))]
        idx = np.arange(j, steps, per)
        i0, ih, i1 = 2 * idx, 2 * idx + 1, 2 * idx + 2
        known[idx] = (Fe[i0] + dcols[i0] @ Bw[:, :2].T) @ W0.T + (Fe[ih] + dcols[ih] @ Bw[:, :2].T) @ Wh.T \
            + (Fe[i1] + dcols[i1] @ Bw[:, :2].T) @ W1.T \
            + np.concatenate([ecols[i0, :1], ecols[ih, :1], ecols[i1, :1], ecols[i0, 1:], ecols[ih, 1:], ecols[i1, 1:]],
                             axis=1) @ U.T
        Wfr.append(np.hstack([W0 @ Bw[:, 2:], Wh @ Bw[:, 2:], W1 @ Bw[:, 2:]]))
    return known, Wfr


def _general_step(model, cache, j, kj, side, dt, y, i2, data, Nn, N_prev):
    """One step in any contact state: known inputs at t_n, t_n+h/2, t_n+h: u_s = e_s ± b (through
    the sub-steps' stiffness), c ė_s; friction: μ|N| extrapolated linearly from the last two
    steps, A and B at the nodes."""
    Fe, Bw, cm, eed, AA, BB, ee, bb = data
    chi = (int(side[0] != 0), int(side[1] != 0))
    mats = cache.get((j, chi))
    if mats is None:
        mats = cache[(j, chi)] = _expo_matrices(model, kj, chi, dt)
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
         record_from: float, substeps: int | None = None) -> Simulation:
    duration = steps * dt
    dt, per = expo_step(model, dt)
    steps = int(round(duration / dt))
    if substeps is None:                     # resolve the stiffness to ≥ 800 samples per mesh period
        substeps = max(1, math.ceil(800 / per))
    n = model.n
    n2 = 2 * n
    Minv = np.linalg.inv(model.M)
    kstep = _phase_stiffness(model, per, substeps)
    cache = _propagator_cache(model, dt, substeps)
    Gz, Bw = _channels(model, Minv)
    tt = np.arange(2 * steps + 1) * (dt / 2)          # half-step grid (quadratic hold)
    kL, kR, e, ed, f, A, B = inputs(model, tt)
    Fe = np.zeros((tt.size, n2))
    Fe[:, n:] = f @ Minv.T
    ee = (e[0].tolist(), e[1].tolist())
    eed = (ed[0].tolist(), ed[1].tolist())
    AA = (A[0].tolist(), A[1].tolist())
    BB = (B[0].tolist(), B[1].tolist())
    mu = model.mu
    bt = model.backlash_at(tt)                          # (2, n): half-width of each helix's dead zone
    bb = bt.tolist()
    cm = (float(model.mesh_damping[0]), float(model.mesh_damping[1]))
    switches = 0
    t_setup = time.perf_counter()
    for j in range(min(per, steps)):         # propagators of the all-in-contact state, built up front
        if (j, (1, 1)) not in cache:
            cache[(j, (1, 1))] = _expo_matrices(model, kstep[j], (1, 1), dt)
    ecols = np.stack([e[0] + bt[0], e[1] + bt[1]], axis=1)    # u_s = e_s + b_s(t) on the drive flank
    dcols = np.stack([cm[0] * ed[0], cm[1] * ed[1]], axis=1)
    known, Wfr = _fast_path_inputs(cache, per, steps, Fe, ecols, dcols, Bw)
    setup = time.perf_counter() - t_setup

    rec = record_plan(steps, dt, record_every, record_from)
    out = np.empty((rec.size, n2))
    ri = 0
    next_rec = rec[0] if rec.size else -1
    y = np.concatenate([q, v])
    N_prev = None
    side_prev = None
    fast = (1, 1)
    t0 = time.perf_counter()
    for i in range(steps + 1):
        if i == next_rec:
            out[ri] = y
            ri += 1
            next_rec = rec[ri] if ri < rec.size else -1
        if i == steps:
            break
        j = i % per
        kj = kstep[j]
        i2 = 2 * i
        gq0, gq1, gv0, gv1 = (Gz @ y).tolist()
        side = [0, 0]
        Nn = [0.0, 0.0]
        for s, (gq, gv) in enumerate(((gq0, gv0), (gq1, gv1))):
            b = bb[s][i2]
            d = gq - ee[s][i2]
            if d > b:
                side[s] = 1
            elif d < -b:
                side[s] = -1
            if mu > 0.0 and side[s] != 0:
                Nn[s] = mu * abs(kj[0][s] * (d - side[s] * b) + cm[s] * (gv - eed[s][i2]))
        side = (side[0], side[1])
        if side != side_prev:
            if side_prev is not None:
                switches += 1
            N_prev = Nn
            side_prev = side
        if side == fast:
            Phi = cache[(j, fast)][0]
            if mu > 0.0:
                a0, a1 = Nn[0], Nn[1]
                d0, d1 = a0 - N_prev[0], a1 - N_prev[1]
                fr = []
                for w in (0.0, 0.5, 1.0):
                    i3 = i2 + int(2 * w)
                    b0, b1 = a0 + w * d0, a1 + w * d1
                    fr += [b0 * AA[0][i3], b0 * BB[0][i3], b1 * AA[1][i3], b1 * BB[1][i3]]
                y = Phi @ y + known[i] + Wfr[j] @ fr
            else:
                y = Phi @ y + known[i]
            N_prev = Nn
            continue
        y = _general_step(model, cache, j, kj, side, dt, y, i2, (Fe, Bw, cm, eed, AA, BB, ee, bb), Nn, N_prev)
        N_prev = Nn
    seconds = time.perf_counter() - t0
    if not np.all(np.isfinite(out)):
        raise ConvergenceError("expo", "the solution became non-finite", {"dt": [dt]})
    return Simulation(model=model, method="expo", dt=dt, t=rec * dt, q=out[:, :n].copy(), v=out[:, n:].copy(),
                      seconds=seconds, steps=steps,
                      info={"contact_switches": switches, "steps_per_mesh_period": per, "cached_propagators": len(cache),
                            "setup_seconds": setup, "substeps": substeps})
