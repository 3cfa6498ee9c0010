"""Per-object lookup tables of the parts' analytic knowledge (built once, cached).

They turn the region, pose and class knowledge that part templates define into flat
arrays indexed by global primitive or part index, so labelling any set of surface
points (sampled or ray cast) is a gather plus a box test, with no Python loop over
points.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np

from artipg.geometry.base import _CORNER_SIGNS
from artipg.vocabulary import ACTIONABLE_ID, AFFORDANCES

_CACHE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


@dataclass
class Knowledge:
    """Flat tables of one object's part knowledge.

    Attributes
    ----------
    part_actionable : (P,) int64
        Index into :data:`artipg.vocabulary.ACTIONABLE_CLASSES` per part.
    part_pose : (P, 4, 4) float64
        Part frame of each part in its link frame (``part.pose``).
    part_canonical : (P, 4, 4) float64
        Canonical frame of each part in its link frame (``part.pose @ part.canonical``).
    part_center : (P, 3) float64
        Centre of the part's bounding box in its canonical frame (metres).
    part_size : (P, 3) float64
        Extents of that box along the canonical axes (metres).
    part_diag : (P,) float64
        Length of the box diagonal (metres): the NPCS scale.
    region_role : (A, M) bool
        Whether primitive m carries a role of its part's region for affordance a
        (``A = len(AFFORDANCES)``, M primitives); False when the part has no region a.
    region_box : (A, M, 2, 3) float64
        Region box of primitive m's part, in the part frame; (-inf, +inf) when the
        region has no box.
    rest_link_poses : (L, 4, 4) float64
        Link poses at the rest state (object frame).
    object_center : (3,) float64, object_diag : float
        Centre and diagonal of the object's bounding box at rest (object NPCS).
    """

    part_actionable: np.ndarray
    part_pose: np.ndarray
    part_canonical: np.ndarray
    part_center: np.ndarray
    part_size: np.ndarray
    part_diag: np.ndarray
    region_role: np.ndarray
    region_box: np.ndarray
    rest_link_poses: np.ndarray
    object_center: np.ndarray
    object_diag: float


def _canonical_boxes(obj, canon_link: np.ndarray) -> np.ndarray:
    """Boxes (P, 2, 3) of the parts' primitives in their canonical frames."""
    table = obj.primitive_table
    P = len(obj.parts)
    lo = np.full((P, 3), np.inf)
    hi = np.full((P, 3), -np.inf)
    inv = np.linalg.inv(canon_link)
    for g in table.groups:
        b = g.geom.bounds_batch(g.P)  # (M, 2, 3) local
        c = b[:, :1] + _CORNER_SIGNS[None] * (b[:, 1:] - b[:, :1])  # (M, 8, 3)
        # primitive frame in its part's canonical frame
        T = inv[g.part] @ g.T
        w = np.einsum("mij,mkj->mki", T[:, :3, :3], c) + T[:, None, :3, 3]
        np.minimum.at(lo, g.part, w.min(axis=1))
        np.maximum.at(hi, g.part, w.max(axis=1))
    return np.stack([lo, hi], axis=1)


def build_knowledge(obj) -> Knowledge:
    """Build the :class:`Knowledge` tables of ``obj`` (use :func:`knowledge`)."""
    parts = obj.parts
    table = obj.primitive_table
    act = np.array([ACTIONABLE_ID[p.actionable] for p in parts], dtype=np.int64)
    pose = np.stack([p.pose for p in parts])
    canon = pose @ np.stack([p.canonical for p in parts])
    box = _canonical_boxes(obj, canon)
    center = (box[:, 0] + box[:, 1]) / 2
    size = box[:, 1] - box[:, 0]
    for i, p in enumerate(parts):  # templates may state the size of a centred canonical box
        if p.size is not None:
            size[i] = np.asarray(p.size, dtype=float)
            center[i] = 0.0
    diag = np.linalg.norm(size, axis=1)
    M = table.n_prims
    A = len(AFFORDANCES)
    role = np.zeros((A, M), dtype=bool)
    rbox = np.empty((A, M, 2, 3))
    rbox[:, :, 0] = -np.inf
    rbox[:, :, 1] = np.inf
    k = 0
    for p in parts:
        n = len(p.primitives)
        for a, name in enumerate(AFFORDANCES):
            reg = p.regions.get(name)
            if reg is None:
                continue
            role[a, k:k + n] = [not reg.roles or pr.role in reg.roles for pr in p.primitives]
            if reg.box is not None:
                rbox[a, k:k + n] = np.asarray(reg.box, dtype=float)
        k += n
    L0 = obj.link_poses(None)
    ob = obj.bounds(None)
    return Knowledge(act, pose, canon, center, size, diag, role, rbox, L0, (ob[0] + ob[1]) / 2,
                     float(np.linalg.norm(ob[1] - ob[0])))


def knowledge(obj) -> Knowledge:
    """The cached :class:`Knowledge` of ``obj``."""
    k = _CACHE.get(obj)
    if k is None:
        k = _CACHE[obj] = build_knowledge(obj)
    return k
