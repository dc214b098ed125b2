"""The ``ehl-line`` lubrication level: line-contact EHL at the positions of the path.

At each contact the isothermal line solution (:func:`solve_line_dimensional`, the FD solver on graded
grids, Roelands viscosity and Dowson–Higginson density at the inlet viscosity η(0, T_bulk) and α(T_bulk)) gives the
pressure and film fields; the sliding traction is the Ree–Eyring shear τ0 asinh(η(p, T) γ̇/τ0),
γ̇ = |v1 − v2|/h, integrated over them, and the contact temperature rise is Blok's flash temperature for
that μ.  μ = ∫τ dx / w'.  (The thermal film and its feedback on the viscosity are the ``tehl`` level.)

One discretisation per path: the contact with the largest Moes M (the thinnest film for its width, the
one that needs the finest grid) is solved first to the tolerance, and its level is kept for every
position (at least ``min_level``), so that the fields along the path are smooth to the solver's
tolerance: a level that changed from one position to the next would step the films by up to that
tolerance.  Each position is warm-started from the previous one and carries its own two-level
Richardson estimate.  The grids resolve the outlet pressure spike (``spike=True`` of
:func:`femgear.physics.ehl.fd.line.solve_line_fd`), so that its peak, ``pressure_max``, is smooth along the path too.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.errors import SceneError
from femgear.physics.contact.film import moes_line
from femgear.physics.ehl.dimensional import DimensionalEHL, EHLOil, solve_line_dimensional
from femgear.physics.ehl.fd.line import DEFAULT_TOL, MAX_LEVEL, MIN_LEVEL, _level_of
from femgear.physics.lubrication.flash import blok_flash_temperature
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, shear_stress


@dataclass(frozen=True)
class LineFilms:
    """The line EHL along a path: films [m], pressure peaks [Pa], the relative error estimate of each
    position (the larger of h_c's and h_min's) and the grid level kept for the path."""

    central: np.ndarray
    minimum: np.ndarray
    pressure_max: np.ndarray
    error_estimate: np.ndarray
    level: int
    results: tuple


def _oil(oil: OilLaw, T: float) -> EHLOil:
    return EHLOil(eta0=float(oil.viscosity(0.0, T)), alpha=float(oil.pressure_viscosity(T)), viscosity="roelands",
                  compressible=True)


def line_ehl_path(w, R, ue, T, oil: OilLaw, E_red: float, *, tol: float = DEFAULT_TOL,
                  min_level: int | None = None, refined: bool = False) -> LineFilms:
    """Isothermal line EHL at each contact (arrays ``w``, ``R``, ``ue``, bulk temperatures ``T`` broadcast
    against them), one grid level for all (module docstring); when a contact's estimate exceeds ``tol`` on the
    probe's level, the path is solved once more one level finer (``refined``: that second pass)."""
    w, R, ue, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, T)))
    shape = w.shape
    w, R, ue, T = (a.ravel() for a in (w, R, ue, T))
    oils = [_oil(oil, float(t)) for t in T]
    M = np.array([moes_line(wi / (E_red * Ri), o.eta0 * ui / (E_red * Ri), o.alpha * E_red)[0]
                  for wi, Ri, ui, o in zip(w, R, ue, oils)])
    first = int(np.argmax(M))
    floor = MIN_LEVEL if min_level is None else min_level
    probe = _solve(w[first], R[first], ue[first], E_red, oils[first], dict(tol=tol, min_level=floor, spike=True))
    level = max(_level_of(probe.result), floor)
    out: list[DimensionalEHL | None] = [None] * w.size
    out[first] = probe if _level_of(probe.result) == level else None
    prev, reuse = None, {}
    for i in range(w.size):
        if out[i] is None:
            out[i] = _solve(w[i], R[i], ue[i], E_red, oils[i], dict(level=level, tol=tol, start=prev, reuse=reuse,
                                                                              spike=True))
        prev = out[i].result
    est = np.array([max(v for v in r.result.error_estimate.values() if v is not None) for r in out])
    if est.max() > tol and level < MAX_LEVEL and not refined:
        # a position other than the probe needs more: the whole path one level finer, once
        return line_ehl_path(w.reshape(shape), R.reshape(shape), ue.reshape(shape), T.reshape(shape), oil, E_red,
                             tol=tol, min_level=level + 1, refined=True)
    films = (np.array([getattr(r, k) for r in out]).reshape(shape) for k in ("hc", "hmin", "pmax"))
    return LineFilms(*films, error_estimate=est.reshape(shape), level=level, results=tuple(out))


def _solve(w, R, ue, E_red, oil: EHLOil, options: dict) -> DimensionalEHL:
    try:
        return solve_line_dimensional(float(w), float(R), float(ue), E_red, oil, **options)
    except SceneError as exc:       # the solver's own range
        raise SceneError("physics.lubrication", f'"ehl-line": {exc.message}; use "formula" or "tehl"') from None


def ehl_line_solver(oil: OilLaw, E_red: float, solids: Solids, tau0: float, tol: float = DEFAULT_TOL,
                    min_level: int | None = None):
    """The ``ehl-line`` contact solver in the map signature (w, R, ue, srr, T) -> (μ, ΔT): line EHL to ``tol``
    with ``oil``, reduced modulus ``E_red`` [Pa], ``solids`` (Blok's flash temperature) and the Eyring stress
    ``tau0`` [Pa]; ``solve.last`` holds the :class:`LineFilms` of the latest call."""

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, srr, T)))
        films = line_ehl_path(w, R, ue, T, oil, E_red, tol=tol, min_level=min_level)
        mu, dT = np.empty(w.size), np.empty(w.size)
        for i, (r, wi, Ri, ui, si, Ti) in enumerate(zip(films.results, w.ravel(), R.ravel(), ue.ravel(), srr.ravel(),
                                                         T.ravel())):
            vs = abs(si) * ui
            tau = shear_stress(oil.viscosity(r.p, Ti), vs / r.h, "eyring", tau0)
            mu[i] = np.trapezoid(tau, r.x) / wi
            b = np.sqrt(8 * wi * Ri / (np.pi * E_red))
            dT[i] = blok_flash_temperature(mu[i], wi, vs, b, ui * (1 + si / 2), ui * (1 - si / 2), solids.B1, solids.B2)
        solve.last = films
        return mu.reshape(w.shape), dT.reshape(w.shape)

    solve.last = None
    return solve
