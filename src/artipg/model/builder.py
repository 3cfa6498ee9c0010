"""Assembly API: create links, place parts, set joints (after ManiSkill's builder)."""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.transforms import IDENTITY, translation
from artipg.model.articulation import JOINT_TYPES, ArticulatedObject, Joint, Link
from artipg.model.part import Part


class _Shared:
    """What an :class:`ObjectBuilder` shares with its link builders: the name counters,
    the parameter record and the record position of the last added part."""

    __slots__ = ("names", "record", "mark")

    def __init__(self, record: dict | None):
        self.names: dict[str, int] = {}
        self.record = record
        self.mark = 0


_new = object.__new__
# "_0", "_1", ...: base + suffix costs half of f"{base}_{k}" (instance names, by the dozen)
_SUFFIX = tuple(f"_{k}" for k in range(64))
_NSUFFIX = len(_SUFFIX)


def _unique(names: dict[str, int], base: str) -> str:
    """``base`` numbered by its earlier uses in ``names`` (which counts this one)."""
    k = names.get(base, 0)
    names[base] = k + 1
    return base + _SUFFIX[k] if k < _NSUFFIX else f"{base}_{k}"


class LinkBuilder:
    """A link under construction. Obtain one from :meth:`ObjectBuilder.create_link`.

    It shares its builder's name counters and parameter record, not the builder itself:
    a strong reference would close the cycle builder -> link builders -> builder, and
    every finished object (its parts and parameter record, reachable from the builder)
    would then wait for the cyclic garbage collector instead of being freed when dropped.
    """

    def __init__(self, owner: "ObjectBuilder", name: str, parent: "LinkBuilder | None"):
        self._shared = owner._shared
        self.name = name
        self.parent = parent
        self.link = Link(name)

    def add(self, part: Part, pose: np.ndarray = IDENTITY, name: str | None = None) -> Part:
        """Place ``part`` at ``pose`` (part frame in this link's frame); returns it.

        The part is named ``{name}_{k}`` (``name`` defaults to its semantic label), ``k``
        counting the earlier uses of that name in the object, and remembers the span of
        the parameter record drawn since the previous part was added.
        """
        shared = self._shared
        part.pose = pose
        part.name = _unique(shared.names, name or part.semantic)
        record = shared.record
        if record is None:
            part.param_span = (0, 0)
        else:
            start = shared.mark
            shared.mark = stop = len(record)
            part.param_span = (start, stop)
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
        if type not in _JOINT_TYPES:
            raise ValueError(f"joint type must be one of {JOINT_TYPES}, got {type!r}")
        x, y, z = axis
        x, y, z = float(x), float(y), float(z)
        norm = math.sqrt(x * x + y * y + z * z)
        if not norm > 0.0:
            raise ValueError(f"joint {self.name}: axis must be non-zero, got {axis}")
        if type == "continuous":
            lim = _UNLIMITED
        else:
            lo, hi = float(limits[0]), float(limits[1])
            if type != "fixed" and not lo < hi:
                raise ValueError(f"joint {self.name}: limits must satisfy lower < upper, got {limits}")
            lim = (lo, hi)
        # Joint(...) without its __init__ call (the same fields)
        j = _new(Joint)
        j.name = name or f"joint_{self.name}"
        j.type = type
        j.parent = self.parent.name
        j.child = self.name
        j.origin = origin
        # a copy filled in costs half of np.array((x, y, z)), the same values;
        # x / 1.0 is x: unit axes (the usual case) skip the divisions
        j.axis = a = _AXIS.copy()
        if norm == 1.0:
            a[0] = x
            a[1] = y
            a[2] = z
        else:
            a[0] = x / norm
            a[1] = y / norm
            a[2] = z / norm
        j.limits = lim
        self.link.joint = j
        return j


_JOINT_TYPES = frozenset(JOINT_TYPES)
_UNLIMITED = (-math.inf, math.inf)
_AXIS = np.zeros(3)


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
        self._shared = _Shared(record)

    def create_link(self, name: str, parent: LinkBuilder | None = None) -> LinkBuilder:
        """A new link named ``name`` (made unique), child of ``parent`` (None: the root)."""
        links = self._links
        if parent is None and links:
            raise ValueError("the object already has a root link; pass a parent")
        # LinkBuilder(self, unique name, parent) without its __init__ call
        lb = _new(LinkBuilder)
        lb._shared = shared = self._shared
        lb.name = name = _unique(shared.names, name)
        lb.parent = parent
        # Link(name) without its __init__ call (the same fields)
        lb.link = link = _new(Link)
        link.name = name
        link.parts = []
        link.joint = None
        links.append(lb)
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
