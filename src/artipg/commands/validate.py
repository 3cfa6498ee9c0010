"""``artipg validate PATH...``: physical checks of object folders on disk."""

from __future__ import annotations

import json
import signal
import time
from pathlib import Path
from typing import List, Optional

import numpy as np
import typer
from rich.console import Console
from rich.table import Table

from artipg.commands import err_console, fail

console = Console(highlight=False)


def _validate_one(task: tuple[str, bool, bool | None]) -> dict:
    """Worker: validate one folder; returns its JSON report (with "path" and "error")."""
    from artipg.validate.folder import validate_folder

    path, sim, fixed_base = task
    try:
        report, meta = validate_folder(path, simulate=sim, fixed_base=fixed_base)
    except Exception as e:  # a broken folder is a failed object, not a crashed run
        msg = f"{type(e).__name__}: {e}".splitlines()[0][:300]
        return {"path": path, "ok": False, "error": msg, "checks": {}}
    out = {"path": path, **{k: v for k, v in meta.items() if k != "path"}}
    out.update(report.to_json())
    return out


def _as_result(r: dict) -> dict:
    """A worker's result, or :func:`artipg.validate.isolation.failure`'s, as an object row."""
    if "item" in r:  # the worker died, timed out or was interrupted
        return {"path": r["item"][0], "ok": False, "error": r["error"], "checks": {}, "seconds": r["seconds"]}
    return r


def _timing(results: list[dict], wall: float, workers: int) -> dict:
    t = np.array([r.get("seconds", 0.0) for r in results], dtype=float)
    return {"wall_seconds": round(wall, 2), "workers": workers,
            "object_seconds": {"median": round(float(np.median(t)), 3) if len(t) else 0.0,
                               "max": round(float(t.max()), 3) if len(t) else 0.0,
                               "total": round(float(t.sum()), 2)}}


def _cell(check: dict | None, unit: float = 1e3) -> str:
    if check is None:
        return "-"
    worst = check.get("worst") or 0.0
    mark = "[green]ok[/]" if check["ok"] else "[bold red]FAIL[/]"
    return f"{mark} {worst * unit:.1f}"


def _short_names(paths: list[str]) -> list[str]:
    """Paths relative to their common folder (the folder's own name for one path)."""
    import os

    if len(paths) == 1:
        return [Path(paths[0]).name or paths[0]]
    base = os.path.commonpath([os.path.abspath(p) for p in paths])
    return [os.path.relpath(os.path.abspath(p), base) for p in paths]


def _table(results: list[dict]) -> Table:
    t = Table(title="artipg validate (worst depth / gap in thousandths of the object's units: mm for metres)",
              show_lines=False)
    t.add_column("object", no_wrap=True)
    t.add_column("geom.")
    for name in ("penetration", "floating", "sweep", "simulator"):
        t.add_column(name)
    t.add_column("s", justify="right")
    t.add_column("result")
    for r, name in zip(results, _short_names([r["path"] for r in results])):
        c = r.get("checks", {})
        sim = c.get("simulator")
        sim_cell = "-" if sim is None else ("[green]ok[/]" if sim["ok"] else "[bold red]FAIL[/] " + ", ".join(
            sorted({i["kind"] for i in sim["issues"]})))
        result = "[green]pass[/]" if r["ok"] else f"[bold red]fail[/] {r.get('error', '')}"
        t.add_row(name, r.get("geometry", "-"), _cell(c.get("penetration")), _cell(c.get("floating")),
                  _cell(c.get("joint_sweep")), sim_cell, f"{r.get('seconds', 0.0):.1f}", result)
    return t


def register(app: typer.Typer) -> None:
    @app.command()
    def validate(
        paths: List[Path] = typer.Argument(..., help="Object folders (with mobility.urdf), or folders holding them."),
        json_out: Optional[Path] = typer.Option(None, "--json", help="Write the full report to this JSON file."),
        sim: bool = typer.Option(True, "--sim/--no-sim", help="Run the pybullet / MuJoCo checks."),
        workers: int = typer.Option(1, "--workers", "-j", help="Worker processes."),
        timeout: float = typer.Option(300.0, "--timeout", help="Seconds one object may take (its failure after)."),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress line per object (on stderr)."),
        issues: bool = typer.Option(False, "--issues", help="Print every issue under the table."),
        fixed_base: Optional[bool] = typer.Option(
            None, "--fixed-base/--free-base",
            help="Simulate the objects mounted (fixtures: faucets, doors...) or dropped on a floor. "
                 "Default: what each annotation.json says, else free (PartNet-Mobility folders)."),
    ) -> None:
        """Check penetration, floating parts, joint sweeps and simulators; exit 1 if any object fails."""
        from artipg.validate.folder import find_objects

        if workers < 1:
            fail(f"--workers must be at least 1, got {workers}")
        if timeout <= 0:
            fail(f"--timeout must be positive, got {timeout:g}")
        try:
            folders = find_objects(paths)
        except FileNotFoundError as e:
            fail(str(e))
        if not folders:
            fail("no object folders (with mobility.urdf) under " + ", ".join(map(str, paths)))
        tasks = [(str(f), sim, fixed_base) for f in folders]
        from artipg.validate.isolation import run_isolated

        t0 = time.perf_counter()
        interrupted = False
        n_done = [0]

        def progress(i: int, r: dict) -> None:
            n_done[0] += 1
            state = "ok" if r.get("ok") else "FAIL"
            err_console.print(f"[{n_done[0]}/{len(tasks)}] {tasks[i][0]}: {state} ({r.get('seconds', 0.0):.1f} s)",
                              soft_wrap=True, highlight=False, markup=False)

        def stop(signum, frame):  # a terminated run reports like an interrupted one
            raise KeyboardInterrupt

        old_term = signal.signal(signal.SIGTERM, stop)
        try:
            results = run_isolated(_validate_one, tasks, workers, timeout, on_result=None if quiet else progress)
        except KeyboardInterrupt as e:  # still report what was done
            results, interrupted = e.results, True
        finally:
            signal.signal(signal.SIGTERM, old_term)
        results = [_as_result(r) for r in results]
        timing = _timing(results, time.perf_counter() - t0, workers)
        console.print(_table(results))
        if issues:
            for r in results:
                for name, c in r.get("checks", {}).items():
                    for i in c["issues"]:
                        console.print(f"{r['path']}: {name}: {json.dumps(i)}", soft_wrap=True)
        n_bad = sum(not r["ok"] for r in results)
        if json_out is not None:
            try:
                json_out.write_text(json.dumps({"objects": results, "passed": len(results) - n_bad,
                                                "failed": n_bad, "interrupted": interrupted, **timing},
                                               indent=1) + "\n")
            except OSError as e:
                fail(f"cannot write {str(json_out)!r}: {e.strerror or e}")
        ts = timing["object_seconds"]
        console.print(f"{timing['wall_seconds']:.1f} s wall with {workers} worker(s); per object: median "
                      f"{ts['median']:.2f} s, max {ts['max']:.2f} s")
        if interrupted:
            fail("interrupted: objects not finished are reported as failed", code=130)
        msg = f"{len(results) - n_bad} of {len(results)} objects pass"
        if n_bad:
            err_console.print(f"[bold red]{msg}[/]")
            raise typer.Exit(1)
        console.print(msg)
