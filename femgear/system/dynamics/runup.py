"""Run-up: a speed ramp in the time domain, and order tracking by resampling to shaft angle.

The driver speed rises linearly from ``rpm0`` to ``rpm1`` over ``duration`` seconds, after the
state has settled for ``settle_cycles`` mesh periods at ``rpm0``.  Everything the speed sets in
the model is a function of the shaft angle or of the speed itself, so the ramp is the model of a
reference speed read at the angle-equivalent time τ(t) = ∫ s dt, s = n(t)/n_ref:

- mesh stiffness, backlash and flank deviations at the mesh phase f_m,ref τ = z₁ θ₁ / 2π;
- transmission errors (eccentricity, profile and pitch errors) at τ, their rates × s;
- unbalance forces × s²;
- the friction tables and the load torque that absorbs the mean friction power: the speed sets the
  sliding signs and the lubrication level's μ, so the models of a grid of speeds (1 % apart,
  :class:`~femgear.system.dynamics.family.SpeedFamily`) are interpolated linearly in speed;
- the nominal angular acceleration α_i of each member: d'Alembert torques −I_i α_i on its halves,
  with the driving member's torque raised by the power Σ I_i α_i Ω_i / Ω_drive that accelerates the
  train (the load torque stays; the rigid rotation gets no net torque).

Integration: fixed-step RK4 (:func:`femgear.system.dynamics.rk4.rk4` with these inputs prescribed,
in chunks so that long runs report progress), at the smaller of the default RK4 steps of the two
end speeds (:func:`femgear.system.dynamics.run.default_step`).

Order tracking (:func:`order_track`): a signal sampled in time is resampled (cubic spline) onto
a uniform grid of the pinion angle; blocks of ``revolutions`` revolutions (50 % overlap, Hanning
window, amplitude-corrected) give the amplitude of every pinion order o (resolution
1/``revolutions``) at the block's mean speed — the waterfall; the mesh orders k are the pinion
orders k z₁, read at their exact bins — the order cuts.  Resampling to angle keeps a tracked order
on one bin while the frequency sweeps, which a fixed-time FFT would smear.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.excitation import contact_indicator, gap_function
from femgear.system.dynamics.bearings import bearing_forces
from femgear.system.dynamics.family import SpeedFamily
from femgear.system.dynamics.model import GearRotorModel

#: relative speed step of the grid of models whose friction tables the ramp interpolates
SPEED_GRID_STEP = 0.01
#: recorded samples per mesh period at the top speed (at least; and 8 per period of the highest mode the mesh
#: reaches, as the steady runs read it: the order tracking resamples the record, which must carry the response's
#: content without aliasing)
RECORD_PER_MESH_PERIOD = 32
#: steps per progress chunk (at most)
CHUNK_STEPS = 20000

Progress = Callable[[float], None]
"""Called with the fraction of the run done (0 … 1)."""


@dataclass(frozen=True)
class Ramp:
    """A linear ramp of the driver speed from ``rpm0`` to ``rpm1`` [rpm] over ``duration`` [s], after
    ``settle_cycles`` mesh periods at ``rpm0``."""

    rpm0: float
    rpm1: float
    duration: float
    settle_cycles: float = 50.0

    def __post_init__(self):
        if not (math.isfinite(self.rpm0) and math.isfinite(self.rpm1) and 0 < self.rpm0 < self.rpm1):
            raise ValueError(f"a run-up needs 0 < rpm0 < rpm1 (got {self.rpm0!r}, {self.rpm1!r})")
        if not (math.isfinite(self.duration) and self.duration > 0):
            raise ValueError(f"duration must be positive (got {self.duration!r})")
        if not self.settle_cycles >= 0:
            raise ValueError(f"settle_cycles must be ≥ 0 (got {self.settle_cycles!r})")

    def settle_time(self, mesh_frequency0: float) -> float:
        return self.settle_cycles / mesh_frequency0

    def speed(self, t: np.ndarray, t_settle: float) -> np.ndarray:
        """Driver speed at times ``t`` [rpm] (constant during the settling time ``t_settle``)."""
        tau = np.clip(np.asarray(t, dtype=float) - t_settle, 0.0, self.duration)
        return self.rpm0 + (self.rpm1 - self.rpm0) * tau / self.duration

    def revolutions(self, t: np.ndarray, t_settle: float) -> np.ndarray:
        """Driver revolutions turned since t = 0 at times ``t`` [-] (the ramp's integral)."""
        t = np.asarray(t, dtype=float)
        tau = np.clip(t - t_settle, 0.0, self.duration)
        ramp = self.rpm0 * tau + 0.5 * (self.rpm1 - self.rpm0) * tau**2 / self.duration
        after = np.maximum(t - t_settle - self.duration, 0.0) * self.rpm1
        return (self.rpm0 * np.minimum(t, t_settle) + ramp + after) / 60.0


def speed_grid(rpm0: float, rpm1: float, step: float = SPEED_GRID_STEP) -> np.ndarray:
    """Speeds from ``rpm0`` to ``rpm1`` [rpm], geometrically spaced at most ``step`` apart (relative)."""
    n = max(2, math.ceil(math.log(rpm1 / rpm0) / math.log1p(step)) + 1)
    return np.geomspace(rpm0, rpm1, n)


class RampInputs:
    """The prescribed inputs of the ramp (k_L, k_R, e, ė, f, A, B, b̄) at any times, from the models of a speed
    grid (module docstring)."""

    def __init__(self, family: SpeedFamily, ramp: Ramp):
        self.ramp = ramp
        self.grid = speed_grid(ramp.rpm0, ramp.rpm1)
        self.models = [family.at(r) for r in self.grid]
        self.ref = self.models[-1]
        self.t_settle = ramp.settle_time(self.models[0].mesh_frequency)
        case = family.case
        self._inertia = np.array([m.inertia for m in case.members])
        self._driver = 0 if case.operating.driver == "pinion" else 1
        self._torque = np.array([m.torque_full for m in self.models])

    @property
    def end_time(self) -> float:
        return self.t_settle + self.ramp.duration

    def _weights(self, rpm: np.ndarray):
        i = np.clip(np.searchsorted(self.grid, rpm, side="right") - 1, 0, self.grid.size - 2)
        w = np.clip((rpm - self.grid[i]) / (self.grid[i + 1] - self.grid[i]), 0.0, 1.0)
        return i, w

    def _friction(self, phase: np.ndarray, i: np.ndarray, w: np.ndarray):
        A, B = np.zeros((2,) + phase.shape), np.zeros((2,) + phase.shape)
        if self.ref.friction is None:
            return A, B
        for j in np.unique(i):
            sel = i == j
            a0, b0 = self.models[j].friction(phase[sel])
            a1, b1 = self.models[j + 1].friction(phase[sel])
            A[:, sel] = (1 - w[sel]) * a0 + w[sel] * a1
            B[:, sel] = (1 - w[sel]) * b0 + w[sel] * b1
        return A, B

    def angular_acceleration(self, t: np.ndarray) -> np.ndarray:
        """(t.shape, 2) nominal angular acceleration of pinion and gear (signed like their speeds) [rad/s²]."""
        on = (t > self.t_settle) & (t < self.end_time)
        sdot = (self.ramp.rpm1 - self.ramp.rpm0) / (self.ramp.duration * self.grid[-1])
        return np.where(on[..., None], sdot * np.array(self.ref.omega), 0.0)

    def __call__(self, t: np.ndarray):
        t = np.asarray(t, dtype=float)
        ref, rpm_ref = self.ref, self.grid[-1]
        rpm = self.ramp.speed(t, self.t_settle)
        s = rpm / rpm_ref
        tau = self.ramp.revolutions(t, self.t_settle) * 60.0 / rpm_ref    # the angle-equivalent time of ref
        kL, kR = ref.stiffness(ref.mesh_phase(tau))
        e, ed = ref.errors(tau)
        i, w = self._weights(rpm)
        A, B = self._friction(ref.mesh_phase(tau), i, w)
        torque = (1 - w)[:, None] * self._torque[i] + w[:, None] * self._torque[i + 1]
        alpha = self.angular_acceleration(t)
        omega = np.array(ref.omega)
        drive = (alpha * self._inertia * omega).sum(axis=-1) / omega[self._driver]
        for member in range(2):
            for side in range(2):
                d = 6 * (2 * member + side) + 5
                torque[:, d] += 0.5 * (-self._inertia[member] * alpha[:, member] + (member == self._driver) * drive)
        unbalance = ref.external_force(tau) - ref.torque_full @ ref.T
        f = torque @ ref.T + s[:, None] ** 2 * unbalance
        return kL, kR, e, ed * s, f, A, B, ref.backlash_at(tau)


def ramp_mesh_forces(model: GearRotorModel, known, q: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(δ, N) (n_t, 2) of recorded states under the prescribed inputs ``known`` at the same times [m, N]."""
    kL, kR, e, ed, _, _, _, bb = known
    delta = q @ model.G.T - e.T
    chi = contact_indicator(delta, bb.T)
    N = np.stack([kL, kR], axis=-1) * gap_function(delta, bb.T) + model.mesh_damping * chi * (v @ model.G.T - ed.T)
    return delta, N


@document_fields
@dataclass(frozen=True)
class RunUp:
    """The recorded time history of a run-up."""

    t: np.ndarray
    """recorded times from the start of the settling phase [s]"""
    speed: np.ndarray
    """driver speed at ``t`` [rpm]"""
    pinion_revolutions: np.ndarray
    """pinion revolutions turned since t = 0 [-]"""
    mesh_force: np.ndarray
    """(n_t, 2) dynamic mesh force of the left and right helix [N]"""
    dte: np.ndarray
    """dynamic transmission error, the mean of the helices' deflections δ_L, δ_R [m]"""
    bearing_force: np.ndarray
    """(n_t, 4, 3) bearing-station loads (pinion-L/R, gear-L/R; x, y, z), the force of the shaft on the bearing [N]"""
    settle_time: float
    """end of the settling phase at the start speed; the ramp follows [s]"""
    ramp_end: float
    """end of the ramp [s]"""
    teeth: int
    """pinion teeth z₁: the mesh order k is the pinion order k z₁ [-]"""
    dt: float
    """integration step (RK4) [s]"""
    steps: int
    """steps integrated [-]"""
    seconds: float
    """wall time of the integration [s]"""


def simulate_runup(family: SpeedFamily, ramp: Ramp, *, progress: Progress | None = None) -> RunUp:
    """Integrate the ramp (module docstring) from the static state at ``ramp.rpm0``."""
    import time

    from femgear.system.dynamics.modal import mesh_mode_limit
    from femgear.system.dynamics.rk4 import rk4
    from femgear.system.dynamics.run import STEPS_PER_MODE_PERIOD, default_step

    inputs = RampInputs(family, ramp)
    lo, hi = inputs.models[0], inputs.ref
    dt = min(default_step(m, "rk4") for m in (lo, hi))
    f_r = mesh_mode_limit(hi)
    reading = min(hi.mesh_period / RECORD_PER_MESH_PERIOD, 1 / (STEPS_PER_MODE_PERIOD * f_r) if f_r > 0 else math.inf)
    every = max(1, math.floor(reading / dt * (1 + 1e-9)))
    total = math.ceil(inputs.end_time / dt)
    chunk = max(every, (CHUNK_STEPS // every) * every)
    q, v = lo.static_state(), np.zeros(lo.n)
    ts, qs, vs, done, seconds = [], [], [], 0, 0.0
    t0 = time.perf_counter()
    while done < total:
        steps = min(chunk, total - done)
        th = (2 * done + np.arange(2 * steps + 1)) * (dt / 2)
        sim = rk4(hi, steps, dt, q, v, every, 0.0, known=inputs(th))
        first = 0 if not ts else 1
        ts.append(sim.t[first:] + done * dt)
        qs.append(sim.q[first:])
        vs.append(sim.v[first:])
        q, v = _end_state(hi, sim, steps, dt, every, inputs, done)
        done += steps
        seconds += sim.seconds
        if progress is not None:
            progress(done / total)
    t, q_rec, v_rec = np.concatenate(ts), np.concatenate(qs), np.concatenate(vs)
    _, N = ramp_mesh_forces(hi, inputs(t), q_rec, v_rec)
    delta = q_rec @ hi.G.T - inputs(t)[2].T
    ratio = abs(hi.omega[0]) * 60 / (2 * math.pi) / inputs.grid[-1]        # pinion revolutions per driver revolution
    return RunUp(t=t, speed=ramp.speed(t, inputs.t_settle), pinion_revolutions=ratio * ramp.revolutions(t, inputs.t_settle),
                 mesh_force=N, dte=delta.mean(axis=1), bearing_force=bearing_forces(hi, q_rec, v_rec),
                 settle_time=inputs.t_settle, ramp_end=inputs.end_time, teeth=int(hi.pair.z1), dt=dt, steps=total,
                 seconds=time.perf_counter() - t0)


def _end_state(model, sim, steps, dt, every, inputs, done):
    """The state after ``steps`` steps: the last record when it falls there, else one more short RK4 call."""
    if steps % every == 0:
        return sim.q[-1], sim.v[-1]
    from femgear.system.dynamics.rk4 import rk4

    rest = steps - (steps // every) * every
    th = (2 * (done + steps - rest) + np.arange(2 * rest + 1)) * (dt / 2)
    end = rk4(model, rest, dt, sim.q[-1], sim.v[-1], rest, 0.0, known=inputs(th))
    return end.q[-1], end.v[-1]



@document_fields
@dataclass(frozen=True)
class OrderMap:
    """Order spectra of a signal over a run-up: the waterfall and the mesh-order cuts."""

    orders: np.ndarray
    """pinion orders of the spectrum bins (resolution 1/``revolutions``) [-]"""
    speed: np.ndarray
    """driver speed at the centre of each block [rpm]"""
    amplitude: np.ndarray
    """(blocks, orders, …) single-sided amplitude of each pinion order per block (Hanning, amplitude-corrected)
    [unit of the signal]"""
    mesh_orders: np.ndarray
    """the mesh orders k of the cuts [-]"""
    cuts: np.ndarray
    """(blocks, mesh orders, …) amplitude of the mesh order k = pinion order k z₁ per block [unit of the signal]"""
    revolutions: int
    """pinion revolutions per block [-]"""


def order_track(run: RunUp, signal: np.ndarray, *, revolutions: int = 4, samples_per_rev: int | None = None,
                mesh_orders: int = 4, max_order: float | None = None) -> OrderMap:
    """The order spectra of ``signal`` (n_t, …) of ``run`` over its ramp (module docstring).

    ``revolutions``: pinion revolutions per block (50 % overlap); ``samples_per_rev``: the angle grid (default: the
    record's densest sampling in angle, at the start speed, so that the resampling never decimates and folds the
    response's high orders onto the tracked ones; at least 16 samples per tooth); ``max_order``: the highest
    pinion order kept (default (``mesh_orders`` + 0.5) z₁).
    """
    from scipy.interpolate import CubicSpline

    if revolutions < 1:
        raise ValueError(f"revolutions must be ≥ 1 (got {revolutions!r})")
    z1 = run.teeth
    on = (run.t >= run.settle_time - 1e-12) & (run.t <= run.ramp_end + 1e-12)
    rev = run.pinion_revolutions[on]
    spr = samples_per_rev or max(16 * z1, math.ceil(1.0 / float(np.diff(rev).min())))
    x = np.asarray(signal, dtype=float)[on]
    n_blocks = math.floor(2 * (rev[-1] - rev[0]) / revolutions) - 1
    if n_blocks < 1:
        raise ValueError(f"the ramp turns the pinion {rev[-1] - rev[0]:.3g} revolutions: fewer than one block of "
                         f"{revolutions}; lengthen the ramp or shorten the blocks")
    spline = CubicSpline(rev, x, axis=0)
    width = revolutions * spr
    window = np.hanning(width)
    order = np.fft.rfftfreq(width, 1.0 / spr)
    top = (mesh_orders + 0.5) * z1 if max_order is None else max_order
    keep = order <= top
    starts = rev[0] + 0.5 * revolutions * np.arange(n_blocks)
    amps, speeds = [], []
    for r0 in starts:
        grid = r0 + np.arange(width) / spr
        block = spline(grid)
        block = block - block.mean(axis=0)
        X = np.fft.rfft(block * window.reshape((-1,) + (1,) * (block.ndim - 1)), axis=0)
        amps.append(2 * np.abs(X[keep]) / window.sum())
        speeds.append(float(np.interp(r0 + 0.5 * revolutions, rev, run.speed[on])))
    amp = np.array(amps)
    k = np.arange(1, mesh_orders + 1)
    bins = np.rint(k * z1 * revolutions).astype(int)
    return OrderMap(orders=order[keep], speed=np.array(speeds), amplitude=amp, mesh_orders=k.astype(float),
                    cuts=amp[:, bins], revolutions=int(revolutions))
