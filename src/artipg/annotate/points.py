"""Labelled surface point clouds sampled analytically from the primitives.

Every primitive's surface is cut into patches of six families (see
:mod:`artipg.geometry.patches`); sampling draws a multinomial count per patch, runs
each family's closed-form sampler once for all its points and maps them to the object
frame with one gathered transform, so the cost hardly grows with the object.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from artipg.geometry.patches import FAMILIES, sample_family
from artipg.rules.streams import streams
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
    return np.stack([wc - wh, wc + wh], axis=1)


@dataclass
class _Group:
    """The primitives of one geometry template (rows in global primitive order)."""

    geom: type
    P: np.ndarray      # (M, p) parameters
    T: np.ndarray      # (M, 4, 4) primitive frame in its link frame
    link: np.ndarray   # (M,) link index
    part: np.ndarray   # (M,) part index (instance id)
    prim: np.ndarray   # (M,) global primitive index

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
    the multinomial draw."""

    name: str
    params: np.ndarray  # (p, K) family parameters, primitive-local frames
    prim: np.ndarray    # (K,) global primitive index
    area: np.ndarray    # (K,) m^2
    start: int
    stop: int


class PrimitiveTable:
    """An object's primitives, grouped by geometry template, in their link frames.

    Attributes
    ----------
    groups : list of _Group
    n_prims : int
    part_semantic : (P,) int64
        Semantic id of every part.
    prim_T : (N, 4, 4)
        Primitive frame in its link frame, by global primitive index.
    prim_link, prim_part : (N,) int64
    """

    def __init__(self, groups: list[_Group], prim_T: np.ndarray, prim_link: np.ndarray,
                 prim_part: np.ndarray, part_semantic: np.ndarray):
        self.groups = groups
        self.n_prims = len(prim_T)
        self.prim_T = prim_T
        self.prim_link = prim_link
        self.prim_part = prim_part
        self.part_semantic = part_semantic

    @classmethod
    def of(cls, obj) -> "PrimitiveTable":
        by_geom: dict[type, tuple[list, list]] = {}
        part_poses, prim_poses, prim_part, prim_link, sem = [], [], [], [], []
        for li, link in enumerate(obj.links):
            for part in link.parts:
                pi = len(part_poses)
                part_poses.append(part.pose)
                sem.append(label_id(part.semantic))
                for prim in part.primitives:
                    rows = by_geom.get(prim.geom)
                    if rows is None:
                        rows = by_geom[prim.geom] = ([], [])
                    rows[0].append(prim.params)
                    rows[1].append(len(prim_poses))
                    prim_poses.append(prim.pose)
                    prim_part.append(pi)
                    prim_link.append(li)
        prim_part = np.array(prim_part, dtype=np.int64)
        prim_link = np.array(prim_link, dtype=np.int64)
        prim_T = np.array(part_poses)[prim_part] @ np.array(prim_poses)
        groups = []
        for geom, (params, idx) in by_geom.items():
            k = np.array(idx, dtype=np.int64)
            groups.append(_Group(geom, np.array(params, dtype=float), prim_T[k], prim_link[k], prim_part[k], k))
        return cls(groups, prim_T, prim_link, prim_part, np.array(sem, dtype=np.int64))

    # ------------------------------------------------------------ patches
    @cached_property
    def families(self) -> list[_Family]:
        """Non-empty patch families in :data:`FAMILIES` order (cells with area > 0)."""
        parts: dict[str, list] = {f: [] for f in FAMILIES}
        for g in self.groups:
            for b in g.geom.patches(g.P):
                c, p, M = b.params.shape
                prim = g.prim if c == 1 else np.tile(g.prim, c)
                parts[b.family].append((b.params.transpose(1, 0, 2).reshape(p, c * M), prim, b.area.reshape(c * M)))
        out = []
        start = 0
        for name, blocks in parts.items():
            if not blocks:
                continue
            area = np.concatenate([b[2] for b in blocks]) if len(blocks) > 1 else blocks[0][2]
            keep = area > 0.0
            if not keep.any():
                continue
            params = np.concatenate([b[0] for b in blocks], axis=1) if len(blocks) > 1 else blocks[0][0]
            prim = np.concatenate([b[1] for b in blocks]) if len(blocks) > 1 else blocks[0][1]
            K = int(keep.sum())
            out.append(_Family(name, params[:, keep], prim[keep], area[keep], start, start + K))
            start += K
        return out

    @cached_property
    def cell_areas(self) -> np.ndarray:
        """Area (K,) of every patch cell, m^2, in family order."""
        return np.concatenate([f.area for f in self.families])

    @cached_property
    def cell_prim(self) -> np.ndarray:
        """Global primitive index (K,) of every patch cell."""
        return np.concatenate([f.prim for f in self.families])

    @cached_property
    def cell_p(self) -> np.ndarray:
        """Multinomial probabilities (K,) of the cells: proportional to area."""
        return self.cell_areas / self.cell_areas.sum()

    def part_cell_p(self, parts) -> np.ndarray:
        """Cell probabilities restricted to the primitives of ``parts`` (instance ids)."""
        keep = np.isin(self.prim_part[self.cell_prim], np.asarray(parts, dtype=np.int64))
        a = np.where(keep, self.cell_areas, 0.0)
        if a.sum() <= 0:
            raise ValueError(f"parts {list(parts)} have no surface")
        return a / a.sum()

    # ------------------------------------------------------------ frames and boxes
    def shift_root(self, S: np.ndarray) -> None:
        """Apply object-frame transform ``S`` to every root-link primitive."""
        for g in self.groups:
            m = g.link == 0
            if m.any():
                g.T[m] = S @ g.T[m]
        m = self.prim_link == 0
        self.prim_T[m] = S @ self.prim_T[m]

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

    The number of points per primitive is multinomial in its surface area, and within
    a primitive points are exactly area-uniform; the result is shuffled.

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
    with streams(seed) as st:
        rng = st.open(SAMPLING_STREAM)
        table = obj.primitive_table
        L = obj.link_poses(qpos)
        cell_p = table.cell_p if parts is None else table.part_cell_p(parts)
        counts = rng.multinomial(n, cell_p)
        local = np.empty((6, n))
        prim = np.empty(n, dtype=np.int64)
        s = 0
        for f in table.families:
            c = counts[f.start:f.stop]
            rows = np.repeat(np.arange(len(c)), c)
            k = len(rows)
            if k:
                local[:, s:s + k] = sample_family(f.name, f.params.take(rows, axis=1), rng)
                prim[s:s + k] = f.prim.take(rows)
                s += k
        perm = rng.permutation(n)
        prim = prim.take(perm)
        x, y, z, nx, ny, nz = local.take(perm, axis=1)
        # one gathered transform in structure-of-arrays layout: rows of the (3, 4) poses
        G = np.ascontiguousarray(table.world_all(L).reshape(-1, 12).T).take(prim, axis=1)
        pts = np.empty((n, 3))
        nrm = np.empty((n, 3))
        for i in range(3):
            r = 4 * i
            pts[:, i] = G[r] * x + G[r + 1] * y + G[r + 2] * z + G[r + 3]
            nrm[:, i] = G[r] * nx + G[r + 1] * ny + G[r + 2] * nz
        part = table.prim_part.take(prim)
    return PointCloud(
        points=pts,
        normals=nrm,
        semantic=table.part_semantic.take(part),
        instance=part,
        link=table.prim_link.take(prim),
        primitive=prim,
        semantic_names=SEMANTIC_LABELS,
        instance_names=tuple(p.name for p in obj.parts),
        link_names=tuple(lk.name for lk in obj.links),
    )
