"""The line contact's domain and its graded, nested node grids (Hertzian units, X = x/b).

Domain.  The inlet starts at :data:`INLET_MARGIN` times the fully flooded distance m* of Hamrock &
Dowson (1977, J. Lubr. Technol. 99:15; :func:`femgear.physics.ehl.core.accuracy.inlet_distance`) for
the expected central film, and never closer than X = -4.5 (Venner & Lubrecht 2000); the outlet lies a
third of the inlet length downstream and never closer than X = 1.5, so that the rigid films of light
contacts (Martin's cavitation point 0.475 sqrt(2 H) past the centre) stay inside.  m* marks the start of
starvation, not a converged film: measured against an inlet at X = -48 (tol 0.3 %), Hc is low by
1.0-5.0 % at 1.25 m*, 0.2-1.9 % at 2 m*, up to 0.7 % at 3 m* and 0.04-0.32 % at 4 m* over (M, L) = (1, 1),
(1, 10), (1, 25), (2, 5), (3, 10), (5, 25) (the rigid, lightly loaded contacts, whose pressure builds up far
upstream); so 4 m*, which moves a heavily loaded contact's inlet only from -4.5 to about -4.8.

Grading.  A heavily loaded contact changes on the scale of its inlet and outlet
meniscus, where the gap opens to a few central films: the Hertzian gap outside the
contact grows like (|X| - 1)^(3/2), so that zone is w ~ H_c^(2/3) wide (H_c the central
film in Hertzian units; 0.008 at (M, L) = (1000, 4.3) against the half-width 1).  The
nodes are the image of a uniform grid in xi under the mapping whose density is

    rho(X) = 1 + A [sech^2((X + 1)/w) + sech^2((X - 1)/w)],   w = WIDTH H_c^(2/3),

A = clip(L_dom/(4 w) - 1, 0, A_MAX) (L_dom the domain length): uniform for light contacts
(w ~ 1), up to ~50x finer at the two edges of a heavy one.  Measured with the FD scheme
(:mod:`femgear.physics.ehl.fd.line_operator`) at (1000, 4.3), Barus: Hc 1.857 / 1.882 /
1.888 on 257 / 513 / 1025 nodes (uniform: 1.523 / 1.983 / 2.103 / 2.133 on 513 ... 4097
at (300, 4), i.e. the graded grid needs about 8x fewer nodes for the same error).

Spike bump (``LineDomain.with_spike``, the path solvers).  The outlet pressure spike of a light or moderate contact
sits inside the contact (X ~ 0.5 on the baseline's path), away from the edge grading, and is narrower than a cell
of the level that meets the films' tolerance: its height does not converge with the grid (627 / 670 / 718 / 749 /
773 MPa on 513 ... 8193 nodes at the baseline's first contact), and its maximum over the nodes steps from one path
position to the next as it crosses them (second differences 7 % of the peak on 513 and 1025 nodes, 0.7 % on 8193).
A third term of the density, A_s sech^2((X - X_s)/w_s) with X_s the spike located by a first solve (and moved to
where the bumped solve finds it: ``solve_line_fd``, :data:`femgear.physics.ehl.fd.line.SPIKE_PASSES`), puts
:data:`SPIKE_DENSITY` times more nodes across :data:`SPIKE_WIDTH` about it, so that the spike is resolved on every
level and the peaks along a path are smooth.  The bump sits at the spike, the local pressure maximum nearest the
outlet, not at the largest pressure (:func:`femgear.physics.ehl.fd.line.spike_index`): on a heavy contact the Hertzian
dome is the higher.  Its cells, down to 0.0003 b on 1025 nodes, can stall the thermal loop of a heavy contact near
rolling (the marine zoo pair); a path sequence where that happens is solved again on the gentler
:data:`SPIKE_DENSITY_GENTLE` (:func:`femgear.physics.tehl.solver.tehl_path_results`), about 35 nodes across w_s on
1025 nodes.

The levels are nested: level k has ``16 * 2**k`` intervals, the image of the uniform xi
grid, so that each level's nodes are every other node of the next and the Richardson
estimate of :mod:`femgear.physics.ehl.core.accuracy` applies; X = 0 is a node of every level
(the mapping is split there, so that Hc is read at the centre).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from femgear.physics.ehl.core import accuracy as acc

X0_MIN, X1_MIN = -4.5, 1.5   #: the shortest domain [Hertz half-widths]
INLET_MARGIN = 4.0           #: the inlet at this multiple of m* [-] (module docstring)
WIDTH = 4.0                  #: w = WIDTH H_c^(2/3) [-]
A_MAX = 100.0                #: the largest density ratio of the grading [-]
N0 = 16                      #: intervals of level 0
SPIKE_WIDTH = 0.05           #: w_s of the spike bump [Hertz half-widths] (module docstring)
SPIKE_DENSITY = 100.0        #: A_s of the spike bump: its density ratio [-] (30: second differences 1.8 %, 100: 0.5 % at level 5)
#: the gentler bump of a path sequence where a contact's thermal loop does not settle on the first one (module
#: docstring)
SPIKE_DENSITY_GENTLE = 10.0


@dataclass(frozen=True)
class LineDomain:
    """Domain [x0, x1] and the grading width ``w`` and amplitude ``A`` of its grids."""

    x0: float
    x1: float
    w: float
    A: float
    xs: float = 0.0     #: centre X_s of the spike bump [-]
    ws: float = 1.0     #: its width w_s [-]
    As: float = 0.0     #: its amplitude A_s (0: none) [-]

    def nodes(self, level: int) -> np.ndarray:
        """The nodes of ``level`` (``16 * 2**level`` intervals)."""
        return _nodes(self.x0, self.x1, self.w, self.A, int(level), (self.xs, self.ws, self.As))

    def with_spike(self, xs: float, density: float = SPIKE_DENSITY) -> LineDomain:
        """This domain with the spike bump of amplitude ``density`` at ``xs`` (module docstring)."""
        return LineDomain(self.x0, self.x1, self.w, self.A, float(xs), SPIKE_WIDTH, float(density))

    def as_list(self) -> list[float]:
        return [self.x0, self.x1, self.w, self.A, self.xs, self.ws, self.As]

    def coarse_level(self, h_max: float) -> int:
        """The lowest level whose largest spacing is at most ``h_max``."""
        k = 0
        while np.max(np.diff(self.nodes(k))) > h_max and k < 12:
            k += 1
        return k


def line_domain(H_hertz: float, x0: float | None = None, x1: float | None = None,
                graded: bool = True) -> LineDomain:
    """The domain of a line contact whose expected central film is ``H_hertz`` (Hertzian
    units); an explicit ``x0`` / ``x1`` is kept as given (an inlet inside m* is then the
    caller's to flag, :func:`femgear.physics.ehl.core.accuracy.inlet_problem`)."""
    if x0 is None:
        x0 = -max(-X0_MIN, INLET_MARGIN * acc.inlet_distance(H_hertz))
    if x1 is None:
        x1 = max(X1_MIN, -x0 / 3.0)
    if not x0 < -1.0 < 1.0 < x1:
        raise ValueError("the domain must contain the Hertzian contact [-1, 1]")
    w = WIDTH * max(H_hertz, 1e-12) ** (2.0 / 3.0)
    A = float(np.clip((x1 - x0) / (4.0 * w) - 1.0, 0.0, A_MAX)) if graded else 0.0
    return LineDomain(float(x0), float(x1), float(w), A)


def _density_integral(x: np.ndarray, w: float, A: float, spike=(0.0, 1.0, 0.0)) -> np.ndarray:
    """int_0^x rho dX = x + A w [tanh((x + 1)/w) + tanh((x - 1)/w)] (the two tanh(1/w) cancel), plus the spike
    bump's A_s w_s [tanh((x - X_s)/w_s) + tanh(X_s/w_s)] where ``spike`` = (X_s, w_s, A_s) has A_s > 0."""
    out = x + A * w * (np.tanh((x + 1.0) / w) + np.tanh((x - 1.0) / w))
    xs, ws, As = spike
    return out + As * ws * (np.tanh((x - xs) / ws) + np.tanh(xs / ws)) if As > 0 else out


@lru_cache(maxsize=64)
def _nodes(x0: float, x1: float, w: float, A: float, level: int, spike=(0.0, 1.0, 0.0)) -> np.ndarray:
    n = N0 * 2**level
    s0, s1 = _density_integral(np.array([x0, x1]), w, A, spike)
    # X = 0 on a node of level 0: the intervals upstream of it
    up = int(min(max(round(N0 * (0.0 - s0) / (s1 - s0)), 1), N0 - 1)) * 2**level
    out = np.empty(n + 1)
    out[: up + 1] = _invert(np.linspace(s0, 0.0, up + 1), x0, 0.0, w, A, spike)
    out[up:] = _invert(np.linspace(0.0, s1, n - up + 1), 0.0, x1, w, A, spike)
    out[0], out[up], out[-1] = x0, 0.0, x1
    out.setflags(write=False)
    return out


def _invert(targets: np.ndarray, lo: float, hi: float, w: float, A: float, spike=(0.0, 1.0, 0.0)) -> np.ndarray:
    """X in [lo, hi] with s(X) = targets, s the increasing :func:`_density_integral`: a
    table start refined by safeguarded Newton steps to round-off."""
    xs = np.linspace(lo, hi, 8193)
    x = np.interp(targets, _density_integral(xs, w, A, spike), xs)
    for _ in range(8):
        x = np.clip(x - (_density_integral(x, w, A, spike) - targets) / _density(x, w, A, spike), lo, hi)
    return x


def _density(x: np.ndarray, w: float, A: float, spike=(0.0, 1.0, 0.0)) -> np.ndarray:
    with np.errstate(over="ignore"):  # sech^2 underflows to 0 far from the edges
        out = 1.0 + A * (1.0 / np.cosh((x + 1.0) / w) ** 2 + 1.0 / np.cosh((x - 1.0) / w) ** 2)
        xs, ws, As = spike
        return out + As / np.cosh((x - xs) / ws) ** 2 if As > 0 else out


def hertz_start(X: np.ndarray) -> np.ndarray:
    """The dry Hertz pressure sqrt(1 - X^2) on the nodes."""
    return np.sqrt(np.maximum(1.0 - X**2, 0.0))


def expected_film(M: float, L: float) -> float:
    """Moes's (1992) central film of the line contact in Hertzian units."""
    from femgear.physics.contact.film import moes_line_central
    from femgear.physics.ehl.core import params as pr

    return float(moes_line_central(M, L)) / pr.line_h_moes_factor(M)

