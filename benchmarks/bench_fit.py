"""Fit every object of a folder of real objects and summarise per category.

    python benchmarks/bench_fit.py --real DIR [--json summary.json] [--restarts 24] [--iterations 80]

``DIR`` holds ``<Category>/<id>/`` object folders (PartNet-Mobility names such as
``StorageFurniture`` are mapped to ours). Per category it prints: objects, median
over twins of the median per-link Chamfer-L1 (averaged over closed / half / open,
bounding-box-normalised), the same area-weighted, the whole-object Chamfer at the
closed state, the share of twins that pass validation, the share of real links
matched, the fit time per object; then the overall proportions (height / width,
depth / width at the closed state) of the real objects against our generator's
(``--prior-seeds`` seeds per category, unvalidated, at the same closed state), and the fitted parameters that
press against an end of their range (:func:`artipg.fit.search.edge_pressure`).

Only aggregate figures are printed or written; no clouds, no per-object geometry.
"""

from __future__ import annotations

import argparse
import json
import time
from collections import Counter

import numpy as np

import artipg
from artipg.fit import FitBudget, fit_object
from artipg.fit.api import proportions
from artipg.fit.labels import our_category
from artipg.fit.shape import object_shape
from artipg.io import find_object_folders


def prior_proportions(category: str, seeds: int) -> np.ndarray:
    """(seeds, 2) height/width, depth/width of our objects 0..seeds-1 at the closed
    state the fit compares (:mod:`artipg.fit.shape`; eyeglasses folded), measured on
    sampled points as the real objects are."""
    out = []
    for s in range(seeds):
        p = proportions(object_shape(artipg.generate(category, s), 1024).extents)
        out.append((p["height_width"], p["depth_width"]))
    return np.array(out)


def _q(a) -> str:
    a = np.asarray(a, dtype=float)
    return f"{np.median(a):.2f} [{np.quantile(a, 0.1):.2f}, {np.quantile(a, 0.9):.2f}]" if len(a) else "-"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--real", required=True)
    ap.add_argument("--json")
    ap.add_argument("--restarts", type=int, default=24)
    ap.add_argument("--iterations", type=int, default=80)
    ap.add_argument("--prior-seeds", type=int, default=200)
    ap.add_argument("--categories", default="", help="comma-separated subset (ours or PartNet-Mobility's names)")
    args = ap.parse_args()
    budget = FitBudget(restarts=args.restarts, iterations=args.iterations)
    wanted = {our_category(c) for c in args.categories.split(",") if c}
    found = {}
    for c, folders in find_object_folders(args.real).items():
        ours = our_category(c)
        if ours in artipg.categories() and (not wanted or ours in wanted):
            found.setdefault(ours, []).extend(folders)
    summary = {}
    for cat, folders in sorted(found.items()):
        rows = []
        for f in folders:
            t = time.perf_counter()
            r = fit_object(f, cat, budget)
            cd = np.array([np.nanmean(d) for d in r.score.link_cd])
            w = np.array([0.5 * (r.target.share[i] + r.twin.share[j]) for i, j in r.score.pairs])
            rows.append({
                "link_median": float(np.median(cd)) if len(cd) else float("nan"),
                "link_weighted": float((cd * w).sum() / w.sum()) if len(cd) else float("nan"),
                "whole_closed": r.score.whole[0], "passed": r.passed, "seconds": time.perf_counter() - t,
                "evaluations": r.evaluations, "subcategory": r.obj.subcategory,
                "matched": len(r.score.pairs) / max(len(r.target.names), 1),
                "target": proportions(r.target.extents), "twin": proportions(r.twin.extents),
                "edges": [(e["name"], e["side"]) for e in r.at_edge]})
            print(f"{cat} {f.name}: link {rows[-1]['link_median']:.4f} whole {rows[-1]['whole_closed']:.4f} "
                  f"{'pass' if r.passed else 'FAIL'} {rows[-1]['seconds']:.1f} s {r.obj.subcategory}", flush=True)
        prior = prior_proportions(cat, args.prior_seeds)
        lo, hi = prior[:, 0].min(), prior[:, 0].max()
        edges = Counter(e for row in rows for e in row["edges"])
        summary[cat] = {
            "objects": len(rows),
            "link_chamfer_median": float(np.nanmedian([r["link_median"] for r in rows])),
            "link_chamfer_weighted_median": float(np.nanmedian([r["link_weighted"] for r in rows])),
            "whole_chamfer_median": float(np.median([r["whole_closed"] for r in rows])),
            "passed": float(np.mean([r["passed"] for r in rows])),
            "links_matched": float(np.mean([r["matched"] for r in rows])),
            "seconds_median": float(np.median([r["seconds"] for r in rows])),
            "evaluations_median": float(np.median([r["evaluations"] for r in rows])),
            "subcategories": dict(Counter(r["subcategory"] for r in rows)),
            "real_height_width": _q([r["target"]["height_width"] for r in rows]),
            "real_depth_width": _q([r["target"]["depth_width"] for r in rows]),
            "ours_height_width": _q(prior[:, 0]), "ours_depth_width": _q(prior[:, 1]),
            "real_in_ours_hw": float(np.mean([lo <= r["target"]["height_width"] <= hi for r in rows])),
            "edges": {f"{n} ({s})": k for (n, s), k in edges.most_common()},
        }
    print("\n| category | objects | median per-link CD | area-weighted | whole CD | pass | links matched "
          "| s / object |")
    print("|---|---|---|---|---|---|---|---|")
    for cat, s in summary.items():
        print(f"| {cat} | {s['objects']} | {s['link_chamfer_median']:.3f} | {s['link_chamfer_weighted_median']:.3f} | "
              f"{s['whole_chamfer_median']:.3f} | {100 * s['passed']:.0f}% | {100 * s['links_matched']:.0f}% | "
              f"{s['seconds_median']:.1f} |")
    print("\n| category | real h/w | ours h/w | real d/w | ours d/w | pressed range ends |")
    print("|---|---|---|---|---|---|")
    for cat, s in summary.items():
        print(f"| {cat} | {s['real_height_width']} | {s['ours_height_width']} | {s['real_depth_width']} | "
              f"{s['ours_depth_width']} | {', '.join(f'{k} x{v}' for k, v in s['edges'].items())} |")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(summary, fh, indent=1)


if __name__ == "__main__":
    main()
