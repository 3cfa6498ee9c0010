"""``artipg detail pairs`` and ``artipg detail train``: the learned detail bridge (needs torch)."""

from __future__ import annotations

import json
import logging
from pathlib import Path
from typing import List, Optional

import typer

from artipg.commands import fail


def _need_torch() -> None:
    try:
        import torch  # noqa: F401
    except ImportError:
        fail("the learned detail bridge needs torch: pip install 'artipg[learn]'")


def register(app: typer.Typer) -> None:
    detail = typer.Typer(no_args_is_help=True, add_completion=False,
                         help="The learned detail bridge: training pairs and training (docs/detail_learned.md).")
    app.add_typer(detail, name="detail")

    @detail.command("pairs")
    def pairs(
        reference: Path = typer.Option(..., "--reference", "-r", help="Folder of real object folders "
                                                                      "(<Category>/<id>/mobility.urdf ...)."),
        out: Path = typer.Option(..., "--out", "-o", help="Folder of the pair files (kept out of git)."),
        category: Optional[List[str]] = typer.Option(None, "--category", "-c",
                                                     help="Only these categories (repeatable)."),
        restarts: int = typer.Option(16, "--restarts", help="Fit: seeds tried per sub-category."),
        iterations: int = typer.Option(60, "--iterations", help="Fit: annealing moves per refined candidate."),
        refine: int = typer.Option(2, "--refine", help="Fit: best candidates refined."),
    ) -> None:
        """Fit a twin to every reference object and write its (structure, detailed) pair. Resumes."""
        from artipg.detail.pairs import make_pairs, reference_objects
        from artipg.fit import FitBudget

        logging.getLogger("yourdfpy").setLevel(logging.CRITICAL)
        if min(restarts, refine) < 1 or iterations < 0:
            fail("--restarts and --refine must be >= 1, --iterations >= 0")
        if not reference.is_dir():
            fail(f"{str(reference)!r} is not a folder")
        todo = reference_objects(reference, category or None)
        if not todo:
            fail(f"no object folders of artipg's categories under {str(reference)!r}")
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            fail(f"cannot write to {str(out)!r}: {e.strerror or e}")
        done, errors = make_pairs(reference, out, category or None,
                                  FitBudget(restarts=restarts, refine=refine, iterations=iterations),
                                  progress=lambda name, status: typer.echo(f"{name}: {status}"))
        typer.echo(f"{len(done)} pairs in {out}")
        for folder, why in errors:
            typer.echo(f"skipped {folder}: {why}", err=True)
        if not done:
            raise typer.Exit(1)

    @detail.command("train")
    def train(
        pairs: Path = typer.Option(..., "--pairs", "-p", help="Folder of pair files ('artipg detail pairs')."),
        out: Path = typer.Option(..., "--out", "-o", help="Model file to write (never commit it: the weights "
                                                          "carry the reference data's licence)."),
        steps: int = typer.Option(3000, "--steps", help="Optimiser steps."),
        minutes: Optional[float] = typer.Option(None, "--minutes", help="Stop after this wall time."),
        batch: int = typer.Option(8, "--batch", help="Clouds per step."),
        points: int = typer.Option(512, "--points", help="Points per training cloud (and per applied chunk)."),
        bound: float = typer.Option(0.006, "--bound", help="Drift bound stored with the model, as a fraction "
                                                           "of the object's bounding-box diagonal."),
        seed: int = typer.Option(0, "--seed", help="Training seed."),
        threads: Optional[int] = typer.Option(None, "--threads", help="torch threads (default: torch's)."),
        only: Optional[List[str]] = typer.Option(None, "--only", help="Only these pair files (stems; repeatable)."),
    ) -> None:
        """Train the detail bridge on a folder of pairs and write the model file."""
        _need_torch()
        from artipg.detail.model import ModelConfig, save_model
        from artipg.detail.pairs import load_pairs
        from artipg.detail.training import TrainConfig
        from artipg.detail.training import train as run

        if min(steps, batch, points) < 1 or (minutes is not None and minutes <= 0):
            fail("--steps, --batch and --points must be >= 1, --minutes > 0")
        if not 0 < bound < 1:
            fail(f"--bound must be in (0, 1), got {bound}")
        try:
            data = load_pairs(pairs, only or None)
        except (FileNotFoundError, ValueError) as e:
            fail(str(e))
        if out.parent and not out.parent.is_dir():
            fail(f"{str(out.parent)!r} is not a folder")
        cfg = TrainConfig(steps=steps, batch=batch, points=points, seed=seed, minutes=minutes, threads=threads)

        def show(step: int, loss: float) -> None:
            if step % 250 == 0:
                typer.echo(f"step {step}: loss {loss:.4f}")

        try:
            net, hist = run(data, ModelConfig(bound=bound), cfg, progress=show)
        except ValueError as e:
            fail(str(e))
        log = out.with_suffix(out.suffix + ".json")
        try:
            save_model(net, out, extra={"history": hist})
            log.write_text(json.dumps(hist, indent=1) + "\n")
        except OSError as e:
            fail(f"cannot write {str(out)!r}: {e.strerror or e}")
        typer.echo(f"{len(hist['pairs'])} of {len(data)} pairs used, {hist['steps']} steps in {hist['seconds']:.0f} s on "
                   f"{hist['threads']} threads: loss {hist['initial_loss']:.4f} -> {hist['final_loss']:.4f}; "
                   f"wrote {out} and {log.name}")
