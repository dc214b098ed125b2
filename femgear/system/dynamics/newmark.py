"""Hilber–Hughes–Taylor α-method with exact Newton on the piecewise-linear gap.

Hilber, Hughes & Taylor, Earthquake Eng. Struct. Dyn. 5:283 (1977); α = 0 is Newmark's
average-acceleration rule (Newmark, J. Eng. Mech. Div. 85:67, 1959).  The mesh forces
are piecewise linear in the state once the contact state of each flank and the sign of
N_s are fixed, so Newton's method is exact in one solve per contact state; the solve
uses the constant factor J0⁻¹ of the linear part and a rank-2 (Woodbury) update for the
two meshes, i.e. only a 2×2 system per step.  A contact state that does not settle in
``max_iter`` trials raises :class:`femgear.errors.ConvergenceError`.
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.errors import ConvergenceError
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.simulation import Simulation, inputs, record_plan


def _hht_operators(model, dt: float, alpha: float):
    """Constant operators of the HHT-α step (linear part eliminated through J0 = cq M + (1+α)(K + cv C))."""
    n = model.n
    M, C, K, G = model.M, model.C, model.K, model.G
    gamma = 0.5 - alpha
    beta = 0.25 * (1 - alpha) ** 2
    h = dt
    ap = 1 + alpha
    cq = 1 / (beta * h * h)      # a_{n+1} = cq q_{n+1} + ã
    cv = gamma / (beta * h)      # v_{n+1} = cv q_{n+1} + ṽ
    J0inv = np.linalg.inv(cq * M + ap * (K + cv * C))
    # ã = −cq q_n − h cq v_n − (1/(2β) − 1) a_n ;  ṽ = −cv q_n + (1 − γ/β) v_n + h(1 − γ/(2β)) a_n
    Ta = np.hstack([-cq * np.eye(n), -h * cq * np.eye(n), -(1 / (2 * beta) - 1) * np.eye(n)])
    Tv = np.hstack([-cv * np.eye(n), (1 - gamma / beta) * np.eye(n), h * (1 - gamma / (2 * beta)) * np.eye(n)])
    # r0 = −M ã − ap C ṽ + α (C v_n + K q_n)   (forces added separately)
    Rz = -M @ Ta - ap * C @ Tv + alpha * np.hstack([K, C, np.zeros((n, n))])
    X = J0inv @ Rz
    return ap, cq, cv, J0inv, Ta, Tv, np.vstack([X, G @ X, G @ Tv])


def _hht_inputs(model, steps: int, dt: float, alpha: float, J0inv: np.ndarray):
    """Known inputs on the step grid: α-weighted external forces through J0⁻¹, stiffness, errors,
    friction tables and dead-zone half-widths (as lists for the scalar step loop)."""
    tt = np.arange(steps + 1) * dt
    kL, kR, e, ed, f, A, B = inputs(model, tt)
    ff = np.empty_like(f)
    ff[0] = f[0]
    ff[1:] = (1 + alpha) * f[1:] - alpha * f[:-1]
    xf = ff @ J0inv.T
    return (xf, xf @ model.G.T, (kL.tolist(), kR.tolist()), (e[0].tolist(), e[1].tolist()),
            (ed[0].tolist(), ed[1].tolist()), (A[0].tolist(), A[1].tolist()), (B[0].tolist(), B[1].tolist()),
            model.backlash_at(tt).tolist())


def newmark(model: GearRotorModel, steps: int, dt: float, q: np.ndarray, v: np.ndarray, *, record_every: int,
            record_from: float, alpha: float = 0.0, max_iter: int = 20) -> Simulation:
    """HHT-α (α ∈ [−1/3, 0]; 0: Newmark's average acceleration), exact Newton on the gap."""
    n = model.n
    G = model.G
    ap, cq, cv, J0inv, Ta, Tv, Big = _hht_operators(model, dt, alpha)
    PG = J0inv @ G.T               # (n, 2)
    P0 = J0inv @ model.H0.T
    P1 = J0inv @ model.H1.T
    GPG, GP0, GP1 = G @ PG, G @ P0, G @ P1   # (2, 2): [row r, column s]
    h, gamma, beta = dt, 0.5 - alpha, 0.25 * (1 - alpha) ** 2
    xf, Gxf, kk, ee, eed, AA, BB, bb = _hht_inputs(model, steps, dt, alpha, J0inv)
    mu, cm = model.mu, (float(model.mesh_damping[0]), float(model.mesh_damping[1]))

    # initial acceleration from the equations of motion
    a = model.acceleration(np.array(0.0), q, v)
    _, Nprev, _ = model.mesh_forces(np.array(0.0), q, v)
    Nprev = Nprev.tolist()
    PWprev = [PG[:, s] + mu * np.sign(Nprev[s]) * (AA[s][0] * P0[:, s] + BB[s][0] * P1[:, s]) for s in range(2)]
    z = np.concatenate([q, v, a])
    # contact state per flank: +1 drive contact, −1 back contact, 0 open;  sign of N
    state = [1, 1]
    sgn = [1.0, 1.0]
    rec = record_plan(steps, dt, record_every, record_from)
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
        b = (bb[0][j], bb[1][j])
        for it in range(max_iter):  # noqa: B007 — the count is reported after the loop
            iters_total += 1
            kap = [0.0, 0.0]
            n0 = [0.0, 0.0]
            for s in range(2):
                if state[s] != 0:
                    kap[s] = kk[s][j] + cm[s] * cv
                    n0[s] = -kk[s][j] * (ee[s][j] + state[s] * b[s]) + cm[s] * (gvt[s] - eed[s][j])
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
            new_state = [1 if d[s] > b[s] else (-1 if d[s] < -b[s] else 0) for s in range(2)]
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


