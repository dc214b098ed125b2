"""Load distribution along the contact lines of one helix, with profile deviations.

Each instant (mesh phase φ) the contact lines of a helix cover transverse positions
``u`` of the path of contact.  With a Winkler layer of stiffness ``c_l(u)`` per unit
contact-line length (the local stiffness of the tooth pair at the position u, e.g. the
potential-energy pair stiffness, which is ≈ 25 % lower at the ends of the path than at
the pitch point; or the mesh stiffness spread evenly over the lines) and flank
deviations h(u) (wear of both members, thermal expansion with the opposite sign), the
local load per unit length is

    w'(u, φ) = c_l(u) · max(δ(φ) − h(u), 0),

with the approach δ(φ) set by equilibrium Σ∫ w' dl = F (the helix's normal force).
Without deviations and with a uniform c_l this is the uniform ISO 6336 distribution
w' = F / L(φ); a stiffer pair (near the pitch point) carries more.  Along a
line dl = du / sin β_b.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from femgear.physics.geometry import GearPair
from femgear.physics.geometry.lines import line_weights


@dataclass(frozen=True)
class LoadMap:
    """Time-mean load intensity seen by each profile position over one mesh cycle."""

    u: np.ndarray            #: positions on the path of contact [m]
    mean_load: np.ndarray    #: mean w' over the phases that load u [N/m] (0 if never loaded)
    loaded_fraction: np.ndarray  #: fraction of phases in which u carries load [-]


def distribute(force: np.ndarray, weights: np.ndarray, deviation: np.ndarray,
               c_l: float | np.ndarray, sin_beta_b: float) -> np.ndarray:
    """Load per unit length w'(φ, u) [N/m] for per-phase forces ``force`` [N].

    ``weights`` are the contact lines' quadrature weights per phase and position
    (:func:`line_weights`; 0 off the lines), ``deviation`` the flank deviation h(u) [m]
    (positive = material removed), or one row per phase (the effective deviation of
    :func:`reference_load_map`); ``c_l`` the stiffness per unit line length [N/m²], a
    number, one value per position or one row per phase.  At each phase the approach δ
    solves Σ_k c_l,k max(δ − h_k, 0) W_k / sin β_b = F exactly.
    """
    c_l = np.asarray(c_l, dtype=float)
    w = np.zeros(weights.shape)
    for i in range(weights.shape[0]):
        on = weights[i] > 0
        if not on.any() or force[i] <= 0:
            continue
        h = (deviation[i] if deviation.ndim == 2 else deviation)[on]
        c_all = np.broadcast_to(c_l[i] if c_l.ndim == 2 else c_l, weights.shape[1:])
        cw = c_all[on] * weights[i, on] / sin_beta_b

        def excess(delta: float) -> float:
            return float(np.sum(np.maximum(delta - h, 0.0) * cw)) - force[i]

        lo = float(h.min())
        hi = lo + force[i] / cw.sum() + float(np.ptp(h)) + 1e-30
        while excess(hi) < 0:   # only by round-off: the bracket above suffices in exact arithmetic
            hi += hi - lo           # (a doubling of hi itself ran away when hi < 0: effective deviations)
        delta = brentq(excess, lo, hi, xtol=1e-16, rtol=1e-13)
        w[i, on] = c_all[on] * np.maximum(delta - h, 0.0)
    return w


def trapezoid_weights(u: np.ndarray) -> np.ndarray:
    """Trapezoid quadrature weights of the grid ``u``."""
    d = np.diff(u)
    w = np.zeros_like(u)
    w[:-1] += d / 2
    w[1:] += d / 2
    return w


def load_map(pair: GearPair, u: np.ndarray, force: np.ndarray, deviation: np.ndarray, c_l: float | np.ndarray,
             n_phase: int | None = None, offset: float = 0.0) -> LoadMap:
    """Mean load intensity at each position over one mesh cycle of one helix.

    ``force`` is the helix's normal force [N], a scalar or one value per phase.
    """
    force = np.atleast_1d(np.asarray(force, dtype=float))
    if math.sin(pair.beta_b) == 0.0:
        return _spur_load_map(pair, u, force, deviation, c_l, offset)
    n_phase = n_phase or (force.size if force.size > 1 else 64)
    phases = np.arange(n_phase) / n_phase
    force = np.broadcast_to(force, phases.shape) if force.size == 1 else force
    w = distribute(force, line_weights(pair, u, phases, offset), deviation, c_l, math.sin(pair.beta_b))
    loaded = w > 0
    count = loaded.sum(axis=0)
    mean = np.where(count > 0, w.sum(axis=0) / np.maximum(count, 1), 0.0)
    return LoadMap(u=u, mean_load=mean, loaded_fraction=count / n_phase)


LOADED = 1e-9   #: w' above this fraction of the largest counts as loaded (the approach is solved to ~1e-13)
SECANT_FLOOR = 0.05   #: approaches below this fraction of the median use c_l (w'/(δ − ε) is ill-defined there)


@dataclass(frozen=True)
class ReferenceLoad:
    """A contact analysis's load along the contact lines, to share the load by instead of a Winkler layer.

    ``load[s, i, k]``: load per unit line length [N/m] of helix s at mesh phase
    ``phases[i]`` and path position u_k (0 off its contact lines), e.g. an LTCA cycle
    (:meth:`femgear.physics.ltca.analysis.LTCAResult.path_load`); ``deviation``: the flank
    deviation h_ref(u) (the same quantity as the ``deviation`` later passed to
    :func:`reference_load_map`) under which it was computed; ``offsets``: phase offset of
    each helix's contact lines (0 and the stagger).

    ``end``: optionally a second analysis (same phases) on the flanks a deviation path
    reaches, which begins at ``start`` (default: ``deviation``): along the path the reference
    is blended linearly between the two (:func:`reference_loads`), so that both analyses are
    reproduced where they were computed.
    """

    phases: np.ndarray
    load: np.ndarray
    deviation: np.ndarray
    offsets: tuple[float, ...] = (0.0, 0.0)
    end: ReferenceLoad | None = None
    start: np.ndarray | None = None
    #: elastic approach δ − ε of the analysis at the same points [m] (NaN off the lines); where given,
    #: the deviation change moves each loaded point with its secant stiffness w'/(δ − ε), not c_l
    approach: np.ndarray | None = None

    def stiffness(self, c_l: np.ndarray) -> np.ndarray:
        """Per helix, phase and position the stiffness the deviation change acts through [N/m²]:
        the secant w'/(δ − ε) at loaded points whose approach exceeds :data:`SECANT_FLOOR` × the
        median approach of the loaded points, else ``c_l`` (open gaps, the contact boundary)."""
        c = np.broadcast_to(c_l, self.load.shape).copy()
        if self.approach is None:
            return c
        loaded = (self.load > 0) & np.isfinite(self.approach)
        if not loaded.any():
            return c
        floor = SECANT_FLOOR * float(np.median(self.approach[loaded]))
        ok = loaded & (np.nan_to_num(self.approach, nan=-1.0) > floor)
        c[ok] = self.load[ok] / self.approach[ok]
        return c

    def progress(self, deviation: np.ndarray) -> float:
        """s ∈ [0, 1]: projection of deviation − start on end.deviation − start (1 where they coincide)."""
        if self.end is None:
            return 0.0
        start = self.deviation if self.start is None else self.start
        d, x = np.broadcast_arrays(self.end.deviation - start, deviation - start)
        dd = float(np.vdot(d, d))
        return 1.0 if dd == 0.0 else min(max(float(np.vdot(x, d)) / dd, 0.0), 1.0)


def _phase_forces(force, phases: np.ndarray, n_helices: int) -> np.ndarray:
    """(n_helices, phases) helix forces from a scalar, one value per phase i/k, or one row per helix."""
    f = np.asarray(force, dtype=float)
    if f.ndim == 0 or f.size == 1:
        return np.full((n_helices, phases.size), float(f.ravel()[0]))
    rows = np.broadcast_to(f, (n_helices, f.shape[-1])) if f.ndim == 1 else f[:n_helices]
    grid = np.arange(rows.shape[1]) / rows.shape[1]
    return np.array([np.interp(phases, grid, r, period=1.0) for r in rows])


def reference_loads(pair: GearPair, u: np.ndarray, force, deviation: np.ndarray, c_l: float | np.ndarray,
                    ref: ReferenceLoad) -> np.ndarray:
    """Load per unit length w'(s, φ, u) [N/m] shared like ``ref`` and moved by the deviation change h − h_ref.

    At each phase the reference shape is scaled to the helix's force F_s(φ) (a scalar, one
    value per phase i/k shared by the helices, or one row per helix; interpolated
    periodically onto ``ref.phases``): ŵ = w_ref F_s / Σ_lines ∫ w_ref dl, dl = du / sin β_b
    (:func:`line_weights`: every line counts, also where lines overlap in u).  A deviation h(u) other than the reference's changes it locally
    by a Winkler layer ``c_l``, with the approach change Δδ(φ) set by equilibrium:

        w'(u, φ) = max(ŵ(u, φ) + c_l(u) (Δδ(φ) − (h(u) − h_ref(u))), 0),  Σ∫ w' dl = F_s(φ),

    i.e. :func:`distribute` with the effective deviation h − h_ref − ŵ/c_l.  With
    ``ref.approach`` c_l is, at each loaded point, the analysis's own secant stiffness
    w_ref/(δ − ε) (:meth:`ReferenceLoad.stiffness`): a point then unloads once the deviation
    change reaches its elastic approach, as in the analysis — the uniform c_l would keep a
    load peak (the LTCA's path ends of unmodified flanks: up to 6× the mean w') loaded until
    the wear reached that peak over c_l (34 µm).  At h = h_ref
    it is the reference itself (Δδ = 0); with a zero reference it is the Winkler sharing.
    The local update is the linearisation that keeps the wear integration cheap between
    two contact analyses (Flodin & Andersson, Wear 207 (1997) 16 use the Winkler layer
    throughout); the reference carries what the Winkler layer misses (the elastic
    coupling along the lines, flank modifications, line-end effects).

    ``deviation`` (and ``ref.deviation``) may also be given per helix, phase and position,
    (n_helices, phases, n): the deviation at the contact-line point at u of that phase, e.g. a
    face-resolved wear field read along the lines (:mod:`femgear.physics.wear.face`).

    With ``ref.end`` the reference is ŵ = (1 − s) ŵ_ref + s ŵ_end and h_ref = (1 − s) h_ref +
    s h_end, s = ``ref.progress(h)``: the secant of the contact analysis between its two
    solutions instead of the Winkler layer's response (which differs from it, and made the
    coupling loop's wear oscillate when it bridged the whole wear from the end alone).
    """
    if math.sin(pair.beta_b) == 0.0:
        raise ValueError("reference_loads: a reference load map needs helical contact lines (beta_b > 0)")
    n_h = pair.n_helices
    for a in (ref, ref.end or ref):
        if a.load.shape[1:] != (ref.phases.size, u.size) or a.load.shape[0] < n_h:
            raise ValueError(f"reference load shape {a.load.shape} does not match ({n_h}, {ref.phases.size}, {u.size})")
    forces = _phase_forces(force, ref.phases, n_h)
    sb = math.sin(pair.beta_b)
    c_l = np.broadcast_to(np.asarray(c_l, dtype=float), u.shape)
    deviation = np.asarray(deviation, dtype=float)
    t = ref.progress(deviation)
    anchors = [(wt, a) for wt, a in ((1.0 - t, ref), (t, ref.end)) if wt > 0]
    dh = deviation - sum(wt * a.deviation for wt, a in anchors)
    stiff = sum(wt * a.stiffness(c_l) for wt, a in anchors)
    out = np.zeros((n_h, ref.phases.size, u.size))
    for s in range(n_h):
        weights = line_weights(pair, u, ref.phases, ref.offsets[s])
        base = np.zeros(weights.shape)
        for wt, a in anchors:
            shape = np.where(weights > 0, a.load[s], 0.0)
            carried = np.sum(shape * weights, axis=1) / sb
            base += wt * shape * np.divide(forces[s], carried, out=np.zeros_like(carried), where=carried > 0)[:, None]
        out[s] = distribute(forces[s], weights, (dh[s] if dh.ndim == 3 else dh[None, :]) - base / stiff[s],
                            stiff[s], sb)
    return out


def reference_load_map(pair: GearPair, u: np.ndarray, force, deviation: np.ndarray, c_l: float | np.ndarray,
                       ref: ReferenceLoad) -> LoadMap:
    """:class:`LoadMap` of :func:`reference_loads`: per helix the mean over the phases that load u, then
    the mean of the helices (both helices carry the same face-uniform deviation).

    A flank point at u passes the contact once per engagement, at a face position that moves
    linearly with the phase, so this phase mean is the mean over the face of the passage load
    (the face-uniform wear reading); positions whose reference load is 0 (e.g. a tip relief's
    open gap) count as unloaded unless the deviation change closes them
    (w' > :data:`LOADED` × the largest).
    """
    w = reference_loads(pair, u, force, deviation, c_l, ref)
    loaded = w > LOADED * w.max()
    count = loaded.sum(axis=1)
    mean = np.where(count > 0, w.sum(axis=1) / np.maximum(count, 1), 0.0)
    return LoadMap(u=u, mean_load=mean.mean(axis=0), loaded_fraction=(count / ref.phases.size).mean(axis=0))


def _spur_load_map(pair: GearPair, u: np.ndarray, force: np.ndarray, deviation: np.ndarray,
                   c_l: float | np.ndarray, offset: float = 0.0) -> LoadMap:
    """Spur pairs: a contact line is the whole face width at one position, so position u is
    loaded once per base pitch, together with the pairs at u ± k p_bt on the path.  At that
    instant (mesh phase (u − u_A)/p_bt − offset) the approach δ satisfies
    Σ_k c_l(u_k) b max(δ − h(u_k), 0) = F, and w'(u) = c_l(u) max(δ − h(u), 0)."""
    c = np.broadcast_to(np.asarray(c_l, dtype=float), u.shape)
    phases = np.arange(force.size) / force.size
    w = np.zeros(u.shape)
    for i, ui in enumerate(u):
        k = np.arange(-4, 5)
        uk = ui + k * pair.p_bt
        uk = uk[(uk >= pair.u_start - 1e-12) & (uk <= pair.u_end + 1e-12)]
        hk, ck = np.interp(uk, u, deviation), np.interp(uk, u, c) * pair.b
        F = float(np.interp(((ui - pair.u_start) / pair.p_bt - offset) % 1.0, phases, force, period=1.0))
        if F <= 0:
            continue
        lo = float(hk.min())
        hi = lo + 1.01 * F / ck.sum() + float(np.ptp(hk)) + 1e-30
        delta = brentq(lambda d: float(np.sum(ck * np.maximum(d - hk, 0.0))) - F, lo, hi, xtol=1e-16, rtol=1e-13)
        w[i] = c[i] * max(delta - deviation[i], 0.0)
    return LoadMap(u=u, mean_load=w, loaded_fraction=(w > 0).astype(float))
