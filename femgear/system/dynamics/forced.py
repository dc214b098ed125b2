"""Linear forced response per mesh order over speed: the gear-rotor model linearised about its mean mesh.

The mesh law N_s = k_s(φ) (G_s q − d_s(φ)) + c_s (G_s q̇ − ẋ_s) (drive flanks in contact; d_s the drive-flank
threshold: backlash, flank deviation, mesh-order profile error x_s) is replaced by the time-invariant
N_s = k̄_s (G_s q − ε_s(φ)) + c_s (G_s q̇ − ẋ_s), with ε_s the *effective transmission error* that makes the two
laws agree at every phase in the quasi-static limit:

    ε_s(φ) = G_s q_qs(φ) − N_qs,s(φ) / k̄_s,

q_qs(φ) the static equilibrium under the torques with the stiffness k_s(φ) of that phase
(:func:`mesh_excitation`).  Its mesh orders drive the linear system (:func:`order_response`):

    [K̄ + iω (C + Σ c_s G_sᵀ G_s) − ω² M] Q_k = Σ_s G_sᵀ (k̄_s E_s,k + iω c_s X_s,k),    ω = 2π k f_m,

E_s,k, X_s,k the complex amplitudes of order k of ε_s and x_s.  This is the stiffness-variation and TE excitation
of the standard NVH workflow (the harmonic response per order of a linearised model about the loaded static
state); it leaves out the parametric coupling between orders (small where the stiffness ripple is small: the
baseline's two-helix ripple is ±2.4 %), friction, contact loss, and the shaft-order sources (eccentricity,
random pitch errors, unbalance), none of which is at a mesh order.  ``tests/housing/test_forced.py`` checks
it against the time integration.

The result (:class:`OrderResponse`: the complex state amplitudes Q (speeds, orders, n)) is the interface of every
frequency-domain output: the bearing forces F = (K_F + iω C_F) Q, the mesh forces, and the housing's sensors and
surface (:mod:`femgear.system.dynamics.nvh`).  Any solver that delivers the harmonics of the state per order
(a harmonic-balance solution, the line fit of a time record) can feed the same outputs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.system.dynamics.bearings import force_matrices
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.orders import ORDERS

#: mesh phases per period of the quasi-static excitation (the tables are band-limited well below its Nyquist order)
EXCITATION_PHASES = 512


@document_fields
@dataclass(frozen=True)
class MeshExcitation:
    """The effective transmission error of the linearised mesh over one mesh period."""

    phase: np.ndarray
    """mesh phases φ ∈ [0, 1) [-]"""
    effective: np.ndarray
    """(2, n_phase) ε_s(φ) of the left and right helix (module docstring) [m]"""
    explicit: np.ndarray
    """(2, n_phase) the geometric part x_s(φ) (profile error and the flank deviation's shift) [m]"""
    quasi_static_force: np.ndarray
    """(2, n_phase) quasi-static mesh force N_qs,s(φ) [N]"""
    contact: bool
    """True when every quasi-static mesh force is positive (the drive flanks stay in contact, the linearisation
    holds) [-]"""

    def harmonics(self, orders: int) -> tuple[np.ndarray, np.ndarray]:
        """(E, X): (orders, 2) complex amplitudes of mesh orders 1 … ``orders`` of ``effective`` and ``explicit``
        (x(φ) = x̄ + Re Σ_k X_k e^{2πikφ}) [m]."""
        n = self.phase.size
        if not 2 * orders < n:
            raise ValueError(f"{orders} mesh orders need more than {2 * orders} phases (have {n})")

        def amp(x):
            return (2.0 / n * np.fft.rfft(x, axis=-1)[:, 1:orders + 1]).T
        return amp(self.effective), amp(self.explicit)


def mesh_excitation(model: GearRotorModel, n_phase: int = EXCITATION_PHASES) -> MeshExcitation:
    """The quasi-static excitation of ``model`` over one mesh period (module docstring)."""
    ph = np.arange(n_phase) / n_phase
    t = ph / model.mesh_frequency
    k = np.stack(model.stiffness(ph))                                        # (2, n_phase)
    x = np.stack([model.profile_errors[s].value(t) for s in range(2)])
    b = np.full((2, n_phase), model.backlash)
    if model.deviation is not None:
        from femgear.system.dynamics.mesh import periodic_interp

        for s in range(2):
            x[s] += periodic_interp(model.deviation.shift[s], ph)
            b[s] += periodic_interp(model.deviation.opening[s], ph)
    d = x + b
    f0 = model.torque_full @ model.T
    kbar = np.array(model.stiffness.mean)
    N = np.zeros((2, n_phase))
    eps = np.zeros((2, n_phase))
    for p in range(n_phase):
        Kp = model.K + sum(k[s, p] * np.outer(model.G[s], model.G[s]) for s in range(2))
        q, *_ = np.linalg.lstsq(Kp, f0 + (k[:, p] * d[:, p]) @ model.G, rcond=None)
        gq = model.G @ q
        N[:, p] = k[:, p] * (gq - d[:, p])
        with np.errstate(divide="ignore", invalid="ignore"):
            eps[:, p] = np.where(kbar > 0, gq - N[:, p] / np.where(kbar > 0, kbar, 1.0), 0.0)
    loaded = kbar > 0
    return MeshExcitation(phase=ph, effective=eps, explicit=x, quasi_static_force=N,
                          contact=bool(np.all(N[loaded] > 0)))


@document_fields
@dataclass(frozen=True)
class OrderResponse:
    """Complex amplitudes per speed and mesh order of the linearised model's steady response."""

    speeds: np.ndarray
    """(n_speed,) pinion speeds [rev/min]"""
    orders: np.ndarray
    """(n_order,) the mesh orders 1, 2, … [-]"""
    frequency: np.ndarray
    """(n_speed, n_order) frequency of each order line k z₁ n/60 [Hz]"""
    state: np.ndarray
    """(n_speed, n_order, n) complex amplitude Q of the model's coordinates (x = Re Q e^{iωt}) [m, rad]"""
    mesh_force: np.ndarray
    """(n_speed, n_order, 2) complex amplitude of the dynamic mesh force of the left and right helix [N]"""
    bearing_force: np.ndarray
    """(n_speed, n_order, 4, 3) complex amplitude of the load of each bearing station along x, y, z [N]"""
    contact: bool
    """the quasi-static mesh forces stay positive: the linearisation about the loaded mesh holds [-]"""


def dynamic_stiffness(model: GearRotorModel, omega: float) -> np.ndarray:
    """Z(ω) = K̄ + iω (C + Σ c_s G_sᵀ G_s) − ω² M of the mean mesh (flanks in contact) [N/m]."""
    C = model.C + sum(c * np.outer(model.G[s], model.G[s]) for s, c in enumerate(model.mesh_damping))
    return model.mean_stiffness_matrix() + 1j * omega * C - omega**2 * model.M


def mesh_forcing(model: GearRotorModel, omega: float, E: np.ndarray, X: np.ndarray) -> np.ndarray:
    """The generalised force Σ_s G_sᵀ (k̄_s E_s + iω c_s X_s) of one order (E, X: (2,) complex) [N]."""
    kbar = np.array(model.stiffness.mean)
    return (kbar * E + 1j * omega * model.mesh_damping * X) @ model.G


def order_response(model: GearRotorModel, speeds: np.ndarray, orders: int = ORDERS,
                   excitation: MeshExcitation | None = None) -> OrderResponse:
    """The linear response of ``model`` per mesh order 1 … ``orders`` at the pinion ``speeds`` [rev/min]."""
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    if np.any(speeds <= 0):
        raise ValueError("order_response: speeds must be positive")
    exc = excitation or mesh_excitation(model)
    E, X = exc.harmonics(orders)
    k = np.arange(1, orders + 1)
    f = np.outer(speeds * model.pair.z1 / 60.0, k)
    Q = np.zeros(f.shape + (model.n,), dtype=complex)
    for i, j in np.ndindex(f.shape):
        w = 2 * math.pi * f[i, j]
        Q[i, j] = np.linalg.solve(dynamic_stiffness(model, w), mesh_forcing(model, w, E[j], X[j]))
    return derived(model, speeds, k, f, Q, E, X, exc.contact)


def derived(model: GearRotorModel, speeds, orders, f, Q, E, X, contact: bool) -> OrderResponse:
    """The :class:`OrderResponse` of state amplitudes ``Q`` (mesh and bearing forces from them)."""
    w = 2 * math.pi * f
    kbar = np.array(model.stiffness.mean)
    GQ = Q @ model.G.T                                                    # (S, H, 2)
    N = kbar * (GQ - E[None]) + 1j * w[..., None] * model.mesh_damping * (GQ - X[None])
    KF, CF = force_matrices(model)
    F = np.einsum("jdn,shn->shjd", KF, Q) + 1j * w[..., None, None] * np.einsum("jdn,shn->shjd", CF, Q)
    return OrderResponse(speeds=speeds, orders=np.asarray(orders), frequency=f, state=Q, mesh_force=N,
                         bearing_force=F, contact=contact)
