"""Box-like geometry templates: the cuboid and the rectangular ring (frame)."""

from __future__ import annotations

import functools

import numpy as np

from artipg.geometry.base import CollisionPiece, GeometryTemplate, Primitive
from artipg.geometry.patches import linear
from artipg.geometry.transforms import _EYE, IDENTITY, translation

# Primitive(...) without the NamedTuple's Python-level __new__ (same tuple): the
# constructors below run dozens of times per object
_tuple_new = tuple.__new__


def _box_tables():
    """Faces -x, +x, -y, +y, -z, +z of a box as linear maps of (sx, sy, sz).

    Returns the rect-patch table (6, 12, 4) of :func:`artipg.geometry.patches.linear`: coefficients of
    (sx, sy, sz) and a constant (the normals).
    """
    coef = np.zeros((6, 12, 4))
    for f in range(6):
        k, sign = f // 2, (f % 2) * 2.0 - 1.0
        i, j = [ax for ax in range(3) if ax != k]
        coef[f, k, k] = 0.5 * sign  # origin: the face's (-, -) corner
        coef[f, i, i] = coef[f, j, j] = -0.5
        coef[f, 3 + i, i] = 1.0  # edge a along axis i
        coef[f, 6 + j, j] = 1.0  # edge b along axis j
        coef[f, 9 + k, 3] = sign
    return coef


_BOX_TABLE = _box_tables()


@functools.cache
def _unit_box() -> tuple[np.ndarray, np.ndarray]:
    """Vertices (8, 3) and faces (12, 3) of trimesh's unit box (trimesh is imported only
    when a mesh is built: ``import artipg`` stays light)."""
    import trimesh

    box = trimesh.creation.box()
    return np.asarray(box.vertices), np.asarray(box.faces, dtype=np.int64)


def _frame_faces() -> np.ndarray:
    """Triangles (32, 3) of a rectangular frame with vertices: top outer 0-3, top inner
    4-7, bottom outer 8-11, bottom inner 12-15 (corners counter-clockwise from +x+y)."""
    k = np.arange(4)
    k1 = (k + 1) % 4
    ot, it, ob, ib = k, 4 + k, 8 + k, 12 + k
    ot1, it1, ob1, ib1 = k1, 4 + k1, 8 + k1, 12 + k1
    top = [np.stack([ot, ot1, it1], 1), np.stack([ot, it1, it], 1)]
    bottom = [f[:, ::-1] + 8 for f in top]
    outer = [np.stack([ot, ob, ob1], 1), np.stack([ot, ob1, ot1], 1)]
    inner = [f[:, ::-1] + 4 for f in outer]
    return np.concatenate(top + bottom + outer + inner).astype(np.int64)


_FRAME_FACES = _frame_faces()


def _box_rows_sdf(ax: np.ndarray, size) -> np.ndarray:
    """Signed distance (N,) to a centred box of extents ``size`` (3,) of points given as
    absolute coordinate rows ``ax`` (3, N) (rows: several times faster than (N, 3))."""
    q = ax - (np.asarray(size, dtype=float) / 2.0)[:, None]
    m = np.maximum(q, 0.0)
    m *= m
    return np.sqrt((m[0] + m[1]) + m[2]) + np.minimum(np.maximum(np.maximum(q[0], q[1]), q[2]), 0.0)


_BOX_COMP = np.arange(6)
# face areas sy sz, sx sz, sx sy: products of these parameter columns
_FACE_I, _FACE_J = np.array([1, 0, 0]), np.array([2, 2, 1])


