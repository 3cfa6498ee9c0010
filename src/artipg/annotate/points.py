"""Labelled surface point clouds sampled analytically from the primitives.

Every primitive's surface is cut into patches of six families (see
:mod:`artipg.geometry.patches`); sampling picks each point's patch cell with
probability proportional to its area and places it with the family's sampler
(:func:`artipg.geometry.patches.sample_family`, the one sampler of each family), then
maps it to the object frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from itertools import chain
from typing import NamedTuple

import numpy as np

from artipg.geometry.patches import FAMILIES, sample_family
from artipg.rules.streams import stream
from artipg.vocabulary import SEMANTIC_LABELS, label_id


#: Stream key of point sampling (``seed`` is the sampling seed, not the object's).
SAMPLING_STREAM = 0x5A3D1E

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


@dataclass
class _Family:
    """The patches of one family over the whole object: the cells ``start:stop`` of
    the table.

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

    name: str
    params: np.ndarray
    prim: np.ndarray
    area: np.ndarray
    start: int
    stop: int


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
                 prim_T: np.ndarray, prim_link: np.ndarray, prim_part: np.ndarray, part_semantic: np.ndarray):
        self._geoms = tuple(geoms)
        self._flat = flat
        self._start = start
        self._foff = foff
        self._order = order
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
        prim_part = np.array(prim_part, dtype=np.int64)
        X = np.concatenate(part_poses + list(poses)).reshape(-1, 4, 4)
        prim_T = X[prim_part] @ X[len(sem):]
        return cls(list(first), flat, start, foff, np.array(idx, dtype=np.int64), prim_T,
                   np.array(prim_link, dtype=np.int64), prim_part, np.array(sem, dtype=np.int64))

    # ------------------------------------------------------------ patches
    @cached_property
    def families(self) -> list[_Family]:
        """Non-empty patch families in :data:`FAMILIES` order (cells with area > 0),
        from the templates' ``patches``."""
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

    @cached_property
    def regions(self) -> list[tuple]:
        """Faces the families sample by rejection (flat faces bounded by arcs), one
        ``(draw, row, prim, area)`` per face and primitive: ``draw(row, k, rng)`` gives
        (6, k) points and normals. They follow the patch cells in the cell order."""
        out = []
        for g in self.groups:
            regions = getattr(g.geom, "regions", None)
            if regions is None:
                continue
            for r in regions(g.P):
                for j in np.flatnonzero(np.asarray(r.area) > 0.0):
                    out.append((r.draw, g.P[j], int(g.prim[j]), float(r.area[j])))
        return out

    @cached_property
    def cell_areas(self) -> np.ndarray:
        """Area (K,) of every patch cell, m^2, in family order, then the rejection-sampled
        faces of :attr:`regions`."""
        parts = [f.area for f in self.families] + [np.array([r[3] for r in self.regions])]
        return np.concatenate(parts)

    @cached_property
    def cell_prim(self) -> np.ndarray:
        """Global primitive index (K,) of every patch cell (then of every region face)."""
        parts = [f.prim for f in self.families] + [np.array([r[2] for r in self.regions], dtype=np.int64)]
        return np.concatenate(parts)

    @cached_property
    def cell_p(self) -> np.ndarray:
        """Probabilities (K,) of the cells: proportional to area."""
        a = self.cell_areas
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
        b = self.world_boxes(link_poses)
        return np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


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
    is placed area-uniformly on it by :func:`artipg.geometry.patches.sample_family`,
    all from the sampling stream of ``seed``.

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
    table = obj.primitive_table
    weight = table.cell_areas if parts is None else table.part_cell_p(parts)
    if not len(weight) or not weight.sum() > 0.0:
        raise ValueError("the object has no surface to sample")
    rng = stream(seed, SAMPLING_STREAM)
    cum = np.cumsum(weight)
    cell = np.minimum(np.searchsorted(cum, rng.random(n) * cum[-1], side="right"), len(cum) - 1)
    local = np.empty((6, n))
    for f in table.families:
        idx = np.flatnonzero((cell >= f.start) & (cell < f.stop))
        if len(idx):
            local[:, idx] = sample_family(f.name, f.params[:, cell[idx] - f.start], rng)
    first = table.families[-1].stop if table.families else 0
    for j, (draw, row, _, _) in enumerate(table.regions):
        idx = np.flatnonzero(cell == first + j)
        if len(idx):
            local[:, idx] = draw(row, len(idx), rng)
    prim = table.cell_prim[cell]
    W = table.world_all(obj.link_poses(qpos))[prim]  # (n, 3, 4)
    R = W[:, :, :3]
    points = np.einsum("nij,jn->ni", R, local[:3]) + W[:, :, 3]
    normals = np.einsum("nij,jn->ni", R, local[3:])
    part = table.prim_part[prim]
    links = obj.links
    return PointCloud(points, normals, table.part_semantic[part], part, table.prim_link[prim], prim,
                      SEMANTIC_LABELS, tuple([p.name for lk in links for p in lk.parts]),
                      tuple([lk.name for lk in links]))
