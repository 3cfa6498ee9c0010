"""The extrusion family: a 2-D outline of line segments and arcs, optionally with holes,
extruded along local z over ``-h/2 <= z <= h/2``, optionally tapered.

``Extrusion((n0, n1, ...))`` is the family of outlines whose loops have n0, n1, ...
segments (the first the outer boundary, the others holes; see
:mod:`artipg.geometry.profile`). A row holds the loops' ``(x, y, b)`` rows one after
the other, then ``h`` and ``scale``: the cross-section at height z is the outline
scaled about the local z axis by ``1 + (scale - 1) (z / h + 1/2)`` (1 at the bottom,
``scale`` at the top). The sides of straight segments are planar trapezoids (two
triangle cells each); the sides of arcs are cylinder pieces (``revolved`` cells), so an
outline with arcs cannot be tapered (their tapered sides are oblique cones without a
two-uniform sampler here). Caps of polygonal outlines are triangle cells (earcut);
caps with arcs are sampled exactly by rejection against the exact inside test.

Thin constructors: :func:`prism` (regular n-gon), :func:`tri_prism` (wedge),
:func:`rect_ring` (a rectangular frame) and outline helpers for blades, plier halves, clips and rulers in
:mod:`artipg.geometry.outlines`.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import profile
from artipg.geometry.base import TWO_PI, CollisionPiece, Primitive, convex_hull
from artipg.geometry.family import Family, Region, convex_pieces, rejection_region, row_triangles, triangulate, weld
from artipg.geometry.patches import block
from artipg.geometry.revolved import cells
from artipg.geometry.transforms import IDENTITY, translation


class Extrusion(Family):
    """Outlines with loops of ``key`` segment counts, extruded along z."""

    kind = "extrusion"

    def param_names(self):
        names = [f"{c}{j}_{i}" for j, n in enumerate(self.key) for i in range(n) for c in ("x", "y", "b")]
        return tuple(names) + ("h", "scale")

    def n_components(self):
        return sum(self.key) + 2  # the sides of every segment, then bottom and top

    def loops(self, p) -> list[np.ndarray]:
        """The loops (n_j, 3) of row ``p``."""
        p = np.asarray(p, dtype=float)
        out, s = [], 0
        for n in self.key:
            out.append(p[s:s + 3 * n].reshape(n, 3))
            s += 3 * n
        return out

    def _segs(self, P):
        """Segment start/end points (c, M, 2) and bulges (c, M) of all loops."""
        M, s = len(P), 0
        p0, p1, b = [], [], []
        for n in self.key:
            L = P[:, s:s + 3 * n].reshape(M, n, 3)
            a0, a1, bb = profile.segments(L)
            p0.append(a0)
            p1.append(a1)
            b.append(bb)
            s += 3 * n
        return (np.concatenate(p0, axis=1).transpose(1, 0, 2), np.concatenate(p1, axis=1).transpose(1, 0, 2),
                np.concatenate(b, axis=1).T)

    def _patches(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        h, k = P[:, -2], P[:, -1]
        p0, p1, b = self._segs(P)
        if ((b != 0).any(axis=0) & (k != 1.0)).any():
            raise ValueError("a tapered extrusion needs a polygonal outline (no arcs)")
        c = len(b)
        comp = np.arange(c)
        straight = (b == 0).astype(float)
        z0 = -h / 2
        if (k == 1.0).all():  # straight sides are rectangles: one cell each
            A = (p0[..., 0], p0[..., 1], z0)
            E = (p1[..., 0] - p0[..., 0], p1[..., 1] - p0[..., 1])
            L = np.hypot(*E)
            L = np.where(L > 0, L, 1.0)
            out = [block("rect", comp, np.hypot(*E) * h * straight, *A, *E, 0.0, 0.0, 0.0, h,
                         E[1] / L, -E[0] / L, 0.0)]
        else:
            out = self._tapered_sides(comp, p0, p1, h, k, straight)
        if not (b != 0).any():
            return out + self._cap_tris(P)
        # arc sides: the vertical segment at the arc's radius revolved about its centre
        cen, R, a0, d = profile.arc_geometry(p0, p1, b)
        Rf = np.where(np.isfinite(R), R, 0.0)
        pos = d >= 0
        start = np.where(pos, a0, a0 + d)
        e1 = (np.cos(start), np.sin(start), 0.0)
        out.append(cells(comp, (cen[..., 0], cen[..., 1], z0), e1, (0.0, 0.0, 1.0), Rf,
                         np.where(pos, 0.0, h), Rf, np.where(pos, h, 0.0), 0.0, np.abs(d), scale=1.0 - straight))
        return out

    @staticmethod
    def _tapered_sides(comp, p0, p1, h, k, straight):
        """The sides of straight segments of tapered rows as two triangle cells each."""
        z0 = -h / 2
        # side trapezoid A B C D = (p0, z0) (p1, z0) (k p1, z1) (k p0, z1) as triangles ABC, ACD
        A = (p0[..., 0], p0[..., 1], z0)
        AB = (p1[..., 0] - p0[..., 0], p1[..., 1] - p0[..., 1], 0.0 * z0)
        AC = (k * p1[..., 0] - p0[..., 0], k * p1[..., 1] - p0[..., 1], h)
        AD = (k * p0[..., 0] - p0[..., 0], k * p0[..., 1] - p0[..., 1], h)
        nx, ny, nz = AB[1] * AD[2] - AB[2] * AD[1], AB[2] * AD[0] - AB[0] * AD[2], AB[0] * AD[1] - AB[1] * AD[0]
        nn = np.sqrt(nx * nx + ny * ny + nz * nz)
        nn = np.where(nn > 0, nn, 1.0)
        N = (nx / nn, ny / nn, nz / nn)
        return [_tris(comp, A, AB, AC, N, straight), _tris(comp, A, AC, AD, N, straight)]

    def _cap_tris(self, P):
        V = np.concatenate([l[..., :2] for l in _loop_arrays(self.key, P)], axis=1)  # (M, v, 2)
        T = row_triangles(P[:, :-2], lambda row: [l[:, :2] for l in self.loops(np.append(row, (0.0, 0.0)))],
                          V, self.key, self.__dict__.setdefault("_tri", {}))
        t = T.shape[1]
        rows = np.arange(len(P))[:, None]
        A, B, C = (V[rows, T[:, :, j]].transpose(1, 0, 2) for j in range(3))
        h, k = P[:, -2], P[:, -1]
        out = []
        for e, (z, s, sg) in enumerate(((-h / 2, 1.0, -1.0), (h / 2, k, 1.0))):
            # the bottom faces -z: swap the edges so that a x b points down
            a, bb = (C - A, B - A) if sg < 0 else (B - A, C - A)
            out.append(_tris(np.full(t, sum(self.key) + e), (s * A[..., 0], s * A[..., 1], z),
                             (s * a[..., 0], s * a[..., 1], 0.0), (s * bb[..., 0], s * bb[..., 1], 0.0),
                             (0.0, 0.0, sg), 1.0))
        return out

    def regions(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        if not P[:, 2:3 * sum(self.key):3].any():  # no arcs
            return []
        area = sum(profile.loop_area(L) for L in _loop_arrays(self.key, P))
        out = []
        for e, sg in ((0, -1.0), (1, 1.0)):
            def origin(p, e=e):
                return np.array([0.0, 0.0, (e - 0.5) * p[-2]])

            def ex(p, e=e):
                return np.array([p[-1] if e else 1.0, 0.0, 0.0])

            def ey(p, e=e):
                return np.array([0.0, p[-1] if e else 1.0, 0.0])

            draw = rejection_region(self.loops, origin, ex, ey, lambda p, sg=sg: np.array([0.0, 0.0, sg]))
            out.append(Region(sum(self.key) + e, area * (P[:, -1] ** 2 if e else 1.0), draw))
        return out

    def frames(self, P) -> tuple[np.ndarray, np.ndarray]:
        """Rows of ``P`` that are rectangular frames (an untapered, axis-aligned,
        centred rectangle with a centred rectangular hole, as :func:`rect_ring` makes):
        mask (M,) and their (ox, oy, depth, ix, iy) (M, 5) (meaningful where masked)."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        M = len(P)
        if self.key != (4, 4):
            return np.zeros(M, dtype=bool), np.zeros((M, 5))
        L = P[:, :24].reshape(M, 2, 4, 3)
        half = np.abs(L[..., :2]).max(axis=2)  # (M, 2 loops, 2 axes)
        corner = (np.abs(L[..., :2]) == half[:, :, None]).all(axis=(1, 2, 3))
        centred = (L[..., :2].sum(axis=2) == 0.0).all(axis=(1, 2))
        ok = corner & centred & (L[..., 2] == 0.0).all(axis=(1, 2)) & (P[:, -1] == 1.0)
        dims = np.column_stack([2 * half[:, 0, 0], 2 * half[:, 0, 1], P[:, -2], 2 * half[:, 1, 0], 2 * half[:, 1, 1]])
        return ok, dims

    def sdf(self, p, x):
        """Exact without taper (the 2-D outline distance combined with the slab);
        with taper the same in each horizontal slice, scaled: exact sign, the distance
        within the slice (not a bound of the 3-D distance)."""
        x = np.asarray(x, dtype=float)
        h, k = float(p[-2]), float(p[-1])
        s = 1.0 + (k - 1.0) * np.clip(x[:, 2] / h + 0.5, 0.0, 1.0)
        d2 = s * profile.sdf(self.loops(p), x[:, :2] / s[:, None])
        dz = np.abs(x[:, 2]) - h / 2
        return np.minimum(np.maximum(d2, dz), 0.0) + np.hypot(np.maximum(d2, 0.0), np.maximum(dz, 0.0))

    def bounds(self, p):
        return self.bounds_batch(np.asarray(p, dtype=float)[None])[0]

    def bounds_batch(self, P):
        P = np.asarray(P, dtype=float)
        b = profile.bounds(P[:, :3 * self.key[0]].reshape(len(P), -1, 3))  # the outer loop's (M, 2, 2)
        k = P[:, -1:]
        out = np.empty((len(P), 2, 3))
        out[:, 0, :2] = np.minimum(b[:, 0], k * b[:, 0])
        out[:, 1, :2] = np.maximum(b[:, 1], k * b[:, 1])
        out[:, 1, 2] = P[:, -2] / 2
        out[:, 0, 2] = -out[:, 1, 2]
        return out

    def _rings(self, p, sections):
        out = []
        for l in self.loops(p):
            poly = profile.polygonise(l, sections)
            out.append(poly[np.any(poly != np.roll(poly, 1, axis=0), axis=1)])
        return out

    def mesh_arrays(self, p, sections=32):
        h, k = float(p[-2]), float(p[-1])
        rings = self._rings(p, sections)
        V2 = np.concatenate(rings)
        nv = len(V2)
        V = np.concatenate([np.column_stack([V2, np.full(nv, -h / 2)]), np.column_stack([k * V2, np.full(nv, h / 2)])])
        T = triangulate(rings)
        F = [T[:, ::-1], T + nv]
        s = 0
        for r in rings:
            i = s + np.arange(len(r))
            j = s + (np.arange(len(r)) + 1) % len(r)
            F += [np.stack([i, j, j + nv], 1), np.stack([i, j + nv, i + nv], 1)]
            s += len(r)
        return weld(V, np.concatenate(F))

    def volume(self, p):
        k = float(p[-1])
        return float(profile.outline_area(self.loops(p)) * p[-2] * (1.0 + k + k * k) / 3.0)

    def collision(self, p):
        """Convex pieces of the polygonised outline (triangulation merged greedily),
        each extruded (and tapered): one convex hull each; a rectangular frame gives
        its four boxes."""
        ok, dims = self.frames(np.asarray(p, dtype=float)[None])
        if ok[0]:
            return [CollisionPiece("box", s, T) for s, T in frame_pieces(*(float(v) for v in dims[0]))]
        h, k = float(p[-2]), float(p[-1])
        out = []
        for piece in convex_pieces(self._rings(p, 24)):
            n = len(piece)
            pts = np.concatenate([np.column_stack([piece, np.full(n, -h / 2)]),
                                  np.column_stack([k * piece, np.full(n, h / 2)])])
            V, F = convex_hull(pts)
            out.append(CollisionPiece("mesh", vertices=V, faces=F))
        return out

    def uv_bounds(self, p):
        loops = self.loops(p)
        b = profile.bounds(loops[0])
        total = sum(profile.perimeter(l)[-1] for l in loops)
        side = float((b[1] - b[0]).max())  # caps run v along the outline's longer side
        return np.array([[0.0, 0.0], [max(total, side), max(float(p[-2]), side)]])

    def uv_seams(self, p, n=None):
        offs = np.concatenate([[0.0], np.cumsum([profile.perimeter(l)[-1] for l in self.loops(p)])])
        return [(0, float(a), float(b), None) for a, b in zip(offs[:-1], offs[1:])]

    def uv(self, p, x, n):
        """Sides: u = arc length (m) along the closest loop (holes continue after the
        outer loop's perimeter), v = z + h/2 (m). Caps (|nz| > 0.999 on a straight
        extrusion, the cap planes otherwise): planar, u = x - x_min, v = y - y_min of the
        unscaled outline (m), swapped where the outline is longer along x (v runs along
        the longer side, as on box faces)."""
        x = np.asarray(x, dtype=float)
        h, k = float(p[-2]), float(p[-1])
        s = 1.0 + (k - 1.0) * np.clip(x[:, 2] / h + 0.5, 0.0, 1.0)
        q = x[:, :2] / s[:, None]
        loops = self.loops(p)
        dist = np.stack([profile.loop_distance(l, q) for l in loops])
        which = dist.argmin(axis=0)
        offs = np.concatenate([[0.0], np.cumsum([profile.perimeter(l)[-1] for l in loops])])
        u_side = np.zeros(len(x))
        for j, l in enumerate(loops):
            sel = which == j
            if sel.any():
                u_side[sel] = offs[j] + profile.loop_length_at(l, q[sel])
        b = profile.bounds(loops[0])
        cap = np.abs(np.abs(x[:, 2]) - h / 2) <= 1e-9 * max(h, 1.0)
        if n is not None:
            cap &= np.abs(np.asarray(n)[:, 2]) > 0.999 if k == 1.0 else cap
        cu, cv = q[:, 0] - b[0, 0], q[:, 1] - b[0, 1]
        if b[1, 0] - b[0, 0] > b[1, 1] - b[0, 1]:  # v along the outline's longer side
            cu, cv = cv, cu
        return np.column_stack([np.where(cap, cu, u_side), np.where(cap, cv, x[:, 2] + h / 2)])


