"""Filling a rectangular front opening with a drawer or a hinged door, handle included.

Shared by categories whose bodies have drawers or doors in some opening (tables,
desks, appliances). Rectangles are given on the parent's front plane x = ``front_x``
(parent link frame, or the frame that ``parent_pose`` maps into it):
``outer`` = (y0, y1, z0, z1) is what the front panel covers (overlay fronts), and
for drawers ``inner`` = (y0, y1, z0, z1) the opening the drawer box must pass through.
The conventions are those of :mod:`artipg.templates.panels` and
:mod:`artipg.templates.mounting`.
"""

from __future__ import annotations

from artipg.geometry.extrusion import frame_dims
from artipg.geometry.transforms import translation
from artipg.rules.params import option_name
from artipg.templates.mounting import free_edge_yz, front_thickness, handle_pose, mount_hinged, mount_sliding

CLEARANCE = 0.003  # drawer box to opening, metres


def choose(ctx, q, name: str, options):
    """Template choice drawn on the scoped recorder ``q`` and recorded in ``ctx.templates``."""
    t = q.choice(name, options)
    ctx.templates.setdefault(ctx.slot, []).append(option_name(t))
    return t


def add_drawer(ctx, parent, q, *, front_x: float, outer, inner, depth: float, template, handle=None,
               travel=(0.6, 0.85), parent_pose=None, handle_z: float = 0.0, thickness: float | None = None,
               name: str = "drawer"):
    """A drawer (prismatic along -x) whose front covers ``outer``; returns its link.

    ``depth`` is the box depth behind the front (metres), ``travel`` the opening
    range as fractions of it, ``handle`` a front-handle template (mounted horizontally
    at ``handle_z`` times the front height above its centre) or None.
    """
    y0, y1, z0, z1 = outer
    cy, cz = (y0 + y1) / 2, (z0 + z1) / 2
    c = CLEARANCE
    opening = (inner[0] - cy + c, inner[1] - cy - c, inner[2] - cz + c, inner[3] - cz - c)
    dr = template(q, y1 - y0, z1 - z0, depth, opening=opening, thickness=thickness)
    origin = translation(front_x, cy, cz)
    if parent_pose is not None:
        origin = parent_pose @ origin
    link = mount_sliding(ctx.builder, parent, dr, origin=origin, name=name,
                         limits=(0.0, q.uniform("travel", *travel) * depth))
    if handle is not None and "pull" not in dr.regions:
        h = handle(q.scope("handle"), length=min(0.5 * (y1 - y0), 0.35))
        link.add(h, handle_pose(dr.pose, front_thickness(dr), 0.0, handle_z * (z1 - z0), True))
    return link


def add_door(ctx, parent, q, *, front_x: float, outer, side: str, limits, template, handle=None,
             parent_pose=None, thickness: float | None = None, handle_length: float | None = None,
             margin: float = 0.04, name: str = "door", **door_kw):
    """A door covering ``outer``, hinged on ``side`` ("+y", "-y", "+z", "-z"); returns its link.

    The handle (a front-handle template or None) sits ``margin`` inside the free edge
    (at most half the rail width of framed fronts), vertical on side-hinged doors and
    horizontal on top/bottom-hinged ones. ``door_kw`` go to the door template.
    """
    y0, y1, z0, z1 = outer
    size = (y1 - y0, z1 - z0)
    door = template(q, size[0], size[1], thickness=thickness, **door_kw)
    link = mount_hinged(ctx.builder, parent, door, front_x=front_x, center_yz=((y0 + y1) / 2, (z0 + z1) / 2),
                        size_yz=size, side=side, limits=limits, parent_pose=parent_pose, name=name)
    if handle is not None:
        prim = door.primitives[0]
        dims = frame_dims(prim)
        if dims is not None:  # framed fronts: keep the handle on the frame, not the recessed panel
            margin = min(margin, (dims[0] - dims[3]) / 4)
        horizontal = side in ("+z", "-z")
        span = size[0] if horizontal else size[1]
        length = handle_length if handle_length is not None else min(0.4 * span, 0.35)
        hy, hz = free_edge_yz(side, size, margin)
        link.add(handle(q.scope("handle"), length=length),
                 handle_pose(door.pose, front_thickness(door), hy, hz, horizontal))
    return link
