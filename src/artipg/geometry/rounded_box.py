"""The box family: a box of extents (sx, sy, sz) centred on the origin with its edges
rounded by radius ``r`` (0 <= r <= min(sx, sy, sz) / 2; r = 0 is today's
:class:`~artipg.geometry.box.Cuboid`). The rectangular frame
(:class:`~artipg.geometry.box.RectRing`) is an extrusion with a hole:
:func:`artipg.geometry.extrusion.rect_ring`.

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
from artipg.geometry.transforms import IDENTITY

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

    def patches(self, P):
        # every cell parameter is affine in (sx, sy, sz, r): one matrix product per block
        # (tables compiled once from :func:`_blocks`, the definition); areas in closed form
        P = np.atleast_2d(np.asarray(P, dtype=float))
        A = self.component_areas(P).T  # (8, M)
        r = P[:, 3]
        edge = (0.5 * math.pi) * r * (P[:, :3] - 2 * r[:, None]).T[_EK]
        corner = np.broadcast_to((0.5 * math.pi) * r * r, (8, len(P)))
        return [linear("rect", _FACE_COMP, P, _TABLES[0], A[:6]),
                linear(NAME, _EDGE_COMP, P, _TABLES[1], edge),
                linear(NAME, _CORNER_COMP, P, _TABLES[2], corner)]

    def component_areas(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        a, b, c = (P[:, :3] - 2 * P[:, 3:4]).T
        r = P[:, 3]
        return np.column_stack([b * c, b * c, a * c, a * c, a * b, a * b,
                                2 * math.pi * r * (a + b + c), 4 * math.pi * r * r])

    def sdf(self, p, x):
        """Exact: the distance to the inner box, minus r."""
        half = np.asarray(p[:3], dtype=float) / 2 - p[3]
        q = np.abs(np.asarray(x, dtype=float)) - half
        return (np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)) - p[3]

    def bounds(self, p):
        h = np.asarray(p[:3], dtype=float) / 2
        return np.stack([-h, h])

    def bounds_batch(self, P):
        h = np.asarray(P, dtype=float)[:, :3] / 2
        return np.stack([-h, h], axis=1)

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
        axis k, in cyclic order (k, i, j), offset by the half extents: u in [0, s_i]."""
        x = np.asarray(x, dtype=float)
        half = np.asarray(p[:3], dtype=float) / 2
        k = np.abs(np.asarray(n)).argmax(axis=1)
        i, j = (k + 1) % 3, (k + 2) % 3
        rows = np.arange(len(x))
        return np.column_stack([x[rows, i] + half[i], x[rows, j] + half[j]])


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
    return Primitive(RoundedBox(()), (float(sx), float(sy), float(sz), float(r)), pose, role)
