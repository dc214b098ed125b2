"""Loaded tooth contact analysis over one mesh cycle: TE, stiffness, loads, pressures.

:func:`build_model` computes (or reads from the disk cache) the bulk flank kernels of
both members once; :func:`mesh_cycle` solves the contact problem at ``n_phases`` phases
of one mesh period for a transmitted normal force, both helices together (pinion
axially fixed: both helices share the rigid normal approach δ).  A single-helical or spur
pair (``pair.n_helices`` = 1) is one helix of its real face width on one-helix member bodies:
its "left" fields carry the mesh, the "right" ones are zero (``LTCAResult.n_helices``).

Outputs per phase (all along the normal line of action, SI):
- ``lte``: loaded transmission error δ [m] (transverse, on the base tangent: δ / cos β_b);
- ``nlte_left/right``: unloaded (kinematic) TE min ε per helix, from a dense sampling of
  the contact lines (8× the contact points);
- ``force_left/right``: normal load carried by each helix [N];
- ``k_secant_*`` = F_h / (δ − NLTE_h), ``k_tangent_*`` = dF_h/dδ by a +0.1 % load step [N/m];
- ``p_max_*``: largest Hertz pressure √(w E′/(2πR)) on the helix [Pa];
- ``line_load``: per phase, (helix, line, ζ, load per length w) of every point.

Dynamics input (:meth:`LTCAResult.excitation`): with the mesh law N_s = k_s(φ)·f(δ_s −
e_s), the LTCA reproduces its own loads at the operating point with the secant
stiffness and e_s = LTE − F_s/k_s (= NLTE_s).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np

from femgear.docfields import document_fields
from femgear.perf import Progress
from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.lines import hat_integrals
from femgear.physics.ltca.compliance import MemberCompliance, member_compliance
from femgear.physics.ltca.contact import phase_matrix, phase_points, solve_phase
from femgear.physics.ltca.halfspace import hertz_pressure, reduced_modulus
from femgear.physics.ltca.separation import Deviation, check_modification, separation
from femgear.physics.mesh.segment import default_spec


@document_fields
@dataclass(frozen=True)
class LTCAModel:
    """Pair, material and the bulk kernels of both members (build once, reuse)."""

    pair: GearPair
    """the gear pair the member bodies were built for [-]"""
    youngs_modulus: float
    """Young's modulus of both members [Pa]"""
    poisson_ratio: float
    """Poisson's ratio of both members [-]"""
    kernels: dict
    """bulk flank compliance of each member body, {1: pinion, 2: gear}
    (:class:`femgear.physics.ltca.compliance.MemberCompliance`) [-]"""
    level: int
    """body resolution level the member bodies were meshed at (``numerics.body_level``) [-]"""
    seconds: float
    """wall time to build (or read from the disk cache) both kernels [s]"""
    stagger: float = 0.0
    """the stagger the member bodies were built with [base pitches]"""


def build_model(pair: GearPair, youngs_modulus: float, poisson_ratio: float, level: int = 1, order: int | str = 1,
                n_rho: int = 7, n_z: int = 9, n_teeth: int = 5, cache: bool = True,
                bore_radius: tuple[float, float] = (0.0, 0.0), groove_width: float = 0.0,
                stagger: float = 0.0, spec_options: dict | None = None) -> LTCAModel:
    """Flank kernels of pinion and gear at body resolution ``level`` (see :func:`default_spec`).

    Each member is one body holding both helices, the groove of ``groove_width`` and the rim down to
    ``bore_radius`` (per member; 0: r_f − 3 m_n), the right helix staggered by ``stagger`` base pitches
    (:mod:`femgear.physics.mesh.segment`); :func:`femgear.levels.stiffness.body_options` reads these from a
    case.  ``spec_options``:
    other :class:`femgear.physics.mesh.segment.SegmentSpec` fields (the far-field grading of a study).
    """
    t0 = time.perf_counter()
    kernels: dict[int, MemberCompliance] = {}
    for member in (1, 2):
        spec = default_spec(pair, member, level, n_teeth=n_teeth, r_bore=bore_radius[member - 1],
                            groove=groove_width, stagger=stagger)
        if spec_options:
            spec = replace(spec, **spec_options)
        kernels[member] = member_compliance(pair, member, spec, youngs_modulus, poisson_ratio, order=order,
                                            n_rho=n_rho, n_z=n_z, cache=cache)
    return LTCAModel(pair, youngs_modulus, poisson_ratio, kernels, level, time.perf_counter() - t0, stagger)