class Cuboid(GeometryTemplate):
    """Axis-aligned box of extents ``(sx, sy, sz)`` metres, centred on the origin."""

    name = "cuboid"
    params = ("sx", "sy", "sz")

    @classmethod
    def component_areas(cls, P):
        # faces -x, +x, -y, +y, -z, +z: sy sz twice, sx sz twice, sx sy twice
        out = np.empty((len(P), 3, 2))
        np.multiply(P.take(_FACE_I, axis=1)[:, :, None], P.take(_FACE_J, axis=1)[:, :, None], out=out)
        return out.reshape(len(P), 6)

    @classmethod
    def area(cls, P):
        sx, sy, sz = P[:, 0], P[:, 1], P[:, 2]
        return 2.0 * (sx * sy + sy * sz + sx * sz)

    @classmethod
    def patches(cls, P):
        return [linear("rect", _BOX_COMP, P, _BOX_TABLE, cls.component_areas(P).T)]

    @classmethod
    def sdf(cls, p, x):
        return _box_rows_sdf(np.abs(x.T, order="C"), p)

    @classmethod
    def bounds(cls, p):
        h = np.asarray(p, dtype=float) / 2.0
        return np.stack([-h, h])

    @classmethod
    def bounds_batch(cls, P):
        out = np.empty((len(P), 2, 3))
        np.multiply(P[:, :3], 0.5, out=out[:, 1])
        np.negative(out[:, 1], out=out[:, 0])
        return out

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        V, F = _unit_box()
        return V * np.asarray(p[:3], dtype=float), F

    @classmethod
    def volume(cls, p):
        return float(p[0] * p[1] * p[2])

    @classmethod
    def collision(cls, p):
        return [CollisionPiece("box", tuple(float(v) for v in p))]


class RectRing(GeometryTemplate):
    """Rectangular frame: an ``ox`` x ``oy`` rectangle with a centred ``ix`` x ``iy``
    hole, extruded ``depth`` along z and centred on the origin (a door frame, a
    window sash, a picture frame)."""

    name = "rect_ring"
    params = ("ox", "oy", "depth", "ix", "iy")

    @classmethod
    def component_areas(cls, P):
        sides = P @ _RING_SIDES  # the two in-plane side lengths of each rectangle
        return sides[:, :16] * sides[:, 16:]

    @classmethod
    def area(cls, P):
        ox, oy, d, ix, iy = (P[:, i] for i in range(5))
        return 2.0 * (ox * oy - ix * iy) + 2.0 * d * (ox + oy + ix + iy)

    @classmethod
    def patches(cls, P):
        return [linear("rect", _RING_COMP, P, _RING_TABLE, cls.component_areas(P).T)]

    @classmethod
    def sdf(cls, p, x):
        ox, oy, d, ix, iy = p
        ax = np.abs(x.T, order="C")
        return np.maximum(_box_rows_sdf(ax, (ox, oy, d)), -_box_rows_sdf(ax, (ix, iy, 4.0 * d + 1.0)))

    @classmethod
    def bounds(cls, p):
        return Cuboid.bounds((p[0], p[1], p[2]))

    @classmethod
    def bounds_batch(cls, P):
        return Cuboid.bounds_batch(P[:, :3])

    @classmethod
    def pieces(cls, p) -> list[tuple[tuple[float, float, float], np.ndarray]]:
        """The frame as four disjoint boxes: (size, pose) pairs."""
        ox, oy, d, ix, iy = (float(v) for v in p)
        bx, by = (ox - ix) / 2.0, (oy - iy) / 2.0
        return [
            ((ox, by, d), translation(0, (iy + by) / 2, 0)),
            ((ox, by, d), translation(0, -(iy + by) / 2, 0)),
            ((bx, iy, d), translation((ix + bx) / 2, 0, 0)),
            ((bx, iy, d), translation(-(ix + bx) / 2, 0, 0)),
        ]

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        ox, oy, d, ix, iy = (float(v) for v in p)
        xy = np.array([[ox, oy], [-ox, oy], [-ox, -oy], [ox, -oy],   # outer corners, counter-clockwise
                       [ix, iy], [-ix, iy], [-ix, -iy], [ix, -iy]]) / 2  # inner corners
        V = np.concatenate([np.column_stack([xy, np.full(8, d / 2)]), np.column_stack([xy, np.full(8, -d / 2)])])
        return V, _FRAME_FACES

    @classmethod
    def volume(cls, p):
        ox, oy, d, ix, iy = p
        return float((ox * oy - ix * iy) * d)

    @classmethod
    def collision(cls, p):
        return [CollisionPiece("box", s, T) for s, T in cls.pieces(p)]


