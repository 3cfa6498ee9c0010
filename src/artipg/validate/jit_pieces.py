"""The arrays of :meth:`artipg.validate.shapes.Pieces.of` in one compiled pass.

The primitives of each geometry template in turn (the primitive table's groups), a
rectangular ring as its four boxes: frames, links, parts, zero-padded parameters and
local boxes (centre, half extents), bit for bit those of the numpy code
(``tests/test_validate_fast.py``); the ring's box frames need
:func:`artipg.validate.jit_base.kernels_match` (an einsum's order).

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import numba
import numpy as np

from artipg.geometry.box import Cuboid, RectRing
from artipg.kernel_cache import drop_stale_caches
from artipg.validate.jit_base import apply, copy4
from artipg.validate import jit_base

drop_stale_caches(__file__, [jit_base.__file__])


def pieces_arrays(table, local):
    """``(link, part, T, center, half, params, kinds)`` of the pieces of a primitive
    table (``local``: its primitives' local boxes (N, 2, 3)) as :meth:`Pieces.of`
    makes them, ``kinds`` as ``Pieces(kinds=...)`` takes them."""
    groups = table.groups
    index: dict = {}
    kind, ring, width = [], [], 0
    for g in groups:
        is_ring = g.geom is RectRing
        kind.append(index.setdefault(Cuboid if is_ring else g.geom, len(index)))
        ring.append(is_ring)
        width = max(width, 3 if is_ring else g.P.shape[1])
    if len(groups) == 1:
        order, P = groups[0].prim, groups[0].P
    else:
        order = np.concatenate([g.prim for g in groups])
        P = np.zeros((len(order), max(g.P.shape[1] for g in groups)))
        k = 0
        for g in groups:
            P[k:k + len(g.P), :g.P.shape[1]] = g.P
            k += len(g.P)
    sizes = np.array([len(g.P) for g in groups], dtype=np.int64)
    link, part, T, center, half, params, kind_of = _assemble(
        order, P, sizes, np.array(ring, dtype=np.bool_), np.array(kind, dtype=np.int64), width, table.prim_T,
        table.prim_link, table.prim_part, local)
    return link, part, T, center, half, params, (list(index), kind_of)


@numba.njit(cache=True)
def _assemble(order, P, sizes, ring, kind, width, prim_T, prim_link, prim_part, local):
    N = len(order)
    M = 0
    g = 0
    k = 0
    for i in range(N):
        while k == sizes[g]:
            g += 1
            k = 0
        M += 4 if ring[g] else 1
        k += 1
    link = np.empty(M, dtype=np.int64)
    part = np.empty(M, dtype=np.int64)
    T = np.empty((M, 4, 4))
    center = np.empty((M, 3))
    half = np.empty((M, 3))
    params = np.zeros((M, width))
    kind_of = np.empty(M, dtype=np.int64)
    m = 0
    g = 0
    k = 0
    size = np.empty((4, 3))
    off = np.zeros((4, 3))
    for i in range(N):
        while k == sizes[g]:
            g += 1
            k = 0
        k += 1
        p = order[i]
        if not ring[g]:
            link[m], part[m], kind_of[m] = prim_link[p], prim_part[p], kind[g]
            copy4(prim_T[p], T[m])
            for c in range(min(P.shape[1], width)):  # beyond the group's own width: zeros
                params[m, c] = P[i, c]
            for c in range(3):
                center[m, c] = 0.5 * (local[p, 0, c] + local[p, 1, c])
                half[m, c] = 0.5 * (local[p, 1, c] - local[p, 0, c])
            m += 1
            continue
        # shapes._rect_ring_boxes: the four boxes of the frame and their offsets
        ox, oy, d, ix, iy = P[i, 0], P[i, 1], P[i, 2], P[i, 3], P[i, 4]
        bx, by = (ox - ix) / 2, (oy - iy) / 2
        size[0, 0], size[0, 1], size[1, 0], size[1, 1] = ox, by, ox, by
        size[2, 0], size[2, 1], size[3, 0], size[3, 1] = bx, iy, bx, iy
        for b in range(4):
            size[b, 2] = d
        off[0, 1], off[1, 1] = (iy + by) / 2, -(iy + by) / 2
        off[2, 0], off[3, 0] = (ix + bx) / 2, -(ix + bx) / 2
        for b in range(4):
            link[m], part[m], kind_of[m] = prim_link[p], prim_part[p], kind[g]
            copy4(prim_T[p], T[m])
            for r in range(3):
                T[m, r, 3] += apply(prim_T[p], off[b, 0], off[b, 1], off[b, 2], r)
            for c in range(3):
                params[m, c] = size[b, c]
                hi = size[b, c] * 0.5  # Cuboid.bounds_batch
                lo = -hi
                center[m, c] = 0.5 * (lo + hi)
                half[m, c] = 0.5 * (hi - lo)
            m += 1
    return link, part, T, center, half, params, kind_of