@document_fields
@dataclass(frozen=True)
class LTCAResult:
    """LTCA of one mesh cycle (arrays over ``phase`` in base pitches, [0, 1))."""

    phase: np.ndarray
    """mesh phases of the cycle over one mesh period, [0, 1) [base pitches]"""
    force: float
    """total normal force of both helices the cycle carries [N]"""
    lte: np.ndarray
    """loaded transmission error: the rigid normal approach δ of the flanks along the normal line of action at each
    phase (on the transverse base tangent δ / cos β_b) [m]"""
    nlte_left: np.ndarray
    """unloaded (kinematic) TE of the left helix: min ε over its contact lines at each phase [m]"""
    nlte_right: np.ndarray
    """unloaded (kinematic) TE of the right helix at each phase [m]"""
    force_left: np.ndarray
    """normal load carried by the left helix at each phase [N]"""
    force_right: np.ndarray
    """normal load carried by the right helix at each phase [N]"""
    k_secant_left: np.ndarray
    """secant stiffness of the left helix, F_left / (δ − NLTE_left), along the normal line of action [N/m]"""
    k_secant_right: np.ndarray
    """secant stiffness of the right helix, F_right / (δ − NLTE_right), along the normal line of action [N/m]"""
    k_tangent_left: np.ndarray
    """tangent stiffness of the left helix dF/dδ by a +0.1 % load step [N/m]"""
    k_tangent_right: np.ndarray
    """tangent stiffness of the right helix dF/dδ by a +0.1 % load step [N/m]"""
    p_max_left: np.ndarray
    """largest Hertz pressure √(w E′/(2πR)) on the left helix at each phase [Pa]"""
    p_max_right: np.ndarray
    """largest Hertz pressure on the right helix at each phase [Pa]"""
    load_error: np.ndarray
    """relative force balance error |Σf − F| / F at each phase [-]"""
    line_load: tuple = ()
    """per phase: array (n, 5) of helix (0 left, 1 right), line index, u from T1 [m], ζ [m], load per length w [N/m] of
    every contact point (empty unless kept) [-]"""
    line_length: tuple = ()
    """per phase: the contact-line segment length Δℓ of each point [m]"""
    seconds: float = 0.0
    """wall time of the cycle's contact solves [s]"""
    n_line: int = 0
    """points per contact line the cycle was solved with [-]"""
    stagger: float = 0.0
    """offset of the right helix against the left one the cycle was solved with [base pitches]"""
    groove: float = 0.0
    """width of the member bodies' groove between the helices [m]"""
    n_helices: int = 2
    """helices of the pair: 2 double-helical; 1 single-helical or spur (the mesh is the "left" helix, the "right"
    fields are zero) [-]"""

    @property
    def helices(self) -> tuple[str, ...]:
        """The names of the helices the cycle has: ("left", "right") or ("left",)."""
        return ("left", "right")[:self.n_helices]

    @property
    def nlte(self) -> np.ndarray:
        return self.nlte_left if self.n_helices == 1 else np.minimum(self.nlte_left, self.nlte_right)

    def lte_peak_to_peak(self) -> float:
        return float(np.ptp(self.lte))

    def harmonics(self, n: int = 5) -> np.ndarray:
        """Amplitudes of the LTE at mesh orders 1…n [m]."""
        c = np.fft.rfft(self.lte) / self.lte.size
        return 2 * np.abs(c[1:n + 1])

    @property
    def k_secant(self) -> np.ndarray:
        return self.k_secant_left + self.k_secant_right

    def mean_stiffness(self) -> float:
        """Cycle mean of the total secant mesh stiffness [N/m]."""
        return float(np.mean(self.k_secant))

    def loads_per_line(self, i: int) -> dict[tuple[str, int], float]:
        """Total normal load [N] of each contact line at phase index ``i``: {(helix, line index): F}."""
        if not self.line_load:
            raise ValueError("no line loads kept: run mesh_cycle(..., keep_lines=True)")
        arr = self.line_load[i]
        out: dict[tuple[str, int], float] = {}
        for h, name in enumerate(self.helices):
            s = arr[:, 0] == h
            for j in np.unique(arr[s, 1]).astype(int):
                m = s & (arr[:, 1] == j)
                out[(name, int(j))] = float(np.sum(arr[m, 4] * self.line_length[i][m]))
        return out

    def _path_lines(self, pair: GearPair, u: np.ndarray):
        """Per phase i and helix h, each contact line's grid positions: (i, h, on-mask, u_j, w_j, ζ(u), F,
        (u_lo, u_hi)) with the line's point positions u_j and loads w_j sorted in u, the face coordinate of u
        on it, the line's load F = Σ w_j Δℓ_j [N] and its extent in u (half a segment beyond the end points)."""
        if not self.line_load:
            raise ValueError("no line loads kept: run mesh_cycle(..., keep_lines=True)")
        if pair.beta_b == 0:
            raise ValueError("a spur contact line lies at one path position: its loads make no (phase, u) map "
                             "(the spur pair shares the load by the Winkler layer of the level's pair stiffness)")
        tb = math.tan(pair.beta_b)
        half = 0.5 * math.cos(pair.beta_b) * tb   # Δu of half a segment per unit Δℓ
        for i, arr in enumerate(self.line_load):
            dl = self.line_length[i]
            for h in range(self.n_helices):
                for j in np.unique(arr[arr[:, 0] == h, 1]):
                    m = (arr[:, 0] == h) & (arr[:, 1] == j)
                    order = np.argsort(arr[m, 2])
                    uj, wj, zj, lj = arr[m, 2][order], arr[m, 4][order], arr[m, 3][order], dl[m][order]
                    lo, hi = uj[0] - half * lj[0], uj[-1] + half * lj[-1]
                    on = (u >= lo) & (u <= hi)
                    yield i, h, on, uj, wj, zj[0] + (u[on] - uj[0]) / tb, float(wj @ lj), (lo, hi)

    def path_load(self, pair: GearPair, u: np.ndarray, scaled: bool = False) -> np.ndarray:
        """Load per unit contact-line length w' at the path positions ``u`` [N/m]: (helix, phase, position).

        For each phase and helix, every grid position u on a contact line takes the linear
        interpolant of the line's point loads in u (constant beyond the first and last segment
        centre up to the line's ends, which lie half a segment further); 0 off the lines.  The
        points of a helical line have distinct u (u = u₀ + ζ tan β_b), so a line is a function
        of u.  Where lines of one helix overlap in u (overlap ratio ε_β > 1) the loads of the
        covering lines are averaged (the face-uniform reading of :mod:`femgear.physics.wear.load_sharing`).

        ``scaled``: each line's grid loads are scaled to carry the line's LTCA load, Σ_k w'_k H_k / sin β_b
        = Σ w'_p Δℓ_p with H_k the line's exact hat-function weights
        (:func:`femgear.physics.geometry.lines.hat_integrals`; nodes of the grid outside the line count 0).  Without it a line
        piece much shorter than the grid spacing (where a contact line meets a tip edge, its
        one point can carry 30× the mean w') would count over a whole grid cell (up to 3× the
        helix force at that phase on the level-1 model with 61 positions).
        """
        u = np.asarray(u, float)
        out = np.zeros((2, self.phase.size, u.size))
        hits = np.zeros(out.shape)
        for i, h, on, w, _ in self._grid_lines(pair, u, scaled):
            out[h, i, on] += w
            hits[h, i, on] += 1
        return out / np.maximum(hits, 1)

    def _grid_lines(self, pair: GearPair, u: np.ndarray, scaled: bool):
        """Per phase i, helix h and contact line: (i, h, on-mask, w' at u[on], ζ at u[on]), the line's loads
        interpolated in u and, if ``scaled``, scaled to carry its LTCA load (:meth:`path_load`)."""
        sb = math.sin(pair.beta_b)
        for i, h, on, uj, wj, zeta, carried, (lo, hi) in self._path_lines(pair, u):
            w = np.interp(u[on], uj, wj)
            grid = float(w @ hat_integrals(u, lo, hi)[on]) / sb if scaled else 0.0
            yield i, h, on, (w * (carried / grid) if grid > 0 else w), zeta

    def path_zeta(self, pair: GearPair, u: np.ndarray) -> np.ndarray:
        """Face coordinate ζ of the contact-line point at the path positions ``u`` [m]: (helix, phase, position),
        NaN off the lines; the companion of :meth:`path_load` for the face-resolved wear
        (:mod:`femgear.physics.wear.face`).  Raises where lines of one helix overlap in u (ε_β > 1: two face
        positions at one (phase, u), which the (phase, u) grid cannot hold)."""
        u = np.asarray(u, float)
        out = np.full((2, self.phase.size, u.size), np.nan)
        for i, h, on, _, zeta in self._grid_lines(pair, u, False):
            if np.any(np.isfinite(out[h, i, on])):
                raise ValueError("path_zeta: contact lines of one helix overlap in u (overlap ratio > 1); "
                                 "the face-resolved wear needs one line per helix at each path position")
            out[h, i, on] = zeta
        return out

    def path_approach(self, pair: GearPair, u: np.ndarray, modifications=None, extra: Deviation | None = None):
        """Elastic approach δ − ε at the path positions ``u`` on the contact lines [m]: (helix, phase, position).

        δ: the cycle's loaded TE (normal approach) at that phase; ε: the initial separation of
        the flanks (:func:`femgear.physics.ltca.separation.separation`) at the point of the line at u,
        for the ``modifications`` and ``extra`` deviation the cycle was run with.  Positive where
        the flanks are pressed together (the load there over it is the local secant stiffness),
        negative at an open gap; NaN off the lines (the mean of overlapping lines, as
        :meth:`path_load`).
        """
        u = np.asarray(u, float)
        out = np.zeros((2, self.phase.size, u.size))
        hits = np.zeros(out.shape)
        for i, h, on, _, _, zeta, _, _ in self._path_lines(pair, u):
            eps = separation(pair, modifications, ("left", "right")[h], u[on], zeta, extra)
            out[h, i, on] += self.lte[i] - eps
            hits[h, i, on] += 1
        return np.where(hits > 0, out / np.maximum(hits, 1), np.nan)

    def excitation(self) -> dict[str, np.ndarray]:
        """Per helix: secant/tangent stiffness, loaded and unloaded TE, e_s = LTE − F_s/k_s (SI); the absent right
        helix of a one-helix pair has zero stiffness and force (its e_s is the LTE: it never carries)."""
        out = {"phase": self.phase}
        for h in ("left", "right"):
            k = getattr(self, f"k_secant_{h}")
            F = getattr(self, f"force_{h}")
            e = unloaded_te(self.lte, F, k)
            out.update({f"k_secant_{h}": k, f"k_tangent_{h}": getattr(self, f"k_tangent_{h}"), f"lte_{h}": self.lte,
                        f"nlte_{h}": getattr(self, f"nlte_{h}"), f"e_{h}": e, f"force_{h}": F,
                        f"p_max_{h}": getattr(self, f"p_max_{h}")})
        return out


