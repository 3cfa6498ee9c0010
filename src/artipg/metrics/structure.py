"""Structure statistics of object sets: joints, joint types, links and sizes.

The joint count of an object is its number of *movable* joints (revolute, continuous,
prismatic, planar, floating); fixed joints only glue links together (PartNet-Mobility
uses them for its empty ``base`` link). Histograms bin 0, 1, ..., 9 and "10+" joints,
as in the paper's Fig. 4 (which shows 1-9 and >= 10).
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from artipg.io.structure import MOVABLE_TYPES, ObjectStructure  # noqa: F401 - re-exported

JOINT_BINS = tuple(str(i) for i in range(10)) + ("10+",)


def joint_histogram(counts) -> np.ndarray:
    """Fraction of objects with 0, 1, ..., 9 and 10 or more joints.

    Parameters
    ----------
    counts : (M,) int array_like
        Joints per object.

    Returns
    -------
    (11,) float ndarray
        Frequencies in the order of :data:`JOINT_BINS`; sums to 1 (zeros if M = 0).
    """
    c = np.minimum(np.asarray(counts, dtype=np.int64), 10)
    h = np.bincount(c, minlength=11).astype(float)
    return h / max(1, len(c))


def _describe(x: np.ndarray) -> dict:
    if not len(x):
        return {"mean": float("nan"), "std": float("nan"), "median": float("nan"), "min": float("nan"),
                "max": float("nan")}
    return {"mean": float(np.mean(x)), "std": float(np.std(x)), "median": float(np.median(x)),
            "min": float(np.min(x)), "max": float(np.max(x))}


def summarize_structure(structures) -> dict:
    """Statistics of a set of objects (JSON-ready).

    Parameters
    ----------
    structures : sequence of ObjectStructure

    Returns
    -------
    dict
        ``n_objects``; ``joints`` (mean/std/median/min/max of movable joints per object
        and ``histogram``: {bin label: fraction}); ``joint_types`` ({type: joints of that
        type per object, averaged}); ``links`` (mean/std/median/min/max of links per
        object); ``size`` ({"depth_x", "width_y", "height_z", "diagonal"}: mean/std/
        median/min/max in metres); ``proportions`` ({"height_width", "depth_width"}:
        the same statistics of the extents' ratios, unit-free, so unit-less sets such as
        PartNet-Mobility compare with metric ones).
    """
    s = list(structures)
    joints = np.array([o.n_joints for o in s], dtype=float)
    links = np.array([o.n_links for o in s], dtype=float)
    ext = np.array([o.extents for o in s], dtype=float).reshape(-1, 3)
    types = Counter(t for o in s for t in o.joint_types)
    hist = joint_histogram(joints.astype(np.int64))
    return {
        "n_objects": len(s),
        "joints": {**_describe(joints), "histogram": dict(zip(JOINT_BINS, hist.tolist()))},
        "joint_types": {t: types[t] / max(1, len(s)) for t in sorted(types)},
        "links": _describe(links),
        "size": {"depth_x": _describe(ext[:, 0]), "width_y": _describe(ext[:, 1]), "height_z": _describe(ext[:, 2]),
                 "diagonal": _describe(np.linalg.norm(ext, axis=1))},
        "proportions": {"height_width": _describe(_ratio(ext[:, 2], ext[:, 1])),
                        "depth_width": _describe(_ratio(ext[:, 0], ext[:, 1]))},
    }


def _ratio(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a / b`` where ``b > 0`` (objects of zero width are left out)."""
    keep = b > 0
    return a[keep] / b[keep]
