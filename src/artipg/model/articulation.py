"""Links, joints and the articulated object (URDF-shaped), with forward kinematics."""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from artipg.geometry.transforms import IDENTITY, unit_rotation
from artipg.model.part import Part

JOINT_TYPES = ("fixed", "revolute", "prismatic", "continuous")
_matmul = np.matmul


def _table_of(obj):
    """``PrimitiveTable.of(obj)``; :mod:`artipg.annotate.points` is imported on first use
    (a function-level import statement costs more than a module lookup)."""
    m = sys.modules.get("artipg.annotate.points")
    if m is None:
        import artipg.annotate.points as m
    return m.PrimitiveTable.of(obj)


@dataclass(eq=False)
class Joint:
    """A joint between two links.

    Attributes
    ----------
    name : str
    type : str
        One of ``fixed``, ``revolute``, ``prismatic``, ``continuous``.
    parent, child : str
        Link names.
    origin : (4, 4) ndarray
        Joint frame (= child link frame at q = 0) in the parent link frame.
    axis : (3,) ndarray
        Unit motion axis in the joint frame.
    limits : (float, float)
        (lower, upper), radians or metres; ``(-inf, inf)`` for continuous joints.
    """

    name: str
    type: str
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 1.0]))
    limits: tuple[float, float] = (0.0, 0.0)

    @property
    def movable(self) -> bool:
        return self.type != "fixed"

    def motion(self, q: float) -> np.ndarray:
        """Transform (4, 4) of the child relative to the joint frame at value ``q``."""
        if self.type == "fixed" or q == 0.0:
            return IDENTITY
        if self.type == "prismatic":
            T = np.eye(4)
            T[:3, 3] = self.axis * q
            return T
        x, y, z = self.axis
        return unit_rotation(float(x), float(y), float(z), q)


@dataclass(eq=False)
class Link:
    """A rigid group of parts; its frame is its parent joint's frame."""

    name: str
    parts: list[Part] = field(default_factory=list)
    joint: Joint | None = None


