"""The ``femgear`` command line.

Each sub-command lives in its own module with a ``register(subparsers)`` function
that adds its parser and sets ``func``; :data:`_COMMAND_MODULES` lists them.

One error boundary (:func:`main`): every expected failure ends with one line on
stderr naming the key or argument, and an exit code

- 2: the input is wrong (bad scene, bad argument, unwritable output, over the memory
  budget: :class:`femgear.errors.FemgearError`, argparse errors) or the output could
  not be written (a full disk: every file is written atomically, so none is left corrupt);
- 1: a solver failed (:class:`femgear.errors.ConvergenceError`), or an internal error;
- 130: interrupted (Ctrl-C or SIGTERM).

No traceback unless ``--debug``.  ``-v``/``-q`` set the logging level (warnings are
shown by default); ``--json`` commands print one JSON object as the last line of stdout.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import logging
import signal
import sys
from collections.abc import Iterator
from typing import NoReturn

from femgear.errors import FemgearError

_COMMAND_MODULES = ("new", "info", "run", "sweep", "dynamics", "ehl", "ltca", "rexs", "oils")
EXIT_INPUT, EXIT_SOLVER, EXIT_INTERRUPTED = 2, 1, 130


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``femgear run: error: ... (see femgear run --help)``."""

    def error(self, message: str) -> NoReturn:
        self.exit(EXIT_INPUT, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("femgear")
    except PackageNotFoundError:  # running from a source tree that is not installed
        return "unknown"


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="femgear",
        description="Finite-element tribo-dynamics of double-helical gear pairs.",
    )
    parser.add_argument("--version", action="version", version=f"femgear {_version()}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", parser_class=_Parser)
    for name in _COMMAND_MODULES:
        importlib.import_module(f"femgear.edge.cli.{name}").register(sub)
    _add_global_options(parser)
    parser.set_defaults(verbose=0, quiet=False, debug=False)
    return parser


def _add_global_options(parser: argparse.ArgumentParser) -> None:
    """``-v``, ``-q``, ``--debug`` on every (sub-)parser, before or after the command name."""
    parser.add_argument("-v", "--verbose", action="count", default=argparse.SUPPRESS,
                        help="more log output (-v: progress and info, -vv: debug)")
    parser.add_argument("-q", "--quiet", action="store_true", default=argparse.SUPPRESS,
                        help="errors only: no warnings, no progress display")
    parser.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                        help="show the traceback of an error")
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for child in dict.fromkeys(action.choices.values()):
                _add_global_options(child)


@contextlib.contextmanager
def cli_logging(verbose: int = 0, quiet: bool = False) -> Iterator[None]:
    """While a command runs: records of ``femgear.*`` to stderr as ``femgear: level: message``
    (warnings and the cost notices of long stages by default, INFO with -v, DEBUG with -vv, errors only
    with -q); Python warnings
    (numpy's RuntimeWarnings inside a diverging iteration, ...) only with -v.  The previous
    logging state is restored afterwards (the CLI may run inside another program or a test).
    """
    from femgear.perf import NOTICE  # cost estimates and progress of long stages: shown by default

    level = logging.ERROR if quiet else (NOTICE, logging.INFO, logging.DEBUG)[min(verbose, 2)]
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(_Formatter())
    loggers = {logging.getLogger("femgear"): level,
               logging.getLogger("py.warnings"): logging.WARNING if verbose else logging.CRITICAL}
    saved = {lg: (lg.level, lg.propagate) for lg in loggers}
    for lg, lvl in loggers.items():
        lg.addHandler(handler)
        lg.setLevel(lvl)
        lg.propagate = False
    logging.captureWarnings(True)
    try:
        yield
    finally:
        logging.captureWarnings(False)
        for lg, (lvl, propagate) in saved.items():
            lg.removeHandler(handler)
            lg.setLevel(lvl)
            lg.propagate = propagate


class _Formatter(logging.Formatter):
    def format(self, record: logging.LogRecord) -> str:
        label = "" if record.levelname == "NOTICE" else f"{record.levelname.lower()}: "
        text = f"femgear: {label}{record.getMessage()}"
        return text + ("\n" + self.formatException(record.exc_info) if record.exc_info else "")


def _raise_interrupt(signum, frame) -> NoReturn:
    raise KeyboardInterrupt(f"signal {signum}")


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    previous = signal.getsignal(signal.SIGTERM)
    try:
        signal.signal(signal.SIGTERM, _raise_interrupt)  # SIGTERM stops cleanly, like Ctrl-C
    except ValueError:  # not the main thread (e.g. called from a test runner thread)
        previous = None
    try:
        with cli_logging(args.verbose, args.quiet):
            return _dispatch(args)
    finally:
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _dispatch(args: argparse.Namespace) -> int:
    """Run the command; every expected failure becomes one line and an exit code."""
    try:
        return int(args.func(args) or 0)
    except FemgearError as exc:
        if args.debug:
            raise
        print(f"femgear: error: {exc}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        if args.debug:
            raise
        print("femgear: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except MemoryError as exc:
        if args.debug:
            raise
        why = f": {exc}" if str(exc) else ""
        print(f"femgear: error: out of memory{why} (choose a coarser level or resolution)", file=sys.stderr)
        return EXIT_SOLVER
    except BrokenPipeError:  # stdout closed early (| head): not an error of the run
        sys.stderr.close()
        return 0
    except OSError as exc:  # a full disk, a file that vanished: one line naming the file
        if args.debug:
            raise
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"femgear: error: {where}{exc.strerror or exc} (nothing was left half-written)", file=sys.stderr)
        return EXIT_INPUT
    except Exception as exc:
        if args.debug:
            raise
        print(f"femgear: internal error: {type(exc).__name__}: {exc} (rerun with --debug for the traceback)",
              file=sys.stderr)
        return EXIT_SOLVER


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
