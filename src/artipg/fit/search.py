"""The search for a twin: restarts over seeds per sub-category, then refinement.

1. **Restarts.** For every sub-category (overriding ``"subcategory"``), seeds
   ``0 .. restarts - 1`` are generated and scored (:func:`artipg.fit.score.compare`):
   the seed fixes the template choices and a first draw of every parameter.
2. **Refinement** of the ``refine`` best distinct candidates, through overrides of
   their recorded parameters (each clamped to its then-valid range by the recorder):
   one sweep over every continuous parameter (a step of a quarter of its range up,
   then down; kept if better) that also measures each one's influence, then simulated
   annealing whose moves pick 1-3 parameters in proportion to that influence
   (Gaussian steps for continuous ones; +-1 for counts; with a small weight, another
   option of a choice or flag, i.e. a template change).

Cost per object: ``len(subcategories) * restarts + refine * (sweep + iterations)``
evaluations, each one generation plus three 2048-point samples and Chamfer distances
(about 5-15 ms); see ``docs/fit.md`` for measured figures.

Deterministic for (target, category, budget): the moves draw from
``default_rng([FIT_STREAM, k])`` for the ``k``-th refined candidate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from artipg.fit.score import Score, compare
from artipg.fit.shape import Shape, object_shape

FIT_STREAM = 0xF17


@dataclass(frozen=True)
class FitBudget:
    """Limits of the search.

    Attributes
    ----------
    restarts : int
        Seeds tried per sub-category.
    refine : int
        Best distinct (sub-category, seed) candidates refined.
    iterations : int
        Annealing moves per refined candidate (after the sweep).
    sweep : bool
        Run the one-parameter sweep before annealing.
    points : int
        Points per whole-object cloud.
    t0 : float
        Initial temperature as a fraction of the candidate's score.
    cooling : float
        Temperature factor per move.
    """

    restarts: int = 24
    refine: int = 3
    iterations: int = 80
    sweep: bool = True
    points: int = 2048
    t0: float = 0.05
    cooling: float = 0.95


@dataclass
class Candidate:
    """A scored generation: (seed, overrides) -> object, shape, score."""

    seed: int
    overrides: dict
    obj: object
    shape: Shape
    score: Score

    @property
    def total(self) -> float:
        return self.score.total


class Evaluator:
    """Generates and scores candidates, counting evaluations."""

    def __init__(self, category, target: Shape, points: int):
        self.category, self.target, self.points = category, target, points
        self.count = 0

    def __call__(self, seed: int, overrides: dict) -> Candidate | None:
        self.count += 1
        try:
            obj = self.category.generate(int(seed), dict(overrides))
            shape = object_shape(obj, self.points)
        except ValueError:  # an override combination the rules cannot build
            return None
        return Candidate(int(seed), dict(overrides), obj, shape, compare(self.target, shape))


def restarts(ev: Evaluator, budget: FitBudget) -> list[Candidate]:
    """Stage 1: every sub-category x seeds ``0 .. restarts - 1``, best first."""
    out = []
    for sub in ev.category.subcategories:
        for seed in range(budget.restarts):
            c = ev(seed, {"subcategory": sub})
            if c is not None:
                out.append(c)
    return sorted(out, key=lambda c: c.total)


_TUNABLE = ("uniform", "integer", "choice", "flag")


def _tunable(obj) -> list[str]:
    return [n for n, p in obj.params.items() if n != "subcategory" and p.kind in _TUNABLE]


def _move(p, rng: np.random.Generator, heat: float):
    """A new value for recorded parameter ``p`` (see the module docstring)."""
    if p.kind == "uniform":
        lo, hi = float(p.lo), float(p.hi)
        return float(min(hi, max(lo, p.value + rng.normal() * (0.03 + 0.2 * heat) * (hi - lo))))
    if p.kind == "integer":
        v = p.value + (1 if rng.random() < 0.5 else -1)
        return int(min(p.hi, max(p.lo, v)))
    if p.kind == "flag":
        return not p.value
    others = [o for o in p.options if o != p.value]
    return others[int(rng.integers(len(others)))] if others else p.value


def refine(ev: Evaluator, start: Candidate, budget: FitBudget, k: int) -> list[Candidate]:
    """Stage 2 on one candidate; returns every improving candidate, best last."""
    rng = np.random.default_rng([FIT_STREAM, int(k)])
    best = cur = start
    kept = [start]
    influence: dict[str, float] = {}
    if budget.sweep:
        for n in [n for n in _tunable(start.obj) if start.obj.params[n].kind == "uniform"]:
            p = cur.obj.params.get(n)
            if p is None or p.kind != "uniform" or p.hi <= p.lo:
                continue
            step = 0.25 * (p.hi - p.lo)
            gain = 0.0
            for v in (min(p.hi, p.value + step), max(p.lo, p.value - step)):
                c = ev(cur.seed, {**cur.overrides, n: v})
                if c is None:
                    continue
                gain = max(gain, abs(c.total - cur.total))
                if c.total < cur.total:
                    cur = c
                    kept.append(c)
                    break
            influence[n] = gain
        best = cur
    T0 = budget.t0 * max(cur.total, 1e-6)
    T = T0
    for _ in range(budget.iterations):
        names = _tunable(cur.obj)
        if not names:
            break
        w = np.array([(3.0 * influence.get(n, 0.0) / max(cur.total, 1e-9) + 0.05) if cur.obj.params[n].kind == "uniform"
                      else (0.03 if cur.obj.params[n].kind == "integer" else 0.01) for n in names])
        kk = min(len(names), 1 + int(rng.random() < 0.3) + int(rng.random() < 0.1))
        picked = rng.choice(len(names), size=kk, replace=False, p=w / w.sum())
        ov = dict(cur.overrides)
        for i in picked:
            ov[names[i]] = _move(cur.obj.params[names[i]], rng, T / T0)
        c = ev(cur.seed, ov)
        T *= budget.cooling
        if c is None:
            continue
        d = c.total - cur.total
        if d <= 0 or rng.random() < math.exp(-d / max(T, 1e-12)):
            cur = c
            if c.total < best.total:
                best = c
                kept.append(c)
    return kept


def edge_pressure(ev: Evaluator, cand: Candidate, edge: float = 0.01, inward: float = 0.1,
                  worse: float = 0.005) -> list[dict]:
    """Overridden continuous parameters of ``cand`` that sit at an end of their range
    (within ``edge`` of it, as a fraction of the range) *and* press against it: moving
    them ``inward`` of the range away from the end worsens the score by more than a
    fraction ``worse``. These are the ranges a real object would widen."""
    out = []
    for n in cand.overrides:
        p = cand.obj.params.get(n)
        if p is None or p.kind != "uniform" or p.hi <= p.lo:
            continue
        f = (p.value - p.lo) / (p.hi - p.lo)
        if edge < f < 1 - edge:
            continue
        side = "low" if f <= edge else "high"
        v = p.value + (inward if side == "low" else -inward) * (p.hi - p.lo)
        c = ev(cand.seed, {**cand.overrides, n: v})
        if c is not None and c.total > cand.total * (1 + worse):
            out.append({"name": n, "value": p.value, "range": [p.lo, p.hi], "side": side,
                        "worse_inward": (c.total - cand.total) / cand.total})
    return out


def search(category, target: Shape, budget: FitBudget = FitBudget()) -> tuple[list[Candidate], Evaluator]:
    """Run both stages; returns (candidates best first, the evaluator: its ``count`` is
    the number of evaluations, and it scores further candidates)."""
    ev = Evaluator(category, target, budget.points)
    first = restarts(ev, budget)
    pool = list(first)
    for k, start in enumerate(first[:budget.refine]):
        pool += refine(ev, start, budget, k)[1:]
    pool.sort(key=lambda c: c.total)
    return pool, ev
