"""Parallel-jaw grasp poses at any joint state, checked against a two-finger gripper.

Grasps are defined on the part templates (:class:`artipg.model.part.Grasp`, part
frame) and mapped to the object frame with the part's pose at ``qpos``. Each one gets

- a collision check of a simple gripper model (two finger boxes and a palm box, see
  :class:`Gripper`) against the exact SDFs of all the object's primitives, the
  grasped part included;
- the direction that opens the part: for a revolute (or continuous) joint the tangent
  of the grasp point's circle about the joint axis, for a prismatic joint the joint
  axis, both pointing towards increasing joint value when the joint opens that way
  (the side of 0 with the larger range); the part's joint is the nearest movable
  joint at or above its link. Parts on the root link use the template's ``open_dir``.

Gripper frame (as on the templates): +z is the approach direction (towards the part),
+y the axis along which the jaws close, origin between the finger tips (as
:class:`artipg.model.part.Grasp` defines it).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from artipg.annotate.sdf import primitive_params


@dataclass(frozen=True)
class Gripper:
    """A two-finger parallel gripper made of three boxes (metres, gripper frame).

    Fingers are ``finger_thickness`` thick along y with their inner faces at
    ``y = ±width / 2``, ``finger_width`` wide along x and ``finger_length`` long along
    z, their tips ``tip_depth`` beyond the origin (0: the tips are at the origin, the
    convention of :class:`artipg.model.part.Grasp`); the palm closes them off behind.
    Defaults are close to a Franka Panda hand.
    """

    finger_length: float = 0.045
    finger_width: float = 0.018
    finger_thickness: float = 0.01
    tip_depth: float = 0.0
    palm_thickness: float = 0.02
    palm_width: float = 0.06

    def boxes(self, width: float) -> np.ndarray:
        """The three boxes (3, 2, 3) as (lo, hi) corners in the gripper frame."""
        w, t = width / 2, self.finger_thickness
        z0, z1 = self.tip_depth - self.finger_length, self.tip_depth
        fx = self.finger_width / 2
        py = max(w + t, self.palm_width / 2)
        return np.array([
            [[-fx, w, z0], [fx, w + t, z1]],
            [[-fx, -w - t, z0], [fx, -w, z1]],
            [[-fx, -py, z0 - self.palm_thickness], [fx, py, z0]],
        ])

    def closing_box(self, width: float) -> np.ndarray:
        """The volume swept by the closing fingers (2, 3), gripper frame."""
        return np.array([[-self.finger_width / 2, -width / 2, self.tip_depth - self.finger_length],
                         [self.finger_width / 2, width / 2, self.tip_depth]])


DEFAULT_GRIPPER = Gripper()


def box_surface_grid(boxes: np.ndarray, spacing: float) -> tuple[np.ndarray, np.ndarray]:
    """Regular grid points (K, 3) on the faces of boxes (B, 2, 3), at most ``spacing``
    apart along each edge direction, and the box index (K,) of each point.

    Every point of a face is within ``spacing * sqrt(2) / 2`` of a grid point.
    """
    boxes = np.asarray(boxes, dtype=float)
    lo, span = boxes[:, 0], boxes[:, 1] - boxes[:, 0]
    n = np.maximum(2, np.ceil(span / spacing).astype(int) + 1)
    u, idx = _surface_lattices(tuple(map(tuple, n.tolist())))
    return lo[idx] + u * span[idx], idx.copy()


@lru_cache(maxsize=1024)
def _surface_lattices(counts: tuple) -> tuple[np.ndarray, np.ndarray]:
    """The lattices of :func:`_surface_lattice` for boxes of ``counts`` ((nx, ny, nz)
    per box) stacked (K, 3), and the box index (K,) of each point (read-only)."""
    parts = [_surface_lattice(*c) for c in counts]
    u = np.concatenate(parts) if parts else np.zeros((0, 3))
    idx = np.repeat(np.arange(len(parts)), [len(p) for p in parts])
    u.flags.writeable = idx.flags.writeable = False
    return u, idx


@lru_cache(maxsize=1024)
def _surface_lattice(nx: int, ny: int, nz: int) -> np.ndarray:
    """Points (K, 3) of the regular nx x ny x nz lattice of the unit cube that lie on
    its faces."""
    n = np.array([nx, ny, nz])
    ijk = np.stack(np.meshgrid(np.arange(nx), np.arange(ny), np.arange(nz), indexing="ij"), axis=-1).reshape(-1, 3)
    u = ijk[np.any((ijk == 0) | (ijk == n - 1), axis=1)] / (n - 1)
    u.flags.writeable = False
    return u


@dataclass
class WorldGrasps:
    """Grasps of an object at one joint state (object frame, metres).

    Attributes
    ----------
    pose : (G, 4, 4) float64
        Gripper frames (+z approach, +y jaw axis, origin between the finger tips).
    width : (G,) float64
        Jaw opening.
    approach : (G, 3) float64
        Approach direction (``pose[:, :3, 2]``).
    open_dir : (G, 3) float64
        Unit direction in which moving the grasp point opens the part (zeros when
        unknown).
    part : (G,) int64
        Instance id of the grasped part.
    joint : (G,) int64
        Index into ``obj.joints`` of the joint that moves the part, -1 if none.
    lever : (G,) float64
        Distance of the grasp point from a revolute joint's axis (0 otherwise).
    collision_free : (G,) bool
        Whether the gripper model at that pose clears the whole object.
    clearance : (G,) float64
        Smallest signed distance from the gripper's sample grid to the object.
    """

    pose: np.ndarray
    width: np.ndarray
    approach: np.ndarray
    open_dir: np.ndarray
    part: np.ndarray
    joint: np.ndarray
    lever: np.ndarray
    collision_free: np.ndarray
    clearance: np.ndarray

    def __len__(self) -> int:
        return len(self.width)

    def subset(self, m) -> "WorldGrasps":
        """The grasps selected by the mask or index array ``m``."""
        return WorldGrasps(*(getattr(self, f)[m] for f in self.__dataclass_fields__))


def part_joint(obj) -> np.ndarray:
    """Index into ``obj.joints`` of the nearest movable joint at or above each part's
    link (-1 for parts that only move with the root)."""
    links = obj.links
    idx = obj.link_index
    jindex = {j.name: i for i, j in enumerate(obj.joints)}
    link_joint = np.full(len(links), -1, dtype=np.int64)
    for li, link in enumerate(links[1:], start=1):  # topological order: parent first
        j = link.joint
        link_joint[li] = jindex[j.name] if j.movable else link_joint[idx[j.parent]]
    return link_joint[obj.part_link]


def _opening_sign(joint) -> float:
    lo, hi = joint.limits
    if not np.isfinite(lo) or not np.isfinite(hi):
        return 1.0
    return 1.0 if hi >= -lo else -1.0


def world_grasps(obj, qpos=None, check: bool = True, gripper: Gripper = DEFAULT_GRIPPER, spacing: float = 0.004,
                 min_lever: float = 0.25) -> WorldGrasps:
    """All template grasps of ``obj`` in the object frame at ``qpos``.

    Parameters
    ----------
    obj : ArticulatedObject
    qpos : None, dict or sequence
        Joint state.
    check : bool
        Run the gripper collision check (otherwise ``collision_free`` is all True and
        ``clearance`` all +inf).
    gripper : Gripper
        The gripper model.
    spacing : float
        Grid spacing (metres) of the points on the faces of the gripper boxes. A
        grasp is collision-free when every grid point is farther than
        ``spacing * sqrt(2) / 2`` from the object: then no face of a box meets the
        object (the SDF is 1-Lipschitz), so the boxes are clear unless a whole
        primitive hides inside a finger. The test is conservative by up to that
        distance (about 3 mm by default).
    min_lever : float
        Grasps on a revolute part closer to the joint axis than ``min_lever`` times
        the largest lever among that part's grasps (e.g. on a door's hinge edge)
        cannot open it and are left out.

    Returns
    -------
    WorldGrasps
    """
    poses = obj.part_poses(qpos)
    L = obj.link_poses(qpos)
    pj = part_joint(obj)
    rows = [(i, g) for i, part in enumerate(obj.parts) for g in part.grasps]
    G = len(rows)
    if G == 0:
        z = np.zeros((0, 3))
        return WorldGrasps(np.zeros((0, 4, 4)), np.zeros(0), z, z, np.zeros(0, np.int64), np.zeros(0, np.int64),
                           np.zeros(0), np.zeros(0, bool), np.zeros(0))
    # stacked products: the same product per grasp as one call each, so the same numbers
    part = np.array([i for i, _ in rows], dtype=np.int64)
    Pp = poses[part]
    T = Pp @ np.stack([np.asarray(g.pose, dtype=float) for _, g in rows])
    width = np.array([float(g.width) for _, g in rows])
    open_dir = (Pp[:, :3, :3] @ np.stack([np.asarray(g.open_dir, dtype=float) for _, g in rows])[:, :, None])[:, :, 0]
    joint = pj[part]
    lever = np.zeros(G)
    moved = np.flatnonzero(joint >= 0)
    if len(moved):
        axis, sign, prismatic, origin = {}, {}, {}, {}
        for ji in set(joint[moved].tolist()):
            j = obj.joints[ji]
            Tj = L[obj.link_index[j.child]]  # joint frame at q (the child link frame)
            axis[ji], origin[ji] = Tj[:3, :3] @ j.axis, Tj[:3, 3]
            sign[ji], prismatic[ji] = _opening_sign(j), j.type == "prismatic"
        js = joint[moved].tolist()
        a = np.stack([axis[ji] for ji in js])
        sg = np.array([sign[ji] for ji in js])[:, None]
        slide = np.array([prismatic[ji] for ji in js], dtype=bool)
        open_dir[moved[slide]] = sg[slide] * a[slide]
        turn = ~slide
        if turn.any():
            k = moved[turn]
            t = np.cross(a[turn], T[k, :3, 3] - np.stack([origin[ji] for ji, on in zip(js, turn) if on]))
            lever[k] = [np.sqrt(np.dot(v, v)) for v in t]  # np.linalg.norm of each, as it computes it
            on_axis = lever[k] > 1e-6  # on the axis (a knob's centre) keep the template's direction
            open_dir[k[on_axis]] = sg[turn][on_axis] * t[on_axis] / lever[k[on_axis]][:, None]
    n = np.linalg.norm(open_dir, axis=1)
    open_dir = np.where(n[:, None] > 1e-12, open_dir / np.maximum(n, 1e-12)[:, None], 0.0)
    longest = np.zeros(len(obj.parts))
    np.maximum.at(longest, part, lever)
    revolute = np.array([j >= 0 and obj.joints[j].type in ("revolute", "continuous") for j in joint], dtype=bool)
    keep = ~revolute | (lever >= min_lever * longest[part])
    out = WorldGrasps(T, width, T[:, :3, 2].copy(), open_dir, part, joint, lever, np.ones(G, bool),
                      np.full(G, np.inf)).subset(keep)
    if check and len(out):
        out.clearance = gripper_clearance(obj, out.pose, out.width, qpos, gripper, spacing)
        out.collision_free = out.clearance > collision_margin(spacing)
    return out


def collision_margin(spacing: float) -> float:
    """Clearance (metres) a grid of ``spacing`` must show for the boxes to be clear."""
    return spacing * np.sqrt(2.0) / 2.0


def gripper_points(pose: np.ndarray, width: np.ndarray, gripper: Gripper = DEFAULT_GRIPPER, spacing: float = 0.004
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Grid points (K, 3) on the faces of every grasp's gripper boxes, object frame,
    and the grasp index (K,) of each point (each grasp's points are contiguous)."""
    G = len(width)
    grids = [_gripper_grid(gripper, round(float(w), 6), spacing) for w in width]
    count = np.array([g.shape[1] for g in grids], dtype=np.int64)
    grasp = np.repeat(np.arange(G), count)
    if not G:
        return np.zeros((0, 3)), grasp
    g = np.concatenate(grids, axis=1)  # (3, K) gripper-frame coordinates, grasp after grasp
    # each point's R[j, 0], R[j, 1], R[j, 2], t[j] (j = 0, 1, 2): rows (12, K)
    A = np.repeat(np.ascontiguousarray(pose[:, :3, :].reshape(G, 12).T), count, axis=1)
    out = np.empty((3, len(grasp)))
    for j in range(3):  # the sums of g[:, :1] * R[:, 0] + g[:, 1:2] * R[:, 1] + ..., in that order
        out[j] = g[0] * A[4 * j] + g[1] * A[4 * j + 1] + g[2] * A[4 * j + 2] + A[4 * j + 3]
    return np.ascontiguousarray(out.T), grasp


