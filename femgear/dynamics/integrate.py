"""Time integration of a :class:`GearRotorModel`: fixed-step RK4 and implicit HHT-α.

- ``rk4``: the classical fourth-order Runge–Kutta scheme with a fixed step, as the
  paper uses (dt = 1e-5 s).  Explicit, so the step must lie inside its stability
  region for the stiffest linearised state (:func:`stability_limit`); a larger step is
  refused.  All time-dependent inputs (k(t), e(t), ė(t), f(t), friction factors) are
  evaluated vectorised on the half-step grid before the loop; one stage is one dense
  mat-vec of the linear part plus the two mesh forces.
- ``newmark``: Hilber–Hughes–Taylor α-method (Hilber, Hughes & Taylor, Earthquake Eng.
  Struct. Dyn. 5:283, 1977; α = 0 is Newmark's average acceleration rule, Newmark,
  J. Eng. Mech. Div. 85:67, 1959), unconditionally stable.  The mesh forces are
  piecewise linear in the state once the contact state of each flank and the sign of
  N_s are fixed, so Newton's method is exact in one solve per contact state; the
  solve uses the constant factor J0⁻¹ of the linear part and a rank-2 (Woodbury)
  update for the two meshes, i.e. only a 2×2 system per step.  If the contact state
  found differs from the assumed one, the step is repeated with the new state
  (Newton on the piecewise-linear gap); more than ``max_iter`` changes raise
  :class:`femgear.errors.ConvergenceError`.

- ``expo``: an exponential integrator for the periodic, piecewise-linear structure.
  The step is set to an integer fraction of the mesh period, so the mesh stiffness
  seen in step j (its exact average over the step, from the periodic table) repeats
  every period.  For each phase j and contact state (each flank in contact or open)
  the linear time-invariant system of that step is propagated exactly by
  Φ_j = e^{A_j h}; the known inputs (external forces, transmission errors, backlash
  offset) enter with a quadratic hold through t_n, t_n+h/2, t_n+h (the mesh force is
  a small difference of k·e and k·Gq, so a linear hold's O(h²) error is amplified), and the friction force — the only
  state-dependent remainder — with a linear extrapolation from the last two steps
  (exponential time differencing, Cox & Matthews, J. Comput. Phys. 176:430, 2002).
  Φ_j and the two hold integrals come from one block matrix exponential (Van Loan,
  IEEE TAC 23:395, 1978) and are cached per (phase, contact state) — and across runs
  of the same structure and step (:func:`_propagator_cache`).  Inside a step the mesh
  stiffness is piecewise constant over ``substeps`` sub-steps.  Exact for the linear
  time-invariant case; stable far above the RK4 limit.

All return a :class:`Simulation` with the recorded states.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from femgear.dynamics.model import GearRotorModel
from femgear.errors import ConvergenceError

METHODS = ("rk4", "newmark", "expo")


@dataclass(frozen=True)
class Simulation:
    """Recorded time history (reduced coordinates)."""

    model: GearRotorModel
    method: str
    dt: float
    t: np.ndarray        #: recorded times [s]
    q: np.ndarray        #: (n_rec, n) displacements
    v: np.ndarray        #: (n_rec, n) velocities
    seconds: float       #: wall time of the integration loop [s]
    steps: int
    info: dict = field(default_factory=dict, compare=False)


def first_order_matrix(model: GearRotorModel, k: tuple[float, float] | None = None) -> np.ndarray:
    """A of ẏ = A y for the linearised model, flanks in contact, mesh stiffness ``k``."""
    n = model.n
    if k is None:
        k = (model.stiffness.max, model.stiffness.max)
    K = model.K + sum(k[s] * np.outer(model.G[s], model.G[s]) for s in range(2))
    C = model.C + sum(model.mesh_damping[s] * np.outer(model.G[s], model.G[s]) for s in range(2))
    Minv = np.linalg.inv(model.M)
    return np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])


def _rk4_amplification(z: np.ndarray) -> np.ndarray:
    return np.abs(1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24)


def stability_limit(model: GearRotorModel) -> float:
    """Largest RK4 step [s] with |R(dt λ)| ≤ 1 for every eigenvalue λ of the stiffest linearisation.

    The linearisation takes the maximum mesh stiffness on both flanks (contact); the
    rigid rotation (λ = 0) is neutral.  Found by bisection on dt.
    """
    lam = np.linalg.eigvals(first_order_matrix(model))
    lam = lam[np.abs(lam) > 1e-6 * np.abs(lam).max()]   # rigid rotation: a (perturbed) double zero
    hi = 3.0 / np.abs(lam).max()
    lo = 0.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if np.all(_rk4_amplification(mid * lam) <= 1 + 1e-12):
            lo = mid
        else:
            hi = mid
    return lo


def _inputs(model: GearRotorModel, t: np.ndarray):
    ph = model.mesh_phase(t)
    kL, kR = model.stiffness(ph)
    e, ed = model.errors(t)
    f = model.external_force(t)
    if model.mu > 0 and model.friction is not None:
        A, B = model.friction(ph)
    else:
        A = B = np.zeros((2,) + t.shape)
    return kL, kR, e, ed, f, A, B


def simulate(
    model: GearRotorModel,
    duration: float,
    dt: float,
    method: str = "rk4",
    *,
    q0: np.ndarray | None = None,
    v0: np.ndarray | None = None,
    record_every: int = 1,
    record_from: float = 0.0,
    alpha: float = 0.0,
    max_iter: int = 20,
    check_stability: bool = True,
    substeps: int | None = None,
) -> Simulation:
    """Integrate from t = 0 over ``duration`` [s] with the fixed step ``dt`` [s].

    Initial state: the static equilibrium of the mean system (``q0``/``v0`` override).
    States at t ≥ ``record_from`` are recorded every ``record_every`` steps.
    ``alpha`` ∈ [−1/3, 0]: HHT numerical damping (``newmark`` only).
    ``substeps``: stiffness sub-steps inside one ``expo`` step (default: ≥ 800 per mesh period).
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)} (got {method!r})")
    if not (math.isfinite(dt) and dt > 0):
        raise ValueError(f"dt must be positive (got {dt!r})")
    if not duration > 0:
        raise ValueError(f"duration must be positive (got {duration!r})")
    if not isinstance(record_every, int) or record_every < 1:
        raise ValueError(f"record_every must be a positive integer (got {record_every!r})")
    steps = int(round(duration / dt))
    q = model.static_state() if q0 is None else np.asarray(q0, dtype=float).copy()
    v = np.zeros(model.n) if v0 is None else np.asarray(v0, dtype=float).copy()
    if method == "rk4":
        if check_stability:
            limit = stability_limit(model)
            if dt > limit:
                raise ValueError(
                    f"dt = {dt:.3g} s exceeds the RK4 stability limit {limit:.3g} s of this model "
                    f"(stiffest mode {1 / (2 * math.pi) * 2.785 / limit:.0f} Hz); lower dt or use method='newmark'"
                )
        return _rk4(model, steps, dt, q, v, record_every, record_from)
    if method == "expo":
        return _expo(model, steps, dt, q, v, record_every, record_from, substeps)
    if not -1 / 3 <= alpha <= 0:
        raise ValueError(f"alpha must be in [-1/3, 0] (got {alpha!r})")
    return _hht(model, steps, dt, q, v, record_every, record_from, alpha, max_iter)


