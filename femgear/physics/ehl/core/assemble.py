"""Assembly of an :class:`EHLResult` from a solved field (shared by the Newton and the
multigrid drivers): centre-line quantities, finiteness check, error estimate and flags."""

from __future__ import annotations

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core.results import EHLResult, centre_values


def assemble(kind: str, M: float, L: float, x, y, P2: np.ndarray, H2: np.ndarray, *, H0: float,
             load_error: float, fac: float, history: dict, iterations: int, per_level,
             seconds: float, tol: float = acc.DEFAULT_TOL,
             extra_flags: tuple[str, ...] = (), estimate: dict | None = None) -> EHLResult:
    """EHLResult of the fields ``P2``, ``H2`` (Hertzian units; (ny, nx) or (nx,)).

    Raises :class:`ConvergenceError` (with ``history``) on a non-finite field; P within
    round-off of 0 is set to 0 (the active set of the last update).  ``estimate``: the error
    estimate when the solver made it (default: :func:`accuracy.error_estimate` of ``per_level``)."""
    if not (np.all(np.isfinite(P2)) and np.all(np.isfinite(H2))):
        raise ConvergenceError(f"ehl {kind}", "non-finite solution", history)
    P2 = np.where(np.abs(P2) <= 1e-12 * max(P2.max(), 1.0), np.maximum(P2, 0.0), P2)
    Hc, Hmin, Pmax, at, outlet = centre_values(x, y, P2, H2)
    estimate = acc.error_estimate(per_level) if estimate is None else estimate
    return EHLResult(kind=kind, M=float(M), L=float(L), Hc=Hc * fac, Hmin=Hmin * fac,
                     Pmax=Pmax, Pmax_at=at, outlet_x=outlet, Hc_hertz=Hc, Hmin_hertz=Hmin,
                     H0=float(H0), load_error=float(load_error), iterations=int(iterations),
                     nodes=int(P2.size), seconds=seconds, x=x, y=y, P=P2, H=H2, history=history,
                     levels=tuple(per_level), error_estimate=estimate, tol=tol,
                     flags=acc.flags_for(estimate, tol, extra_flags))
