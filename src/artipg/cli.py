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
    "artipg.commands.eval",
    "artipg.commands.render",
    "artipg.commands.validate",
    "artipg.commands.convert",
    "artipg.commands.view",
    "artipg.commands.fit",
    "artipg.commands.detail",
)

app = typer.Typer(add_completion=False, no_args_is_help=True, pretty_exceptions_enable=False,
                  help="Procedurally generate articulated 3D objects with exact annotations.")

for _name in COMMAND_MODULES:
    importlib.import_module(_name).register(app)


def _is_cli_error(e: BaseException) -> bool:
    """True for click / typer usage errors (typer may vendor its own click)."""
    return hasattr(e, "format_message") and hasattr(e, "exit_code")


def main() -> None:
    """Console entry point: run the app, turning user errors into one-line messages."""
    try:
        code = app(standalone_mode=False)
    except (KeyboardInterrupt, typer.Abort):
        print("interrupted; re-run the same command to resume", file=sys.stderr)
        raise SystemExit(130)
    except typer.Exit as e:
        raise SystemExit(e.exit_code)
    except Exception as e:
        if not _is_cli_error(e):
            raise
        ctx = getattr(e, "ctx", None)
        if type(e).__name__ == "NoArgsIsHelpError" and ctx is not None:
            print(ctx.get_help())
            raise SystemExit(0)
        # bad option values, missing arguments: one line, no box, no traceback
        hint = f" (see '{ctx.command_path} --help')" if ctx is not None else ""
        print(f"error: {e.format_message()}{hint}", file=sys.stderr)
        raise SystemExit(e.exit_code or 2)
    raise SystemExit(code if isinstance(code, int) else 0)


if __name__ == "__main__":
    main()
