"""The frozen gear-rotor model: bodies, shafts, bearings, damping, mesh, excitation.

Built by :func:`femgear.system.dynamics.build.build_model`; levels (``physics.dynamics``),
assembled by :mod:`femgear.system.dynamics.structure`:
``lumped`` (the four helical halves, 24 DOF, tied rigidly per member and integrated in
12 rigid-member coordinates) and ``timoshenko`` (halves and bearing stations joined by
Timoshenko shaft elements, bearing stations condensed, 24 DOF).

Damping: bearing dashpots (scene ``support_damping``), Rayleigh damping
a0 M_f + a1 K_struct with a0, a1 chosen so that the two lowest flexible modes of the
mean-stiffness system have the ratio ``rayleigh_ratio`` (paper: 0.03), where
M_f = M − M Φ_r Φ_rᵀ M is the mass matrix with the rigid-body modes Φ_r (mass-
normalised kernel of the mean stiffness) projected out, so that the free rotation of
the gear train is not damped (the flexible modes keep exactly a0 + a1 ω²), and mesh
damping c_s = 2 ζ_m sqrt(k̄_s m_eq,s) along each line of action with
m_eq,s = 1/Σ_j g_sj²/m_j over the DOFs of the mesh (notes §7; ζ_m from
``stiffness.damping_ratio``).  Rayleigh damping is applied to the structural
stiffness only so that the mesh damping is not counted twice.

Equations of motion (reduced coordinates q, full = T q):

    M q̈ + C q̇ + K q = f(t) − Σ_s [ G_sᵀ N_s + μ |N_s| (A_s H0_s + B_s H1_s)ᵀ ]
    δ_s = G_s q − e_s(t) − c_s(φ),   N_s = k_s(t) f_gap(δ_s; b̄_s(φ)) + c_s χ_s δ̇_s

with χ_s the contact indicator (the mesh damper acts only while a flank is in
contact, unlike the paper's form, which damps across the gap too).

Flank deviations enter once (:class:`MeshDeviation`).  With d_D,s(φ) and d_C,s(φ) the
deviations of the drive and coast flanks of helix s (material removed > 0, both
members summed, averaged over the contact lines), the drive flanks touch when
G_s q − e_s > b + d_D,s and the coast flanks when G_s q − e_s < −(b + d_C,s).  The
dead zone with these two thresholds is the symmetric one of half-width
b̄_s = b + (d_D,s + d_C,s)/2 shifted by c_s = (d_D,s − d_C,s)/2:
f(δ; b + d_D, b + d_C) = f_gap(δ − c_s; b̄_s) exactly.  So wear w on the drive flanks
(d_D = w, d_C = 0) moves the drive threshold by w and leaves the coast threshold; a
uniform thermal expansion ζ (d_D = d_C = −ζ) closes both by ζ.  The paper's eqs. 11
and 14 put the same deviation into the mesh deflection δ_m (its e = ζ_T + h) and into
the backlash b(t) = b0 + w1 + w2 − ζ_T1 − ζ_T2, so the drive threshold moves by
2(w − ζ): the deviation is counted twice.  Transmission errors e_s (eccentricity,
pitch and profile errors of the scene's ``[errors]``) move the tooth bodily and shift
both thresholds together.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from femgear.physics.excitation import CumulativePitchError, Eccentricity, ProfileError, RandomError, Unbalance
from femgear.physics.geometry import GearPair
from femgear.system.dynamics.layout import NDOF
from femgear.system.dynamics.mesh import FrictionTable, MeshGeometry, StiffnessTable, periodic_interp, periodic_slope
from femgear.system.dynamics.structure import Bearings


@dataclass(frozen=True)
class MeshDeviation:
    """Flank deviations of the drive and coast flanks per helix over one mesh period [m].

    ``drive``/``coast``: (2, n) samples at the phases i/n, material removed > 0 (wear),
    material added < 0 (thermal expansion), both members summed and averaged over the
    contact lines of the helix (see the module docstring for how they enter).
    """

    drive: np.ndarray
    coast: np.ndarray

    def __post_init__(self):
        for name in ("drive", "coast"):
            a = np.asarray(getattr(self, name), dtype=float)
            if a.ndim != 2 or a.shape[0] != 2 or not np.all(np.isfinite(a)):
                raise ValueError(f"MeshDeviation.{name} must be a finite (2, n) array over one mesh period")
            object.__setattr__(self, name, a)
        if self.drive.shape != self.coast.shape:
            raise ValueError("MeshDeviation.drive and .coast must have the same shape")

    def plus(self, other: MeshDeviation | None) -> MeshDeviation:
        """The sum of two deviations, the coarser table interpolated onto the finer phase grid."""
        if other is None:
            return self
        n = max(self.drive.shape[1], other.drive.shape[1])
        ph = np.arange(n) / n

        def on(a: np.ndarray) -> np.ndarray:
            return a if a.shape[1] == n else np.array([periodic_interp(row, ph) for row in a])

        return MeshDeviation(drive=on(self.drive) + on(other.drive), coast=on(self.coast) + on(other.coast))

    @property
    def shift(self) -> np.ndarray:
        """c_s = (d_D − d_C)/2: the shift of the dead zone [m]."""
        return 0.5 * (self.drive - self.coast)

    @property
    def opening(self) -> np.ndarray:
        """(d_D + d_C)/2: the change of the dead zone's half-width [m]."""
        return 0.5 * (self.drive + self.coast)


