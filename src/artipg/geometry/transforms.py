"""Rigid transforms as 4x4 homogeneous matrices (metres, radians).

All poses in artipg are ``(4, 4)`` float64 arrays mapping points from a child frame
into its parent frame: ``p_parent = T @ [p_child, 1]``.
"""

from __future__ import annotations

import math

import numpy as np

IDENTITY = np.eye(4)
IDENTITY.flags.writeable = False
_EYE = np.eye(4)


def translation(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> np.ndarray:
    """Pure translation by ``(x, y, z)`` metres, as a (4, 4) matrix."""
    T = _EYE.copy()
    T[0, 3] = x
    T[1, 3] = y
    T[2, 3] = z
    return T




def translated(T: np.ndarray, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> np.ndarray:
    """``T @ translation(x, y, z)`` (4, 4), metres."""
    return T @ translation(x, y, z)


class Placer:
    """A constant rigid transform ``M`` to be placed at many points.

    ``Placer(M).at(x, y, z)`` is ``translation(x, y, z) @ M``, made by adding the
    translation to ``M``'s last column (templates place constant axis turns this way
    at dozens of sites).

    Parameters
    ----------
    M : (4, 4) array_like
        Finite, with bottom row ``(0, 0, 0, 1)`` (a rotation, optionally with a
        translation); kept as a read-only copy in :attr:`matrix`.
    """

    __slots__ = ("matrix", "_m", "_t")

    def __init__(self, M):
        M = np.array(M, dtype=float)
        if M.shape != (4, 4) or not np.isfinite(M).all() or M[3].tolist() != [0.0, 0.0, 0.0, 1.0]:
            raise ValueError(f"Placer needs a finite (4, 4) matrix with bottom row (0, 0, 0, 1), got {M!r}")
        M.flags.writeable = False
        self.matrix = M
        self._m = M
        self._t = tuple(M[:3, 3].tolist())

    def at(self, x: float = 0.0, y: float = 0.0, z: float = 0.0) -> np.ndarray:
        """``translation(x, y, z) @ matrix`` (4, 4) for finite ``x, y, z`` (metres)."""
        T = self._m.copy()
        tx, ty, tz = self._t
        T[0, 3] = float(x) + tx
        T[1, 3] = float(y) + ty
        T[2, 3] = float(z) + tz
        return T


def rotation(axis, angle: float, about=None) -> np.ndarray:
    """Rotation by ``angle`` radians about unit-length ``axis`` (3,).

    Parameters
    ----------
    axis : array_like, shape (3,)
        Rotation axis; normalised here.
    angle : float
        Right-handed angle in radians.
    about : array_like, shape (3,), optional
        A point on the axis (default: the origin).

    Returns
    -------
    (4, 4) ndarray
    """
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    T = unit_rotation(x / n, y / n, z / n, angle)
    if about is not None:
        p = np.asarray(about, dtype=float)
        T[:3, 3] = p - T[:3, :3] @ p
    return T


def unit_rotation(x: float, y: float, z: float, angle: float) -> np.ndarray:
    """Rotation (4, 4) by ``angle`` radians about the axis ``(x, y, z)``, which must be
    unit length already (Rodrigues' formula; :func:`rotation` normalises first)."""
    c, s = math.cos(angle), math.sin(angle)
    C = 1.0 - c
    return np.array(  # a flat tuple converts faster than nested lists
        (
            c + x * x * C, x * y * C - z * s, x * z * C + y * s, 0.0,
            y * x * C + z * s, c + y * y * C, y * z * C - x * s, 0.0,
            z * x * C - y * s, z * y * C + x * s, c + z * z * C, 0.0,
            0.0, 0.0, 0.0, 1.0,
        )
    ).reshape(4, 4)


# the unit axes are their own normalisation (x / 1.0 == x): same values as rotation()
def rot_x(angle: float) -> np.ndarray:
    """Rotation about +X by ``angle`` radians."""
    return unit_rotation(1.0, 0.0, 0.0, angle)


def rot_y(angle: float) -> np.ndarray:
    """Rotation about +Y by ``angle`` radians."""
    return unit_rotation(0.0, 1.0, 0.0, angle)


def rot_z(angle: float) -> np.ndarray:
    """Rotation about +Z by ``angle`` radians."""
    return unit_rotation(0.0, 0.0, 1.0, angle)


def pose(xyz=(0.0, 0.0, 0.0), rot=None) -> np.ndarray:
    """Pose with translation ``xyz`` (3,) and optional rotation ``rot`` ((3, 3) or (4, 4))."""
    T = _EYE.copy()
    if rot is not None:
        T[:3, :3] = np.asarray(rot, dtype=float)[:3, :3]
    T[0, 3], T[1, 3], T[2, 3] = xyz
    return T


def rpy_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """URDF fixed-axis roll-pitch-yaw (X then Y then Z, extrinsic) as a (4, 4) rotation."""
    return rot_z(yaw) @ rot_y(pitch) @ rot_x(roll)


def matrix_to_rpy(T: np.ndarray) -> tuple[float, float, float]:
    """Inverse of :func:`rpy_matrix` for the rotation part of ``T``."""
    R = T[:3, :3]
    sy = -R[2, 0]
    sy = min(1.0, max(-1.0, sy))
    pitch = math.asin(sy)
    if abs(sy) < 1.0 - 1e-9:
        roll = math.atan2(R[2, 1], R[2, 2])
        yaw = math.atan2(R[1, 0], R[0, 0])
    else:  # gimbal lock: put everything in yaw
        roll = 0.0
        yaw = math.atan2(-R[0, 1], R[1, 1])
    return roll, pitch, yaw


def invert(T: np.ndarray) -> np.ndarray:
    """Inverse of a rigid transform (4, 4)."""
    Ti = _EYE.copy()
    R = T[:3, :3]
    Ti[:3, :3] = R.T
    Ti[:3, 3] = -R.T @ T[:3, 3]
    return Ti


def apply(T: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Apply a (4, 4) transform to points (N, 3); returns (N, 3)."""
    return points @ T[:3, :3].T + T[:3, 3]


def apply_batched(T: np.ndarray, points: np.ndarray, vectors: np.ndarray | None = None):
    """Apply per-point transforms.

    Parameters
    ----------
    T : (N, 4, 4) ndarray
        One transform per point.
    points : (N, 3) ndarray
    vectors : (N, 3) ndarray, optional
        Direction vectors (e.g. normals) rotated but not translated.

    Returns
    -------
    points : (N, 3) ndarray, and vectors : (N, 3) ndarray when given.
    """
    R = T[:, :3, :3]
    p = np.einsum("nij,nj->ni", R, points) + T[:, :3, 3]
    if vectors is None:
        return p
    return p, np.einsum("nij,nj->ni", R, vectors)
