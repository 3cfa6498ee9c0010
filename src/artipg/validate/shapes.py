"""Solid pieces of an object for validation: exact SDFs and surface samples per piece.

A *piece* is one solid in one link: a geometry-template primitive of an artipg object
(a rectangular ring counts as its four boxes) or a triangle mesh of a URDF folder.
Every piece carries

- its frame in its link frame, ``T`` (M, 4, 4), and its local bounding box
  (``center``, ``half``: (M, 3));
- its signed distance (negative inside, metres): the template's own
  :meth:`artipg.geometry.base.GeometryTemplate.sdf`, evaluated once per distinct
  (template, parameters) among the rows asked for;
- surface samples in its own frame, drawn on first use (:meth:`Pieces.require`) by
  the template's own sampler (:meth:`GeometryTemplate.sample_components`, the code
  annotation samples with): area-proportional per surface component with a minimum
  per component, plus the corners and edge midpoints of boxes, so that small faces
  (a handle post's end cap) and sharp features are never missed. Box-box pairs
  never need samples.

A piece's samples depend on the object and its sample seed only, never on which
pieces were asked for before: the first request for any piece of a template draws
all pieces of that template from the template's own stream
``default_rng([seed, template index])`` (mesh pieces: one stream per piece).
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from artipg.geometry.base import pick
from artipg.geometry.box import Cuboid, RectRing
from artipg.geometry.patches import sample_family
from artipg.geometry.prism import Prism, TriPrism
from artipg.geometry.extrusion import Extrusion
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus

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
        Geometry template of every piece, or None for a mesh piece. Templates
        validation has no traits for (:data:`_TRAITS`) raise ``ValueError``.
    params : (M, p) float64
        Parameters of primitive pieces (zero-padded).
    part_names : list of str
        Name of every part (index = part index).
    part_link : (P,) int64
        Link index of every part.
    rng : numpy.random.Generator or int
        Seeds the surface-sample streams (one number is drawn from it here; an int is
        that number, see :func:`stream_seed`).
    meshes : dict, optional
        Piece index -> ``trimesh.Trimesh`` (piece frame) for mesh pieces.
    """

    def __init__(self, link, part, T, center, half, geom, params, part_names, part_link, rng, meshes=None):
        self.link = np.asarray(link, dtype=np.int64)
        self.part = np.asarray(part, dtype=np.int64)
        self.T = np.asarray(T, dtype=float)
        self.center = np.asarray(center, dtype=float)
        self.half = np.asarray(half, dtype=float)
        self.params = np.asarray(params, dtype=float).reshape(len(self.link), -1)
        self.part_names = list(part_names)
        self.part_link = np.asarray(part_link, dtype=np.int64)
        self.meshes = meshes or {}
        self._seed = stream_seed(rng)
        index: dict = {}  # templates in order of first appearance
        self._kind = np.array([index.setdefault(g, len(index)) for g in geom], dtype=np.int64)
        self._kinds = list(index)
        M = self.n
        self.is_box = np.zeros(M, dtype=bool)
        self.is_ball = np.zeros(M, dtype=bool)
        self.symmetric = np.zeros(M, dtype=bool)
        self.radial = np.tile([-np.inf, np.inf], (M, 1))
        for k, g in enumerate(self._kinds):
            rows = (self._kind == k).nonzero()[0]
            if g is not None:
                traits(g)(self, rows, self.params[rows])
        self.symmetric_rows = self.symmetric.nonzero()[0]
        self.start = np.zeros(M, dtype=np.int64)
        self.count = np.zeros(M, dtype=np.int64)
        self._drawn = np.zeros(M, dtype=bool)
        self._chunks: list = []  # (3, n) blocks of samples, in drawing order
        self._size = 0

    @property
    def geom(self) -> list:
        """Geometry template of every piece (None: a mesh piece)."""
        return [self._kinds[k] for k in self._kind.tolist()]

    @property
    def n(self) -> int:
        return len(self.link)

    @cached_property
    def _shape(self) -> tuple[np.ndarray, np.ndarray]:
        """Id (M,) of each piece's distinct solid (template and parameters; every mesh
        piece its own) and a representative piece (S,) of each id."""
        mesh = np.where([g is None for g in self.geom], np.arange(self.n), -1)
        key = np.column_stack([self._kind, mesh, self.params])
        _, rep, inv = np.unique(key, axis=0, return_index=True, return_inverse=True)
        return inv.reshape(-1), rep

    # ------------------------------------------------------------ samples
    @property
    def points_t(self) -> np.ndarray:
        """All surface samples drawn so far as coordinate rows (3, N), piece frames."""
        if len(self._chunks) != 1:
            self._chunks = [np.concatenate(self._chunks, axis=1) if self._chunks else np.zeros((3, 0))]
        return self._chunks[0]

    @property
    def points(self) -> np.ndarray:
        """All surface samples drawn so far (N, 3), piece frames (a view of :attr:`points_t`)."""
        return self.points_t.T

    def samples(self, i: int) -> np.ndarray:
        """Surface samples (n, 3) of piece ``i`` in its frame (drawn if needed)."""
        self.require(np.array([i]))
        return self.points[self.start[i]:self.start[i] + self.count[i]]

    def require(self, idx: np.ndarray) -> None:
        """Draw the surface samples of the pieces ``idx`` that have none yet: all pieces
        of their geometry templates at once, each template from its own stream; mesh
        pieces one by one, each from its own stream."""
        need = np.zeros(self.n, dtype=bool)
        need[np.asarray(idx, dtype=np.int64)] = True
        need &= ~self._drawn
        for k in np.unique(self._kind[need]).tolist():
            g = self._kinds[k]
            if g is None:
                rows = (need & (self._kind == k)).nonzero()[0]
                got = [_sample_mesh(self.meshes[r], self._stream(len(self._kinds) + r)) for r in rows.tolist()]
                p, cnt = np.concatenate(got), np.array([len(x) for x in got], dtype=np.int64)
            else:
                rows = (self._kind == k).nonzero()[0]
                p, cnt = sample_surface(g, self.params[rows, :len(g.params)], self._stream(k))
            self.start[rows] = self._size + cnt.cumsum() - cnt
            self.count[rows] = cnt
            self._drawn[rows] = True
            self._chunks.append(np.ascontiguousarray(p.T))
            self._size += len(p)

    def _stream(self, key: int) -> np.random.Generator:
        """The sample stream ``key`` (a template index, or a mesh piece's) of this object."""
        return np.random.default_rng([self._seed, key])

    # ------------------------------------------------------------ signed distances
    def sdf(self, rows: np.ndarray, x: np.ndarray) -> np.ndarray:
        """Signed distance (K,) of points ``x`` (K, 3), each in the frame of its piece
        ``rows`` (K,), to that piece (metres, negative inside)."""
        return self.prepare(rows)(x)

    def prepare(self, rows: np.ndarray):
        """``f(x)`` equal to ``self.sdf(rows, x)`` for points ``x`` (len(rows), 3), with
        the rows grouped by distinct solid once: for evaluating the same rows at
        several point sets in turn."""
        rows = np.asarray(rows, dtype=np.int64)
        shape, rep = self._shape
        s = shape[rows]
        order = np.argsort(s, kind="stable")
        cuts = np.flatnonzero(np.diff(s[order])) + 1
        groups = [(sel, int(rep[s[sel[0]]])) for sel in np.split(order, cuts) if len(sel)]

        def f(x):
            out = np.empty(len(rows))
            for sel, piece in groups:
                out[sel] = self._piece_sdf(piece, x[sel])
            return out

        return f

    def _piece_sdf(self, i: int, x: np.ndarray) -> np.ndarray:
        """Signed distance of points ``x`` (k, 3), piece frame, to piece ``i``."""
        g = self._kinds[self._kind[i]]
        if g is None:
            return _mesh_sdf(self.meshes[i], x)
        return g.sdf(tuple(self.params[i, :len(g.params)].tolist()), x)

    # ------------------------------------------------------------ constructors
    @classmethod
    def of(cls, obj, rng: np.random.Generator) -> "Pieces":
        """The primitives of an :class:`artipg.model.ArticulatedObject` as pieces.

        A rectangular ring (frame) becomes its four boxes, so that every box-like
        solid goes through the exact box-box tests of :mod:`artipg.validate.contacts`.
        """
        table = obj.primitive_table
        geom, Ps, Ts, links, parts, boxes = [], [], [], [], [], []
        for g in table.groups:
            T = table.prim_T[g.prim]
            if g.geom is RectRing:
                sizes, offs = _rect_ring_boxes(g.P)
                T = T.repeat(4, axis=0)
                T[:, :3, 3] += np.einsum("kij,kj->ki", T[:, :3, :3], offs)
                tmpl, P, link, part = Cuboid, sizes, g.link.repeat(4), g.part.repeat(4)
            else:
                tmpl, P, link, part = g.geom, g.P, g.link, g.part
            geom += [tmpl] * len(P)
            Ps.append(P)
            Ts.append(T)
            links.append(link)
            parts.append(part)
            boxes.append(tmpl.bounds_batch(P))
        params = np.zeros((len(geom), max(P.shape[1] for P in Ps)))
        k = 0
        for P in Ps:
            params[k:k + len(P), :P.shape[1]] = P
            k += len(P)
        b = np.concatenate(boxes)
        return cls(np.concatenate(links), np.concatenate(parts), np.concatenate(Ts), 0.5 * (b[:, 0] + b[:, 1]),
                   0.5 * (b[:, 1] - b[:, 0]), geom, params, [p.name for p in obj.parts], obj.part_link, rng)


