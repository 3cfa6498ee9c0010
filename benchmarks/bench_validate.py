"""Validation and repair over many seeds of every registered category.

For each category, over seeds 0..N-1 with validation on (``generate_valid``), prints

- pass: share of objects that pass every geometric check after repair, and, on the
  first ``--sim-seeds`` of them, every simulator check (pybullet + MuJoCo);
- repaired / replaced: share that needed repair, share replaced by a derived seed;
- median repair iterations (over the objects that needed repair);
- median milliseconds per object (one process): generation alone, the geometric
  checks alone (on the final object), validated generation (generation + checks +
  repair), and the simulator checks (export to a temporary folder + both engines).

Failing objects are listed with the check that failed. Usage:

    python benchmarks/bench_validate.py [--categories a b] [--seeds 200] [--sim-seeds 50] [--workers 2]
"""

from __future__ import annotations

import argparse
import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np

import artipg


def _one(task):
    from artipg.validate import check_object, generate_valid
    from artipg.validate.sim import simulate_object

    category, seed, sim = task
    t0 = time.perf_counter()
    artipg.generate(category, seed)
    t1 = time.perf_counter()
    obj = generate_valid(category, seed)
    t2 = time.perf_counter()
    check_object(obj)
    t3 = time.perf_counter()
    rep = obj.report
    out = {"seed": seed, "ok": bool(rep["ok"]), "failed": [k for k, c in rep["checks"].items() if not c["ok"]],
           "iterations": rep["repair"]["iterations"], "replaced": rep["repair"]["replaced"],
           "gen_ms": 1e3 * (t1 - t0), "valid_ms": 1e3 * (t2 - t1), "check_ms": 1e3 * (t3 - t2)}
    if sim:
        t4 = time.perf_counter()
        s = simulate_object(obj)
        out["sim_ms"] = 1e3 * (time.perf_counter() - t4)
        out["sim_ok"] = s.ok
        out["sim_issues"] = sorted({f"{i.kind}({i.detail.split(':')[0]})" for i in s.issues})
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=200)
    ap.add_argument("--sim-seeds", type=int, default=50, help="seeds per category that also run the simulators")
    ap.add_argument("--workers", type=int, default=1)
    args = ap.parse_args()
    cats = args.categories or artipg.categories()
    tasks = [(c, s, s < args.sim_seeds) for c in cats for s in range(args.seeds)]
    for c in cats:  # warm imports and caches
        _one((c, 0, False))
    if args.workers > 1:
        with ProcessPoolExecutor(args.workers) as pool:
            results = list(pool.map(_one, tasks, chunksize=8))
    else:
        results = [_one(t) for t in tasks]
    print(f"artipg {artipg.__version__}: seeds 0..{args.seeds - 1} per category, simulators on seeds "
          f"0..{min(args.sim_seeds, args.seeds) - 1}; medians in ms per object")
    head = (f"{'category':<18}{'pass':>7}{'sim pass':>9}{'repaired':>9}{'replaced':>9}{'med it':>7}"
            f"{'gen':>7}{'checks':>8}{'valid':>8}{'sim':>8}")
    print(head)
    allr = []
    failures = []
    for c in cats:
        rs = [r for (cc, _, _), r in zip(tasks, results) if cc == c]
        allr += rs
        _row(c, rs)
        failures += [(c, r["seed"], r["failed"]) for r in rs if not r["ok"]]
        failures += [(c, r["seed"], r["sim_issues"]) for r in rs if r.get("sim_ok") is False]
    print("-" * len(head))
    _row("all", allr)
    if failures:
        print("\nfailing objects (category, seed, checks):")
        for f in failures:
            print("  ", *f)


def _row(name, rs):
    sims = [r for r in rs if "sim_ok" in r]
    rep = [r for r in rs if r["iterations"] > 0 or r["replaced"]]
    med = lambda k, xs: float(np.median([r[k] for r in xs])) if xs else float("nan")  # noqa: E731
    print(f"{name:<18}{np.mean([r['ok'] for r in rs]):>7.1%}"
          f"{(np.mean([r['sim_ok'] for r in sims]) if sims else float('nan')):>9.1%}"
          f"{len(rep) / len(rs):>9.1%}{np.mean([r['replaced'] for r in rs]):>9.1%}"
          f"{med('iterations', rep):>7.1f}{med('gen_ms', rs):>7.2f}{med('check_ms', rs):>8.2f}"
          f"{med('valid_ms', rs):>8.2f}{med('sim_ms', sims):>8.0f}", flush=True)


if __name__ == "__main__":
    main()
