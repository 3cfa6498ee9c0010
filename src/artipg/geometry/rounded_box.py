"""The box family: a box of extents (sx, sy, sz) centred on the origin with its edges
rounded by radius ``r`` (0 <= r <= min(sx, sy, sz) / 2; r = 0 is the plain box of :func:`cuboid`). The
rectangular frame is an extrusion with a hole: :func:`artipg.geometry.extrusion.rect_ring`.

Surface: six flat faces (rect cells, shrunk by r), twelve quarter cylinders (revolved
cells of a straight segment) and eight sphere octants (revolved cells of a quarter
arc); components: the six faces (-x, +x, -y, +y, -z, +z), the edges, the corners.
One family instance (``RoundedBox(())``); parameters ``(sx, sy, sz, r)``.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.base import CollisionPiece, Primitive
from artipg.geometry.family import Family, weld
from artipg.geometry.patches import compile_linear, linear, rects
from artipg.geometry.revolved import NAME, cells
from artipg.geometry.transforms import _EYE, IDENTITY

# Primitive(...) without the NamedTuple's Python-level __new__ (same tuple): the box
# constructors run dozens of times per object
_tuple_new = tuple.__new__

_CYC = ((0, 1, 2), (1, 2, 0), (2, 0, 1))  # (k, i, j) with e_i x e_j = e_k
_EDGES = [(k, i, j, si, sj) for k, i, j in _CYC for si in (-1.0, 1.0) for sj in (-1.0, 1.0)]
_CORNERS = [(sx, sy, sz) for sx in (-1.0, 1.0) for sy in (-1.0, 1.0) for sz in (-1.0, 1.0)]
_QUARTER_BULGE = math.tan(math.pi / 8)


def _unit(axis: int, sign: float = 1.0) -> np.ndarray:
    e = np.zeros(3)
    e[axis] = sign
    return e


def _edge_tables():
    """Axis points (12, 3) as signs of the inner half extents (-1 along the edge),
    e1 (12, 3), e3 (12, 3), and the edge axis (12,)."""
    O, E1, E3, K = [], [], [], []
    for k, i, j, si, sj in _EDGES:
        o = np.zeros(3)
        o[k], o[i], o[j] = -1.0, si, sj
        O.append(o)
        E3.append(_unit(k))
        # e2 = e_k x e1 must be the other face normal of the edge
        E1.append(_unit(i, si) if si == sj else _unit(j, sj))
        K.append(k)
    return np.array(O), np.array(E1), np.array(E3), np.array(K)


def _corner_tables():
    O = np.array(_CORNERS)
    E3 = O * np.array([0.0, 0.0, 1.0])
    E1 = np.array([_unit(0, s[0]) if s[0] * s[1] * s[2] > 0 else _unit(1, s[1]) for s in _CORNERS])
    return O, E1, E3


_EO, _EE1, _EE3, _EK = _edge_tables()
_CO, _CE1, _CE3 = _corner_tables()


class RoundedBox(Family):
    """Boxes with rounded edges, parameters (sx, sy, sz, r)."""

    kind = "rounded_box"

    def param_names(self):
        return ("sx", "sy", "sz", "r")

    def n_components(self):
        return 8

    def _patches(self, P):
        # every cell parameter is affine in (sx, sy, sz, r): one matrix product per block
        # (tables compiled once from :func:`_blocks`, the definition); areas in closed form
        P = np.atleast_2d(np.asarray(P, dtype=float))
        A = self.component_areas(P).T  # (8, M)
        r = P[:, 3]
        if not r.any():  # plain boxes (the common case): the edges and corners have no area
            return [linear("rect", _FACE_COMP, P, _TABLES[0], A[:6])]
        edge = (0.5 * math.pi) * r * (P[:, :3] - 2 * r[:, None]).T[_EK]
        corner = np.broadcast_to((0.5 * math.pi) * r * r, (8, len(P)))
        return [linear("rect", _FACE_COMP, P, _TABLES[0], A[:6]),
                linear(NAME, _EDGE_COMP, P, _TABLES[1], edge),
                linear(NAME, _CORNER_COMP, P, _TABLES[2], corner)]

    def component_areas(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        r = P[:, 3]
        out = np.empty((len(P), 8))
        abc = P[:, :3] - 2 * P[:, 3:4] if r.any() else P[:, :3]
        a, b, c = abc.T
        out[:, 0] = out[:, 1] = b * c
        out[:, 2] = out[:, 3] = a * c
        out[:, 4] = out[:, 5] = a * b
        out[:, 6] = 2 * math.pi * r * (a + b + c)
        out[:, 7] = 4 * math.pi * r * r
        return out

    def is_box(self, P) -> np.ndarray:
        """(M,) True for rows without rounding: plain boxes of extents P[:, :3]."""
        return np.asarray(P, dtype=float).reshape(-1, 4)[:, 3] == 0.0

    def sdf(self, p, x):
        """Exact: the distance to the inner box, minus r."""
        return box_rows_sdf(np.abs(np.asarray(x, dtype=float).T), np.asarray(p[:3], dtype=float) - 2 * p[3]) - p[3]

    def bounds(self, p):
        h = np.asarray(p[:3], dtype=float) / 2
        return np.stack([-h, h])

    def bounds_batch(self, P):
        out = np.empty((len(P), 2, 3))
        np.multiply(P[:, :3], 0.5, out=out[:, 1])
        np.negative(out[:, 1], out=out[:, 0])
        return out

    def volume(self, p):
        a, b, c = (float(v) - 2 * p[3] for v in p[:3])
        r = float(p[3])
        return a * b * c + 2 * r * (a * b + b * c + c * a) + math.pi * r * r * (a + b + c) + 4 / 3 * math.pi * r ** 3

    def mesh_arrays(self, p, sections=32):
        """A cube grid with lines at the inner box and at equal angles across the
        roundings, pushed onto the surface (inner-box point + r x unit offset)."""
        half = np.asarray(p[:3], dtype=float) / 2
        r = float(p[3])
        inner = half - r
        m = max(1, sections // 8) if r > 0 else 1
        tn = np.tan(np.linspace(0.0, math.pi / 4, m + 1))
        grids = [np.concatenate([-(inner[a] + r * tn[::-1]), inner[a] + r * tn]) for a in range(3)]
        for a in range(3):  # tan(π/4) rounds below 1: the faces must meet at the same ends
            grids[a][0], grids[a][-1] = -half[a], half[a]
        Vs, Fs, base = [], [], 0
        for k, i, j in _CYC:
            gi, gj = grids[i], grids[j]
            ni, nj = len(gi), len(gj)
            I, J = np.meshgrid(np.arange(ni), np.arange(nj), indexing="ij")
            a0 = (I[:-1, :-1] * nj + J[:-1, :-1]).ravel()
            q = np.stack([a0, a0 + nj, a0 + nj + 1, a0 + 1], 1)  # counter-clockwise in (i, j)
            tri = np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
            for sg in (-1.0, 1.0):
                V = np.zeros((ni * nj, 3))
                V[:, i], V[:, j], V[:, k] = np.repeat(gi, nj), np.tile(gj, ni), sg * half[k]
                Vs.append(V)
                Fs.append((tri if sg > 0 else tri[:, ::-1]) + base)
                base += len(V)
        V = np.concatenate(Vs)
        c = np.clip(V, -inner, inner)
        d = V - c
        nrm = np.linalg.norm(d, axis=1, keepdims=True)
        V = np.where(nrm > 0, c + r * d / np.where(nrm > 0, nrm, 1.0), V) + 0.0
        return weld(V, np.concatenate(Fs))

    def collision(self, p):
        if p[3] == 0:
            return [CollisionPiece("box", tuple(float(v) for v in p[:3]))]
        return super().collision(p)

    def uv_bounds(self, p):
        return np.array([[0.0, 0.0], [max(p[:3]), max(p[:3])]])

    def uv(self, p, x, n):
        """Per face, planar (m): the two coordinates other than the normal's dominant
        axis k, offset by the half extents, v along the longer of the two sides (wood
        grain and brushing run along a rail, a door or a top lengthwise): u in [0, s_i],
        v in [0, s_j], s_i <= s_j."""
        x = np.asarray(x, dtype=float)
        size = np.asarray(p[:3], dtype=float)
        half = size / 2
        k = np.abs(np.asarray(n)).argmax(axis=1)
        i, j = (k + 1) % 3, (k + 2) % 3
        i, j = np.where(size[i] > size[j], j, i), np.where(size[i] > size[j], i, j)
        rows = np.arange(len(x))
        return np.column_stack([x[rows, i] + half[i], x[rows, j] + half[j]])


def box_rows_sdf(ax: np.ndarray, size) -> np.ndarray:
    """Signed distance (N,) to a centred box of extents ``size`` (3,) of points given as
    absolute coordinate rows ``ax`` (3, N) (rows: several times faster than (N, 3))."""
    q = ax - (np.asarray(size, dtype=float) / 2.0)[:, None]
    m = np.maximum(q, 0.0)
    m *= m
    return np.sqrt((m[0] + m[1]) + m[2]) + np.minimum(np.maximum(np.maximum(q[0], q[1]), q[2]), 0.0)


def _blocks(P):
    """The cells of rows ``P`` (M, 4): six face rects (shrunk by r), twelve quarter
    cylinders (a segment (r, 0) -> (r, edge length) revolved a quarter turn) and eight
    sphere octants (the quarter arc (r, 0) -> (0, r) revolved a quarter turn)."""
    half, r = P[:, :3].T / 2, P[:, 3]  # (3, M), (M,)
    inner = half - r
    o, a, b, n = [np.zeros((3, 6, len(P))) for _ in range(4)]
    for f in range(6):
        k, sg = f // 2, (f % 2) * 2.0 - 1.0
        _, i, j = _CYC[k]
        o[k, f], o[i, f], o[j, f] = sg * half[k], -inner[i], -inner[j]
        a[i, f], b[j, f], n[k, f] = 2 * inner[i], 2 * inner[j], sg
    faces = rects(_FACE_COMP, tuple(o), tuple(a), tuple(b), tuple(n))
    O = _EO.T[:, :, None] * inner[:, None, :]  # (3, 12, M)
    edges = cells(_EDGE_COMP, tuple(O), tuple(_EE1.T[:, :, None]), tuple(_EE3.T[:, :, None]),
                  r, 0.0, r, 2 * inner[_EK], 0.0, 0.5 * math.pi)
    O = _CO.T[:, :, None] * inner[:, None, :]
    corners = cells(_CORNER_COMP, tuple(O), tuple(_CE1.T[:, :, None]), tuple(_CE3.T[:, :, None]),
                    r, 0.0, 0.0, r, _QUARTER_BULGE, 0.5 * math.pi)
    return faces, edges, corners


_FACE_COMP, _EDGE_COMP, _CORNER_COMP = np.arange(6), np.full(12, 6), np.full(8, 7)
_TABLES = [compile_linear(lambda P, i=i: _blocks(P)[i], 4) for i in range(3)]


def rounded_box(sx: float, sy: float, sz: float, r: float = 0.0, pose: np.ndarray = IDENTITY,
                role: str = "") -> Primitive:
    """A box of extents (sx, sy, sz) metres with edges rounded by ``r``, centred at ``pose``."""
    if not 0.0 <= r <= 0.5 * min(sx, sy, sz):
        raise ValueError(f"edge radius {r} must lie in [0, min(sx, sy, sz) / 2]")
    return Primitive(BOX, (float(sx), float(sy), float(sz), float(r)), pose, role)


#: The one box family instance (every box, rounded or not).
BOX = RoundedBox(())


def cuboid(sx: float, sy: float, sz: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """A box of extents (sx, sy, sz) metres centred at ``pose`` (no rounding)."""
    return _tuple_new(Primitive, (BOX, (float(sx), float(sy), float(sz), 0.0), pose, role))


def cuboid_between(lo, hi, role: str = "") -> Primitive:
    """An axis-aligned box spanning corners ``lo`` and ``hi`` (3,) in metres."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    T = _EYE.copy()  # translation() of the centre, inline
    T[0, 3] = 0.5 * (x0 + x1)
    T[1, 3] = 0.5 * (y0 + y1)
    T[2, 3] = 0.5 * (z0 + z1)
    return _tuple_new(Primitive, (BOX, (float(x1 - x0), float(y1 - y0), float(z1 - z0), 0.0), T, role))
