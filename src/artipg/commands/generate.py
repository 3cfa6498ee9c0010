"""``artipg categories`` and ``artipg generate``."""

from __future__ import annotations

import os
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import List

import typer
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

import artipg
from artipg.commands import fail


def _generate_one(task: tuple) -> tuple[str, int, str]:
    """Worker: generate (validated and repaired unless told not to) and export one
    object; returns (category, seed, status), status "written", "skipped" or
    "invalid" (written, but no candidate passed validation within the budget)."""
    from artipg.export.folder import export_object

    category, seed, out, n_points, overwrite, views, validate, sim, formats, actuators = task
    dest = Path(out) / category / str(seed)
    if dest.exists() and not overwrite:
        return category, seed, "skipped"
    if validate:
        from artipg.validate import generate_valid

        obj = generate_valid(category, seed, simulate=sim)
    else:
        obj = artipg.generate(category, seed)
    export_object(obj, dest, n_points=n_points, overwrite=overwrite, views=views, formats=formats,
                  actuators=actuators)
    return category, seed, "written" if obj.report.get("ok", True) else "invalid"


def _check_out_dir(out: Path) -> None:
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / f".artipg-write-test-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as e:
        fail(f"cannot write to output folder {str(out)!r}: {e.strerror or e}")


def resolve_categories(names: list[str]) -> list[str]:
    """Expand ``all`` and check names; exits with the valid list on an unknown name."""
    valid = artipg.categories()
    out: list[str] = []
    for n in names:
        if n == "all":
            out += [c for c in valid if c not in out]
        elif n in valid:
            if n not in out:
                out.append(n)
        else:
            fail(f"unknown category {n!r}; valid categories: {', '.join(valid)} (or 'all')")
    return out


def register(app: typer.Typer) -> None:
    @app.command()
    def categories() -> None:
        """List the registered categories and their sub-categories."""
        for name in artipg.categories():
            subs = ", ".join(artipg.get_category(name).subcategories)
            typer.echo(f"{name}: {subs}")

    @app.command()
    def generate(
        category: List[str] = typer.Argument(..., help="Category names (see 'artipg categories'), or 'all'."),
        n: int = typer.Option(10, "-n", "--num", help="Objects per category (seeds S..S+N-1)."),
        seed: int = typer.Option(0, "--seed", "-s", help="First seed."),
        out: Path = typer.Option(Path("out"), "--out", "-o", help="Output folder."),
        points: int = typer.Option(2048, "--points", help="Labelled points per object in points.npz (0: none)."),
        views: int = typer.Option(0, "--views", help="Partial views (2048 points each) per object in views.npz."),
        workers: int = typer.Option(1, "--workers", "-j", help="Worker processes."),
        overwrite: bool = typer.Option(False, "--overwrite", help="Rewrite objects that already exist."),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
        validate: bool = typer.Option(True, "--validate/--no-validate",
                                      help="Check penetration, floating parts and joint sweeps; repair failures."),
        sim: bool = typer.Option(False, "--sim", help="Also require the pybullet / MuJoCo checks (slower)."),
        formats: str = typer.Option(None, "--formats", show_default=False,
                                    help="Files beside the URDF, of urdf,mjcf,usd,glb [default: urdf,mjcf] "
                                         "(see docs/formats.md)."),
        actuators: bool = typer.Option(False, "--actuators", help="Position servos per joint in MJCF and USD."),
    ) -> None:
        """Generate objects into OUT/<category>/<seed>/ (re-running resumes)."""
        from artipg.export.folder import clean_stale_tmp

        if n < 1:
            fail(f"-n must be at least 1, got {n}")
        if seed < 0:
            fail(f"--seed must be >= 0, got {seed}")
        if points < 0:
            fail(f"--points must be >= 0, got {points}")
        if views < 0:
            fail(f"--views must be >= 0, got {views}")
        if workers < 1:
            fail(f"--workers must be at least 1, got {workers}")
        from artipg.export.formats import DEFAULT_FORMATS, parse_formats

        try:
            fmts = parse_formats(formats or DEFAULT_FORMATS)
        except ValueError as e:
            fail(str(e))
        cats = resolve_categories(category)
        _check_out_dir(out)
        for c in cats:
            clean_stale_tmp(out / c)
        tasks = [(c, s, str(out), points, overwrite, views, validate, sim, fmts, actuators)
                 for c in cats for s in range(seed, seed + n)]
        counts = {"written": 0, "skipped": 0, "invalid": 0}
        columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                   TimeRemainingColumn())
        with Progress(*columns, disable=quiet, transient=False) as bar:
            job = bar.add_task("generating", total=len(tasks))
            if workers == 1:
                results = map(_generate_one, tasks)
            else:
                pool = ProcessPoolExecutor(max_workers=workers)
                results = pool.map(_generate_one, tasks, chunksize=max(1, min(32, len(tasks) // (8 * workers))))
            try:
                for _, _, status in results:
                    counts[status] += 1
                    bar.advance(job)
            finally:
                if workers > 1:
                    pool.shutdown(cancel_futures=True)
        typer.echo(f"{counts['written'] + counts['invalid']} written, {counts['skipped']} already present, in {out}")
        if counts["invalid"]:
            typer.echo(f"{counts['invalid']} failed validation after repair (see 'validation' in their "
                       "annotation.json)", err=True)
