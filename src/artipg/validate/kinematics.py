"""Kinematic trees for validation: links, joints and vectorised joint motions.

The same structure is built from an :class:`artipg.model.ArticulatedObject` or from a
URDF (:mod:`artipg.validate.folder`), so every check runs on both. Frames follow the
URDF: a link frame is its parent joint's frame, poses are (4, 4) matrices mapping
child-frame points into the parent (object) frame, metres and radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

MOVABLE = ("revolute", "prismatic", "continuous")
#: Codes of the movable joint types (:attr:`Kinematics.type_codes`).
MOVABLE_CODES = {"revolute": 1, "prismatic": 2, "continuous": 3}
_I4 = np.eye(4)
_ZERO3 = np.zeros(3)


@dataclass
class Kinematics:
    """A kinematic tree in topological order (root first).

    Attributes
    ----------
    names : list of str
        Link names, (L,).
    parent : (L,) int64
        Parent link index (-1 for the root).
    joint_names : list of str
        Name of each link's parent joint ("" for the root).
    joint_types : list of str
        ``fixed``, ``revolute``, ``prismatic`` or ``continuous`` ("fixed" for the root).
    origin : (L, 4, 4) float64
        Joint frame in the parent link frame (identity for the root).
    axis : (L, 3) float64
        Unit joint axis in the joint frame.
    limits : (L, 2) float64
        Joint limits (radians or metres; ``-inf, inf`` for continuous joints).
    """

    names: list
    parent: np.ndarray
    joint_names: list
    joint_types: list
    origin: np.ndarray
    axis: np.ndarray
    limits: np.ndarray

    @classmethod
    def of(cls, obj) -> "Kinematics":
        """The tree of an :class:`artipg.model.ArticulatedObject`."""
        idx = obj.link_index
        L = len(obj.links)
        joints = [lk.joint for lk in obj.links[1:]]
        parent = np.array([-1] + [idx[j.parent] for j in joints], dtype=np.int64)
        origin = np.concatenate([_I4] + [j.origin for j in joints], dtype=float).reshape(L, 4, 4)
        axis = np.concatenate([_ZERO3] + [j.axis for j in joints], dtype=float).reshape(L, 3)
        limits = np.array([(0.0, 0.0)] + [j.limits for j in joints], dtype=float).reshape(L, 2)
        jn = [""] + [j.name for j in joints]
        jt = ["fixed"] + [j.type for j in joints]
        kin = cls([lk.name for lk in obj.links], parent, jn, jt, origin, axis, limits)
        # the cached type codes and movable joints, from the codes at hand
        codes = [MOVABLE_CODES.get(t, 0) for t in jt]
        kin.__dict__["type_codes"] = np.array(codes, dtype=np.int64)
        kin.__dict__["_movable"] = np.array([i for i, c in enumerate(codes) if c], dtype=np.int64)
        return kin

    @property
    def n_links(self) -> int:
        return len(self.names)

    def movable(self) -> np.ndarray:
        """Indices of links whose parent joint can move."""
        return self._movable

    @cached_property
    def _movable(self) -> np.ndarray:
        return np.array([i for i, t in enumerate(self.joint_types) if t in MOVABLE], dtype=np.int64)

    @cached_property
    def slides(self) -> np.ndarray:
        """Boolean (J,): the :meth:`movable` joint is prismatic."""
        return np.array([self.joint_types[i] == "prismatic" for i in self.movable()], dtype=bool)

    @cached_property
    def type_codes(self) -> np.ndarray:
        """Joint type of each link as a code (L,) int64: 0 fixed (or any other
        immovable type), 1 revolute, 2 prismatic, 3 continuous."""
        return np.array([MOVABLE_CODES.get(t, 0) for t in self.joint_types], dtype=np.int64)

    @cached_property
    def not_fixed(self) -> np.ndarray:
        """Boolean (L,): the link's parent joint type is not ``fixed`` (the root's is)."""
        return np.array([t != "fixed" for t in self.joint_types], dtype=bool)

    @cached_property
    def continuous(self) -> np.ndarray:
        """Boolean (J,): the :meth:`movable` joint is continuous."""
        return np.array([self.joint_types[i] == "continuous" for i in self.movable()], dtype=bool)

    def world_axes(self, rest: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Axis lines of the :meth:`movable` joints in the object frame at the poses
        ``rest`` (L, 4, 4): unit directions (J, 3) and points on them (J, 3), metres."""
        mv = self.movable()
        R = rest[mv]
        u = self.axis[mv]
        a = R[:, :3, 0] * u[:, 0, None] + R[:, :3, 1] * u[:, 1, None] + R[:, :3, 2] * u[:, 2, None]
        return a, R[:, :3, 3]

    def poses(self, q: dict | None = None) -> np.ndarray:
        """Link poses (L, 4, 4) in the object frame; ``q`` maps joint name -> value."""
        q = q or {}
        T = np.empty((self.n_links, 4, 4))
        T[0] = _I4
        for i in range(1, self.n_links):
            Ti = T[self.parent[i]] @ self.origin[i]
            v = q.get(self.joint_names[i], 0.0)
            if v and self.joint_types[i] in MOVABLE:
                Ti = Ti @ _motion1(self.joint_types[i], self.axis[i], float(v))
            T[i] = Ti
        return T

    def subtree(self, i: int) -> np.ndarray:
        """Boolean mask (L,) of link ``i`` and its descendants."""
        return self.descendants[i]

    @cached_property
    def descendants(self) -> np.ndarray:
        """Boolean (L, L): ``[i, k]`` is True when link ``k`` is ``i`` or below it."""
        L = self.n_links
        parent = self.parent.tolist()
        up: list = [[] for _ in range(L)]  # ancestors of each link (itself first)
        for k in range(L):  # topological order: a parent's list is final before its children
            p = parent[k]
            up[k] = [k] + (up[p] if p >= 0 else [])
        m = np.zeros((L, L), dtype=bool)
        m[[i for a in up for i in a], [k for k, a in enumerate(up) for _ in a]] = True
        return m

    def sweep_values(self, i: int, n: int = 16) -> np.ndarray:
        """``n`` joint values of link ``i``'s joint spread over its range, rest excluded.

        Revolute / prismatic: ``n + 1`` evenly spaced values from lower to upper limit
        without the value 0 (the rest pose, checked separately) when it is one of
        them. Continuous: ``n`` angles of a full turn, 0 excluded.
        """
        if self.joint_types[i] == "continuous":
            return 2.0 * np.pi * np.arange(1, n + 1) / (n + 1)
        lo, hi = self.limits[i]
        v = np.linspace(lo, hi, n + 1)
        return v[np.abs(v) > 1e-12]

    def sweep_table(self, n: int = 16) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`sweep_values` of every movable joint, flattened (same values, same order).

        Returns
        -------
        joint : (S,) int64
            Index into :meth:`movable` of each scene's joint.
        q : (S,) float64
            Its joint value.
        """
        movable = self.movable()
        J = len(movable)
        if not J:
            return np.zeros(0, dtype=np.int64), np.zeros(0)
        cont = self.continuous
        lo = np.where(cont, 0.0, self.limits[movable, 0])
        hi = np.where(cont, 0.0, self.limits[movable, 1])
        k = np.arange(n + 1, dtype=float)
        # np.linspace(lo, hi, n + 1) row by row (same arithmetic: k * step + lo, last = hi)
        V = k[None, :] * ((hi - lo) / n)[:, None] + lo[:, None]
        V[:, -1] = hi
        keep = np.abs(V) > 1e-12
        if cont.any():
            V[cont, :n] = 2.0 * np.pi * np.arange(1, n + 1) / (n + 1)
            keep[cont] = np.arange(n + 1) < n
        joint = np.nonzero(keep)[0]
        return joint, V[keep]

    def poses_batch(self, Q: np.ndarray) -> np.ndarray:
        """Link poses (S, L, 4, 4) for joint values ``Q`` (S, L) (one value per link's
        parent joint; ignored for fixed joints), like :meth:`poses` for each row."""
        S = len(Q)
        T = np.empty((S, self.n_links, 4, 4))
        T[:, 0] = _I4
        for i in range(1, self.n_links):
            Ti = T[:, self.parent[i]] @ self.origin[i]
            if self.joint_types[i] in MOVABLE and Q[:, i].any():  # q = 0: the identity motion
                Ti = Ti @ motion(self.joint_types[i], self.axis[i], Q[:, i])
            T[:, i] = Ti
        return T

    def open_values(self, frac: float) -> dict:
        """Every movable joint at ``frac`` of its range (continuous: ``frac`` * π)."""
        q = {}
        for i in self.movable():
            if self.joint_types[i] == "continuous":
                q[self.joint_names[i]] = frac * np.pi
            else:
                lo, hi = self.limits[i]
                q[self.joint_names[i]] = lo + frac * (hi - lo)
        return q


def motion(jtype, axis: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Joint motions (K, 4, 4) for values ``q`` (K,).

    ``jtype`` is one joint type for all rows or a sequence of K types; ``axis`` is a
    unit axis (3,) or one per row (K, 3).
    """
    q = np.asarray(q, dtype=float)
    K = len(q)
    axis = np.broadcast_to(np.asarray(axis, dtype=float), (K, 3))
    slide = np.broadcast_to(np.asarray(jtype) == "prismatic", (K,))
    T = np.zeros((K, 4, 4))
    T[:, 3, 3] = 1.0
    T[:, :3, :3] = rotations(axis, np.where(slide, 0.0, q))
    T[:, :3, 3] = np.where(slide, q, 0.0)[:, None] * axis
    return T


