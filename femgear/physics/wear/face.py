"""Face-resolved Archard wear: a depth field h(ρ, ζ) per member and helix from a contact analysis's line loads.

The path model (:mod:`.archard`) keeps one depth per path position u: the load a flank point
sees is averaged over the face (the passage mean of :func:`.load_sharing.reference_load_map`),
and the depth is the same at every face position ζ and on both helices.  With lead crowning,
end relief or a helix-slope deviation the load, and so the wear, varies over the face and
between the helices.  Here every flank point is followed on its own.

A flank point of helix s at path position u (pinion roll distance ρ₁ = u, gear ρ₂ = T₁T₂ − u)
and face coordinate ζ is met by a contact line once per engagement, at the mesh phase φ where
the line u₀(φ) + ζ tan β_b passes through u; the contact (Hertz) band of semi-width
a(w') = √(4 w' R / (π E′)) (Johnson, *Contact Mechanics* 1985, eq. 4.43) crosses it in the time
2a/v_j.  Archard's law per point (Archard, J. Appl. Phys. 24 (1953) 981; the single-point
observation of Flodin & Andersson, Wear 207 (1997) 16, helical: Wear 249 (2001) 285):

    Δh_j(u, ζ) = (K/H) ∫ p |v_s| dt = (K/H) |v_s(u)| / v_j(u) ∫_{−a}^{a} p dx = (K/H) w'(u, ζ) |v_s| / v_j,

the form and coefficient of the path model (:func:`.archard.archard_rates`, the same
function), with w'(u, ζ) the load per unit line length of the contact line at that point in
place of the face-mean w̄'(u); the semi-width cancels (∫p dx = w' for any a), so the depth needs
only the local line load (valid while the load is constant during the passage, i.e. a far
below the face spacing of the load's variation: 0.1 mm against millimetres here).

The line loads come from a contact analysis sampled on the path grid, (helix, phase, u) with
the face coordinate ζ of the line at each sample (:meth:`femgear.physics.ltca.analysis.LTCAResult.path_load`
and :meth:`~femgear.physics.ltca.analysis.LTCAResult.path_zeta`): for fixed u the phases that load u
visit ζ ∈ [0, b] uniformly, so w'(u, ζ) is the interpolant of those samples in ζ
(:func:`face_load`), and its face mean is the phase mean over the loading phases that the path
model uses (they integrate the same loads).  Open gaps (w' = 0 on a line, e.g. a relief) count
as zero here; the path model's passage mean leaves them out.

Integration over many cycles keeps the path model's logic (:func:`.archard.wear_steps`): per
step the analysis's loads are scaled to the helix forces and moved by the wear grown through
the analysis's secant stiffness with equilibrium at every phase
(:func:`.load_sharing.reference_loads`, the depth now read along each line at its own ζ), and
the step is capped by the same stability rule (:func:`.archard.stable_cycles`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from femgear.physics.wear.archard import WearSetup, archard_rates, stepped
from femgear.physics.wear.load_sharing import ReferenceLoad, reference_loads


@dataclass(frozen=True)
class FaceReference:
    """A contact analysis's line loads with the face coordinate of each sample, and the face grid."""

    ref: ReferenceLoad     #: loads (helix, phase, u) and their secant update (:class:`.load_sharing.ReferenceLoad`)
    zeta: np.ndarray       #: (helix, phase, u) face coordinate of the line at each sample [m], NaN off the lines
    grid: np.ndarray       #: uniform face grid ζ_0 = 0 … ζ_m = b [m]
    #: face resolution of the analysis's line loads [m]: the load is averaged over ζ windows of this width
    #: (:func:`face_load`; the LTCA's point spacing b / n_line), 0: none
    window: float = 0.0

    def __post_init__(self):
        g = np.asarray(self.grid, float)
        if g.size < 2 or g[0] != 0.0 or np.any(np.abs(np.diff(g) - g[1]) > 1e-9 * g[-1]):
            raise ValueError("FaceReference.grid must be uniform from 0 to the face width with >= 2 points")
        if self.zeta.shape != self.ref.load.shape:
            raise ValueError(f"FaceReference.zeta shape {self.zeta.shape} differs from the load's {self.ref.load.shape}")


@dataclass(frozen=True)
class FaceWearState:
    """Face-resolved wear after ``cycles`` pinion revolutions: depths normal to the flank [m].

    ``h1[s, k, m]``: pinion, helix s (0 left, 1 right), roll distance ρ₁ = u_k, face ζ_m;
    ``h2[s, k, m]``: the gear's point that meets it (ρ₂ = T₁T₂ − u_k, the same ζ_m).
    """

    cycles: float
    h1: np.ndarray
    h2: np.ndarray
    steps: int = 0

    @classmethod
    def zero(cls, n_u: int, n_zeta: int) -> FaceWearState:
        return cls(cycles=0.0, h1=np.zeros((2, n_u, n_zeta)), h2=np.zeros((2, n_u, n_zeta)))

    def path_mean(self, grid: np.ndarray) -> np.ndarray:
        """(2, n): face mean (trapezoid) of both helices' depths of pinion and gear: the path model's h(u)."""
        return np.array([face_mean(h, grid).mean(axis=0) for h in (self.h1, self.h2)])