@dataclass(eq=False)
class ArticulatedObject:
    """An articulated object: links in topological order (root first) and joints.

    Attributes
    ----------
    category, subcategory : str
    seed : int
    links : list of Link
    joints : list of Joint
        One per non-root link, in the order of ``links[1:]``.
    params : dict
        Recorded parameters: name -> :class:`artipg.rules.params.Param`.
    templates : dict
        Slot -> chosen part template name(s).
    materials : dict
        Semantic label -> material class overrides of the object's category
        (:attr:`artipg.rules.Category.materials`); other labels use the defaults of
        :data:`artipg.materials.MATERIAL`.
    """

    category: str
    subcategory: str
    seed: int
    links: list[Link]
    joints: list[Joint]
    params: dict = field(default_factory=dict)
    templates: dict = field(default_factory=dict)
    report: dict = field(default_factory=dict)
    materials: dict = field(default_factory=dict)

    # ------------------------------------------------------------ structure
    @cached_property
    def link_index(self) -> dict[str, int]:
        return {link.name: i for i, link in enumerate(self.links)}

    @cached_property
    def parts(self) -> list[Part]:
        """All parts, in link order; a part's instance id is its index here."""
        return [p for link in self.links for p in link.parts]

    @cached_property
    def part_link(self) -> np.ndarray:
        """Link index (P,) of every part."""
        return np.array([i for i, link in enumerate(self.links) for _ in link.parts], dtype=np.int64)

    @property
    def movable_joints(self) -> list[Joint]:
        return [j for j in self.joints if j.movable]

    @property
    def dof(self) -> int:
        return sum(1 for j in self.joints if j.movable)

    def joint(self, name: str) -> Joint:
        for j in self.joints:
            if j.name == name:
                return j
        raise KeyError(name)

    # ------------------------------------------------------------ kinematics
    def qpos_dict(self, qpos=None) -> dict[str, float]:
        """Normalise ``qpos`` to {joint name: value}.

        ``qpos`` may be None (rest pose), a dict by joint name, or a sequence with one
        value per movable joint in :attr:`movable_joints` order.
        """
        if qpos is None:
            return {}
        if isinstance(qpos, dict):
            return {k: float(v) for k, v in qpos.items()}
        mv = self.movable_joints
        q = np.asarray(qpos, dtype=float).ravel()
        if len(q) != len(mv):
            raise ValueError(f"qpos has {len(q)} values, object has {len(mv)} movable joints")
        return {j.name: float(v) for j, v in zip(mv, q)}

    @cached_property
    def _levels(self) -> list[tuple]:
        """The non-root links by depth: (links, parent, joint indices, link indices) per
        level, the first three slices or one parent's index when they can be, else arrays."""
        return self._plan_levels()

    def _plan_levels(self) -> list[tuple]:
        """:attr:`_levels`, computed."""
        links = self.links
        n = len(links) - 1
        parents = [lk.joint.parent for lk in links[1:]]
        if parents.count(links[0].name) == n:  # every link on the root: one level
            return [(slice(1, n + 1), 0, slice(0, n), range(1, n + 1))] if n else []
        idx = self.__dict__.get("link_index")
        if idx is None:  # link_index, cached without cached_property's lock
            idx = self.__dict__["link_index"] = {link.name: i for i, link in enumerate(links)}
        # the links of each depth, in link order, with their parents
        by_depth: list[list[int]] = []
        depth = [0] * (n + 1)
        for i, name in enumerate(parents, 1):
            p = idx[name]
            if p >= i:
                raise ValueError(f"link {links[i].name} comes before its parent")
            d = depth[i] = depth[p] + 1
            if d > len(by_depth):
                by_depth.append([])
            by_depth[d - 1].append(i)
        out = []
        for kids in by_depth:
            pars = [idx[parents[i - 1]] for i in kids]
            if kids[-1] - kids[0] == len(kids) - 1:
                rows, joints = slice(kids[0], kids[-1] + 1), slice(kids[0] - 1, kids[-1])
            else:
                rows = np.array(kids)
                joints = rows - 1
            out.append((rows, pars[0] if min(pars) == max(pars) else np.array(pars), joints, kids))
        return out

    def link_poses(self, qpos=None) -> np.ndarray:
        """Pose (L, 4, 4) of every link in the object frame at joint state ``qpos``."""
        q = self.qpos_dict(qpos) if qpos is not None else None
        links = self.links
        T = np.empty((len(links), 4, 4))
        T[0] = IDENTITY
        if len(links) == 1:
            return T
        # the cached plan read directly: functools.cached_property's first access takes a
        # lock (Python 3.11), a few microseconds on every new object
        levels = self.__dict__.get("_levels")
        if levels is None:
            levels = self.__dict__["_levels"] = self._plan_levels()
        # a level at a time: T[link] = T[parent] @ origin for all its links at once (the
        # same product for each), then the moved ones times their motion
        origins = np.concatenate([lk.joint.origin for lk in links[1:]]).reshape(-1, 4, 4)
        for kids, parents, joints, members in levels:
            A = T[parents] @ origins[joints]
            if q:
                for k, i in enumerate(members):
                    j = links[i].joint
                    v = q.get(j.name, 0.0)
                    if v:
                        A[k] = A[k] @ j.motion(v)
            T[kids] = A
        return T

    def part_poses(self, qpos=None) -> np.ndarray:
        """Pose (P, 4, 4) of every part frame in the object frame."""
        L = self.link_poses(qpos)
        return L[self.part_link] @ np.stack([p.pose for p in self.parts])

    def limits(self) -> np.ndarray:
        """(J, 2) lower/upper limits of the movable joints (continuous: -π..π)."""
        out = []
        for j in self.movable_joints:
            lo, hi = j.limits
            out.append((-math.pi, math.pi) if j.type == "continuous" else (lo, hi))
        return np.array(out, dtype=float).reshape(-1, 2)

    # ------------------------------------------------------------ geometry
    @cached_property
    def primitive_table(self):
        """Primitives grouped by geometry template (see :mod:`artipg.annotate.points`)."""
        return _table_of(self)

    def bounds(self, qpos=None) -> np.ndarray:
        """Axis-aligned bounding box (2, 3) of the object at ``qpos``: the union of each
        primitive's local box transformed to the object frame, so exact for boxes and
        axis-aligned solids and slightly loose for rotated round ones."""
        table = self.__dict__.get("primitive_table")
        if table is None:  # as primitive_table, without cached_property's lock
            table = self.__dict__["primitive_table"] = _table_of(self)
        return table.bounds(self.link_poses(qpos))

    def sample_points(self, n: int = 2048, seed: int = 0, qpos=None, parts=None):
        """Area-uniform labelled surface points; see :func:`artipg.annotate.points.sample_points`."""
        from artipg.annotate.points import sample_points

        return sample_points(self, n, seed=seed, qpos=qpos, parts=parts)

    def to_trimesh(self, qpos=None, sections: int = 32):
        """The whole object at ``qpos`` as one ``trimesh.Trimesh`` (object frame)."""
        import trimesh

        L = self.link_poses(qpos)
        meshes = []
        for li, link in enumerate(self.links):
            for part in link.parts:
                for prim in part.primitives:
                    meshes.append(prim.placed(L[li] @ part.pose).mesh(sections))
        return trimesh.util.concatenate(meshes)
