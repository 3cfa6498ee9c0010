"""Two-fold cross-validation of the learned detail bridge on a reference split.

    python benchmarks/bench_detail.py --pairs PAIRS --reference REAL --work WORK [--minutes 8] [--draws 5]

PAIRS is the folder of ``artipg detail pairs --reference REAL --out PAIRS``. Per
category, the reference objects (sorted by id) alternate between fold 0 and fold 1. For
each fold a model is trained on the *other* fold's pairs (``WORK/fold<k>.pt``, reused
when present; one torch thread) and every category with objects in the fold is
measured against them, as ``artipg eval --generate match --draws D --pose partnet``
does: D disjoint blocks of as many generated objects as reference objects, Chamfer-L1
after bounding-box normalisation, COV / 1-NNA / MMD / NND averaged over the blocks.
Each block is measured with detail off, learned (the model's drift bound) and learned
without the bound (to see what the model itself learned). The two folds' figures are
averaged per category (weighted by their reference counts).

Also measured: drift per category (max and 95th percentile of the distance of a
detailed point from the structure cloud, metres, pooled over the category's generated
points), the cost of applying the bridge per object (2048 points, one thread; median)
and of generating the structure cloud, and the training time.

Writes ``WORK/bench_detail.json`` and prints a markdown table. Nothing of the reference
data is written outside WORK.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np


def folds(pair_names: list[str]) -> dict[str, int]:
    """Fold (0/1) of every pair stem ``<category>_<id>``: alternating per category in id order."""
    by_cat: dict[str, list[str]] = {}
    for n in pair_names:
        cat, oid = n.rsplit("_", 1)
        by_cat.setdefault(cat, []).append(n)
    out = {}
    for names in by_cat.values():
        names.sort(key=lambda s: (len(s), s))
        out.update({n: i % 2 for i, n in enumerate(names)})
    return out


def train_fold(pairs_dir: Path, names: list[str], path: Path, minutes: float, seed: int) -> dict:
    import torch

    from artipg.detail.model import ModelConfig, save_model
    from artipg.detail.pairs import load_pairs
    from artipg.detail.training import TrainConfig, train

    if path.is_file():
        return torch.load(path, weights_only=True)["extra"]["history"]
    torch.set_num_threads(1)
    net, hist = train(load_pairs(pairs_dir, names), ModelConfig(),
                      TrainConfig(steps=100000, minutes=minutes, seed=seed, threads=1),
                      progress=lambda s, loss: print(f"  step {s}: {loss:.4f}", flush=True) if s % 250 == 0 else None)
    save_model(net, path, extra={"history": hist})
    return hist


def measure(category: str, ref_points: np.ndarray, model, draws: int, n_points: int) -> dict:
    """Set metrics of detail off / learned / learned unbounded against ``ref_points``,
    averaged over ``draws`` blocks, with drift and cost."""
    from artipg.detail.application import detail_points
    from artipg.io.generated import generated_set
    from artipg.metrics.evaluate import compare_sets

    n = len(ref_points)
    runs = {"off": [], "learned": [], "unbounded": []}
    drift, raw, cost_apply, cost_gen, diag = [], [], [], [], []
    for k in range(draws):
        t = time.perf_counter()
        g = generated_set(category, range(k * max(n, 2), (k + 1) * max(n, 2)), n_points, pose="partnet")
        cost_gen.append((time.perf_counter() - t) / len(g))
        learned, unbounded = [], []
        for i, pts in enumerate(g.points):
            seed = k * max(n, 2) + i
            t = time.perf_counter()
            d = detail_points(model, pts, seed=seed)
            cost_apply.append(time.perf_counter() - t)
            learned.append(d.points)
            unbounded.append(detail_points(model, pts, seed=seed, bound=1.0).points)
            drift.append(d.drift)
            raw.append(d.raw)
            diag.append(float(np.linalg.norm(np.ptp(pts, axis=0))))
        for key, G in (("off", g.points), ("learned", np.stack(learned)), ("unbounded", np.stack(unbounded))):
            runs[key].append(compare_sets(G, ref_points, "bbox", "l1", workers=1))
    out = {"n_reference": n}
    for key, rs in runs.items():
        out[key] = {m: float(np.nanmean([r[m] for r in rs])) for m in ("cov", "one_nna", "mmd", "nnd_generated")}
    drift, raw = np.concatenate(drift), np.concatenate(raw)
    out["drift_max_m"] = float(drift.max())
    out["drift_p95_m"] = float(np.percentile(drift, 95))
    out["raw_p95_m"] = float(np.percentile(raw, 95))
    out["pulled_back"] = float(np.mean(raw > model.config.bound * np.repeat(diag, n_points)))
    out["diagonal_median_m"] = float(np.median(diag))
    out["apply_s"] = cost_apply
    out["generate_s"] = cost_gen
    return out


def combine(per_fold: list[dict]) -> dict:
    """Reference-count-weighted mean of the folds' metrics; max / pooled of the rest."""
    w = np.array([f["n_reference"] for f in per_fold], dtype=float)
    out = {"n_reference": int(w.sum())}
    for key in ("off", "learned", "unbounded"):
        out[key] = {m: float(np.average([f[key][m] if np.isfinite(f[key][m]) else 0.0 for f in per_fold], weights=w))
                    for m in ("cov", "one_nna", "mmd", "nnd_generated")}
    out["drift_max_m"] = max(f["drift_max_m"] for f in per_fold)
    out["drift_p95_m"] = float(np.average([f["drift_p95_m"] for f in per_fold], weights=w))
    out["raw_p95_m"] = float(np.average([f["raw_p95_m"] for f in per_fold], weights=w))
    out["pulled_back"] = float(np.average([f["pulled_back"] for f in per_fold], weights=w))
    out["diagonal_median_m"] = float(np.median([f["diagonal_median_m"] for f in per_fold]))
    out["apply_s_median"] = float(np.median([x for f in per_fold for x in f["apply_s"]]))
    out["generate_s_median"] = float(np.median([x for f in per_fold for x in f["generate_s"]]))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pairs", type=Path, required=True)
    ap.add_argument("--reference", type=Path, required=True)
    ap.add_argument("--work", type=Path, required=True, help="Models and results (keep out of git).")
    ap.add_argument("--minutes", type=float, default=8.0, help="Training wall time per fold.")
    ap.add_argument("--draws", type=int, default=5)
    ap.add_argument("--points", type=int, default=2048)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--categories", nargs="*", default=None)
    args = ap.parse_args()

    import torch

    from artipg.detail.application import load_detail_model
    from artipg.detail.pairs import reference_objects
    from artipg.io import load_set

    torch.set_num_threads(1)
    args.work.mkdir(parents=True, exist_ok=True)
    names = sorted(p.stem for p in args.pairs.glob("*.npz") if not p.name.endswith(".tmp.npz"))
    fold = folds(names)
    folder_of = {f"{c}_{f.name}": f for c, f in reference_objects(args.reference)}
    report = {"folds": {}, "categories": {}, "args": {k: str(v) for k, v in vars(args).items()}}
    per_cat: dict[str, list[dict]] = {}
    for k in (0, 1):
        train_names = [n for n in names if fold[n] != k]
        print(f"fold {k}: training on {len(train_names)} pairs", flush=True)
        hist = train_fold(args.pairs, train_names, args.work / f"fold{k}.pt", args.minutes, args.seed + k)
        report["folds"][k] = {"train": train_names, "steps": hist["steps"], "seconds": hist["seconds"],
                              "initial_loss": hist["initial_loss"], "final_loss": hist["final_loss"]}
        model = load_detail_model(args.work / f"fold{k}.pt")
        held: dict[str, list[Path]] = {}
        for n in names:
            cat = n.rsplit("_", 1)[0]
            if fold[n] == k and n in folder_of and (args.categories is None or cat in args.categories):
                held.setdefault(cat, []).append(folder_of[n])
        for cat, folders in sorted(held.items()):
            ref = load_set(folders, args.points, source="mesh", seed=args.seed, workers=1)
            if not len(ref):
                continue
            r = measure(cat, ref.points, model, args.draws, args.points)
            per_cat.setdefault(cat, []).append(r)
            print(f"  {cat} ({len(ref)}): 1-NNA off {r['off']['one_nna']:.3f} learned {r['learned']['one_nna']:.3f} "
                  f"unbounded {r['unbounded']['one_nna']:.3f}; COV {r['off']['cov']:.2f} / {r['learned']['cov']:.2f}",
                  flush=True)
    for cat, rs in per_cat.items():
        report["categories"][cat] = combine(rs)
    (args.work / "bench_detail.json").write_text(json.dumps(report, indent=1) + "\n")
    print("\n| category | refs | COV off / learned / unbounded | 1-NNA off / learned / unbounded | "
          "NND off / learned | drift max / p95 (mm) | raw p95 (mm) | pulled back | apply ms |")
    print("|---|---|---|---|---|---|---|---|---|")
    for cat, c in sorted(report["categories"].items()):
        o, le, u = c["off"], c["learned"], c["unbounded"]
        print(f"| {cat} | {c['n_reference']} | {o['cov']:.2f} / {le['cov']:.2f} / {u['cov']:.2f} | "
              f"{o['one_nna']:.3f} / {le['one_nna']:.3f} / {u['one_nna']:.3f} | "
              f"{o['nnd_generated']:.4f} / {le['nnd_generated']:.4f} | "
              f"{1e3 * c['drift_max_m']:.1f} / {1e3 * c['drift_p95_m']:.1f} | {1e3 * c['raw_p95_m']:.1f} | "
              f"{100 * c['pulled_back']:.0f}% | {1e3 * c['apply_s_median']:.0f} |")
    for k, f in report["folds"].items():
        print(f"fold {k}: {len(f['train'])} training pairs, {f['steps']} steps in {f['seconds']:.0f} s, "
              f"loss {f['initial_loss']:.3f} -> {f['final_loss']:.3f}")


if __name__ == "__main__":
    main()
