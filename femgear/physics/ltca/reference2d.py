"""2-D plane-strain references of the LTCA's mesh stiffness: whole sections loaded by the Hertz pressure.

Each member's whole transverse section (P2, plane strain, the bore clamped; the ``fe`` level's mesh rule,
:func:`femgear.physics.mesh.section.gear_section`) is refined to a/``per_width`` within 4a of one contact point and
loaded there by the Hertz pressure p(s) = p_H √(1 − s²/a²) of a line load w, a = b_H/cos β_b the Hertz half-width
in the section (b_H of the normal radius of curvature, :func:`femgear.physics.ltca.halfspace.hertz_half_width`).
The pair's approach is read at the surface points themselves: no contact formula and no FE/half-space split, so
these are independent of :mod:`femgear.physics.ltca.compliance`'s kernels.

- :func:`pair_compliance`: one tooth pair, the approach at the contact point and, as the ``fe`` level reads it,
  averaged over the tooth section through that point (:class:`femgear.physics.body.compliance.ToothFE`); the
  difference is the local contact flattening, beside :func:`weber_banaschek`'s formula for it.
- :func:`coupled_stiffness`: all tooth pairs in contact in one section loaded at once, each load read on the
  other teeth too (the coupling of the teeth through the body), the load shared at one approach; and the same
  teeth uncoupled (springs in parallel, the slice levels' ``pem`` and ``fe`` assumption).

Used by ``studies/ltca/ltca_local_contact.py`` and ``tests/ltca/test_tooth_coupling.py`` (issue 37).
"""

from __future__ import annotations

import math

import numpy as np

from femgear.physics.geometry.gear import GearPair


