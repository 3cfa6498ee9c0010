"""Assembly API: create links, place parts, set joints (after ManiSkill's builder)."""

from __future__ import annotations

import math
import weakref

import numpy as np

from artipg.geometry.transforms import IDENTITY, translation
from artipg.model.articulation import JOINT_TYPES, ArticulatedObject, Joint, Link
from artipg.model.part import Part


class LinkBuilder:
    """A link under construction. Obtain one from :meth:`ObjectBuilder.create_link`.

    It refers to its :class:`ObjectBuilder` weakly, so keep the builder while adding
    parts (a link builder whose builder is gone raises ``ReferenceError``).
    """

    def __init__(self, owner: "ObjectBuilder", name: str, parent: "LinkBuilder | None"):
        # a strong reference would close the cycle builder -> link builders -> builder,
        # and every finished object (its parts and parameter record, reachable from
        # the builder) would then wait for the cyclic garbage collector instead of
        # being freed when dropped; that collector's passes cost more than the proxy
        self._owner = weakref.proxy(owner)
        self.name = name
        self.parent = parent
        self.link = Link(name)

    def add(self, part: Part, pose: np.ndarray = IDENTITY, name: str | None = None) -> Part:
        """Place ``part`` at ``pose`` (part frame in this link's frame); returns it."""
        part.pose = pose
        part.name = self._owner._unique(name or part.semantic)
        part.param_span = self._owner._param_span()
        self.link.parts.append(part)
        return part

    def set_joint(self, type: str, origin: np.ndarray, axis=(0.0, 0.0, 1.0),
                  limits: tuple[float, float] = (0.0, 0.0), name: str | None = None) -> Joint:
        """Connect this link to its parent.

        Parameters
        ----------
        type : {"fixed", "revolute", "prismatic", "continuous"}
        origin : (4, 4) ndarray
            Joint frame in the parent link frame; this link's frame coincides with it
            at q = 0.
        axis : (3,) array_like
            Motion axis in the joint frame (normalised here).
        limits : (lower, upper)
            Radians or metres, lower < upper for revolute/prismatic joints.
        """
        if self.parent is None:
            raise ValueError("the root link has no joint")
        if type not in JOINT_TYPES:
            raise ValueError(f"joint type must be one of {JOINT_TYPES}, got {type!r}")
        x, y, z = axis
        x, y, z = float(x), float(y), float(z)
        norm = math.sqrt(x * x + y * y + z * z)
        if not norm > 0.0:
            raise ValueError(f"joint {self.name}: axis must be non-zero, got {axis}")
        a = np.array((x / norm, y / norm, z / norm))
        lo, hi = float(limits[0]), float(limits[1])
        if type == "continuous":
            lo, hi = -np.inf, np.inf
        elif type != "fixed" and not lo < hi:
            raise ValueError(f"joint {self.name}: limits must satisfy lower < upper, got {limits}")
        j = Joint(name or f"joint_{self.name}", type, self.parent.name, self.name, origin, a, (lo, hi))
        self.link.joint = j
        return j


class ObjectBuilder:
    """Collects links and joints and builds an :class:`ArticulatedObject`.

    Parameters
    ----------
    record : dict, optional
        The parameter record the category draws into (insertion ordered). When given,
        each added part remembers which record entries were drawn to build it
        (:attr:`artipg.model.part.Part.param_span`).
    """

    def __init__(self, record: dict | None = None):
        self._links: list[LinkBuilder] = []
        self._names: dict[str, int] = {}
        self._record = record
        self._mark = 0

    def _param_span(self) -> tuple[int, int]:
        """Record positions drawn since the previous part was added."""
        if self._record is None:
            return (0, 0)
        start, self._mark = self._mark, len(self._record)
        return (start, self._mark)

    def _unique(self, base: str) -> str:
        k = self._names.get(base, 0)
        self._names[base] = k + 1
        return f"{base}_{k}"

    def create_link(self, name: str, parent: LinkBuilder | None = None) -> LinkBuilder:
        """A new link named ``name`` (made unique), child of ``parent`` (None: the root)."""
        if parent is None and self._links:
            raise ValueError("the object already has a root link; pass a parent")
        lb = LinkBuilder(self, self._unique(name), parent)
        self._links.append(lb)
        return lb

    @property
    def root(self) -> LinkBuilder:
        return self._links[0]

    def build(self, category: str, subcategory: str, seed: int, params=None, templates=None,
              normalize: bool = True) -> ArticulatedObject:
        """Freeze into an :class:`ArticulatedObject`.

        With ``normalize`` the object is translated so that at rest it stands on z = 0
        with its bounding box centred on the z axis (DESIGN.md section 1).
        """
        for lb in self._links[1:]:
            if lb.link.joint is None:
                raise ValueError(f"link {lb.name} has no joint; call set_joint")
        links = [lb.link for lb in self._links]
        obj = ArticulatedObject(category, subcategory, seed, links, [lk.joint for lk in links[1:]],
                                params or {}, templates or {})
        if normalize:
            (x0, y0, z0), (x1, y1, z1) = obj.bounds().tolist()
            S = translation(-((x0 + x1) / 2.0), -((y0 + y1) / 2.0), -z0)
            root = links[0]
            kids = [j for j in obj.joints if j.parent == root.name]
            table = obj.primitive_table
            # one stacked product (the same 4x4 products) for the root parts, the joints on
            # the root and the root primitives; the poses become its slices
            n, m = len(root.parts), len(kids)
            moved = S @ _stack([part.pose for part in root.parts] + [j.origin for j in kids]
                               + [table.prim_T[:table._n_root].reshape(-1, 4)])
            for part, T in zip(root.parts, moved):
                part.pose = T
            for j, T in zip(kids, moved[n:]):
                j.origin = T
            table.shift_root(S, moved[n + m:])
        return obj


def _stack(poses: list) -> np.ndarray:
    """(n, 4, 4) array of (4, 4) poses and (4 k, 4) stacks of poses (concatenating is
    faster than np.array)."""
    return np.concatenate(poses).reshape(-1, 4, 4)