# ---------------------------------------------------------------- per-template traits
# Each sets, for the rows of one template, what the contact tests need beyond the SDF:
# ``is_box`` (exact box-box tests), ``is_ball`` (a whole sphere: exact ball-ball
# distances), ``symmetric`` (unchanged by a turn about the local z axis) and
# ``radial`` (min, max distance of the solid from the local z axis; the SDF is at
# least the distance of a point's radius to this range).

def _box_traits(pieces, rows, P):
    pieces.is_box[rows] = True


def _no_traits(pieces, rows, P):
    pass


def _frustum_traits(pieces, rows, P):
    pieces.symmetric[rows] = True
    pieces.radial[rows] = np.column_stack([np.zeros(len(P)), np.maximum(P[:, 0], P[:, 1])])


def _ring_traits(pieces, rows, P):
    ro, ri, tp = P[:, 0], P[:, 1], P[:, 4]
    pieces.symmetric[rows] = P[:, 3] >= 2 * np.pi - 1e-9
    pieces.radial[rows] = np.column_stack([np.minimum(ri, ri + tp), np.maximum(ro, ro + tp)])


def _sphere_traits(pieces, rows, P):
    R, lo, hi = P[:, 0], P[:, 1], P[:, 2]
    pieces.symmetric[rows] = True
    pieces.is_ball[rows] = (lo <= -R) & (hi >= R)
    pieces.radial[rows] = np.column_stack([np.zeros(len(P)), R])


