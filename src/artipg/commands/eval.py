"""``artipg eval`` (a generated set against a reference set) and ``artipg stats`` (one set)."""

from __future__ import annotations

import json
import math
import zipfile
from pathlib import Path
from typing import List, Optional

import numpy as np
import typer
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn
from rich.table import Table

from artipg.commands import DETAIL_HELP, check_detail, err_console, fail

console = Console(highlight=False)

_NORMALIZE_HELP = "Per-cloud normalisation before distances: 'bbox' (centre at the box centre, unit box " \
                  "diagonal) or 'none' (raw metres)."
_SOURCE_HELP = "Where points come from: 'auto' (artipg's points.npz when it has enough points, else the " \
               "URDF's meshes), 'mesh' or 'npz'."


def _progress(quiet: bool) -> Progress:
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
               TimeRemainingColumn())
    return Progress(*columns, console=err_console, disable=quiet, transient=False)


def _find(root: Path, what: str) -> dict:
    from artipg.io import find_object_folders

    try:
        found = find_object_folders(root)
    except FileNotFoundError:
        fail(f"{what} folder {str(root)!r} is not a directory")
    if not found:
        fail(f"no object folders (with mobility.urdf) under {str(root)!r}")
    return found


def _select(found: dict, only: list[str], what: str) -> dict:
    if not only:
        return found
    missing = [c for c in only if c not in found]
    if missing:
        fail(f"{what} has no category {', '.join(missing)}; it has: {', '.join(found)}")
    return {c: found[c] for c in only}


def _load(bar: Progress, label: str, folders, points: int, source: str, seed: int, workers: int | None):
    from artipg.io import load_set

    job = bar.add_task(f"reading {label}", total=len(folders))
    s = load_set(folders, points, source=source, seed=seed, workers=workers,
                 progress=lambda k: bar.advance(job, k))
    for folder, why in s.errors:
        err_console.print(f"[yellow]skipped[/] {folder}: {why}", soft_wrap=True)
    return s


def _fmt(x, spec: str = ".4f", scale: float = 1.0) -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return format(x * scale, spec)


def _mean_std(d: dict, spec: str = ".2f") -> str:
    if math.isnan(d["mean"]):
        return "-"
    return f"{d['mean']:{spec}} ± {d['std']:{spec}}"


def _types(d: dict) -> str:
    return ", ".join(f"{t} {v:.2f}" for t, v in d.items()) or "-"


def _structure_rows(table: Table, structs: list[dict], pad: int) -> None:
    """Structure rows, one column per set in ``structs``; ``pad`` empty trailing cells."""
    def row(name, cells):
        table.add_row(name, *cells, *([""] * pad))

    row("joints / object", [_mean_std(s["joints"]) for s in structs])
    row("joint types / object", [_types(s["joint_types"]) for s in structs])
    row("links / object", [_mean_std(s["links"]) for s in structs])
    for key, name in (("depth_x", "depth x (m)"), ("width_y", "width y (m)"), ("height_z", "height z (m)"),
                      ("diagonal", "diagonal (m)")):
        row(name, [_mean_std(s["size"][key], ".3f") for s in structs])
    row("height / width", [_mean_std(s["proportions"]["height_width"]) for s in structs])
    row("depth / width", [_mean_std(s["proportions"]["depth_width"]) for s in structs])


def _histogram_table(title: str, rows: dict) -> Table:
    from artipg.metrics.structure import JOINT_BINS

    t = Table(title=title, title_justify="left")
    t.add_column("set")
    for b in JOINT_BINS:
        t.add_column(b, justify="right")
    for name, hist in rows.items():
        t.add_row(name, *(f"{100 * hist[b]:.0f}" for b in JOINT_BINS))
    return t


def _write_json(path: Optional[Path], data: dict) -> None:
    if path is None:
        return
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(data, indent=1, allow_nan=False, default=_json_default) + "\n")
    except OSError as e:
        fail(f"cannot write {str(path)!r}: {e.strerror or e}")
    console.print(f"wrote {path}")


