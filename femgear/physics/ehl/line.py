"""The line-contact EHL entry: :func:`solve_line` (Moes groups in, :class:`EHLResult` out).

``method="fd"`` (default): the finite-difference scheme on graded grids, converged to a
tolerance by the nested Newton of :mod:`femgear.physics.ehl.fd.line` (the solver picks the
grid; every result carries its Richardson estimate).  ``method="fe"``: the Galerkin solver of
:mod:`femgear.physics.ehl.fe.line` on uniform grids (artificial diffusion; a fixed level by
default), kept as the independent reference of the validation tests and for the transient
roughness solver, which builds on its levels.
"""

from __future__ import annotations

from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.fd.line import DEFAULT_TOL, solve_line_fd

METHODS = ("fd", "fe")


def solve_line(M: float, L: float, *, method: str = "fd", **kwargs) -> EHLResult:
    """Isothermal line contact (M, L) by ``method`` (module docstring); ``kwargs`` go to
    :func:`femgear.physics.ehl.fd.line.solve_line_fd` or :func:`femgear.physics.ehl.fe.line.solve_line`."""
    if method == "fd":
        return solve_line_fd(M, L, **kwargs)
    if method == "fe":
        from femgear.physics.ehl.fe.line import solve_line as solve_fe

        return solve_fe(M, L, **kwargs)
    raise ValueError(f"method must be one of {METHODS}, not {method!r}")


__all__ = ["solve_line", "DEFAULT_TOL", "METHODS"]
