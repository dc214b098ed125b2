"""Error estimates and adequacy checks that every EHL result carries.

Discretisation error (Richardson).  The nested iteration already solves every level
from the coarsest to the finest; the central and minimum films of consecutive levels
give the error of the last one.  With the changes d_k = f_k - f_(k-1) and the observed
ratio r = d_(k-1)/d_k = 2^p (mesh halved each level),

    e_k = |d_k| / (2^p - 1),

p clamped to [1, 2] (the Q1/P1 Galerkin discretisation with O(h^2) diffusion is second
order; a higher observed order is taken as cancellation, not as a licence to trust the
level more).  Outside the asymptotic range (the changes do not decrease, or change sign)
p = 1, i.e. e_k = |d_k|.  With only two levels p = 2.  The estimate is relative.

Inlet adequacy (the domain).  The fully flooded inlet of a point contact lies at
m* = 1 + 3.06 H^0.58 Hertz radii upstream of the centre, H = h_c R / a^2 the central
film in Hertzian units (Hamrock & Dowson 1977, J. Lubr. Technol. 99:15, "Part IV -
starvation results"; the boundary between fully flooded and starved).  H comes from the
film formula of the contact (NVM for points, Moes for lines), so it grows as M falls: in
the rigid regimes the pressure spreads far beyond the Hertzian radius (at M = 1, L = 10:
m* = 24 a).  A domain whose inlet lies inside m* truncates the inlet build-up and
underestimates the film (measured at (3, 10): -44 % on the default inlet X = -4.5, still
-40 % at X = -12, converging as 1/inlet); the line contact uses the same correlation
with its Hertzian film (a judgement: the inlet build-up of a line contact is at most as
long, the side leakage being absent).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

DEFAULT_TOL = 0.02  # flag results whose estimated relative error exceeds 2 %


def richardson(values: Sequence[float]) -> float | None:
    """Relative error estimate of the last of ``values`` (one per level, h halved each
    time); None with fewer than two levels."""
    v = [float(x) for x in values]
    if len(v) < 2:
        return None
    d = v[-1] - v[-2]
    if len(v) == 2:
        p = 2.0
    else:
        prev = v[-2] - v[-3]
        if d == 0.0:
            return 0.0
        r = prev / d
        p = min(2.0, max(1.0, math.log2(r))) if r > 1.0 else 1.0
    return abs(d) / (2.0**p - 1.0) / max(abs(v[-1]), 1e-300)


NON_ASYMPTOTIC = 0.10  # a last change above 10 % (any film) marks an unresolved grid pair


def error_estimate(per_level: Sequence[dict]) -> dict[str, float | None]:
    """Richardson estimates of Hc and Hmin from the level summaries of a nested solve.

    Only consecutive levels (nodes growing) count: a level summary from a continuation
    on one grid does not estimate the discretisation error. When either film changed by
    more than :data:`NON_ASYMPTOTIC` between the last two levels, the pair lies outside
    the asymptotic range for the whole film shape and both quantities get the larger
    estimate (a judgement; the line contact at (1000, 10) on levels 5/6 has Hc change
    0.9 % and Hmin 205 %, and Hc then still moves 7 % on finer grids)."""
    run = consecutive_levels(per_level)
    est = {k: richardson([lv[k] for lv in run]) for k in ("Hc", "Hmin")}
    if len(run) >= 2 and None not in est.values() and any(
            abs(run[-1][k] - run[-2][k]) > NON_ASYMPTOTIC * abs(run[-1][k]) for k in est):
        worst = max(est.values())
        est = {k: worst for k in est}
    return est


def consecutive_levels(per_level: Sequence[dict]) -> list[dict]:
    """The last run of level summaries whose ``nodes`` grow to the last one (a continuation on one grid, or a solve
    begun again, ends the run before it)."""
    levels = list(per_level)
    run = levels[-1:]
    for lv in reversed(levels[:-1]):
        if lv["nodes"] >= run[0]["nodes"]:
            break
        run.insert(0, lv)
    return run


def inlet_distance(H_hertz: float) -> float:
    """Hamrock & Dowson's (1977) fully flooded inlet distance m* [Hertz radii]."""
    return 1.0 + 3.06 * max(H_hertz, 0.0) ** 0.58


def inlet_problem(x0: float, H_hertz: float) -> str | None:
    """None when the inlet at X = x0 lies at or beyond m*, else the reason."""
    m = inlet_distance(H_hertz)
    if -x0 >= m:
        return None
    return (f"inlet at X = {x0:g} lies inside the fully flooded inlet distance "
            f"m* = {m:.3g} (Hamrock & Dowson 1977, for the expected central film "
            f"H = {H_hertz:.3g} in Hertzian units): the truncated inlet under-predicts the film")


def flags_for(estimate: dict[str, float | None], tol: float, extra: Sequence[str] = ()) -> tuple[str, ...]:
    """Warning flags: estimate missing or above ``tol``, plus ``extra`` (domain) flags."""
    out = []
    for k, e in estimate.items():
        if e is None:
            out.append(f"{k}: no error estimate (a single level was solved)")
        elif e > tol:
            out.append(f"{k}: estimated discretisation error {100 * e:.2g} % exceeds "
                       f"tol {100 * tol:.2g} %")
    return tuple(out) + tuple(extra)
