"""Validation and repair over many seeds of every registered category.

For each category, over seeds 0..N-1 with validation on (``generate_valid``), prints

- the pass rate of each check on the final objects: ``penetration``, ``floating``,
  ``joint_sweep`` (geometric, after repair) and ``simulator`` (pybullet + MuJoCo, on
  the first ``--sim-seeds`` objects, all by default), of all of them together, and the
  number of objects that fail any (rates are rounded, counts are not). The
  simulator check runs on the object geometric repair returned: a simulator failure
  is counted, never replaced by another sample;
- repaired / replaced: share that needed repair, share replaced by a derived seed;
- median repair iterations (over the objects that needed repair);
- median milliseconds per object (one process): generation alone, the geometric
  checks alone (on the final object), validated generation (generation + checks +
  repair), and the simulator checks (export to a temporary folder + both engines).

Failing objects are listed with the checks that failed. Usage:

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
           "checks": {k: bool(c["ok"]) for k, c in rep["checks"].items()},
           "iterations": rep["repair"]["iterations"], "replaced": rep["repair"]["replaced"],
           "gen_ms": 1e3 * (t1 - t0), "valid_ms": 1e3 * (t2 - t1), "check_ms": 1e3 * (t3 - t2)}
    if sim:
        t4 = time.perf_counter()
        s = simulate_object(obj)
        out["sim_ms"] = 1e3 * (time.perf_counter() - t4)
        out["checks"]["simulator"] = s.ok
        out["ok"] = out["ok"] and s.ok
        if not s.ok:
            out["failed"].append("simulator: " + ", ".join(sorted({f"{i.kind}({i.detail.split(':')[0]}"
                                                                   f"{', ' + i.joint if i.joint else ''})"
                                                                   for i in s.issues})))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=200)
    ap.add_argument("--sim-seeds", type=int, default=None,
                    help="seeds per category that also run the simulators (default: all)")
    ap.add_argument("--workers", type=int, default=1)
    args = ap.parse_args()
    cats = args.categories or artipg.categories()
    n_sim = args.seeds if args.sim_seeds is None else min(args.sim_seeds, args.seeds)
    tasks = [(c, s, s < n_sim) for c in cats for s in range(args.seeds)]
    for c in cats:  # warm imports and caches
        _one((c, 0, False))
    if args.workers > 1:
        with ProcessPoolExecutor(args.workers) as pool:
            results = list(pool.map(_one, tasks, chunksize=8))
    else:
        results = [_one(t) for t in tasks]
    print(f"artipg {artipg.__version__}: seeds 0..{args.seeds - 1} per category, simulators on seeds "
          f"0..{n_sim - 1}; pass rates per check, medians in ms per object")
    head = (f"{'category':<18}" + "".join(f"{SHORT[k]:>7}" for k in CHECKS) + f"{'all':>7}{'failed':>7}{'repaired':>9}"
            f"{'replaced':>9}{'med it':>7}{'gen':>7}{'checks':>8}{'valid':>8}{'sim':>8}")
    print(head)
    allr = []
    failures = []
    for c in cats:
        rs = [r for (cc, _, _), r in zip(tasks, results) if cc == c]
        allr += rs
        _row(c, rs)
        failures += [(c, r["seed"], r["failed"]) for r in rs if not r["ok"]]
    print("-" * len(head))
    _row("all", allr)
    if failures:
        print("\nfailing objects (category, seed, checks):")
        for f in failures:
            print("  ", *f)


CHECKS = ("penetration", "floating", "joint_sweep", "simulator")
SHORT = {"penetration": "pen", "floating": "float", "joint_sweep": "sweep", "simulator": "sim"}


def _row(name, rs):
    sims = [r for r in rs if "sim_ms" in r]
    rep = [r for r in rs if r["iterations"] > 0 or r["replaced"]]
    med = lambda k, xs: float(np.median([r[k] for r in xs])) if xs else float("nan")  # noqa: E731

    def rate(check):
        xs = [r["checks"][check] for r in rs if check in r["checks"]]
        return f"{np.mean(xs):>7.1%}" if xs else f"{'-':>7}"

    print(f"{name:<18}" + "".join(rate(k) for k in CHECKS) + f"{np.mean([r['ok'] for r in rs]):>7.1%}"
          f"{sum(not r['ok'] for r in rs):>7d}{len(rep) / len(rs):>9.1%}{np.mean([r['replaced'] for r in rs]):>9.1%}"
          f"{med('iterations', rep):>7.1f}{med('gen_ms', rs):>7.2f}{med('check_ms', rs):>8.2f}"
          f"{med('valid_ms', rs):>8.2f}{med('sim_ms', sims):>8.0f}", flush=True)


if __name__ == "__main__":
    main()
