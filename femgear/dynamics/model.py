"""Assembly of the gear-rotor model: bodies, shafts, bearings, damping, mesh, excitation.

Levels (``physics.dynamics``), assembled by :mod:`femgear.dynamics.structure`:
``lumped`` (the four helical halves, 24 DOF, tied rigidly per member and integrated in
12 rigid-member coordinates) and ``timoshenko`` (halves and bearing stations joined by
Timoshenko shaft elements, bearing stations condensed, 24 DOF).

Damping: bearing dashpots (scene ``support_damping``), Rayleigh damping
a0 M + a1 K_struct with a0, a1 chosen so that the two lowest flexible modes of the
mean-stiffness system have the ratio ``rayleigh_ratio`` (paper: 0.03), and mesh
damping c_s = 2 ζ_m sqrt(k̄_s m_eq,s) along each line of action with
m_eq,s = 1/Σ_j g_sj²/m_j over the DOFs of the mesh (notes §7; ζ_m from
``stiffness.damping_ratio``).  Rayleigh damping is applied to the structural
stiffness only so that the mesh damping is not counted twice.

Equations of motion (reduced coordinates q, full = T q):

    M q̈ + C q̇ + K q = f(t) − Σ_s [ G_sᵀ N_s + μ |N_s| (A_s H0_s + B_s H1_s)ᵀ ]
    δ_s = G_s q − e_s(t),   N_s = k_s(t) f_gap(δ_s) + c_s χ_s δ̇_s

with χ_s the contact indicator (the mesh damper acts only while a flank is in
contact, unlike the paper's form, which damps across the gap too).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import eigh

from femgear.contact.path import pinion_speed, pinion_torque
from femgear.dynamics.layout import NDOF
from femgear.dynamics.mesh import (
    FrictionTable,
    MeshGeometry,
    StiffnessTable,
    as_stiffness_table,
    constant_stiffness,
    periodic_interp,
    periodic_slope,
    contact_line_stiffness,
    friction_table,
    mesh_geometry,
)
from femgear.dynamics.structure import require_positive, assemble_structure
from femgear.errors import SceneError
from femgear.excitation import Eccentricity, ProfileError, RandomError, Unbalance
from femgear.geometry import GearPair, mesh_frequency

LEVELS = ("lumped", "timoshenko")


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
    #: (e_L, e_R) samples over one mesh period [m]: profile deviations from wear / thermal expansion
    profile_deviation: tuple[np.ndarray, np.ndarray] | None = None
    #: Δb samples over one mesh period [m]: the dynamic backlash b(t) = b0 + Δb(φ) (paper's b(t))
    backlash_variation: np.ndarray | None = None
    info: dict = field(default_factory=dict, compare=False)

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
        """Dynamic backlash b(t) = b0 + Δb(f_m t) [m], shape of ``t``."""
        t = np.asarray(t, dtype=float)
        if self.backlash_variation is None:
            return np.full(t.shape, self.backlash)
        return self.backlash + periodic_interp(self.backlash_variation, self.mesh_phase(t))

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
            if self.profile_deviation is not None:
                ph = self.mesh_phase(t)
                e[s] += periodic_interp(self.profile_deviation[s], ph)
                ed[s] += self.mesh_frequency * periodic_slope(self.profile_deviation[s], ph)
        return e, ed

    @property
    def _g_translation(self) -> np.ndarray:
        """(2, 2): d δ_s / d(x, y) of a pinion-centre offset (= −d/d gear offset)."""
        return self.info["g_xy"]

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
        from femgear.excitation import contact_indicator, gap_function

        t = np.asarray(t, dtype=float)
        ph = self.mesh_phase(t)
        kL, kR = self.stiffness(ph)
        k = np.stack([kL, kR], axis=-1)
        e, ed = self.errors(t)
        delta = q @ self.G.T - np.moveaxis(e, 0, -1)
        ddot = v @ self.G.T - np.moveaxis(ed, 0, -1)
        b = self.backlash_at(t)[..., None]
        N = k * gap_function(delta, b) + self.mesh_damping * contact_indicator(delta, b) * ddot
        Q = -(N @ self.G)
        if self.mu > 0 and self.friction is not None:
            A, B = self.friction(ph)
            aN = self.mu * np.abs(N)
            Q = Q - (aN * np.moveaxis(A, 0, -1)) @ self.H0 - (aN * np.moveaxis(B, 0, -1)) @ self.H1
        return delta, N, Q

    def acceleration(self, t, q, v) -> np.ndarray:
        """q̈ from the equations of motion (vectorised; for post-processing)."""
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
        f = self.torque_full @ self.T + (kbar * self.backlash) @ self.G
        if self.mu > 0 and self.friction is not None:
            for s in range(2):
                w = self.mu * (self.friction.A[s].mean() * self.H0[s] + self.friction.B[s].mean() * self.H1[s])
                Km = Km + kbar[s] * np.outer(w, self.G[s])
                f = f + kbar[s] * self.backlash * w
        q0, *_ = np.linalg.lstsq(Km, f, rcond=None)
        return q0


def rayleigh_coefficients(omega_i: float, omega_j: float, ratio: float) -> tuple[float, float]:
    """a0, a1 with ζ(ω) = a0/(2ω) + a1 ω/2 equal to ``ratio`` at ω_i and ω_j [rad/s]."""
    if ratio == 0.0:
        return 0.0, 0.0
    return 2 * ratio * omega_i * omega_j / (omega_i + omega_j), 2 * ratio / (omega_i + omega_j)


def build_model(
    scene,
    level: str | None = None,
    *,
    stiffness: StiffnessTable | str | None = None,
    rayleigh_ratio: float | None = None,
    mesh_damping_ratio: float | None = None,
    friction_coefficient: float | None = None,
    v_reg: float | None = None,
    bearing_span: tuple[float, float] | None = None,
    shaft_diameter: tuple[float, float] | None = None,
    backlash: float | None = None,
    load_stiffness: float | None = None,
    profile_deviation: tuple[np.ndarray, np.ndarray] | None = None,
    backlash_variation: np.ndarray | None = None,
) -> GearRotorModel:
    """Assemble the model of a scene.

    ``level``: "lumped" or "timoshenko" (default: the scene's ``physics.dynamics``, and
    "lumped" when that is "none").  ``stiffness``: a :class:`StiffnessTable` table (any
    TVMS model), "constant" (c_γ b) or "contact-line" (contact-line-length TVMS), or
    a level of :mod:`femgear.stiffness` ("iso6336", "pem", "fe"); default follows
    ``physics.stiffness``.  ``friction_coefficient``: a number, a callable μ(u) of the path position u [m], or "scene" for the
    μ(u) of the scene's lubrication level at the static load (:func:`femgear.run.friction_of`;
    U-shaped, zero at the pitch point); default from ``physics.lubrication``: 0 for
    ``none``, ``friction.coefficient`` for ``constant``, "scene" otherwise.
    ``bearing_span``, ``shaft_diameter`` [m] (pinion, gear), ``rayleigh_ratio``,
    ``v_reg`` and ``load_stiffness`` default to the scene keys ``<member>.bearing_span``,
    ``<member>.shaft_diameter``, ``stiffness.rayleigh_ratio``,
    ``friction.regularisation_speed`` and ``operating.loop_stiffness``.  ``load_stiffness``
    [N m/rad]: torsional stiffness of a closed power loop (FZG-type rig: pinion shaft,
    slave gearbox, gear shaft), referred to the gear shaft, resisting the relative twist
    θz_gear + (r_b1/r_b2) θz_pinion; 0 (default, the paper's equations: prescribed
    torques) leaves pinion and gear free to rotate against each other at low frequency.
    ``profile_deviation`` = (e_L, e_R) and ``backlash_variation`` Δb: samples [m] at the
    phases i/n of one mesh period — where the wear and thermal sub-models enter (the
    paper's ζ_h, ζ_T in δ_m and its b(t) = b0 + δ_e + w1 + w2 − ζ_T1 − ζ_T2).
    """
    pair = GearPair.from_scene(scene)
    if level is None:
        level = scene.physics.dynamics if scene.physics.dynamics in LEVELS else "lumped"
    if level not in LEVELS:
        raise SceneError("physics.dynamics", f"unknown dynamics level {level!r}; choose one of {', '.join(LEVELS)}")
    if bearing_span is None:
        bearing_span = (scene.pinion.bearing_span, scene.gear.bearing_span)
    if shaft_diameter is None:
        shaft_diameter = (scene.pinion.shaft_diameter, scene.gear.shaft_diameter)
    rayleigh_ratio = scene.stiffness.rayleigh_ratio if rayleigh_ratio is None else rayleigh_ratio
    v_reg = scene.friction.regularisation_speed if v_reg is None else v_reg
    load_stiffness = scene.operating.loop_stiffness if load_stiffness is None else load_stiffness
    half = 0.5 * (pair.b + scene.pair.groove_width)
    for name, span in zip(("pinion", "gear"), bearing_span):
        if not span > 2 * half:
            raise SceneError(f"{name}.bearing_span",
                             f"must exceed the distance of the helix centres {2 * half:.4g} m (got {span!r})")
    if not 0 <= rayleigh_ratio < 1:
        raise ValueError(f"rayleigh_ratio must be in [0, 1) (got {rayleigh_ratio!r})")

    # ---------- speeds ----------
    op = scene.operating
    require_positive(op.speed_rpm, "operating.speed_rpm")
    rpm1 = pinion_speed(scene)
    w1 = 2 * math.pi * rpm1 / 60
    w2 = w1 * pair.z1 / pair.z2
    sense = 1.0 if op.driver == "pinion" else -1.0     # pinion CCW when driving (layout docstring)
    omega = (sense * w1, -sense * w2)
    fm = mesh_frequency(pair, rpm1)

    # ---------- bodies, bearings, shafts ----------
    st = assemble_structure(scene, pair, level, bearing_span, shaft_diameter, half)
    M, K, Cb, T, bearing_map, M24 = st.M, st.K, st.C, st.T, st.bearing_map, st.M24

    if load_stiffness < 0:
        raise ValueError(f"load_stiffness must be non-negative (got {load_stiffness!r})")
    K_free = K                 # structure without the load spring: the Rayleigh fit uses its modes
    if load_stiffness > 0:
        # power loop: twist φ = θz_gear + (r_b1/r_b2) θz_pinion (means over the halves) vanishes for the
        # free rotation of the train; the loop resists it with k_loop (referred to the gear shaft)
        w = np.zeros(NDOF)
        for side in range(2):
            w[6 * side + 5] = 0.5 * pair.rb1 / pair.rb2
            w[6 * (2 + side) + 5] = 0.5
        wr = w @ T
        K = K + load_stiffness * np.outer(wr, wr)

    # ---------- mesh ----------
    geom: MeshGeometry = mesh_geometry(pair, half)
    G, H0, H1 = geom.g @ T, geom.h0 @ T, geom.h1 @ T
    c_gamma = scene.stiffness.mesh_stiffness_per_width
    if stiffness is None:
        stiffness = scene.physics.stiffness
    if isinstance(stiffness, str):
        if stiffness == "constant":
            stiffness = constant_stiffness(pair, c_gamma)
        elif stiffness == "contact-line":
            stiffness = contact_line_stiffness(pair, c_gamma, scene.pair.stagger)
        else:  # iso6336 / pem / fe: the stiffness package's TVMS of this scene
            from femgear.stiffness import mesh_stiffness_from_scene

            stiffness = mesh_stiffness_from_scene(scene, level=stiffness)
    stiffness = as_stiffness_table(stiffness)
    zeta_m = scene.stiffness.damping_ratio if mesh_damping_ratio is None else mesh_damping_ratio
    if not 0 <= zeta_m < 1:
        raise ValueError(f"mesh_damping_ratio must be in [0, 1) (got {zeta_m!r})")
    mdiag = np.diag(M24)
    c_mesh = np.array([
        2 * zeta_m * math.sqrt(k * 1.0 / np.sum(geom.g[s] ** 2 / mdiag)) for s, k in enumerate(stiffness.mean)
    ])
    b0 = scene.pair.backlash if backlash is None else backlash
    if b0 < 0:
        raise ValueError(f"backlash must be non-negative (got {b0!r})")

    def _table(a, name):
        a = np.atleast_1d(np.asarray(a, dtype=float))
        if a.ndim != 1 or not np.all(np.isfinite(a)):
            raise ValueError(f"{name} must be a finite 1-D array of samples over one mesh period")
        return a

    if profile_deviation is not None:
        profile_deviation = (_table(profile_deviation[0], "profile_deviation[0]"),
                             _table(profile_deviation[1], "profile_deviation[1]"))
    if backlash_variation is not None:
        backlash_variation = _table(backlash_variation, "backlash_variation")
        if np.any(b0 + backlash_variation < 0):
            raise ValueError("backlash + backlash_variation must stay non-negative")

    # ---------- torques: drive and load balance the mean mesh force ----------
    torque = np.zeros(NDOF)
    require_positive(op.torque, "operating.torque")
    T1 = pinion_torque(scene)
    T2 = T1 * pair.rb2 / pair.rb1
    for side in range(2):
        torque[6 * side + 5] = T1 / 2
        torque[6 * (2 + side) + 5] = T2 / 2

    # ---------- friction ----------
    mu_of_u = None
    if friction_coefficient is None:
        lub = scene.physics.lubrication
        friction_coefficient = {"none": 0.0, "constant": scene.friction.coefficient}.get(lub, "scene")
    if callable(friction_coefficient):              # μ(u) along the path, e.g. from the coupling loop
        mu_of_u, friction_coefficient = friction_coefficient, 1.0
    elif isinstance(friction_coefficient, str):
        if friction_coefficient != "scene":
            raise ValueError(f"friction_coefficient must be a number, a callable or 'scene' (got {friction_coefficient!r})")
        from femgear.contact.path import contact_along_path
        from femgear.run import friction_of

        contact = contact_along_path(scene, pair=pair)
        u_tab, mu_tab = contact.kin.u, friction_of(scene, contact)["mu"]
        mu_of_u = lambda u: np.interp(u, u_tab, mu_tab)  # noqa: E731
        friction_coefficient = 1.0                        # μ(u) is folded into the tables
    if friction_coefficient < 0:
        raise ValueError(f"friction_coefficient must be non-negative (got {friction_coefficient!r})")
    qdot_nom = np.zeros(NDOF)
    for side in range(2):
        qdot_nom[6 * side + 5] = omega[0]
        qdot_nom[6 * (2 + side) + 5] = omega[1]
    ftab = None
    if friction_coefficient > 0:
        ftab = friction_table(pair, geom.h0 @ qdot_nom, geom.h1 @ qdot_nom, scene.pair.stagger, v_reg,
                              mu_of_u=mu_of_u)
        # the load torque absorbs the mean friction torque, so the free rotation does not drift
        N0 = T1 / 2 / geom.g[0, 5]
        Qf = -friction_coefficient * N0 * (ftab.A.mean(axis=1) @ geom.h0 + ftab.B.mean(axis=1) @ geom.h1)
        rigid = qdot_nom / omega[0]
        loss = Qf @ rigid                       # mean friction power per unit pinion speed [N m]
        gear_dofs = [6 * 2 + 5, 6 * 3 + 5]
        for d in gear_dofs:
            torque[d] -= loss / (2 * rigid[d])

    # ---------- errors ----------
    err = scene.errors
    profile = tuple(ProfileError(err.profile_error, fm, err.profile_error_orders, math.radians(err.profile_error_phase_deg),
                                 off) for off in (0.0, scene.pair.stagger))
    rnd = tuple(RandomError(err.random, fm, pair.z1, pair.z2, err.seed, off) for off in (0.0, scene.pair.stagger))
    ecc = (Eccentricity(scene.pinion.eccentricity, omega[0], math.radians(scene.pinion.eccentricity_phase_deg)),
           Eccentricity(scene.gear.eccentricity, omega[1], math.radians(scene.gear.eccentricity_phase_deg)))
    unb = (Unbalance(scene.pinion.unbalance, omega[0], math.radians(scene.pinion.eccentricity_phase_deg)),
           Unbalance(scene.gear.unbalance, omega[1], math.radians(scene.gear.eccentricity_phase_deg)))

    # ---------- Rayleigh damping from the two lowest flexible modes of the mean system ----------
    Kmean = K_free + sum(k * np.outer(G[s], G[s]) for s, k in enumerate(stiffness.mean))
    w2 = eigh(Kmean, M, eigvals_only=True)
    wflex = np.sqrt(w2[w2 > 1e-6 * w2.max()])
    a0, a1 = rayleigh_coefficients(wflex[0], wflex[1], rayleigh_ratio)
    C = Cb + a0 * M + a1 * K

    return GearRotorModel(
        level=level, pair=pair, M=M, K=K, C=C, T=T, G=G, H0=H0, H1=H1, stiffness=stiffness,
        mesh_damping=c_mesh, backlash=float(b0), mu=float(friction_coefficient), friction=ftab,
        mesh_frequency=fm, omega=omega, torque_full=torque, bearing_map=bearing_map, stagger=scene.pair.stagger,
        profile_errors=profile, random_errors=rnd, eccentricities=ecc, unbalances=unb, rayleigh=(a0, a1),
        profile_deviation=profile_deviation, backlash_variation=backlash_variation,
        info={"g_xy": np.array([geom.g[s, 6 * s: 6 * s + 2] for s in range(2)]), "bearing_span": bearing_span, "shaft_diameter": shaft_diameter,
              "half_spacing": half, "mesh_damping_ratio": zeta_m, "v_reg": v_reg,
              "flexible_modes_hz": (wflex / (2 * math.pi)).tolist(), "load_stiffness": load_stiffness},
    )
