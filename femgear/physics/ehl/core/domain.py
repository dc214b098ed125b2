"""The point-contact domain (shared by the FE and FD solvers): the Hertz ellipse of a ratio
lambda = R_x/R_y, the default domain around it, and the checks that the domain holds the inlet
build-up and the film's side extent."""

from __future__ import annotations

import math
from functools import lru_cache

from femgear.physics.contact.hertz import hertz_point
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core.grid import Domain


@lru_cache(maxsize=64)
def hertz_ellipse(ratio: float) -> tuple[float, float, float]:
    """(a, b, p_h) of the dry Hertz ellipse for lambda = R_x/R_y = ``ratio`` in the units of
    the circular contact on R_x (a/a_c, b/a_c, p_h/p_c): a along X (entrainment), b along Y.

    Exact elliptic-integral solution (Johnson 1985, eq. 4.39; :func:`femgear.physics.contact.hertz.
    hertz_point`) with F = 1, R_x = 1, E' = 3/2, for which a_c = (3 F R_x / 2E')^(1/3) = 1
    and p_c = 3F/(2 pi a_c^2) = 3/(2 pi). At lambda = 0.02: a = 0.4712, b = 5.688,
    p_h = 0.373 (the table of /work/shared/notes/ehl_extensions.md, tested)."""
    if ratio == 1.0:
        return 1.0, 1.0, 1.0
    hz = hertz_point(1.0, 1.0, 1.0 / ratio, 1.5)
    return hz.a, hz.b, hz.max_pressure * 2.0 * math.pi / 3.0


def default_domain(ratio: float = 1.0, H_hertz: float | None = None,
                   enlarge: tuple[float, float] = (1.0, 1.0)) -> Domain:
    """The contact domain in units of the circular contact on R_x (a_c).

    lambda = R_x/R_y = 1: X in [-4.5, 1.5], Y in [-3, 3], square cells (Venner & Lubrecht
    2000); a low-M case whose inlet this truncates is refused by :func:`solve_point`.

    lambda != 1: the domain follows the Hertz ellipse (a, b) = :func:`hertz_ellipse`:
    X in [-x_in a, x_in a / 3], Y in [-3 b, 3 b], and stretched cells hy/hx = b/a, so the
    contact has as many nodes across it in Y as in X and a slender contact costs the same
    as a circular one. The inlet x_in = max(4.5, 1.2 m*), with m* Hamrock & Dowson's (1977)
    fully flooded inlet distance in units of a for the expected central film ``H_hertz``
    (Hertzian units on a_c; converted to a by (a_c/a)^2): at low M and small lambda the
    inlet build-up reaches ~12 a (M = 20, lambda = 0.02). The outlet x_in a / 3 (1.5 a for
    the default inlet) keeps X = 0 on a node of every level (12 of the 16 level-0 intervals
    upstream), so that Hc is read at the centre on every level.

    ``enlarge`` = (fx, fy), for domain-convergence studies (studies/ehl/ehl_elliptic_domain.py):
    the inlet times fx and the Y half-width times fy; the outlet is lengthened to the next
    length that keeps X = 0 on a level-0 node (a domain that moves the centre off the nodes
    reads Hc beside the centre: -1.7 % at (20, 10), lambda = 0.1, inlet x2), and the cells
    keep the default's aspect scaled by fy / (length ratio along X), so that the enlarged
    grid one level up per doubling has the default's cells. (1, 1) is the default domain."""
    fx, fy = enlarge
    if not (fx >= 1.0 and fy >= 1.0):
        raise ValueError(f"enlarge factors must be >= 1, got {enlarge!r}")
    if ratio == 1.0:
        d0 = Domain(-4.5, 1.5, -3.0, 3.0)
    else:
        a, b, _ = hertz_ellipse(ratio)
        x_in = 4.5 if H_hertz is None else max(4.5, 1.2 * acc.inlet_distance(H_hertz / a**2))
        d0 = Domain(-x_in * a, x_in * a / 3.0, -3.0 * b, 3.0 * b, aspect=b / a)
    if (fx, fy) == (1.0, 1.0):
        return d0
    x_in = -d0.x0 * fx
    upstream = math.floor(16 * x_in / (x_in + d0.x1) + 1e-9)  # level-0 intervals upstream of X = 0
    x_out = x_in * (16 - upstream) / upstream
    stretch = (x_in + x_out) / (d0.x1 - d0.x0)
    aspect = (1.0 if d0.aspect is None else d0.aspect) * fy / stretch
    return Domain(-x_in, x_out, d0.y0 * fy, d0.y1 * fy, aspect=aspect)



def check_inlet(dom: Domain, expected: float, ratio: float) -> str | None:
    """The inlet check of :mod:`accuracy` in units of the ellipse's X semi-axis a
    (Hamrock & Dowson's m* is measured in the semi-axis along the rolling direction)."""
    a = hertz_ellipse(ratio)[0]
    return acc.inlet_problem(dom.x0 / a, expected / a**2)


# the rigid film of a slender contact spreads along the contact line to |Y| ~ sqrt(2 H / lambda);
# beyond this fraction of the domain's half-width the default domain truncates it and Hc is off
# (studies/ehl/ehl_elliptic_regimes.py, studies/ehl/ehl_elliptic_domain.py: (20, 0) at lambda 0.1
# (ratio 0.34) 13 % low, (20, 10) at lambda 0.05 / 0.02 (0.52 / 0.81) 11 / 38 % low, but at
# lambda 0.12-0.1 (0.43) 13-17 % HIGH (the enlarged inlet and sides take load off the centre);
# (100, 10) (<= 0.28) unaffected)
SIDE_EXTENT_MAX = 0.33


def check_sides(dom: Domain, expected: float, ratio: float) -> str | None:
    """A slender contact whose rigid-film side extent sqrt(2 H / lambda) (H the expected
    central film, Hertzian units) exceeds SIDE_EXTENT_MAX of the domain's Y half-width:
    the solution may be truncated along the contact line (flagged, not refused: the
    criterion is calibrated on a few cases and also flags some that are not truncated).
    The error has either sign: truncation starves the near-rigid film (Hc low, isoviscous
    and very slender cases) or keeps load on the centre that the unbounded domain spreads
    into the inlet and the sides (Hc high at (20, 10), lambda 0.1-0.15; docs/elliptic_regimes.md)."""
    if ratio >= 1.0:
        return None
    r = math.sqrt(2.0 * expected / ratio) / min(-dom.y0, dom.y1)
    if r <= SIDE_EXTENT_MAX:
        return None
    return (f"rigid-film side extent sqrt(2H/lambda) is {r:.2f} of the domain half-width "
            f"(> {SIDE_EXTENT_MAX}): the film may be truncated along the contact line and Hc off "
            "by 10-40 % either way (check with default_domain(..., enlarge=))")
