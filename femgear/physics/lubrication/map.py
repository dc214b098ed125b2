"""Friction and temperature maps: μ and ΔT tabulated over an operating envelope.

A map is built once from any contact solver (the Hertz-level thermal traction here,
the FE TEHL solver when it is on) and queried in the dynamics' time loop at the cost
of a multilinear interpolation.  Its accuracy is not assumed: :meth:`FrictionMap.validate`
compares it with fresh solves at random points inside the envelope and reports the
errors, which the build records.

Axes: load per unit length ``w`` [N/m], reduced radius ``R`` [m], entrainment speed
``ue`` [m/s], |slide-to-roll ratio| ``srr`` [-] and bulk temperature ``T`` [K].  μ is
even in the SRR (its sign is the sliding direction, which the dynamics applies).
Speeds, loads and radii are interpolated in their logarithms, where μ is smoother.
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from femgear.docfields import document_fields

AXES = ("w", "R", "ue", "srr", "T")
_LOG_AXES = frozenset({"w", "R", "ue"})

Solver = Callable[..., tuple[np.ndarray, np.ndarray]]
"""solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise), arrays of one shape."""


def _coord(name: str, values) -> np.ndarray:
    v = np.asarray(values, dtype=float)
    return np.log(v) if name in _LOG_AXES else v


#: the map's tolerance on μ: the largest |Δμ| / max(μ, 0.005) at the validation samples [-].  A choice: μ enters
#: the dynamics as the friction force, whose error then stays within that of the traction law itself
MU_TOLERANCE = 0.05
MU_FLOOR = 0.005   #: the μ below which the map's μ errors are measured absolutely (relative to this value) [-]
#: the map's tolerance on the temperature rise: this share of the map's largest ΔT, at least DT_FLOOR [-]
DT_TOLERANCE = 0.05
DT_FLOOR = 1.0   #: [K]

log = logging.getLogger("femgear.physics.lubrication")


@document_fields
@dataclass(frozen=True)
class MapError:
    """Interpolation error against fresh solves at random points of the envelope, beside the map's tolerance."""

    samples: int
    """fresh solves at random points of the envelope [-]"""
    mu_max_abs: float
    """largest |Δμ| at the samples [-]"""
    mu_rms_abs: float
    """root-mean-square Δμ at the samples [-]"""
    mu_max_rel: float
    """largest |Δμ| / max(μ, 0.005) at the samples [-]"""
    dT_max_abs: float
    """largest |ΔT| error at the samples [K]"""
    mu_tolerance: float = MU_TOLERANCE
    """the tolerance on ``mu_max_rel`` [-]"""
    dT_tolerance: float = math.inf
    """the tolerance on ``dT_max_abs`` [K]"""

    @property
    def within_tolerance(self) -> bool:
        return self.mu_max_rel <= self.mu_tolerance and self.dT_max_abs <= self.dT_tolerance

    def message(self) -> str:
        """One line: the errors against the tolerances, and whether they hold."""
        verdict = "within" if self.within_tolerance else "ABOVE"
        return (f"friction map error at {self.samples} fresh solves: mu {100 * self.mu_max_rel:.2g} % (tolerance "
                f"{100 * self.mu_tolerance:g} %), temperature rise {self.dT_max_abs:.3g} K (tolerance "
                f"{self.dT_tolerance:.3g} K): {verdict} its tolerance")


