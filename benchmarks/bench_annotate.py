"""Annotation speed per category (one process, CPU).

Prints, per category, median milliseconds per object for
(a) 2048 labelled points with every per-point label (semantic, instance, link,
    actionable class, affordance masks, part and object NPCS) plus part poses, at a
    random joint state (object already generated);
(b) the grasp poses at that state with the gripper collision check;
(c) one rendered view at 640 x 480 (depth, hit points, normals, labels);
(d) one completion sample: 16384 labelled points + 8 partial views of 2048 points
    (320 x 240 ray casts).

Usage: python benchmarks/bench_annotate.py [--categories a b] [--seeds 50] [--view-seeds 10] [--cpu]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import artipg
from artipg.annotate.grasps import world_grasps
from artipg.annotate.labels import part_frames, point_labels
from artipg.annotate.views import hemisphere_cameras, partial_views, render_view


CLOCK = time.perf_counter


def _median_ms(fn, items) -> float:
    times = []
    for it in items:
        t0 = CLOCK()
        fn(it)
        times.append(CLOCK() - t0)
    return 1e3 * float(np.median(times))


def _state(obj, seed):
    lim = obj.limits()
    lo = np.where(np.isfinite(lim[:, 0]), lim[:, 0], -np.pi)
    hi = np.where(np.isfinite(lim[:, 1]), lim[:, 1], np.pi)
    return lo + np.random.default_rng(seed).random(len(lim)) * (hi - lo)


def labels_npcs_poses(obj, q, n=2048):
    pc = obj.sample_points(n, seed=0, qpos=q)
    lab = point_labels(obj, pc.points, pc.primitive, q)
    return pc, lab, part_frames(obj, q)


def completion_sample(obj, q):
    pc = obj.sample_points(16384, seed=0, qpos=q)
    return pc, point_labels(obj, pc.points, pc.primitive, q), partial_views(obj, 8, 2048, q, seed=0)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=50, help="objects per category for (a) and (b)")
    ap.add_argument("--view-seeds", type=int, default=10, help="objects per category for (c) and (d)")
    ap.add_argument("--cpu", action="store_true",
                    help="time with the process CPU clock (steadier on a loaded machine; single-threaded code)")
    args = ap.parse_args()
    global CLOCK
    if args.cpu:
        CLOCK = time.process_time
    cats = args.categories or artipg.categories()
    print(f"artipg {artipg.__version__}, {len(cats)} categories, medians over {args.seeds} objects "
          f"({args.view_seeds} for views), one process, {'CPU' if args.cpu else 'wall'} clock")
    print(f"{'category':<20}{'(a) labels ms':>14}{'(b) grasps ms':>15}{'(c) view ms':>13}{'(d) sample ms':>15}")
    rows = []
    for c in cats:
        objs = [(artipg.generate(c, s), s) for s in range(args.seeds)]
        items = [(o, _state(o, s)) for o, s in objs]
        for o, q in items[:3]:  # warm caches (knowledge tables, meshes) and imports
            labels_npcs_poses(o, q)
        a = _median_ms(lambda it: labels_npcs_poses(*it), items)
        b = _median_ms(lambda it: world_grasps(*it), items)
        vitems = items[:args.view_seeds]
        cams = [hemisphere_cameras(o, 1, np.random.default_rng(0), q, 640, 480)[0] for o, q in vitems]
        for (o, q), cam in zip(vitems, cams):  # warm: mesh of every link built once per object
            render_view(o, cam, q)
        v = _median_ms(lambda k: render_view(vitems[k][0], cams[k], vitems[k][1]), range(len(vitems)))
        d = _median_ms(lambda it: completion_sample(*it), vitems)
        rows.append((a, b, v, d))
        print(f"{c:<20}{a:>14.3f}{b:>15.1f}{v:>13.1f}{d:>15.1f}")
    m = np.median(np.array(rows), axis=0)
    print(f"{'median':<20}{m[0]:>14.3f}{m[1]:>15.1f}{m[2]:>13.1f}{m[3]:>15.1f}")


if __name__ == "__main__":
    main()
