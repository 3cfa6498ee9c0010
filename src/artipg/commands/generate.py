"""``artipg categories``, ``artipg generate`` and ``artipg index``."""

from __future__ import annotations

import os
import signal
import threading
import time
from collections import Counter
from pathlib import Path
from typing import List

import typer
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

import artipg
from artipg.commands import DETAIL_HELP, check_detail, fail


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
        rgb: str = typer.Option(None, "--rgb", show_default=False,
                                help="With --views: colour images of the views in views_rgb.npz, lit 'studio' or "
                                     "'random' (light and background drawn per view); needs the render extra."),
        workers: int = typer.Option(1, "--workers", "-j", help="Worker processes."),
        overwrite: bool = typer.Option(False, "--overwrite", help="Rewrite objects that already exist."),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bar."),
        validate: bool = typer.Option(True, "--validate/--no-validate",
                                      help="Check penetration, floating parts and joint sweeps; repair failures."),
        sim: bool = typer.Option(False, "--sim", help="Also require the pybullet / MuJoCo checks (slower)."),
        shards: int = typer.Option(0, "--shards", help="Also pack points and annotations into WebDataset-style tar "
                                                       "shards of N objects in OUT/shards/ (0: none)."),
        formats: str = typer.Option(None, "--formats", show_default=False,
                                    help="Files beside the URDF, of urdf,mjcf,usd,glb [default: urdf,mjcf] "
                                         "(see docs/formats.md)."),
        actuators: bool = typer.Option(False, "--actuators", help="Position servos per joint in MJCF and USD."),
        detail: str = typer.Option("procedural", "--detail",
                                   help=DETAIL_HELP[:-1] + ", or learned (the sharp structure, its points.npz "
                                        "cloud detailed by --detail-model; docs/detail_learned.md)."),
        engine: str = typer.Option("local", "--engine", help="local (process pool) or ray (a Ray cluster; "
                                                            "see docs/cluster.md)."),
        address: str = typer.Option(None, "--address", show_default=False,
                                    help="Ray cluster to join, HOST:PORT or auto (without it: a local Ray "
                                         "instance with --workers CPUs)."),
        detail_model: Path = typer.Option(None, "--detail-model", show_default=False,
                                          help="With --detail learned: a model from 'artipg detail train'."),
    ) -> None:
        """Generate objects into OUT/<category>/<seed>/ and index them in OUT/index.jsonl.

        Re-running resumes: complete folders are kept, incomplete or damaged ones (files
        that differ from the list in their annotation.json) are rebuilt. Ctrl-C stops
        after the objects in progress.
        """
        from artipg.data.engine import BuildOptions
        from artipg.export.folder import clean_stale_tmp

        if n < 1:
            fail(f"-n must be at least 1, got {n}")
        if seed < 0:
            fail(f"--seed must be >= 0, got {seed}")
        if points < 0:
            fail(f"--points must be >= 0, got {points}")
        if views < 0:
            fail(f"--views must be >= 0, got {views}")
        if rgb is not None:
            if rgb not in ("studio", "random"):
                fail(f"--rgb must be 'studio' or 'random', got {rgb!r}")
            if views == 0:
                fail("--rgb renders the partial views: give --views K too")
            try:
                import mitsuba  # noqa: F401
            except ImportError:
                fail("--rgb needs Mitsuba 3: pip install -e '.[render]'")
        if workers < 1:
            fail(f"--workers must be at least 1, got {workers}")
        if shards < 0:
            fail(f"--shards must be >= 0, got {shards}")
        _check_engine(engine, address)
        detail = _check_detail(detail, detail_model, points)
        from artipg.export.formats import DEFAULT_FORMATS, parse_formats

        try:
            fmts = parse_formats(formats or DEFAULT_FORMATS)
        except ValueError as e:
            fail(str(e))
        cats = resolve_categories(category)
        _check_out_dir(out)
        for c in cats:
            clean_stale_tmp(out / c)
        tasks = [(c, s) for c in cats for s in range(seed, seed + n)]
        opts = BuildOptions(str(out), n_points=points, views=views, validate=validate, simulate=sim, rgb=rgb,
                            overwrite=overwrite, formats=fmts, actuators=actuators, detail=detail,
                            detail_model=str(detail_model.resolve()) if detail_model is not None else None)
        try:
            counts, errors, stopped = _run(tasks, opts, out, workers, quiet, engine, address)
        except RuntimeError as e:
            from artipg.data.ray_engine import EngineError

            if not isinstance(e, EngineError):
                raise
            fail(str(e))
        _summary(counts, errors, out, validate)
        if stopped:
            typer.echo(f"interrupted: {_written(counts)} written, re-run to resume", err=True)
            raise typer.Exit(130)
        if shards:
            _write_shards(out, shards)
        if counts["error"]:
            raise typer.Exit(1)

    @app.command()
    def index(
        out: Path = typer.Argument(..., help="Output folder of 'artipg generate'."),
        hashes: bool = typer.Option(True, "--hashes/--sizes-only", help="Check file hashes, not only sizes."),
        shards: int = typer.Option(0, "--shards", help="Also rewrite OUT/shards/ with N objects per shard."),
    ) -> None:
        """Rebuild OUT/index.jsonl from the complete object folders on disk."""
        from artipg.data.index import INDEX_NAME, rebuild_index

        if not out.is_dir():
            fail(f"{str(out)!r} is not a folder")
        if shards < 0:
            fail(f"--shards must be >= 0, got {shards}")
        rows, bad = rebuild_index(out, hashes=hashes)
        typer.echo(f"indexed {len(rows)} objects in {out / INDEX_NAME}")
        if bad:
            typer.echo(f"{len(bad)} incomplete or damaged folders left out (re-run 'artipg generate' to rebuild "
                       f"them), e.g. {bad[0][0]}: {bad[0][1]}", err=True)
        if shards:
            _write_shards(out, shards)


