"""Frozen result records of the EHL solvers and their derived quantities."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class EHLResult:
    """Converged EHL solution in Hertzian units plus Moes-unit films.

    Fields are on the node grid: point contacts ``P``/``H`` of shape (ny, nx) with
    coordinates ``x`` (nx,) and ``y`` (ny,); line contacts shape (nx,), ``y`` empty.
    ``error_estimate`` holds the relative Richardson estimates of Hc and Hmin from the
    nested levels (:mod:`femgear.physics.ehl.core.accuracy`), ``tol`` the tolerance they are held
    to and ``flags`` every reason not to trust the result at that tolerance.
    ``Hc``/``Hmin`` are in Moes units (H_Moes = (h/R_x)(2U)^(-1/2)); ``Hc_hertz`` etc. in
    Hertzian units (H = h R / a^2). ``history`` holds per-level Newton histories.
    """

    kind: str  # "point" or "line"
    M: float
    L: float
    Hc: float
    Hmin: float
    Pmax: float
    Pmax_at: tuple[float, float]
    outlet_x: float
    Hc_hertz: float
    Hmin_hertz: float
    H0: float
    load_error: float
    iterations: int
    nodes: int
    seconds: float
    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    P: np.ndarray = field(repr=False)
    H: np.ndarray = field(repr=False)
    history: dict[str, Any] = field(repr=False, default_factory=dict)
    levels: tuple[dict, ...] = field(repr=False, default=())
    converged: bool = True
    error_estimate: dict[str, float | None] = field(default_factory=dict)
    tol: float | None = None
    flags: tuple[str, ...] = ()

    @property
    def warning(self) -> str | None:
        """The flags joined, or None: set whenever the result's own error estimate
        exceeds its tolerance (or is missing) or the domain truncates the inlet."""
        return "; ".join(self.flags) if self.flags else None

    def summary(self) -> dict[str, Any]:
        """JSON-friendly scalars (the CLI's output keys)."""
        return {
            "kind": self.kind, "M": self.M, "L": self.L, "Hc": self.Hc, "Hmin": self.Hmin,
            "Pmax": self.Pmax, "Pmax_at": list(self.Pmax_at), "outlet_x": self.outlet_x,
            "Hc_hertz": self.Hc_hertz, "Hmin_hertz": self.Hmin_hertz, "H0": self.H0,
            "load_error": self.load_error, "converged": self.converged,
            "iterations": self.iterations, "nodes": self.nodes, "seconds": self.seconds,
            "levels": list(self.levels), "error_estimate": dict(self.error_estimate),
            "tol": self.tol, "flags": list(self.flags), "warning": self.warning,
            "method": self.history.get("method", "newton"), "fallback": list(self.history.get("fallback", [])),
            "residual_history": list(self.history.get("residual", [])),
            "load_error_history": list(self.history.get("load_error", [])),
        }


def centre_values(x: np.ndarray, y: np.ndarray, P: np.ndarray, H: np.ndarray):
    """Hc (at X = Y = 0), Hmin, Pmax and its location, outlet (cavitation) X on Y = 0."""
    if P.ndim == 2:
        j0 = int(np.argmin(np.abs(y)))
        i0 = int(np.argmin(np.abs(x)))
        Hc = float(H[j0, i0])
        k = np.unravel_index(int(np.argmax(P)), P.shape)
        at = (float(x[k[1]]), float(y[k[0]]))
        line_P = P[j0]
    else:
        i0 = int(np.argmin(np.abs(x)))
        Hc = float(H[i0])
        k = int(np.argmax(P))
        at = (float(x[k]), 0.0)
        line_P = P
    # outlet: first node downstream of the pressure maximum where P returns to ~0
    kc = int(np.argmax(line_P))
    tail = np.nonzero(line_P[kc:] <= 1e-6 * max(line_P.max(), 1e-300))[0]
    outlet = float(x[kc + tail[0]]) if tail.size else float(x[-1])
    inside = H if P.ndim == 1 else H
    return Hc, float(inside.min()), float(P.max()), at, outlet
