"""Speed of the evaluation toolkit.

Prints wall-clock medians over ``--repeats`` runs of:
(a) a 200 x 200 Chamfer-L1 matrix of one set (the NND / D_gg case) at 2048 points,
    with 1 and 2 threads; (b) the cross matrix of two sets of 200 (D_gr); (c) the full
    ``artipg eval`` matrix of 200 vs 200 (the 400 x 400 union, which gives D_gg, D_rr
    and D_gr at once); the naive per-pair loop (``chamfer_distance`` on every pair,
    extrapolated from 200 pairs) for comparison; (d) EMD per pair at 1024 / 2048
    points; (e) numpy PointNet features of 200 clouds; (f) reading object folders
    (URDF + meshes, and points.npz).

Wall-clock seconds depend on what else runs on the machine; CPU seconds (summed over
threads) do much less, and on an idle machine wall ~ CPU / threads for the matrices.
The (a) lines also give wall / CPU nanoseconds per nearest-neighbour query. The
matrices use pykdtree (see :mod:`artipg.metrics.chamfer`); the naive per-pair loop
uses ``chamfer_distance`` (scipy cKDTree).

Clouds are rest-pose samples of registered categories (round robin over categories,
consecutive seeds), bounding-box normalised as ``artipg eval`` does.

Usage: python benchmarks/bench_metrics.py [--objects 200] [--points 2048] [--repeats 3] [--workers 2]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np

import artipg
from artipg.export.folder import export_object
from artipg.io import read_object
from artipg.metrics import chamfer_distance, chamfer_matrix, earth_movers_distance, load_default_encoder, normalize_bbox


def _clouds(n_objects: int, n_points: int, first_seed: int) -> np.ndarray:
    cats = artipg.categories()
    return normalize_bbox(np.stack([
        artipg.generate(cats[i % len(cats)], first_seed + i // len(cats)).sample_points(n_points, seed=0).points
        for i in range(n_objects)]))


def _median_s(fn, repeats: int) -> tuple[float, float]:
    """Median wall-clock seconds and median CPU seconds (all threads) of ``fn()``."""
    times, cpu = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return float(np.median(times)), float(np.median(cpu))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objects", type=int, default=200)
    ap.add_argument("--points", type=int, default=2048)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--skip-single", action="store_true", help="skip the 1-thread and naive timings")
    args = ap.parse_args()
    n, m, w = args.objects, args.points, args.workers
    print(f"artipg {artipg.__version__}; {len(artipg.categories())} categories; {n} objects x {m} points; "
          f"{os.cpu_count()} cores visible; load average {os.getloadavg()[0]:.1f}; medians of {args.repeats}")
    A = _clouds(n, m, 0)
    B = _clouds(n, m, 100_000)

    queries = n * n * m   # a self matrix queries every cloud against every tree once

    def per_query(wall: float, cpu: float) -> str:
        return f"({wall / queries * 1e9:4.0f} / {cpu / queries * 1e9:4.0f} ns per query)"

    if not args.skip_single:
        t1, c1 = _median_s(lambda: chamfer_matrix(A, workers=1), args.repeats)
        print(f"(a) {n} x {n} Chamfer matrix, one set, 1 thread : {t1:7.2f} s wall, {c1:7.2f} s CPU "
              f"{per_query(t1, c1)}")
    tw, cw = _median_s(lambda: chamfer_matrix(A, workers=w), args.repeats)
    print(f"(a) {n} x {n} Chamfer matrix, one set, {w} threads: {tw:7.2f} s wall, {cw:7.2f} s CPU {per_query(tw, cw)}")
    print(f"    {queries / 1e6:.0f} M nearest-neighbour queries: {cw / queries * 1e9:.0f} ns CPU each; "
          f"{cw / w:.1f} s on {w} idle cores")
    tc, cc = _median_s(lambda: chamfer_matrix(A, B, workers=w), args.repeats)
    print(f"(b) {n} x {n} Chamfer matrix, two sets, {w} threads: {tc:7.2f} s wall, {cc:7.2f} s CPU")
    te, ce = _median_s(lambda: chamfer_matrix(list(A) + list(B), workers=w), args.repeats)
    print(f"(c) eval {n} vs {n} (union {2 * n} x {2 * n}), {w} threads: {te:7.2f} s wall, "
          f"{ce:7.2f} s CPU")
    if not args.skip_single:
        pairs = [(i, (i * 7 + 3) % n) for i in range(200)]
        c0 = time.process_time()
        for i, j in pairs:
            chamfer_distance(A[i], B[j])
        per_pair = (time.process_time() - c0) / len(pairs)
        print(f"    naive per-pair loop (cKDTree per pair, 1 thread): {per_pair * 1e3:.1f} ms CPU/pair -> "
              f"{per_pair * n * (n - 1) / 2:.0f} s CPU for the symmetric {n} x {n}")

    for k in (1024, 2048):
        if k <= m:
            t, _ = _median_s(lambda: earth_movers_distance(A[0], B[0], max_points=k), args.repeats)
            print(f"(d) EMD, exact assignment of {k} points: {t:7.2f} s wall per pair")

    enc = load_default_encoder()
    if enc is not None:
        t, _ = _median_s(lambda: enc.features(A), args.repeats)
        print(f"(e) PointNet features (numpy) of {n} clouds: {t:7.2f} s wall")
    else:
        print("(e) no shipped encoder; skipped")

    with tempfile.TemporaryDirectory(prefix="artipg-bench-") as tmp:
        cat = artipg.categories()[0]
        folders = [export_object(artipg.generate(cat, s), os.path.join(tmp, str(s)), n_points=m) for s in range(10)]
        for src in ("mesh", "npz"):
            t = _median_s(lambda: [read_object(f, m, source=src) for f in folders], args.repeats)[0] / len(folders)
            print(f"(f) read one {cat} folder, points from {src}: {t * 1e3:7.1f} ms wall")


if __name__ == "__main__":
    main()
