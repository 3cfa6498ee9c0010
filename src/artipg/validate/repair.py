"""Repair by simulated annealing over recorded parameters, and fresh-sample fallback.

:func:`generate_valid` generates object ``seed`` of a category and, while a geometric
check fails, perturbs the recorded parameters of the parts at fault (see
:mod:`artipg.validate.blame`) within their valid ranges and regenerates with those
overrides, so dependent parameters follow the rules. A candidate is accepted by the
Metropolis rule on the penalty (total penetration depth + gaps, metres) at a
temperature that cools geometrically. Moves: for every new set of blamed
parameters, first the ends of their ranges and their other options one at a time
(a conflict often resolves at the thinnest, widest or lowest setting, or with the
other hinge side); then random steps of one or two parameters, a move that improved
the penalty being repeated with twice the step (pattern search). The blamed set
widens when the search stalls. When the budget runs out the object is replaced by a fresh sample
from a derived seed (:func:`replacement_seed`), which is repaired the same way.

Everything is deterministic for a given (category, seed, overrides): the annealing
draws from ``default_rng([seed, attempt, ANNEAL_STREAM])``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from artipg.validate.api import check_object
from artipg.validate.blame import blame, max_level
from artipg.validate.checks import Tolerances
from artipg.validate.report import rnd

ANNEAL_STREAM = 0xA22EA1
REPLACE_STREAM = 0x5EED5


@dataclass(frozen=True)
class RepairBudget:
    """Limits of the repair search.

    Attributes
    ----------
    iterations : int
        Regenerations per attempt (the original seed, then each replacement).
    replacements : int
        Fresh samples tried after the original seed's budget is spent.
    patience : int
        Iterations without a new best penalty before the blamed set widens.
    probes : int
        Single-parameter moves (range ends, other options) tried first whenever the
        blamed set changes.
    t0 : float
        Initial temperature as a fraction of the initial penalty.
    cooling : float
        Temperature factor per iteration.
    """

    iterations: int = 48
    replacements: int = 4
    patience: int = 8
    probes: int = 12
    t0: float = 0.3
    cooling: float = 0.9


def replacement_seed(seed: int, attempt: int) -> int:
    """Seed of the ``attempt``-th (>= 1) replacement of object ``seed``.

    ``SeedSequence([seed, attempt, REPLACE_STREAM])`` hashed to 63 bits: far above the
    seeds a dataset uses, so a replacement never duplicates another object.
    """
    state = np.random.SeedSequence([int(seed), int(attempt), REPLACE_STREAM]).generate_state(2, dtype=np.uint32)
    return int((int(state[0]) << 31) ^ int(state[1])) & ((1 << 63) - 1)


def generate_valid(category, seed: int, overrides: dict | None = None, tol: Tolerances = Tolerances(),
                   budget: RepairBudget = RepairBudget(), simulate: bool = False, sim_options=None):
    """Generate object ``seed`` of ``category`` so that every check passes.

    Parameters
    ----------
    category : artipg.rules.Category or str
    seed : int
    overrides : dict, optional
        User overrides, kept through repair unless repair must change them.
    tol : Tolerances
    budget : RepairBudget
    simulate : bool
        Also require the simulator checks (a simulator failure is not annealed: the
        object is replaced by the next fresh sample).

    Returns
    -------
    ArticulatedObject
        With ``obj.seed == seed`` and ``obj.report`` holding the validation report
        (``"ok"``, ``"checks"``, ``"tolerances"``), ``"fixed_base"`` (the category's
        mounting policy, which the simulator check follows) and ``"repair"``: iterations,
        accepted moves, penalties, the parameters changed, and the seed the object
        was generated from when it had to be replaced. If nothing passes within the
        budget, the least-penalised candidate is returned with ``"ok": false``.
    """
    if isinstance(category, str):
        import artipg

        category = artipg.get_category(category)
    fixed_base = bool(getattr(category, "fixed_base", False))
    attempts = []
    best = None
    for attempt in range(budget.replacements + 1):
        src = int(seed) if attempt == 0 else replacement_seed(seed, attempt)
        obj, report, log = anneal(category, src, dict(overrides or {}), tol, budget, attempt)
        if report.ok and simulate:
            report = check_object(obj, tol, simulate=True, sim_options=sim_options, fixed_base=fixed_base)
        log["ok"] = report.ok
        attempts.append(log)
        if best is None or (report.ok, -report.penalty()) > (best[1].ok, -best[1].penalty()):
            best = (obj, report, log)
        if report.ok:
            break
    obj, report, log = best
    out = report.to_json()
    out["fixed_base"] = fixed_base
    out["repair"] = {
        "iterations": sum(a["iterations"] for a in attempts),
        "replaced": log["seed"] != int(seed),
        "source_seed": log["seed"],
        "attempts": attempts,
    }
    obj.seed = int(seed)
    obj.report = rnd(out)
    return obj


def anneal(category, seed: int, overrides: dict, tol: Tolerances, budget: RepairBudget, attempt: int = 0):
    """Simulated annealing of one seed; returns (object, report, log).

    The log holds the seed, iterations, accepted moves, initial / final penalty,
    the failed checks before repair and the parameters changed
    ({name: {"from": value, "to": value}}).
    """
    rng = np.random.default_rng([int(seed), int(attempt), ANNEAL_STREAM])
    obj = category.generate(seed, overrides or None)
    report = check_object(obj, tol)
    log = {"seed": int(seed), "iterations": 0, "accepted": 0, "failed": report.failed(),
           "penalty": [report.penalty(), report.penalty()], "changed": {}}
    if report.ok:
        return obj, report, log
    original = {n: p.value for n, p in obj.params.items()}
    cur = (dict(overrides), obj, report, report.penalty())
    best = cur
    T0 = budget.t0 * max(cur[3], 1e-4)
    T = T0
    level, stall, top = 0, 0, max_level(obj)
    momentum, probed, probes = None, None, []
    for it in range(1, budget.iterations + 1):
        ov, o, r, pen = cur
        parts = sorted({p for i in r.issues for p in (i.parts or _link_parts(o, i.links))})
        names = blame(o, parts, level)
        while not names and level < top:
            level += 1
            names = blame(o, parts, level)
        if not names:
            break
        key = (level, tuple(names))
        if key != probed:  # a new blame set: first try each parameter's extremes / options
            probed, probes = key, _probes(o, names, rng, budget.probes)
        new_ov = dict(ov)
        if probes:
            n, v = probes.pop()
            if n in o.params:
                new_ov[n] = v
        elif momentum is not None and momentum[0] in o.params and rng.random() < 0.6:
            # pattern move: repeat the last improving step, twice as long
            n, step = momentum
            p = o.params[n]
            new_ov[n] = float(min(p.hi, max(p.lo, p.value + 2.0 * step)))
        else:
            for n in _pick(o, names, rng):
                new_ov[n] = _propose(o.params[n], rng, T / T0)
        moved = [n for n in new_ov if new_ov[n] != ov.get(n) and n in o.params]
        o2 = category.generate(seed, new_ov)
        r2 = check_object(o2, tol)
        pen2 = r2.penalty()
        log["iterations"] = it
        single = len(moved) == 1 and o.params[moved[0]].kind == "uniform" and moved[0] in o2.params
        momentum = (moved[0], o2.params[moved[0]].value - o.params[moved[0]].value) if single and pen2 < pen else None
        if r2.ok or pen2 <= pen or rng.random() < math.exp(-(pen2 - pen) / max(T, 1e-12)):
            cur = (new_ov, o2, r2, pen2)
            log["accepted"] += 1
        if r2.ok:
            best = cur
            break
        if pen2 < best[3] - 1e-9:
            best, stall = cur, 0
        else:
            stall += 1
            if stall >= budget.patience:  # widen the blame and restart from the best
                level, stall, cur = min(level + 1, top), 0, best
        T *= budget.cooling
    _, obj, report, pen = best
    log["penalty"][1] = pen
    log["changed"] = {n: {"from": original.get(n), "to": p.value} for n, p in obj.params.items()
                      if n in original and p.value != original[n]}
    return obj, report, log


def _link_parts(obj, link_names) -> list[str]:
    names = set(link_names)
    return [p.name for lk in obj.links if lk.name in names for p in lk.parts]


def _probes(obj, names, rng, limit: int) -> list[tuple[str, object]]:
    """Single-parameter moves tried first for a new set of blamed parameters: both
    ends of each continuous range, the other options of each discrete draw (at most
    ``limit``, in a random order; popped from the end)."""
    moves = []
    for n in names:
        p = obj.params[n]
        if p.kind == "uniform":
            moves += [(n, float(v)) for v in (p.lo, p.hi) if v != p.value]
        elif p.kind == "integer":
            moves += [(n, int(v)) for v in (p.value - 1, p.value + 1) if p.lo <= v <= p.hi]
        elif p.kind == "flag":
            moves.append((n, not p.value))
        else:
            moves += [(n, o) for o in p.options if o != p.value]
    order = rng.permutation(len(moves))[:limit]
    return [moves[i] for i in order]


def _pick(obj, names, rng) -> list[str]:
    """One or two parameters, continuous ones three times as likely as discrete ones
    (a different template or count can re-randomise the rest of its slot)."""
    w = np.array([3.0 if obj.params[n].kind == "uniform" else 1.0 for n in names])
    k = 2 if len(names) > 1 and rng.random() < 0.3 else 1
    idx = rng.choice(len(names), size=k, replace=False, p=w / w.sum())
    return [names[i] for i in sorted(idx)]


def _propose(p, rng, heat: float):
    """A new value for recorded parameter ``p`` within its recorded range.

    Uniform: one end of the range (probability 0.15: conflicts often resolve at the
    thinnest / widest / lowest setting), a uniform jump (0.25), else a Gaussian step
    of (0.05 + 0.3 * heat) of the range; integer: +-1; choice: another option;
    flag: flipped.
    """
    if p.kind == "uniform":
        lo, hi = float(p.lo), float(p.hi)
        u = rng.random()
        if u < 0.15:
            return hi if rng.random() < 0.5 else lo
        if u < 0.4:
            return lo + rng.random() * (hi - lo)
        return float(min(hi, max(lo, p.value + rng.normal() * (0.05 + 0.3 * heat) * (hi - lo))))
    if p.kind == "integer":
        step = 1 if rng.random() < 0.5 else -1
        v = p.value + step
        return int(min(p.hi, max(p.lo, v if p.lo <= v <= p.hi else p.value - step)))
    if p.kind == "flag":
        return not p.value
    others = [o for o in p.options if o != p.value]
    return others[int(rng.integers(len(others)))] if others else p.value
