"""Contact points of one mesh phase, their compliance matrix, and the unilateral contact solve.

Contact lines (same convention as :func:`femgear.physics.geometry.contact_lines`): a line of a
helix runs u(ζ) = u₀ + ζ tan β_b over ζ ∈ [0, b] in the helix's own face coordinate
(the right helix is the mirror image, groove at ζ = b for both), u₀ = u_A − b tan β_b +
(φ + offset) p_bt + j p_bt.  Each line is clipped to the path [u_A, u_E] and cut into
round(n_line · piece/b) ≥ 1 equal segments with a point at each segment's centre
(midpoint rule: the point spacing never falls below the strip length, which keeps the
discrete half-space operator positive definite); Δℓ, the segment length along the line,
varies continuously with the phase, so does the total contact length.

Compliance between points a, b (both members m, kernel offsets s_m (j_a − j_b) with
s₁ = −1, s₂ = +1: tooth j of the path is tooth −j of the pinion's and +j of the gear's
counter-clockwise numbering, :mod:`femgear.physics.ltca.flank`; j is the point's path tooth, its
line index less one where the stagger shift wrapped past a base pitch):

    C_ab = Σ_m R_m,a · K_m[s_m(j_a − j_b)] · R_m,bᵀ + [j_a = j_b, same helix] H₀,ab

with K the member's same-helix bulk kernel for points of one helix and its cross-helix kernel
(one helix loaded, the other read through the body, :mod:`femgear.physics.ltca.compliance`) for points
on different helices.

H₀ (both bodies): Love's uniform strip 2a × Δℓ as the self term (a = 0.824 b_H
from the current load, :mod:`femgear.physics.ltca.halfspace`), (1−ν²)/(πE r) between points of
the same line.  b_H depends on the load: the solve is repeated with updated b_H (secant
local compliance) until the loads change < 1e-6 relative.

Solve (Conry & Seireg 1971 form): f ≥ 0, g = C f + ε − δ 1 ≥ 0, fᵀg = 0, 1ᵀf = F
by a primal active set on the bordered system [C_SS −1; −1ᵀ 0][f_S; δ] = [−ε_S; −F],
with the pinion axially fixed (both helices see the same normal approach δ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.geometry.gear import GearPair
from femgear.physics.ltca.halfspace import (
    HERTZ_TO_UNIFORM,
    hertz_half_width,
    reduced_modulus,
    strip_self_compliance,
    surface_green,
)


@dataclass(frozen=True)
class ContactPoints:
    """Contact points of both helices at one phase (arrays of equal length)."""

    helix: np.ndarray     #: 0 left, 1 right
    line: np.ndarray      #: line index j (larger j: further along the path)
    u: np.ndarray         #: path position [m] (pinion roll distance ρ₁)
    zeta: np.ndarray      #: face coordinate of the helix [m]
    length: np.ndarray    #: segment length along the line Δℓ [m]
    tooth: np.ndarray | None = None   #: path tooth index of the point's line (default: ``line``)

    @property
    def size(self) -> int:
        return int(self.u.size)


def phase_points(pair: GearPair, phase: float, stagger: float, n_line: int) -> ContactPoints:
    """Points on the contact lines of every helix of ``pair`` at ``phase`` [base pitches]: both helices of a
    double-helical pair, the one helix (``helix`` 0) of a single-helical or spur pair (``pair.n_helices``).

    A spur line (β_b = 0) lies at one path position u₀ across the whole face ζ ∈ [0, b], inside the path
    for u_A ≤ u₀ < u_E (one end open, so that a line leaving at u_E is the next one entering at u_A)."""
    tb = math.tan(pair.beta_b)
    cb = math.cos(pair.beta_b)
    span = pair.b * tb
    k_max = int(math.ceil((pair.g_alpha + span) / pair.p_bt)) + 1
    cols = {k: [] for k in ("helix", "line", "u", "zeta", "length", "tooth")}
    for h, offset in enumerate((0.0, stagger)[:pair.n_helices]):
        shift = ((phase + offset) % 1.0) * pair.p_bt
        wrap = math.floor(phase + offset)             # line j of a wrapped shift sits on the tooth of line j − 1
        for j in range(-1, k_max + 1):
            u0 = pair.u_start - span + shift + j * pair.p_bt
            if tb > 0:
                z_lo = max(0.0, (pair.u_start - u0) / tb)
                z_hi = min(pair.b, (pair.u_end - u0) / tb)
            elif pair.u_start <= u0 < pair.u_end:
                z_lo, z_hi = 0.0, pair.b
            else:
                continue
            if z_hi <= z_lo + 1e-9 * pair.b:
                continue
            n = max(1, int(round(n_line * (z_hi - z_lo) / pair.b)))
            dz = (z_hi - z_lo) / n
            zeta = z_lo + (np.arange(n) + 0.5) * dz
            w = np.full(n, dz)
            cols["helix"].append(np.full(n, h))
            cols["line"].append(np.full(n, j))
            cols["tooth"].append(np.full(n, j - wrap))
            cols["u"].append(u0 + zeta * tb)
            cols["zeta"].append(zeta)
            cols["length"].append(w / cb)
    arr = {k: np.concatenate(v) for k, v in cols.items()}
    return ContactPoints(arr["helix"].astype(int), arr["line"].astype(int), arr["u"], arr["zeta"], arr["length"],
                         arr["tooth"].astype(int))


def bulk_matrix(pair: GearPair, kernels, pts: ContactPoints) -> np.ndarray:
    """Σ over members of the interpolated bulk kernels between all points, every helix [m/N].

    Same helix: the member's self kernels (``kernel(offset, helix)``); across the helices (through the
    groove and the rim): the cross kernel X (reading on the right helix, load on the left one) for
    right-left pairs and, by Maxwell–Betti reciprocity, its transpose for left-right pairs.
    """
    n = pts.size
    C = np.zeros((n, n))
    X = np.zeros((n, n))
    tooth = pts.line if pts.tooth is None else pts.tooth
    dj = tooth[:, None] - tooth[None, :]
    right_left = (pts.helix[:, None] == 1) & (pts.helix[None, :] == 0)
    for member, sign in ((1, -1), (2, 1)):
        kern = kernels[member]
        rho = pts.u if member == 1 else pair.line_of_action - pts.u
        R = kern.weights(rho, pts.zeta)
        for h in np.unique(pts.helix):
            same = (pts.helix[:, None] == h) & (pts.helix[None, :] == h)
            for d in np.unique(dj[same]):
                mask = same & (dj == d)
                C[mask] += (R @ kern.kernel(int(sign * d), helix=h) @ R.T)[mask]
        if getattr(kern, "cross", None) is not None:
            for d in np.unique(dj[right_left]):
                mask = right_left & (dj == d)
                X[mask] += (R @ kern.cross_kernel(int(sign * d)) @ R.T)[mask]
    C += X + X.T
    # The kernel pairs a hat *load* with a point *reading* at depth: these functionals differ, so G is not
    # symmetric (≈ 22 % on a 3 × 3 grid, for P1 and P2 alike: not a discretisation error).  The contact
    # operator of the Galerkin (energy) form is symmetric; its symmetric part is used (Maxwell–Betti).
    return 0.5 * (C + C.T)


def local_matrix(pair: GearPair, pts: ContactPoints, load: np.ndarray, E: float, nu: float,
                 groove: float = 0.0, across: bool = True) -> np.ndarray:
    """H₀ of both bodies: Hertz-strip self terms and surface Boussinesq terms between the points of one tooth [m/N].

    Points of one tooth: the same line of a helix and, with ``across`` (kernels with a cross-helix block,
    which dropped the half-space part of that reading too), the two helices' lines of the same path tooth.
    Distances in the plane of action: path position u and axial position z (ζ on the left helix,
    2b + g − ζ on the right one, ``groove`` g).
    """
    H = local_coupling(pair, pts, E, nu, groove, across)
    H[np.diag_indices(pts.size)] = local_self(pair, pts, load, E, nu)
    return H


def local_coupling(pair: GearPair, pts: ContactPoints, E: float, nu: float, groove: float = 0.0,
                   across: bool = True) -> np.ndarray:
    """The off-diagonal part of :func:`local_matrix` (surface Boussinesq terms; zero diagonal): it does not
    depend on the loads, so the Hertz-width passes of :func:`solve_phase` compute it once."""
    tooth = pts.line if pts.tooth is None else pts.tooth
    same_helix = pts.helix[:, None] == pts.helix[None, :]
    same = np.where(same_helix, pts.line[:, None] == pts.line[None, :], across & (tooth[:, None] == tooth[None, :]))
    z = np.where(pts.helix == 0, pts.zeta, 2 * pair.b + groove - pts.zeta)
    r = np.hypot(z[:, None] - z[None, :], pts.u[:, None] - pts.u[None, :])
    H = np.zeros((pts.size, pts.size))
    off = same & (r > 0)
    H[off] = 2 * surface_green(r[off], E, nu)
    return H


def local_self(pair: GearPair, pts: ContactPoints, load: np.ndarray, E: float, nu: float) -> np.ndarray:
    """The diagonal of :func:`local_matrix`: Love's strip 2a × Δℓ of both bodies, a from the points' loads."""
    cb = math.cos(pair.beta_b)
    rho1 = pts.u
    rho2 = pair.line_of_action - pts.u
    R = (rho1 * rho2) / (rho1 + rho2) / cb
    w = np.maximum(load, 1e-12) / pts.length
    a = HERTZ_TO_UNIFORM * hertz_half_width(w, R, reduced_modulus(E, nu))
    return 2 * strip_self_compliance(a, pts.length / 2, E, nu)


@dataclass(frozen=True)
class ContactSolution:
    load: np.ndarray      #: normal force per point [N]
    approach: float       #: rigid normal approach δ [m]
    gap: np.ndarray       #: loaded gap g ≥ 0 [m]
    iterations: int


def solve_contact(C: np.ndarray, eps: np.ndarray, force: float, case: str = "LTCA contact",
                  active: np.ndarray | None = None, max_iter: int | None = None) -> ContactSolution:
    """Active-set solution of the unilateral contact problem for the total normal force ``force`` [N].

    One point enters or leaves the active set per iteration, so the cap scales with the points:
    ``max_iter`` default 200 + 2 n (a wide, high-overlap helix, the turbo zoo pair's 2 × 100 mm at
    ε_β 4, has several hundred loaded points and ran out of the old fixed 200)."""
    n = eps.size
    max_iter = 200 + 2 * n if max_iter is None else max_iter
    if force <= 0:
        raise ValueError(f"force must be positive, got {force}")
    S = np.zeros(n, bool)
    if active is not None and active.any():
        S[:] = active
    else:
        S[np.argsort(eps)[: max(1, n // 4)]] = True
    scale = float(np.mean(np.diag(C)))
    hist = []
    for it in range(1, max_iter + 1):
        idx = np.nonzero(S)[0]
        m = idx.size
        A = np.zeros((m + 1, m + 1))
        A[:m, :m] = C[np.ix_(idx, idx)] / scale
        A[:m, m] = -1.0
        A[m, :m] = -1.0
        rhs = np.concatenate([-eps[idx], [-force * scale]])      # unknowns: x = f·scale [m] and δ [m]
        try:
            x = np.linalg.solve(A, rhs)
        except np.linalg.LinAlgError as exc:
            raise ConvergenceError(case, f"singular contact system on {m} active points ({exc})", {"violation": hist}) from exc
        if not np.all(np.isfinite(x)):
            raise ConvergenceError(case, "non-finite contact loads", {"violation": hist})
        f = np.zeros(n)
        f[idx] = x[:m] / scale
        delta = x[m]
        if f.min() < -1e-12 * force:
            S[idx[np.argmin(x[:m])]] = False
            hist.append(float(f.min()))
            continue
        f = np.maximum(f, 0.0)
        g = C @ f + eps - delta
        viol = np.nonzero(~S & (g < -1e-12 * max(abs(delta), 1e-9)))[0]
        if viol.size == 0:
            return ContactSolution(f, float(delta), np.maximum(g, 0.0), it)
        S[viol[np.argmin(g[viol])]] = True
        hist.append(float(g[viol].min()))
    raise ConvergenceError(case, f"active set did not settle in {max_iter} iterations", {"violation": hist})


def phase_matrix(pair: GearPair, kernels, pts: ContactPoints, E: float, nu: float) -> np.ndarray:
    """The load-independent part of the phase's compliance: bulk kernels and the surface coupling of H₀."""
    return bulk_matrix(pair, kernels, pts) + local_coupling(pair, pts, E, nu, getattr(kernels[1], "groove", 0.0),
                                                            getattr(kernels[1], "cross", None) is not None)