def face_mean(field: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """Trapezoid mean over the last axis (the face grid ``grid``)."""
    return np.trapezoid(field, grid, axis=-1) / (grid[-1] - grid[0])


def along_lines(field: np.ndarray, zeta: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """A face field (helix, u, ζ grid) read at the line samples (helix, phase, u) of face coordinate ``zeta``:
    linear in ζ on the uniform grid, 0 off the lines (NaN ζ)."""
    n_h, n_p, n_u = zeta.shape
    on = np.isfinite(zeta)
    x = np.clip(np.where(on, zeta, 0.0) / grid[1], 0.0, grid.size - 1.0)
    j = np.minimum(np.floor(x).astype(int), grid.size - 2)
    t = x - j
    s = np.arange(n_h)[:, None, None]
    k = np.arange(n_u)[None, None, :]
    out = (1 - t) * field[s, k, j] + t * field[s, k, j + 1]
    return np.where(on, out, 0.0)


def face_load(load: np.ndarray, zeta: np.ndarray, grid: np.ndarray, window: float = 0.0) -> np.ndarray:
    """Line load w'(u, ζ) on the face grid (helix, u, ζ) [N/m] from samples (helix, phase, u) at ``zeta``.

    For each helix and u, the samples on a line (finite ζ, loads 0 included) sorted in ζ, interpolated
    linearly and held constant beyond the outermost samples to the face ends 0 and b = grid[-1]; 0 where
    no line reaches u.  With ``window`` > 0 the interpolant's mean over [ζ − window/2, ζ + window/2] ∩
    [0, b] (exact integral of the piecewise-linear interpolant).

    Why the window: consecutive phases place the analysis's points differently along their lines (the
    LTCA's midpoint segments of b / n_line shift with the clipped line), so at a fixed u the samples of
    successive phases carry a discretisation jitter of period ≈ b / n_line in ζ; a box of that width
    removes it.  Without it the worn field holds structure finer than the analysis resolves, which the
    analysis re-run on it reads back as point-to-point noise: orders 4–12 of the loaded TE of the rig's
    test gear after 1e6 cycles came out at 20–120 nm and changed by up to 3.7× between face grids of 21,
    41 and 81 points; with the window (one point spacing) orders 1–10 agree within 40 % across those
    grids, order 1 within 0.5 % (README, face-resolved wear).  Whether the LTCA resolves them is a separate
    question (:func:`femgear.system.coupling.passes.worn_orders`).
    """
    n_h, _, n_u = load.shape
    b = float(grid[-1])
    half = 0.5 * window
    lo, hi = np.clip(grid - half, 0.0, b), np.clip(grid + half, 0.0, b)
    out = np.zeros((n_h, n_u, grid.size))
    for s in range(n_h):
        for k in range(n_u):
            on = np.isfinite(zeta[s, :, k])
            if not on.any():
                continue
            z, w = zeta[s, on, k], load[s, on, k]
            order = np.argsort(z)
            z, w = z[order], w[order]
            if half <= 0:
                out[s, k] = np.interp(grid, z, w)
                continue
            z = np.concatenate([[min(0.0, z[0])], z, [max(b, z[-1])]])
            w = np.concatenate([w[:1], w, w[-1:]])
            out[s, k] = (_integral(z, w, hi) - _integral(z, w, lo)) / np.maximum(hi - lo, 1e-300)
    return out


def _integral(z: np.ndarray, w: np.ndarray, x: np.ndarray) -> np.ndarray:
    """∫_{z_0}^{x} of the piecewise-linear interpolant of (z, w), exactly, at the points ``x`` in [z_0, z_n]."""
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(z))])
    j = np.clip(np.searchsorted(z, x, side="right") - 1, 0, z.size - 2)
    dz = np.maximum(z[j + 1] - z[j], 1e-300)
    t = x - z[j]
    slope = (w[j + 1] - w[j]) / dz
    return cum[j] + w[j] * t + 0.5 * slope * t**2