def _torus_traits(pieces, rows, P):
    R, r = P[:, 0], P[:, 1]
    pieces.symmetric[rows] = P[:, 2] >= 2 * np.pi - 1e-9
    pieces.radial[rows] = np.column_stack([R - r, R + r])


#: Geometry template -> its traits (see above). RectRing is absent: :meth:`Pieces.of`
#: splits it into boxes.
_TRAITS = {Cuboid: _box_traits, Frustum: _frustum_traits, Ring: _ring_traits, Sphere: _sphere_traits,
           Torus: _torus_traits, Prism: _no_traits, TriPrism: _no_traits, Extrusion: _no_traits}


def traits(geom):
    """The trait setter of geometry template ``geom``; ``ValueError`` for a template
    validation does not know."""
    try:
        return _TRAITS[geom] if geom in _TRAITS else _TRAITS[type(geom)]  # family instances by their class
    except KeyError:
        raise ValueError(f"validation does not know geometry template {getattr(geom, '__name__', geom)!r}: "
                         "add its traits to artipg.validate.shapes._TRAITS") from None


# ---------------------------------------------------------------- sampling

def stream_seed(rng) -> int:
    """The seed of an object's surface-sample streams: one number drawn from ``rng``
    (a :class:`numpy.random.Generator`), or ``rng`` itself when it is an int."""
    if isinstance(rng, (int, np.integer)):
        return int(rng)
    return int(rng.integers(2 ** 63))


