"""Exceptions shared by all of femgear.

User errors (a bad scene, a bad argument, an unwritable output folder, a job over the
memory budget) derive from :class:`FemgearError` and are reported by the CLI as one
line without a traceback, exit code :attr:`FemgearError.exit_code` (2: the input is
wrong).  Solvers that fail raise :class:`ConvergenceError` (exit code 1), which
carries the iteration history.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any


class FemgearError(Exception):
    """Base class of the errors femgear reports to a user as one line.

    Picklable with its attributes (a process pool sends a worker's error back to the parent; the
    default pickling calls ``cls(*args)`` with the one formatted message, which the subclasses'
    constructors do not take).
    """

    exit_code: int = 2

    def __reduce__(self):
        return _rebuild, (type(self), self.args, dict(self.__dict__))


def _rebuild(cls: type, args: tuple, state: dict) -> FemgearError:
    """The unpickled error: ``args`` (the message) and the attributes, without calling ``cls.__init__``."""
    try:
        err = cls.__new__(cls)
    except TypeError:          # MemoryError.__new__ refuses subclasses of two bases ("not safe")
        err = Exception.__new__(cls)
    Exception.__init__(err, *args)
    err.__dict__.update(state)
    return err


class ArgumentError(FemgearError, ValueError):
    """A command-line argument (or function argument) is invalid; ``argument`` names it."""

    def __init__(self, argument: str, message: str):
        self.argument = argument
        self.message = message
        super().__init__(f"{argument}: {message}")


class OutputError(FemgearError, OSError):
    """An output location cannot be created or written; ``argument`` names where it came from."""

    def __init__(self, argument: str, path: str, reason: str):
        self.argument = argument
        self.path = path
        super().__init__(f"{argument}: cannot write to {path}: {reason}")


class ResourceError(FemgearError, MemoryError):
    """A job would need more memory than allowed; raised before anything is allocated."""

    def __init__(self, argument: str, needed: float, budget: float, hint: str = ""):
        self.argument = argument
        self.needed = needed
        self.budget = budget
        gib = 1024.0**3
        tail = f"; {hint}" if hint else ""
        super().__init__(f"{argument}: needs about {needed / gib:.3g} GiB of memory, "
                         f"over the budget of {budget / gib:.3g} GiB{tail}")


class SceneError(FemgearError, ValueError):
    """A scene (or an override) is invalid; ``key`` names the offending entry."""

    def __init__(self, key: str, message: str):
        self.key = key
        self.message = message
        super().__init__(f"{key}: {message}")


class ConvergenceError(FemgearError, RuntimeError):
    """An iterative solver did not converge (CLI exit code 1).

    ``history`` maps names (``"residual"``, ``"load_error"``, ...) to the per-iteration
    values, so that nothing computed before the failure is lost.
    """

    exit_code = 1

    def __init__(self, case: str, message: str, history: Mapping[str, Sequence[Any]] | None = None):
        self.case = case
        self.history = {k: list(v) for k, v in (history or {}).items()}
        last = {k: v[-1] for k, v in self.history.items() if len(v)}
        tail = f" (last: {', '.join(f'{k}={v:.3g}' if isinstance(v, float) else f'{k}={v}' for k, v in last.items())})" if last else ""
        super().__init__(f"{case}: {message}{tail}")