def _record_plan(steps: int, dt: float, record_every: int, record_from: float) -> np.ndarray:
    idx = np.arange(0, steps + 1, record_every)
    return idx[idx * dt >= record_from - 1e-12 * dt]


def _rk4(model, steps, dt, q, v, record_every, record_from) -> Simulation:
    n = model.n
    Minv = np.linalg.inv(model.M)
    L = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ model.K, -Minv @ model.C]])
    Gz = np.zeros((4, 2 * n))
    Gz[0:2, :n] = model.G
    Gz[2:4, n:] = model.G
    R = np.vstack([L, Gz])
    W = np.zeros((2 * n, 6))
    W[n:] = -Minv @ np.vstack([model.G[0], model.G[1], model.H0[0], model.H1[0], model.H0[1], model.H1[1]]).T
    th = np.arange(2 * steps + 1) * (dt / 2)
    kL, kR, e, ed, f, A, B = _inputs(model, th)
    F = np.zeros((th.size, 2 * n))
    F[:, n:] = f @ Minv.T
    kL, kR = kL.tolist(), kR.tolist()
    e0, e1, ed0, ed1 = e[0].tolist(), e[1].tolist(), ed[0].tolist(), ed[1].tolist()
    mu = model.mu
    A0, A1, B0, B1 = A[0].tolist(), A[1].tolist(), B[0].tolist(), B[1].tolist()
    bb = model.backlash_at(th).tolist()
    c0, c1 = float(model.mesh_damping[0]), float(model.mesh_damping[1])
    n2 = 2 * n

    def stage(y, j):
        r = R @ y
        d0, d1, dd0, dd1 = r[n2:].tolist()
        d0 -= e0[j]
        d1 -= e1[j]
        b = bb[j]
        if d0 > b:
            N0 = kL[j] * (d0 - b) + c0 * (dd0 - ed0[j])
        elif d0 < -b:
            N0 = kL[j] * (d0 + b) + c0 * (dd0 - ed0[j])
        else:
            N0 = 0.0
        if d1 > b:
            N1 = kR[j] * (d1 - b) + c1 * (dd1 - ed1[j])
        elif d1 < -b:
            N1 = kR[j] * (d1 + b) + c1 * (dd1 - ed1[j])
        else:
            N1 = 0.0
        a0 = mu * abs(N0)
        a1 = mu * abs(N1)
        return r[:n2] + W @ (N0, N1, a0 * A0[j], a0 * B0[j], a1 * A1[j], a1 * B1[j]) + F[j]

    rec = _record_plan(steps, dt, record_every, record_from)
    out = np.empty((rec.size, n2))
    y = np.concatenate([q, v])
    h, h2, h6 = dt, dt / 2, dt / 6
    ri = 0
    next_rec = rec[0] if rec.size else -1
    t0 = time.perf_counter()
    for i in range(steps + 1):
        if i == next_rec:
            out[ri] = y
            ri += 1
            next_rec = rec[ri] if ri < rec.size else -1
        if i == steps:
            break
        j = 2 * i
        k1 = stage(y, j)
        k2 = stage(y + h2 * k1, j + 1)
        k3 = stage(y + h2 * k2, j + 1)
        k4 = stage(y + h * k3, j + 2)
        y = y + h6 * (k1 + 2.0 * (k2 + k3) + k4)
    seconds = time.perf_counter() - t0
    if not np.all(np.isfinite(out)):
        raise ConvergenceError("rk4", "the solution became non-finite (step too large?)", {"dt": [dt]})
    return Simulation(model=model, method="rk4", dt=dt, t=rec * dt, q=out[:, :n].copy(), v=out[:, n:].copy(),
                      seconds=seconds, steps=steps)