def sample_counts(geom, P: np.ndarray) -> np.ndarray:
    """Samples (M, C) per surface component of pieces ``P`` (M, p) of template ``geom``:
    ``DENSITY`` per square metre, clipped to [``MIN``, ``MAX``] (zero for empty components)."""
    area = geom.component_areas(P)
    n = np.clip(np.ceil(area * DENSITY), MIN_PER_COMPONENT, MAX_PER_COMPONENT)
    return np.where(area > 0.0, n, 0.0).astype(np.int64)


def sample_surface(geom, P: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Surface samples of the pieces ``P`` (M, p) of one geometry template, local frames.

    Every component of every piece gets :func:`sample_counts` points, drawn as the
    template's own :meth:`~artipg.geometry.base.GeometryTemplate.sample_components`
    of the pieces repeated per sample draws them (the same patch pick and patch
    samplers, :func:`artipg.geometry.patches.sample_family`), with the patch tables
    built once per piece instead of once per sample; boxes also get their corners
    and edge midpoints.

    Returns
    -------
    points : (N, 3) float64
        Piece by piece in row order, metres.
    count : (M,) int64
        Points of each piece.
    """
    n = sample_counts(geom, P)
    M, C = n.shape
    cell = np.arange(M * C).repeat(n.ravel())  # (piece, component) of each sample, piece-major
    row = cell // C
    comp = cell % C
    blocks = geom.patches(P)
    area = np.concatenate([b.area for b in blocks])  # (patches, M)
    pcomp = np.concatenate([b.comp for b in blocks])
    which = pick(np.where(pcomp[None, :] == comp[:, None], area.T[row], 0.0), rng)
    pts = np.empty((len(row), 3))
    start = 0
    for b in blocks:
        sel = np.flatnonzero((which >= start) & (which < start + len(b.comp)))
        if len(sel):
            pts[sel] = sample_family(b.family, b.params[which[sel] - start, :, row[sel]].T, rng)[:3].T
        start += len(b.comp)
    count = n.sum(axis=1)
    if geom is not Cuboid:
        return pts, count
    f = len(_BOX_FEATURES)
    feat = (_BOX_FEATURES[None] * P[:, None, :3]).reshape(-1, 3)
    owner = np.concatenate([row, np.arange(M).repeat(f)])
    order = np.argsort(owner, kind="stable")  # each box's features after its samples
    return np.concatenate([pts, feat])[order], count + f


def _sample_mesh(mesh, rng: np.random.Generator) -> np.ndarray:
    """Surface samples (n, 3) of a mesh piece and a subset of its vertices."""
    import trimesh

    n = int(np.clip(np.ceil(mesh.area * DENSITY * 2), 64, 4000))
    p, _ = trimesh.sample.sample_surface(mesh, n, seed=int(rng.integers(2 ** 31)))
    v = np.asarray(mesh.vertices)[:: max(1, len(mesh.vertices) // 512)]
    return np.concatenate([p, v])


def _mesh_sdf(mesh, x: np.ndarray) -> np.ndarray:
    """Signed distance to a triangle mesh (negative inside), metres; the sign comes
    from ray tests, so it is reliable for closed meshes only."""
    import trimesh

    return -trimesh.proximity.signed_distance(mesh, x)


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
    s = (-0.5, 0.5)
    corners = [(a, b, c) for a in s for b in s for c in s]
    edges = []
    for ax in range(3):
        o = [k for k in range(3) if k != ax]
        for a in s:
            for b in s:
                v = [0.0, 0.0, 0.0]
                v[o[0]], v[o[1]] = a, b
                edges.append(v)
    return np.array(corners + edges, dtype=float)


_BOX_FEATURES = _box_features()
