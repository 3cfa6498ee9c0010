"""The structure of one object: its joints, links and size at the rest pose.

Made by the readers (:func:`artipg.io.read_object`, :func:`artipg.io.generated_set`) and
summarised over sets by :mod:`artipg.metrics.structure`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

MOVABLE_TYPES = ("revolute", "continuous", "prismatic", "planar", "floating")


@dataclass(frozen=True)
class ObjectStructure:
    """Kinematic structure and size of one object at its rest pose.

    Attributes
    ----------
    joint_types : tuple of str
        URDF type of every joint, fixed ones included.
    n_links : int
        Links that carry visual geometry.
    extents : (3,) float ndarray
        Axis-aligned bounding-box size (x depth, y width, z height) at the rest pose,
        in the units of the source (metres for artipg; PartNet-Mobility is unit-less).
    """

    joint_types: tuple
    n_links: int
    extents: np.ndarray = field(compare=False)

    @property
    def n_joints(self) -> int:
        """Number of movable joints."""
        return sum(1 for t in self.joint_types if t in MOVABLE_TYPES)

    @property
    def diagonal(self) -> float:
        """Bounding-box diagonal (same units as ``extents``)."""
        return float(np.linalg.norm(self.extents))
