"""Prisms: convex polygons extruded along z, centred on z = 0 — the regular n-gon prism
and the triangular prism (wedge)."""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.base import TWO_PI, GeometryTemplate, Primitive, polygon_sdf_rows
from artipg.geometry.patches import Patch, cross_norm
from artipg.geometry.transforms import IDENTITY

# Primitive(...) without the NamedTuple's Python-level __new__ (same tuple): the
# constructors below run dozens of times per object
_tuple_new = tuple.__new__

MAX_SIDES = 16
_SIDE_COMP, _END_COMP = np.array([0, 1, 2]), np.array([3, 4])


def _extrusion_sdf(poly: np.ndarray, depth: float, x: np.ndarray) -> np.ndarray:
    xt = np.ascontiguousarray(x.T)
    return np.maximum(polygon_sdf_rows(xt[0], xt[1], poly), np.abs(xt[2]) - depth / 2)


def _extrusion_arrays(poly: np.ndarray, depth: float) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and outward faces of a convex polygon (n, 2) extruded ``depth`` along z,
    centred on z = 0."""
    poly = np.asarray(poly, dtype=float)
    x, y = poly[:, 0], poly[:, 1]
    if np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) < 0:  # make it counter-clockwise
        poly = poly[::-1]
    n = len(poly)
    V = np.concatenate([np.column_stack([poly, np.full(n, -depth / 2)]), np.column_stack([poly, np.full(n, depth / 2)])])
    i = np.arange(1, n - 1)
    k = np.arange(n)
    k1 = (k + 1) % n
    F = np.concatenate([np.stack([np.zeros_like(i), i + 1, i], 1),  # bottom fan, facing -z
                        np.stack([np.full_like(i, n), n + i, n + i + 1], 1),  # top fan
                        np.stack([k, k1, n + k1], 1), np.stack([k, n + k1, n + k], 1)])  # sides
    return V, F.astype(np.int64)


class Prism(GeometryTemplate):
    """Regular ``n``-gon prism: circumradius ``r``, height ``h`` along z, centred; the
    first vertex sits at angle π/n so a square prism is axis-aligned."""

    name = "prism"
    params = ("r", "h", "n")

    @staticmethod
    def polygon(r: float, n: int) -> np.ndarray:
        """Vertices (n, 2) of the cross-section, counter-clockwise."""
        a = np.pi / n + 2 * np.pi * np.arange(n) / n
        return np.stack([r * np.cos(a), r * np.sin(a)], axis=1)

    @classmethod
    def component_areas(cls, P):
        r, h, n = P.T
        cap = 0.5 * n * r * r * np.sin(2 * np.pi / n)
        return np.column_stack([2 * n * r * np.sin(np.pi / n) * h, cap, cap])  # sides, bottom, top

    @classmethod
    def patches(cls, P):
        out = []
        r, h = P[:, 0], P[:, 1]
        M = len(P)
        # rows are grouped by side count: each n-gon gives n side rects and 2n fan triangles
        # (written in place: the values of ``rects``/``tris`` of the columns in the comments)
        for n in np.unique(P[:, 2]).astype(int):
            on = (P[:, 2] == n).astype(float)
            a = (np.pi / n + TWO_PI * np.arange(n) / n)[:, None]
            x0, y0 = r * np.cos(a), r * np.sin(a)
            x1, y1 = r * np.cos(a + TWO_PI / n), r * np.sin(a + TWO_PI / n)
            mid = a + np.pi / n
            dx, dy = x1 - x0, y1 - y0
            # sides: o (x0, y0, -h/2), a (dx, dy, 0), b (0, 0, h), n (cos mid, sin mid, 0)
            side = np.zeros((n, 12, M))
            side[:, 0] = x0
            side[:, 1] = y0
            side[:, 2] = -h / 2
            side[:, 3] = dx
            side[:, 4] = dy
            side[:, 8] = h
            side[:, 9] = np.cos(mid)
            side[:, 10] = np.sin(mid)
            out.append(Patch("rect", np.zeros(n, dtype=np.int64), cross_norm((dx, dy, 0.0), (0.0, 0.0, h)) * on,
                             side))
            # bottom then top fans: o (0, 0, ∓h/2), a (x0, y0, 0), b (x1, y1, 0), n (0, 0, ∓1)
            fan = np.zeros((2, n, 12, M))
            fan[0, :, 2] = -h / 2
            fan[1, :, 2] = h / 2
            fan[:, :, 3] = x0
            fan[:, :, 4] = y0
            fan[:, :, 6] = x1
            fan[:, :, 7] = y1
            fan[0, :, 11] = -1.0
            fan[1, :, 11] = 1.0
            area = 0.5 * cross_norm((x0, y0, 0.0), (x1, y1, 0.0)) * on
            out.append(Patch("tri", np.repeat(np.array([1, 2]), n), np.concatenate([area, area]),
                             fan.reshape(2 * n, 12, M)))
        return out

    @classmethod
    def sdf(cls, p, x):
        return _extrusion_sdf(cls.polygon(p[0], int(p[2])), p[1], x)

    @classmethod
    def bounds(cls, p):
        V = cls.polygon(p[0], int(p[2]))
        return np.array([[*V.min(axis=0), -p[1] / 2], [*V.max(axis=0), p[1] / 2]])

    @classmethod
    def bounds_batch(cls, P):
        r, h, n = P[:, 0], P[:, 1], P[:, 2]
        # vertex angles π/n + 2πk/n: the extremes along ±x, ±y are the vertices nearest
        # to the axis directions, found per row by rounding
        out = np.empty((len(P), 2, 3))
        for k, phi in enumerate((np.pi, 1.5 * np.pi)):
            for j, sgn in ((0, -1.0), (1, 1.0)):
                target = phi if sgn < 0 else phi - np.pi
                step = TWO_PI / n
                i = np.round((target - np.pi / n) / step)
                out[:, j, k] = r * (np.cos if k == 0 else np.sin)(np.pi / n + i * step)
        out[:, 0, 2] = -h / 2
        out[:, 1, 2] = h / 2
        return out

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        return _extrusion_arrays(cls.polygon(p[0], int(p[2])), p[1])

    @classmethod
    def volume(cls, p):
        r, h, n = p
        return float(0.5 * n * r * r * math.sin(2 * math.pi / n) * h)


class TriPrism(GeometryTemplate):
    """Triangular prism (wedge): the triangle (-w/2, 0), (w/2, 0), (a, t) in the x-y
    plane, extruded ``depth`` along z and centred on z = 0."""

    name = "tri_prism"
    params = ("w", "t", "a", "depth")

    @staticmethod
    def polygon(p) -> np.ndarray:
        w, t, a = p[0], p[1], p[2]
        return np.array([[-w / 2, 0.0], [w / 2, 0.0], [a, t]])

    @staticmethod
    def _verts(P):
        w, t, a = P[:, 0], P[:, 1], P[:, 2]
        z = np.zeros_like(w)
        return np.stack([np.column_stack([-w / 2, z]), np.column_stack([w / 2, z]), np.column_stack([a, t])], axis=1)

    @classmethod
    def component_areas(cls, P):
        w, t, a, d = P.T
        l1 = np.hypot(a - w / 2, t)
        l2 = np.hypot(a + w / 2, t)
        return np.column_stack([w * d, l1 * d, l2 * d, w * t / 2, w * t / 2])  # 3 sides, bottom, top

    @classmethod
    def patches(cls, P):
        w, t, a, d = P.T
        M = len(P)
        V = np.empty((3, 2, M))  # the vertices (-w/2, 0), (w/2, 0), (a, t)
        V[0, 0] = -w / 2
        V[1, 0] = w / 2
        V[0:2, 1] = 0.0
        V[2, 0] = a
        V[2, 1] = t
        E = np.empty((3, 2, M))  # the three edges v1 - v0, v2 - v1, v0 - v2
        np.subtract(V[1:], V[:2], out=E[:2])
        np.subtract(V[0], V[2], out=E[2])
        L = np.hypot(E[:, 0], E[:, 1])
        # the values of ``rects((0, 1, 2), (V0, V1, -d/2), (E0, E1, 0), (0, 0, d), (E1/L, -E0/L, 0))``
        side = np.zeros((3, 12, M))
        side[:, 0:2] = V
        side[:, 2] = -d / 2
        side[:, 3:5] = E
        side[:, 8] = d
        np.divide(E[:, 1], L, out=side[:, 9])
        np.divide(-E[:, 0], L, out=side[:, 10])
        sides = Patch("rect", _SIDE_COMP, cross_norm((E[:, 0], E[:, 1], 0.0), (0.0, 0.0, d)), side)
        # and of ``tris((3, 4), (V00, V01, ∓d/2), (E00, E01, 0), (-E20, -E21, 0), (0, 0, ∓1))``
        end = np.zeros((2, 12, M))
        end[:, 0:2] = V[0]
        end[0, 2] = -d / 2
        end[1, 2] = d / 2
        end[:, 3:5] = E[0]
        np.negative(E[2], out=end[0, 6:8])
        end[1, 6:8] = end[0, 6:8]
        end[0, 11] = -1.0
        end[1, 11] = 1.0
        area = 0.5 * cross_norm((E[0, 0], E[0, 1], 0.0), (-E[2, 0], -E[2, 1], 0.0))
        return [sides, Patch("tri", _END_COMP, np.array([area, area]), end)]

    @classmethod
    def sdf(cls, p, x):
        return _extrusion_sdf(cls.polygon(p), p[3], x)

    @classmethod
    def bounds(cls, p):
        V = cls.polygon(p)
        return np.array([[*V.min(axis=0), -p[3] / 2], [*V.max(axis=0), p[3] / 2]])

    @classmethod
    def bounds_batch(cls, P):
        w, t, a, d = P.T
        out = np.empty((len(P), 2, 3))
        np.minimum(-w / 2, a, out=out[:, 0, 0])
        np.minimum(0.0, t, out=out[:, 0, 1])
        out[:, 0, 2] = -d / 2
        np.maximum(w / 2, a, out=out[:, 1, 0])
        np.maximum(0.0, t, out=out[:, 1, 1])
        out[:, 1, 2] = d / 2
        return out

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        return _extrusion_arrays(cls.polygon(p), p[3])

    @classmethod
    def volume(cls, p):
        return float(0.5 * p[0] * p[1] * p[3])


def prism(r: float, h: float, n: int, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Regular ``n``-gon prism (3 <= n <= 16) of circumradius ``r`` and height ``h``."""
    if not 3 <= n <= MAX_SIDES:
        raise ValueError(f"prism needs 3..{MAX_SIDES} sides, got {n}")
    return _tuple_new(Primitive, (Prism, (float(r), float(h), float(n)), pose, role))


def tri_prism(w: float, t: float, a: float, depth: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Triangular prism with base ``w``, height ``t``, apex x-offset ``a``, depth along z."""
    return _tuple_new(Primitive, (TriPrism, (float(w), float(t), float(a), float(depth)), pose, role))