def solve_phase(pair: GearPair, kernels, pts: ContactPoints, eps: np.ndarray, force: float, E: float, nu: float,
                tol: float = 1e-6, max_pass: int = 80, case: str = "LTCA phase", base: np.ndarray | None = None,
                load0: np.ndarray | None = None):
    """Contact solution with the Hertz strip width updated to the loads; returns (solution, C, passes).

    The fixed point converges linearly; on a face-resolved worn flank (the rig's test gear after 3e6
    cycles) it took more than 12 passes (load change 1.2e-6 after 12), hence up to 30; on the uncrowned
    baseline under the face-resolved 3-D thermal growth of a 30 K flank rise (``thermal = "fe3d"``,
    ``wear.field = "face"``) one phase contracts by 0.73 a pass and needs 49, hence up to 80.  A solve
    that converged within fewer passes returns the same solution as before.  ``base``: :func:`phase_matrix` of
    these points when the caller already has it (a second force at the same phase).  ``load0``: the start of
    the fixed point and of the active set (default: the force spread evenly, no active set), e.g. the solution
    of the same points on flanks that differ a little; the fixed point and the contact solution are unique,
    so only the passes it takes change (the answer within ``tol``)."""
    Cb = phase_matrix(pair, kernels, pts, E, nu) if base is None else base
    diag = np.diag_indices(pts.size)
    load = np.full(pts.size, force / pts.size) if load0 is None else np.asarray(load0, dtype=float).copy()
    active = None if load0 is None else load > 0
    changes = []
    for p in range(1, max_pass + 1):
        C = Cb.copy()
        C[diag] += local_self(pair, pts, load, E, nu)         # = Cb + local_matrix(...): only the strip widths move
        sol = solve_contact(C, eps, force, case, active)
        changes.append(float(np.max(np.abs(sol.load - load)) / force))
        load, active = sol.load, sol.load > 0
        if changes[-1] < tol:
            return sol, C, p
    raise ConvergenceError(case, f"Hertz width fixed point did not settle in {max_pass} passes",
                           {"load_change": changes})