@lru_cache(maxsize=256)
def _gripper_grid(gripper: Gripper, width: float, spacing: float) -> np.ndarray:
    """Coordinates (3, K) of :func:`box_surface_grid` on the gripper's boxes at
    ``width`` (gripper frame, read-only)."""
    g, _ = box_surface_grid(gripper.boxes(width), spacing)
    g = np.ascontiguousarray(g.T)
    g.flags.writeable = False
    return g


#: Primitives farther than this (metres, by bounding box) from a gripper are not
#: evaluated for it: its clearance is then +inf or at least this much.
CLEARANCE_RANGE = 0.02


def gripper_clearance(obj, pose: np.ndarray, width: np.ndarray, qpos=None, gripper: Gripper = DEFAULT_GRIPPER,
                      spacing: float = 0.004) -> np.ndarray:
    """Smallest signed distance (G,) between each gripper's box grid and ``obj``.

    Each gripper is tested only against the primitives whose bounding box comes within
    :data:`CLEARANCE_RANGE` of its own (exact SDFs, one call per primitive for all the
    grippers near it).

    Parameters
    ----------
    pose : (G, 4, 4) array
        Gripper frames in the object frame.
    width : (G,) array
        Jaw openings (metres).
    """
    pts, gi = gripper_points(pose, width, gripper, spacing)
    G = len(width)
    out = np.full(G, np.inf)
    if not len(pts):
        return out
    start = np.searchsorted(gi, np.arange(G + 1))  # each gripper's points are contiguous
    glo = np.minimum.reduceat(pts, start[:-1], axis=0) - CLEARANCE_RANGE
    ghi = np.maximum.reduceat(pts, start[:-1], axis=0) + CLEARANCE_RANGE
    table = obj.primitive_table
    L = obj.link_poses(qpos)
    B = table.world_boxes(L)
    near = np.all((B[None, :, 0] <= ghi[:, None]) & (B[None, :, 1] >= glo[:, None]), axis=2)  # (G, N)
    W = table.world_all(L)
    geoms, params = primitive_params(obj)
    for k in np.flatnonzero(near.any(axis=0)):
        gs = np.flatnonzero(near[:, k])
        n = start[gs + 1] - start[gs]
        first = np.zeros(len(gs), dtype=np.int64)
        np.cumsum(n[:-1], out=first[1:])
        idx = np.arange(n.sum()) + np.repeat(start[gs] - first, n)  # the points of the grippers gs
        R, t = W[k, :, :3], W[k, :, 3]
        x = (np.take(pts, idx, axis=0) - t) @ R  # take: faster than pts[idx], same rows
        d = geoms[k].sdf(params[k], x)
        out[gs] = np.minimum(out[gs], np.minimum.reduceat(d, first))
    return out


def mesh_gripper(pose: np.ndarray, width: float, gripper: Gripper = DEFAULT_GRIPPER):
    """A ``trimesh.Trimesh`` of the gripper boxes at ``pose`` (for pictures)."""
    import trimesh

    meshes = []
    for lo, hi in gripper.boxes(width):
        m = trimesh.creation.box(extents=hi - lo)
        m.apply_translation((lo + hi) / 2)
        m.apply_transform(pose)
        meshes.append(m)
    return trimesh.util.concatenate(meshes)
