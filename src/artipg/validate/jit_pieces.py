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
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.kernel_cache import drop_stale_caches
from artipg.validate.jit_base import apply, copy4
from artipg.validate.jit_contacts import SDF_CODES, _table_trig
from artipg.validate import jit_base, jit_contacts, shapes
from artipg.validate.shapes import _CODES

drop_stale_caches(__file__, [jit_base.__file__, jit_contacts.__file__, shapes.__file__])

# the template codes of Pieces' flags (constants of the kernel)
_BOX, _FRUSTUM, _RING, _SPHERE, _TORUS = _CODES[Cuboid], _CODES[Frustum], _CODES[Ring], _CODES[Sphere], _CODES[Torus]
_FULL_TURN = 2 * np.pi - 1e-9


def pieces_arrays(table, local, codes):
    """``(link, part, T, center, half, params, kinds, flags, sdf_table)`` of the pieces
    of a primitive table (``local``: its primitives' local boxes (N, 2, 3)) as
    :meth:`Pieces.of` makes them, ``kinds`` and ``flags`` as ``Pieces(kinds=...,
    flags=...)`` take them (``codes``: the templates' codes, ``shapes._CODES``), and
    their :attr:`Pieces.jit_table` (:func:`artipg.validate.jit_contacts.piece_table`;
    None where a template has no compiled SDF)."""
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
    kind_code = np.array([codes.get(t, 0) for t in index], dtype=np.int64)
    sdf_code = np.array([SDF_CODES.get(t, 0) for t in index], dtype=np.int64)
    (link, part, T, center, half, params, kind_of, code, is_box, is_ball, symmetric, piece_sdf, aux, radial) = _arrays(
        order, P, sizes, np.array(ring, dtype=np.bool_), np.array(kind, dtype=np.int64), kind_code, sdf_code, width,
        table.prim_T, table.prim_link, table.prim_part, local)
    sdf_table = (piece_sdf, aux, radial) if sdf_code.all() else None
    return (link, part, T, center, half, params, (list(index), kind_of), (code, is_box, is_ball, symmetric),
            sdf_table)


@numba.njit(cache=True)
def _arrays(order, P, sizes, ring, kind, kind_code, sdf_code, width, prim_T, prim_link, prim_part, local):
    """:func:`_assemble`, then (every template having an SDF code ``sdf_code``) the
    pieces' SDF codes and :func:`artipg.validate.jit_contacts._table_trig` (empty
    tables otherwise)."""
    link, part, T, center, half, params, kind_of, code, is_box, is_ball, symmetric = _assemble(
        order, P, sizes, ring, kind, kind_code, width, prim_T, prim_link, prim_part, local)
    piece_sdf = np.empty(len(kind_of), dtype=np.int64)
    for m in range(len(kind_of)):
        piece_sdf[m] = sdf_code[kind_of[m]]
    if np.all(sdf_code != 0):
        aux, radial = _table_trig(piece_sdf, params)
    else:
        aux, radial = np.zeros((0, 0)), np.zeros((0, 2))
    return link, part, T, center, half, params, kind_of, code, is_box, is_ball, symmetric, piece_sdf, aux, radial


@numba.njit(cache=True)
def _assemble(order, P, sizes, ring, kind, kind_code, width, prim_T, prim_link, prim_part, local):
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
    code, is_box, is_ball, symmetric = _flags(params, kind_of, kind_code)
    return link, part, T, center, half, params, kind_of, code, is_box, is_ball, symmetric


@numba.njit(cache=True)
def _flags(params, kind_of, kind_code):
    """``Pieces._flags``: every piece's template code (``kind_code``: per template) and
    whether it is a box, a whole ball, a full solid of revolution about its z axis."""
    M = len(kind_of)
    code = np.empty(M, dtype=np.int64)
    is_box = np.empty(M, dtype=np.bool_)
    is_ball = np.zeros(M, dtype=np.bool_)
    symmetric = np.empty(M, dtype=np.bool_)
    for m in range(M):
        c = kind_code[kind_of[m]]
        code[m] = c
        is_box[m] = c == _BOX
        sym = c == _FRUSTUM
        if c == _SPHERE:
            is_ball[m] = (params[m, 1] <= -params[m, 0]) and (params[m, 2] >= params[m, 0])
            sym = True
        elif c == _RING:
            sym = params[m, 3] >= _FULL_TURN
        elif c == _TORUS:
            sym = params[m, 2] >= _FULL_TURN
        symmetric[m] = sym
    return code, is_box, is_ball, symmetric
