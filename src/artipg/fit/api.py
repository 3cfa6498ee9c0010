"""``fit_object``: the procedural twin of an object folder, and its fit report."""

from __future__ import annotations

import json
import time
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from artipg.fit.labels import our_category
from artipg.fit.score import Score, compare
from artipg.fit.search import FitBudget, edge_pressure, search
from artipg.fit.shape import STATES, Shape, folder_shape, object_shape

REPORT_NAME = "fit_report.json"
STATE_NAMES = ("closed", "half", "open")
#: Candidates (best first) checked for validity before repairing the best one.
VALIDATE_TRIES = 6


@dataclass
class FitResult:
    """The twin of a target folder.

    Attributes
    ----------
    obj : ArticulatedObject
        The twin, at real-world scale (metres), ``obj.report`` holding its validation.
    folder : Path
        The target folder.
    category : str
    seed : int
        The twin's seed (with ``overrides`` it regenerates the searched object).
    overrides : dict
        Recorded-parameter overrides found by the search (``"subcategory"`` included).
    score : Score
        The twin against the target, links compared at every state of :data:`STATES`.
    target, twin : Shape
    evaluations : int
        Candidates generated and scored.
    seconds : float
        Wall time of the fit.
    budget : FitBudget
    at_edge : list of dict
        Fitted parameters pressing against an end of their range
        (:func:`artipg.fit.search.edge_pressure`): name, value, range, side.
    """

    obj: object
    folder: Path
    category: str
    seed: int
    overrides: dict
    score: Score
    target: Shape
    twin: Shape
    evaluations: int
    seconds: float
    budget: FitBudget
    at_edge: list

    @property
    def passed(self) -> bool:
        """Whether the twin passes validation."""
        return bool(self.obj.report.get("ok", False))

    def link_chamfers(self) -> np.ndarray:
        """Per matched link, its Chamfer-L1 averaged over the states (normalised units)."""
        return np.array([np.nanmean(d) for d in self.score.link_cd]) if self.score.link_cd else np.zeros(0)

    def to_json(self) -> dict:
        """The fit report (``fit_report.json``): distances, matches, what is unmatched, cost."""
        t, w, s = self.target, self.twin, self.score
        links = []
        for (i, j), d, je in zip(s.pairs, s.link_cd, s.joints):
            links.append({"target_link": t.names[i], "target_label": t.raw_labels[i], "twin_link": w.names[j],
                          "twin_label": w.raw_labels[j], "chamfer": dict(zip(STATE_NAMES, map(_r, d))),
                          "joint": _rounded(je)})
        return {
            "target": str(self.folder), "category": self.category,
            "twin": {"subcategory": self.obj.subcategory, "seed": self.seed, "overrides": _rounded(self.overrides),
                     "templates": self.obj.templates},
            "distance_units": "Chamfer-L1, in units of each object's closed bounding-box diagonal",
            "states": dict(zip(STATE_NAMES, STATES)),
            "score": _r(s.total),
            "whole_chamfer": dict(zip(STATE_NAMES, map(_r, s.whole))),
            "median_link_chamfer": _r(float(np.median(self.link_chamfers()))) if s.link_cd else None,
            "links": links,
            "unmatched": {
                "target": [{"link": t.names[i], "label": t.raw_labels[i], "area_share": _r(t.share[i])}
                           for i in s.unmatched_target],
                "twin": [{"link": w.names[j], "label": w.raw_labels[j], "area_share": _r(w.share[j])}
                         for j in s.unmatched_twin]},
            "target_inconsistent": [
                {"link": t.names[i], "label": t.raw_labels[i],
                 "issue": "semantics.txt says it moves; its joint is fixed"}
                for i in range(len(t.names)) if t.labels[i] != "body" and t.joint_type[i] == "fixed"],
            "movable_joints": {"target": sum(x != "fixed" for x in t.joint_type),
                               "twin": sum(x != "fixed" for x in w.joint_type)},
            "proportions": {"target": proportions(t.extents), "twin": proportions(w.extents)},
            "twin_extents_m": [_r(x) for x in w.extents],
            "parameters_at_edge": _rounded(self.at_edge),
            "validation": {"ok": self.passed, "repair": self.obj.report.get("repair", {}).get("iterations", 0)},
            "cost": {"evaluations": self.evaluations, "seconds": round(self.seconds, 2), "budget": asdict(self.budget)},
        }


