"""The swept-tube family: a circle of radius r swept along a planar path of lines and
arcs in the local x-z plane, closed by flat discs (the one-primitive form of
:mod:`artipg.geometry.tube`, which splits a tube into frustum and torus primitives).

``Sweep("LAL")`` is the family of paths with that sequence of (L)ine and (A)rc
segments. A row holds ``r``, ``heading`` (the start direction (cos α, 0, sin α)), then
two numbers per segment: ``(length, 0)`` for a line, ``(radius, turn)`` for an arc
(:func:`artipg.geometry.tube.arc`'s convention). Lines are cylinders (a revolved
straight segment), arcs are torus arcs (two revolved half circles), so the tube is
sampled exactly through ``revolved`` cells; the end discs are sector cells. The mesh
is :class:`artipg.geometry.tube.Tube`'s loft.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.base import TWO_PI, Primitive, wedge_sdf
from artipg.geometry.family import Family
from artipg.geometry.patches import sectors
from artipg.geometry.revolved import cells
from artipg.geometry.transforms import IDENTITY
from artipg.geometry.tube import Tube

_Y = np.array([0.0, 1.0, 0.0])


class Sweep(Family):
    """Tubes along paths of ``key`` segment kinds ("L" line, "A" arc)."""

    kind = "sweep"

    def param_names(self):
        return ("r", "heading") + tuple(f"{c}{i}" for i in range(len(self.key)) for c in ("a", "b"))

    def n_components(self):
        return len(self.key) + 2  # one per segment, then the start and end discs

    def pieces(self, P):
        """Per segment (kind, o, e1, e3, start length (M,), length (M,), R, arc): the
        frames of each piece for rows ``P``, each vector (3, M); then the end point and
        heading (M,). Lines: o the start, e3 the heading; arcs: o the bend centre, e1
        towards the start, e2 = e3 x e1 the start heading."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        M = len(P)
        x, z, a = np.zeros(M), np.zeros(M), P[:, 1].copy()
        s = np.zeros(M)
        out = []
        for i, kind in enumerate(self.key):
            A, B = P[:, 2 + 2 * i], P[:, 3 + 2 * i]
            ca, sa = np.cos(a), np.sin(a)
            zero = np.zeros(M)
            if kind == "L":
                out.append(("L", np.stack([x, zero, z]), np.tile(_Y[:, None], M), np.stack([ca, zero, sa]),
                            s.copy(), A, zero, zero))
                x, z, s = x + ca * A, z + sa * A, s + A
            else:
                sg = np.where(B > 0, 1.0, -1.0)
                cx, cz = x - sa * A * sg, z + ca * A * sg
                e1 = np.stack([(x - cx) / A, zero, (z - cz) / A])
                e2 = np.stack([ca, zero, sa])
                e3 = np.cross(e1, e2, axis=0)
                out.append(("A", np.stack([cx, zero, cz]), e1, e3, s.copy(), A * np.abs(B), A, np.abs(B)))
                a = a + B
                x, z = cx + np.sin(a) * A * sg, cz - np.cos(a) * A * sg
                s = s + A * np.abs(B)
        return out, np.stack([x, np.zeros(M), z]), a

    def _patches(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        r = P[:, 0]
        pieces, end, a_end = self.pieces(P)
        out = []
        for i, (kind, o, e1, e3, s0, L, R, arc) in enumerate(pieces):
            if kind == "L":
                out.append(cells([i], tuple(o), tuple(e1), tuple(e3), r, 0.0, r, L, 0.0, TWO_PI))
            else:  # the tube circle about (R, 0) as two half circles
                out.append(cells([i, i], tuple(o), tuple(e1), tuple(e3), np.stack([R + r, R - r]), 0.0,
                                 np.stack([R - r, R + r]), 0.0, 1.0, arc))
        h0 = P[:, 1]
        n0 = -np.stack([np.cos(h0), np.zeros(len(P)), np.sin(h0)])
        n1 = np.stack([np.cos(a_end), np.zeros(len(P)), np.sin(a_end)])
        start = np.zeros((3, len(P)))
        for k, (c, n) in enumerate(((start, n0), (end, n1))):
            b = np.cross(n, np.tile(_Y[:, None], len(P)), axis=0)
            out.append(sectors([len(self.key) + k], tuple(c[:, None]), (0.0, 1.0, 0.0), tuple(b[:, None]),
                               tuple(n[:, None]), 0.0, r, TWO_PI))
        return out

    def _piece_sdfs(self, p, x):
        """Signed distances (pieces, N) of points x (N, 3) to each piece as a solid."""
        r = float(p[0])
        pieces, _, _ = self.pieces(np.asarray(p, dtype=float)[None])
        out = []
        for kind, o, e1, e3, s0, L, R, arc in pieces:
            o, e1, e3 = o[:, 0], e1[:, 0], e3[:, 0]
            w = x - o
            if kind == "L":
                t = w @ e3
                rad = np.linalg.norm(w - t[:, None] * e3, axis=1)
                dx, dz = rad - r, np.abs(t - L[0] / 2) - L[0] / 2
                out.append(np.hypot(np.maximum(dx, 0), np.maximum(dz, 0)) + np.minimum(np.maximum(dx, dz), 0))
            else:
                e2 = np.cross(e3, e1)
                loc = np.column_stack([w @ e1, w @ e2, w @ e3])
                rho = np.hypot(loc[:, 0], loc[:, 1])
                out.append(np.maximum(np.hypot(rho - R[0], loc[:, 2]) - r, wedge_sdf(loc, arc[0])))
        return np.stack(out)

    def sdf(self, p, x):
        """The union (min) of the pieces: exact sign; exact distance outside near line
        pieces and inside a bend's wedge, a lower bound elsewhere."""
        return self._piece_sdfs(p, np.asarray(x, dtype=float)).min(axis=0)

    def bounds(self, p):
        p = np.asarray(p, dtype=float)
        r = float(p[0])
        pieces, _, _ = self.pieces(p[None])
        pts = []
        for kind, o, e1, e3, s0, L, R, arc in pieces:
            o, e1, e3 = o[:, 0], e1[:, 0], e3[:, 0]
            if kind == "L":
                ext = r * np.sqrt(np.maximum(1.0 - e3 * e3, 0.0))  # a disc's half extents
                for c in (o, o + L[0] * e3):
                    pts += [c - ext, c + ext]
            else:
                e2 = np.cross(e3, e1)
                th = [0.0, arc[0]]
                for ax in range(3):  # angles where the in-plane direction is extreme along ax
                    base = math.atan2(e2[ax], e1[ax])
                    th += [t for t in np.mod(base + np.array([0.0, math.pi]), TWO_PI) if t <= arc[0]]
                for t in th:
                    u = math.cos(t) * e1 + math.sin(t) * e2
                    for rho in (R[0] - r, R[0] + r):
                        pts += [o + rho * u - r * np.abs(e3), o + rho * u + r * np.abs(e3)]
        pts = np.array(pts)
        return np.stack([pts.min(axis=0), pts.max(axis=0)])

    def collision(self, p):
        """A cylinder per line piece; convex sectors of the tube circle per bend."""
        from artipg.geometry.base import CollisionPiece
        from artipg.geometry.profile import circle, polygonise
        from artipg.geometry.revolve import sector_hulls

        r = float(p[0])
        pieces, _, _ = self.pieces(np.asarray(p, dtype=float)[None])
        out = []
        for kind, o, e1, e3, s0, L, R, arc in pieces:
            T = np.eye(4)
            T[:3, 0], T[:3, 2] = e1[:, 0], e3[:, 0]
            T[:3, 1] = np.cross(e3[:, 0], e1[:, 0])
            T[:3, 3] = o[:, 0]
            if kind == "L":
                T[:3, 3] += 0.5 * L[0] * e3[:, 0]
                out.append(CollisionPiece("cylinder", (r, float(L[0])), T))
            else:
                poly = polygonise(circle(r, (float(R[0]), 0.0)), 16)
                out += [CollisionPiece("mesh", pose=T @ c.pose, vertices=c.vertices, faces=c.faces)
                        for c in sector_hulls(poly, float(arc[0]), float(R[0]) - r)]
        return out

    def _tube(self, p):
        segs = tuple(("line", float(p[2 + 2 * i])) if k == "L" else ("arc", float(p[2 + 2 * i]), float(p[3 + 2 * i]))
                     for i, k in enumerate(self.key))
        return Tube(float(p[0]), segs, float(p[1]))

    def mesh_arrays(self, p, sections=32):
        m = self._tube(p).mesh(sections)
        return np.asarray(m.vertices), np.asarray(m.faces, dtype=np.int64)

    def volume(self, p):
        """π r² times the path length (Pappus for the bends)."""
        r = float(p[0])
        return float(math.pi * r * r * self.length(p))

    def length(self, p) -> float:
        """Length (m) of the centre line."""
        return float(sum(abs(p[2 + 2 * i]) if k == "L" else p[2 + 2 * i] * abs(p[3 + 2 * i])
                         for i, k in enumerate(self.key)))

    def uv_bounds(self, p):
        return np.array([[0.0, 0.0], [self.length(p), TWO_PI * float(p[0])]])

    def uv_seams(self, p, n=None):
        return [(1, 0.0, TWO_PI * float(p[0]), None)]

    def uv(self, p, x, n=None):
        """u = arc length (m) of the closest centre-line point, in [0, length]; v = the
        angle around the centre line times the radius (m), in [0, 2π r) (0 on the +y side)."""
        x = np.asarray(x, dtype=float)
        d = np.abs(self._piece_sdfs(p, x))
        which = d.argmin(axis=0)
        pieces, _, _ = self.pieces(np.asarray(p, dtype=float)[None])
        u, v = np.zeros(len(x)), np.zeros(len(x))
        for i, (kind, o, e1, e3, s0, L, R, arc) in enumerate(pieces):
            sel = which == i
            o, e1, e3 = o[:, 0], e1[:, 0], e3[:, 0]
            w = x[sel] - o
            if kind == "L":
                t = np.clip(w @ e3, 0.0, L[0])
                c, tan = o + t[:, None] * e3, np.broadcast_to(e3, w.shape)
                u[sel] = s0[0] + t
            else:
                e2 = np.cross(e3, e1)
                th = np.clip(np.mod(np.arctan2(w @ e2, w @ e1), TWO_PI), 0.0, arc[0])
                th = np.where(np.mod(np.arctan2(w @ e2, w @ e1), TWO_PI) > 0.5 * (arc[0] + TWO_PI), 0.0, th)
                radial = np.cos(th)[:, None] * e1 + np.sin(th)[:, None] * e2
                c = o + R[0] * radial
                tan = -np.sin(th)[:, None] * e1 + np.cos(th)[:, None] * e2
                u[sel] = s0[0] + R[0] * th
            dv = x[sel] - c
            side = np.cross(tan, _Y)
            v[sel] = np.mod(np.arctan2((dv * side).sum(axis=1), dv @ _Y), TWO_PI) * float(p[0])
        return np.column_stack([u, v])


def sweep(r: float, segments, heading: float = 0.0, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """A swept tube primitive: radius ``r`` along ``segments`` (:func:`artipg.geometry.tube.line`,
    :func:`artipg.geometry.tube.arc`) starting at the origin along heading ``heading``."""
    kinds = "".join("L" if s[0] == "line" else "A" for s in segments)
    vals = [v for s in segments for v in ((s[1], 0.0) if s[0] == "line" else (s[1], s[2]))]
    if any(s[0] == "arc" and s[1] <= r for s in segments):
        raise ValueError("a bend radius must exceed the tube radius")
    return Primitive(Sweep(kinds), (float(r), float(heading)) + tuple(float(v) for v in vals), pose, role)