def unloaded_te(lte: np.ndarray, force: np.ndarray, k_secant: np.ndarray) -> np.ndarray:
    """e_s = LTE − F_s/k_s: the kinematic error with which the secant mesh law
    N_s = k_s (δ − e_s) reproduces the LTCA's loads; LTE where the helix carries no load."""
    return lte - force / np.where(k_secant > 0, k_secant, np.inf)


def normal_force(pair: GearPair, torque: float, driver: str = "pinion") -> float:
    """Total normal force of the mesh (both helices, or the one) for ``torque`` on the driver [N]: T / r_b / cos β_b."""
    rb = pair.rb1 if driver == "pinion" else pair.rb2
    return torque / rb / math.cos(pair.beta_b)


def _nlte(pair, modifications, stagger, phase, extra, n_line):
    """(left, right) unloaded TE: min ε over each helix's dense contact points (right 0 for a one-helix pair)."""
    dense = phase_points(pair, phase, stagger, 8 * n_line)
    eps = _eps(pair, modifications, dense, extra)
    left = dense.helix == 0
    return float(eps[left].min()), float(eps[~left].min()) if pair.n_helices == 2 else 0.0


def _eps(pair, modifications, pts, extra):
    eps = np.empty(pts.size)
    for h, name in enumerate(("left", "right")[:pair.n_helices]):
        s = pts.helix == h
        eps[s] = separation(pair, modifications, name, pts.u[s], pts.zeta[s], extra)
    return eps


