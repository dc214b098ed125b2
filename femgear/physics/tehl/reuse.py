"""Reuse of a contact's TEHL solve when its load has hardly changed (issue 26: the full fidelity's cost).

The coupling loop queries the lubrication level at the same path contacts in every pass (same
radii, entrainment speed, slide-to-roll ratio and bulk temperature); only the loads move, and
after the first dynamic pass by ~1e-5 of themselves (the baseline's passes 2 and 3: mesh-force
changes 5.8e-6 and 6.5e-9).  A direct point solve costs ~0.3–1 s (the line-contact fallback of
a contact the point solver cannot hold: ~7 s), four passes × 21–42 contacts.

Rule: a contact's latest result is reused when the change it would make is estimated below
:data:`REUSE_TOL` (relative, on μ and on the largest film temperature rise):

    estimate = s · |F − F_prev| / F_prev + s_T · |T − T_prev|,   s = max(|Δμ/μ|, |ΔT/T|) / |ΔF/F|

from the contact's two latest distinct solves at one bulk temperature (its own measured load sensitivity; the
baseline's contacts: s = 0.07–1.7), or s = :data:`ASSUMED_SENSITIVITY` while only one solve exists (or the two
were at different bulk temperatures, which the load's share cannot be told from).  The bulk temperature T
moves from pass to pass with the flanks' bulk rise (the coupling's step 5); s_T is the oil's temperature-viscosity
coefficient β = −d ln η/dT [1/K], which bounds the relative change per kelvin of the film (h ∝ η^0.7) and of the
friction and flash temperature (μ ∝ η^n, n ≤ 1 from the Newtonian to the Eyring film).  The
solver's answer is smooth in the load at this scale (a 1e-6 load change moves μ by 6.5e-8 …
3.7e-7 relative, linearly), so the estimate is a first-order bound.  Where the estimate
exceeds the tolerance the contact is solved again: the rule never reuses what its estimate
does not support.  :class:`ReuseReport` counts both and the largest load change and estimate
reused (the solver's :attr:`LatestSolve.reuse`; logged at ``-v``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

#: largest estimated relative change of μ and ΔT_max that a reused solve may hide
REUSE_TOL = 1e-4
#: load sensitivity assumed while a contact has only one solve (measured 0.07–1.7 on the baseline)
ASSUMED_SENSITIVITY = 2.0
_T_FLOOR = 0.01    #: [K] temperature rises below this count as this (a cold contact's relative ΔT is noise)


@dataclass
class ReuseReport:
    """What one call of the solver reused: counts, the largest load change and change estimate reused."""

    solved: int = 0
    reused: int = 0
    max_load_change: float = 0.0
    max_estimate: float = 0.0
    tolerance: float = REUSE_TOL

    def describe(self) -> str:
        return (f"{self.reused} contacts reused from the previous pass (load change ≤ {self.max_load_change:.2g}, "
                f"estimated μ/ΔT change ≤ {self.max_estimate:.2g} < {self.tolerance:g}), {self.solved} solved")


def sensitivity(history: list) -> float:
    """max(|Δμ/μ|, |ΔT/T|) / |ΔF/F| from the two latest solves [(load, result)] or [(load, result, bulk
    temperature)] (the assumed value with fewer, when their loads are too close to tell, or when their bulk
    temperatures differ)."""
    if len(history) < 2:
        return ASSUMED_SENSITIVITY
    (f1, r1, *t1), (f2, r2, *t2) = history[-2], history[-1]
    df = abs(f2 - f1) / f1
    if df < 1e-7 or t1 != t2:
        return ASSUMED_SENSITIVITY
    dmu = abs(r2.mu - r1.mu) / max(abs(r1.mu), 1e-12)
    dT = abs(r2.dT_max - r1.dT_max) / max(abs(r1.dT_max), _T_FLOOR)
    return max(dmu, dT) / df


def reusable(history: list, load: float, report: ReuseReport, temperature: float | None = None,
             temperature_sensitivity: float = 0.0):
    """The latest result of ``history`` [(load, result)], or [(load, result, bulk temperature)] with
    ``temperature`` [K] the query's and ``temperature_sensitivity`` s_T [1/K] (module docstring), if reusing it
    at ``load`` is estimated within :data:`REUSE_TOL` (counted in ``report``), else None (a solve is due;
    counted)."""
    if history:
        f_prev, r_prev, *t_prev = history[-1]
        change = abs(load - f_prev) / f_prev
        estimate = sensitivity(history) * change
        if t_prev and temperature is not None:
            estimate += temperature_sensitivity * abs(temperature - t_prev[0])
        if estimate <= REUSE_TOL:
            report.reused += 1
            report.max_load_change = max(report.max_load_change, change)
            report.max_estimate = max(report.max_estimate, estimate)
            return r_prev
    report.solved += 1
    return None


@dataclass(frozen=True)
class LatestSolve:
    """What a contact solver's latest call solved: its inputs and per-contact results (a thermal level's film reads
    them instead of solving the same contacts again), the reuse it made and the contacts it handed over."""

    inputs: tuple[np.ndarray, ...]     #: (w [N/m], R [m], ue [m/s], |srr| [-], T [K]) as solved, broadcast
    results: tuple                     #: one result per contact, in the inputs' order
    reuse: ReuseReport | None = None   #: what the call reused (:func:`reusable`; None: the solver never reuses)
    handed_over: int = 0               #: contacts handed over to the face slices (``tehl-point``) [-]

    def at(self, *inputs: np.ndarray) -> tuple | None:
        """The results where ``inputs`` are exactly the solved ones (same shapes and values), else None."""
        same = len(inputs) == len(self.inputs) and all(
            np.shape(a) == b.shape and np.array_equal(a, b) for a, b in zip(inputs, self.inputs))
        return self.results if same else None


@dataclass
class RecordingSolver:
    """A contact solver in the map signature ``solver(w=, R=, ue=, srr=, T=) -> (μ, ΔT)`` that keeps its latest
    call's :class:`LatestSolve` (declared state of a callable, not attributes set on a function): ``run(w, R, ue,
    srr, T) -> (μ, ΔT, LatestSolve)``."""

    run: Callable[..., tuple[np.ndarray, np.ndarray, LatestSolve]]
    latest: LatestSolve | None = None  #: the latest call's record (None before the first)

    def __call__(self, w, R, ue, srr, T) -> tuple[np.ndarray, np.ndarray]:
        mu, dT, self.latest = self.run(w, R, ue, srr, T)
        return mu, dT
