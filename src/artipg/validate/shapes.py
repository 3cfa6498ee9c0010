"""Solid pieces of an object for validation: exact SDFs and surface samples per piece.

A *piece* is one solid in one link: a geometry-template primitive of an artipg object
(exact signed distance) or a triangle mesh of a URDF folder. Every piece carries

- its frame in its link frame, ``T`` (M, 4, 4), and its local bounding box
  (``center``, ``half``: (M, 3));
- surface samples in its own frame, grouped by piece (``points`` (N, 3) with
  ``offsets`` (M + 1,)): area-proportional per surface component with a minimum
  per component, plus the corners and edge points of boxes, so small faces
  (a handle post's end cap) and sharp features are never missed;
- a vectorised signed distance ``sdf(piece_rows, x)`` (negative inside, metres).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from artipg.geometry.box import Cuboid, RectRing

#: Surface samples per square metre, and the per-component minimum / maximum.
DENSITY = 4000.0
MIN_PER_COMPONENT = 6
MAX_PER_COMPONENT = 160


def _cuboid_rows(P: np.ndarray, x: np.ndarray) -> np.ndarray:
    q = np.abs(x) - 0.5 * P
    return np.sqrt((np.maximum(q, 0.0) ** 2).sum(axis=1)) + np.minimum(q.max(axis=1), 0.0)


def _rect_ring_rows(P: np.ndarray, x: np.ndarray) -> np.ndarray:
    outer = _cuboid_rows(P[:, :3], x)
    hole = _cuboid_rows(np.column_stack([P[:, 3], P[:, 4], 4.0 * P[:, 2] + 1.0]), x)
    return np.maximum(outer, -hole)


#: Geometry templates with a signed distance vectorised over rows of parameters.
ROW_SDF = {Cuboid: _cuboid_rows, RectRing: _rect_ring_rows}


@dataclass
class Pieces:
    """The solid pieces of an object (see module docstring).

    Attributes
    ----------
    link, part : (M,) int64
        Link and part index of every piece.
    T : (M, 4, 4) float64
        Piece frame in its link frame.
    center, half : (M, 3) float64
        Local axis-aligned bounding box (centre and half extents), piece frame.
    points : (N, 3) float64
        Surface samples in their piece's frame, grouped by piece.
    offsets : (M + 1,) int64
        Piece ``i`` owns ``points[offsets[i]:offsets[i + 1]]``.
    part_names : list of str
        Name of every part (index = part index).
    part_link : (P,) int64
        Link index of every part.
    """

    link: np.ndarray
    part: np.ndarray
    T: np.ndarray
    center: np.ndarray
    half: np.ndarray
    points: np.ndarray
    offsets: np.ndarray
    part_names: list
    part_link: np.ndarray
    geom: list = field(default_factory=list)     # per piece: geometry template or None (mesh)
    params: np.ndarray | None = None             # per piece parameters (padded), primitives only
    meshes: dict = field(default_factory=dict)   # piece index -> trimesh.Trimesh (mesh pieces)

    @property
    def n(self) -> int:
        return len(self.link)

    @property
    def counts(self) -> np.ndarray:
        return np.diff(self.offsets)

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
            if g in ROW_SDF:
                r = rows[sel]
                out[sel] = ROW_SDF[g](self.params[r, :self._nparams[k]], x[sel])
                continue
            r = rows[sel]
            order = np.argsort(r, kind="stable")
            r_sorted = r[order]
            cuts = np.flatnonzero(np.diff(r_sorted)) + 1
            for chunk in np.split(order, cuts):
                piece = int(r[chunk[0]])
                idx = sel[chunk]
                if g is None:
                    out[idx] = _mesh_sdf(self.meshes[piece], x[idx])
                else:
                    out[idx] = g.sdf(tuple(self.params[piece, :self._nparams[k]]), x[idx])
        return out

    def __post_init__(self):
        kinds = []
        for g in self.geom:
            if g not in kinds:
                kinds.append(g)
        self._kinds = kinds
        self._kind = np.array([kinds.index(g) for g in self.geom], dtype=np.int64)
        self._nparams = [len(g.params) if g is not None else 0 for g in kinds]

    # ------------------------------------------------------------ constructors
    @classmethod
    def of(cls, obj, rng: np.random.Generator) -> "Pieces":
        """The primitives of an :class:`artipg.model.ArticulatedObject` as pieces."""
        table = obj.primitive_table
        M = table.n_prims
        geom: list = [None] * M
        width = max(len(g.geom.params) for g in table.groups)
        params = np.zeros((M, width))
        center = np.zeros((M, 3))
        half = np.zeros((M, 3))
        pts, owner = [], []
        for g in table.groups:
            for k in g.prim:
                geom[k] = g.geom
            params[g.prim, :g.P.shape[1]] = g.P
            b = g.geom.bounds_batch(g.P)
            center[g.prim] = 0.5 * (b[:, 0] + b[:, 1])
            half[g.prim] = 0.5 * (b[:, 1] - b[:, 0])
            p, o = _sample_group(g.geom, g.P, g.comp_area, g.prim, rng)
            pts.append(p)
            owner.append(o)
        points, offsets = _group_by_owner(np.concatenate(pts), np.concatenate(owner), M)
        return cls(table.prim_link.copy(), table.prim_part.copy(), table.prim_T.copy(), center, half, points,
                   offsets, [p.name for p in obj.parts], obj.part_link.copy(), geom, params)

    @classmethod
    def of_meshes(cls, items, part_names, part_link, rng: np.random.Generator) -> "Pieces":
        """Pieces from triangle meshes.

        Parameters
        ----------
        items : list of (link index, part index, trimesh.Trimesh, (4, 4) pose in link frame)
        part_names : list of str
        part_link : (P,) int
        rng : numpy.random.Generator
            Stream for the surface samples.
        """
        import trimesh

        M = len(items)
        link = np.array([it[0] for it in items], dtype=np.int64)
        part = np.array([it[1] for it in items], dtype=np.int64)
        T = np.array([it[3] for it in items]).reshape(M, 4, 4)
        center = np.zeros((M, 3))
        half = np.zeros((M, 3))
        pts, owner, meshes = [], [], {}
        for i, (_, _, mesh, _) in enumerate(items):
            b = mesh.bounds
            center[i] = 0.5 * (b[0] + b[1])
            half[i] = 0.5 * (b[1] - b[0])
            n = int(np.clip(np.ceil(mesh.area * DENSITY), 64, 4000))
            p, _ = trimesh.sample.sample_surface(mesh, n, seed=int(rng.integers(2 ** 31)))
            pts.append(np.concatenate([p, mesh.vertices[:: max(1, len(mesh.vertices) // 512)]]))
            owner.append(np.full(len(pts[-1]), i))
            meshes[i] = mesh
        points, offsets = _group_by_owner(np.concatenate(pts) if pts else np.zeros((0, 3)),
                                          np.concatenate(owner) if owner else np.zeros(0, np.int64), M)
        return cls(link, part, T, center, half, points, offsets, list(part_names),
                   np.asarray(part_link, dtype=np.int64), [None] * M, np.zeros((M, 1)), meshes)


def _mesh_sdf(mesh, x: np.ndarray) -> np.ndarray:
    """Signed distance to a triangle mesh (negative inside), metres."""
    import trimesh

    return -trimesh.proximity.signed_distance(mesh, x)


def _sample_group(geom, P, comp_area, prim, rng):
    """Surface samples of all primitives of one geometry template (local frames)."""
    n = np.where(comp_area > 0.0,
                 np.clip(np.ceil(comp_area * DENSITY), MIN_PER_COMPONENT, MAX_PER_COMPONENT), 0).astype(np.int64)
    M, C = comp_area.shape
    cells = np.repeat(np.arange(M * C), n.ravel())
    rows = cells // C
    p, _ = geom.sample_components(P[rows], cells - rows * C, rng)
    owner = prim[rows]
    if geom is Cuboid:  # corners and edge points: where boxes poke into each other
        f = _BOX_FEATURES
        extra = (f[None] * P[:, None, :]).reshape(-1, 3)
        p = np.concatenate([p, extra])
        owner = np.concatenate([owner, np.repeat(prim, len(f))])
    return p, owner


def _box_features() -> np.ndarray:
    """Corners and 3 points on each edge of the unit box centred at 0, (44, 3)."""
    s = np.array([-0.5, 0.5])
    corners = np.array([[a, b, c] for a in s for b in s for c in s])
    edges = []
    for ax in range(3):
        o = [k for k in range(3) if k != ax]
        for a in s:
            for b in s:
                for t in (-0.25, 0.0, 0.25):
                    v = np.zeros(3)
                    v[ax], v[o[0]], v[o[1]] = t, a, b
                    edges.append(v)
    return np.concatenate([corners, np.array(edges)])


_BOX_FEATURES = _box_features()


def _group_by_owner(points: np.ndarray, owner: np.ndarray, M: int):
    order = np.argsort(owner, kind="stable")
    counts = np.bincount(owner, minlength=M)
    return points[order], np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
