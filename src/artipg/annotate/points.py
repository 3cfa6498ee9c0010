"""Labelled surface point clouds sampled analytically from the primitives.

Every primitive's surface is cut into patches of six families (see
:mod:`artipg.geometry.patches`); sampling draws three uniforms per point, picks each
point's patch by the inverse CDF of the patch areas, places it with the family's
closed-form sampler and maps it to the object frame (a compiled kernel,
:mod:`artipg.annotate.draw`), so the cost hardly grows with the object.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from functools import cached_property
from itertools import chain
from typing import NamedTuple

import numpy as np

from artipg.geometry.patches import FAMILIES, place_family
from artipg.geometry.prism import Prism
from artipg.rules.streams import streams
from artipg.vocabulary import SEMANTIC_LABELS, label_id


#: Stream key of point sampling (``seed`` is the sampling seed, not the object's).
SAMPLING_STREAM = 0x5A3D1E
#: Family code of each patch family: its position in :data:`FAMILIES` (sampling order).
FAMILY_CODE = {name: i for i, name in enumerate(FAMILIES)}


def transform_boxes(boxes: np.ndarray, W: np.ndarray) -> np.ndarray:
    """Axis-aligned bounds (M, 2, 3) of local boxes ``boxes`` (M, 2, 3) posed by ``W``
    (M, 3 or 4, 4): centre ± |R| · half-extent, exactly the box of the 8 moved corners."""
    c = (boxes[:, 0] + boxes[:, 1]) * 0.5
    h = (boxes[:, 1] - boxes[:, 0]) * 0.5
    R = W[:, :3, :3]
    wc = (R @ c[:, :, None])[:, :, 0] + W[:, :3, 3]
    wh = (np.abs(R) @ h[:, :, None])[:, :, 0]
    out = np.empty((len(boxes), 2, 3))
    np.subtract(wc, wh, out=out[:, 0])
    np.add(wc, wh, out=out[:, 1])
    return out


class _Rows(NamedTuple):
    """The arrays of a :class:`PrimitiveTable` that its groups read (the same objects;
    ``prim_T`` is changed in place only)."""

    flat: np.ndarray
    start: list
    foff: list
    order: np.ndarray
    prim_T: np.ndarray
    prim_link: np.ndarray
    prim_part: np.ndarray


class _Group:
    """The primitives of one geometry template (rows in global primitive order).

    Attributes
    ----------
    geom : type
        The geometry template.
    P : (M, p) ndarray
        Parameters (a view of the table's packed parameters).
    prim : (M,) int64
        Global primitive index of each row.
    T : (M, 4, 4) ndarray
        Primitive frame in its link frame (read from the table's ``prim_T``).
    link, part : (M,) int64
        Link index and part index (instance id).
    """

    def __init__(self, table: "_Rows", geom: type, index: int):
        # the table's arrays, not the table: the table holds its groups, and a reference
        # back would make every table a cycle that only the cyclic GC frees
        self._rows = table
        self.geom = geom
        self._index = index

    @cached_property
    def P(self) -> np.ndarray:
        t, g = self._rows, self._index
        M = t.start[g + 1] - t.start[g]
        a, b = t.foff[g], t.foff[g + 1]
        return t.flat[a:b].reshape(M, (b - a) // M)

    @cached_property
    def prim(self) -> np.ndarray:
        t, g = self._rows, self._index
        return t.order[t.start[g]:t.start[g + 1]]

    @cached_property
    def T(self) -> np.ndarray:
        return self._rows.prim_T[self.prim]

    @cached_property
    def link(self) -> np.ndarray:
        return self._rows.prim_link[self.prim]

    @cached_property
    def part(self) -> np.ndarray:
        return self._rows.prim_part[self.prim]

    @cached_property
    def comp_area(self) -> np.ndarray:
        """(M, C) surface area of each component, m^2."""
        return self.geom.component_areas(self.P)

    @property
    def area(self) -> np.ndarray:
        return self.comp_area.sum(axis=1)


class _Family:
    """The patches of one family over the whole object: the cells ``start:stop`` of
    the point draw.

    Attributes
    ----------
    name : str
    params : (p, K) ndarray
        Family parameters, primitive-local frames.
    prim : (K,) int64
        Global primitive index.
    area : (K,) ndarray
        m^2.
    start, stop : int
    """

    __slots__ = ("name", "start", "stop", "_arrays", "_cells")

    def __init__(self, name: str, params, prim, area, start: int, stop: int, cells: tuple | None = None):
        self.name, self.start, self.stop = name, start, stop
        # from the table's cell arrays (cells), the views are made when first read
        self._arrays = None if cells is not None else (params, prim, area)
        self._cells = cells

    def _array(self, i: int) -> np.ndarray:
        if self._arrays is None:
            _, Q, area, prim = self._cells[:4]
            s, e = self.start, self.stop
            self._arrays = (Q[s:e, :FAMILIES[self.name]].T, prim[s:e], area[s:e])
        return self._arrays[i]

    params = property(lambda self: self._array(0))
    prim = property(lambda self: self._array(1))
    area = property(lambda self: self._array(2))


def _draw():
    """:mod:`artipg.annotate.draw`, imported on first use (it loads numba)."""
    d = sys.modules.get("artipg.annotate.draw")
    if d is None:
        import artipg.annotate.draw as d
    return d


def _kernels():
    """:mod:`artipg.geometry.kernels`, imported on first use (it loads numba); a
    function-level ``from ... import`` costs more than the small kernels it calls."""
    k = sys.modules.get("artipg.geometry.kernels")
    if k is None:
        import artipg.geometry.kernels as k
    return k


#: Geometry templates of a table's groups -> (their codes (G,), the same as a tuple,
#: any ring or torus) for the compiled kernels, or None when one has no compiled twin.
_KERNEL_INFO: dict[tuple, tuple | None] = {}


def _kernel_info(geoms: tuple) -> tuple | None:
    hit = _KERNEL_INFO.get(geoms, False)
    if hit is not False:
        return hit
    from artipg.geometry.kernels import ARC_COLUMN, CODES

    code = [CODES.get(g) for g in geoms]
    info = None
    if code and None not in code:
        info = (np.array(code, dtype=np.int64), tuple(code), any(c in ARC_COLUMN for c in code))
    if len(_KERNEL_INFO) < 4096:  # template combinations: a few dozen
        _KERNEL_INFO[geoms] = info
    return info


class PrimitiveTable:
    """An object's primitives, grouped by geometry template, in their link frames.

    Parameters
    ----------
    geoms : list of type
        The geometry template of each group, in order of first appearance.
    flat : (F,) ndarray
        Parameters of the groups' rows one after the other (row-major within a group).
    start, foff : list of int
        Group g is rows ``start[g]:start[g + 1]`` of ``order`` and ``flat[foff[g]:foff[g + 1]]``.
    order : (N,) int64
        Global primitive index of every row, groups one after the other.
    prim_T, prim_link, prim_part, part_semantic
        The attributes below.
    offsets : ((G + 1,) int64, (G + 1,) int64), optional
        ``foff`` and ``start`` as arrays (made from the lists when not given).

    Attributes
    ----------
    groups : list of _Group
        One per geometry template, in order of first appearance.
    n_prims : int
    part_semantic : (P,) int64
        Semantic id of every part.
    prim_T : (N, 4, 4)
        Primitive frame in its link frame, by global primitive index.
    prim_link, prim_part : (N,) int64
    """

    def __init__(self, geoms: list[type], flat: np.ndarray, start: list[int], foff: list[int], order: np.ndarray,
                 prim_T: np.ndarray, prim_link: np.ndarray, prim_part: np.ndarray, part_semantic: np.ndarray,
                 offsets: tuple | None = None):
        self._geoms = tuple(geoms)
        self._flat = flat
        self._start = start
        self._foff = foff
        self._order = order
        # foff and start as int64 arrays (the kernels' arguments), when the caller has them
        self._offsets = offsets
        self.n_prims = len(prim_T)
        self.prim_T = prim_T
        self.prim_link = prim_link
        self.prim_part = prim_part
        self.part_semantic = part_semantic

    @cached_property
    def groups(self) -> list[_Group]:
        """One :class:`_Group` per geometry template, in order of first appearance (made
        when first read: the sampling path reads the packed arrays instead)."""
        rows = _Rows(self._flat, self._start, self._foff, self._order, self.prim_T, self.prim_link, self.prim_part)
        return [_Group(rows, geom, g) for g, geom in enumerate(self._geoms)]

    @classmethod
    def of(cls, obj) -> "PrimitiveTable":
        """The table of ``obj``'s primitives (parts in link order, primitives in part order)."""
        prims, part_poses, sem, prim_link, prim_part = [], [], [], [], []
        pi = 0
        for li, link in enumerate(obj.links):
            for part in link.parts:
                ps = part.primitives
                k = len(ps)
                part_poses.append(part.pose)
                sem.append(label_id(part.semantic))
                prim_link += [li] * k
                prim_part += [pi] * k
                pi += 1
                prims += ps
        N = len(prims)
        if not prims:
            sem = np.array(sem, dtype=np.int64)
            none = np.zeros(0, dtype=np.int64)
            return cls([], np.zeros(0), [0], [0], none, np.zeros((0, 4, 4)), none, none, sem)
        geoms, params, poses = list(zip(*prims))[:3]
        # rows of each geometry template, templates in order of first appearance
        first = dict.fromkeys(geoms)
        if len(first) == 1:
            start, idx = [0, N], range(N)
            rows = params
        else:
            by_group: list[list[int]] = [[] for _ in first]
            for i, j in enumerate(map(dict(zip(first, range(len(first)))).__getitem__, geoms)):
                by_group[j].append(i)
            start = [0]
            for r in by_group:
                start.append(start[-1] + len(r))
            idx = [i for r in by_group for i in r]
            rows = [params[i] for i in idx]
        # every row of a group has its template's parameter count (numpy would refuse ragged rows)
        foff = [0]
        for g in range(len(first)):
            width = len(rows[start[g]])
            foff.append(foff[-1] + width * (start[g + 1] - start[g]))
        if sum(map(len, rows)) != foff[-1]:
            raise ValueError("primitives of one geometry template have different parameter counts")
        flat = np.fromiter(chain.from_iterable(rows), float, foff[-1])
        # the index arrays are slices of one int64 array (one conversion instead of six):
        # link, part, row order (N each), semantic ids (P), foff and start (G + 1 each)
        P, G1 = len(sem), len(foff)
        ints = np.fromiter(chain(prim_link, prim_part, idx, sem, foff, start), np.int64, 3 * N + P + 2 * G1)
        prim_part = ints[N:2 * N]
        # the part poses then the primitive poses in one concatenation (concatenating
        # (4, 4) arrays is about twice as fast as np.array on a list of them)
        X = np.concatenate(part_poses + list(poses)).reshape(-1, 4, 4)
        prim_T = X[prim_part] @ X[P:]
        e = 3 * N + P
        table = cls(list(first), flat, start, foff, ints[2 * N:3 * N], prim_T, ints[:N], prim_part, ints[3 * N:e],
                    (ints[e:e + G1], ints[e + G1:]))
        table._n_root = prim_link.count(0)
        return table

    # ------------------------------------------------------------ patches
    @cached_property
    def _packed(self) -> tuple | None:
        """The groups as the compiled kernels (:mod:`artipg.geometry.kernels`) take them:
        (packed parameters (F,), their group offsets (G + 1,), group row offsets
        (G + 1,), global primitive index of each row (N,), template codes (G,), numpy's
        cos and sin of the packed parameters (F,)); None when a template has no
        compiled twin."""
        return self._pack()

    def _pack(self) -> tuple | None:
        """:attr:`_packed`, computed."""
        info = _kernel_info(self._geoms)
        if info is None:
            return None
        code, _, arcs = info
        flat = self._flat
        # the arcs of rings and tori are the only parameters whose cos and sin are read
        trig = (np.cos(flat), np.sin(flat)) if arcs else (flat, flat)
        foff, start = self._offsets or (np.array(self._foff), np.array(self._start))
        return (flat, foff, start, self._order, code) + trig

    def _compiled_boxes(self) -> bool:
        """Whether local boxes and bounds take the compiled path: once numba is loaded
        (by the patch families, the point draw or the checks), so that a process that
        only generates objects never waits for numba's start (the results are the same)."""
        if "numba" not in sys.modules:
            return False
        # the cached value read directly: functools.cached_property's first access takes
        # a lock (Python 3.11), a few microseconds on every new object
        d = self.__dict__
        packed = d["_packed"] if "_packed" in d else d.setdefault("_packed", self._pack())
        return packed is not None

    @cached_property
    def _cells(self) -> tuple:
        """(family code (K,), parameter rows (K, 15), areas (K,), primitives (K,),
        running area sums (K,), cells per family (6,) list) of the patch cells, from
        the compiled kernel, or from :meth:`_plain_families` without one."""
        packed = self._packed
        if packed is None:
            return self._cells_of(self._plain_families())
        *arrays, counts = _kernels().cell_arrays(*packed)
        return (*arrays, counts.tolist())

    @staticmethod
    def _cells_of(fams: list) -> tuple:
        """:attr:`_cells` of the families ``fams``."""
        K = fams[-1].stop if fams else 0
        code = np.empty(K, dtype=np.int64)
        Q = np.zeros((K, max(FAMILIES.values())))
        counts = [0] * len(FAMILIES)
        for f in fams:
            c = FAMILY_CODE[f.name]
            code[f.start:f.stop] = c
            Q[f.start:f.stop, :len(f.params)] = f.params.T
            counts[c] = f.stop - f.start
        if len(fams) == 1:
            area, prim = fams[0].area, fams[0].prim
        elif fams:
            area, prim = np.concatenate([f.area for f in fams]), np.concatenate([f.prim for f in fams])
        else:
            area, prim = np.zeros(0), np.zeros(0, dtype=np.int64)
        return code, Q, area, prim, np.cumsum(area), counts

    @cached_property
    def families(self) -> list[_Family]:
        """Non-empty patch families in :data:`FAMILIES` order (cells with area > 0)."""
        if self._packed is None:
            return self._plain_families()
        cells = self._cells
        out = []
        start = 0
        for name, k in zip(FAMILIES, cells[5]):
            if k:
                out.append(_Family(name, None, None, None, start, start + k, cells))
                start += k
        return out

    def _plain_families(self) -> list[_Family]:
        """:attr:`families` from the templates' ``patches`` (numpy): the definition."""
        found: dict[str, list] = {}
        for g in self.groups:
            for b in g.geom.patches(g.P):
                found.setdefault(b.family, []).append((b, g.prim))
        out = []
        start = 0
        for name in FAMILIES:
            blocks = found.get(name)
            if blocks is None:
                continue
            params, area, prim = [], [], []
            for b, gprim in blocks:
                c, p, M = b.params.shape
                params.append(b.params.transpose(1, 0, 2).reshape(p, c * M))
                area.append(b.area.reshape(c * M))
                cp = np.empty((c, M), dtype=np.int64)
                cp[:] = gprim
                prim.append(cp.reshape(c * M))
            if len(blocks) > 1:
                params = np.concatenate(params, axis=1)
                area, prim = np.concatenate(area), np.concatenate(prim)
            else:
                params, area, prim = params[0], area[0], prim[0]
            keep = area > 0.0
            K = int(np.count_nonzero(keep))
            if K == 0:
                continue
            if K < len(keep):
                params, area, prim = params[:, keep], area[keep], prim[keep]
            out.append(_Family(name, params, prim, area, start, start + K))
            start += K
        return out

    @property
    def cell_areas(self) -> np.ndarray:
        """Area (K,) of every patch cell, m^2, in family order."""
        return self._cells[2]

    @property
    def cell_prim(self) -> np.ndarray:
        """Global primitive index (K,) of every patch cell."""
        return self._cells[3]

    @property
    def cell_rows(self) -> tuple[np.ndarray, np.ndarray]:
        """Family code (K,) and parameters (K, 15) of every patch cell, one row per cell
        (zero-padded past the family's parameter count): the draw kernel's layout."""
        return self._cells[:2]

    @property
    def cell_cdf(self) -> np.ndarray:
        """Running sum (K,) of :attr:`cell_areas`, m^2 (``np.cumsum``)."""
        return self._cells[4]

    @cached_property
    def cell_p(self) -> np.ndarray:
        """Probabilities (K,) of the cells: proportional to area."""
        a = self._cells[2]
        return a / a.sum()

    def part_cell_p(self, parts) -> np.ndarray:
        """Cell probabilities restricted to the primitives of ``parts`` (instance ids)."""
        keep = np.isin(self.prim_part[self.cell_prim], np.asarray(parts, dtype=np.int64))
        a = np.where(keep, self.cell_areas, 0.0)
        if a.sum() <= 0:
            raise ValueError(f"parts {list(parts)} have no surface")
        return a / a.sum()

    # ------------------------------------------------------------ frames and boxes
    def shift_root(self, S: np.ndarray, moved: np.ndarray | None = None) -> None:
        """Apply object-frame transform ``S`` to every root-link primitive; ``moved``, when
        given, is the product ``S @ prim_T[:n]`` (n, 4, 4) already computed (n root
        primitives)."""
        n = self._n_root
        self.prim_T[:n] = S @ self.prim_T[:n] if moved is None else moved
        for g in self.__dict__.get("groups", ()):
            g.__dict__.pop("T", None)

    @cached_property
    def _n_root(self) -> int:
        """Number of root-link primitives: they come first (parts are in link order)."""
        n = int(np.count_nonzero(self.prim_link == 0))
        if not (self.prim_link[:n] == 0).all():
            raise ValueError("primitives are not in link order")
        return n

    def world_all(self, link_poses: np.ndarray) -> np.ndarray:
        """Poses (M, 3, 4) of all primitives in the object frame, by global index."""
        return (link_poses[self.prim_link] @ self.prim_T)[:, :3]

    def world(self, link_poses: np.ndarray) -> list[np.ndarray]:
        """Per-group primitive poses (M, 4, 4) in the object frame."""
        return [link_poses[g.link] @ g.T for g in self.groups]

    @cached_property
    def local_boxes(self) -> np.ndarray:
        """Bounding box (N, 2, 3) of every primitive in its own frame, by global index."""
        if not self._compiled_boxes():
            return self._plain_local_boxes()
        return self._compiled_local_boxes()

    def _compiled_local_boxes(self) -> np.ndarray:
        """:attr:`local_boxes` from the compiled kernel, cached with
        :attr:`_local_centre_half` (compiled path only)."""
        k = _kernels()
        out = np.empty((self.n_prims, 2, 3))
        ch = np.empty((2, self.n_prims, 3))
        if not k.local_boxes(*self.__dict__["_packed"], out, ch):  # a prism side count off the kernel's table
            for g, c in zip(self.groups, _kernel_info(self._geoms)[1]):
                if c == k.CODES[Prism]:
                    b = out[g.prim] = g.geom.bounds_batch(g.P)
                    ch[0, g.prim] = (b[:, 0] + b[:, 1]) * 0.5
                    ch[1, g.prim] = (b[:, 1] - b[:, 0]) * 0.5
        d = self.__dict__
        d["local_boxes"] = out
        d["_local_centre_half"] = ch
        return out

    def _plain_local_boxes(self) -> np.ndarray:
        """:attr:`local_boxes` from the templates' ``bounds_batch`` (numpy): the definition."""
        out = np.empty((self.n_prims, 2, 3))
        for g in self.groups:
            out[g.prim] = g.geom.bounds_batch(g.P)
        return out

    def world_boxes(self, link_poses: np.ndarray) -> np.ndarray:
        """Bounding boxes (N, 2, 3) of all primitives in the object frame."""
        return transform_boxes(self.local_boxes, self.world_all(link_poses))

    def bounds(self, link_poses: np.ndarray) -> np.ndarray:
        """Bounding box (2, 3) of all primitives in the object frame (union of their
        transformed local boxes: exact for boxes, loose for rotated round solids)."""
        out = np.empty((2, 3))
        if not self._compiled_boxes():
            b = self.world_boxes(link_poses)
            b[:, 0].min(axis=0, out=out[0])
            b[:, 1].max(axis=0, out=out[1])
            return out
        # transform_boxes and the union, with its two matrix products left to numpy (BLAS)
        W = self.world_all(link_poses)
        d = self.__dict__
        if "_local_centre_half" not in d and "local_boxes" not in d:
            self._compiled_local_boxes()  # sets both, without the cached_property machinery
        ch = self._local_centre_half
        # R c and |R| h as one stacked product: each (3, 3) @ (3, 1) item is the same BLAS
        # call as in two products, one numpy call fewer
        R = np.empty((2, self.n_prims, 3, 3))
        R[0] = W[:, :, :3]
        np.abs(R[0], out=R[1])
        Rc, Rh = R @ ch[:, :, :, None]
        _kernels().box_union(Rc, Rh, W, out)
        return out

    @cached_property
    def _local_centre_half(self) -> np.ndarray:
        """Centres and half extents (2, N, 3) of :attr:`local_boxes` (compiled path only;
        the compiled :attr:`local_boxes` sets them with the boxes)."""
        boxes = self.local_boxes
        ch = self.__dict__.get("_local_centre_half")
        if ch is None:
            ch = np.empty((2, self.n_prims, 3))
            _kernels().centre_half(boxes, ch)
        return ch


@dataclass
class PointCloud:
    """Labelled surface points in the object frame.

    Attributes
    ----------
    points, normals : (N, 3) float64
        Positions (metres) and outward unit normals.
    semantic : (N,) int64
        Index into :data:`artipg.vocabulary.SEMANTIC_LABELS`.
    instance : (N,) int64
        Part instance id (index into ``instance_names`` / ``obj.parts``).
    link : (N,) int64
        Link index (index into ``link_names``).
    primitive : (N,) int64
        Global primitive index (parts' primitives in order).
    semantic_names, instance_names, link_names : tuple of str
    """

    points: np.ndarray
    normals: np.ndarray
    semantic: np.ndarray
    instance: np.ndarray
    link: np.ndarray
    primitive: np.ndarray
    semantic_names: tuple
    instance_names: tuple
    link_names: tuple


def sample_points(obj, n: int = 2048, seed: int = 0, qpos=None, parts=None) -> PointCloud:
    """Sample ``n`` area-uniform labelled surface points of ``obj`` at ``qpos``.

    The points are independent: each picks a patch cell with probability proportional
    to its area (so points per primitive are multinomial in area, in random order) and
    is placed exactly area-uniformly on it, from three uniforms per point (one draw of
    ``3 n`` on the sampling stream of ``seed``, made in the compiled draw; see
    :func:`draw_plain` and :mod:`artipg.annotate.draw`).

    Parameters
    ----------
    obj : ArticulatedObject
    n : int
        Number of points.
    seed : int
        Seed of the sampling stream (independent of the object's seed).
    qpos : None, dict or sequence
        Joint state (see :meth:`ArticulatedObject.qpos_dict`).
    parts : sequence of int, optional
        Sample only the surfaces of these parts (instance ids), area-uniformly.
    """
    draw = _draw()
    table = obj.primitive_table
    out = np.empty((2, n, 3))
    labels = np.empty((4, n), dtype=np.int64)
    if parts is None and draw.PCG64_MATCHES and "_cells" not in table.__dict__ and table._packed is not None:
        # the cells made in the draw and not kept: boxing them for the table costs more
        # than making them again when they are asked for
        if not draw.draw_table(*table._packed, table.world_all(obj.link_poses(qpos)), table.prim_part,
                               table.prim_link, table.part_semantic, draw.stream_words(seed, SAMPLING_STREAM),
                               out, labels):
            raise ValueError("the object has no surface to sample")
    else:
        weight = table.cell_areas if parts is None else table.part_cell_p(parts)
        if not len(weight):
            raise ValueError("the object has no surface to sample")
        code, Q = table.cell_rows
        args = (weight, code, Q, table.world_all(obj.link_poses(qpos)), table.cell_prim, table.prim_part,
                table.prim_link, table.part_semantic, out, labels)
        if draw.PCG64_MATCHES:  # the uniforms drawn in the kernel: the same doubles
            draw.draw_stream(draw.stream_words(seed, SAMPLING_STREAM), *args)
        else:
            with streams(seed) as st:
                U = st.open(SAMPLING_STREAM).random((3, n))
            draw.draw_kernel(U, *args)
    links = obj.links
    # positional: points, normals, semantic, instance, link, primitive and the names
    return PointCloud(out[0], out[1], labels[2], labels[1], labels[3], labels[0], SEMANTIC_LABELS,
                      tuple([p.name for lk in links for p in lk.parts]), tuple([lk.name for lk in links]))


def draw_plain(U, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out, labels) -> None:
    """The point draw in numpy: the definition that :func:`artipg.annotate.draw.draw_kernel`
    (same arguments, same bits) compiles.

    Point j takes the first cell whose cumulative weight exceeds ``U[0, j]`` times the
    total weight and is placed on it by :func:`artipg.geometry.patches.place_family`
    with ``u = U[1, j]``, ``v = U[2, j]``: directly in the object frame for the planar
    families, whose cell parameters are posed first by the primitive's pose ``W``
    (N, 3, 4); in the primitive's frame, then posed, for the others. Writes positions
    and normals into ``out`` (2, n, 3) and primitive, part, semantic id and link into
    ``labels`` (4, n).
    """
    cum = np.cumsum(weight)
    cell = np.searchsorted(cum, U[0] * cum[-1], side="right")
    fam = code[cell]
    prim = cell_prim[cell]
    pts, nrm = out
    local = np.empty((6, U.shape[1]))
    for name, f in FAMILY_CODE.items():
        idx = np.flatnonzero(fam == f)
        if not len(idx):
            continue
        q = Q[cell[idx], :FAMILIES[name]]
        if f <= _PLANAR:
            posed = _pose_planar(q, W[prim[idx]])
            xyz = place_family(name, posed.T, U[1, idx], U[2, idx])
            pts[idx] = xyz[:3].T
            nrm[idx] = xyz[3:].T
        else:
            local[:, idx] = place_family(name, q.T, U[1, idx], U[2, idx])
    idx = np.flatnonzero(fam > _PLANAR)
    G = W[prim[idx]]  # (m, 3, 4)
    x, y, z, nx, ny, nz = local[:, idx, None]
    pts[idx] = ((G[:, :, 0] * x + G[:, :, 1] * y) + G[:, :, 2] * z) + G[:, :, 3]
    nrm[idx] = (G[:, :, 0] * nx + G[:, :, 1] * ny) + G[:, :, 2] * nz
    part = prim_part[prim]
    labels[0] = prim
    labels[1] = part
    labels[2] = part_semantic[part]
    labels[3] = prim_link[prim]


#: Families up to this code (rect, tri, sector) are affine in their o, a, b, n: the draw
#: poses their parameters instead of their points.
_PLANAR = FAMILY_CODE["sector"]


def _pose_planar(q: np.ndarray, G: np.ndarray) -> np.ndarray:
    """Rect, tri or sector parameters ``q`` (m, p) posed by ``G`` (m, 3, 4): o as a point,
    a, b and n as directions (the rest copied)."""
    out = q.copy()
    for r in range(0, 12, 3):
        x, y, z = q[:, r:r + 1], q[:, r + 1:r + 2], q[:, r + 2:r + 3]  # (m, 1) each
        out[:, r:r + 3] = (G[:, :, 0] * x + G[:, :, 1] * y) + G[:, :, 2] * z
    out[:, 0:3] += G[:, :, 3]
    return out
