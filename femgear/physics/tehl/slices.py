"""Wide helices: a contact too slender for the point solver, as line TEHL contacts in face slices.

Below the point solver's slender-ellipse limit (R_x/R_y < :data:`femgear.physics.contact.crowning.
MIN_POINT_RATIO`, or no crowning at all) a tooth pair's contact is a line contact along its contact line:
practice treats it slice by slice with the local load (the project's envelope note; the thin-slice models of
LTCA).  The contact line of one tooth pair (mean length L, :class:`femgear.physics.contact.crowning.
CrownedContact`) lies in the plane of action at the base helix angle β_b to the axis, so a slice at distance s
from its middle sits at the transverse position u + s sin β_b of the path of contact: its own radii of
curvature ρ1 + s sin β_b and ρ2 − s sin β_b, hence its own reduced radius R = ρ1 ρ2 / ((ρ1 + ρ2) cos β_b),
rolling speeds v_i = ω_i ρ_i, entrainment speed and SRR (:func:`femgear.physics.geometry.kinematics`
conventions).  The load along the line follows the Hertz ellipse of the crowned contact, w(s) ∝ 1 − (s/b_H)²
(b_H its semi-axis along the line), over the loaded part of the line (the shorter of L and 2 b_H), and uniform
for an uncrowned pair; it is scaled so that the slices carry the contact's load F = w̄ L.  Each slice is a :func:`femgear.physics.tehl.line.
solve_tehl_line` contact (all on one grid level, :func:`femgear.physics.tehl.solver.tehl_path_results`).

The slices are the nodes of a quadrature along the line (:func:`slice_nodes`): Gauss–Lobatto where the load is
finite at the line's ends (uncrowned, or crowned with the ellipse longer than the line), so the ends, where the
film is thinnest and the film hottest, are solved; Gauss–Legendre inside a crowned span, whose load vanishes at
its ends.  A line that straddles the pitch point is split there: the friction force turns its sign within a
small slide, and each side is smooth (Gauss–Radau there, with the line's end as its fixed node).

The contact's figures: μ = |Σ W_j μ_c,j w_j| / Σ W_j w_j (W_j the quadrature weights: the friction force of the
slices over the load, signed by each slice's sliding direction: a line that straddles the pitch point has
both), the largest temperatures and pressure and the smallest film over the slices, the central film at the
line's middle (linear between the slices beside it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from femgear.physics.contact.hertz import hertz_point

SLICES = 7   #: face slices of one contact line (odd: the middle one is the contact's centre)
PITCH_MARGIN = 0.05   #: a pitch point closer than this share of the span to a line end does not split the line


@dataclass(frozen=True)
class SliceGeometry:
    """What the slices need beyond the contact's centre values: the pinion and gear speeds [rad/s], the base
    helix angle [rad], the contact-line length of one tooth pair [m] and the summed crowning curvature [1/m]
    (0: uncrowned)."""

    omega1: float
    omega2: float
    beta_b: float
    contact_length: float
    kappa: float


@dataclass(frozen=True)
class SliceResult:
    """A contact solved in face slices (the fields of a TEHL result that the levels read)."""

    hc: float
    hmin: float
    pmax: float
    hc_isothermal: float
    dT_max: float
    dT_surface: float
    mu: float
    error_estimate: dict
    level: int                                 #: the grid level all slices were solved on
    layers: int                                #: the layers across the film all slices were solved with
    s: np.ndarray = field(repr=False)          #: slice centres along the contact line [m]
    load: np.ndarray = field(repr=False)       #: load per length of each slice [N/m]
    results: tuple = field(repr=False, default=())


@dataclass
class SliceLevel:
    """The grid level and the layers across the film the latest face-slice hand-over of a solver ended on: the next
    contact's first try (:func:`slice_contact`'s ``start_level`` and ``nz``), so that a contact whose level or
    layers the probe would miss is not solved twice."""

    level: int | None = None
    layers: int | None = None


def slice_rule(count: int, rule: str) -> tuple[np.ndarray, np.ndarray]:
    """Nodes on [−1, 1] and weights (summing to 2) of a ``count``-point Gauss rule: ``"legendre"`` (no end
    node), ``"lobatto"`` (both ends nodes) or ``"radau"`` (the node −1 and none at +1).  Nodes and weights as
    in Abramowitz & Stegun (1964) §25.4.29–32; ``count`` 1 is the midpoint."""
    if count == 1:
        return np.zeros(1), np.full(1, 2.0)
    P = np.polynomial.Legendre.basis
    if rule == "legendre":
        return np.polynomial.legendre.leggauss(count)
    if rule == "lobatto":
        x = np.concatenate(([-1.0], np.sort(P(count - 1).deriv().roots().real), [1.0]))
        return x, 2.0 / (count * (count - 1) * P(count - 1)(x) ** 2)
    inner = np.sort(((P(count - 1) + P(count)) // np.polynomial.Legendre([1.0, 1.0])).roots().real)
    x = np.concatenate(([-1.0], inner))
    wt = np.concatenate(([2.0 / count**2], (1.0 - inner) / (count**2 * P(count - 1)(inner) ** 2)))
    return x, wt


def slice_nodes(span: float, pitch: float, count: int, ends: bool) -> tuple[np.ndarray, np.ndarray]:
    """Positions s [m] along a loaded line of length ``span`` (centred on 0) and their quadrature weights [m]
    (summing to ``span``): ``count`` Gauss–Lobatto nodes where the load is finite at the ends (``ends``: the
    line's extremes are solved), Gauss–Legendre ones otherwise.  A line that straddles the pitch point (at
    s = ``pitch``, more than :data:`PITCH_MARGIN` of the span inside) is integrated on each side separately, with
    ``count`` // 2 nodes per side (at least 2): the friction force turns its sign there within a small slide, which no
    polynomial over the line follows, and on either side it is smooth.  A side has Gauss–Radau nodes with its
    fixed node at the line's end (``ends``) or Gauss–Legendre nodes: no node at the pitch point itself, whose
    pure-rolling value stands for neither side."""
    half = span / 2
    if not abs(pitch) < half * (1.0 - 2.0 * PITCH_MARGIN):
        x, wt = slice_rule(count, "lobatto" if ends else "legendre")
        return x * half, wt * half
    m = max(count // 2, 2)
    x, wt = slice_rule(m, "radau" if ends else "legendre")
    left = -half + (x + 1.0) * (pitch + half) / 2           # Radau's fixed node at the line's left end
    right = half - (x + 1.0) * (half - pitch) / 2            # ... and, mirrored, at its right end
    s = np.concatenate((left, right[::-1]))
    w = np.concatenate((wt * (pitch + half) / 2, (wt * (half - pitch) / 2)[::-1]))
    return s, w


def slice_inputs(w: float, R: float, ue: float, srr: float, Rx: float, Ry: float, geo: SliceGeometry,
                 E_red: float, count: int = SLICES):
    """(s, w_j, R_j, ue_j, srr_j) of the ``count`` slices of a contact whose centre has load per length ``w``
    [N/m], reduced radius ``R`` [m], entrainment ``ue`` [m/s], SRR ``srr`` (its sign or its magnitude: the side of
    the pitch point is taken from the radius it reproduces) and ellipse radii ``Rx``, ``Ry`` [m]."""
    cb, sb = math.cos(geo.beta_b), math.sin(geo.beta_b)
    best = None
    for sign in (1.0, -1.0):        # the side of the pitch point whose radii give R
        v1, v2 = ue * (1 + sign * abs(srr) / 2), ue * (1 - sign * abs(srr) / 2)
        r1, r2 = v1 / geo.omega1, v2 / geo.omega2
        miss = abs(r1 * r2 / ((r1 + r2) * cb) / R - 1.0) if r1 > 0 and r2 > 0 else math.inf
        if best is None or miss < best[0]:
            best = (miss, r1, r2)
    _, r1, r2 = best
    L = geo.contact_length
    crowned = geo.kappa > 0 and np.isfinite(Ry)
    bH = hertz_point(w * L, Rx, Ry, E_red).b if crowned else math.inf
    span = min(L, 2.0 * bH)         # the loaded part of the line
    pitch = (geo.omega2 * r2 - geo.omega1 * r1) / ((geo.omega1 + geo.omega2) * sb) if sb > 0 else math.inf
    s, weights = slice_nodes(span, pitch, count, ends=not (crowned and 2.0 * bH < L))
    d = s * sb
    lo = 1e-3 * min(r1, r2)
    rho1, rho2 = np.maximum(r1 + d, lo), np.maximum(r2 - d, lo)
    Rj = rho1 * rho2 / ((rho1 + rho2) * cb)
    v1, v2 = geo.omega1 * rho1, geo.omega2 * rho2
    uej = 0.5 * (v1 + v2)
    srrj = (v1 - v2) / uej
    shape = 1.0 - (s / bH) ** 2 if crowned else np.ones(s.size)
    wj = shape * (w * L / np.dot(weights, shape))     # the slices carry F = w L
    return s, wj, Rj, uej, srrj, weights


def slice_contact(w: float, R: float, ue: float, srr: float, T: float, Rx: float, Ry: float, geo: SliceGeometry,
                  setup, count: int = SLICES, start_level: int | None = None, **options) -> SliceResult:
    """The contact as ``count`` line TEHL slices (module docstring); ``setup`` a
    :class:`femgear.physics.tehl.solver.TEHLSetup`, ``start_level`` the level to try first (the previous
    contact's :attr:`SliceResult.level`, :func:`femgear.physics.tehl.solver.tehl_path_results`), ``options`` to
    :func:`femgear.physics.tehl.line.solve_tehl_line`."""
    from femgear.physics.tehl.solver import _level_of_nodes, tehl_path_results

    s, wj, Rj, uej, srrj, weights = slice_inputs(w, R, ue, srr, Rx, Ry, geo, setup.E_red, count)
    rs = tehl_path_results(wj, Rj, uej, srrj, T, setup, start_level=start_level, **options)
    force = float(np.dot(weights, [r.mu_couette * wi for r, wi in zip(rs, wj)]))
    centre = lambda name: float(np.interp(0.0, s, [getattr(r, name) for r in rs]))  # noqa: E731
    est = [max(v for v in r.error_estimate.values() if v is not None) for r in rs]
    return SliceResult(hc=centre("hc"), hmin=min(r.hmin for r in rs), pmax=max(r.pmax for r in rs),
                       hc_isothermal=centre("hc_isothermal"), dT_max=max(r.dT_max for r in rs),
                       dT_surface=max(r.dT_surface for r in rs), mu=abs(force) / float(np.dot(weights, wj)),
                       error_estimate={"hc": max(est), "hmin": max(est)},
                       level=_level_of_nodes(rs[0].nodes), layers=rs[0].layers, s=s, load=wj, results=tuple(rs))
