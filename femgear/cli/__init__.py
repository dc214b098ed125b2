"""The ``femgear`` command line.

Each sub-command lives in its own module with a ``register(subparsers)`` function
that adds its parser and sets ``func``; :data:`_COMMAND_MODULES` lists them.  User
errors (:class:`femgear.errors.FemgearError`) are printed as one line on stderr with
exit code 2, never as a traceback; ``--json`` commands print one JSON object as the
last line of stdout.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from femgear.errors import FemgearError

_COMMAND_MODULES = ("info", "run", "sweep", "dynamics", "ehl")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="femgear",
        description="Finite-element tribo-dynamics of double-helical gear pairs.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in _COMMAND_MODULES:
        importlib.import_module(f"femgear.cli.{name}").register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except FemgearError as exc:
        print(f"femgear: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