def flank_point(pair: GearPair, member: int, u: float, tooth: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """(point (2,), unit load direction into the tooth (2,)) of path position ``u`` on the loaded flank of ``tooth``
    in the transverse section z = 0 (:func:`femgear.physics.ltca.flank.flank_points`: tooth k counter-clockwise),
    the direction the unit transverse normal (the ``fe`` level's load direction)."""
    from femgear.physics.ltca.flank import flank_normals, flank_points

    rho = np.array([u if member == 1 else pair.line_of_action - u])
    z = np.zeros(1)
    n = flank_normals(pair, member, rho, z, tooth)[:2, 0]       # the transverse part of a helicoid's normal
    return flank_points(pair, member, rho, z, tooth)[:2, 0], -n / np.linalg.norm(n)


def hertz_section(pair: GearPair, member: int, point: np.ndarray, E: float, nu: float, bore: float, h: float,
                  a: float, per_width: float = 4.0):
    """(problem, loaded-side flank facets): the whole section of ``member`` clamped at ``bore`` (0: r_f/2), size
    ``h`` on the teeth, a/``per_width`` within 4a of ``point`` [m]."""
    from femgear.physics.body.compliance import GRADE
    from femgear.physics.body.elastic import ElasticProblem
    from femgear.physics.mesh.section import gear_section
    from femgear.physics.mesh.segment import FAR_FRACTION

    rf = pair.rf1 if member == 1 else pair.rf2
    rbore = bore if bore > 0 else 0.5 * rf
    mesh = gear_section(pair, member, h, n_teeth=None, bore_radius=rbore, refine_at=(float(point[0]), float(point[1])),
                        refine_ratio=a / per_width / h, refine_radius=4 * a,
                        grade=(GRADE, max(4.0 * h, FAR_FRACTION * (rf - rbore)), 3))
    problem = ElasticProblem(mesh, E, nu, "strain", order=2, solver="lu")
    problem.fix(problem.boundary_dofs("bore"), 0.0)
    flank = mesh.boundaries["flank"]
    return problem, flank[mesh.p[0, mesh.facets[:, flank]].mean(axis=0) > 0]


def hertz_field(problem, point: np.ndarray, direction: np.ndarray, flank: np.ndarray, a: float,
                w: float = 1.0) -> np.ndarray:
    """Displacements under p(s) = p_H √(1 − s²/a²) of total ``w`` [N/m] along ``direction`` on the ``flank`` facets
    (s the distance from ``point``; the discrete pressure carries exactly w)."""
    from skfem import FacetBasis

    from femgear.physics.body.forms import traction

    fb = FacetBasis(problem.mesh, problem.basis.elem, facets=flank)
    x = fb.global_coordinates()
    shape = np.sqrt(np.clip(1 - (np.hypot(x[0] - point[0], x[1] - point[1]) / a) ** 2, 0.0, None))
    p = w / float(np.sum(shape * fb.dx)) * shape
    disp, _ = problem.solve(traction.assemble(fb, tx=p * direction[0], ty=p * direction[1]), case="Hertz-loaded section")
    return disp


def approach(problem, disp: np.ndarray, points: np.ndarray, direction: np.ndarray) -> np.ndarray:
    """Displacements along ``direction`` (2,) at ``points`` (2, n) [m]."""
    (ux, bx), (uy, by) = problem.basis.split(disp)
    return (bx.probes(points) @ ux) * direction[0] + (by.probes(points) @ uy) * direction[1]


def surface_approach(problem, disp: np.ndarray, point: np.ndarray, direction: np.ndarray, depth: float = 1e-7) -> float:
    """Displacement along ``direction`` just inside the flank point ``point``: ``depth`` [m] below it, deeper by
    decades up to 1000 × where the straight-sided elements' chords leave the point outside the mesh (a coarse
    tooth away from the load, the tip corner at the end of the path)."""
    for t in depth * 10.0 ** np.arange(4):
        try:
            return float(approach(problem, disp, (point + t * direction)[:, None], direction)[0])
        except ValueError:            # outside the mesh
            continue
    raise ValueError(f"no mesh point within {1e3 * depth:.3g} m below the flank point {point}")


def section_width(pair: GearPair, u: float, w: float, E: float, nu: float) -> float:
    """Hertz half-width in the transverse section at path position ``u`` under the line load ``w`` [m]."""
    from femgear.physics.ltca.halfspace import hertz_half_width, reduced_modulus

    cb = math.cos(pair.beta_b)
    R = u * (pair.line_of_action - u) / pair.line_of_action / cb
    return float(hertz_half_width(w, R, reduced_modulus(E, nu))) / cb


def pair_compliance(pair: GearPair, u: float, E: float, nu: float, bores, w: float, h: float,
                    per_width: float = 4.0) -> tuple[float, float]:
    """(surface, section) approach of one tooth pair at path position ``u`` per unit line load [m/N · m]: at the
    contact points, and averaged over the teeth's sections through them (|y| ≤ 0.9 h_P across the centre line,
    as :class:`femgear.physics.body.compliance.ToothFE` reads it)."""
    from femgear.physics.stiffness.pem import load_point

    a = section_width(pair, u, w, E, nu)
    surface = section = 0.0
    for member in (1, 2):
        P, d = flank_point(pair, member, u)
        problem, flank = hertz_section(pair, member, P, E, nu, bores[member - 1], h, a, per_width)
        disp = hertz_field(problem, P, d, flank, a, w)
        xP, hP, _ = load_point(pair, member, np.array([u]))
        ys = np.linspace(-0.9, 0.9, 15) * float(hP[0])
        surface += surface_approach(problem, disp, P, d) / w
        section += float(np.mean(approach(problem, disp, np.vstack([-ys, np.full(ys.size, float(xP[0]))]), d))) / w
    return surface, section


def weber_banaschek(pair: GearPair, u: float, a: float, E: float, nu: float) -> float:
    """Local approach of the pair per unit line load from the teeth's centre lines [m/N · m] (Weber & Banaschek,
    *Formänderung und Profilrücknahme bei gerad- und schrägverzahnten Rädern*, Vieweg 1953):
    2(1−ν²)/(πE) [ln(2h₁/a) + ln(2h₂/a) − ν/(1−ν)], h_i = h_P/cos α₁ the distance of the contact point from
    member i's centre line along the load, a the Hertz half-width [m]."""
    from femgear.physics.stiffness.pem import load_point

    logs = 0.0
    for member in (1, 2):
        _, hP, a1 = load_point(pair, member, np.array([u]))
        logs += math.log(2 * float(hP[0]) / math.cos(float(a1[0])) / a)
    return 2 * (1 - nu**2) / (math.pi * E) * (logs - nu / (1 - nu))


def transverse_points(pair: GearPair, phase: float) -> tuple[np.ndarray, np.ndarray]:
    """(path positions u_j, path teeth j) of the tooth pairs in contact in one transverse section at ``phase``
    [base pitches]: u_j = u_A + (phase + j) p_bt on [u_A, u_E)."""
    j = np.arange(-1, int(math.ceil(pair.eps_alpha)) + 1)
    u = pair.u_start + (phase % 1.0 + j) * pair.p_bt
    on = (u >= pair.u_start) & (u < pair.u_end)
    return u[on], j[on]


def coupled_stiffness(pair: GearPair, u: np.ndarray, teeth: np.ndarray, force: float, E: float, nu: float, bores,
                      h: float, per_width: float = 4.0) -> tuple[float, float]:
    """(coupled, uncoupled) stiffness F/δ of the tooth pairs at path positions ``u`` on path teeth ``teeth`` of one
    section sharing the line load ``force`` [N/m] at one approach δ [N/m per m of line].

    Load b on tooth 0 of each member is read at every point a on tooth s_m (j_a − j_b) (s₁ = −1, s₂ = +1: path tooth
    j is the pinion's tooth −j and the gear's +j, the LTCA's convention); uncoupled keeps only the readings under
    each load.  The self terms follow each share's Hertz width by the half-space's −4(1−ν²)/(πE) ln a (both
    members; exact where a is small against the tooth), so each section is solved once."""
    n = u.size
    a0 = np.array([section_width(pair, ui, force / n, E, nu) for ui in u])
    C = np.zeros((n, n))
    for member, sign in ((1, -1), (2, 1)):
        for b in range(n):
            P, d = flank_point(pair, member, u[b])
            problem, flank = hertz_section(pair, member, P, E, nu, bores[member - 1], h, a0[b], per_width)
            disp = hertz_field(problem, P, d, flank, a0[b])
            for i in range(n):
                Pa, da = flank_point(pair, member, u[i], sign * int(teeth[i] - teeth[b]))
                C[i, b] += surface_approach(problem, disp, Pa, da, 1e-7 if i == b else 0.05 * h)
    return tuple(_shared(pair, M, u, a0, force, E, nu) for M in (C, np.diag(np.diag(C))))


def _shared(pair: GearPair, C: np.ndarray, u: np.ndarray, a0: np.ndarray, force: float, E: float, nu: float) -> float:
    """F/δ of the points of compliance ``C`` (per unit load, Hertz widths ``a0``) sharing ``force`` at one approach,
    the self terms following each share's Hertz width (fixed point)."""
    n = u.size
    log_self = 4 * (1 - nu**2) / (math.pi * E)
    w = np.full(n, force / n)
    for _ in range(100):
        a = np.array([section_width(pair, ui, max(wi, 1e-9 * force), E, nu) for ui, wi in zip(u, w)])
        A = np.block([[C - np.diag(log_self * np.log(a / a0)), -np.ones((n, 1))], [np.ones((1, n)), np.zeros((1, 1))]])
        x = np.linalg.solve(A, np.concatenate([np.zeros(n), [force]]))
        if np.any(x[:n] < 0):
            raise ValueError("a tooth pair of the 2-D reference unloads: every pair in contact must carry load")
        settled = np.max(np.abs(x[:n] - w)) < 1e-9 * force
        w = x[:n]
        if settled:
            return float(force / x[n])
    raise RuntimeError("the Hertz widths of the 2-D coupled reference did not settle in 100 passes")


__all__ = ["flank_point", "hertz_section", "hertz_field", "approach", "surface_approach", "section_width", "pair_compliance",
           "weber_banaschek", "transverse_points", "coupled_stiffness"]
