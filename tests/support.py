"""Helpers shared by tests (not a test module): ``from tests.support import ...`` (the repository root is on the path)."""

from __future__ import annotations

import signal


def default_sigint() -> None:
    """``preexec_fn`` of a CLI child process: Ctrl-C at its default, so that Python installs its KeyboardInterrupt
    handler even when the tests run from a shell that ignores SIGINT in background jobs (``nohup make test &``)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
