"""Signed distances of geometry templates, vectorised over rows of parameters.

``ROW_SDF[geom](P, x)`` evaluates row ``k`` of ``x`` (K, 3) against the solid with
parameters ``P[k]`` (K, p), in one numpy pass for any mix of sizes. The formulas are
the templates' own (:mod:`artipg.geometry`), batched; ``tests/test_validate.py``
checks that both agree. Metres, local frames, negative inside.

``PREPARE[geom](P)`` returns ``f(x)`` with ``f(x) == ROW_SDF[geom](P, x)`` (the very
same arithmetic): everything that depends on the parameters only (polygon edges,
wedge planes) is computed once, so that evaluating the same rows at many points in
turn (the projections of :func:`artipg.validate.contacts.refine_distance`) costs only
the point-dependent operations.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.base import TWO_PI
from artipg.geometry.box import Cuboid
from artipg.geometry.prism import MAX_SIDES, Prism, TriPrism
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus


#: ``np.roll(np.arange(V), -1)`` for small V: the next vertex of each polygon vertex.
_NEXT = [np.roll(np.arange(v), -1) for v in range(17)]


def _cols(x):
    """Components (3 contiguous arrays (K,)) of points (K, 3)."""
    c = np.ascontiguousarray(np.asarray(x, dtype=float).T)
    return c[0], c[1], c[2]


def cuboid_rows(P: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Boxes of extents ``P[:, :3]`` centred at the origin."""
    return prepare_cuboid(P)(x)


def prepare_cuboid(P: np.ndarray):
    S = np.ascontiguousarray(P[:, :3].T) * 0.5

    def f(x):
        X, Y, Z = _cols(x)
        qx, qy, qz = np.abs(X) - S[0], np.abs(Y) - S[1], np.abs(Z) - S[2]
        ox, oy, oz = np.maximum(qx, 0.0), np.maximum(qy, 0.0), np.maximum(qz, 0.0)
        return np.sqrt(ox * ox + oy * oy + oz * oz) + np.minimum(np.maximum(np.maximum(qx, qy), qz), 0.0)

    return f


def prepare_polygon(px, py):
    """``f(qx, qy)``: signed distance of 2-D points (``qx``, ``qy``: (K,)) to one polygon
    per point with vertex coordinates ``px``, ``py`` (V, K) (see :func:`polygon_rows`)."""
    nxt = _NEXT[len(px)] if len(px) < len(_NEXT) else np.roll(np.arange(len(px)), -1)
    bx, by = px[nxt], py[nxt]  # the next vertex of each (np.roll(p, -1, axis=0))
    ex, ey = bx - px, by - py
    ee = np.maximum(ex * ex + ey * ey, 1e-30)
    ey_safe = np.where(np.abs(ey) > 1e-30, ey, 1e-30)

    def f(qx, qy):
        wx, wy = qx - px, qy - py
        t = np.minimum(np.maximum((wx * ex + wy * ey) / ee, 0.0), 1.0)  # np.clip without its wrapper
        dx, dy = wx - t * ex, wy - t * ey
        dist = np.sqrt(np.minimum.reduce(dx * dx + dy * dy, axis=0))
        above = py > qy
        cond = above != above[nxt]  # (py > qy) != (by > qy)
        xint = px + (qy - py) * ex / ey_safe
        inside = np.add.reduce(cond & (qx < xint), axis=0, dtype=np.int64) % 2 == 1
        return np.where(inside, -dist, dist)

    return f


def polygon_rows(qx, qy, px, py) -> np.ndarray:
    """Signed distance of 2-D points (``qx``, ``qy``: (K,)) to one polygon per point
    with vertex coordinates ``px``, ``py`` (V, K), counter-clockwise or not.

    Polygons with fewer vertices repeat their last vertex (zero-length edges are
    harmless). Negative inside (even-odd rule).
    """
    return prepare_polygon(px, py)(qx, qy)


def prepare_wedge(arc: np.ndarray):
    """``f(X, Y)``: row-wise :func:`artipg.geometry.base.wedge_sdf` for arcs (K,) radians."""
    ns, c = -np.sin(arc), np.cos(arc)
    small = arc <= np.pi
    full = arc >= TWO_PI - 1e-9

    def f(X, Y):
        d0 = -Y
        d1 = ns * X + c * Y
        out = np.where(small, np.maximum(d0, d1), np.minimum(d0, d1))
        return np.where(full, -np.inf, out)

    return f


def wedge_rows(X, Y, arc: np.ndarray) -> np.ndarray:
    """Row-wise :func:`artipg.geometry.base.wedge_sdf` (point components, arc (K,) radians)."""
    return prepare_wedge(arc)(X, Y)


