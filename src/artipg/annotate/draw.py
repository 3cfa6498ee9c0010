"""The compiled point draw: patch cells and uniform numbers in, labelled points out.

:func:`artipg.annotate.points.sample_points` draws three uniforms per point with numpy
and hands them to :func:`draw_kernel`, which picks each point's patch cell by the
inverse CDF of the cell areas, places the point with its family's closed-form sampler
(:func:`artipg.geometry.patches.place_family`), applies the primitive's pose and
gathers its labels, one point at a time (the cells of the planar families are posed
once, and their points placed in the object frame directly). Its arithmetic is that of
the numpy definition (:func:`artipg.annotate.points.draw_plain`), operation for
operation and in the same order, so the points are the same to the bit
(``tests/test_points_fast.py`` compares them).

This module imports numba; import it only where points are drawn (``import artipg``
and generation stay light).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from artipg.annotate import points
from artipg.annotate.points import FAMILY_CODE
from artipg.geometry import patches
from artipg.geometry.patches import TUBE_MAX_STEPS, TUBE_TOL
from artipg.kernel_cache import drop_stale_caches

drop_stale_caches(__file__, [points.__file__, patches.__file__])  # FAMILY_CODE, TUBE_* are compiled in

if list(FAMILY_CODE) != ["rect", "tri", "sector", "band", "zone", "torus"]:
    raise RuntimeError("draw_kernel hard-codes the family codes: update it with FAMILIES")
_TWO_PI = 2.0 * math.pi


@numba.njit(cache=True, nogil=True, error_model="numpy")
def tube_cos_sin(e, M):  # pragma: no cover - compiled
    """Cosine and sine of the tube angle v in [0, 2π] with ``v + e sin v = M``: one
    element of :func:`artipg.geometry.patches.torus_tube_quantiles` (e = r / R, M = 2π u)."""
    a = e / (1.0 - e)
    k = 0.25 * a * a + a / 6.0
    lo = 0.0
    hi = _TWO_PI
    v = M
    for _ in range(TUBE_MAX_STEPS):
        s = math.sin(v)
        c = math.cos(v)
        g = (v + e * s) - M
        if g == 0.0:
            return c, s
        if g < 0.0:
            lo = v
        elif g > 0.0:
            hi = v
        fp = 1.0 + e * c
        den = fp * fp + 0.5 * g * e * s
        halley = den >= 0.5 * fp * fp
        w = v - (g * fp / den if halley else g / fp)
        inside = w >= lo and w <= hi
        if not inside:
            w = 0.5 * (lo + hi)
        d = v - w
        dd = d * d
        if halley and inside and abs(d) * dd * k <= TUBE_TOL:
            cd = 1.0 - dd * (0.5 - dd / 24.0)
            sd = d * (1.0 - dd / 6.0)
            return c * cd + s * sd, s * cd - c * sd
        v = w
    return math.cos(v), math.sin(v)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_kernel(U, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic,
                out, labels):  # pragma: no cover - compiled
    """Labelled points of an object from their uniforms (in place).

    Parameters
    ----------
    U : (3, n) float64
        Uniforms in [0, 1) of the n points: ``U[0]`` picks the cell (the first whose
        cumulative weight exceeds ``U[0]`` times the total), ``U[1]`` and ``U[2]`` are
        the family sampler's u and v.
    weight : (K,) float64
        Cell weights >= 0 (areas, or probabilities), not all zero.
    code : (K,) int64
        Family code of each cell (:data:`FAMILY_CODE`).
    Q : (K, 15) float64
        Family parameters of each cell, primitive-local frame (unused columns ignored).
    W : (N, 3, 4) float64
        Pose of every primitive in the object frame.
    cell_prim, prim_part, prim_link, part_semantic : int64 arrays
        Primitive of each cell; part and link of each primitive; semantic id of each part.
    out : (2, n, 3) float64
        Output positions (metres) and unit normals, object frame.
    labels : (4, n) int64
        Output primitive, part, semantic id and link of each point.
    """
    K = weight.shape[0]
    n = U.shape[1]
    cum = np.empty(K)
    acc = 0.0
    for c in range(K):  # np.cumsum: a running sum
        acc += weight[c]
        cum[c] = acc
    total = cum[K - 1]
    # The cell of x = U[0, j] * total is np.searchsorted(cum, x, side="right"): the first
    # with cum > x (< K, as x < total). It is found by a scan from guide[int(U[0, j] * K)],
    # the first cell with cum > y_b, where y_b = b total / K shrunk by 2^-40 stays below
    # every x of bucket b despite rounding: so the scan starts at or before the answer,
    # and is about one step long.
    guide = np.empty(K, np.int64)
    scale = total / K * (1.0 - 2.0 ** -40)
    c = 0
    for b in range(K):
        y = b * scale
        while cum[c] <= y:
            c += 1
        guide[b] = c
    # per cell: its labels, and for the planar families (affine in o, a, b) its
    # parameters posed in the object frame, so that their points need no transform
    lab = np.empty((K, 4), np.int64)
    P = np.empty((K, 15))
    for c in range(K):
        p = cell_prim[c]
        part = prim_part[p]
        lab[c, 0] = p
        lab[c, 1] = part
        lab[c, 2] = part_semantic[part]
        lab[c, 3] = prim_link[p]
        if code[c] <= 2:
            q = Q[c]
            w = W[p]
            for a in range(3):
                P[c, a] = ((w[a, 0] * q[0] + w[a, 1] * q[1]) + w[a, 2] * q[2]) + w[a, 3]
                for r in range(3, 12, 3):
                    P[c, r + a] = (w[a, 0] * q[r] + w[a, 1] * q[r + 1]) + w[a, 2] * q[r + 2]
            P[c, 12] = q[12]
            P[c, 13] = q[13]
            P[c, 14] = q[14]
    for j in range(n):
        x = U[0, j] * total
        c = guide[int(U[0, j] * K)]
        while cum[c] <= x:
            c += 1
        for a in range(4):
            labels[a, j] = lab[c, a]
        f = code[c]
        u = U[1, j]
        v = U[2, j]
        if f <= 2:  # rect, tri, sector: o + u a + v b, posed
            q = P[c]
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
            for a in range(3):
                out[0, j, a] = q[a] + u * q[3 + a] + v * q[6 + a]
                out[1, j, a] = q[9 + a]
            continue
        q = Q[c]
        if f == 3:  # band
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
            th = v * _TWO_PI
            x = math.cos(th) * rho
            y = math.sin(th) * rho
            nx, ny, nz = x / R, y / R, z / R
        else:  # torus: the tube angle by its inverse CDF, then the arc angle
            R = q[0]
            r = q[1]
            cv, sv = tube_cos_sin(r / R, u * _TWO_PI)
            th = v * q[2]
            ct = math.cos(th)
            st = math.sin(th)
            rho = R + r * cv
            x = rho * ct
            y = rho * st
            z = r * sv
            nx, ny, nz = cv * ct, cv * st, sv
        w = W[lab[c, 0]]
        for a in range(3):
            out[0, j, a] = ((w[a, 0] * x + w[a, 1] * y) + w[a, 2] * z) + w[a, 3]
            out[1, j, a] = (w[a, 0] * nx + w[a, 1] * ny) + w[a, 2] * nz
