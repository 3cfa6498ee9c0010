"""Generation speed per category.

Prints, per category, the median milliseconds per object for
(a) ``artipg.generate``, (b) generate + 2048 labelled points, (c) a full export to
disk (URDF, meshes, semantics, annotation, points), and the objects/second of
``artipg generate -n N --workers 2`` end to end (CLI, process pool, disk).
It also times the issue's yardstick, a plain numpy loop that builds a 13-box cabinet and
samples 2048 labelled points (``reference_cabinet.py``), alternating with (b) object by
object, and prints each category's (b) as a multiple of it: on a shared machine whose
speed drifts by 10-20 % the ratio moves less than the milliseconds.
(b) is split into where its time goes: the patch table of the object (built once per
object, cached) and the draw of 2048 points from it; the rest is (a).

``--detail off|procedural`` times objects at that geometric detail level (default
procedural, as ``artipg.generate``).

Usage: python benchmarks/bench_generate.py [--categories a b] [--seeds 200] [--cli-n 500] [--detail off]
"""

from __future__ import annotations

import argparse
import functools
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

import artipg
from artipg.export.folder import export_object

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from reference_cabinet import reference_object  # noqa: E402


CLOCK = time.perf_counter


def _median_ms(fn, seeds) -> float:
    times = []
    for s in seeds:
        t0 = CLOCK()
        fn(s)
        times.append(CLOCK() - t0)
    return 1e3 * float(np.median(times))


def _paired_median_ms(fn, ref, seeds) -> tuple[float, float, float]:
    """Median ms of ``fn(s)`` and of ``ref(s)``, called alternately seed by seed (so a
    drift of the machine's speed reaches both), and the median of their paired ratios."""
    a, b = [], []
    for s in seeds:
        t0 = CLOCK()
        fn(s)
        t1 = CLOCK()
        ref(s)
        t2 = CLOCK()
        a.append(t1 - t0)
        b.append(t2 - t1)
    a, b = np.array(a), np.array(b)
    return 1e3 * float(np.median(a)), 1e3 * float(np.median(b)), float(np.median(a / b))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=200, help="seeds per category for (a) and (b)")
    ap.add_argument("--export-seeds", type=int, default=20, help="seeds per category for (c)")
    ap.add_argument("--cli-n", type=int, default=500, help="objects for the CLI run (0: skip)")
    ap.add_argument("--cli-category", default="storage_furniture")
    ap.add_argument("--clock", choices=("wall", "cpu"), default="wall",
                    help="wall time, or this process's CPU time (steadier on a shared machine)")
    ap.add_argument("--detail", default="procedural", help="geometric detail level: procedural or off")
    args = ap.parse_args()
    from artipg.rules.detail import parse_detail

    try:
        detail = parse_detail(args.detail)
    except ValueError as e:
        ap.error(str(e))
    gen = functools.partial(artipg.generate, detail=detail)
    global CLOCK
    CLOCK = time.perf_counter if args.clock == "wall" else time.process_time
    cats = args.categories or artipg.categories()
    seeds = range(args.seeds)
    tmp = tempfile.mkdtemp(prefix="artipg-bench-")
    print(f"artipg {artipg.__version__}, {len(cats)} categories, medians over {args.seeds} seeds "
          f"({args.export_seeds} for export), one process, {args.clock} clock, detail {detail}")
    for s in range(5):
        reference_object(s)
    refs, ratios = [], []
    print("ref: the reference (plain numpy 13-box cabinet + 2048 labelled points), timed alternately with (b)")
    print(f"{'category':<20}{'(a) gen ms':>12}{'(b) +2048 pts ms':>18}{'ref ms':>8}{'(b)/ref':>8}{'patches':>9}{'draw':>7}"
          f"{'(c) export ms':>15}{'joints mean/median/max':>26}")
    worst_b = 0.0
    all_dof = []
    for c in cats:
        for s in range(5):  # warm caches and imports
            gen(c, s).sample_points(2048)
        a = _median_ms(lambda s: gen(c, s), seeds)
        b, ref, ratio = _paired_median_ms(lambda s: gen(c, s).sample_points(2048), reference_object,
                                          seeds)
        refs.append(ref)
        ratios.append(ratio)
        objs = {s: gen(c, s) for s in seeds}
        patches = _median_ms(lambda s: objs[s].primitive_table.families, seeds)
        draw = _median_ms(lambda s: objs[s].sample_points(2048), seeds)
        e = _median_ms(lambda s: export_object(gen(c, s), os.path.join(tmp, c, str(s)), overwrite=True),
                       range(args.export_seeds))
        dof = np.array([gen(c, s).dof for s in seeds])
        all_dof.append(dof)
        worst_b = max(worst_b, b)
        joints = f"{dof.mean():.1f} / {np.median(dof):.0f} / {dof.max()}"
        print(f"{c:<20}{a:>12.3f}{b:>18.3f}{ref:>8.3f}{ratio:>8.2f}{patches:>9.3f}{draw:>7.3f}{e:>15.1f}{joints:>26}")
    print(f"worst median (b): {worst_b:.3f} ms per object; worst (b)/ref: {max(ratios):.2f}; "
          f"reference {min(refs):.3f}-{max(refs):.3f} ms (median {np.median(refs):.3f})")
    dof = np.concatenate(all_dof)
    print(f"movable joints over all categories: mean {dof.mean():.2f}, median {np.median(dof):.0f}, "
          f"{100 * (dof >= 10).mean():.1f}% of objects with 10 or more")
    if args.cli_n:
        out = os.path.join(tmp, "cli")
        cmd = [sys.executable, "-m", "artipg.cli", "generate", args.cli_category, "-n", str(args.cli_n),
               "--out", out, "--workers", "2", "--quiet", "--detail", detail]
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        dt = time.perf_counter() - t0
        print(f"CLI: artipg generate {args.cli_category} -n {args.cli_n} --workers 2: {dt:.1f} s, "
              f"{args.cli_n / dt:.1f} objects/s (process start-up included)")
    shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
