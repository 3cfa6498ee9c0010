"""Swept tube: a circle of radius ``r`` swept along a planar path made of straight
lines and circular arcs (handles, bails, spouts, temples).

The path lives in the local x-z plane, starts at the origin heading along
``(cos α0, 0, sin α0)``. Because lines and arcs join tangentially, the tube is exactly
the union of cylinders and torus arcs (lathe primitives, :mod:`artipg.geometry.lathe`)
whose joints are left out of the sampled surface, which is how :func:`tube` builds it;
its mesh is a single watertight loft (the swept-tube family,
:mod:`artipg.geometry.sweep`, is the one-primitive form).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from artipg.geometry.base import Primitive
from artipg.geometry.lathe import frustum, torus
from artipg.geometry.transforms import IDENTITY

Y = np.array([0.0, 1.0, 0.0])


def line(length: float) -> tuple:
    """A straight path segment of ``length`` metres."""
    return ("line", float(length))


def arc(radius: float, turn: float) -> tuple:
    """A circular path segment of bend ``radius`` turning ``turn`` radians (> 0: towards +z
    when heading +x, i.e. counter-clockwise in the (x, z) plane)."""
    return ("arc", float(radius), float(turn))


def _walk(segments: tuple, heading: float):
    """Yield (segment, start (x, z), heading α) along the path (plain floats)."""
    x = z = 0.0
    a = heading
    for seg in segments:
        yield seg, (x, z), a
        if seg[0] == "line":
            x += math.cos(a) * seg[1]
            z += math.sin(a) * seg[1]
        else:
            R, turn = seg[1], seg[2]
            sg = R if turn > 0 else -R
            cx, cz = x - math.sin(a) * sg, z + math.cos(a) * sg
            a += turn
            x, z = cx + math.sin(a) * sg, cz - math.cos(a) * sg


def _primitives(r: float, segments: tuple, heading: float, pose: np.ndarray, role: str) -> list[Primitive]:
    """:meth:`Tube.primitives` of ``Tube(r, segments, heading)`` (without making the Tube)."""
    n = len(segments)
    made, frames = [], []
    for i, (seg, (x, z), a) in enumerate(_walk(segments, heading)):
        c0, c1 = float(i == 0), float(i == n - 1)
        ca, sa = math.cos(a), math.sin(a)
        if seg[0] == "line":
            L = seg[1]
            # local z -> heading (ca, 0, sa); local x -> (sa, 0, -ca); local y -> y
            frames += (sa, 0.0, ca, x + ca * L / 2, 0.0, 1.0, 0.0, 0.0,
                       -ca, 0.0, sa, z + sa * L / 2, 0.0, 0.0, 0.0, 1.0)
            made.append(frustum(r, r, L, None, role, (c0, c1)))
        else:
            R, turn = seg[1], seg[2]
            sg = 1.0 if turn > 0 else -1.0
            # centre is R to the left (sg > 0) or right of the heading
            cx, cz = x - sa * R * sg, z + ca * R * sg
            ex = ((x - cx) / R, 0.0, (z - cz) / R)  # local x: centre -> start
            ey = (ca, 0.0, sa)  # local y: heading at the start
            ez = (ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2], ex[0] * ey[1] - ex[1] * ey[0])
            frames += (ex[0], ey[0], ez[0], cx, ex[1], ey[1], ez[1], 0.0,
                       ex[2], ey[2], ez[2], cz, 0.0, 0.0, 0.0, 1.0)
            made.append(torus(R, r, abs(turn), None, role, (c0, c1)))
    # one stacked product places every piece (the same 4x4 product for each)
    placed = pose @ np.fromiter(frames, float, 16 * n).reshape(n, 4, 4)  # fromiter: faster than np.array
    new = tuple.__new__  # Primitive(...) without the NamedTuple's Python-level __new__
    return [new(Primitive, (m[0], m[1], T, role)) for m, T in zip(made, placed)]


@dataclass(frozen=True)
class Tube:
    """A tube of radius ``r`` along ``segments`` (see :func:`line`, :func:`arc`)."""

    r: float
    segments: tuple
    heading: float = 0.0

    def _walk(self):
        """Yield (segment, start (x, z), heading α) along the path (plain floats)."""
        return _walk(self.segments, self.heading)

    def end(self) -> tuple[np.ndarray, float]:
        """End point (3,) and heading angle of the centre line."""
        x = z = a = 0.0
        for seg, (x, z), a in self._walk():
            pass
        if seg[0] == "line":
            return np.array([x + np.cos(a) * seg[1], 0.0, z + np.sin(a) * seg[1]]), a
        R, turn = seg[1], seg[2]
        sg = R if turn > 0 else -R
        cx, cz = x - math.sin(a) * sg, z + math.cos(a) * sg
        b = a + turn
        return np.array([cx + math.sin(b) * sg, 0.0, cz - math.cos(b) * sg]), b

    def primitives(self, pose: np.ndarray = IDENTITY, role: str = "") -> list[Primitive]:
        """The tube as open cylinders and torus arcs, capped at both ends, in ``pose``."""
        return _primitives(self.r, self.segments, self.heading, pose, role)

    def _stations(self, step: float = math.pi / 16):
        """Centre-line stations (point (3,), heading) for the loft."""
        for k, (seg, (x, z), a) in enumerate(self._walk()):
            if seg[0] == "line":
                if k == 0:
                    yield np.array([x, 0.0, z]), a
                yield np.array([x + math.cos(a) * seg[1], 0.0, z + math.sin(a) * seg[1]]), a
            else:
                R, turn = seg[1], seg[2]
                sg = R if turn > 0 else -R
                cx, cz = x - math.sin(a) * sg, z + math.cos(a) * sg
                m = max(2, int(math.ceil(abs(turn) / step)))
                for j in range(0 if k == 0 else 1, m + 1):
                    b = a + turn * j / m
                    yield np.array([cx + math.sin(b) * sg, 0.0, cz - math.cos(b) * sg]), b

    def mesh(self, sections: int = 24) -> trimesh.Trimesh:
        """Watertight loft of the tube (outward faces)."""
        import trimesh

        st = list(self._stations())
        phi = np.linspace(0.0, 2 * math.pi, sections, endpoint=False)
        rings = []
        for p, a in st:
            t = np.array([math.cos(a), 0.0, math.sin(a)])
            nrm = np.cross(Y, t)
            rings.append(p + self.r * (np.cos(phi)[:, None] * nrm + np.sin(phi)[:, None] * Y))
        V = np.concatenate(rings + [st[0][0][None], st[-1][0][None]])
        S, M = sections, len(st)
        i = np.arange(S)
        i1 = (i + 1) % S
        faces = []
        for j in range(M - 1):
            a0, b0 = j * S + i, j * S + i1
            a1, b1 = (j + 1) * S + i, (j + 1) * S + i1
            faces += [np.stack([a0, b0, b1], 1), np.stack([a0, b1, a1], 1)]
        c0, c1 = M * S, M * S + 1
        faces.append(np.stack([np.full(S, c0), i1, i], 1))
        faces.append(np.stack([np.full(S, c1), (M - 1) * S + i, (M - 1) * S + i1], 1))
        m = trimesh.Trimesh(V, np.concatenate(faces), process=True)
        if m.volume < 0:
            m.invert()
        return m

    def sdf(self, x: np.ndarray) -> np.ndarray:
        """Signed distance of local points (N, 3) (union of the pieces' solids)."""
        d = np.full(len(x), np.inf)
        for prim in self.primitives():
            d = np.minimum(d, prim.sdf(x))
        return d

    def bounds(self) -> np.ndarray:
        b = np.stack([prim.bounds() for prim in self.primitives()])
        return np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


def tube(r: float, segments, heading: float = 0.0, pose: np.ndarray = IDENTITY, role: str = "") -> list[Primitive]:
    """Primitives of a :class:`Tube` placed at ``pose`` (see module docstring)."""
    return _primitives(float(r), tuple(segments), heading, pose, role)  # Tube(...).primitives(), no Tube made
