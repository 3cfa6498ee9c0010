"""Signed distance to an object at any joint state, from the primitives' exact SDFs.

The object is the union of its primitives, so its signed distance is the minimum of
theirs: exact outside the object and a bound inside (where only the sign matters).
Primitives are culled by their bounding boxes, so a query only evaluates the
primitives that can be closer than ``max_dist``.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.base import _CORNER_SIGNS


def primitive_world_bounds(obj, qpos=None) -> np.ndarray:
    """Bounding boxes (M, 2, 3) of all primitives in the object frame at ``qpos``,
    indexed by global primitive index (metres)."""
    table = obj.primitive_table
    L = obj.link_poses(qpos)
    out = np.empty((table.n_prims, 2, 3))
    for g, W in zip(table.groups, table.world(L)):
        b = g.geom.bounds_batch(g.P)
        c = b[:, :1] + _CORNER_SIGNS[None] * (b[:, 1:] - b[:, :1])
        w = np.einsum("mij,mkj->mki", W[:, :3, :3], c) + W[:, None, :3, 3]
        out[g.prim, 0] = w.min(axis=1)
        out[g.prim, 1] = w.max(axis=1)
    return out


_CHUNK = 64


def _spatial_order(x: np.ndarray, cell: float = 0.05) -> np.ndarray:
    """A permutation that groups points of the same ``cell``-sized voxel together."""
    q = np.floor((x - x.min(axis=0)) / cell).astype(np.int64)
    return np.lexsort((q[:, 2], q[:, 1], q[:, 0]))


def primitive_params(obj) -> tuple[list, list]:
    """Geometry template and parameter vector of every primitive, by global index."""
    table = obj.primitive_table
    geoms: list = [None] * table.n_prims
    params: list = [None] * table.n_prims
    for g in table.groups:
        for row, k in enumerate(g.prim):
            geoms[k] = g.geom
            params[k] = g.P[row]
    return geoms, params


def object_sdf(obj, x: np.ndarray, qpos=None, max_dist: float = np.inf, parts=None,
               exclude_parts=None, unsigned: bool = False, sort: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Signed distance of points to ``obj`` at ``qpos`` and the nearest primitive.

    Parameters
    ----------
    obj : ArticulatedObject
    x : (N, 3) array
        Query points, object frame (metres).
    qpos : None, dict or sequence
        Joint state.
    max_dist : float
        Primitives whose bounding box is farther than this from a point are skipped
        for it; such points may get ``+inf``.
    parts, exclude_parts : iterable of int, optional
        Restrict the union to these part indices / leave these out.
    unsigned : bool
        Minimise ``|sdf|`` instead: the distance to the nearest primitive *surface*
        (a point on one primitive's face that lies inside an overlapping primitive
        is then attributed to the face it lies on).
    sort : bool
        Group the points spatially first (leave False when consecutive points are
        already close together, e.g. grids on small boxes).

    Returns
    -------
    sdf : (N,) float64
        Minimum signed distance over the primitives (negative inside), metres; the
        minimum unsigned distance with ``unsigned``.
    primitive : (N,) int64
        Global index of the primitive giving that minimum (-1 where none was within
        ``max_dist``).
    """
    x = np.asarray(x, dtype=float).reshape(-1, 3)
    table = obj.primitive_table
    n = len(x)
    best = np.full(n, np.inf)
    arg = np.full(n, -1, dtype=np.int64)
    if n == 0:
        return best, arg
    keep = np.ones(table.n_prims, dtype=bool)
    if parts is not None:
        keep[:] = False
        keep[np.isin(table.prim_part, np.asarray(list(parts), dtype=np.int64))] = True
    if exclude_parts is not None:
        keep[np.isin(table.prim_part, np.asarray(list(exclude_parts), dtype=np.int64))] = False
    B = primitive_world_bounds(obj, qpos)[keep]
    kidx = np.flatnonzero(keep)
    if not len(kidx):
        return best, arg
    # broad phase: spatially sorted chunks of points against primitive boxes
    order = _spatial_order(x) if sort else np.arange(n)
    xs = x[order]
    nch = (n + _CHUNK - 1) // _CHUNK
    pad = np.concatenate([xs, np.repeat(xs[-1:], nch * _CHUNK - n, axis=0)]).reshape(nch, _CHUNK, 3)
    clo, chi = pad.min(axis=1), pad.max(axis=1)
    r = max_dist if np.isfinite(max_dist) else np.inf
    hit = np.all(B[None, :, 0] - r <= chi[:, None], axis=2) & np.all(B[None, :, 1] + r >= clo[:, None], axis=2)
    L = obj.link_poses(qpos)
    geoms, params = primitive_params(obj)
    bs = np.full(n, np.inf)
    ba = np.full(n, -1, dtype=np.int64)
    for col in np.flatnonzero(hit.any(axis=0)):
        k = kidx[col]
        ch = np.flatnonzero(hit[:, col])
        idx = (ch[:, None] * _CHUNK + np.arange(_CHUNK)[None]).ravel()
        idx = idx[idx < n]
        W = L[table.prim_link[k]] @ table.prim_T[k]
        Ri, ti = W[:3, :3].T, -W[:3, :3].T @ W[:3, 3]
        d = geoms[k].sdf(params[k], xs[idx] @ Ri.T + ti)
        if unsigned:
            d = np.abs(d)
        better = d < bs[idx]
        bs[idx[better]] = d[better]
        ba[idx[better]] = k
    best[order] = bs
    arg[order] = ba
    return best, arg
