"""Solid pieces of an object for validation: exact SDFs and surface samples per piece.

A *piece* is one solid in one link: a geometry-family primitive of an artipg object
(a rectangular frame counts as its four boxes) or a triangle mesh of a URDF folder.
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

from artipg.geometry import profile
from artipg.geometry.base import pick
from artipg.geometry.extrusion import Extrusion
from artipg.geometry.family import Family
from artipg.geometry.lathe import Lathe
from artipg.geometry.patches import sample_family
from artipg.geometry.rounded_box import BOX, RoundedBox

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
        Geometry family of every piece, or None for a mesh piece (see :func:`traits`).
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
        self.ball_radius = np.zeros(M)
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

        A rectangular frame becomes its four boxes, so that every box-like solid goes
        through the exact box-box tests of :mod:`artipg.validate.contacts`.
        """
        table = obj.primitive_table
        geom, Ps, Ts, links, parts, boxes = [], [], [], [], [], []

        def add(tmpl, P, T, link, part):
            geom.extend([tmpl] * len(P))
            Ps.append(P)
            Ts.append(T)
            links.append(link)
            parts.append(part)
            boxes.append(tmpl.bounds_batch(P))

        for g in table.groups:
            T = table.prim_T[g.prim]
            frame = g.geom.frames(g.P) if isinstance(g.geom, Extrusion) else None
            if frame is None or not frame[0].any():
                add(g.geom, g.P, T, g.link, g.part)
                continue
            ok, dims = frame
            if not ok.all():
                add(g.geom, g.P[~ok], T[~ok], g.link[~ok], g.part[~ok])
            sizes, offs = _rect_ring_boxes(dims[ok])
            T = T[ok].repeat(4, axis=0)
            T[:, :3, 3] += np.einsum("kij,kj->ki", T[:, :3, :3], offs)
            add(BOX, np.column_stack([sizes, np.zeros(len(sizes))]), T, g.link[ok].repeat(4), g.part[ok].repeat(4))
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
    pieces.is_box[rows] = P[:, 3] == 0.0


def _no_traits(pieces, rows, P):
    pass


def _lathe_traits(pieces, rows, P):
    """Full turns are symmetric; the radial range is that of the profile (vertices and
    the discs of its arcs: a bound); a whole sphere (every vertex at one distance from
    the origin, its one arc centred there) is a ball."""
    n = (P.shape[1] - 3) // 4
    V = P[:, :4 * n].reshape(len(P), n, 4)
    p0, p1, b = profile.segments(V[..., :3])
    c, rad, _, _ = profile.arc_geometry(p0, p1, b)
    arc = b != 0.0
    rr = np.where(arc, rad, 0.0)
    lo = np.minimum(V[..., 0].min(axis=1), np.where(arc, c[..., 0] - rr, np.inf).min(axis=1))
    hi = np.maximum(V[..., 0].max(axis=1), np.where(arc, c[..., 0] + rr, -np.inf).max(axis=1))
    full = P[:, 4 * n] >= 2 * np.pi - 1e-9
    pieces.symmetric[rows] = full
    pieces.radial[rows] = np.column_stack([np.maximum(lo, 0.0), hi])
    d = np.hypot(V[..., 0], V[..., 1])
    R = d.max(axis=1)
    ball = (full & (arc.sum(axis=1) == 1) & (d.min(axis=1) >= R * (1 - 1e-12))
            & (np.where(arc, np.hypot(c[..., 0], c[..., 1]), 0.0).max(axis=1) <= 1e-12 * R)
            & (V[..., 1].min(axis=1) <= -R * (1 - 1e-12)) & (V[..., 1].max(axis=1) >= R * (1 - 1e-12)))
    pieces.is_ball[rows] = ball
    pieces.ball_radius[rows] = np.where(ball, R, 0.0)


def traits(geom):
    """The trait setter of geometry family ``geom`` (see above); ``ValueError`` for a
    geometry validation does not know."""
    if isinstance(geom, RoundedBox):
        return _box_traits
    if isinstance(geom, Lathe):
        return _lathe_traits
    if isinstance(geom, Family):
        return _no_traits
    raise ValueError(f"validation does not know geometry {getattr(geom, '__name__', geom)!r}")


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
    if geom.regions(P):  # planar faces bounded by arcs (sampled by rejection): the family's own sampler
        pts = geom.sample_components(P[row], comp, rng)[0]
    else:
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
    box = np.flatnonzero(P[:, 3] == 0.0) if geom is BOX else np.zeros(0, dtype=np.int64)
    if not len(box):
        return pts, count
    f = len(_BOX_FEATURES)
    feat = (_BOX_FEATURES[None] * P[box, None, :3]).reshape(-1, 3)
    owner = np.concatenate([row, box.repeat(f)])
    count = count.copy()
    count[box] += f
    return np.concatenate([pts, feat])[np.argsort(owner, kind="stable")], count


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
    """The four boxes of rectangular frames ``P`` (m, 5) (ox, oy, depth, ix, iy): sizes
    and centre offsets, (4m, 3) each: the bands at +y, -y, +x, -x."""
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