def _hht(model, steps, dt, q, v, record_every, record_from, alpha, max_iter) -> Simulation:
    n = model.n
    M, C, K, G = model.M, model.C, model.K, model.G
    gamma = 0.5 - alpha
    beta = 0.25 * (1 - alpha) ** 2
    h = dt
    ap = 1 + alpha
    cq = 1 / (beta * h * h)      # a_{n+1} = cq q_{n+1} + ã
    cv = gamma / (beta * h)      # v_{n+1} = cv q_{n+1} + ṽ
    J0 = cq * M + ap * (K + cv * C)
    J0inv = np.linalg.inv(J0)
    # ã = −cq q_n − h cq v_n − (1/(2β) − 1) a_n ;  ṽ = −cv q_n + (1 − γ/β) v_n + h(1 − γ/(2β)) a_n
    Ta = np.hstack([-cq * np.eye(n), -h * cq * np.eye(n), -(1 / (2 * beta) - 1) * np.eye(n)])
    Tv = np.hstack([-cv * np.eye(n), (1 - gamma / beta) * np.eye(n), h * (1 - gamma / (2 * beta)) * np.eye(n)])
    # r0 = −M ã − ap C ṽ + α (C v_n + K q_n)   (forces added separately)
    Rz = -M @ Ta - ap * C @ Tv + alpha * np.hstack([K, C, np.zeros((n, n))])
    X = J0inv @ Rz
    Big = np.vstack([X, G @ X, G @ Tv])
    PG = J0inv @ G.T               # (n, 2)
    P0 = J0inv @ model.H0.T
    P1 = J0inv @ model.H1.T
    GPG, GP0, GP1 = G @ PG, G @ P0, G @ P1   # (2, 2): [row r, column s]

    tt = np.arange(steps + 1) * dt
    kL, kR, e, ed, f, A, B = _inputs(model, tt)
    ff = np.empty_like(f)
    ff[0] = f[0]
    ff[1:] = ap * f[1:] - alpha * f[:-1]
    xf = ff @ J0inv.T
    Gxf = xf @ G.T
    kk = (kL.tolist(), kR.tolist())
    ee = (e[0].tolist(), e[1].tolist())
    eed = (ed[0].tolist(), ed[1].tolist())
    AA = (A[0].tolist(), A[1].tolist())
    BB = (B[0].tolist(), B[1].tolist())
    mu = model.mu
    bb = model.backlash_at(tt).tolist()
    cm = (float(model.mesh_damping[0]), float(model.mesh_damping[1]))

    # initial acceleration from the equations of motion
    a = model.acceleration(np.array(0.0), q, v)
    _, Nprev, _ = model.mesh_forces(np.array(0.0), q, v)
    Nprev = Nprev.tolist()
    PWprev = [PG[:, s] + mu * np.sign(Nprev[s]) * (AA[s][0] * P0[:, s] + BB[s][0] * P1[:, s]) for s in range(2)]
    z = np.concatenate([q, v, a])
    # contact state per flank: +1 drive contact, −1 back contact, 0 open;  sign of N
    state = [1, 1]
    sgn = [1.0, 1.0]
    rec = _record_plan(steps, dt, record_every, record_from)
    outq = np.empty((rec.size, n))
    outv = np.empty((rec.size, n))
    ri = 0
    next_rec = rec[0] if rec.size else -1
    iters_total = 0
    changes = 0
    t0 = time.perf_counter()
    for i in range(steps + 1):
        if i == next_rec:
            outq[ri] = z[:n]
            outv[ri] = z[n:2 * n]
            ri += 1
            next_rec = rec[ri] if ri < rec.size else -1
        if i == steps:
            break
        j = i + 1
        w = Big @ z
        x = w[:n] + xf[j]
        gx0, gx1 = (w[n:n + 2] + Gxf[j]).tolist()
        gvt0, gvt1 = w[n + 2:n + 4].tolist()
        gvt = (gvt0, gvt1)
        # explicit part of the previous mesh force: α·J0⁻¹·Qm_n = −α Σ N_n PW_n
        if alpha != 0.0:
            x = x - alpha * (Nprev[0] * PWprev[0] + Nprev[1] * PWprev[1])
            gx0, gx1 = (np.array([gx0, gx1]) - alpha * (Nprev[0] * (G @ PWprev[0]) + Nprev[1] * (G @ PWprev[1]))).tolist()
        b = bb[j]
        for it in range(max_iter):
            iters_total += 1
            kap = [0.0, 0.0]
            n0 = [0.0, 0.0]
            for s in range(2):
                if state[s] != 0:
                    kap[s] = kk[s][j] + cm[s] * cv
                    n0[s] = -kk[s][j] * (ee[s][j] + state[s] * b) + cm[s] * (gvt[s] - eed[s][j])
            # G PW_s (2-vectors) with the friction sign of each flank
            gpw = []
            for s in range(2):
                fs = mu * sgn[s]
                gpw.append((GPG[0, s] + fs * (AA[s][j] * GP0[0, s] + BB[s][j] * GP1[0, s]),
                            GPG[1, s] + fs * (AA[s][j] * GP0[1, s] + BB[s][j] * GP1[1, s])))
            # (I + ap Σ_s gpw_s κ_s e_sᵀ) y = Gx − ap Σ_s gpw_s n0_s
            m00 = 1 + ap * gpw[0][0] * kap[0]
            m01 = ap * gpw[1][0] * kap[1]
            m10 = ap * gpw[0][1] * kap[0]
            m11 = 1 + ap * gpw[1][1] * kap[1]
            r0 = gx0 - ap * (gpw[0][0] * n0[0] + gpw[1][0] * n0[1])
            r1 = gx1 - ap * (gpw[0][1] * n0[0] + gpw[1][1] * n0[1])
            det = m00 * m11 - m01 * m10
            y0 = (r0 * m11 - m01 * r1) / det
            y1 = (m00 * r1 - m10 * r0) / det
            N = [kap[0] * y0 + n0[0], kap[1] * y1 + n0[1]]
            # check the assumed contact state and friction sign
            d = (y0 - ee[0][j], y1 - ee[1][j])
            new_state = [1 if d[s] > b else (-1 if d[s] < -b else 0) for s in range(2)]
            new_sgn = [sgn[s] if N[s] == 0.0 else math.copysign(1.0, N[s]) for s in range(2)]
            if new_state == state and (mu == 0.0 or new_sgn == sgn):
                break
            changes += 1
            state, sgn = new_state, new_sgn
        else:
            raise ConvergenceError(
                "newmark", f"contact state did not settle at t = {j * dt:.6g} s",
                {"iterations": [it + 1], "state_left": [state[0]], "state_right": [state[1]]},
            )
        PW = [PG[:, s] + (mu * sgn[s]) * (AA[s][j] * P0[:, s] + BB[s][j] * P1[:, s]) for s in range(2)]
        qn = x - ap * (N[0] * PW[0] + N[1] * PW[1])
        zq = z[:n]
        an = cq * (qn - zq - h * z[n:2 * n]) - (1 / (2 * beta) - 1) * z[2 * n:]
        vn = z[n:2 * n] + h * ((1 - gamma) * z[2 * n:] + gamma * an)
        z = np.concatenate([qn, vn, an])
        Nprev, PWprev = N, PW
    seconds = time.perf_counter() - t0
    if not (np.all(np.isfinite(outq)) and np.all(np.isfinite(outv))):
        raise ConvergenceError("newmark", "the solution became non-finite", {"dt": [dt]})
    return Simulation(model=model, method="newmark", dt=dt, t=rec * dt, q=outq, v=outv, seconds=seconds,
                      steps=steps, info={"alpha": alpha, "solves": iters_total, "state_changes": changes})


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