def _start_loads(start: LTCAResult | None, i: int, pts, force: float) -> np.ndarray | None:
    """Point loads [N] of phase ``i`` of ``start`` when its points are these (else None)."""
    if start is None or not start.line_load or i >= len(start.line_load) or start.force != force:
        return None
    lines = start.line_load[i]
    if lines.shape[0] != pts.size or not (np.array_equal(lines[:, 2], pts.u) and np.array_equal(lines[:, 3], pts.zeta)):
        return None
    return lines[:, 4] * start.line_length[i]


def mesh_cycle(model: LTCAModel, force: float, modifications=None, n_phases: int = 64, stagger: float = 0.0,
               n_line: int = 16, extra: Deviation | None = None, keep_lines: bool = True,
               start: LTCAResult | None = None) -> LTCAResult:
    """LTCA at ``n_phases`` phases of one mesh period for the total normal force ``force`` [N].

    ``start``: a cycle of the same model, force, phases and contact points (kept lines) whose loads start
    each phase's solve at ``force`` (:func:`femgear.physics.ltca.contact.solve_phase` ``load0``): a re-run on
    flanks with a small deviation (wear, thermal growth) takes fewer Hertz-width passes and active-set
    steps to the same solution (within the fixed point's 1e-6 of the force)."""
    pair, E, nu = model.pair, model.youngs_modulus, model.poisson_ratio
    if n_phases < 2:
        raise ValueError(f"n_phases must be ≥ 2, got {n_phases}")
    if abs(stagger - model.stagger) > 1e-12:
        raise ValueError(f"stagger={stagger} differs from the stagger {model.stagger} the member bodies were built "
                         "with (build_model(..., stagger=...))")
    if modifications is not None:
        for member in (1, 2):
            check_modification(pair, member, modifications.member(member))
    t0 = time.perf_counter()
    phases = np.arange(n_phases) / n_phases
    cols = {k: np.zeros(n_phases) for k in ("lte", "nl", "nr", "fl", "fr", "ksl", "ksr", "ktl", "ktr", "pl", "pr", "err")}
    lines, lengths = [], []
    Ep = reduced_modulus(E, nu)
    cb = math.cos(pair.beta_b)
    progress = Progress(f"LTCA contact cycle ({n_line} points per contact line)", n_phases)
    for i, ph in enumerate(phases):
        pts = phase_points(pair, ph, stagger, n_line)
        eps = _eps(pair, modifications, pts, extra)
        case = f"LTCA phase {ph:.4f}"
        base = phase_matrix(pair, model.kernels, pts, E, nu)
        load0 = _start_loads(start, i, pts, force)
        sol, _, _ = solve_phase(pair, model.kernels, pts, eps, force, E, nu, case=case, base=base, load0=load0)
        up, _, _ = solve_phase(pair, model.kernels, pts, eps, force * 1.001, E, nu, case=case, base=base)
        nl, nr = _nlte(pair, modifications, stagger, ph, extra, n_line)
        left = pts.helix == 0
        w = sol.load / pts.length
        R = pts.u * (pair.line_of_action - pts.u) / pair.line_of_action / cb
        p = hertz_pressure(w, R, Ep)
        cols["lte"][i] = sol.approach
        cols["nl"][i], cols["nr"][i] = nl, nr
        for h, s, kf in (("l", left, "fl"), ("r", ~left, "fr")):
            F = float(sol.load[s].sum())
            cols[kf][i] = F
            gap = sol.approach - (nl if h == "l" else nr)
            cols["ks" + h][i] = F / gap if F > 0 and gap > 0 else 0.0
            cols["kt" + h][i] = (float(up.load[s].sum()) - F) / (up.approach - sol.approach)
            cols["p" + h][i] = float(p[s].max()) if s.any() else 0.0
        cols["err"][i] = abs(sol.load.sum() - force) / force
        if keep_lines:
            lines.append(np.column_stack([pts.helix, pts.line, pts.u, pts.zeta, w]))
            lengths.append(pts.length)
        progress(i + 1)
    return LTCAResult(phases, force, cols["lte"], cols["nl"], cols["nr"], cols["fl"], cols["fr"], cols["ksl"],
                      cols["ksr"], cols["ktl"], cols["ktr"], cols["pl"], cols["pr"], cols["err"], tuple(lines),
                      tuple(lengths), time.perf_counter() - t0, n_line=n_line, stagger=stagger,
                      groove=float(model.kernels[1].groove), n_helices=pair.n_helices)
