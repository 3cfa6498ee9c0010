"""Toaster parts: a slotted housing over a crumb-tray pocket, carriage levers and the
crumb tray.

Frames: the housing is built in the object frame (front face at x = -depth / 2, facing
-x; floor at z = 0). A lever's origin is on the housing's front face (plane x = 0,
outward normal -x) at the centre of its stem; it slides down (-z) in a vertical slot of
the front wall. The crumb tray's origin is at the bottom centre of its lip's front
face; the tray extends along +x into the pocket.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid_between
from artipg.model.part import Part, Region

GAP = 0.001  # running clearance of the sliding parts (touching within 2 mm at rest)


def _wall_with_slots(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, slots) -> list:
    """Cuboids of a front wall (x0..x1, y0..y1, z0..z1) around vertical slots
    ``slots`` = [(y_centre, half_width, z_lo, z_hi)] sorted by y."""
    prims, y = [], y0
    for yc, hw, zl, zh in slots:
        prims.append(cuboid_between((x0, y, z0), (x1, yc - hw, z1), role="shell"))
        prims.append(cuboid_between((x0, yc - hw, z0), (x1, yc + hw, zl), role="shell"))
        prims.append(cuboid_between((x0, yc - hw, zh), (x1, yc + hw, z1), role="shell"))
        y = yc + hw
    prims.append(cuboid_between((x0, y, z0), (x1, y1, z1), role="shell"))
    return prims


def toaster_housing(p, depth: float, width: float, height: float, slots, side: float, floor: float,
                    pocket: float, lever_slots=()) -> Part:
    """Housing of ``depth`` x ``width`` x ``height`` metres with bread slots open at
    the top and a crumb-tray pocket under them, open at the front.

    ``slots`` = [(y0, y1)] the bread slots across y (they run along x between the
    front and back walls); ``side`` the side walls' thickness; ``floor`` the floor
    plate's thickness, ``pocket`` the pocket's height above it; ``lever_slots`` as in
    :func:`_wall_with_slots` (vertical slots in the front wall for lever stems).
    Anchors: ``pocket_lo`` / ``pocket_hi`` (the pocket's corners), ``front_wall`` (its
    thickness in x), ``slot_floor`` (z under the slots).
    """
    wf = p.uniform("front_wall", 0.012, 0.02)
    wb = p.uniform("back_wall", 0.012, 0.02)
    D2, W2, zp = depth / 2, width / 2, floor + pocket
    prims = [cuboid_between((-D2, -W2, 0.0), (D2, W2, floor), role="shell"),
             cuboid_between((-D2 + wf, -W2, floor), (D2, -W2 + side, height), role="shell"),
             cuboid_between((-D2 + wf, W2 - side, floor), (D2, W2, height), role="shell"),
             cuboid_between((D2 - wb, -W2 + side, floor), (D2, W2 - side, height), role="shell"),
             cuboid_between((-D2, -W2, floor), (-D2 + wf, -W2 + side, zp), role="shell"),  # beside the pocket
             cuboid_between((-D2, W2 - side, floor), (-D2 + wf, W2, zp), role="shell")]
    prims += _wall_with_slots(-D2, -D2 + wf, -W2, W2, zp, height, lever_slots)  # the full-width front wall
    edges = [y for s in slots for y in s]
    for y0, y1 in zip(edges[1:-1:2], edges[2::2]):  # the walls between slots
        prims.append(cuboid_between((-D2 + wf, y0, zp), (D2 - wb, y1, height), role="shell"))
    return Part("body", "toaster_housing", prims,
                anchors={"pocket_lo": (-D2, -W2 + side, floor), "pocket_hi": (D2 - wb, W2 - side, zp),
                         "front_wall": (wf, 0.0, 0.0), "slot_floor": (0.0, 0.0, zp)},
                regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def carriage_lever(p, stem: tuple[float, float, float], max_width: float | None = None,
                   thickness: float | None = None) -> Part:
    """Carriage lever: a stem through the front wall's slot and a flat paddle in front.

    ``stem`` = (depth through the wall, width, height) metres. The paddle stands
    :data:`GAP` off the face; its top is what a finger presses down.
    """
    sd, sw, sh = stem
    L = p.uniform("reach", 0.02, 0.035)
    w = p.uniform("width", 0.028, 0.045 if max_width is None else max(0.029, min(0.045, max_width)))
    t = p.uniform("thickness", 0.01, 0.018, fixed=thickness)
    x0 = -GAP
    prims = [cuboid_between((x0, -sw / 2, -sh / 2), (sd, sw / 2, sh / 2), role="stem"),
             cuboid_between((x0 - L, -w / 2, -t / 2), (x0, w / 2, t / 2), role="paddle")]
    top = np.array([[x0 - L, -w / 2, t / 2 - 1e-4], [x0, w / 2, t / 2 + 1e-4]])
    return Part("lever", "carriage_lever", prims, anchors={"front": (x0 - L, 0.0, 0.0), "half_height": (t / 2, 0, 0)},
                regions={"press": Region(("paddle",), top), "push": Region(("paddle",), top)},
                actionable="slider_button")


def crumb_tray(p, length: float, width: float, lip: tuple[float, float]) -> Part:
    """Crumb tray: a thin plate ``length`` x ``width`` behind a front lip
    (``lip`` = (thickness in x, height)), with a finger tab on the lip."""
    lt, lh = lip
    pt = p.uniform("plate", 0.0015, 0.003)
    tab_w, tab_d = p.uniform("tab_width", 0.3, 0.6) * width, p.uniform("tab_depth", 0.003, 0.007)
    tab_h = p.uniform("tab_height", 0.4, 0.8) * lh
    prims = [cuboid_between((0.0, -width / 2, 0.0), (lt, width / 2, lh), role="lip"),
             cuboid_between((lt, -width / 2, 0.0), (length, width / 2, pt), role="plate"),
             cuboid_between((-tab_d, -tab_w / 2, (lh - tab_h) / 2), (0.0, tab_w / 2, (lh + tab_h) / 2), role="tab")]
    return Part("tray", "crumb_tray", prims, anchors={"front": (-tab_d, 0.0, lh / 2)},
                regions={"pull": Region(("tab", "lip")), "push": Region(("lip",)), "grasp": Region(("tab",))},
                actionable="slider_drawer")