def _write_shards(out: Path, per_shard: int) -> None:
    from artipg.data.shards import SHARD_DIR, write_shards

    paths = write_shards(out, per_shard)
    typer.echo(f"{len(paths)} shards of up to {per_shard} objects in {out / SHARD_DIR}")


def _written(counts: Counter) -> int:
    return counts["new"] + counts["rebuilt"] + counts["rewritten"]


def _check_detail(detail: str, model: Path | None, points: int) -> str:
    """--detail and --detail-model: a geometric level (procedural, off) or learned with a
    model that loads; the level, or one line of error."""
    if str(detail).strip().lower() != "learned":
        if model is not None:
            fail("--detail-model needs --detail learned")
        return check_detail(detail)
    if model is None:
        fail("--detail learned needs --detail-model MODEL (see 'artipg detail train')")
    if points == 0:
        fail("--detail learned details the points.npz cloud: give --points > 0")
    from artipg.detail.application import DetailModelError, load_detail_model

    try:
        load_detail_model(model)
    except DetailModelError as e:
        fail(str(e))
    return "learned"


def _check_engine(engine: str, address: str | None) -> None:
    from artipg.data.engine import ENGINES

    if engine not in ENGINES:
        fail(f"unknown engine {engine!r}; valid engines: {', '.join(ENGINES)}")
    if address is not None and engine != "ray":
        fail("--address needs --engine ray")
    if engine == "ray":
        from artipg.data.ray_engine import ray_available

        if not ray_available():
            fail("--engine ray needs Ray: pip install 'artipg[ray]'")


def _run(tasks: list, opts, out: Path, workers: int, quiet: bool, engine: str = "local",
         address: str | None = None) -> tuple[Counter, list[str], bool]:
    """Run the tasks with a progress display and the index kept as they finish;
    returns (outcome counts, "category/seed: error" lines, whether Ctrl-C stopped the run)."""
    from artipg.data.engine import run_tasks
    from artipg.data.index import IndexAppender, read_index, write_index

    # rows of this run's objects are re-emitted as they are checked or written; rows
    # of other objects stay while their folder does
    mine = {f"{c}/{s}" for c, s in tasks}
    rows = [r for r in read_index(out) if r["path"] not in mine and (out / r["path"] / "annotation.json").is_file()]
    write_index(out, rows)
    counts: Counter = Counter()
    errors: list[str] = []
    stop = threading.Event()

    def on_sigint(signum, frame):
        if stop.is_set():  # a second Ctrl-C: stop now
            raise KeyboardInterrupt
        stop.set()

    previous = signal.signal(signal.SIGINT, on_sigint)
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TextColumn("{task.fields[stats]}"),
               TimeElapsedColumn(), TimeRemainingColumn())
    t0 = time.perf_counter()
    try:
        with Progress(*columns, disable=quiet, transient=False) as bar, IndexAppender(out) as index:
            job = bar.add_task("generating", total=len(tasks), stats="")
            for o in run_tasks(tasks, opts, workers=workers, stop=stop, engine=engine, address=address):
                counts[o.status] += 1
                if o.status == "rebuilt":
                    counts[f"rebuilt:{o.reason}"] += 1
                if o.status == "error":
                    errors.append(f"{o.category}/{o.seed}: {o.reason}")
                if o.row is not None:
                    index.append(o.row)
                    rows.append(o.row)
                    if o.written:
                        counts["repaired"] += bool((o.row["repair"] or {}).get("iterations"))
                        counts["invalid"] += o.row["valid"] is False
                rate = sum(counts[k] for k in ("new", "rebuilt", "rewritten", "kept", "error")) / max(
                    time.perf_counter() - t0, 1e-9)
                bar.update(job, advance=1, stats=f"{rate:6.1f} obj/s  {counts['repaired']} repaired  "
                                                 f"{counts['invalid'] + counts['error']} failed")
    finally:
        signal.signal(signal.SIGINT, previous)
        write_index(out, rows)
    return counts, errors, stop.is_set()


def _summary(counts: Counter, errors: list[str], out: Path, validate: bool) -> None:
    """Print what the run did: written (new, rebuilt, rewritten), kept, repaired, failed."""
    parts = [f"{counts['new']} new"] if counts["new"] else []
    if counts["rebuilt"]:
        why = ", ".join(f"{counts['rebuilt:' + r]} {r}" for r in ("damaged", "incomplete", "missing")
                        if counts["rebuilt:" + r])
        parts.append(f"{counts['rebuilt']} rebuilt: {why}")
    if counts["rewritten"]:
        parts.append(f"{counts['rewritten']} overwritten")
    detail = f" ({'; '.join(parts)})" if counts["rebuilt"] or counts["rewritten"] else ""
    typer.echo(f"{_written(counts)} written{detail}, {counts['kept']} already present, in {out}")
    if validate and counts["repaired"]:
        typer.echo(f"{counts['repaired']} repaired")
    if counts["invalid"]:
        typer.echo(f"{counts['invalid']} failed validation after repair (see 'validation' in their "
                   "annotation.json)", err=True)
    if errors:
        typer.echo(f"{len(errors)} objects could not be built, e.g. {min(errors)}", err=True)
