"""Fixed-step classical RK4 (the paper's integrator) and its stability limit.

The step must lie inside RK4's stability region for the stiffest linearised state
(:func:`stability_limit`); :func:`femgear.system.dynamics.integrate.simulate` refuses a larger
one.  All time-dependent inputs (k(t), e(t), ė(t), b(t), f(t), friction factors) are
evaluated vectorised on the half-step grid before the loop; one stage is one dense
mat-vec of the linear part plus the two mesh forces.
"""

from __future__ import annotations

import time

import numpy as np

from femgear.errors import ConvergenceError
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.simulation import Simulation, inputs, record_plan


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


def rk4(model: GearRotorModel, steps: int, dt: float, q: np.ndarray, v: np.ndarray, record_every: int,
        record_from: float, known: tuple[np.ndarray, ...] | None = None) -> Simulation:
    """RK4 over ``steps`` steps from (q, v); ``known``: the inputs (k_L, k_R, e, ė, f, A, B, b̄) on the half-step
    grid (2 steps + 1 times) when the caller prescribes them (a speed ramp, :mod:`femgear.system.dynamics.runup`),
    else :func:`~femgear.system.dynamics.simulation.inputs` of the model."""
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
    if known is None:
        kL, kR, e, ed, f, A, B = inputs(model, th)
        bb = model.backlash_at(th)
    else:
        kL, kR, e, ed, f, A, B, bb = known
    F = np.zeros((th.size, 2 * n))
    F[:, n:] = f @ Minv.T
    kL, kR = kL.tolist(), kR.tolist()
    e0, e1, ed0, ed1 = e[0].tolist(), e[1].tolist(), ed[0].tolist(), ed[1].tolist()
    mu = model.mu
    A0, A1, B0, B1 = A[0].tolist(), A[1].tolist(), B[0].tolist(), B[1].tolist()
    bb0, bb1 = bb.tolist()
    c0, c1 = float(model.mesh_damping[0]), float(model.mesh_damping[1])
    n2 = 2 * n

    def stage(y, j):
        r = R @ y
        d0, d1, dd0, dd1 = r[n2:].tolist()
        d0 -= e0[j]
        d1 -= e1[j]
        b = bb0[j]
        if d0 > b:
            N0 = kL[j] * (d0 - b) + c0 * (dd0 - ed0[j])
        elif d0 < -b:
            N0 = kL[j] * (d0 + b) + c0 * (dd0 - ed0[j])
        else:
            N0 = 0.0
        b = bb1[j]
        if d1 > b:
            N1 = kR[j] * (d1 - b) + c1 * (dd1 - ed1[j])
        elif d1 < -b:
            N1 = kR[j] * (d1 + b) + c1 * (dd1 - ed1[j])
        else:
            N1 = 0.0
        a0 = mu * abs(N0)
        a1 = mu * abs(N1)
        return r[:n2] + W @ (N0, N1, a0 * A0[j], a0 * B0[j], a1 * A1[j], a1 * B1[j]) + F[j]

    rec = record_plan(steps, dt, record_every, record_from)
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


