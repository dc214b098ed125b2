"""Exceptions shared by all of femgear.

User errors (a bad scene, a bad argument) derive from :class:`FemgearError` and are
reported by the CLI as one line without a traceback.  Solvers that fail raise
:class:`ConvergenceError`, which carries the iteration history.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any


class FemgearError(Exception):
    """Base class of the errors femgear reports to a user as one line."""


class SceneError(FemgearError, ValueError):
    """A scene (or an override) is invalid; ``key`` names the offending entry."""

    def __init__(self, key: str, message: str):
        self.key = key
        self.message = message
        super().__init__(f"{key}: {message}")


class ConvergenceError(FemgearError, RuntimeError):
    """An iterative solver did not converge.

    ``history`` maps names (``"residual"``, ``"load_error"``, ...) to the per-iteration
    values, so that nothing computed before the failure is lost.
    """

    def __init__(self, case: str, message: str, history: Mapping[str, Sequence[Any]] | None = None):
        self.case = case
        self.history = {k: list(v) for k, v in (history or {}).items()}
        last = {k: v[-1] for k, v in self.history.items() if len(v)}
        tail = f" (last: {', '.join(f'{k}={v:.3g}' if isinstance(v, float) else f'{k}={v}' for k, v in last.items())})" if last else ""
        super().__init__(f"{case}: {message}{tail}")