def proportions(extents) -> dict:
    """Height / width and depth / width of a box (x depth, y width, z height)."""
    d, w, h = (float(x) for x in extents)
    w = w if w > 0 else 1.0
    return {"height_width": _r(h / w), "depth_width": _r(d / w)}


def _r(x):
    return None if x is None or not np.isfinite(x) else round(float(x), 6)


def _rounded(v):
    if isinstance(v, dict):
        return {k: _rounded(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_rounded(x) for x in v]
    if isinstance(v, (float, np.floating)):
        return _r(v)
    if isinstance(v, np.integer):
        return int(v)
    return v


def _valid(category, seed: int, overrides: dict, anneal: bool):
    """The candidate through :func:`artipg.validate.generate_valid`: checks only, or
    checks and repair (never a replacement seed: that would be another object)."""
    from artipg.validate import RepairBudget, generate_valid

    budget = RepairBudget(replacements=0) if anneal else RepairBudget(iterations=0, replacements=0)
    return generate_valid(category, seed, overrides, budget=budget)


def fit_object(folder: str | Path, category: str, budget: FitBudget = FitBudget(), seed: int = 0,
               validate: bool = True) -> FitResult:
    """Find the sub-category, templates and parameters whose object best matches a folder.

    Parameters
    ----------
    folder : str or Path
        An object folder: ``mobility.urdf`` + meshes + ``semantics.txt``
        (PartNet-Mobility's or artipg's), in any units (shapes are compared after
        normalising by the bounding box).
    category : str
        Our category name (``storage_furniture``) or PartNet-Mobility's (``StorageFurniture``).
    budget : FitBudget
        Search limits (see :mod:`artipg.fit.search` for the cost).
    seed : int
        Seed of the target's point sampling.
    validate : bool
        Make the twin pass validation: the best candidate that passes among the
        first :data:`VALIDATE_TRIES`, else the best one repaired.

    Returns
    -------
    FitResult

    Raises
    ------
    KeyError
        Unknown category (the message lists the valid ones).
    FileNotFoundError
        No ``mobility.urdf`` in ``folder`` (or a mesh it names is missing).
    ValueError
        A URDF without visual geometry, or one that cannot be parsed.
    """
    import artipg

    start = time.perf_counter()
    name = our_category(category)
    cat = artipg.get_category(name)
    try:
        target = folder_shape(folder, budget.points, seed=seed, per_link=512)
    except (FileNotFoundError, ValueError):
        raise
    except Exception as e:  # a malformed URDF or mesh: the parsers raise their own types
        raise ValueError(f"{folder}: cannot read the object: {type(e).__name__}: {e}") from e
    pool, ev = search(cat, target, budget)
    best = pool[0]
    obj = None
    if validate:
        for c in pool[:VALIDATE_TRIES]:
            o = _valid(cat, c.seed, c.overrides, anneal=False)
            if o.report.get("ok"):
                obj, best = o, c
                break
        if obj is None:
            obj = _valid(cat, best.seed, best.overrides, anneal=True)
    else:
        obj = best.obj
        obj.report = {}
    edges = edge_pressure(ev, best)
    twin = object_shape(obj, budget.points, per_link=512)
    score = compare(target, twin, per_state_links=True)
    return FitResult(obj, Path(folder), name, best.seed, best.overrides, score, target, twin, ev.count,
                     time.perf_counter() - start, budget, edges)


def write_twin(result: FitResult, out: str | Path, n_points: int = 2048, overwrite: bool = False) -> Path:
    """Write the twin's object folder at ``out`` (every annotation, through
    :func:`artipg.export.export_object`) and its ``fit_report.json`` inside it."""
    from artipg.export import export_object

    dest = export_object(result.obj, Path(out), n_points=n_points, overwrite=overwrite)
    (dest / REPORT_NAME).write_text(json.dumps(result.to_json(), indent=1) + "\n")
    return dest
