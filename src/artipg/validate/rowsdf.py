"""Signed distances of geometry templates, vectorised over rows of parameters.

``ROW_SDF[geom](P, x)`` evaluates row ``k`` of ``x`` (K, 3) against the solid with
parameters ``P[k]`` (K, p), in one numpy pass for any mix of sizes. The formulas are
the templates' own (:mod:`artipg.geometry`), batched; ``tests/test_validate.py``
checks that both agree. Metres, local frames, negative inside.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.base import TWO_PI
from artipg.geometry.box import Cuboid
from artipg.geometry.prism import MAX_SIDES, Prism, TriPrism
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus


def _cols(x):
    """Components (3 contiguous arrays (K,)) of points (K, 3)."""
    c = np.ascontiguousarray(np.asarray(x, dtype=float).T)
    return c[0], c[1], c[2]


def cuboid_rows(P: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Boxes of extents ``P[:, :3]`` centred at the origin."""
    X, Y, Z = _cols(x)
    S = np.ascontiguousarray(P[:, :3].T) * 0.5
    qx, qy, qz = np.abs(X) - S[0], np.abs(Y) - S[1], np.abs(Z) - S[2]
    ox, oy, oz = np.maximum(qx, 0.0), np.maximum(qy, 0.0), np.maximum(qz, 0.0)
    return np.sqrt(ox * ox + oy * oy + oz * oz) + np.minimum(np.maximum(np.maximum(qx, qy), qz), 0.0)


def polygon_rows(qx, qy, px, py) -> np.ndarray:
    """Signed distance of 2-D points (``qx``, ``qy``: (K,)) to one polygon per point
    with vertex coordinates ``px``, ``py`` (V, K), counter-clockwise or not.

    Polygons with fewer vertices repeat their last vertex (zero-length edges are
    harmless). Negative inside (even-odd rule).
    """
    bx, by = np.roll(px, -1, axis=0), np.roll(py, -1, axis=0)
    ex, ey = bx - px, by - py
    wx, wy = qx - px, qy - py
    ee = np.maximum(ex * ex + ey * ey, 1e-30)
    t = np.clip((wx * ex + wy * ey) / ee, 0.0, 1.0)
    dx, dy = wx - t * ex, wy - t * ey
    dist = np.sqrt(np.min(dx * dx + dy * dy, axis=0))
    cond = (py > qy) != (by > qy)
    xint = px + (qy - py) * ex / np.where(np.abs(ey) > 1e-30, ey, 1e-30)
    inside = np.count_nonzero(cond & (qx < xint), axis=0) % 2 == 1
    return np.where(inside, -dist, dist)


def wedge_rows(X, Y, arc: np.ndarray) -> np.ndarray:
    """Row-wise :func:`artipg.geometry.base.wedge_sdf` (point components, arc (K,) radians)."""
    d0 = -Y
    d1 = -np.sin(arc) * X + np.cos(arc) * Y
    out = np.where(arc <= np.pi, np.maximum(d0, d1), np.minimum(d0, d1))
    return np.where(arc >= TWO_PI - 1e-9, -np.inf, out)


def _profile_rows(x, r_lo_bot, r_hi_bot, r_hi_top, r_lo_top, h):
    """(ρ, z) quadrilateral profiles [(r_lo_bot, -h/2), (r_hi_bot, -h/2), (r_hi_top, h/2),
    (r_lo_top, h/2)] of solids of revolution; returns the profile SDF and X, Y."""
    X, Y, Z = _cols(x)
    rho = np.hypot(X, Y)
    px = np.stack([r_lo_bot, r_hi_bot, r_hi_top, r_lo_top])
    py = np.stack([-h / 2, -h / 2, h / 2, h / 2])
    return polygon_rows(rho, Z, px, py), X, Y


def frustum_rows(P, x):
    r0, r1, h = P[:, 0], P[:, 1], P[:, 2]
    return _profile_rows(x, -r0, r0, r1, -r1, h)[0]


def ring_rows(P, x):
    ro, ri, h, arc, tp = P[:, 0], P[:, 1], P[:, 2], P[:, 3], P[:, 4]
    d, X, Y = _profile_rows(x, ri, ro, ro + tp, ri + tp, h)
    return np.maximum(d, wedge_rows(X, Y, arc))


def sphere_rows(P, x):
    X, Y, Z = _cols(x)
    R, lo, hi = P[:, 0], P[:, 1], P[:, 2]
    return np.maximum(np.maximum(np.sqrt(X * X + Y * Y + Z * Z) - R, lo - Z), Z - hi)


def torus_rows(P, x):
    X, Y, Z = _cols(x)
    R, r, arc = P[:, 0], P[:, 1], P[:, 2]
    return np.maximum(np.hypot(np.hypot(X, Y) - R, Z) - r, wedge_rows(X, Y, arc))


def prism_rows(P, x):
    X, Y, Z = _cols(x)
    r, h, n = P[:, 0], P[:, 1], P[:, 2]
    k = np.minimum(np.arange(MAX_SIDES)[:, None], n[None, :] - 1)  # pad with the last vertex
    a = np.pi / n + 2 * np.pi * k / n
    return np.maximum(polygon_rows(X, Y, r * np.cos(a), r * np.sin(a)), np.abs(Z) - h / 2)


def tri_prism_rows(P, x):
    X, Y, Z = _cols(x)
    w, t, a, d = P[:, 0], P[:, 1], P[:, 2], P[:, 3]
    z = np.zeros_like(w)
    return np.maximum(polygon_rows(X, Y, np.stack([-w / 2, w / 2, a]), np.stack([z, z, t])), np.abs(Z) - d / 2)


#: Geometry template -> row-wise signed distance ``f(P (K, p), x (K, 3)) -> (K,)``.
ROW_SDF = {Cuboid: cuboid_rows, Frustum: frustum_rows, Ring: ring_rows, Sphere: sphere_rows, Torus: torus_rows,
           Prism: prism_rows, TriPrism: tri_prism_rows}