def _tris(comp, o, a, b, n, scale):
    """Triangle cells ``o + u a + v b`` with unit normal n (3-tuples of (c, M) columns)."""
    from artipg.geometry.patches import cross_norm

    return block("tri", comp, 0.5 * cross_norm(a, b) * scale, *o, *a, *b, *n)


def _loop_arrays(key, P):
    """The loops of rows ``P`` as arrays (M, n_j, 3)."""
    out, s = [], 0
    for n in key:
        out.append(P[:, s:s + 3 * n].reshape(len(P), n, 3))
        s += 3 * n
    return out


# ---------------------------------------------------------------- constructors

def extrusion(loops, height: float, scale: float = 1.0, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """An extrusion primitive: ``loops`` (the outer first; oriented here: outer
    counter-clockwise, holes clockwise), extruded ``height`` along z, centred, the top
    scaled by ``scale``."""
    ls = [profile.oriented(l, i == 0) for i, l in enumerate(loops)]
    if scale != 1.0 and profile.has_arcs(ls):
        raise ValueError("a tapered extrusion needs a polygonal outline (no arcs)")
    params = tuple(float(v) for l in ls for v in l.ravel()) + (float(height), float(scale))
    return Primitive(Extrusion(tuple(len(l) for l in ls)), params, pose, role)


MAX_SIDES = 16


def prism(r: float, h: float, n: int, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Regular ``n``-gon prism (3 <= n <= 16) of circumradius ``r`` and height ``h``
    along z, centred; the first vertex at angle π/n (a square prism is axis-aligned)."""
    if not 3 <= n <= MAX_SIDES:
        raise ValueError(f"prism needs 3..{MAX_SIDES} sides, got {n}")
    n, r = int(n), float(r)
    row = []
    for k in range(n):  # profile.regular_polygon, counter-clockwise, written out
        a = math.pi / n + TWO_PI * k / n
        row += (r * math.cos(a), r * math.sin(a), 0.0)
    return _counter_clockwise((n,), tuple(row) + (float(h), 1.0), pose, role)


def tri_prism(w: float, t: float, a: float, depth: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Triangular prism (wedge): the triangle (-w/2, 0), (w/2, 0), (a, t) in the x-y
    plane extruded ``depth`` along z, centred on z = 0."""
    if not (w > 0 and t > 0):  # the clockwise triangles: the general constructor orients them
        return extrusion([profile.polygon([[-w / 2, 0.0], [w / 2, 0.0], [a, t]])], depth, pose=pose, role=role)
    w, t, a = float(w), float(t), float(a)
    return _counter_clockwise((3,), (-w / 2, 0.0, 0.0, w / 2, 0.0, 0.0, a, t, 0.0, float(depth), 1.0), pose, role)


def rect_ring(ox, oy, depth, ix, iy, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Rectangular frame: an ``ox`` x ``oy`` rectangle with a centred ``ix`` x ``iy``
    hole, extruded ``depth`` along z and centred (a door frame, a window sash)."""
    x, y, u, v = float(ox) / 2, float(oy) / 2, float(ix) / 2, float(iy) / 2
    # profile.rectangle(ox, oy) counter-clockwise, then the hole clockwise, written out
    return _counter_clockwise((4, 4), (x, -y, 0.0, x, y, 0.0, -x, y, 0.0, -x, -y, 0.0,
                                       -u, -v, 0.0, -u, v, 0.0, u, v, 0.0, u, -v, 0.0, float(depth), 1.0), pose, role)


_FAMILIES: dict = {}


def _counter_clockwise(key: tuple, params: tuple, pose, role) -> Primitive:
    """An extrusion primitive of a row whose loops the caller built oriented (the thin
    constructors: no orientation test, no arrays; they run dozens of times per object)."""
    geom = _FAMILIES.get(key)
    if geom is None:
        geom = _FAMILIES[key] = Extrusion(key)
    return tuple.__new__(Primitive, (geom, params, pose, role))


def frame_dims(prim: Primitive) -> tuple | None:
    """``(ox, oy, depth, ix, iy)`` of a primitive that is a rectangular frame (as
    :func:`rect_ring` makes), else None."""
    if not isinstance(prim.geom, Extrusion) or prim.geom.key != (4, 4):
        return None
    ok, dims = prim.geom.frames(np.asarray(prim.params, dtype=float)[None])
    return tuple(float(v) for v in dims[0]) if ok[0] else None


def frame_pieces(ox, oy, depth, ix, iy) -> list[tuple[tuple[float, float, float], np.ndarray]]:
    """A rectangular frame as four disjoint boxes: (size, pose) pairs, the bands at +y,
    -y (full width), +x, -x (between them)."""
    bx, by = (ox - ix) / 2.0, (oy - iy) / 2.0
    return [
        ((ox, by, depth), translation(0, (iy + by) / 2, 0)),
        ((ox, by, depth), translation(0, -(iy + by) / 2, 0)),
        ((bx, iy, depth), translation((ix + bx) / 2, 0, 0)),
        ((bx, iy, depth), translation(-(ix + bx) / 2, 0, 0)),
    ]
