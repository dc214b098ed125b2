"""The ``ltca`` stiffness level: one LTCA mesh cycle for the level's factory (:mod:`femgear.levels.stiffness`).

tvms wraps the cycle as a ``MeshStiffness``: ``k_left``/``k_right`` are the secant
stiffnesses F_h/(δ − NLTE_h) of each helix along the normal line of action at the
operating load; ``MeshStiffness.ltca`` is the whole :class:`femgear.physics.ltca.cycle.LTCACycle`
(its ``result``, the :class:`femgear.physics.ltca.analysis.LTCAResult`, and ``excitation``, its per-helix
tables: loaded/unloaded TE, tangent stiffness, e_s = LTE − F_s/k_s).  (This module does not import tvms:
no import cycle.)

Resolved mesh orders.  The contact lines are cut into a whole number of points, so the
secant stiffness carries a discretisation noise floor (≈ 1e-4 of the mean here) at every
mesh order; at low speed the orders 50–100 of that floor fall on the 2.6–5 kHz modes of
the rotor model and dominate the bearing accelerations.  :func:`resolved_orders` finds
the mesh orders the contact discretisation resolves — the orders up to the first band
whose stiffness harmonics change by more than :data:`RESOLUTION_TOLERANCE` of themselves
when the points per contact line are doubled (64 phases) — and ``LTCACycle.resolved_orders`` tells
the dynamics to keep only those (:func:`femgear.system.dynamics.build.ltca_table`).  Where fewer
than :data:`MIN_RESOLVED_ORDERS` are resolved, :func:`ltca_cycle` doubles the points per
contact line (up to :data:`MAX_LINE_POINTS`): a tip relief near the load it takes up
leaves small low-order harmonics that 16 points do not resolve (the rig's test gear at
150 N m: orders 2–3 change by 28 / 60 % between 16 and 32 points, so one order was kept
and the tables lost their mesh harmonics; with 32 points 18 orders are resolved).

Why 16 orders.  The kept bandwidth must not depend on the load, or the dynamics' torque
trend becomes an artefact of the rule.  With a minimum of 8, the rig's test gear kept 9 / 18
/ 10 orders at 100 / 150 / 200 N m (16 / 32 / 16 points), although orders 10–18 have the
same amplitude at all three torques (5–15e-4 of the mean secant stiffness, converged to a
few % between 32 and 64 points): 100 and 200 N m lost them, 150 N m kept them.  With 16,
the three torques keep 17 / 18 / 19 orders (32 points each).  16 orders also reach the
lowest flexible mode of the baseline rotor model (2.64 kHz) from about 310 rpm up (mesh
frequency z₁ n / 60).  The unmodified baseline resolves 30 orders with 16 points: no change there.
"""

from __future__ import annotations

import numpy as np

from femgear.physics.geometry.gear import GearPair

RESOLUTION_TOLERANCE = 0.25   #: relative change of a stiffness harmonic that marks it unresolved
MIN_RESOLVED_ORDERS = 16      #: fewer resolved mesh orders than this: refine the contact lines
MAX_LINE_POINTS = 64          #: the finest contact-line discretisation that refinement goes to


