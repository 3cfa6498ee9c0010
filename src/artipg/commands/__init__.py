"""CLI commands, one module each (see :mod:`artipg.cli`)."""

from __future__ import annotations

import typer
from rich.console import Console

err_console = Console(stderr=True, highlight=False)


def fail(message: str, code: int = 2) -> None:
    """Print a one-line error and exit with ``code`` (no traceback)."""
    err_console.print(f"[bold red]error:[/] {message}", soft_wrap=True)
    raise typer.Exit(code)


#: Help of every command's ``--detail`` option (one definition: the levels are
#: :data:`artipg.rules.detail.DETAIL_LEVELS`).
DETAIL_HELP = "Geometric detail: procedural (rounded edges, lips, door styles) or off (sharp structure)."


def check_detail(value: str) -> str:
    """The detail level of a ``--detail`` option (:func:`artipg.rules.detail.parse_detail`);
    a one-line error and exit code 2 for an unknown level."""
    from artipg.rules.detail import parse_detail

    try:
        return parse_detail(value)
    except ValueError as e:
        fail(str(e))
