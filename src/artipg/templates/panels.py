"""Flat panel templates: doors, drawers, shelves and fronts.

Front frame convention (doors and drawers): the origin is the centre of the panel's
**back** face, the panel spans ``x in [-thickness, 0]`` (its front faces -x), width
along y and height along z. Anchors ``edge_+y``/``edge_-y``/``edge_+z``/``edge_-z``
are the mid-points of the front edges, ``handle`` the suggested handle mount on the
front face (set by the mounting helper once the hinge side is known).
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid, cuboid_between, rect_ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.detail import edge_radius, rbox, rbox_between

_FRAME_TO_X = Placer(rot_y(np.pi / 2))  # rect ring's z (thickness) -> x


def _front_anchors(t: float, w: float, h: float) -> dict:
    return {"edge_+y": (-t, w / 2, 0.0), "edge_-y": (-t, -w / 2, 0.0), "edge_+z": (-t, 0.0, h / 2),
            "edge_-z": (-t, 0.0, -h / 2), "front": (-t, 0.0, 0.0)}


def _edge_frame(out_y: float, out_z: float) -> np.ndarray:
    z_g = np.array([0.0, -out_y, -out_z])  # approach: against the edge's outward normal
    y_g = np.array([1.0, 0.0, 0.0])        # jaws close across the panel's thickness
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2] = np.cross(y_g, z_g), y_g, z_g
    return T


# gripper frames for the four edges, built once (templates must stay cheap)
_EDGE_FRAMES = {(sy, sz): _edge_frame(sy, sz) for sy, sz in ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0))}
_EDGE_STACK = np.stack([_EDGE_FRAMES[e] for e in ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0))])
_NO_DIR = np.zeros(3)
_NO_DIR.flags.writeable = False


def edge_grasp(t: float, y: float, z: float, out_y: float, out_z: float, inset: float = 0.01) -> Grasp:
    """A pinch grasp across a panel's thickness at its edge point (y, z).

    (out_y, out_z) is the edge's outward unit normal in the y-z plane (one of
    (±1, 0), (0, ±1)); the gripper approaches against it, its jaws close along x over
    the ``t``-thick panel, and the grip centre lies ``inset`` inside the edge.
    ``open_dir`` is left to the joint.
    """
    T = _EDGE_FRAMES[(out_y, out_z)].copy()
    T[0, 3], T[1, 3], T[2, 3] = -t / 2, y - out_y * inset, z - out_z * inset
    return Grasp(T, t + 0.02, _NO_DIR)


def door_edge_grasps(t: float, w: float, h: float) -> list[Grasp]:
    """Pinch grasps at the mid-points of the four edges of a front panel; the
    annotation drops the one on the hinge edge, which cannot open it.

    The :func:`edge_grasp` of each edge (+y, -y, +z, -z), their poses filled in one array.
    """
    T = _EDGE_STACK.copy()
    x, i = -t / 2, 0.01  # edge_grasp's inset
    T[:, :3, 3] = ((x, w / 2 - i, 0.0), (x, -w / 2 + i, 0.0), (x, 0.0, h / 2 - i), (x, 0.0, -h / 2 + i))
    g = t + 0.02
    return [Grasp(T[0], g, _NO_DIR), Grasp(T[1], g, _NO_DIR), Grasp(T[2], g, _NO_DIR), Grasp(T[3], g, _NO_DIR)]


def _front_regions(t, w, h, edge=0.25):
    # push anywhere on the front face; pull near the edges (fingers behind the edge)
    front = np.array([[-t - 1e-4, -w / 2, -h / 2], [-t + 1e-4, w / 2, h / 2]])
    return {"push": Region(("panel",), front)}


def slab_door(p, width: float, height: float, thickness: float | None = None) -> Part:
    """Plain flat door panel (edges rounded with detail)."""
    t = p.uniform("thickness", 0.012, 0.025, fixed=thickness)
    r = edge_radius(p, t)
    part = Part("door", "slab_door", [rbox(t, width, height, r, translation(-t / 2, 0, 0), role="panel")],
                anchors=_front_anchors(t, width, height), regions=_front_regions(t, width, height),
                grasps=Deferred(door_edge_grasps, t, width, height), actionable="hinge_door")
    return part


#: Centre panel styles of a framed door (a detail choice): the flat recessed panel of
#: a shaker door, or a raised field (a thicker panel with rounded edges, its face
#: still behind the frame's).
CENTRE_PANELS = {"flat": 1.0, "raised": 1.0}


def framed_door(p, width: float, height: float, thickness: float | None = None) -> Part:
    """Shaker-style door: a frame (stiles and rails) around a recessed centre panel;
    with detail, the centre panel is flat or a raised field (:data:`CENTRE_PANELS`)."""
    t = p.uniform("thickness", 0.016, 0.025, fixed=thickness)
    rail = p.uniform("rail_width", 0.04, 0.09) * min(1.0, min(width, height) / 0.4)
    rail = min(rail, 0.3 * min(width, height))
    panel_t = p.uniform("panel_thickness", 0.3, 0.6) * t
    frame = rect_ring(height, width, t, height - 2 * rail, width - 2 * rail,
                      _FRAME_TO_X.at(-t / 2, 0, 0), role="panel")
    if p.detail_choice("centre", CENTRE_PANELS, "flat") == "raised":
        # the field rises to 1-3 mm behind the frame's face; its rounded edges read as the bevel
        panel_t = max(panel_t, t - p.detail_uniform("field_recess", 0.001, 0.003))
        r = min(p.detail_uniform("field_radius", 0.25, 0.45) * panel_t, 0.006)
    else:
        r = edge_radius(p, panel_t, "inset_radius", hi=0.002)
    inner = rbox(panel_t, width - 2 * rail, height - 2 * rail, r, translation(-panel_t / 2, 0, 0), role="inset")
    return Part("door", "framed_door", [frame, inner], anchors=_front_anchors(t, width, height),
                regions=_front_regions(t, width, height), grasps=Deferred(door_edge_grasps, t, width, height),
                actionable="hinge_door")


def glass_door(p, width: float, height: float, thickness: float | None = None) -> Part:
    """Frame with a glass pane (display cabinets, oven and microwave windows)."""
    t = p.uniform("thickness", 0.016, 0.03, fixed=thickness)
    rail = min(p.uniform("rail_width", 0.03, 0.07), 0.3 * min(width, height))
    glass_t = p.uniform("glass_thickness", 0.004, 0.006)
    frame = rect_ring(height, width, t, height - 2 * rail, width - 2 * rail,
                      _FRAME_TO_X.at(-t / 2, 0, 0), role="panel")
    pane = cuboid(glass_t, width - 2 * rail, height - 2 * rail, translation(-t / 2, 0, 0), role="glass")
    return Part("door", "glass_door", [frame, pane], anchors=_front_anchors(t, width, height),
                regions=_front_regions(t, width, height), grasps=Deferred(door_edge_grasps, t, width, height),
                actionable="hinge_door")


DOORS = {slab_door: 3.0, framed_door: 2.0, glass_door: 1.0}


def _drawer_box(wall: float, depth: float, opening, height_frac: float, role: str = "box") -> list:
    """Open-top box behind a drawer front filling ``opening`` = (y0, y1, z0, z1)."""
    y0, y1, z0, z1 = opening
    zt = z0 + height_frac * (z1 - z0)
    return [
        cuboid_between((0.0, y0, z0), (depth, y1, z0 + wall), role=role),
        cuboid_between((0.0, y0, z0 + wall), (depth, y0 + wall, zt), role=role),
        cuboid_between((0.0, y1 - wall, z0 + wall), (depth, y1, zt), role=role),
        cuboid_between((depth - wall, y0 + wall, z0 + wall), (depth, y1 - wall, zt), role=role),
    ]


def _default_opening(width, height):
    return (-width / 2 + 0.01, width / 2 - 0.01, -height / 2 + 0.01, height / 2 - 0.01)


def box_drawer(p, width: float, height: float, depth: float, opening=None, thickness: float | None = None) -> Part:
    """Drawer: a ``width`` x ``height`` front panel and an open-top box ``depth`` deep
    behind it (x > 0) that fits the ``opening`` (y0, y1, z0, z1) of the part frame."""
    t = p.uniform("front_thickness", 0.015, 0.025, fixed=thickness)
    wall = p.uniform("wall", 0.008, 0.014)
    frac = p.uniform("box_height", 0.6, 0.95)
    prims = [rbox(t, width, height, edge_radius(p, t), translation(-t / 2, 0, 0), role="panel")]
    prims += _drawer_box(wall, depth, opening or _default_opening(width, height), frac)
    front = np.array([[-t - 1e-4, -width / 2, -height / 2], [-t + 1e-4, width / 2, height / 2]])
    return Part("drawer", "box_drawer", prims, anchors=_front_anchors(t, width, height),
                regions={"push": Region(("panel",), front)},
                grasps=Deferred.one(edge_grasp, t, 0.0, height / 2, 0.0, 1.0),
                actionable="slider_drawer")


def slot_drawer(p, width: float, height: float, depth: float, opening=None, thickness: float | None = None) -> Part:
    """Handle-less drawer: a finger slot cut along the top of its front."""
    t = p.uniform("front_thickness", 0.015, 0.025, fixed=thickness)
    wall = p.uniform("wall", 0.008, 0.012)
    slot = min(p.uniform("slot_height", 0.02, 0.035), 0.3 * height)
    frac = p.uniform("box_height", 0.5, 0.8)
    h2, w2 = height / 2, width / 2
    r = edge_radius(p, min(t, slot))
    prims = [
        rbox_between((-t, -w2, -h2), (0.0, w2, h2 - slot), r, role="panel"),
        rbox_between((-t, -w2, h2 - slot - r), (0.0, -w2 / 2, h2), r, role="panel"),
        rbox_between((-t, w2 / 2, h2 - slot - r), (0.0, w2, h2), r, role="panel"),
    ]
    op = opening or _default_opening(width, height)
    op = (op[0], op[1], op[2], min(op[3], h2 - slot - 0.005))
    prims += _drawer_box(wall, depth, op, frac)
    grip = np.array([[-t - 1e-3, -w2 / 2, h2 - slot - 1e-3], [1e-3, w2 / 2, h2 - slot + 1e-3]])
    front = np.array([[-t - 1e-4, -w2, -h2], [-t + 1e-4, w2, h2]])
    return Part("drawer", "slot_drawer", prims, anchors=_front_anchors(t, width, height),
                regions={"push": Region(("panel",), front), "pull": Region(("panel",), grip),
                         "grasp": Region(("panel",), grip)},
                grasps=Deferred.one(edge_grasp, t, 0.0, h2 - slot, 0.0, 1.0),
                actionable="slider_drawer")


DRAWERS = {box_drawer: 4.0, slot_drawer: 1.0}


def shelf_board(p, width: float, depth: float, thickness: float | None = None) -> Part:
    """Horizontal shelf board centred on its frame origin (x = depth, y = width)."""
    t = p.uniform("thickness", 0.012, 0.022, fixed=thickness)
    return Part("shelf", "shelf_board", [cuboid(depth, width, t, role="board")])
