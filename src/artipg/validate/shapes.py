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
stream, which covers all pieces of that template (mesh pieces: one stream per piece).
Only the samples of the pieces asked for are computed, but the stream is consumed as
if all were drawn, so a piece gets the same samples whenever and with whichever others
it is asked for (drawing only the requested pieces from one shared stream once made a
check's verdict depend on the order of earlier queries). The draws and arithmetic are
the templates' own ``sample_components``; only the patch tables are built once per
piece instead of once per sample, and the streams' doubles come from a shared cache
(:mod:`artipg.validate.streams`: every object uses the same few streams).
"""

from __future__ import annotations

from functools import cached_property
from typing import NamedTuple

import numpy as np

from artipg.geometry.box import Cuboid, RectRing
from artipg.geometry.patches import sample_family
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.validate import compiled
from artipg.validate.rowsdf import PREPARE, prepare_quad_profiles
from artipg.validate.streams import UniformStream

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
        Geometry template of every piece, or None for a mesh piece (unused with
        ``kinds``).
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
    kinds : tuple, optional
        The templates in order of first appearance and each piece's index into them
        ((M,) int64), instead of ``geom``.
    flags : tuple, optional
        ``(code, is_box, is_ball, symmetric)`` of the pieces ((M,) arrays) as this
        class computes them (given by :func:`artipg.validate.jit_pieces.pieces_arrays`).
    """

    def __init__(self, link, part, T, center, half, geom, params, part_names, part_link, rng, meshes=None, *,
                 kinds=None, flags=None):
        self.link = np.asarray(link, dtype=np.int64)
        self.part = np.asarray(part, dtype=np.int64)
        self.T = T
        self.center = center
        self.half = half
        self.params = params
        self.part_names = list(part_names)
        self.part_link = np.asarray(part_link, dtype=np.int64)
        self.meshes = meshes or {}
        # one stream per geometry template (meshes: per piece), children of this seed
        self._seed = stream_seed(rng)
        if kinds is None:  # kinds in order of appearance, and each piece's
            index: dict = {}
            kind = [index.setdefault(g, len(index)) for g in geom]
            kinds = (list(index), np.array(kind, dtype=np.int64))
        self._kinds, self._kind = kinds
        self._nparams = [len(g.params) if g is not None else 0 for g in self._kinds]
        M = len(self._kind)
        if flags is not None:
            self._code, self.is_box, self.is_ball, self.symmetric = flags
        else:
            self._flags(M)
        self.symmetric_rows = self.symmetric.nonzero()[0]
        self.start = np.zeros(M, dtype=np.int64)
        self.count = np.zeros(M, dtype=np.int64)
        self._drawn = np.zeros(M, dtype=bool)
        self._chunks: list = []  # (3, n) blocks of samples, in drawing order
        self._size = 0
        self._points_t = np.zeros((3, 0))

    def _flags(self, M: int) -> None:
        """The template code, ``is_box``, ``is_ball`` and ``symmetric`` of every piece."""
        # template of every piece as a small code, for per-template flags
        code = np.array([_CODES.get(g, 0) for g in self._kinds] + [0], dtype=np.int64)[self._kind]
        self._code = code
        self.is_box = code == _CODES[Cuboid]
        # full solids of revolution about their local z axis (frustum, full ring or
        # torus, sphere): unchanged by a turn about that axis; whole balls (a sphere
        # not cut by its slab): exact ball-ball distances
        symmetric = code == _CODES[Frustum]
        self.is_ball = np.zeros(M, dtype=bool)
        if Sphere in self._kinds:
            sphere = code == _CODES[Sphere]
            self.is_ball = sphere & (self.params[:, 1] <= -self.params[:, 0]) & (self.params[:, 2] >= self.params[:, 0])
            symmetric |= sphere
        if Ring in self._kinds:
            symmetric |= (code == _CODES[Ring]) & (self.params[:, 3] >= 2 * np.pi - 1e-9)
        if Torus in self._kinds:
            symmetric |= (code == _CODES[Torus]) & (self.params[:, 2] >= 2 * np.pi - 1e-9)
        self.symmetric = symmetric

    @property
    def geom(self) -> list:
        """Geometry template of every piece (None: a mesh piece)."""
        return [self._kinds[k] for k in self._kind.tolist()]

    @property
    def n(self) -> int:
        return len(self.link)

    @cached_property
    def radial(self) -> np.ndarray:
        """(M, 2): radial extent (min, max distance from the local z axis, metres) of the
        solids of revolution, ``(-inf, inf)`` for other pieces. The SDF of a solid of
        revolution is at least the distance of a point's radius to this range."""
        M = self.n
        Q = np.zeros((M, 5))
        Q[:, :min(5, self.params.shape[1])] = self.params[:, :5]
        out = np.empty((M, 2))
        out[:, 0], out[:, 1] = -np.inf, np.inf
        code = self._code
        for c in np.unique(code).tolist():
            sel = (code == c).nonzero()[0]
            q = Q[sel]
            if c == _CODES[Frustum]:
                out[sel, 0], out[sel, 1] = 0.0, np.maximum(q[:, 0], q[:, 1])
            elif c == _CODES[Ring]:
                out[sel, 0] = np.minimum(q[:, 1], q[:, 1] + q[:, 4])
                out[sel, 1] = np.maximum(q[:, 0], q[:, 0] + q[:, 4])
            elif c == _CODES[Sphere]:
                out[sel, 0], out[sel, 1] = 0.0, q[:, 0]
            elif c == _CODES[Torus]:
                out[sel, 0], out[sel, 1] = q[:, 0] - q[:, 1], q[:, 0] + q[:, 1]
        return out

    @cached_property
    def jit_table(self):
        """The SDF codes, parameter table and radial extents of the pieces for the
        compiled kernels (:func:`artipg.validate.jit_contacts.piece_table`), or None
        where a piece has no compiled SDF (a mesh) or the kernels are off
        (:mod:`artipg.validate.compiled`)."""
        if not compiled.ENABLED or any(g is None for g in self._kinds) or not _kernels_match():
            return None
        given = self.__dict__.get("_sdf_table")  # by Pieces.of (pieces_arrays)
        if given is not None:
            return given
        from artipg.validate.jit_contacts import SDF_CODES, piece_table

        if any(g not in SDF_CODES for g in self._kinds):
            return None
        return piece_table(self)

    @property
    def points_t(self) -> np.ndarray:
        """All surface samples drawn so far as coordinate rows (3, N), piece frames:
        contiguous rows for the per-sample arithmetic."""
        if len(self._chunks) > 1 or (self._chunks and self._chunks[0] is not self._points_t):
            self._points_t = np.concatenate(self._chunks, axis=1)
            self._chunks = [self._points_t]
        return self._points_t

    @property
    def points(self) -> np.ndarray:
        """All surface samples drawn so far (N, 3), piece frames (a view of :attr:`points_t`)."""
        return self.points_t.T

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
        if compiled.ENABLED and _kernels_match():
            from artipg.validate import jit_samples

            left = jit_samples.require(self, idx)
            if left is None or not left[0]:
                return
            kinds, need = left
        else:
            need = np.zeros(self.n, dtype=bool)
            need[np.asarray(idx, dtype=np.int64)] = True
            need &= ~self._drawn
            if not need.any():
                return
            kinds = np.bincount(self._kind[need], minlength=len(self._kinds)).nonzero()[0].tolist()
        for k in kinds:
            g = self._kinds[k]
            if g is None:
                rows = (need & (self._kind == k)).nonzero()[0]
                streams = [self._stream(len(self._kinds) + int(r)) for r in rows]
                p, owner = _sample_meshes([self.meshes[int(r)] for r in rows], rows, streams)
                order = np.argsort(owner, kind="stable")
                p, cnt = p[order].T, np.bincount(owner, minlength=self.n)[rows]
            else:
                rows = (self._kind == k).nonzero()[0]
                want = need[rows]
                want = None if want.all() else want
                P = self.params[rows, :self._nparams[k]]
                got = None
                if compiled.ENABLED and _kernels_match():
                    from artipg.validate.jit_samples import draw_group

                    got = draw_group(g, P, self._seed, k, want)
                if got is None:
                    p, cnt = _sample_group(g, P, UniformStream(self._seed, k), want)
                    p = p.T
                else:
                    p, cnt = got
                if want is not None:
                    rows, cnt = rows[want], cnt[want]
            self.start[rows] = self._size + cnt.cumsum() - cnt
            self.count[rows] = cnt
            self._drawn[rows] = True
            self._chunks.append(np.ascontiguousarray(p))  # (3, n)
            self._size += p.shape[1]

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
        if len(self._kinds) == 1:
            return self._prepare_kind(0, rows)
        kinds = np.bincount(kind, minlength=len(self._kinds)).nonzero()[0].tolist()
        if len(kinds) == 1:
            return self._prepare_kind(kinds[0], rows)
        groups = []
        kf = self._kinds.index(Frustum) if Frustum in self._kinds else -1
        kr = self._kinds.index(Ring) if Ring in self._kinds else -1
        if kf in kinds and kr in kinds:
            sf, sr = (kind == kf).nonzero()[0], (kind == kr).nonzero()[0]
            fn = prepare_quad_profiles(self.params[rows[sf], :3], self.params[rows[sr], :5])
            groups.append((np.concatenate([sf, sr]), fn))
            kinds = [k for k in kinds if k not in (kf, kr)]
        for k in kinds:
            sel = (kind == k).nonzero()[0]
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
        cuts = np.diff(r[order]).nonzero()[0] + 1
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
        local = getattr(table, "local_boxes", None)  # the templates' bounds_batch, cached by generation
        part_names = [p.name for p in obj.parts]
        if compiled.ENABLED and local is not None and table.groups and _kernels_match():
            from artipg.validate.jit_pieces import pieces_arrays

            link, part, T, center, half, params, kinds, flags, sdf_table = pieces_arrays(table, local, _CODES)
            pieces = cls(link, part, T, center, half, None, params, part_names, obj.part_link, rng, kinds=kinds,
                         flags=flags)
            pieces._sdf_table = sdf_table  # jit_table's, computed with the arrays
            return pieces
        index: dict = {}  # templates in order of appearance
        Ps, Ts, links, parts, boxes, kind = [], [], [], [], [], []
        for g in table.groups:
            T = table.prim_T[g.prim]
            if g.geom is RectRing:
                sizes, offs = _rect_ring_boxes(g.P)
                Tb = T.repeat(4, axis=0)
                Tb[:, :3, 3] += np.einsum("kij,kj->ki", Tb[:, :3, :3], offs)
                kind.append((index.setdefault(Cuboid, len(index)), len(sizes)))
                Ps.append(sizes)
                Ts.append(Tb)
                links.append(np.repeat(g.link, 4))
                parts.append(np.repeat(g.part, 4))
                boxes.append(Cuboid.bounds_batch(sizes))
            else:
                kind.append((index.setdefault(g.geom, len(index)), len(g.P)))
                Ps.append(g.P)
                Ts.append(T)
                links.append(g.link)
                parts.append(g.part)
                boxes.append(local[g.prim] if local is not None else g.geom.bounds_batch(g.P))
        width = max(P.shape[1] for P in Ps)
        one = len(Ps) == 1
        if one and width == Ps[0].shape[1]:
            params = np.array(Ps[0], dtype=float)
            b = boxes[0]
        else:
            params = np.zeros((sum(len(P) for P in Ps), width))
            k = 0
            for P in Ps:
                params[k:k + len(P), :P.shape[1]] = P
                k += len(P)
            b = np.concatenate(boxes)
        center = 0.5 * (b[:, 0] + b[:, 1])
        half = 0.5 * (b[:, 1] - b[:, 0])
        kinds = (list(index), np.repeat([k for k, _ in kind], [n for _, n in kind]).astype(np.int64))
        return cls(links[0] if one else np.concatenate(links), parts[0] if one else np.concatenate(parts),
                   Ts[0] if one else np.concatenate(Ts), center, half, None, params, part_names, obj.part_link, rng,
                   kinds=kinds)


def _kernels_match() -> bool:
    """:func:`artipg.validate.jit_base.kernels_match` (imported on first use: numba)."""
    if not _KERNELS_MATCH:
        from artipg.validate.jit_base import kernels_match

        _KERNELS_MATCH.append(kernels_match)
    return _KERNELS_MATCH[0]()


#: :func:`artipg.validate.jit_base.kernels_match`, once imported (an import statement
#: per call cost more than the probe's answer).
_KERNELS_MATCH: list = []


#: Small codes of the templates that get per-template flags (0: any other, meshes).
_CODES = {Cuboid: 1, Frustum: 2, Ring: 3, Sphere: 4, Torus: 5}


def stream_seed(rng) -> int:
    """The seed of an object's surface-sample streams: one number drawn from ``rng``
    (a :class:`numpy.random.Generator`), or ``rng`` itself when it is an int."""
    if isinstance(rng, (int, np.integer)):
        return int(rng)
    return int(rng.integers(2 ** 63))


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


def _sample_group(geom, P, rng, want=None):
    """Surface samples of the pieces ``P`` (M, p) of one geometry template, local frames.

    The same draws and arithmetic as ``geom.sample_components(P[r], comp, rng)`` for
    every sample's row ``r`` and component ``comp`` in cell order, with the patch
    tables built once per piece instead of once per sample. With ``want`` (M,) bool,
    only the samples of those pieces are computed: the stream is consumed as for all
    pieces (a family sampler's one draw is taken here and handed to it cut down to
    the wanted samples), so every piece gets the same samples whichever are wanted.
    ``rng`` needs only ``random`` (a :class:`numpy.random.Generator` or a
    :class:`artipg.validate.streams.UniformStream`).

    Returns the points (N, 3), piece by piece in row order (a box's corners and edge
    points after its surface samples), and the count per piece (M,) (zero for the
    pieces not wanted).
    """
    comp_area = geom.component_areas(P)
    M, C = comp_area.shape
    # np.where(area > 0, clip(ceil(area * DENSITY), MIN, MAX), 0), in place
    n = np.ceil(comp_area * DENSITY)
    np.minimum(np.maximum(n, MIN_PER_COMPONENT, out=n), MAX_PER_COMPONENT, out=n)
    n[~(comp_area > 0.0)] = 0.0
    n = n.astype(np.int64)
    per = n.sum(axis=1)
    used = per.nonzero()[0]  # pieces with samples, in order
    if len(used) < M:
        n, Pu = n[used], P[used]
    else:
        Pu = P
    cells = np.arange(len(used) * C).repeat(n.ravel())  # (used piece, component) of each sample
    comp = cells % C
    inv = cells // C
    blocks = geom.patches(Pu)
    lay = _layout(blocks, C)
    if lay.one_per_comp and (lay.complete or (lay.patch[n.any(axis=0)] >= 0).all()):
        # one patch per component: :func:`artipg.geometry.base.pick` returns it (every
        # other weight is zero and u * w < w); its draw is still taken
        rng.random(len(cells))
        which = lay.patch[comp]
    else:  # pick over each sample's component-masked patch areas, cumulated per cell
        area = np.concatenate([b.area for b in blocks])  # (patches, used)
        cum = np.cumsum(np.where(lay.pcomp[None, None, :] == np.arange(C)[None, :, None], area.T[:, None, :], 0.0),
                        axis=2).reshape(len(used) * C, -1)[cells]
        u = rng.random(len(cells)) * cum[:, -1]
        which = (u[:, None] >= cum[:, :-1]).sum(axis=1)
    if want is None:
        take = None
        p = np.empty((len(cells), 3))
    else:
        take = want[used][inv]
        pos = take.cumsum() - 1  # output row of each wanted sample
        p = np.empty((int(pos[-1]) + 1 if len(pos) else 0, 3))
    blk = lay.block[which] if len(blocks) > 1 else None
    for bi, b in enumerate(blocks):  # each family sampler draws only when its block has samples
        sel = (blk == bi).nonzero()[0] if blk is not None else np.arange(len(cells))
        if not len(sel):
            continue
        start = lay.start[bi]
        if take is None:
            p[sel] = _family(b, which[sel] - start, inv[sel], rng)
        elif b.family in _REPLAYABLE:  # compute the wanted samples only, from the same draw
            keep = take[sel]
            uv = rng.random((2, len(sel)))[:, keep]
            sel = sel[keep]
            if len(sel):
                p[pos[sel]] = _family(b, which[sel] - start, inv[sel], _Drawn(uv))
        else:
            keep = take[sel]
            p[pos[sel[keep]]] = _family(b, which[sel] - start, inv[sel], rng)[keep]
    if want is None:
        rows = np.arange(M)
    else:
        per = per * want
        rows = want.nonzero()[0]
    if geom is not Cuboid:
        return p, per
    # corners and edge points: where boxes poke into other solids; after each box's samples
    f = len(_BOX_FEATURES)
    got = per[rows]  # surface samples of each output piece
    out = np.empty((len(p) + f * len(rows), 3))
    out[np.arange(len(p)) + f * np.arange(len(rows)).repeat(got)] = p
    out[(got.cumsum() + f * np.arange(len(rows)))[:, None] + np.arange(f)] = _BOX_FEATURES[None] * P[rows, None, :]
    per[rows] += f
    return out, per


class _Layout(NamedTuple):
    """How a template's patch blocks cover its components (see :func:`_layout`)."""

    pcomp: np.ndarray  # (patches,) component of each patch
    patch: np.ndarray  # (C,) the patch of each component when there is one per component, else -1
    block: np.ndarray  # (patches,) block of each patch
    start: list  # first patch index of each block
    one_per_comp: bool  # no component has two patches
    complete: bool  # every component has a patch
    meta: np.ndarray  # the above as one int64 table (see artipg.validate.jit_samples)


_LAYOUTS: dict = {}


def _layout(blocks, C: int) -> _Layout:
    """The :class:`_Layout` of patch blocks over ``C`` components (cached: it depends
    on the blocks' families and components only)."""
    key = (C,) + tuple((b.family, b.comp.tobytes()) for b in blocks)
    lay = _LAYOUTS.get(key)
    if lay is None:
        pcomp = np.concatenate([b.comp for b in blocks])
        patch = np.full(C, -1)
        patch[pcomp] = np.arange(len(pcomp))
        sizes = [len(b.comp) for b in blocks]
        block = np.arange(len(blocks)).repeat(sizes)
        one, complete = len(set(pcomp.tolist())) == len(pcomp), bool((patch >= 0).all())
        meta = np.concatenate([[C, len(pcomp), len(blocks), one, complete], patch, pcomp, block,
                               [_FAMILY_CODES[b.family] for b in blocks], [b.params.shape[1] for b in blocks],
                               sizes]).astype(np.int64)
        lay = _Layout(pcomp, patch, block, np.cumsum([0] + sizes[:-1]).tolist(), one, complete, meta)
        _LAYOUTS[key] = lay
    return lay


#: Family codes of :attr:`_Layout.meta`, in :data:`artipg.geometry.patches.FAMILIES` order.
_FAMILY_CODES = {"rect": 0, "tri": 1, "sector": 2, "band": 3, "zone": 4, "torus": 5}


def _family(b, patch, row, rng) -> np.ndarray:
    """Points (k, 3) on patches ``patch`` (k,) of block ``b`` of pieces ``row`` (k,)."""
    c, p, m = b.params.shape
    q = b.params.transpose(1, 0, 2).reshape(p, c * m).take(patch * m + row, axis=1)  # (p, k) rows
    return sample_family(b.family, q, rng)[:3].T


#: Patch families whose sampler draws exactly ``rng.random((2, k))``, once.
_REPLAYABLE = frozenset(("rect", "tri", "sector", "band", "zone"))


class _Drawn:
    """Stands in for the generator of a patch sampler whose one draw,
    ``random((2, k))``, was already taken from the real stream: hands back ``uv``
    (2, k), the columns of the samples wanted."""

    def __init__(self, uv: np.ndarray):
        self._uv = uv

    def random(self, size):
        if self._uv is None or tuple(size) != self._uv.shape:
            raise RuntimeError("a patch sampler no longer draws random((2, k)) once; update _REPLAYABLE")
        uv, self._uv = self._uv, None
        return uv


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