def _ring_tables():
    """Rectangles of a :class:`RectRing` as linear maps of (ox, oy, d, ix, iy).

    Returns centre and size coefficient tensors (5, 16, 3), unit normals (16, 3) and
    the two in-plane axes (16,) of each rectangle.
    """
    C = np.zeros((5, 16, 3))
    S = np.zeros((5, 16, 3))
    N = np.zeros((16, 3))
    OX, OY, D, IX, IY = np.eye(5)
    half = 0.5
    rects = []
    for zs in (-1.0, 1.0):  # front/back faces as four strips
        for ys in (-1.0, 1.0):
            # centre y = ys*(iy/2 + (oy-iy)/4) = ys*(oy+iy)/4, size (ox, (oy-iy)/2, 0)
            rects.append(((0 * OX, ys * (OY + IY) / 4, zs * D * half), (OX, (OY - IY) / 2, 0 * OX), (0, 0, zs)))
        for xs in (-1.0, 1.0):
            rects.append(((xs * (OX + IX) / 4, 0 * OX, zs * D * half), ((OX - IX) / 2, IY, 0 * OX), (0, 0, zs)))
    for (W, H), inward in (((OX, OY), 1.0), ((IX, IY), -1.0)):  # outer and inner walls
        for xs in (-1.0, 1.0):
            rects.append(((xs * W / 2, 0 * OX, 0 * OX), (0 * OX, H, D), (xs * inward, 0, 0)))
        for ys in (-1.0, 1.0):
            rects.append(((0 * OX, ys * H / 2, 0 * OX), (W, 0 * OX, D), (0, ys * inward, 0)))
    A0 = np.zeros(16, dtype=int)
    A1 = np.zeros(16, dtype=int)
    for r, (c, sz, n) in enumerate(rects):
        for ax in range(3):
            C[:, r, ax] = c[ax]
            S[:, r, ax] = sz[ax]
        N[r] = n
        a0, a1 = [ax for ax in range(3) if n[ax] == 0]
        A0[r], A1[r] = a0, a1
    return C, S, N, A0, A1


_RING_TABLES = _ring_tables()


def _ring_sides() -> np.ndarray:
    """(5, 32): the side lengths along the first, then the second in-plane axis of the 16
    rectangles, as linear maps of (ox, oy, d, ix, iy). Every coefficient is 0, ±1/2 or 1
    and each side has at most two non-zero ones, so a side is one exactly rounded sum of
    exact products whatever order a matrix product adds them in."""
    C, S, N, A0, A1 = _RING_TABLES
    rows = np.arange(16)
    return np.concatenate([S[:, rows, A0], S[:, rows, A1]], axis=1)


_RING_SIDES = _ring_sides()


def _ring_patch_tables():
    """The 16 rectangles of :func:`_ring_tables` as the rect-patch table (16, 12, 6) of
    :func:`artipg.geometry.patches.linear`: origin = centre - size / 2, edges along the two in-plane axes."""
    C, S, N, A0, A1 = _RING_TABLES
    coef = np.zeros((16, 12, 6))
    rows = np.arange(16)
    coef[:, 0:3, :5] = (C - S / 2).transpose(1, 2, 0)
    coef[rows, 3 + A0, :5] = S[:, rows, A0].T
    coef[rows, 6 + A1, :5] = S[:, rows, A1].T
    coef[:, 9:12, 5] = N
    return coef


_RING_TABLE = _ring_patch_tables()
_RING_COMP = np.arange(16)


def cuboid(sx: float, sy: float, sz: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """A :class:`Cuboid` of extents (sx, sy, sz) metres centred at ``pose``."""
    return _tuple_new(Primitive, (Cuboid, (float(sx), float(sy), float(sz)), pose, role))


def cuboid_between(lo, hi, role: str = "") -> Primitive:
    """An axis-aligned :class:`Cuboid` spanning corners ``lo`` and ``hi`` (3,) in metres."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    T = _EYE.copy()  # translation() of the centre, inline
    T[0, 3] = 0.5 * (x0 + x1)
    T[1, 3] = 0.5 * (y0 + y1)
    T[2, 3] = 0.5 * (z0 + z1)
    return _tuple_new(Primitive, (Cuboid, (float(x1 - x0), float(y1 - y0), float(z1 - z0)), T, role))


def rect_ring(ox, oy, depth, ix, iy, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """A :class:`RectRing` frame (outer ox x oy, hole ix x iy, thickness ``depth`` along z)."""
    return _tuple_new(Primitive, (RectRing, (float(ox), float(oy), float(depth), float(ix), float(iy)), pose, role))
