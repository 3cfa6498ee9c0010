"""The compiled point draw: patch cells and uniform numbers in, labelled points out.

:func:`artipg.annotate.points.sample_points` draws the random numbers with numpy (the
multinomial cell counts, two uniforms per point, the torus tube angles, the shuffle)
and hands them to :func:`draw_kernel`, which evaluates every family's closed-form
sampler (:mod:`artipg.geometry.patches`), applies each point's primitive pose and
gathers its labels in one pass. Its arithmetic is that of the numpy samplers,
operation for operation and in the same order, so the points are the same to the bit
(``tests/test_points_fast.py`` compares them with a plain numpy draw).

This module imports numba; import it only where points are drawn (``import artipg``
and generation stay light).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from artipg.annotate import points
from artipg.annotate.points import FAMILY_CODE
from artipg.kernel_cache import drop_stale_caches

drop_stale_caches(__file__, [points.__file__])  # FAMILY_CODE is compiled in

_TORUS = FAMILY_CODE["torus"]
if _TORUS != len(FAMILY_CODE) - 1:
    raise RuntimeError("the torus family must be the last in FAMILIES: its draws follow the others'")


@numba.njit(cache=True, nogil=True)
def draw_kernel(counts, code, Q, U, torus_local, perm, W, cell_prim, prim_part, prim_link, part_semantic,
                pts, nrm, prim_out, part_out, semantic_out, link_out):  # pragma: no cover - compiled
    """Labelled points of an object from its drawn random numbers (in place).

    Parameters
    ----------
    counts : (K,) int64
        Points per patch cell (the multinomial draw), cells in family order.
    code : (K,) int64
        Family code of each cell (:data:`FAMILY_CODE`).
    Q : (K, 15) float64
        Family parameters of each cell, primitive-local frame (unused columns ignored).
    U : (2 * m,) float64
        The uniforms of the m points of the non-torus families: a family whose points
        are ``s .. s + k - 1`` (in cell order) reads its ``u`` from ``U[2s : 2s + k]``
        and its ``v`` from ``U[2s + k : 2s + 2k]``, as ``rng.random((2, k))`` gives them.
    torus_local : (6, t) float64
        Local points and normals of the t torus points (the last ones in cell order).
    perm : (n,) int64
        Output position j holds the point ``perm[j]`` of the cell order.
    W : (N, 3, 4) float64
        Pose of every primitive in the object frame.
    cell_prim, prim_part, prim_link, part_semantic : int64 arrays
        Primitive of each cell; part and link of each primitive; semantic id of each part.
    pts, nrm : (n, 3) float64
        Output positions (metres) and unit normals, object frame.
    prim_out, part_out, semantic_out, link_out : (n,) int64
        Output labels.
    """
    K = counts.shape[0]
    n = perm.shape[0]
    cell = np.empty(n, np.int64)
    first = np.empty(n, np.int64)  # first point (cell order) of the point's family
    size = np.empty(n, np.int64)   # number of points of the point's family
    i = 0
    c = 0
    while c < K:
        f = code[c]
        start = i
        e = c
        while e < K and code[e] == f:
            for _ in range(counts[e]):
                cell[i] = e
                i += 1
            e += 1
        for t in range(start, i):
            first[t] = start
            size[t] = i - start
        c = e
    two_pi = 2.0 * math.pi
    for j in range(n):
        i = perm[j]
        c = cell[i]
        f = code[c]
        q = Q[c]
        r = i - first[i]
        u = 0.0
        v = 0.0
        if f != _TORUS:
            u = U[2 * first[i] + r]
            v = U[2 * first[i] + size[i] + r]
        if f <= 2:  # rect, tri, sector: o + u a + v b
            if f == 1 and u + v > 1.0:  # the far half of the unit square folds onto the triangle
                u = 1.0 - u
                v = 1.0 - v
            elif f == 2:  # polar (rho, phi) -> (u, v) in the sector's plane
                r0 = q[12]
                r1 = q[13]
                rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
                phi = v * q[14]
                u = math.cos(phi) * rho
                v = math.sin(phi) * rho
            x = q[0] + u * q[3] + v * q[6]
            y = q[1] + u * q[4] + v * q[7]
            z = q[2] + u * q[5] + v * q[8]
            nx, ny, nz = q[9], q[10], q[11]
        elif f == 3:  # band
            r0 = q[0]
            r1 = q[1]
            rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
            s = u * (r0 + r1) / (rho + r0 + 1e-300)
            th = v * q[4]
            ct = math.cos(th)
            st = math.sin(th)
            x = rho * ct
            y = rho * st
            z = q[2] + s * (q[3] - q[2])
            nx, ny, nz = ct * q[5], st * q[5], q[6]
        elif f == 4:  # zone
            R = q[0]
            z = u * (q[2] - q[1]) + q[1]
            rho = math.sqrt(max(R * R - z * z, 0.0))
            th = v * two_pi
            x = math.cos(th) * rho
            y = math.sin(th) * rho
            nx, ny, nz = x / R, y / R, z / R
        else:  # torus: sampled by numpy (rejection), copied
            t = i - first[i]
            x, y, z = torus_local[0, t], torus_local[1, t], torus_local[2, t]
            nx, ny, nz = torus_local[3, t], torus_local[4, t], torus_local[5, t]
        p = cell_prim[c]
        w = W[p]
        for a in range(3):
            pts[j, a] = ((w[a, 0] * x + w[a, 1] * y) + w[a, 2] * z) + w[a, 3]
            nrm[j, a] = (w[a, 0] * nx + w[a, 1] * ny) + w[a, 2] * nz
        prim_out[j] = p
        part = prim_part[p]
        part_out[j] = part
        semantic_out[j] = part_semantic[part]
        link_out[j] = prim_link[p]
