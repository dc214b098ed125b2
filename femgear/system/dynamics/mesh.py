"""Mesh coupling per helix: line-of-action vectors, time-varying mesh stiffness, friction.

Deflection of helix s ∈ {L, R} (Kang & Kahraman, JSV 350:11, 2015; notes §6):

    δ_s = n_s · (u_1(P) − u_2(P)) − e_s(t) = g_sᵀ q − e_s(t)

with the 3-D mesh normal n_s = (cos β_b n_t, σ_s sin β_b) (n_t the transverse line of
action, pointing along the force on the gear), P the pitch point in the helix's
mid-plane, u_i(P) = d_i + θ_i × (P − C_i) the displacement of P as a point of body i.
Writing g_s out gives the paper's δ_m with β_b (the helix angle on the base cylinder,
where the flank normal lies) in place of β:

    δ_s = [(x1−x2) sin α + (y1−y2) cos α + r_b1 θz1 + r_b2 θz2] cos β_b
          + σ_s [(z1−z2) − r_w1 θy1 − r_w2 θy2] sin β_b − e_s(t)

(line of centres on x, so ψ = α_wt).  The tilt arm is the pitch radius r_w, the common
contact point of both bodies; the notes' form with r_b for each member applies the
axial force at two different points and breaks action = reaction.  The generalised
mesh force is −F_s g_s, so action = reaction and energy conservation hold by
construction.

Mesh stiffness enters as a :class:`StiffnessTable`: k_L, k_R over ONE mesh period,
sampled at equidistant mesh phases φ ∈ [0, 1) and interpolated periodically — any
TVMS model (ISO 6336, potential energy, FE) plugs in by producing such a table, or by
any object with the same ``__call__(phase) -> (k_L, k_R)``.

Friction (paper: τ = sgn(v_s) μ F): it acts along the sliding direction t (normal to
the plane of action, across the contact lines), opposing the sliding velocity ẇ of the
pinion flank relative to the gear flank along t (in this frame ẇ = −v_s, v_s = ω1 ρ1 −
ω2 ρ2 of :func:`femgear.physics.geometry.kinematics`), with sgn regularised as tanh(ẇ/v_reg)
near the pitch point, where ẇ changes sign.  Along a helical contact line ẇ changes with
the position u on the path, so the net friction force and moment per helix are
averaged over the contact lines (load per unit length uniform, friction of both signs
on a line that crosses the pitch point): A(φ) = ⟨tanh(ẇ/v_reg)⟩,
B(φ) = ⟨(u − u_C) tanh(ẇ/v_reg)⟩, and the generalised friction force is
−μ |N_s| (A h0_s + B h1_s), h(u) = h0 + (u − u_C) h1 being the gradient of the relative
displacement along t at the point u of the path.  ẇ uses the nominal rotation (the
vibratory sliding is orders of magnitude smaller), so friction is a state-dependent
excitation through |N_s|, as in the paper.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from femgear.physics.geometry import GearPair, double_helical_contact
from femgear.system.dynamics.layout import point_jacobian


def periodic_interp(samples: np.ndarray, phase: np.ndarray) -> np.ndarray:
    """Linear interpolation of ``samples`` taken at phases i/n (one period) at any real ``phase``."""
    phase = np.asarray(phase, dtype=float)
    n = samples.size
    if n == 1:
        return np.full(phase.shape, samples[0])
    x = np.mod(phase, 1.0) * n
    return np.interp(x, np.arange(n + 1.0), np.append(samples, samples[0]))


def periodic_slope(samples: np.ndarray, phase: np.ndarray) -> np.ndarray:
    """d/dphase of :func:`periodic_interp` (piecewise constant)."""
    phase = np.asarray(phase, dtype=float)
    n = samples.size
    if n == 1:
        return np.zeros(phase.shape)
    i = np.floor(np.mod(phase, 1.0) * n).astype(np.int64) % n
    return (samples[(i + 1) % n] - samples[i]) * n


@dataclass(frozen=True)
class StiffnessTable:
    """Mesh stiffness of the left and right helix over one mesh period [N/m].

    ``k_left``/``k_right`` are samples at phases ``i/n`` (i = 0..n−1) of one mesh
    cycle; a length-1 table is a constant stiffness.  Calling with mesh phases
    (cycles, any real numbers) interpolates linearly and periodically.
    """

    k_left: np.ndarray
    k_right: np.ndarray
    label: str = "table"

    def __post_init__(self):
        kl = np.atleast_1d(np.asarray(self.k_left, dtype=float))
        kr = np.atleast_1d(np.asarray(self.k_right, dtype=float))
        if kl.shape != kr.shape or kl.ndim != 1:
            raise ValueError("StiffnessTable: k_left and k_right must be 1-D arrays of equal length")
        absent_right = np.all(kr == 0)          # one-mesh pairs (spur, single helix): no right mesh
        if not (np.all(kl > 0) and (absent_right or np.all(kr > 0))) or not np.all(np.isfinite(kl + kr)):
            raise ValueError("StiffnessTable: mesh stiffness must be positive and finite (k_left/k_right; "
                             "k_right may be 0 throughout for a pair with one mesh)")
        object.__setattr__(self, "k_left", kl)
        object.__setattr__(self, "k_right", kr)

    def __call__(self, phase: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return periodic_interp(self.k_left, phase), periodic_interp(self.k_right, phase)

    @property
    def mean(self) -> tuple[float, float]:
        return float(self.k_left.mean()), float(self.k_right.mean())

    @property
    def max(self) -> float:
        return float(max(self.k_left.max(), self.k_right.max()))


def as_stiffness_table(source, samples: int = 256) -> StiffnessTable:
    """A :class:`StiffnessTable` from any TVMS: itself, or any callable phase -> (k_L, k_R).

    Callables (e.g. :class:`femgear.physics.stiffness.MeshStiffness`) are sampled at
    ``samples`` equidistant phases of one mesh period (base pitches, phase = f_m t).
    """
    if isinstance(source, StiffnessTable):
        return source
    if not callable(source):
        raise TypeError(f"mesh stiffness must be a StiffnessTable or a callable phase -> (k_left, k_right), got {type(source)!r}")
    phases = np.arange(samples) / samples
    kl, kr = source(phases)
    return StiffnessTable(np.asarray(kl, float), np.asarray(kr, float), label=str(getattr(source, "level", "callable")))


def constant_stiffness(pair: GearPair, c_gamma: float) -> StiffnessTable:
    """``constant`` level: k = c_γ b per helix (c_γ [N/m per m of face width]); a pair with one mesh (spur,
    single helix) has no right helix (k_right = 0)."""
    if not c_gamma > 0:
        raise ValueError(f"c_gamma (stiffness.mesh_stiffness_per_width) must be positive (got {c_gamma!r})")
    k = c_gamma * pair.b
    return StiffnessTable(np.array([k]), np.array([k if pair.n_helices == 2 else 0.0]), label="constant")


def contact_line_stiffness(pair: GearPair, c_gamma: float, stagger: float = 0.0, samples: int = 256) -> StiffnessTable:
    """Contact-line-length TVMS: k_s(φ) = c_γ b · L_s(φ) / L̄, L̄ = ε_α b / cos β_b.

    Stiffness per unit length of contact line is taken constant (ISO 6336-1's c_γ is a
    mean mesh stiffness per face width, so the time mean of k equals the ``constant``
    level's c_γ b; equivalently k = c_γ L(φ) cos β_b / ε_α).  L_s(φ) comes from
    :func:`femgear.physics.geometry.double_helical_contact`, the right helix shifted by the
    ``stagger`` (in base pitches); a pair with one mesh has no right helix (k_right = 0).
    """
    if not c_gamma > 0:
        raise ValueError(f"c_gamma (stiffness.mesh_stiffness_per_width) must be positive (got {c_gamma!r})")
    phases = np.arange(samples) / samples
    c = double_helical_contact(pair, phases, stagger)
    mean_length = pair.mean_contact_length
    scale = c_gamma * pair.b / mean_length
    right = scale * c["length_right"] if pair.n_helices == 2 else np.zeros(samples)
    return StiffnessTable(scale * c["length_left"], right, label="contact-line")


@dataclass(frozen=True)
class MeshGeometry:
    """Line-of-action vectors of both helices in the full 24-DOF space."""

    g: np.ndarray          #: (2, 24) gradients of δ_L, δ_R
    h0: np.ndarray         #: (2, 24) gradient of relative displacement along t at the pitch point
    h1: np.ndarray         #: (2, 24) its derivative with respect to the path position u [1/m]
    normal: np.ndarray     #: (2, 3) mesh normals n_s
    pitch_point: np.ndarray  #: (2, 3) P_s relative to the pinion centre [m]
    sigma: tuple[int, int] = (1, -1)


def mesh_geometry(pair: GearPair, half_spacing: float) -> MeshGeometry:
    """Vectors g_s, h0_s, h1_s of both helices (see the module docstring)."""
    a = pair.alpha_wt
    bb = pair.beta_b
    n_t = np.array([math.sin(a), math.cos(a), 0.0])
    t_dir = np.array([math.cos(a), -math.sin(a), 0.0])   # from C1 towards T1: normal to the plane of action
    C2 = np.array([pair.a_w, 0.0, 0.0])
    g = np.zeros((2, 24))
    h0 = np.zeros((2, 24))
    h1 = np.zeros((2, 24))
    normals, points = [], []
    for s, (sigma, zc) in enumerate(((1, -half_spacing), (-1, +half_spacing))):
        n = np.array([math.cos(bb) * n_t[0], math.cos(bb) * n_t[1], sigma * math.sin(bb)])
        P = np.array([pair.rw1, 0.0, 0.0])
        b1, b2 = 6 * (0 + s), 6 * (2 + s)  # pinion half s, gear half s
        r1 = P - np.array([0.0, 0.0, 0.0])
        r2 = P - C2
        g[s, b1:b1 + 6] = n @ point_jacobian(r1)
        g[s, b2:b2 + 6] = -(n @ point_jacobian(r2))
        h0[s, b1:b1 + 6] = t_dir @ point_jacobian(r1)
        h0[s, b2:b2 + 6] = -(t_dir @ point_jacobian(r2))
        # moving P along the line of action by du (direction n_t): d/du of J(r) = J(n_t) − I-part
        dJ = point_jacobian(n_t) - np.hstack([np.eye(3), np.zeros((3, 3))])
        h1[s, b1:b1 + 6] = t_dir @ dJ
        h1[s, b2:b2 + 6] = -(t_dir @ dJ)
        normals.append(n)
        points.append(P + np.array([0.0, 0.0, zc]))
    return MeshGeometry(g=g, h0=h0, h1=h1, normal=np.array(normals), pitch_point=np.array(points))


MuFunction = Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class FrictionTable:
    """Contact-line averages A(φ), B(φ) per helix over one mesh period (see module doc)."""

    A: np.ndarray   #: (2, n) ⟨tanh(v_s/v_reg)⟩ [-]
    B: np.ndarray   #: (2, n) ⟨(u − u_C) tanh(v_s/v_reg)⟩ [m]

    def __call__(self, phase: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A, B at mesh ``phase`` (arrays of shape (2,) + phase.shape)."""
        return (np.stack([periodic_interp(a, phase) for a in self.A]),
                np.stack([periodic_interp(b, phase) for b in self.B]))


@dataclass(frozen=True)
class FrictionLines:
    """The contact-line sample points of both helices over one mesh period (speed-independent), flattened and
    sorted by their path position u (a speed sweep evaluates μ(u) and the sliding sign on them per speed).

    ``u`` (P,): path positions of the points [m]; ``weight`` (P,): each point's share of its helix's total contact
    length at its phase [-], so that a contact-line average is Σ weight · value over the points of one (helix,
    phase); ``helix`` (P,) 0 or 1 and ``cell`` (P,) = helix · samples + phase index of each point [-].
    """

    u: np.ndarray
    weight: np.ndarray
    helix: np.ndarray
    cell: np.ndarray
    samples: int
    u_pitch: float


def friction_lines(pair: GearPair, stagger: float = 0.0, samples: int = 256,
                   points_per_line: int = 64) -> FrictionLines:
    """:class:`FrictionLines` of ``pair``: ``points_per_line`` midpoints on every contact line at the phases
    i/``samples`` (the right helix shifted by ``stagger`` base pitches)."""
    from femgear.physics.geometry import contact_lines

    xi = (np.arange(points_per_line) + 0.5) / points_per_line
    us, ws, cells = [], [], []
    for s, offset in enumerate((0.0, stagger)):
        for i in range(samples):
            lines = contact_lines(pair, i / samples, offset)
            if lines.count == 0:
                continue
            u = lines.u_lo[:, None] + (lines.u_hi - lines.u_lo)[:, None] * xi[None, :]
            w = np.repeat(lines.length[:, None], points_per_line, axis=1) / points_per_line / lines.total_length
            us.append(u.ravel())
            ws.append(w.ravel())
            cells.append(np.full(u.size, s * samples + i))
    u, w, cell = np.concatenate(us), np.concatenate(ws), np.concatenate(cells)
    order = np.argsort(u, kind="stable")
    return FrictionLines(u=u[order], weight=w[order], helix=cell[order] // samples, cell=cell[order], samples=samples,
                         u_pitch=float(pair.u_pitch))


def friction_from_lines(lines: FrictionLines, rate0: np.ndarray, rate1: np.ndarray, v_reg: float = 0.01,
                        mu_of_u: MuFunction | None = None) -> FrictionTable:
    """The tables A, B of :func:`friction_table` on precomputed contact-line points (vectorised: a speed sweep
    builds the points once and evaluates the sliding sign per speed)."""
    if not v_reg > 0:
        raise ValueError(f"v_reg must be positive (got {v_reg!r})")
    du = lines.u - lines.u_pitch
    rate0, rate1 = np.asarray(rate0, dtype=float), np.asarray(rate1, dtype=float)
    wsg = lines.weight * np.tanh((rate0[lines.helix] + du * rate1[lines.helix]) / v_reg)
    if mu_of_u is not None:
        wsg = wsg * mu_of_u(lines.u)
    n = 2 * lines.samples
    A = np.bincount(lines.cell, wsg, minlength=n).reshape(2, lines.samples)
    B = np.bincount(lines.cell, wsg * du, minlength=n).reshape(2, lines.samples)
    return FrictionTable(A=A, B=B)


def friction_table(pair: GearPair, rate0: np.ndarray, rate1: np.ndarray, stagger: float = 0.0,
                   v_reg: float = 0.01, samples: int = 256, points_per_line: int = 64,
                   mu_of_u: MuFunction | None = None) -> FrictionTable:
    """Tables A, B of the regularised sliding sign over one mesh period.

    ``rate0[s]``, ``rate1[s]``: nominal sliding velocity of the pinion relative to the
    gear along t at the pitch point [m/s] and its gradient along the path [1/s], i.e.
    h0_s·q̇_nom and h1_s·q̇_nom for the nominal rotation q̇_nom; so ẇ(u) = rate0 +
    (u − u_C) rate1, which vanishes at the pitch point C.  tanh(ẇ/v_reg) replaces
    sgn(ẇ) (regularisation speed ``v_reg`` [m/s]), so a contact line crossing the
    pitch point feels friction of both signs.  ``mu_of_u``: friction coefficient along
    the path (u [m] -> μ [-]); it is then folded into A and B (use μ_ref = 1 with them).
    The contact-line points are :func:`friction_lines` (``points_per_line`` midpoints per line).
    """
    if not v_reg > 0:
        raise ValueError(f"v_reg must be positive (got {v_reg!r})")
    return friction_from_lines(friction_lines(pair, stagger, samples, points_per_line), rate0, rate1, v_reg,
                               mu_of_u)
