"""End-to-end throughput of ``artipg generate`` and where a folder's export time goes.

1. ``artipg generate CATEGORY -n N --workers W`` (validation on, default formats) run as
   a subprocess, alternately with an older checkout (``--before SRC``, its ``src``
   folder) so both see the same drift of a shared machine: objects/s by the wall clock
   and CPU seconds per object (parent + workers).
2. One process, object by object: milliseconds per stage of a folder (generation with
   validation, grasps, URDF + mesh text + collision pieces, points, annotation text,
   file list hashes, writing the files), for ``--stage-category``.
3. Export time per object (files built and written) against the object's number of
   parts, over every category: a table of medians per part-count bin.
4. The cost of checking an existing folder on resume: sizes only, and with hashes.
5. With ``--dataset`` (needs torch): a training-style loop over
   :class:`artipg.data.ProceduralDataset` with 2 loader workers, clouds/s, run twice
   to check that both runs give the same batches.

Usage: python benchmarks/bench_throughput.py [--before ../main/src] [-n 300] [--workers 2]
       [--repeats 2] [--seeds 20] [--skip-cli] [--dataset]
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import artipg
from artipg.export.folder import object_files, write_files_atomic
from artipg.io.manifest import check_folder

CLOCK = time.perf_counter
SRC = str(Path(__file__).resolve().parent.parent / "src")


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def cli_run(src: str, category: str, n: int, workers: int, out: str) -> tuple[float, float]:
    """(wall s, CPU s of the process and its workers) of one ``artipg generate`` run."""
    shutil.rmtree(out, ignore_errors=True)
    env = dict(os.environ, PYTHONPATH=src)
    cpu0, t0 = _children_cpu(), time.perf_counter()
    subprocess.run([sys.executable, "-m", "artipg.cli", "generate", category, "-n", str(n), "--workers",
                    str(workers), "-q", "--out", out], env=env, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0, _children_cpu() - cpu0


def bench_cli(args, tmp: str) -> None:
    srcs = [("before", args.before)] if args.before else []
    srcs.append(("after", SRC))
    results = {name: [] for name, _ in srcs}
    for _ in range(args.repeats):
        for name, src in srcs:
            results[name].append(cli_run(src, args.category, args.n, args.workers, os.path.join(tmp, name)))
    print(f"\n## artipg generate {args.category} -n {args.n} --workers {args.workers} (validation on), "
          f"{args.repeats} alternating runs")
    print("| code | objects/s (wall, each run) | median | CPU ms / object (median) |")
    print("|---|---|---|---|")
    for name, runs in results.items():
        rates = [args.n / w for w, _ in runs]
        cpu = float(np.median([1e3 * c / args.n for _, c in runs]))
        print(f"| {name} | {', '.join(f'{r:.1f}' for r in rates)} | {np.median(rates):.1f} | {cpu:.1f} |")


def _stage_times(category: str, seed: int, folder: str) -> dict[str, float]:
    """Milliseconds of each stage of one folder, as :func:`object_files` runs them."""
    from artipg.annotate.grasps import world_grasps
    from artipg.export.annotation import annotation_text
    from artipg.export.folder import point_arrays
    from artipg.export.npz import npz_bytes
    from artipg.export.semantics import semantics_text
    from artipg.export.urdf import build_urdf, urdf_text
    from artipg.io.manifest import file_records

    t = {}
    t0 = CLOCK()
    obj = artipg.generate(category, seed, validate=True)
    t1 = CLOCK()
    grasps = world_grasps(obj)
    t2 = CLOCK()
    robot, meshes = build_urdf(obj)
    t3 = CLOCK()
    files = {"mobility.urdf": urdf_text(robot).encode(), "semantics.txt": semantics_text(obj).encode()}
    files.update({k: v.encode() for k, v in meshes.items()})
    t4 = CLOCK()
    files["points.npz"] = npz_bytes(point_arrays(obj, 2048, grasps=grasps))
    t5 = CLOCK()
    records = file_records(files)
    t6 = CLOCK()
    files["annotation.json"] = annotation_text(obj, grasps, records).encode()
    t7 = CLOCK()
    write_files_atomic(files, Path(folder), overwrite=True)
    t8 = CLOCK()
    marks = [t0, t1, t2, t3, t4, t5, t6, t7, t8]
    names = ["generate + validate", "grasps", "URDF tree, mesh text, collision pieces, inertia",
             "URDF text, semantics", "points.npz", "file list (sha256)", "annotation.json text",
             "write files (temp folder + rename)"]
    for k, name in enumerate(names):
        t[name] = 1e3 * (marks[k + 1] - marks[k])
    t["files per folder"] = len(files)
    t["kB per folder"] = sum(len(v) for v in files.values()) / 1e3
    return t


def bench_stages(args, tmp: str) -> None:
    _stage_times(args.stage_category, 0, os.path.join(tmp, "warm"))
    rows = [_stage_times(args.stage_category, s, os.path.join(tmp, "stages", str(s))) for s in range(args.seeds)]
    print(f"\n## Where a folder's time goes ({args.stage_category}, {args.seeds} seeds, one process, medians, "
          f"{args.clock} clock)")
    print("| stage | ms / object |")
    print("|---|---|")
    total = 0.0
    for name in rows[0]:
        v = float(np.median([r[name] for r in rows]))
        if name.startswith(("files", "kB")):
            print(f"| {name} | {v:.0f} |")
        else:
            total += v
            print(f"| {name} | {v:.2f} |")
    print(f"| sum of medians | {total:.2f} |")


def bench_parts(args, tmp: str) -> None:
    parts, ms, ms_files = [], [], []
    for c in artipg.categories():
        for s in range(args.seeds):
            obj = artipg.generate(c, s, validate=True)
            t0 = CLOCK()
            files = object_files(obj)
            t1 = CLOCK()
            write_files_atomic(files, Path(tmp) / "parts" / c / str(s), overwrite=True)
            t2 = CLOCK()
            parts.append(len(obj.parts))
            ms.append(1e3 * (t2 - t0))
            ms_files.append(1e3 * (t2 - t1))
    parts, ms, ms_files = np.array(parts), np.array(ms), np.array(ms_files)
    print(f"\n## Export time per object against its number of parts (all categories x {args.seeds} seeds, "
          f"{args.clock} clock)")
    print("| parts | objects | export ms (median) | of which writing | ms per part |")
    print("|---|---|---|---|---|")
    edges = [1, 3, 5, 9, 13, 17, 25, 33, 49, 1000]
    for lo, hi in zip(edges[:-1], edges[1:]):
        m = (parts >= lo) & (parts < hi)
        if m.any():
            med = float(np.median(ms[m]))
            label = f"{lo}-{hi - 1}" if hi < 1000 else f">= {lo}"
            print(f"| {label} | {int(m.sum())} | {med:.1f} | {np.median(ms_files[m]):.1f} | "
                  f"{med / np.median(parts[m]):.2f} |")
    slope, icpt = np.polyfit(parts, ms, 1)
    print(f"least squares: {icpt:.1f} ms + {slope:.2f} ms per part")


def bench_resume(args, tmp: str) -> None:
    folders = sorted((Path(tmp) / "parts").glob("*/*"))
    out = {}
    for hashes in (False, True):
        check_folder(folders[0], hashes=hashes)
        t0 = CLOCK()
        assert all(check_folder(f, hashes=hashes).ok for f in folders)
        out[hashes] = 1e3 * (CLOCK() - t0) / len(folders)
    print(f"\n## Checking an existing folder on resume ({len(folders)} folders, page cache warm)")
    print(f"sizes only {out[False]:.2f} ms / folder, with sha256 {out[True]:.2f} ms / folder")


def bench_dataset(args) -> None:
    import hashlib

    import torch
    from torch.utils.data import DataLoader

    from artipg.data import ProceduralDataset

    n = args.dataset_n
    digests, rates = [], []
    for _ in range(2):
        ds = ProceduralDataset(artipg.categories(), range(n // len(artipg.categories()) + 1), qpos="random")
        h = hashlib.sha256()
        t0, count = time.perf_counter(), 0
        for batch in DataLoader(ds, batch_size=16, num_workers=2):
            x = batch["points"]
            loss = (x - x.mean(dim=1, keepdim=True)).square().mean()  # stand-in for a model step
            h.update(x.numpy().tobytes())
            h.update(batch["semantic"].numpy().tobytes())
            count += len(x)
            assert torch.isfinite(loss)
        rates.append(count / (time.perf_counter() - t0))
        digests.append(h.hexdigest())
    print(f"\n## Training-style loop over ProceduralDataset (all categories, qpos random, 2048 points, "
          f"batch 16, 2 loader workers, {count} clouds)")
    print(f"clouds/s: {rates[0]:.1f}, {rates[1]:.1f}; same batches in both runs: {digests[0] == digests[1]}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", help="src folder of the code to compare with (e.g. another checkout's src)")
    ap.add_argument("--category", default="storage_furniture")
    ap.add_argument("-n", type=int, default=300)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--seeds", type=int, default=20, help="seeds per category for the stage and part tables")
    ap.add_argument("--stage-category", default="storage_furniture")
    ap.add_argument("--skip-cli", action="store_true")
    ap.add_argument("--clock", choices=("wall", "cpu"), default="wall",
                    help="clock of the per-object tables: cpu (process time) moves less on a busy machine")
    ap.add_argument("--dataset", action="store_true", help="also time a loop over ProceduralDataset (torch)")
    ap.add_argument("--dataset-n", type=int, default=440)
    args = ap.parse_args()
    global CLOCK
    CLOCK = time.process_time if args.clock == "cpu" else time.perf_counter
    tmp = tempfile.mkdtemp(prefix="artipg-bench-")
    try:
        if not args.skip_cli:
            bench_cli(args, tmp)
        bench_stages(args, tmp)
        bench_parts(args, tmp)
        bench_resume(args, tmp)
        if args.dataset:
            bench_dataset(args)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