def resolved_orders(model, force: float, modifications=None, stagger: float = 0.0, n_line: int = 16, extra=None,
                    n_phases: int = 64, spectra: dict | None = None) -> tuple[int, np.ndarray]:
    """(H, change): mesh orders 1…H of the total secant stiffness are resolved by ``n_line`` points per line.

    ``change[h − 1]`` = |K_h(n_line) − K_h(2 n_line)| / |K_h(2 n_line)| for the complex harmonics K_h of
    k_s,left + k_s,right at ``n_phases`` phases.  H = the last order before the first whose running median
    of ``change`` over the orders h − 1, h, h + 1 exceeds :data:`RESOLUTION_TOLERANCE` (at least 1): the
    median ignores a single nearly vanishing harmonic (whose relative change is large while its
    amplitude is negligible, e.g. order 4 at 200 N m on the baseline) and stops where the
    discretisation noise dominates the orders as a band.
    """
    from femgear.physics.ltca.analysis import mesh_cycle

    memo = {} if spectra is None else spectra     # spectra by points per line: doubling reuses the finer one
    for n in (n_line, 2 * n_line):
        if n not in memo:
            r = mesh_cycle(model, force, modifications, n_phases=n_phases, stagger=stagger, n_line=n, extra=extra,
                           keep_lines=False)
            memo[n] = np.fft.rfft(r.k_secant)[1:n_phases // 2]
    a, b = memo[n_line], memo[2 * n_line]
    change = np.abs(a - b) / np.maximum(np.abs(b), 1e-300)
    median = np.array([np.median(change[max(0, i - 1):i + 2]) for i in range(change.size)])
    bad = np.nonzero(median > RESOLUTION_TOLERANCE)[0]
    return (max(1, int(bad[0])) if bad.size else change.size), change


#: a body level whose Richardson-extrapolated error exceeds this is flagged (issue 26's mesh-convergence bound)
MESH_ERROR_FLAG = 0.02


def richardson(h, values) -> dict | None:
    """Richardson extrapolation of a mesh sequence f(h) = f* + C h^p from three levels (h₁ > h₂ > h₃,
    any refinement ratios): the order p solves (f₁ − f₂)/(f₂ − f₃) = (h₁^p − h₂^p)/(h₂^p − h₃^p)
    (bisection, 0.05 ≤ p ≤ 10), then f* = f₃ − C h₃^p.  Returns {"order", "extrapolated", "errors"
    (f_i/f* − 1 per level), "flagged" (errors above :data:`MESH_ERROR_FLAG`)}, or None where the
    sequence is not in its asymptotic range (the differences change sign or grow: no such p)."""
    h, f = (np.asarray(a, dtype=float) for a in (h, values))
    if h.size != 3 or not (h[0] > h[1] > h[2] > 0) or f[1] == f[2]:
        return None
    ratio = (f[0] - f[1]) / (f[1] - f[2])

    def mismatch(p):
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - ratio

    lo, hi = 0.05, 10.0
    if mismatch(lo) * mismatch(hi) > 0:
        return None
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if mismatch(lo) * mismatch(mid) > 0 else (lo, mid)
    p = 0.5 * (lo + hi)
    C = (f[1] - f[2]) / (h[1] ** p - h[2] ** p)
    fs = float(f[2] - C * h[2] ** p)
    errors = [float(x) for x in f / fs - 1]
    return {"order": p, "extrapolated": fs, "errors": errors, "flagged": [abs(e) > MESH_ERROR_FLAG for e in errors]}


def ltca_cycle(pair: GearPair, force: float, modifications=None, n_positions: int = 64, stagger: float = 0.0,
               youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, level: int = 1, n_line: int = 16,
               extra=None, body: dict | None = None, order: int | str = 1):
    """The :class:`~femgear.physics.ltca.cycle.LTCACycle` at the total normal force ``force`` [N].

    The line loads are kept (:meth:`LTCAResult.path_load`: the wear and lubrication load map of
    the ``ltca`` level, :func:`femgear.system.coupling.setup.ltca_reference`).  ``body``: ``bore_radius``
    and ``groove_width`` of the member bodies (:func:`femgear.levels.stiffness.body_options`).
    ``n_line`` points per contact line, doubled while fewer than :data:`MIN_RESOLVED_ORDERS`
    mesh orders are resolved (``LTCACycle.n_line`` is the one used).  ``order``: the bodies' elements
    (1: P1; ``"p2-bending"``: P2 where they bend, :func:`femgear.physics.ltca.compliance.bending_elements`).
    """
    from femgear.physics.ltca.analysis import build_model, mesh_cycle
    from femgear.physics.ltca.cycle import LTCACycle

    body = {k: v for k, v in (body or {}).items() if k != "stagger"}
    check_body_memory(pair, youngs_modulus, poisson_ratio, level, stagger, order=order, **body)
    model = build_model(pair, youngs_modulus, poisson_ratio, level=level, stagger=stagger, order=order, **body)
    spectra: dict = {}
    orders, change = resolved_orders(model, force, modifications, stagger, n_line, extra, spectra=spectra)
    while orders < MIN_RESOLVED_ORDERS and 2 * n_line <= MAX_LINE_POINTS:
        n_line *= 2
        orders, change = resolved_orders(model, force, modifications, stagger, n_line, extra, spectra=spectra)
    res = mesh_cycle(model, force, modifications, n_phases=n_positions, stagger=stagger, n_line=n_line, extra=extra)
    return LTCACycle.from_result(res, model, modifications, resolved_orders=orders, harmonic_change=change)


def body_estimates(pair: GearPair, youngs_modulus: float, poisson_ratio: float, level: int, stagger: float = 0.0,
                   bore_radius: tuple[float, float] = (0.0, 0.0), groove_width: float = 0.0,
                   cached: bool = True, order: int | str = 1) -> list:
    """:class:`femgear.perf.Estimate` of each member body that :func:`ltca_cycle` would compute at body
    ``level`` (``cached`` False: also those already in the disk cache).  Meshes the sections only."""
    from femgear.physics.ltca.compliance import build_estimate, cache_path
    from femgear.physics.mesh.segment import default_spec

    out = []
    for member in (1, 2):
        spec = default_spec(pair, member, level, r_bore=bore_radius[member - 1], groove=groove_width,
                            stagger=stagger)
        if cached and cache_path(pair, member, spec, youngs_modulus, poisson_ratio, order).exists():
            continue
        try:
            out.append(build_estimate(pair, member, spec, order, n_loads=63 * (1 if stagger == 0 else 2)))
        except ValueError as exc:      # e.g. a bore too close to the root circle for the body's rim
            from femgear.errors import SceneError

            name = "pinion" if member == 1 else "gear"
            raise SceneError(f"{name}.bore_radius", f"the {name}'s LTCA body cannot be meshed: {exc} "
                             f"(the bore is the scene's bore_radius, else the shaft radius, at least 1.2 h_t below the root)") from None
    return out


def check_body_memory(pair: GearPair, youngs_modulus: float, poisson_ratio: float, level: int, stagger: float = 0.0,
                      order: int | str = 1, **body) -> None:
    """Refuse (:class:`femgear.errors.ResourceError`, exit 2, naming ``numerics.body_level`` and the finest
    level that fits) before any body is built when one needs more memory than the budget."""
    from femgear.errors import ResourceError
    from femgear.perf import memory_budget

    budget = memory_budget()
    over = [e for e in body_estimates(pair, youngs_modulus, poisson_ratio, level, stagger, order=order, **body)
            if e.memory_bytes > budget]
    if not over:
        return
    fits = next((k for k in range(level - 1, -1, -1)
                 if all(e.memory_bytes <= budget
                        for e in body_estimates(pair, youngs_modulus, poisson_ratio, k, stagger, cached=False,
                                                order=order, **body))),
                None)
    hint = f"numerics.body_level = {fits} fits" if fits is not None else "no body level fits"
    if fits is None and order != 1 and all(e.memory_bytes <= budget for e in body_estimates(
            pair, youngs_modulus, poisson_ratio, 0, stagger, cached=False, order=1, **body)):
        hint += ' with these elements; numerics.body_elements = "p1" at level 0 fits (stiffer by ≈ 5 %, docs/cost.md)'
    worst = max(over, key=lambda e: e.memory_bytes)
    raise ResourceError("numerics.body_level", worst.memory_bytes, budget, f"{worst.stage} at level {level}; {hint}")


