"""``artipg fit FOLDER --category C``: the procedural twin of an object folder."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Optional

import typer

from artipg.commands import fail


def register(app: typer.Typer) -> None:
    @app.command()
    def fit(
        folder: Path = typer.Argument(..., help="Object folder (mobility.urdf + meshes + semantics.txt)."),
        category: Optional[str] = typer.Option(
            None, "--category", "-c",
            help="Our category (storage_furniture) or PartNet-Mobility's (StorageFurniture); "
                 "default: the folder's meta.json / annotation.json."),
        out: Optional[Path] = typer.Option(None, "--out", "-o",
                                           help="Twin folder to write (default: twin_<FOLDER name>)."),
        restarts: int = typer.Option(24, "--restarts", help="Seeds tried per sub-category."),
        iterations: int = typer.Option(80, "--iterations", help="Annealing moves per refined candidate."),
        refine: int = typer.Option(3, "--refine", help="Best candidates refined."),
        overwrite: bool = typer.Option(False, "--overwrite", help="Replace an existing twin folder."),
    ) -> None:
        """Fit sub-category, templates and parameters to FOLDER; write the twin's folder and fit_report.json."""
        import artipg
        from artipg.fit import FitBudget, fit_object, write_twin
        from artipg.fit.labels import our_category
        from artipg.io.folders import URDF_NAME, metadata_category

        # the URDF parser logs its own messages on a malformed file: the error line says it
        logging.getLogger("yourdfpy").setLevel(logging.CRITICAL)
        if min(restarts, refine) < 1 or iterations < 0:
            fail("--restarts and --refine must be >= 1, --iterations >= 0")
        if not (folder / URDF_NAME).is_file():
            fail(f"{folder}: no {URDF_NAME} (not an object folder)")
        name = category or metadata_category(folder)
        if name is None:
            fail(f"{folder}: no category in meta.json / annotation.json; pass --category")
        name = our_category(name)
        if name not in artipg.categories():
            fail(f"unknown category {name!r}; valid categories: {', '.join(artipg.categories())}")
        out = out if out is not None else Path(f"twin_{folder.resolve().name}")
        if out.exists() and not overwrite:
            fail(f"{out} exists (pass --overwrite to replace it)")
        try:
            result = fit_object(folder, name, FitBudget(restarts=restarts, refine=refine, iterations=iterations))
        except (FileNotFoundError, ValueError) as e:
            fail(str(e))
        try:
            dest = write_twin(result, out, overwrite=overwrite)
        except OSError as e:
            fail(f"cannot write {str(out)!r}: {e.strerror or e}")
        s = result.score
        typer.echo(f"{result.category}/{result.obj.subcategory} seed {result.seed}: whole Chamfer "
                   f"{s.whole[0]:.4f} closed, {s.whole[-1]:.4f} open; {len(s.pairs)} links matched, "
                   f"{len(s.unmatched_target)} of the target's and {len(s.unmatched_twin)} of the twin's unmatched; "
                   f"validation {'passed' if result.passed else 'FAILED'}; {result.evaluations} evaluations in "
                   f"{result.seconds:.1f} s -> {dest}")
        if not result.passed:
            raise typer.Exit(1)