@dataclass(frozen=True)
class GearRotorModel:
    """A linear structure with two nonlinear, time-varying mesh couplings (frozen)."""

    level: str
    pair: GearPair
    M: np.ndarray            #: reduced mass matrix (n×n) [kg, kg m^2]
    K: np.ndarray            #: structural stiffness (bearings + shafts) (n×n)
    C: np.ndarray            #: structural damping (bearings + Rayleigh) (n×n)
    T: np.ndarray            #: full (24) = T @ reduced
    G: np.ndarray            #: (2, n) mesh gradients ∂δ_s/∂q
    H0: np.ndarray           #: (2, n) friction direction at the pitch point
    H1: np.ndarray           #: (2, n) its gradient along the path [1/m]
    stiffness: StiffnessTable
    mesh_damping: np.ndarray  #: (2,) c_s [N s/m]
    backlash: float          #: b [m]
    mu: float                #: friction coefficient [-]
    friction: FrictionTable | None
    mesh_frequency: float    #: f_m [Hz]
    omega: tuple[float, float]  #: signed speeds of pinion and gear [rad/s]
    torque_full: np.ndarray  #: (24,) constant external torques on the halves [N m]
    bearing_map: np.ndarray  #: (3·4, n) displacement of the bearing stations (pinion L, R, gear L, R)
    stagger: float
    profile_errors: tuple[ProfileError, ProfileError]
    random_errors: tuple[RandomError, RandomError]
    eccentricities: tuple[Eccentricity, Eccentricity]
    unbalances: tuple[Unbalance, Unbalance]
    rayleigh: tuple[float, float]   #: (a0, a1)
    geometry: MeshGeometry          #: line-of-action vectors in the full 24-DOF space
    nominal_rate: np.ndarray        #: (24,) nominal rotation q̇_nom of the halves [rad/s]
    flexible_modes_hz: tuple[float, ...]   #: natural frequencies of the mean system [Hz]
    half_spacing: float             #: z of the helix centres [m]
    v_reg: float                    #: friction regularisation speed [m/s]
    load_stiffness: float           #: power-loop stiffness [N m/rad]
    bearings: Bearings              #: springs, dashpots and positions of the four bearing stations
    #: flank deviations of the drive and coast flanks per helix over one mesh period
    deviation: MeshDeviation | None = None
    #: the part of ``deviation`` that belongs to the tooth geometry (the unloaded TE of the
    #: flank modifications from the LTCA level); :func:`with_deviation` adds to it
    base_deviation: MeshDeviation | None = None
    #: per helix, the once-per-revolution cumulative pitch deviations of pinion and gear it sees
    pitch_errors: tuple[tuple[CumulativePitchError, ...], ...] = ()
    #: the compliant housing the bearings sit in (:class:`femgear.system.dynamics.housing.HousingCoupling`,
    #: :func:`femgear.system.dynamics.housing.couple_housing`); None: the bearings stand on rigid ground
    housing: Any = None

    @property
    def n(self) -> int:
        return self.M.shape[0]

    @property
    def mesh_period(self) -> float:
        return 1.0 / self.mesh_frequency

    # ---------- excitation, vectorised over time ----------
    def mesh_phase(self, t: np.ndarray) -> np.ndarray:
        return self.mesh_frequency * np.asarray(t, dtype=float)

    def backlash_at(self, t: np.ndarray) -> np.ndarray:
        """Half-width b̄_s(t) of each helix's dead zone [m], shape (2,) + t.shape."""
        t = np.asarray(t, dtype=float)
        b = np.full((2,) + t.shape, self.backlash)
        if self.deviation is not None:
            ph = self.mesh_phase(t)
            for s in range(2):
                b[s] += periodic_interp(self.deviation.opening[s], ph)
        return b

    def errors(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Transmission errors e_s(t) and their rates, shape (2,) + t.shape [m, m/s]."""
        t = np.asarray(t, dtype=float)
        e = np.zeros((2,) + t.shape)
        ed = np.zeros((2,) + t.shape)
        ecc1, ecc2 = self.eccentricities
        r = ecc1.offset(t) - ecc2.offset(t)            # (..., 2) relative centre offset
        rd = ecc1.offset_rate(t) - ecc2.offset_rate(t)
        gx = self._g_translation
        for s in range(2):
            # geometric centre offsets act like bearing translations of the members
            e[s] = -(r @ gx[s])
            ed[s] = -(rd @ gx[s])
            e[s] += self.profile_errors[s].value(t) + self.random_errors[s].value(t)
            ed[s] += self.profile_errors[s].rate(t) + self.random_errors[s].rate(t)
            for pitch in self.pitch_errors[s] if self.pitch_errors else ():
                e[s] += pitch.value(t)
                ed[s] += pitch.rate(t)
            if self.deviation is not None:
                ph = self.mesh_phase(t)
                e[s] += periodic_interp(self.deviation.shift[s], ph)
                ed[s] += self.mesh_frequency * periodic_slope(self.deviation.shift[s], ph)
        return e, ed

    @property
    def _g_translation(self) -> np.ndarray:
        """(2, 2): d δ_s / d(x, y) of a pinion-centre offset (= −d/d gear offset)."""
        g = self.geometry.g
        return np.array([g[s, 6 * s: 6 * s + 2] for s in range(2)])

    def external_force(self, t: np.ndarray) -> np.ndarray:
        """Reduced external force f(t): torques + unbalance, shape t.shape + (n,) [N, N m]."""
        t = np.asarray(t, dtype=float)
        full = np.broadcast_to(self.torque_full, t.shape + (NDOF,)).copy()
        for member, unb in enumerate(self.unbalances):
            if unb.unbalance == 0.0:
                continue
            F = unb.force(t)
            for side in range(2):
                b = 6 * (2 * member + side)
                full[..., b] += 0.5 * F[..., 0]
                full[..., b + 1] += 0.5 * F[..., 1]
        return full @ self.T

    # ---------- mesh forces ----------
    def mesh_forces(self, t, q, v):
        """Mesh deflections, normal forces and generalised forces for arrays of states.

        ``q``, ``v`` have shape t.shape + (n,).  Returns (δ, N, Q) with δ, N of shape
        t.shape + (2,) and Q (the generalised mesh + friction force) like ``q``.
        """
        from femgear.physics.excitation import contact_indicator, gap_function

        t = np.asarray(t, dtype=float)
        ph = self.mesh_phase(t)
        kL, kR = self.stiffness(ph)
        k = np.stack([kL, kR], axis=-1)
        e, ed = self.errors(t)
        delta = q @ self.G.T - np.moveaxis(e, 0, -1)
        ddot = v @ self.G.T - np.moveaxis(ed, 0, -1)
        b = np.moveaxis(self.backlash_at(t), 0, -1)
        N = k * gap_function(delta, b) + self.mesh_damping * contact_indicator(delta, b) * ddot
        Q = -(N @ self.G)
        if self.mu > 0 and self.friction is not None:
            A, B = self.friction(ph)
            aN = self.mu * np.abs(N)
            Q = Q - (aN * np.moveaxis(A, 0, -1)) @ self.H0 - (aN * np.moveaxis(B, 0, -1)) @ self.H1
        return delta, N, Q

    def acceleration(self, t, q, v, Q: np.ndarray | None = None) -> np.ndarray:
        """q̈ from the equations of motion (vectorised; for post-processing); ``Q``: the generalised
        mesh forces of :meth:`mesh_forces` when already known."""
        if Q is None:
            _, _, Q = self.mesh_forces(t, q, v)
        rhs = self.external_force(t) + Q - q @ self.K.T - v @ self.C.T
        return np.linalg.solve(self.M, np.moveaxis(rhs, -1, 0).reshape(self.n, -1)).T.reshape(np.shape(q))

    def mean_stiffness_matrix(self, contact: bool = True) -> np.ndarray:
        """K + Σ k̄_s G_sᵀ G_s (flanks in contact) — the linearised stiffness."""
        K = self.K.copy()
        if contact:
            for s, k in enumerate(self.stiffness.mean):
                K += k * np.outer(self.G[s], self.G[s])
        return K

    def static_state(self) -> np.ndarray:
        """Static equilibrium q0 of the mean system under the torques (drive flanks in contact).

        Includes the mean friction force (period-averaged A, B).  Solved in the
        least-squares sense: the free rigid rotation of the gear train is a null
        direction of K, orthogonal to the balanced torques (minimum-norm q0).
        """
        Km = self.mean_stiffness_matrix()
        kbar = np.array(self.stiffness.mean)
        b = self.backlash + (np.zeros(2) if self.deviation is None else self.deviation.drive.mean(axis=1))
        f = self.torque_full @ self.T + (kbar * b) @ self.G
        if self.mu > 0 and self.friction is not None:
            for s in range(2):
                w = self.mu * (self.friction.A[s].mean() * self.H0[s] + self.friction.B[s].mean() * self.H1[s])
                Km = Km + kbar[s] * np.outer(w, self.G[s])
                f = f + kbar[s] * b[s] * w
        q0, *_ = np.linalg.lstsq(Km, f, rcond=None)
        return q0


