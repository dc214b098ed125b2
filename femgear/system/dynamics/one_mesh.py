"""Dynamics of one-mesh pairs (spur, single-helical): a 12-DOF lumped model and the torsional sweep.

The 24-DOF double-helical model (:mod:`femgear.system.dynamics.build`) is two meshes on four
half bodies; a spur or single-helical pair has ONE mesh in the mid-plane of two rigid
bodies.  Coordinates per member (pinion 0, gear 1): x, y, z, θx, θy, θz.  The mesh
deflection is the double-helical model's for one helix (:mod:`femgear.system.dynamics.mesh`,
Kang & Kahraman 2015), σ = +1:

    δ = [(x1−x2) sin α_wt + (y1−y2) cos α_wt + r_b1 θz1 + r_b2 θz2] cos β_b
        + [(z1−z2) − r_w1 θy1 − r_w2 θy2] sin β_b,        F = k(φ) f(δ) + c_m δ̇

with f the backlash dead zone of half-width b0.  A single helix puts the unbalanced
axial force F sin β_b on the thrust bearings (``axial_stiffness``, ``axial_damping``
per member) and its moment F sin β_b r_w on the tilt stiffness of the two radial bearings
(k_r s²/4, span s); a spur pair (β_b = 0) has no axial mesh force.

``simulate_one_mesh`` integrates the 12-DOF model (RK4, mesh phase φ = f_m t, backlash
dead zone, mesh damping only while in contact) from the static state.

``torsional_sweep`` reduces a spur pair to its dynamic transmission error
x = r_b1 θz1 + r_b2 θz2 (rigid supports): m_e ẍ + c ẋ + k(f_m t) f(x) = F_bn,
m_e = 1/(r_b1²/I1 + r_b2²/I2) — the oscillator of Kahraman & Singh (JSV 142:49, 1990),
here with the pair's own time-varying mesh stiffness as the excitation; slow up- and
down-sweeps of the mesh frequency follow different branches when the teeth separate
(the softening jump).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import eigh

from femgear.physics.geometry.gear import GearPair

NDOF = 12


@dataclass(frozen=True)
class MemberData:
    """Rigid member on two radial bearings and a thrust bearing (SI)."""

    mass: float
    inertia: float          #: polar moment of inertia I_p [kg m²]
    radial_stiffness: float  #: per direction x, y (both bearings) [N/m]
    axial_stiffness: float  #: [N/m]
    radial_damping: float = 0.0
    axial_damping: float = 0.0
    bearing_span: float = 0.1  #: distance of the two radial bearings [m]


@dataclass(frozen=True)
class OneMeshModel:
    """Matrices and mesh data of a one-mesh pair (12 DOF)."""

    pair: GearPair
    M: np.ndarray
    K: np.ndarray           #: supports only
    C: np.ndarray           #: supports only
    g: np.ndarray           #: mesh vector, δ = gᵀ q
    k_mesh: np.ndarray      #: mesh stiffness over one period (normal line of action) [N/m]
    c_mesh: float           #: mesh damping [N s/m]
    backlash: float         #: half-width of the dead zone b0 [m]
    load: np.ndarray        #: generalised static load (drive and brake torques) [N, N m]

    @property
    def k_mean(self) -> float:
        return float(np.mean(self.k_mesh))

    def mean_stiffness(self) -> np.ndarray:
        """K + k̄ g gᵀ (contact closed)."""
        return self.K + self.k_mean * np.outer(self.g, self.g)


def mesh_vector(pair: GearPair) -> np.ndarray:
    """g with δ = gᵀ q for q = (pinion x, y, z, θx, θy, θz, gear x, y, z, θx, θy, θz)."""
    a, cb, sb = pair.alpha_wt, math.cos(pair.beta_b), math.sin(pair.beta_b)
    g = np.zeros(NDOF)
    g[[0, 1, 5]] = math.sin(a) * cb, math.cos(a) * cb, pair.rb1 * cb
    g[[6, 7, 11]] = -math.sin(a) * cb, -math.cos(a) * cb, pair.rb2 * cb
    g[[2, 4]] = sb, -pair.rw1 * sb
    g[[8, 10]] = -sb, -pair.rw2 * sb
    return g


def build_one_mesh(pair: GearPair, members: tuple[MemberData, MemberData], k_mesh: np.ndarray,
                   pinion_torque: float, backlash: float = 0.0, mesh_damping_ratio: float = 0.07) -> OneMeshModel:
    """Assemble the 12-DOF model of a spur or single-helical ``pair`` (``k_mesh``: one period, N/m)."""
    if pair.n_helices != 1:
        raise ValueError("build_one_mesh models one mesh; a double-helical pair uses femgear.system.dynamics.build")
    k_mesh = np.atleast_1d(np.asarray(k_mesh, float))
    if not (np.all(k_mesh > 0) and np.all(np.isfinite(k_mesh))):
        raise ValueError("k_mesh must be positive and finite")
    if backlash < 0 or not 0 <= mesh_damping_ratio < 1:
        raise ValueError("backlash must be ≥ 0 and mesh_damping_ratio in [0, 1)")
    M, K, C = (np.zeros((NDOF, NDOF)) for _ in range(3))
    for i, mem in enumerate(members):
        if min(mem.mass, mem.inertia, mem.radial_stiffness, mem.axial_stiffness, mem.bearing_span) <= 0:
            raise ValueError(f"member {i}: mass, inertia, stiffnesses and bearing_span must be positive")
        o = 6 * i
        Id = mem.inertia / 2 + mem.mass * pair.b**2 / 12
        M[o:o + 6, o:o + 6] = np.diag([mem.mass] * 3 + [Id, Id, mem.inertia])
        tilt = mem.bearing_span**2 / 4
        K[o:o + 5, o:o + 5] = np.diag([mem.radial_stiffness] * 2 + [mem.axial_stiffness]
                                      + [mem.radial_stiffness * tilt] * 2)
        C[o:o + 5, o:o + 5] = np.diag([mem.radial_damping] * 2 + [mem.axial_damping] + [mem.radial_damping * tilt] * 2)
    g = mesh_vector(pair)
    m_eq = 1.0 / np.sum(g**2 / np.diag(M))
    load = np.zeros(NDOF)
    load[5], load[11] = pinion_torque, pinion_torque * pair.rb2 / pair.rb1
    return OneMeshModel(pair=pair, M=M, K=K, C=C, g=g, k_mesh=k_mesh,
                        c_mesh=2 * mesh_damping_ratio * math.sqrt(float(np.mean(k_mesh)) * m_eq),
                        backlash=float(backlash), load=load)


def natural_frequencies(model: OneMeshModel) -> np.ndarray:
    """Undamped natural frequencies of the mean closed-contact system, rigid rotation removed [Hz]."""
    w2 = eigh(model.mean_stiffness(), model.M, eigvals_only=True)
    w2 = w2[w2 > 1e-9 * w2.max()]
    return np.sqrt(w2) / (2 * math.pi)


def torsional_mode_hand(pair: GearPair, I1: float, I2: float, k_mean: float) -> float:
    """f = √(k̄ cos²β_b (r_b1²/I1 + r_b2²/I2)) / 2π: the mesh mode on rigid supports [Hz]."""
    return math.sqrt(k_mean * math.cos(pair.beta_b) ** 2 * (pair.rb1**2 / I1 + pair.rb2**2 / I2)) / (2 * math.pi)


def static_deflection(model: OneMeshModel) -> np.ndarray:
    """Static state under the torques with closed contact and mean stiffness (gear rotation fixed) [m, rad]."""
    keep = np.arange(NDOF) != 11
    K = model.mean_stiffness()
    # the dead zone shifts δ by b0: solve (K) q = load + k̄ b0 g
    rhs = model.load + model.k_mean * model.backlash * model.g
    q = np.zeros(NDOF)
    q[keep] = np.linalg.solve(K[np.ix_(keep, keep)], rhs[keep])
    return q


@dataclass(frozen=True)
class TorsionalSweep:
    """Dynamic transmission error of a one-mesh pair over a slow sweep of the mesh frequency."""

    mesh_frequency: np.ndarray   #: f_m in sweep order [Hz]
    amplitude: np.ndarray        #: half peak-to-peak of x over the measured periods [m]
    mean: np.ndarray             #: mean x [m]
    contact_loss: np.ndarray     #: fraction of the measured time with |x| ≤ b0 [-]
    direction: str
    static_deflection: float     #: F_bn/k̄ + b0 [m]
    natural_frequency: float     #: torsional mesh mode on rigid supports [Hz]


def _periods(fm, k, m_e, c, F, b0, x, v, cycles, measure, steps):
    """RK4 over ``cycles`` mesh periods of m_e ẍ + c ẋ + k(φ) f(x) = F; statistics of the last ``measure``."""
    n = k.size
    h = 1.0 / (fm * steps)
    xmin, xmax, total, loss, count = math.inf, -math.inf, 0.0, 0, 0
    inv_m = 1.0 / m_e

    def acc(t, x, v):
        p = (fm * t) % 1.0 * n
        i = int(p)
        kk = k[i] + (p - i) * (k[(i + 1) % n] - k[i])
        f = x - b0 if x > b0 else (x + b0 if x < -b0 else 0.0)
        return (F - c * v - kk * f) * inv_m

    t = 0.0
    for step in range(cycles * steps):
        a1 = acc(t, x, v)
        a2 = acc(t + 0.5 * h, x + 0.5 * h * v, v + 0.5 * h * a1)
        a3 = acc(t + 0.5 * h, x + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2)
        a4 = acc(t + h, x + h * (v + 0.5 * h * a2), v + h * a3)
        x, v = x + h * (v + h / 6 * (a1 + a2 + a3)), v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
        t += h
        if step >= (cycles - measure) * steps:
            xmin, xmax, total, count = min(xmin, x), max(xmax, x), total + x, count + 1
            loss += abs(x) <= b0
    return x, v, 0.5 * (xmax - xmin), total / count, loss / count


def torsional_sweep(pair: GearPair, k_mesh: np.ndarray, I1: float, I2: float, pinion_torque: float,
                    mesh_frequencies: np.ndarray, backlash: float, damping_ratio: float = 0.05,
                    direction: str = "up", cycles: int = 60, measure: int = 15,
                    steps_per_period: int = 64) -> TorsionalSweep:
    """Sweep the mesh frequency up or down, continuing the state from one frequency to the next."""
    if pair.beta_b != 0:
        raise ValueError("torsional_sweep reduces a spur pair (β_b = 0) to its transmission error")
    if direction not in ("up", "down"):
        raise ValueError(f"direction must be 'up' or 'down', got {direction!r}")
    if not (I1 > 0 and I2 > 0 and pinion_torque > 0 and backlash >= 0 and 0 <= damping_ratio < 1):
        raise ValueError("I1, I2, pinion_torque must be positive, backlash ≥ 0, damping_ratio in [0, 1)")
    k = np.asarray(k_mesh, float)
    fms = np.sort(np.asarray(mesh_frequencies, float))
    fms = fms[::-1] if direction == "down" else fms
    m_e = 1.0 / (pair.rb1**2 / I1 + pair.rb2**2 / I2)
    k_mean = float(k.mean())
    c = 2 * damping_ratio * math.sqrt(k_mean * m_e)
    F = pinion_torque / pair.rb1
    x, v = F / k_mean + backlash, 0.0
    out = np.empty((3, fms.size))
    for i, fm in enumerate(fms):
        x, v, *stats = _periods(fm, k, m_e, c, F, backlash, x, v, cycles, measure, steps_per_period)
        if not (math.isfinite(x) and math.isfinite(v)):
            raise FloatingPointError(f"torsional sweep diverged at f_m = {fm:.6g} Hz (steps_per_period too small?)")
        out[:, i] = stats
    return TorsionalSweep(mesh_frequency=fms, amplitude=out[0], mean=out[1], contact_loss=out[2], direction=direction,
                          static_deflection=F / k_mean + backlash,
                          natural_frequency=torsional_mode_hand(pair, I1, I2, k_mean))


@dataclass(frozen=True)
class OneMeshResponse:
    """Time response of a :class:`OneMeshModel` over the recorded mesh periods."""

    t: np.ndarray            #: [s]
    q: np.ndarray            #: states (time, 12) [m, rad]
    mesh_force: np.ndarray   #: F(t) along the normal line of action [N]
    deflection: np.ndarray   #: δ(t) = gᵀ q [m]
    contact_loss: float      #: fraction of the recorded time with |δ| ≤ b0 [-]

    def axial(self, member: int) -> np.ndarray:
        """Axial displacement z of the pinion (0) or gear (1) [m]."""
        return self.q[:, 6 * member + 2]


def simulate_one_mesh(model: OneMeshModel, mesh_frequency: float, periods: int = 100, record: int = 20,
                      steps_per_period: int = 100) -> OneMeshResponse:
    """RK4 from the static state, mesh phase φ = f_m t; records the last ``record`` periods.

    The step is refused if it exceeds RK4's stability limit 2.78/ω_max of the mean system.
    """
    if not (mesh_frequency > 0 and 0 < record <= periods and steps_per_period >= 10):
        raise ValueError("mesh_frequency > 0, 0 < record ≤ periods and steps_per_period ≥ 10 are required")
    h = 1.0 / (mesh_frequency * steps_per_period)
    w_max = 2 * math.pi * float(natural_frequencies(model).max())
    if h * w_max > 2.78:
        raise ValueError(f"step {h:.3g} s exceeds RK4's stability limit {2.78 / w_max:.3g} s: "
                         f"raise steps_per_period to ≥ {math.ceil(steps_per_period * h * w_max / 2.78)}")
    Minv = 1.0 / np.diag(model.M)
    g, K, C, load, b0, c_m = model.g, model.K, model.C, model.load, model.backlash, model.c_mesh
    k, n = model.k_mesh, model.k_mesh.size

    def force(t, q, v):
        p = (mesh_frequency * t) % 1.0 * n
        i = int(p)
        kk = k[i] + (p - i) * (k[(i + 1) % n] - k[i])
        d = g @ q
        f = d - b0 if d > b0 else (d + b0 if d < -b0 else 0.0)
        return kk * f + c_m * (g @ v) * (abs(d) > b0)

    def acc(t, q, v):
        return Minv * (load - K @ q - C @ v - g * force(t, q, v))

    q, v = static_deflection(model), np.zeros(NDOF)
    n_rec, start = record * steps_per_period, (periods - record) * steps_per_period
    ts, qs, fs = np.empty(n_rec), np.empty((n_rec, NDOF)), np.empty(n_rec)
    t = 0.0
    for step in range(periods * steps_per_period):
        a1 = acc(t, q, v)
        a2 = acc(t + h / 2, q + h / 2 * v, v + h / 2 * a1)
        a3 = acc(t + h / 2, q + h / 2 * (v + h / 2 * a1), v + h / 2 * a2)
        a4 = acc(t + h, q + h * (v + h / 2 * a2), v + h * a3)
        q, v = q + h * (v + h / 6 * (a1 + a2 + a3)), v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
        t += h
        if step >= start:
            j = step - start
            ts[j], qs[j], fs[j] = t, q, force(t, q, v)
    if not np.all(np.isfinite(qs)):
        raise FloatingPointError("one-mesh simulation produced non-finite states")
    d = qs @ g
    return OneMeshResponse(t=ts, q=qs, mesh_force=fs, deflection=d, contact_loss=float(np.mean(np.abs(d) <= b0)))


def one_mesh_from_case(case, k_mesh: np.ndarray | None = None) -> OneMeshModel:
    """The 12-DOF model of a spur or single-helical :class:`femgear.case.Case`.

    Members: ``mass``, ``inertia``, ``support_stiffness``/``support_damping`` (radial, per
    direction), ``axial_stiffness``/``axial_damping`` (default the radial values; required
    by the scene for a single helix), ``bearing_span``; ``pair.backlash``,
    ``stiffness.damping_ratio``; ``k_mesh`` defaults to the scene's stiffness level.
    """
    if k_mesh is None:
        from femgear.levels import stiffness as stiffness_levels

        k_mesh = stiffness_levels.of(case).k_left
    members = tuple(
        MemberData(mass=m.mass, inertia=m.inertia, radial_stiffness=m.support_stiffness,
                   axial_stiffness=m.support_stiffness if m.axial_stiffness is None else m.axial_stiffness,
                   radial_damping=m.support_damping,
                   axial_damping=m.support_damping if m.axial_damping is None else m.axial_damping,
                   bearing_span=m.bearing_span)
        for m in case.members)
    return build_one_mesh(case.pair, members, k_mesh, case.operating.pinion_torque, backlash=case.backlash,
                          mesh_damping_ratio=case.stiffness.damping_ratio)


def simulate_case(case, k_mesh: np.ndarray | None = None) -> OneMeshResponse:
    """:func:`simulate_one_mesh` at the case's mesh frequency with its ``[numerics]`` cycles and step."""
    n = case.numerics
    periods = max(int(math.ceil(n.dynamics_cycles)), 2)
    record = max(periods - int(n.transient_cycles), 1)
    return simulate_one_mesh(one_mesh_from_case(case, k_mesh), case.operating.mesh_frequency, periods=periods,
                             record=record, steps_per_period=n.steps_per_mesh_period)
