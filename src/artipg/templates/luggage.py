"""Suitcase parts: the back shell with holes for the telescopic handle, the front
shell (lid), the telescopic handle, fold-flat carry handles and wheels.

Frames: the back shell is built in the object frame (standing upright, front -x, its
bottom at z = ``bottom``). The lid follows the front-panel convention of
:mod:`artipg.templates.mounting` (back face at x = 0, front at -depth). The
telescopic handle's origin is at the top face between its posts; it rises (+z). A
carry handle's origin is on its hinge axis (local y, along the grip); the grip lies
flat on the surface (local z its outward normal) and spans local x in [-width, 0].
A wheel's origin is its centre, its axle along y.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder
from artipg.geometry.transforms import rot_x
from artipg.model.part import Part, Region

GAP = 0.001  # running clearance of moving parts
MOUNT_LENGTH = (0.015, 0.025)  # metres: a carry handle's end blocks, along the grip
_AXLE_Y = rot_x(math.pi / 2)  # cylinder's z along y


def back_shell(p, x0: float, x1: float, width: float, z0: float, z1: float, wall: float, holes) -> Part:
    """Hollow shell open at the seam ``x0``, its back at ``x1``, ``width`` wide, from
    ``z0`` to ``z1``, walls ``wall`` thick; its top wall has two square holes for the
    telescopic handle's posts: ``holes`` = (x centre, |y| centre, half side)."""
    xc, yc, hs = holes
    W2, zt = width / 2, z1 - wall
    prims = [cuboid_between((x1 - wall, -W2, z0), (x1, W2, z1), role="shell"),
             cuboid_between((x0, -W2, z0), (x1 - wall, -W2 + wall, zt), role="shell"),
             cuboid_between((x0, W2 - wall, z0), (x1 - wall, W2, zt), role="shell"),
             cuboid_between((x0, -W2 + wall, z0), (x1 - wall, W2 - wall, z0 + wall), role="shell"),
             cuboid_between((x0, -W2, zt), (xc - hs, W2, z1), role="shell"),
             cuboid_between((xc + hs, -W2, zt), (x1 - wall, W2, z1), role="shell"),
             cuboid_between((xc - hs, -W2, zt), (xc + hs, -yc - hs, z1), role="shell"),
             cuboid_between((xc - hs, -yc + hs, zt), (xc + hs, yc - hs, z1), role="shell"),
             cuboid_between((xc - hs, yc + hs, zt), (xc + hs, W2, z1), role="shell")]
    return Part("body", "back_shell", prims, regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def front_shell(p, depth: float, width: float, height: float, wall: float) -> Part:
    """The lid: a hollow front shell ``depth`` deep (x in [-depth, 0]), open at the
    back, walls ``wall`` thick, centred on y and z."""
    W2, H2 = width / 2, height / 2
    prims = [cuboid_between((-depth, -W2, -H2), (-depth + wall, W2, H2), role="shell"),
             cuboid_between((-depth + wall, -W2, -H2), (0.0, -W2 + wall, H2), role="shell"),
             cuboid_between((-depth + wall, W2 - wall, -H2), (0.0, W2, H2), role="shell"),
             cuboid_between((-depth + wall, -W2 + wall, -H2), (0.0, W2 - wall, -H2 + wall), role="shell"),
             cuboid_between((-depth + wall, -W2 + wall, H2 - wall), (0.0, W2 - wall, H2), role="shell")]
    face = np.array([[-depth - 1e-4, -W2, -H2], [-depth + 1e-4, W2, H2]])
    return Part("lid", "front_shell", prims, anchors={"front": (-depth, 0.0, 0.0)},
                regions={"lift": Region(("shell",), face), "pull": Region(("shell",), face),
                         "push": Region(("shell",), face)}, actionable="hinge_lid")


def telescopic_handle(p, span: float, post: float, length: float) -> Part:
    """Two square posts ``post`` wide, ``length`` long, ``span`` apart (centres) under a
    grip bar; the posts hang from the origin down (-z), the grip sits on it."""
    gw, gh = p.uniform("grip_width", 0.025, 0.035), p.uniform("grip_height", 0.02, 0.03)
    h = post / 2
    prims = [cuboid_between((-h, s * span / 2 - h, -length), (h, s * span / 2 + h, 0.0), role="post") for s in (-1, 1)]
    prims.append(cuboid_between((-gw / 2, -span / 2 - h, 0.0), (gw / 2, span / 2 + h, gh), role="grip"))
    return Part("handle", "telescopic_handle", prims, anchors={"grip": (0.0, 0.0, gh / 2), "grip_width": (gw, 0, 0)},
                regions={"grasp": Region(("grip",)), "pull": Region(("grip",)), "push": Region(("grip",))},
                actionable="slider_drawer")


def flip_grip(p, length: float, width: float | None = None) -> Part:
    """Fold-flat carry handle's grip: a strap ``length`` along local y, lying on the
    surface, hinged on its +x edge (see the module docstring)."""
    w = p.uniform("width", 0.025, 0.035, fixed=width)
    t = p.uniform("thickness", 0.008, 0.014)
    prims = [cuboid_between((-w, -length / 2, -t / 2), (0.0, length / 2, t / 2), role="grip")]
    return Part("handle", "flip_grip", prims, anchors={"thickness": (t, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "lift": Region(("grip",))}, actionable="hinge_handle")


def grip_mounts(p, length: float, width: float, thickness: float) -> Part:
    """The fixed end blocks a :func:`flip_grip` turns between (same frame, on the surface),
    each ``MOUNT_LENGTH`` long beyond ``GAP`` past either end of the grip."""
    m = p.uniform("mount_length", *MOUNT_LENGTH)
    z0, z1 = -thickness / 2 - GAP, thickness / 2 + 0.002
    y0 = length / 2 + GAP
    prims = [cuboid_between((-width, s * y0 if s > 0 else -y0 - m, z0), (0.0, y0 + m if s > 0 else -y0, z1),
                            role="mount") for s in (-1, 1)]
    return Part("handle", "grip_mounts", prims)


def wheel(p, radius: float, width: float) -> Part:
    """A wheel: a cylinder ``radius`` x ``width`` (metres) along y."""
    return Part("wheel", "wheel", [cylinder(radius, width, _AXLE_Y, role="tyre")])


def fork(p, radius: float, width: float, drop: float, plate: float) -> Part:
    """A wheel fork: a top block ``drop`` above the axle and two side plates reaching
    the axle, ``GAP`` clear of a wheel of ``radius`` and ``width``; origin at the axle."""
    y = width / 2 + GAP
    L = radius * 0.9
    prims = [cuboid_between((-L, -y - plate, radius + GAP), (L, y + plate, drop), role="fork")]
    prims += [cuboid_between((-L * 0.6, s * y if s > 0 else -y - plate, -0.3 * radius),
                             (L * 0.6, y + plate if s > 0 else -y, radius + GAP), role="fork") for s in (-1, 1)]
    return Part("base", "wheel_fork", prims)