def face_rates(setup: WearSetup, face: FaceReference, state: FaceWearState):
    """(r1, r2, W): depth per pinion revolution of pinion and gear on the face grid (helix, u, ζ) [m] and
    the line load W = w'(u, ζ) [N/m] for the wear in ``state`` (the module docstring's Δh_j per point).

    ``setup.force``: the helix normal force, a scalar, one value per phase i/k, or one row per helix
    (:func:`.load_sharing.reference_loads`); ``setup.reference`` is not used (``face.ref`` is)."""
    pair, u = setup.pair, setup.kin.u
    if face.ref.load.shape[2] != u.size:
        raise ValueError(f"face reference has {face.ref.load.shape[2]} path positions, the setup {u.size}")
    dev = along_lines(state.h1 + state.h2, face.zeta, face.grid)[:pair.n_helices]
    w = reference_loads(pair, u, setup.force, dev, setup.c_l, face.ref)
    W = face_load(w, face.zeta[:pair.n_helices], face.grid, face.window)
    r1, r2 = archard_rates(setup, W.swapaxes(-1, -2))
    return r1.swapaxes(-1, -2), r2.swapaxes(-1, -2), W


def face_wear_steps(setup: WearSetup, face: FaceReference, cycles: float, state: FaceWearState | None = None,
                    max_relative_change: float = 0.05) -> Iterator[FaceWearState]:
    """Yield the face-resolved state after each update step until ``cycles`` pinion revolutions
    (:func:`.archard.wear_steps` with the depth and the load resolved over the face)."""
    state = state or FaceWearState.zero(setup.kin.u.size, face.grid.size)
    yield from stepped(setup, lambda s: face_rates(setup, face, s), state, cycles, max_relative_change)


def run_face_wear(setup: WearSetup, face: FaceReference, cycles: float,
                  max_relative_change: float = 0.05) -> FaceWearState:
    """Accumulate face-resolved wear to ``cycles`` pinion revolutions."""
    final = FaceWearState.zero(setup.kin.u.size, face.grid.size)
    for final in face_wear_steps(setup, face, cycles, None, max_relative_change):  # noqa: B007 — keeps the last
        pass
    return final


def base_speed(setup: WearSetup) -> float:
    """Speed of the contact lines along the path ω₁ r_b1 = ω₂ r_b2 [m/s] (from the kinematics)."""
    k = setup.kin
    i = int(np.argmax(k.rho1))
    return float(k.v1[i] / k.rho1[i] * setup.pair.rb1)


def flank_volume(setup: WearSetup, depth: np.ndarray, grid: np.ndarray | None, member: int) -> float:
    """Worn volume of one tooth flank of ``member`` per pass [m³]: ∫∫ h dA over both helices (the one of a
    single-helical pair: its :class:`FaceWearState` rows repeat it).

    ``depth``: (helix, u, ζ) on ``grid``, or (u,) face-uniform (``grid`` None: × the face width, both
    helices).  The contact line sweeps the plane of action (u, ζ) at ω₁ r_b1 along u while it crosses
    the flank at v_j perpendicular to itself, and dℓ = dζ / cos β_b, so dA_j = v_j / (ω₁ r_b1 cos β_b)
    du dζ: with Δh_j = (K/H) w' |v_s| / v_j this makes ∫∫ h dA = (K/H) ∫ Σ w' |v_s| dℓ dt over one mesh
    cycle (:func:`archard_volume`).  Trapezoid in u and ζ."""
    k, pair = setup.kin, setup.pair
    v = k.v1 if member == 1 else k.v2
    scale = v / (base_speed(setup) * math.cos(pair.beta_b))
    if grid is None:
        return float(np.trapezoid(depth * scale, k.u)) * pair.b * pair.n_helices
    per_u = np.trapezoid(depth[:pair.n_helices], grid, axis=-1).sum(axis=0)     # a single helix's state repeats it
    return float(np.trapezoid(per_u * scale, k.u))


def archard_volume(setup: WearSetup, u: np.ndarray, load: np.ndarray, length: np.ndarray) -> float:
    """Archard's volume per mesh cycle (K/H) ∫ Σ w' |v_s| dℓ dt [m³] from contact points sampled at equal
    phase steps: ``u``, ``load`` (w' [N/m]) and ``length`` (Δℓ [m]) are lists with one array per phase
    (e.g. the columns of :attr:`femgear.physics.ltca.analysis.LTCAResult.line_load`); the mesh cycle lasts
    p_bt / (ω₁ r_b1).  With the flank speeds of ``setup.kin`` (interpolated in u), so it equals each
    member's :func:`flank_volume` per pass when the analysis's forces are the wear's."""
    k, pair = setup.kin, setup.pair
    per_phase = [float(np.sum(w * np.abs(np.interp(x, k.u, k.vs)) * dl)) for x, w, dl in zip(u, load, length)]
    period = pair.p_bt / base_speed(setup)
    return setup.coefficient / setup.hardness * period * float(np.mean(per_phase))