def expo_step(model: GearRotorModel, dt: float) -> tuple[float, int]:
    """The ``expo`` step: the integer fraction of the mesh period nearest to ``dt`` (step, steps per period)."""
    per = max(1, int(round(model.mesh_period / dt)))
    return model.mesh_period / per, per


def _expo(model, steps, dt, q, v, record_every, record_from, substeps=None) -> Simulation:
    duration = steps * dt
    dt, per = expo_step(model, dt)
    steps = int(round(duration / dt))
    if substeps is None:                     # resolve the stiffness to ≥ 800 samples per mesh period
        substeps = max(1, math.ceil(800 / per))
    n = model.n
    n2 = 2 * n
    Minv = np.linalg.inv(model.M)
    # mesh stiffness of each phase slot: averages over `substeps` sub-steps (4-point midpoint rule each)
    sub = (np.arange(per)[:, None, None] + (np.arange(substeps)[None, :, None]
                                            + (np.arange(4)[None, None, :] + 0.5) / 4) / substeps) / per
    kLs, kRs = model.stiffness(sub)
    kL_sub, kR_sub = kLs.mean(axis=2), kRs.mean(axis=2)
    kstep = [tuple(zip(kL_sub[j].tolist(), kR_sub[j].tolist())) for j in range(per)]
    cache = _propagator_cache(model, dt, substeps)

    Gz = np.zeros((4, n2))
    Gz[0:2, :n] = model.G
    Gz[2:4, n:] = model.G
    # input channels: mesh damping of ė (force +G_s c ė_s), friction μ|N|A, μ|N|B per side
    Bw = np.zeros((n2, 6))
    Bw[n:] = Minv @ np.vstack([model.G[0], model.G[1], -model.H0[0], -model.H1[0], -model.H0[1], -model.H1[1]]).T
    tt = np.arange(2 * steps + 1) * (dt / 2)          # half-step grid (quadratic hold)
    kL, kR, e, ed, f, A, B = _inputs(model, tt)
    Fe = np.zeros((tt.size, n2))
    Fe[:, n:] = f @ Minv.T
    ee = (e[0].tolist(), e[1].tolist())
    eed = (ed[0].tolist(), ed[1].tolist())
    AA = (A[0].tolist(), A[1].tolist())
    BB = (B[0].tolist(), B[1].tolist())
    mu = model.mu
    bt = model.backlash_at(tt)
    bb = bt.tolist()
    cm = (float(model.mesh_damping[0]), float(model.mesh_damping[1]))
    switches = 0
    t_setup = time.perf_counter()
    for j in range(min(per, steps)):         # propagators of the all-in-contact state, built up front
        if (j, (1, 1)) not in cache:
            cache[(j, (1, 1))] = _expo_matrices(model, kstep[j], (1, 1), dt)
    # fast path (both drive flanks in contact): the known inputs of every step, precomputed per phase
    known = np.empty((steps, n2))
    ecols = np.stack([e[0] + bt, e[1] + bt], axis=1)          # u_s = e_s + b(t) on the drive flank
    dcols = np.stack([cm[0] * ed[0], cm[1] * ed[1]], axis=1)
    Wfr = []
    for j in range(min(per, steps)):
        Phi, W0, Wh, W1, U = cache[(j, (1, 1))]
        idx = np.arange(j, steps, per)
        i0, ih, i1 = 2 * idx, 2 * idx + 1, 2 * idx + 2
        known[idx] = (Fe[i0] + dcols[i0] @ Bw[:, :2].T) @ W0.T + (Fe[ih] + dcols[ih] @ Bw[:, :2].T) @ Wh.T \
            + (Fe[i1] + dcols[i1] @ Bw[:, :2].T) @ W1.T \
            + np.concatenate([ecols[i0, :1], ecols[ih, :1], ecols[i1, :1], ecols[i0, 1:], ecols[ih, 1:], ecols[i1, 1:]],
                             axis=1) @ U.T
        Wfr.append(np.hstack([W0 @ Bw[:, 2:], Wh @ Bw[:, 2:], W1 @ Bw[:, 2:]]))   # (n2, 12): friction at 3 nodes
    setup = time.perf_counter() - t_setup

    rec = _record_plan(steps, dt, record_every, record_from)
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
        b = bb[i2]
        side = [0, 0]
        Nn = [0.0, 0.0]
        for s, (gq, gv) in enumerate(((gq0, gv0), (gq1, gv1))):
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
        chi = (int(side[0] != 0), int(side[1] != 0))
        key = (j, chi)
        mats = cache.get(key)
        if mats is None:
            mats = cache[key] = _expo_matrices(model, kj, chi, dt)
        Phi, W0, Wh, W1, U = mats
        # general path: known inputs at t_n, t_n+h/2, t_n+h: u_s = e_s ± b (through the sub-steps'
        # stiffness), c ė_s; friction: μ|N| extrapolated linearly from the last two steps, A and B at the nodes
        c0, c1 = chi[0] * cm[0], chi[1] * cm[1]
        F = []
        for o, w in ((0, 0.0), (1, 0.5), (2, 1.0)):
            ii = i2 + o
            a0 = Nn[0] + w * (Nn[0] - N_prev[0])
            a1 = Nn[1] + w * (Nn[1] - N_prev[1])
            F.append(Fe[ii] + Bw @ (c0 * eed[0][ii], c1 * eed[1][ii], a0 * AA[0][ii], a0 * BB[0][ii],
                                    a1 * AA[1][ii], a1 * BB[1][ii]))
        u = tuple(ee[s][i2 + o] + side[s] * bb[i2 + o] for s in range(2) for o in range(3))
        y = Phi @ y + W0 @ F[0] + Wh @ F[1] + W1 @ F[2] + U @ u
        N_prev = Nn
    seconds = time.perf_counter() - t0
    if not np.all(np.isfinite(out)):
        raise ConvergenceError("expo", "the solution became non-finite", {"dt": [dt]})
    return Simulation(model=model, method="expo", dt=dt, t=rec * dt, q=out[:, :n].copy(), v=out[:, n:].copy(),
                      seconds=seconds, steps=steps,
                      info={"contact_switches": switches, "steps_per_mesh_period": per, "cached_propagators": len(cache),
                            "setup_seconds": setup, "substeps": substeps})
