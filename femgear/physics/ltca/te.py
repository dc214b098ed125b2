"""Transmission error, its mesh harmonics, the stiffness, the load share and the peak pressure of an LTCA cycle.

:func:`analyse_cycle` reads one :class:`femgear.physics.ltca.analysis.LTCAResult` (a mesh cycle at one load)
and returns a frozen :class:`TEAnalysis`; :func:`harris_map` runs the cycle over a torque range (Smith,
*Gear Noise and Vibration*, 2003, ch. 5: loaded TE peak-to-peak against load, with and without the
modification).  Pure: arrays and typed results, SI units; no file is written here.

Conventions (those of :mod:`femgear.physics.ltca.analysis`):

- the loaded TE is the rigid normal approach δ of the flanks along the line of action [m] (the
  pinion is axially fixed, so both helices share it); on the transverse base tangent it is δ / cos β_b;
- its peak-to-peak is ``np.ptp(lte)`` and its mesh-order amplitudes 2 |c_h| of the discrete Fourier
  series over the ``n_phases`` equally spaced phases of one mesh period (``LTCAResult.harmonics``);
- the per-helix TE (``lte_left``/``lte_right``, :func:`helix_alone_te`) is the normal approach of each
  helix carrying its cycle-mean share of the load alone (the other helix unloaded): the TE the helix
  would excite as a single-helical mesh on the same body.  Its difference to the common δ shows how
  the double helix averages the two;
- the unloaded (kinematic) TE is min ε over the contact lines at each phase (``nlte``);
- the mesh stiffness is the total secant stiffness k_s,left + k_s,right [N/m] (normal line of action),
  ``ripple`` its peak-to-peak over its mean.

The largest contact pressure is the Hertz line-contact pressure √(w E′/(2πR)) of the contact points
(R the normal relative radius of curvature).  At the first and last point of every contact line the
line meets an edge of the active flank (the tip of either member or a face end): there the Hertz
line contact does not hold (an edge contact, whose pressure it does not give), so the peak carries
``edge`` and the largest pressure away from the edges is kept beside it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from femgear.docfields import document_fields
from femgear.errors import ArgumentError, SceneError
from femgear.physics.geometry.gear import GearPair
from femgear.physics.ltca.halfspace import hertz_pressure, reduced_modulus

MAX_NOMINAL_CONTACT_STRESS = 4.0e9   #: [Pa] σ_H0 above which a torque is refused (past any gear steel's static limit)
MAX_TORQUES = 50                     #: torques one ``femgear ltca`` call accepts


@document_fields
@dataclass(frozen=True)
class PressurePeak:
    """The largest contact pressure of a cycle and where it sits."""

    pressure: float
    """largest Hertz pressure over all contact points and phases of the cycle [Pa]"""
    phase: float
    """mesh phase of that point [base pitches]"""
    helix: str
    """the helix of that point, "left" or "right" (a single-helical or spur pair: "left", its one helix) [-]"""
    u: float
    """path position of that point, measured from T1 (= the pinion roll distance ρ₁; the pitch point is at T1C) [m]"""
    zeta: float
    """face coordinate of the helix (groove / apex end at ζ = b) [m]"""
    edge: bool
    """whether the point is a contact line's end on an edge of the active flank (tip or face end: the Hertz line contact
    does not hold there) [-]"""
    where: str
    """where the point sits: "interior", "pinion tip", "gear tip", "outer face end" or "groove face end" (one
    helix: "face end") [-]"""
    interior_pressure: float
    """largest pressure away from the flank edges (not on a contact line's end point) [Pa]"""


@document_fields
@dataclass(frozen=True)
class TEAnalysis:
    """Loaded and unloaded TE, stiffness, load share and peak pressure of one LTCA cycle (SI)."""

    torque: float
    """driver torque of the cycle [N m]"""
    force: float
    """total normal force of both helices, T / r_b / cos β_b [N]"""
    phase: np.ndarray
    """phases of one mesh period, [0, 1) [base pitches]"""
    lte: np.ndarray
    """loaded TE: the common normal approach δ of both helices along the normal line of action at each phase [m]"""
    lte_left: np.ndarray | None
    """loaded TE of the left helix carrying its cycle-mean share of the load alone (None: not computed) [m]"""
    lte_right: np.ndarray | None
    """loaded TE of the right helix carrying its cycle-mean share of the load alone (None: not computed) [m]"""
    nlte: np.ndarray
    """unloaded (kinematic) TE: min ε over the contact lines of both helices at each phase [m]"""
    force_left: np.ndarray
    """normal load carried by the left helix at each phase [N]"""
    force_right: np.ndarray
    """normal load carried by the right helix at each phase [N]"""
    k_total: np.ndarray
    """total secant mesh stiffness k_s,left + k_s,right along the normal line of action at each phase [N/m]"""
    peak_to_peak: float
    """loaded TE peak-to-peak over the cycle [m]"""
    harmonics: np.ndarray
    """loaded TE amplitudes 2|c_h| at mesh orders 1…N (single-sided, peak) [m]"""
    nlte_peak_to_peak: float
    """unloaded TE peak-to-peak over the cycle [m]"""
    stiffness_mean: float
    """cycle mean of the total secant mesh stiffness, along the normal line of action [N/m]"""
    stiffness_ripple: float
    """peak-to-peak of the total secant mesh stiffness over its mean [-]"""
    share_left: float | None
    """cycle mean of F_left / F (None for a one-helix pair: no load share) [-]"""
    share_right: float | None
    """cycle mean of F_right / F (None for a one-helix pair) [-]"""
    balance_error: float
    """largest relative force balance error over the phases, |F_left + F_right − F| / F [-]"""
    pressure: PressurePeak
    """the largest contact pressure of the cycle and where it sits [-]"""
    worst_phase: int
    """index into ``phase`` of the phase holding the largest pressure [-]"""
    interior_force: np.ndarray | None = None
    """(2, n_phases) normal load of each helix away from the flank edges (not on a contact line's end point) [N]"""
    harmonics_refined: np.ndarray | None = None
    """loaded TE amplitudes with twice the points per contact line (None: no refinement run) [m]"""
    peak_to_peak_refined: float | None = None
    """loaded TE peak-to-peak with twice the points per contact line (None: no refinement run) [m]"""
    n_helices: int = 2
    """helices of the pair: 2, or 1 (single-helical, spur: the mesh is the left helix; no share, no right fields) [-]"""

    @property
    def harmonics_change(self) -> np.ndarray | None:
        """|H(2n) − H(n)| over the largest refined amplitude, per order: the discretisation error estimate."""
        if self.harmonics_refined is None:
            return None
        return np.abs(self.harmonics_refined - self.harmonics) / max(float(self.harmonics_refined.max()), 1e-300)


def line_ends(arr: np.ndarray) -> np.ndarray:
    """Mask of the contact points (rows of a ``line_load`` array) that are the first or last point of their line."""
    edge = np.zeros(arr.shape[0], bool)
    for h in (0, 1):
        for j in np.unique(arr[arr[:, 0] == h, 1]):
            idx = np.nonzero((arr[:, 0] == h) & (arr[:, 1] == j))[0]
            z = arr[idx, 3]
            edge[idx[np.argmin(z)]] = edge[idx[np.argmax(z)]] = True
    return edge


def point_pressures(result, pair: GearPair, youngs_modulus: float, poisson_ratio: float, i: int):
    """(p [Pa], edge mask) of the contact points of phase ``i`` (``result.line_load``, keep_lines=True)."""
    arr = result.line_load[i]
    cb = math.cos(pair.beta_b)
    u, w = arr[:, 2], arr[:, 4]
    R = u * (pair.line_of_action - u) / pair.line_of_action / cb
    return hertz_pressure(w, R, reduced_modulus(youngs_modulus, poisson_ratio)), line_ends(arr)


def _where(pair: GearPair, u: float, zeta: float, half_du: float, half_dz: float, edge: bool) -> str:
    if not edge:
        return "interior"
    if u + half_du >= pair.u_end - 1e-9 * pair.m_n:
        return "pinion tip"
    if u - half_du <= pair.u_start + 1e-9 * pair.m_n:
        return "gear tip"
    if pair.n_helices == 1:
        return "face end"
    return "groove face end" if zeta + half_dz >= 0.5 * pair.b else "outer face end"


def pressure_peak(result, pair: GearPair, youngs_modulus: float, poisson_ratio: float) -> tuple[PressurePeak, int]:
    """The :class:`PressurePeak` of a cycle and the index of its phase."""
    best, inner, worst, where = -1.0, 0.0, 0, None
    for i, arr in enumerate(result.line_load):
        p, edge = point_pressures(result, pair, youngs_modulus, poisson_ratio, i)
        if (~edge).any():
            inner = max(inner, float(p[~edge].max()))
        k = int(np.argmax(p))
        if p[k] > best:
            best, worst = float(p[k]), i
            dz = 0.5 * result.line_length[i][k] * math.cos(pair.beta_b)
            where = (int(arr[k, 0]), float(arr[k, 2]), float(arr[k, 3]), bool(edge[k]),
                     _where(pair, float(arr[k, 2]), float(arr[k, 3]), dz * math.tan(pair.beta_b), dz, bool(edge[k])))
    h, u, z, e, label = where
    return PressurePeak(best, float(result.phase[worst]), ("left", "right")[h], u, z, e, label, inner), worst


def interior_force(result) -> np.ndarray:
    """(2, n_phases): the normal load of each helix on contact points that are not a line's end [N]."""
    out = np.zeros((2, result.phase.size))
    for i, arr in enumerate(result.line_load):
        edge = line_ends(arr)
        f = arr[:, 4] * result.line_length[i]
        for h in (0, 1):
            out[h, i] = float(f[(arr[:, 0] == h) & ~edge].sum())
    return out


def analyse_cycle(result, pair: GearPair, youngs_modulus: float, poisson_ratio: float, torque: float,
                  n_harmonics: int = 5, helix_te: tuple[np.ndarray, np.ndarray] | None = None,
                  refined=None) -> TEAnalysis:
    """The :class:`TEAnalysis` of one LTCA cycle ``result`` (run with keep_lines=True) at driver ``torque`` [N m].

    ``helix_te``: (left, right) of :func:`helix_alone_te`; ``refined``: the same cycle with twice the points
    per contact line (its TE harmonics and p-p are kept as the discretisation check)."""
    n_max = result.phase.size // 2 - 1
    if not 1 <= n_harmonics <= n_max:
        raise ValueError(f"n_harmonics must be 1…{n_max} for {result.phase.size} phases, got {n_harmonics}")
    if not result.line_load:
        raise ValueError("analyse_cycle needs the line loads: run mesh_cycle(..., keep_lines=True)")
    F = result.force
    k = result.k_secant
    peak, worst = pressure_peak(result, pair, youngs_modulus, poisson_ratio)
    left, right = (None, None) if helix_te is None or pair.n_helices == 1 else helix_te
    two = pair.n_helices == 2
    return TEAnalysis(
        torque=float(torque), force=float(F), phase=result.phase, lte=result.lte, lte_left=left, lte_right=right,
        nlte=result.nlte, force_left=result.force_left, force_right=result.force_right, k_total=k,
        peak_to_peak=result.lte_peak_to_peak(), harmonics=result.harmonics(n_harmonics),
        nlte_peak_to_peak=float(np.ptp(result.nlte)), stiffness_mean=result.mean_stiffness(),
        stiffness_ripple=float(np.ptp(k) / np.mean(k)), share_left=float(np.mean(result.force_left) / F) if two else None,
        share_right=float(np.mean(result.force_right) / F) if two else None,
        balance_error=float(np.max(np.abs(result.force_left + result.force_right - F)) / F),
        pressure=peak, worst_phase=worst, interior_force=interior_force(result),
        harmonics_refined=None if refined is None else refined.harmonics(n_harmonics),
        peak_to_peak_refined=None if refined is None else refined.lte_peak_to_peak(), n_helices=pair.n_helices)


def helix_alone_te(model, result, modifications=None, extra=None) -> tuple[np.ndarray, np.ndarray]:
    """(left, right): the normal approach of each helix carrying its cycle-mean share of ``result``'s load alone.

    The same contact points, separations and compliance as ``result`` (``result.n_line``, ``result.stagger``),
    restricted to one helix (:func:`femgear.physics.ltca.contact.solve_phase` on its points; the other helix unloaded,
    so the cross-helix compliance does not act).  NaN for a helix with no mean load.  A one-helix pair has no such
    split: ValueError (its cycle's TE is the helix's own)."""
    from femgear.physics.ltca.contact import ContactPoints, phase_points, solve_phase
    from femgear.physics.ltca.separation import separation

    pair, E, nu = model.pair, model.youngs_modulus, model.poisson_ratio
    if pair.n_helices == 1:
        raise ValueError(f"a {pair.kind} pair has one helix: its cycle's loaded TE is the helix's own")
    n_line, stagger = int(result.n_line), float(result.stagger)
    share = (float(np.mean(result.force_left)), float(np.mean(result.force_right)))
    out = np.full((2, result.phase.size), np.nan)
    for i, ph in enumerate(result.phase):
        pts = phase_points(pair, float(ph), stagger, n_line)
        for h, name in enumerate(("left", "right")):
            if share[h] <= 0:
                continue
            s = pts.helix == h
            sub = ContactPoints(pts.helix[s], pts.line[s], pts.u[s], pts.zeta[s], pts.length[s],
                                None if pts.tooth is None else pts.tooth[s])
            eps = separation(pair, modifications, name, sub.u, sub.zeta, extra)
            sol, _, _ = solve_phase(pair, model.kernels, sub, eps, share[h], E, nu, case=f"LTCA {name} helix {ph:.4f}")
            out[h, i] = sol.approach
    return out[0], out[1]


def nominal_contact_stress(pair: GearPair, pinion_torque: float, youngs_modulus: float, poisson_ratio: float) -> float:
    """ISO 6336-2 nominal contact stress σ_H0 at ``pinion_torque`` [Pa] (all load factors 1)."""
    from femgear.physics.rating import contact_stress

    return float(contact_stress(pair, pinion_torque, youngs_modulus, poisson_ratio).sigma_H0)


def check_torques(torques, pair: GearPair, youngs_modulus: float, poisson_ratio: float, driver: str = "pinion",
                  key: str = "--torques") -> tuple[float, ...]:
    """The torques [N m] as floats, or :class:`ArgumentError` naming ``key``: empty, more than
    :data:`MAX_TORQUES`, not finite, ≤ 0, or so large that the nominal contact stress σ_H0 exceeds
    :data:`MAX_NOMINAL_CONTACT_STRESS` (a linear-elastic LTCA no longer applies)."""
    values = tuple(float(t) for t in torques)
    if not values:
        raise ArgumentError(key, "no torque given (e.g. --torques 100,200,300)")
    if len(values) > MAX_TORQUES:
        raise ArgumentError(key, f"{len(values)} torques, at most {MAX_TORQUES}")
    ratio = pair.z2 / pair.z1 if driver == "gear" else 1.0
    for t in values:
        if not math.isfinite(t) or t <= 0:
            raise ArgumentError(key, f"torque {t:g} N m must be positive and finite")
        s = nominal_contact_stress(pair, t / ratio, youngs_modulus, poisson_ratio)
        if s > MAX_NOMINAL_CONTACT_STRESS:
            raise ArgumentError(key, f"torque {t:g} N m gives a nominal contact stress σ_H0 {s / 1e9:.2f} GPa, over "
                                f"{MAX_NOMINAL_CONTACT_STRESS / 1e9:g} GPa (past the static strength of gear steels)")
    return values


def modified_keys(modifications) -> list[str]:
    """The ``modifications.*`` keys with a non-zero amount (for a message naming what the user set)."""
    if modifications is None:
        return []
    keys = [f"modifications.{k}" for k in ("helix_slope_deviation_left", "helix_slope_deviation_right")
            if getattr(modifications, k)]
    for part in ("", "pinion.", "gear."):
        mod = modifications if not part else getattr(modifications, part[:-1])
        if mod is None:
            continue
        keys += [f"modifications.{part}{k}" for k in ("tip_relief", "root_relief", "crowning", "end_relief")
                 if getattr(mod, k)]
        keys += [f"modifications.{part}topography"] if mod.topography is not None else []
    return keys


def check_contact(analysis: TEAnalysis, modifications, tolerance: float = 1e-6) -> None:
    """:class:`SceneError` naming the modification keys if, at some phase of this load, a helix carries no load away
    from the flank edges (less than ``tolerance`` of the force): its flanks lost contact everywhere but, at most,
    on the end points of the contact lines (a misalignment leaving only the apex ends, a relief or crowning that
    opens the flanks more than they deflect)."""
    inner = analysis.interior_force
    if inner is None:
        inner = np.array([analysis.force_left, analysis.force_right])
    names = ("the left helix", "the right helix") if analysis.n_helices == 2 else ("the helix",)
    for h, name in enumerate(names):
        lost = np.nonzero(inner[h] <= tolerance * analysis.force)[0]
        if lost.size:
            keys = modified_keys(modifications) or ["modifications"]
            raise SceneError(", ".join(keys), f"{name} loses contact at {lost.size} of {inner[h].size} "
                             f"phases (first at phase {analysis.phase[lost[0]]:.3f}; load only at the flank edges, if "
                             f"any) at the design load {analysis.torque:g} N m: the modification opens its flanks "
                             "more than they deflect")


@dataclass(frozen=True)
class HarrisMap:
    """Loaded TE peak-to-peak against torque, with the scene's modification and without (SI)."""

    torque: np.ndarray              #: driver torques [N m]
    force: np.ndarray               #: total normal forces [N]
    peak_to_peak: np.ndarray        #: with the modification [m]
    peak_to_peak_unmodified: np.ndarray
    first_harmonic: np.ndarray      #: mesh order 1 amplitude, with the modification [m]
    first_harmonic_unmodified: np.ndarray
    design_torque: float            #: [N m]


def harris_map(model, torques, modifications, design_torque: float, driver: str = "pinion", n_phases: int = 64,
               n_line: int = 16, stagger: float = 0.0) -> HarrisMap:
    """:class:`HarrisMap` over ``torques`` [N m] (:func:`femgear.physics.ltca.analysis.mesh_cycle` at each, both flank
    states)."""
    from femgear.physics.ltca.analysis import mesh_cycle, normal_force

    rows = []
    for t in torques:
        F = normal_force(model.pair, float(t), driver)
        mod = mesh_cycle(model, F, modifications, n_phases=n_phases, n_line=n_line, stagger=stagger, keep_lines=False)
        ref = mesh_cycle(model, F, None, n_phases=n_phases, n_line=n_line, stagger=stagger, keep_lines=False)
        rows.append((F, mod.lte_peak_to_peak(), ref.lte_peak_to_peak(), mod.harmonics(1)[0], ref.harmonics(1)[0]))
    a = np.array(rows, float).reshape(-1, 5)
    return HarrisMap(np.asarray(torques, float), a[:, 0], a[:, 1], a[:, 2], a[:, 3], a[:, 4], float(design_torque))


def one_phase(result, i: int):
    """``result`` with only the line loads of phase ``i`` (for a map of that phase's load distribution)."""
    return replace(result, line_load=(result.line_load[i],), line_length=(result.line_length[i],))


__all__ = ["HarrisMap", "PressurePeak", "TEAnalysis", "analyse_cycle", "check_contact", "check_torques",
           "harris_map", "helix_alone_te", "interior_force", "line_ends", "modified_keys", "nominal_contact_stress", "one_phase",
           "point_pressures", "pressure_peak"]
