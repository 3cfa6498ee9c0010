"""``artipg convert``: MJCF, USD and GLB beside the URDF of existing object folders."""

from __future__ import annotations

import time
from pathlib import Path
from typing import List

import typer

from artipg.commands import fail


def register(app: typer.Typer) -> None:
    @app.command()
    def convert(
        folders: List[Path] = typer.Argument(..., help="Object folders with a URDF (artipg's or PartNet-Mobility's)."),
        to: str = typer.Option("mjcf", "--to", help="Formats to write, of mjcf,usd,glb (comma separated)."),
        actuators: bool = typer.Option(False, "--actuators", help="Position servos per joint in MJCF and USD."),
        check: bool = typer.Option(False, "--check", help="Then drop the MJCF on a floor in MuJoCo and drive "
                                                          "its joints to their limits; print the results."),
    ) -> None:
        """Write mobility.xml / .usd / .glb beside each folder's URDF (see docs/formats.md).

        Non-convex collision meshes are split into convex pieces with CoACD, cached in
        FOLDER/collision/. Every folder is checked before any file is written."""
        from artipg.export.convert import ConvertError, check_folder, convert_folder
        from artipg.export.formats import FILE_NAME, parse_formats

        try:
            formats = tuple(f for f in parse_formats(to) if f != "urdf")
        except ValueError as e:
            fail(str(e))
        if not formats:
            fail("--to needs one of mjcf, usd, glb (the URDF is the input)")
        try:
            for f in folders:
                check_folder(f)
        except ConvertError as e:
            fail(str(e))
        for f in folders:
            t = time.perf_counter()
            try:
                convert_folder(f, formats, actuators=actuators)
            except ConvertError as e:
                fail(str(e))
            line = f"{f}: {', '.join(FILE_NAME[x] for x in formats)} in {time.perf_counter() - t:.1f} s"
            if check and "mjcf" in formats:
                line += _check(Path(f).resolve() / FILE_NAME["mjcf"])
            typer.echo(line)


def _check(mjcf: Path) -> str:
    """MuJoCo results of ``mjcf`` as text: rest drift and joints that miss a limit."""
    from artipg.export.mjcf_sim import drive_limits, drive_tolerance, rest_drift

    xml = mjcf.read_text()
    if "<freejoint" in xml:
        text = f"; rest drift {rest_drift(mjcf) * 1e3:.3g} mm in 1 s"
    else:
        text = "; fixture (welded)"
    if "<position" in xml:
        tol = drive_tolerance(mjcf)
        missed = [k for k, v in drive_limits(mjcf).items() if max(v) > tol[k]]
        text += f"; {len(tol) - len(missed)}/{len(tol)} joints reach both limits"
        if missed:
            text += f" (missed: {', '.join(missed)})"
    return text