def rotations(a: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Rotations (K, 3, 3) by angles ``q`` (K,) radians about unit axes ``a`` (K, 3)
    (Rodrigues: ``cos q I + sin q [a]x + (1 - cos q) a a^T``)."""
    c, s = np.cos(q), np.sin(q)
    a4 = np.concatenate([a, np.zeros((len(a), 1))], axis=1)
    M = (a[:, :, None] * a[:, None, :]) * (1.0 - c)[:, None, None]
    M += a4[:, _SKEW] * _SKEW_SIGN * s[:, None, None]
    M[:, _DIAG, _DIAG] += c[:, None]
    return M


#: [a]x as entries of (x, y, z, 0) with signs: the cross-product matrix of a.
_SKEW = np.array([[3, 2, 1], [2, 3, 0], [1, 0, 3]])
_SKEW_SIGN = np.array([[0.0, -1.0, 1.0], [1.0, 0.0, -1.0], [-1.0, 1.0, 0.0]])
_DIAG = np.arange(3)


def _motion1(jtype: str, axis: np.ndarray, q: float) -> np.ndarray:
    """One joint motion (4, 4) (scalar fast path of :func:`motion`)."""
    T = _I4.copy()
    if jtype == "prismatic":
        T[:3, 3] = q * axis
        return T
    x, y, z = float(axis[0]), float(axis[1]), float(axis[2])
    c, s = math.cos(q), math.sin(q)
    C = 1.0 - c
    T[:3, :3] = ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
                 (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
                 (z * x * C - y * s, z * y * C + x * s, c + z * z * C))
    return T


def rigid_inverse(T: np.ndarray) -> np.ndarray:
    """Inverse of rigid transforms (..., 4, 4)."""
    out = np.zeros_like(T)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    out[..., :3, :3] = Rt
    out[..., :3, 3] = -np.einsum("...ij,...j->...i", Rt, T[..., :3, 3])
    out[..., 3, 3] = 1.0
    return out
