"""Prisms: convex polygons extruded along z, centred on z = 0 — the regular n-gon prism
and the triangular prism (wedge)."""

from __future__ import annotations

import math

import numpy as np
import trimesh
from shapely.geometry import Polygon

from artipg.geometry.base import GeometryTemplate, Primitive, polygon_sdf
from artipg.geometry.transforms import IDENTITY

MAX_SIDES = 16


def _fan_point(V0, A1, A2, rng):
    """Uniform points in triangles V0 + u*A1 + v*A2 (all (k, 2))."""
    u, v = rng.random((2, len(V0)))
    flip = u + v > 1.0
    u = np.where(flip, 1.0 - u, u)
    v = np.where(flip, 1.0 - v, v)
    return V0 + u[:, None] * A1 + v[:, None] * A2


def _extrusion_sdf(poly: np.ndarray, depth: float, x: np.ndarray) -> np.ndarray:
    return np.maximum(polygon_sdf(x[:, :2], poly), np.abs(x[:, 2]) - depth / 2)


def _extrusion_mesh(poly: np.ndarray, depth: float) -> trimesh.Trimesh:
    m = trimesh.creation.extrude_polygon(Polygon(poly), depth)
    m.apply_translation((0.0, 0.0, -depth / 2))
    return m


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
    def sample_components(cls, P, comp, rng):
        r, h, n = P.T
        k = len(P)
        j = np.floor(rng.random(k) * n)  # side / fan triangle index: all equal in area
        a0 = np.pi / n + 2 * np.pi * j / n
        a1 = a0 + 2 * np.pi / n
        v0 = np.column_stack([r * np.cos(a0), r * np.sin(a0)])
        v1 = np.column_stack([r * np.cos(a1), r * np.sin(a1)])
        pts = np.empty((k, 3))
        nrm = np.zeros((k, 3))
        side = comp == 0
        t = rng.random(k)[:, None]
        pts[:, :2] = np.where(side[:, None], v0 + t * (v1 - v0), _fan_point(np.zeros((k, 2)), v0, v1, rng))
        pts[:, 2] = np.where(side, (rng.random(k) - 0.5) * h, np.where(comp == 2, 0.5, -0.5) * h)
        mid = (a0 + a1) / 2
        nrm[:, 0] = np.where(side, np.cos(mid), 0.0)
        nrm[:, 1] = np.where(side, np.sin(mid), 0.0)
        nrm[:, 2] = np.where(side, 0.0, np.where(comp == 2, 1.0, -1.0))
        return pts, nrm

    @classmethod
    def sdf(cls, p, x):
        return _extrusion_sdf(cls.polygon(p[0], int(p[2])), p[1], x)

    @classmethod
    def bounds(cls, p):
        V = cls.polygon(p[0], int(p[2]))
        return np.array([[*V.min(axis=0), -p[1] / 2], [*V.max(axis=0), p[1] / 2]])

    @classmethod
    def mesh(cls, p, sections=32):
        return _extrusion_mesh(cls.polygon(p[0], int(p[2])), p[1])

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
    def sample_components(cls, P, comp, rng):
        V = cls._verts(P)
        d = P[:, 3]
        k = len(P)
        rows = np.arange(k)
        e = np.minimum(comp, 2)
        A = V[rows, e]
        E = V[rows, (e + 1) % 3] - A
        side = comp < 3
        t = rng.random(k)[:, None]
        tri = _fan_point(V[:, 0], V[:, 1] - V[:, 0], V[:, 2] - V[:, 0], rng)
        pts = np.empty((k, 3))
        pts[:, :2] = np.where(side[:, None], A + t * E, tri)
        pts[:, 2] = np.where(side, (rng.random(k) - 0.5) * d, np.where(comp == 4, 0.5, -0.5) * d)
        L = np.hypot(E[:, 0], E[:, 1])
        nrm = np.zeros((k, 3))
        nrm[:, 0] = np.where(side, E[:, 1] / L, 0.0)
        nrm[:, 1] = np.where(side, -E[:, 0] / L, 0.0)
        nrm[:, 2] = np.where(side, 0.0, np.where(comp == 4, 1.0, -1.0))
        return pts, nrm

    @classmethod
    def sdf(cls, p, x):
        return _extrusion_sdf(cls.polygon(p), p[3], x)

    @classmethod
    def bounds(cls, p):
        V = cls.polygon(p)
        return np.array([[*V.min(axis=0), -p[3] / 2], [*V.max(axis=0), p[3] / 2]])

    @classmethod
    def mesh(cls, p, sections=32):
        return _extrusion_mesh(cls.polygon(p), p[3])

    @classmethod
    def volume(cls, p):
        return float(0.5 * p[0] * p[1] * p[3])


def prism(r: float, h: float, n: int, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Regular ``n``-gon prism (3 <= n <= 16) of circumradius ``r`` and height ``h``."""
    if not 3 <= n <= MAX_SIDES:
        raise ValueError(f"prism needs 3..{MAX_SIDES} sides, got {n}")
    return Primitive(Prism, (float(r), float(h), float(n)), pose, role)


def tri_prism(w: float, t: float, a: float, depth: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Triangular prism with base ``w``, height ``t``, apex x-offset ``a``, depth along z."""
    return Primitive(TriPrism, (float(w), float(t), float(a), float(depth)), pose, role)
