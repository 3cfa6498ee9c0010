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

A piece's samples depend on the object and the sample stream only, never on which
pieces were asked for before or together with it: each geometry template has its own
stream, from which all pieces of that template are drawn together on first use (mesh
pieces: one stream per piece). Drawing only the requested pieces from one shared
stream made a check's verdict depend on the order of earlier queries.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.box import Cuboid, RectRing
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.validate.rowsdf import PREPARE, prepare_quad_profiles

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
        Seeds the surface-sample streams (one number is drawn from it here).
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
        # one stream per geometry template (meshes: per piece), children of this seed
        self._seed = int(rng.integers(2 ** 63))
        index: dict = {}
        kind = [index.setdefault(g, len(index)) for g in self.geom]  # kinds in order of appearance
        kinds = list(index)
        self._kinds = kinds
        self._kind = np.array(kind, dtype=np.int64)
        self._nparams = [len(g.params) if g is not None else 0 for g in kinds]
        M = len(self.geom)

        def of_kind(*gs):
            return np.array([g in gs for g in kinds] + [False], dtype=bool)[self._kind if M else np.zeros(0, int)]

        self.is_box = of_kind(Cuboid)
        # full solids of revolution about their local z axis (frustum, full ring or
        # torus, sphere): unchanged by a turn about that axis
        full = self.params[:, 3] >= 2 * np.pi - 1e-9 if self.params.shape[1] > 3 else np.zeros(M, bool)
        arc = self.params[:, 2] >= 2 * np.pi - 1e-9 if self.params.shape[1] > 2 else np.zeros(M, bool)
        # whole balls (a sphere not cut by its slab): exact ball-ball distances
        P3 = self.params[:, :3] if self.params.shape[1] >= 3 else np.zeros((M, 3))
        self.is_ball = of_kind(Sphere) & (P3[:, 1] <= -P3[:, 0]) & (P3[:, 2] >= P3[:, 0])
        self.symmetric = of_kind(Frustum, Sphere) | (of_kind(Ring) & full) | (of_kind(Torus) & arc)
        self.start = np.zeros(M, dtype=np.int64)
        self.count = np.zeros(M, dtype=np.int64)
        self._drawn = np.zeros(M, dtype=bool)
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
        """Draw the surface samples of the pieces ``idx`` that have none yet.

        Primitive pieces are drawn per geometry template, all pieces of a template at
        once from that template's own stream; mesh pieces one by one, each from its
        own stream. The samples of a piece are thus the same whatever was drawn before.
        """
        idx = np.unique(np.asarray(idx, dtype=np.int64))
        idx = idx[~self._drawn[idx]]
        if not len(idx):
            return
        for k in np.unique(self._kind[idx]).tolist():
            g = self._kinds[k]
            if g is None:
                rows = idx[self._kind[idx] == k]
                streams = [self._stream(len(self._kinds) + int(r)) for r in rows]
                p, owner = _sample_meshes([self.meshes[int(r)] for r in rows], rows, streams)
            else:
                rows = np.flatnonzero(self._kind == k)
                P = self.params[rows, :self._nparams[k]]
                p, owner = _sample_group(g, P, rows, self._stream(k))
            order = np.argsort(owner, kind="stable")
            cnt = np.bincount(owner, minlength=self.n)[rows]
            self.start[rows] = self._size + np.cumsum(cnt) - cnt
            self.count[rows] = cnt
            self._drawn[rows] = True
            self._chunks.append(p[order])
            self._size += len(p)

    def _stream(self, key: int) -> np.random.Generator:
        """The sample stream ``key`` (a template index, or a mesh piece's) of this object."""
        return np.random.default_rng([self._seed, key])

    def sdf(self, rows: np.ndarray, x: np.ndarray) -> np.ndarray:
        """Signed distance (K,) of points ``x`` (K, 3), each in the frame of its piece
        ``rows`` (K,), to that piece (metres, negative inside)."""
        if not len(rows):
            return np.empty(0)
        return self.prepare(rows)(x)

    def prepare(self, rows: np.ndarray):
        """``f(x)`` equal to ``self.sdf(rows, x)`` for points ``x`` (len(rows), 3), with
        the per-row work (parameters, polygon edges) done once: for evaluating the same
        rows at several point sets in turn.

        Rows are evaluated per geometry template, frusta and rings together (both are
        quadrilateral profiles turned about z; see
        :func:`artipg.validate.rowsdf.prepare_quad_profiles`).
        """
        rows = np.asarray(rows, dtype=np.int64)
        kind = self._kind[rows]
        kinds = np.unique(kind).tolist()
        if len(kinds) == 1:
            return self._prepare_kind(kinds[0], rows)
        groups = []
        kf = self._kinds.index(Frustum) if Frustum in self._kinds else -1
        kr = self._kinds.index(Ring) if Ring in self._kinds else -1
        if kf in kinds and kr in kinds:
            sf, sr = np.flatnonzero(kind == kf), np.flatnonzero(kind == kr)
            fn = prepare_quad_profiles(self.params[rows[sf], :3], self.params[rows[sr], :5])
            groups.append((np.concatenate([sf, sr]), fn))
            kinds = [k for k in kinds if k not in (kf, kr)]
        for k in kinds:
            sel = np.flatnonzero(kind == k)
            groups.append((sel, self._prepare_kind(k, rows[sel])))
        if len(groups) == 1:
            sel, fn = groups[0]
            return lambda x: _scatter(len(rows), sel, fn(x[sel]))

        def f(x):
            out = np.empty(len(rows))
            for sel, fn in groups:
                out[sel] = fn(x[sel])
            return out

        return f

    def _prepare_kind(self, k: int, r: np.ndarray):
        """Evaluator of rows ``r`` that all have geometry kind ``k``."""
        g = self._kinds[k]
        if g in PREPARE:
            return PREPARE[g](self.params[r, :self._nparams[k]])
        return lambda x: self._sdf_pieces(g, k, r, x)

    def _sdf_pieces(self, g, k: int, r: np.ndarray, x: np.ndarray) -> np.ndarray:
        """Signed distances of rows ``r`` of kind ``k`` without a row-wise SDF (meshes,
        other templates), one piece at a time."""
        out = np.empty(len(r))
        order = np.argsort(r, kind="stable")
        cuts = np.flatnonzero(np.diff(r[order])) + 1
        for chunk in np.split(order, cuts):
            piece = int(r[chunk[0]])
            if g is None:
                out[chunk] = _mesh_sdf(self.meshes[piece], x[chunk])
            else:
                out[chunk] = g.sdf(tuple(self.params[piece, :self._nparams[k]]), x[chunk])
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


def _scatter(n: int, sel: np.ndarray, values: np.ndarray) -> np.ndarray:
    out = np.empty(n)
    out[sel] = values
    return out


def _mesh_sdf(mesh, x: np.ndarray) -> np.ndarray:
    """Signed distance to a triangle mesh (negative inside), metres; the sign comes
    from ray tests, so it is reliable for closed meshes only."""
    import trimesh

    return -trimesh.proximity.signed_distance(mesh, x)


def _sample_meshes(meshes, rows, streams):
    """Surface samples of mesh pieces ``rows``, each drawn from its own stream."""
    import trimesh

    pts, owner = [], []
    for r, mesh, rng in zip(rows, meshes, streams):
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
