"""Helpers that attach front parts (doors, drawers, handles) with the right joint.

They encode the conventions of :mod:`artipg.templates.panels` once, so that every
category hinges a door the same way: the hinge line is the panel's *front* outer edge
on the hinge side, which keeps the swinging panel clear of the body and of its
neighbours for any opening angle up to 180 degrees.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.transforms import Placer, rot_x, translated, translation

_HORIZONTAL = rot_x(math.pi / 2)  # handle frame turned so its long axis runs along y
_HORIZONTAL_AT = Placer(_HORIZONTAL)  # translation(x, y, z) @ _HORIZONTAL as _HORIZONTAL_AT.at(x, y, z)

# hinge side -> (edge direction in (y, z), joint axis); "+y" is the viewer's left
_HINGES = {
    "+y": ((1.0, 0.0), (0.0, 0.0, -1.0)),
    "-y": ((-1.0, 0.0), (0.0, 0.0, 1.0)),
    "-z": ((0.0, -1.0), (0.0, -1.0, 0.0)),
    "+z": ((0.0, 1.0), (0.0, 1.0, 0.0)),
}


def front_thickness(part) -> float:
    """Thickness of a front panel part (its front face is at x = -thickness)."""
    return -float(part.anchors["front"][0])


def mount_hinged(builder, parent, part, *, front_x: float, center_yz, size_yz, side: str,
                 limits: tuple[float, float], name: str = "door", parent_pose=None):
    """Hinge a front panel to ``parent`` on one of its edges.

    Parameters
    ----------
    builder : ObjectBuilder
    parent : LinkBuilder
    part : Part
        A panel in the front convention (back face at x = 0, front at -thickness).
    front_x : float
        x of the parent's front plane in the parent link frame (the panel's back face).
    center_yz, size_yz : (float, float)
        Centre and extents of the panel on that plane.
    side : {"+y", "-y", "+z", "-z"}
        Hinge edge ("+y" is on the viewer's left looking at the front).
    limits : (lower, upper)
        Opening range in radians, 0 = closed.

    Returns
    -------
    LinkBuilder
        The panel's link (frame on the hinge line).
    """
    (ey, ez), axis = _HINGES[side]
    t = front_thickness(part)
    cy, cz = center_yz
    hy, hz = cy + ey * size_yz[0] / 2, cz + ez * size_yz[1] / 2
    link = builder.create_link(name, parent)
    if parent_pose is None:
        origin = translation(front_x - t, hy, hz)
    else:
        origin = translated(parent_pose, front_x - t, hy, hz)
    link.set_joint("revolute", origin, axis=axis, limits=limits)
    link.add(part, translation(t, cy - hy, cz - hz))
    return link


def mount_sliding(builder, parent, part, *, origin: np.ndarray, axis=(-1.0, 0.0, 0.0),
                  limits: tuple[float, float], name: str = "drawer"):
    """Attach ``part`` on a prismatic joint whose frame is the part frame at rest."""
    link = builder.create_link(name, parent)
    link.set_joint("prismatic", origin, axis=axis, limits=limits)
    link.add(part)
    return link


def handle_pose(front_pose: np.ndarray, thickness: float, y: float, z: float, horizontal: bool) -> np.ndarray:
    """Pose of a handle (handle-template frame) on a panel's front face at (y, z).

    ``front_pose`` is the panel part's pose in its link; y, z are in the panel frame.
    """
    T = front_pose @ translation(-thickness, y, z)
    return T @ _HORIZONTAL if horizontal else T


def free_edge_yz(side: str, size_yz, margin: float) -> tuple[float, float]:
    """Handle position (y, z) in the panel frame, ``margin`` inside the free edge."""
    (ey, ez), _ = _HINGES[side]
    return (-ey * (size_yz[0] / 2 - margin), -ez * (size_yz[1] / 2 - margin))