def _prepare_profile(r_lo_bot, r_hi_bot, r_hi_top, r_lo_top, h):
    """(ρ, z) quadrilateral profiles [(r_lo_bot, -h/2), (r_hi_bot, -h/2), (r_hi_top, h/2),
    (r_lo_top, h/2)] of solids of revolution: ``f(x)`` -> profile SDF, X, Y."""
    zb, zt = -h / 2, h / 2
    poly = prepare_polygon(np.array([r_lo_bot, r_hi_bot, r_hi_top, r_lo_top]), np.array([zb, zb, zt, zt]))

    def f(x):
        X, Y, Z = _cols(x)
        return poly(np.hypot(X, Y), Z), X, Y

    return f


def prepare_frustum(P):
    r0, r1, h = P[:, 0], P[:, 1], P[:, 2]
    prof = _prepare_profile(-r0, r0, r1, -r1, h)
    return lambda x: prof(x)[0]


def prepare_ring(P):
    ro, ri, h, arc, tp = P[:, 0], P[:, 1], P[:, 2], P[:, 3], P[:, 4]
    prof = _prepare_profile(ri, ro, ro + tp, ri + tp, h)
    wedge = prepare_wedge(arc)

    def f(x):
        d, X, Y = prof(x)
        return np.maximum(d, wedge(X, Y))

    return f


def prepare_quad_profiles(P_frustum, P_ring):
    """One evaluator for frusta (rows ``P_frustum`` (F, 3+)) followed by rings (rows
    ``P_ring`` (R, 5)): ``f(x)`` (F + R,) equals :func:`prepare_frustum` on the first F
    points and :func:`prepare_ring` on the others, with one polygon pass for both
    (a frustum is a quadrilateral (ρ, z) profile turned a full turn)."""
    r0, r1, hf = P_frustum[:, 0], P_frustum[:, 1], P_frustum[:, 2]
    ro, ri, hr, arc, tp = P_ring[:, 0], P_ring[:, 1], P_ring[:, 2], P_ring[:, 3], P_ring[:, 4]
    nf = len(r0)
    prof = _prepare_profile(np.concatenate([-r0, ri]), np.concatenate([r0, ro]), np.concatenate([r1, ro + tp]),
                            np.concatenate([-r1, ri + tp]), np.concatenate([hf, hr]))
    wedge = prepare_wedge(arc)

    def f(x):
        d, X, Y = prof(x)
        d[nf:] = np.maximum(d[nf:], wedge(X[nf:], Y[nf:]))
        return d

    return f


def prepare_sphere(P):
    R, lo, hi = P[:, 0], P[:, 1], P[:, 2]

    def f(x):
        X, Y, Z = _cols(x)
        return np.maximum(np.maximum(np.sqrt(X * X + Y * Y + Z * Z) - R, lo - Z), Z - hi)

    return f


def prepare_torus(P):
    R, r, arc = P[:, 0], P[:, 1], P[:, 2]
    wedge = prepare_wedge(arc)

    def f(x):
        X, Y, Z = _cols(x)
        return np.maximum(np.hypot(np.hypot(X, Y) - R, Z) - r, wedge(X, Y))

    return f


def prepare_prism(P):
    r, h, n = P[:, 0], P[:, 1], P[:, 2]
    k = np.minimum(np.arange(MAX_SIDES)[:, None], n[None, :] - 1)  # pad with the last vertex
    a = np.pi / n + 2 * np.pi * k / n
    poly = prepare_polygon(r * np.cos(a), r * np.sin(a))

    def f(x):
        X, Y, Z = _cols(x)
        return np.maximum(poly(X, Y), np.abs(Z) - h / 2)

    return f


def prepare_tri_prism(P):
    w, t, a, d = P[:, 0], P[:, 1], P[:, 2], P[:, 3]
    z = np.zeros_like(w)
    poly = prepare_polygon(np.array([-w / 2, w / 2, a]), np.array([z, z, t]))

    def f(x):
        X, Y, Z = _cols(x)
        return np.maximum(poly(X, Y), np.abs(Z) - d / 2)

    return f


#: Geometry template -> ``prepare(P (K, p)) -> f(x (K, 3)) -> (K,)``.
PREPARE = {Cuboid: prepare_cuboid, Frustum: prepare_frustum, Ring: prepare_ring, Sphere: prepare_sphere,
           Torus: prepare_torus, Prism: prepare_prism, TriPrism: prepare_tri_prism}


#: Geometry template -> row-wise signed distance ``f(P (K, p), x (K, 3)) -> (K,)``.
ROW_SDF = {geom: (lambda P, x, prepare=prepare: prepare(P)(x)) for geom, prepare in PREPARE.items()}
