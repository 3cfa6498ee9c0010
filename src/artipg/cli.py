"""Command-line interface: thin wrappers that parse arguments and call the library.

Each command lives in its own module under :mod:`artipg.commands` exposing
``register(app)``; add new modules to ``COMMAND_MODULES``.
"""

from __future__ import annotations

import importlib
import sys

import typer

COMMAND_MODULES = (
    "artipg.commands.generate",
)

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Procedurally generate articulated 3D objects with exact annotations.")

for _name in COMMAND_MODULES:
    importlib.import_module(_name).register(app)


def main() -> None:
    """Console entry point: run the app, turning user errors into one-line messages."""
    try:
        app()
    except KeyboardInterrupt:
        print("interrupted; re-run the same command to resume", file=sys.stderr)
        raise SystemExit(130)


if __name__ == "__main__":
    main()