def _json_default(x):
    raise TypeError(f"not JSON serialisable: {type(x).__name__}")


def _clean(x):
    """NaN -> None, recursively (strict JSON)."""
    if isinstance(x, dict):
        return {k: _clean(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def _pair_categories(gen: dict, ref: dict) -> list[tuple[str, str, str]]:
    """(label, generated category, reference category) to compare."""
    shared = [c for c in gen if c in ref]
    if not shared and len(gen) == 1 and len(ref) == 1:
        (g,), (r,) = gen, ref
        err_console.print(f"[yellow]note:[/] no shared category name; comparing {g!r} with {r!r}")
        return [(f"{g} vs {r}", g, r)]
    for c in gen:
        if c not in ref:
            err_console.print(f"[yellow]note:[/] category {c!r} is only in the generated set; skipped")
    for c in ref:
        if c not in gen:
            err_console.print(f"[yellow]note:[/] category {c!r} is only in the reference set; skipped")
    if shared:
        return [(c, c, c) for c in shared]
    fail("the two sets share no category; use --category / --reference-category to pick the ones to compare")
    return []


def register(app: typer.Typer) -> None:
    @app.command("eval")
    def eval_cmd(
        generated: Optional[Path] = typer.Option(None, "--generated", "-g", help="Generated set: DIR/<category>/<id>/ "
                                                                                   "or a flat folder of object folders."),
        generate: Optional[str] = typer.Option(None, "--generate", "-n", help="Instead of --generated: generate N "
                                               "objects of each reference category on the fly (seeds from --first-seed); "
                                               "'match': as many as the reference category has (balanced 1-NNA)."),
        draws: int = typer.Option(1, "--draws", help="With --generate: average COV / MMD / 1-NNA over this many "
                                                     "disjoint blocks of N seeds (small reference sets are noisy)."),
        first_seed: int = typer.Option(0, "--first-seed", help="With --generate: the first object seed."),
        pose: str = typer.Option("partnet", "--pose", help="With --generate: sample at 'rest' or in 'partnet', the "
                                                           "pose PartNet-Mobility models the category in (laptops open)."),
        reference: Path = typer.Option(..., "--reference", "-r", help="Reference set (same layouts; "
                                                                         "PartNet-Mobility folders work)."),
        points: int = typer.Option(2048, "--points", help="Points per object."),
        normalize: str = typer.Option("bbox", "--normalize", help=_NORMALIZE_HELP),
        json_out: Optional[Path] = typer.Option(None, "--json", help="Write all numbers to this JSON file."),
        plots: Optional[Path] = typer.Option(None, "--plots", help="Write PNG plots (joint counts, sizes) here."),
        category: List[str] = typer.Option([], "--category", "-c", help="Only these generated categories."),
        reference_category: List[str] = typer.Option([], "--reference-category",
                                                     help="Only these reference categories (default: as "
                                                          "--category)."),
        workers: int = typer.Option(0, "--workers", "-j", help="Processes / threads (0: all cores)."),
        source: str = typer.Option("auto", "--source", help=_SOURCE_HELP),
        encoder: Optional[Path] = typer.Option(None, "--encoder", help="FID encoder weights (.npz; default: the "
                                                                          "shipped one)."),
        no_fid: bool = typer.Option(False, "--no-fid", help="Skip FID."),
        seed: int = typer.Option(0, "--seed", help="Point-sampling seed."),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bars."),
        detail: str = typer.Option("procedural", "--detail", help="With --generate: " + DETAIL_HELP),
    ) -> None:
        """Compare a generated object set (folders, or --generate N on the fly) with a reference
        set, per category: COV, MMD and 1-NNA (Chamfer-L1), NND of each set, FID, and structure
        statistics (joints, links, sizes, proportions) side by side."""
        from artipg.metrics.encoder import PointNetEncoder, load_default_encoder
        from artipg.metrics.evaluate import compare_sets
        from artipg.metrics.structure import summarize_structure

        _check_common(points, normalize, source, workers)
        detail = check_detail(detail)
        ref_found = _find(reference, "reference")
        if (generated is None) == (generate is None):
            fail("give either --generated DIR or --generate N")
        if generate:
            gen, pairs, ref = _generated_pairs(generate, draws, first_seed, pose, category, reference_category,
                                               ref_found)
        else:
            gen = _select(_find(generated, "generated"), category, "the generated set")
            ref = _select(ref_found, reference_category or [c for c in category if c in ref_found],
                          "the reference set")
            pairs = _pair_categories(gen, ref)
        enc = None
        if not no_fid:
            if encoder is not None:
                try:
                    enc = PointNetEncoder.load(encoder)
                except (OSError, ValueError, KeyError, zipfile.BadZipFile) as e:
                    fail(f"cannot load encoder {str(encoder)!r}: {e}")
            else:
                enc = load_default_encoder()
        n_workers = workers or None
        report = {"generated": str(generated), "reference": str(reference), "points": points, "detail": detail,
                  "normalize": normalize, "distance": "chamfer_l1", "source": source, "seed": seed,
                  "fid_encoder": None if enc is None else str(encoder or "default"), "categories": {}}
        for label, gc, rc in pairs:
            with _progress(quiet) as bar:
                r = _load(bar, f"{rc} (reference)", ref[rc], points, source, seed, n_workers)
                if len(r) < 1:
                    err_console.print(f"[yellow]note:[/] {label}: nothing readable; skipped")
                    continue
                if generate:
                    res, g = _compare_draws(bar, gc, r, len(r) if generate == "match" else int(generate), draws, first_seed, pose, points, seed, normalize,
                                            n_workers, enc, detail)
                else:
                    g = _load(bar, f"{gc} (generated)", gen[gc], points, source, seed, n_workers)
                    if len(g) < 1:
                        err_console.print(f"[yellow]note:[/] {label}: nothing readable; skipped")
                        continue
                    job = bar.add_task(f"{label}: Chamfer matrix", total=len(g) + len(r))
                    res = compare_sets(g.points, r.points, normalize, "l1", n_workers, enc,
                                       progress=lambda k: bar.advance(job, k))
            res["structure"] = {"generated": summarize_structure(g.structures),
                                "reference": summarize_structure(r.structures)}
            report["categories"][label] = res
            _print_eval(label, res, points, normalize, enc is not None)
            if plots is not None:
                _plot(plots, label, {"generated": g.structures, "reference": r.structures})
        _write_json(json_out, _clean(report))

    @app.command()
    def stats(
        folder: Path = typer.Argument(..., help="An object set: DIR/<category>/<id>/ or a flat folder."),
        points: int = typer.Option(2048, "--points", help="Points per object (for NND)."),
        normalize: str = typer.Option("bbox", "--normalize", help=_NORMALIZE_HELP),
        json_out: Optional[Path] = typer.Option(None, "--json", help="Write all numbers to this JSON file."),
        plots: Optional[Path] = typer.Option(None, "--plots", help="Write PNG plots (joint counts, sizes) here."),
        category: List[str] = typer.Option([], "--category", "-c", help="Only these categories."),
        workers: int = typer.Option(0, "--workers", "-j", help="Processes / threads (0: all cores)."),
        source: str = typer.Option("auto", "--source", help=_SOURCE_HELP),
        no_nnd: bool = typer.Option(False, "--no-nnd", help="Structure only (no point clouds, no distances)."),
        seed: int = typer.Option(0, "--seed", help="Point-sampling seed."),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="No progress bars."),
    ) -> None:
        """Statistics of one object set per category: NND diversity (Chamfer-L1), joints per
        object (histogram as in the paper's Fig. 4), joint types, links and sizes."""
        from artipg.metrics.evaluate import set_statistics

        _check_common(points, normalize, source, workers)
        found = _select(_find(folder, "the"), category, "the set")
        report = {"folder": str(folder), "points": points, "normalize": normalize, "distance": "chamfer_l1",
                  "source": source, "seed": seed, "categories": {}}
        structures = {}
        for cat, folders in found.items():
            with _progress(quiet) as bar:
                s = _load(bar, cat, folders, points, source, seed, workers or None)
                if not len(s):
                    continue
                job = bar.add_task(f"{cat}: Chamfer matrix", total=len(s) if not no_nnd else 0)
                res = set_statistics(s.points, s.structures, normalize, "l1", workers or None, not no_nnd,
                                     progress=lambda k: bar.advance(job, k))
            res["n_objects"] = len(s)
            report["categories"][cat] = res
            structures[cat] = s.structures
        _print_stats(report["categories"])
        if plots is not None:
            for cat, st in structures.items():
                _plot(plots, cat, {cat: st})
            if len(structures) > 1:
                from artipg.metrics.plots import plot_joint_histograms

                p = plot_joint_histograms(structures, plots / "joints_all.png", "movable joints per object")
                console.print(f"wrote {p}")
        _write_json(json_out, _clean(report))


def _generated_pairs(n: str, draws: int, first_seed: int, pose: str, category: list[str],
                     reference_category: list[str], ref_found: dict):
    """Categories to generate on the fly: every reference category artipg has (or the
    ones named), paired by name."""
    import artipg
    from artipg.io.generated import POSES

    if n != "match" and not (n.isdigit() and int(n) >= 2):
        fail(f"--generate must be 'match' or a number of at least 2, got {n!r}")
    if draws < 1:
        fail(f"--draws must be at least 1, got {draws}")
    if first_seed < 0:
        fail(f"--first-seed must be >= 0, got {first_seed}")
    if pose not in POSES:
        fail(f"--pose must be one of {', '.join(POSES)}, got {pose!r}")
    known = artipg.categories()
    for c in category:
        if c not in known:
            fail(f"unknown category {c!r}; valid categories: {', '.join(known)}")
    wanted = category or [c for c in ref_found if c in known]
    for c in ref_found:
        if c not in known:
            err_console.print(f"[yellow]note:[/] reference category {c!r} is not an artipg category; skipped")
    ref = _select(ref_found, reference_category or wanted, "the reference set")
    if not wanted:
        fail(f"no reference category is an artipg category; artipg has: {', '.join(known)}")
    return {c: None for c in wanted}, [(c, c, rc) for c, rc in zip(wanted, reference_category or wanted)], ref


def _compare_draws(bar, category, r, n, draws, first_seed, pose, points, seed, normalize, workers, enc,
                   detail=None):
    """:func:`compare_sets` of ``draws`` disjoint blocks of ``n`` generated seeds against
    the reference set ``r``: the set metrics averaged over the blocks (``*_draws`` keep
    each block's value), the structure of all generated objects together."""
    from artipg.io.generated import generated_set
    from artipg.metrics.evaluate import compare_sets

    runs, sets = [], []
    for k in range(draws):
        seeds = range(first_seed + k * n, first_seed + (k + 1) * n)
        job = bar.add_task(f"{category}: generating block {k + 1}/{draws}", total=n)
        g = generated_set(category, seeds, points, pose=pose, sampling_seed=seed,
                          progress=lambda j: bar.advance(job, j), detail=detail)
        job = bar.add_task(f"{category}: Chamfer matrix {k + 1}/{draws}", total=len(g) + len(r))
        runs.append(compare_sets(g.points, r.points, normalize, "l1", workers, enc,
                                 progress=lambda j: bar.advance(job, j)))
        sets.append(g)
    res = dict(runs[0])
    for key in ("cov", "mmd", "one_nna", "one_nna_generated", "one_nna_reference", "nnd_generated", "fid"):
        vals = [x[key] for x in runs if x.get(key) is not None]
        if vals:
            res[key] = float(np.mean(vals))
            res[f"{key}_draws"] = vals
    res["draws"] = draws
    g = sets[0]
    g.structures = [s for x in sets for s in x.structures]
    return res, g


def _check_common(points: int, normalize: str, source: str, workers: int) -> None:
    from artipg.io.reader import SOURCES
    from artipg.metrics.normalize import NORMALIZATIONS

    if points < 1:
        fail(f"--points must be at least 1, got {points}")
    if normalize not in NORMALIZATIONS:
        fail(f"--normalize must be one of {', '.join(NORMALIZATIONS)}, got {normalize!r}")
    if source not in SOURCES:
        fail(f"--source must be one of {', '.join(SOURCES)}, got {source!r}")
    if workers < 0:
        fail(f"--workers must be >= 0, got {workers}")


def _plot(folder: Path, label: str, structures: dict) -> None:
    from artipg.metrics.plots import plot_joint_histograms, plot_sizes
    from artipg.io.folders import snake_case

    stem = snake_case(label) or "objects"
    try:
        a = plot_joint_histograms(structures, folder / f"{stem}_joints.png", f"{label}: movable joints per object")
        b = plot_sizes(structures, folder / f"{stem}_sizes.png", f"{label}: bounding-box size at rest")
    except OSError as e:
        fail(f"cannot write plots to {str(folder)!r}: {e.strerror or e}")
    console.print(f"wrote {a} and {b}")


def _print_eval(label: str, res: dict, points: int, normalize: str, has_encoder: bool) -> None:
    unit = "box diagonals" if normalize == "bbox" else "m"
    t = Table(title=f"{label}: {res['n_generated']} generated vs {res['n_reference']} reference "
                    f"({points} points, normalize={normalize}, Chamfer-L1 in {unit})", title_justify="left")
    t.add_column("metric")
    t.add_column("generated", justify="right")
    t.add_column("reference", justify="right")
    t.add_column("generated vs reference", justify="right")
    t.add_row("objects", str(res["n_generated"]), str(res["n_reference"]), "")
    t.add_row("COV (%) ↑", "", "", _fmt(res["cov"], ".1f", 100))
    t.add_row("MMD ↓", "", "", _fmt(res["mmd"], ".5f"))
    t.add_row("1-NNA (%) → 50", _fmt(res["one_nna_generated"], ".1f", 100), _fmt(res["one_nna_reference"], ".1f", 100),
              _fmt(res["one_nna"], ".1f", 100))
    t.add_row("NND (diversity)", _fmt(res["nnd_generated"], ".5f"), _fmt(res["nnd_reference"], ".5f"), "")
    t.add_row("FID ↓", "", "", _fmt(res["fid"], ".4f") if has_encoder else "no encoder")
    s = res["structure"]
    _structure_rows(t, [s["generated"], s["reference"]], 1)
    console.print(t)
    console.print(_histogram_table(f"{label}: movable joints per object (% of objects)",
                                   {"generated": s["generated"]["joints"]["histogram"],
                                    "reference": s["reference"]["joints"]["histogram"]}))


def _print_stats(cats: dict) -> None:
    width = max([len("category")] + [len(c) for c in cats])
    t = Table(title="object set statistics (NND: Chamfer-L1)", title_justify="left")
    t.add_column("category", min_width=width, no_wrap=True)
    for col in ("objects", "NND", "joints / object", "links / object"):
        t.add_column(col, justify="right")
    for cat, r in cats.items():
        s = r["structure"]
        t.add_row(cat, str(r["n_objects"]), _fmt(r["nnd"], ".5f"), _mean_std(s["joints"]), _mean_std(s["links"]))
    console.print(t)
    sz = Table(title="bounding-box size at rest (m)", title_justify="left")
    sz.add_column("category", min_width=width, no_wrap=True)
    for col in ("depth x", "width y", "height z", "diagonal"):
        sz.add_column(col, justify="right")
    for cat, r in cats.items():
        s = r["structure"]["size"]
        sz.add_row(cat, *(_mean_std(s[k], ".3f") for k in ("depth_x", "width_y", "height_z", "diagonal")))
    console.print(sz)
    console.print(_histogram_table("movable joints per object (% of objects)",
                                   {c: r["structure"]["joints"]["histogram"] for c, r in cats.items()}))
    tt = Table(title="joints per object by type", title_justify="left")
    tt.add_column("category", min_width=width, no_wrap=True)
    tt.add_column("joint types / object")
    for cat, r in cats.items():
        tt.add_row(cat, _types(r["structure"]["joint_types"]))
    console.print(tt)
