"""Solid pieces of an object for validation: exact SDFs and surface samples per piece.

A *piece* is one solid in one link: a geometry-template primitive of an artipg object
(exact signed distance; a rectangular ring counts as its four boxes) or a triangle
mesh of a URDF folder. Every piece carries

- its frame in its link frame, ``T`` (M, 4, 4), and its local bounding box
  (``center``, ``half``: (M, 3));
- a vectorised signed distance ``sdf(piece_rows, x)`` (negative inside, metres);
- surface samples in its own frame, drawn on first use (:meth:`Pieces.require`):
  area-proportional per surface component with a minimum per component, plus the
  corners and edge points of boxes, so that small faces (a handle post's end cap)
  and sharp features are never missed. Box-box pairs never need samples.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.box import Cuboid, RectRing
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.validate.rowsdf import ROW_SDF

#: Surface samples per square metre, and the per-component minimum / maximum.
DENSITY = 2000.0
MIN_PER_COMPONENT = 4
MAX_PER_COMPONENT = 64




class Pieces:
    """The solid pieces of an object (see module docstring).

    Parameters
    ----------
    link, part : (M,) int64
        Link and part index of every piece.
    T : (M, 4, 4) float64
        Piece frame in its link frame.
    center, half : (M, 3) float64
        Local axis-aligned bounding box (centre and half extents), piece frame.
    geom : list
        Geometry template of every piece, or None for a mesh piece.
    params : (M, p) float64
        Parameters of primitive pieces (zero-padded).
    part_names : list of str
        Name of every part (index = part index).
    part_link : (P,) int64
        Link index of every part.
    rng : numpy.random.Generator
        Stream of the surface samples.
    meshes : dict, optional
        Piece index -> ``trimesh.Trimesh`` (piece frame) for mesh pieces.
    """

    def __init__(self, link, part, T, center, half, geom, params, part_names, part_link, rng, meshes=None):
        self.link = np.asarray(link, dtype=np.int64)
        self.part = np.asarray(part, dtype=np.int64)
        self.T = T
        self.center = center
        self.half = half
        self.geom = list(geom)
        self.params = params
        self.part_names = list(part_names)
        self.part_link = np.asarray(part_link, dtype=np.int64)
        self.meshes = meshes or {}
        self._rng = rng
        kinds: list = []
        for g in self.geom:
            if g not in kinds:
                kinds.append(g)
        self._kinds = kinds
        self._kind = np.array([kinds.index(g) for g in self.geom], dtype=np.int64)
        self._nparams = [len(g.params) if g is not None else 0 for g in kinds]
        self.is_box = np.array([g is Cuboid for g in self.geom], dtype=bool)
        # full solids of revolution about their local z axis (frustum, full ring or
        # torus, sphere): unchanged by a turn about that axis
        full = self.params[:, 3] >= 2 * np.pi - 1e-9 if self.params.shape[1] > 3 else np.zeros(len(self.geom), bool)
        arc = self.params[:, 2] >= 2 * np.pi - 1e-9 if self.params.shape[1] > 2 else np.zeros(len(self.geom), bool)
        self.symmetric = np.array([g in (Frustum, Sphere) for g in self.geom], dtype=bool)
        self.symmetric |= np.array([g is Ring for g in self.geom], dtype=bool) & full
        self.symmetric |= np.array([g is Torus for g in self.geom], dtype=bool) & arc
        M = len(self.geom)
        self.start = np.zeros(M, dtype=np.int64)
        self.count = np.zeros(M, dtype=np.int64)
        self._chunks: list = []
        self._size = 0
        self._points = np.zeros((0, 3))

    @property
    def n(self) -> int:
        return len(self.link)

    @property
    def points(self) -> np.ndarray:
        """All surface samples drawn so far (N, 3), piece frames."""
        if len(self._chunks) > 1 or (self._chunks and self._chunks[0] is not self._points):
            self._points = np.concatenate(self._chunks)
            self._chunks = [self._points]
        return self._points

    def samples(self, i: int) -> np.ndarray:
        """Surface samples (n, 3) of piece ``i`` in its frame (drawn if needed)."""
        self.require(np.array([i]))
        return self.points[self.start[i]:self.start[i] + self.count[i]]

    def require(self, idx: np.ndarray) -> None:
        """Draw the surface samples of the pieces ``idx`` that have none yet."""
        idx = np.unique(idx)
        idx = idx[self.count[idx] == 0]
        if not len(idx):
            return
        kinds = self._kind[idx]
        for k in np.unique(kinds):
            rows = idx[kinds == k]
            g = self._kinds[k]
            if g is None:
                p, owner = _sample_meshes([self.meshes[int(r)] for r in rows], rows, self._rng)
            else:
                P = self.params[rows, :self._nparams[k]]
                p, owner = _sample_group(g, P, rows, self._rng)
            order = np.argsort(owner, kind="stable")
            cnt = np.bincount(owner, minlength=self.n)[rows]
            self.start[rows] = self._size + np.cumsum(cnt) - cnt
            self.count[rows] = cnt
            self._chunks.append(p[order])
            self._size += len(p)

    def sdf(self, rows: np.ndarray, x: np.ndarray) -> np.ndarray:
        """Signed distance (K,) of points ``x`` (K, 3), each in the frame of its piece
        ``rows`` (K,), to that piece (metres, negative inside)."""
        out = np.empty(len(rows))
        if not len(rows):
            return out
        kind = self._kind[rows]
        for k in np.unique(kind):
            sel = np.flatnonzero(kind == k)
            g = self._kinds[k]
            r = rows[sel]
            if g in ROW_SDF:
                out[sel] = ROW_SDF[g](self.params[r, :self._nparams[k]], x[sel])
                continue
            order = np.argsort(r, kind="stable")
            cuts = np.flatnonzero(np.diff(r[order])) + 1
            for chunk in np.split(order, cuts):
                piece = int(r[chunk[0]])
                i = sel[chunk]
                if g is None:
                    out[i] = _mesh_sdf(self.meshes[piece], x[i])
                else:
                    out[i] = g.sdf(tuple(self.params[piece, :self._nparams[k]]), x[i])
        return out

    # ------------------------------------------------------------ constructors
    @classmethod
    def of(cls, obj, rng: np.random.Generator) -> "Pieces":
        """The primitives of an :class:`artipg.model.ArticulatedObject` as pieces.

        A rectangular ring (frame) becomes its four boxes, so that every box-like
        solid goes through the exact box-box tests of :mod:`artipg.validate.contacts`.
        """
        table = obj.primitive_table
        geom, Ps, Ts, links, parts, kinds = [], [], [], [], [], []
        for g in table.groups:
            T = table.prim_T[g.prim]
            if g.geom is RectRing:
                sizes, offs = _rect_ring_boxes(g.P)
                Tb = np.repeat(T, 4, axis=0)
                Tb[:, :3, 3] += np.einsum("kij,kj->ki", Tb[:, :3, :3], offs)
                geom += [Cuboid] * len(sizes)
                kinds.append(Cuboid)
                Ps.append(sizes)
                Ts.append(Tb)
                links.append(np.repeat(g.link, 4))
                parts.append(np.repeat(g.part, 4))
            else:
                geom += [g.geom] * len(g.P)
                kinds.append(g.geom)
                Ps.append(g.P)
                Ts.append(T)
                links.append(g.link)
                parts.append(g.part)
        M = len(geom)
        width = max(P.shape[1] for P in Ps)
        params = np.zeros((M, width))
        center = np.zeros((M, 3))
        half = np.zeros((M, 3))
        k = 0
        for P, g in zip(Ps, kinds):
            params[k:k + len(P), :P.shape[1]] = P
            b = g.bounds_batch(P)
            center[k:k + len(P)] = 0.5 * (b[:, 0] + b[:, 1])
            half[k:k + len(P)] = 0.5 * (b[:, 1] - b[:, 0])
            k += len(P)
        return cls(np.concatenate(links), np.concatenate(parts), np.concatenate(Ts), center, half, geom, params,
                   [p.name for p in obj.parts], obj.part_link, rng)


def _mesh_sdf(mesh, x: np.ndarray) -> np.ndarray:
    """Signed distance to a triangle mesh (negative inside), metres; the sign comes
    from ray tests, so it is reliable for closed meshes only."""
    import trimesh

    return -trimesh.proximity.signed_distance(mesh, x)


def _sample_meshes(meshes, rows, rng):
    import trimesh

    pts, owner = [], []
    for r, mesh in zip(rows, meshes):
        n = int(np.clip(np.ceil(mesh.area * DENSITY * 2), 64, 4000))
        p, _ = trimesh.sample.sample_surface(mesh, n, seed=int(rng.integers(2 ** 31)))
        v = np.asarray(mesh.vertices)[:: max(1, len(mesh.vertices) // 512)]
        pts.append(np.concatenate([p, v]))
        owner.append(np.full(len(pts[-1]), r))
    return np.concatenate(pts), np.concatenate(owner)


def _sample_group(geom, P, rows, rng):
    """Surface samples of pieces ``rows`` of one geometry template (local frames)."""
    comp_area = geom.component_areas(P)
    n = np.where(comp_area > 0.0,
                 np.clip(np.ceil(comp_area * DENSITY), MIN_PER_COMPONENT, MAX_PER_COMPONENT), 0).astype(np.int64)
    M, C = comp_area.shape
    cells = np.repeat(np.arange(M * C), n.ravel())
    r = cells // C
    p, _ = geom.sample_components(P[r], cells - r * C, rng)
    owner = rows[r]
    if geom is Cuboid:  # corners and edge points: where boxes poke into other solids
        f = _BOX_FEATURES
        p = np.concatenate([p, (f[None] * P[:, None, :]).reshape(-1, 3)])
        owner = np.concatenate([owner, np.repeat(rows, len(f))])
    return p, owner


def _rect_ring_boxes(P: np.ndarray):
    """The four boxes of rectangular rings ``P`` (m, 5): sizes and centre offsets, (4m, 3)
    each, in the order of :meth:`artipg.geometry.RectRing.pieces`."""
    ox, oy, d, ix, iy = P.T
    bx, by = (ox - ix) / 2, (oy - iy) / 2
    sizes = np.empty((len(P), 4, 3))
    offs = np.zeros((len(P), 4, 3))
    sizes[:, :2, 0], sizes[:, :2, 1] = ox[:, None], by[:, None]
    sizes[:, 2:, 0], sizes[:, 2:, 1] = bx[:, None], iy[:, None]
    sizes[:, :, 2] = d[:, None]
    offs[:, 0, 1], offs[:, 1, 1] = (iy + by) / 2, -(iy + by) / 2
    offs[:, 2, 0], offs[:, 3, 0] = (ix + bx) / 2, -(ix + bx) / 2
    return sizes.reshape(-1, 3), offs.reshape(-1, 3)


def _box_features() -> np.ndarray:
    """Corners and the midpoint of each edge of the unit box centred at 0, (20, 3)."""
    s = np.array([-0.5, 0.5])
    corners = np.array([[a, b, c] for a in s for b in s for c in s])
    edges = []
    for ax in range(3):
        o = [k for k in range(3) if k != ax]
        for a in s:
            for b in s:
                for t in (0.0,):
                    v = np.zeros(3)
                    v[ax], v[o[0]], v[o[1]] = t, a, b
                    edges.append(v)
    return np.concatenate([corners, np.array(edges)])


_BOX_FEATURES = _box_features()