@dataclass(frozen=True)
class FrictionMap:
    axes: dict[str, np.ndarray]
    mu: np.ndarray
    temperature_rise: np.ndarray
    build_seconds: float
    error: MapError | None = None
    _interp: tuple = field(default=(), repr=False, compare=False)

    @classmethod
    def build(cls, solver: Solver, axes: dict[str, np.ndarray]) -> FrictionMap:
        """Solve at every grid point of ``axes`` (all five, strictly increasing)."""
        missing = set(AXES) - set(axes)
        if missing:
            raise ValueError(f"map axes missing: {', '.join(sorted(missing))}")
        axes = {k: np.asarray(axes[k], dtype=float) for k in AXES}
        for name, v in axes.items():
            if v.ndim != 1 or v.size < 2 or np.any(np.diff(v) <= 0):
                raise ValueError(f"axis {name} must be strictly increasing with ≥ 2 values")
            if name in _LOG_AXES and v[0] <= 0:
                raise ValueError(f"axis {name} must be positive")
        start = time.perf_counter()
        grids = np.meshgrid(*axes.values(), indexing="ij")
        mu, dT = solver(**{k: g.ravel() for k, g in zip(AXES, grids)})
        shape = grids[0].shape
        return cls(axes=axes, mu=np.reshape(mu, shape), temperature_rise=np.reshape(dT, shape),
                   build_seconds=time.perf_counter() - start)

    def _interpolators(self):
        if not self._interp:
            pts = tuple(_coord(k, self.axes[k]) for k in AXES)
            object.__setattr__(self, "_interp", (
                RegularGridInterpolator(pts, self.mu), RegularGridInterpolator(pts, self.temperature_rise)))
        return self._interp

    def __call__(self, w, R, ue, srr, T) -> tuple[np.ndarray, np.ndarray]:
        """μ and ΔT at the given operating points (arrays broadcast); outside the envelope raises."""
        args = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (w, R, ue, np.abs(srr), T)))
        for name, a in zip(AXES, args):
            lo, hi = self.axes[name][0], self.axes[name][-1]
            if np.any(a < lo * (1 - 1e-12)) or np.any(a > hi * (1 + 1e-12)):
                raise ValueError(f"{name} outside the map's envelope [{lo:.4g}, {hi:.4g}]")
        x = np.stack([np.clip(_coord(n, a), _coord(n, self.axes[n][0]), _coord(n, self.axes[n][-1]))
                      for n, a in zip(AXES, args)], axis=-1)
        f_mu, f_dT = self._interpolators()
        return f_mu(x), f_dT(x)

    def validate(self, solver: Solver, samples: int = 200, seed: int = 0) -> FrictionMap:
        """A copy of the map with its error measured at ``samples`` random points, beside its tolerance
        (:data:`MU_TOLERANCE`; :data:`DT_TOLERANCE` of the map's largest ΔT, at least :data:`DT_FLOOR`); an error
        above the tolerance is logged as a warning (and the summary of a run flags it)."""
        rng = np.random.default_rng(seed)
        pts = {}
        for name in AXES:
            lo, hi = _coord(name, self.axes[name][[0, -1]])
            c = rng.uniform(lo, hi, samples)
            pts[name] = np.exp(c) if name in _LOG_AXES else c
        mu_ref, dT_ref = solver(**pts)
        mu, dT = self(**pts)
        err = np.abs(mu - mu_ref)
        e = MapError(samples=samples, mu_max_abs=float(err.max()), mu_rms_abs=float(np.sqrt(np.mean(err**2))),
                     mu_max_rel=float(np.max(err / np.maximum(mu_ref, MU_FLOOR))),
                     dT_max_abs=float(np.max(np.abs(dT - dT_ref))),
                     dT_tolerance=max(DT_TOLERANCE * float(np.max(np.abs(self.temperature_rise))), DT_FLOOR))
        if not e.within_tolerance:
            log.warning(e.message())
        return FrictionMap(self.axes, self.mu, self.temperature_rise, self.build_seconds, e)


def hertz_level_solver(friction) -> Solver:
    """The ``formula``-level contact solver in the map's signature: μ and the film temperature rise of
    ``friction`` (a :class:`femgear.physics.lubrication.path.LineFriction`)."""

    def solve(w, R, ue, srr, T):
        r = friction(w, R, ue, srr, T)
        return r.mu, r.film_max

    return solve


def envelope_axes(contact, ambient_temperature: float, resolution: int = 1,
                  load_range: tuple[float, float] = (0.25, 3.0), temperature_span: float = 60.0) -> dict[str, np.ndarray]:
    """Map axes covering the path of contact of a contact pass (a
    :class:`femgear.physics.contact.path.ContactPath`), with room for dynamic loads.

    Loads span ``load_range`` times the nominal w', temperatures ``ambient_temperature`` … ambient +
    ``temperature_span`` [K]; SRR axes are graded towards 0 where μ has its knee.
    ``resolution`` ≥ 1 multiplies the number of points per axis.
    """
    if resolution < 1:
        raise ValueError(f"resolution must be ≥ 1 (got {resolution})")
    k, r = contact.kin, resolution
    T0 = ambient_temperature
    srr_max = 1.05 * float(np.max(np.abs(k.srr)))
    return {
        "w": contact.load_per_length * np.geomspace(*load_range, 3 + 3 * r),
        "R": np.geomspace(0.98 * k.R.min(), 1.02 * k.R.max(), 1 + 2 * r),
        "ue": np.geomspace(0.95 * k.ue.min(), 1.05 * k.ue.max(), 1 + 2 * r),
        "srr": np.r_[0.0, np.geomspace(1e-3 * srr_max, srr_max, 4 + 4 * r)],
        "T": np.linspace(T0, T0 + temperature_span, 2 + 2 * r),
    }
