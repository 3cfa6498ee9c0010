"""Remote-control parts: the handset body, its sliding battery cover, an IR window and
a display window.

Frames: the body lies flat in the object frame, ``length`` along x (the IR end at
+x), ``width`` along y, its bottom on z = 0 and its top face at z = ``thickness``.
The battery-cover pocket is cut into the bottom at the -x end, open towards -x, so the
cover slides out of the end. The cover's origin is at the centre of its -x edge on
its bottom face.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid_between
from artipg.model.part import Part, Region

GAP = 0.0008  # running clearance of the battery cover in its pocket


def handset(p, length: float, width: float, thickness: float, pocket: tuple[float, float, float]) -> Part:
    """Handset body with a battery pocket ``pocket`` = (length, width, depth) in its
    bottom at the -x end. Anchors: ``top`` (centre of the top face), ``ir`` (centre
    of the +x end face)."""
    L2, W2 = length / 2, width / 2
    pl, pw, pd = pocket
    xe = -L2 + pl
    prims = [cuboid_between((-L2, -W2, pd), (L2, W2, thickness), role="shell"),
             cuboid_between((xe, -W2, 0.0), (L2, W2, pd), role="shell"),
             cuboid_between((-L2, -W2, 0.0), (xe, -pw / 2, pd), role="shell"),
             cuboid_between((-L2, pw / 2, 0.0), (xe, W2, pd), role="shell")]
    return Part("body", "handset", prims, anchors={"top": (0.0, 0.0, thickness), "ir": (L2, 0.0, thickness / 2)},
                regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def battery_cover(p, length: float, width: float, thickness: float) -> Part:
    """Sliding battery cover: a plate ``length`` x ``width`` x ``thickness`` whose
    free (-x) end is where a thumb pushes it out."""
    ridge = p.uniform("ridge_length", 0.008, 0.015)
    prims = [cuboid_between((0.0, -width / 2, 0.0), (length, width / 2, thickness), role="plate")]
    grip = np.array([[0.0, -width / 2, -1e-4], [ridge, width / 2, thickness + 1e-4]])
    return Part("cover", "battery_cover", prims, anchors={"grip": (ridge / 2, 0.0, 0.0)},
                regions={"pull": Region(("plate",), grip), "push": Region(("plate",), grip)},
                actionable="slider_lid")


def end_window(p, width: float, height: float) -> Part:
    """Dark IR window on an end face (the face is x = 0, the window protrudes to +x)."""
    t = p.uniform("window_thickness", 0.0008, 0.0015)
    return Part("lens", "ir_window", [cuboid_between((0.0, -width / 2, -height / 2), (t, width / 2, height / 2),
                                                     role="window")])


def lcd_window(p, length: float, width: float) -> Part:
    """LCD window lying on a top face (the face is z = 0, the window rises to +z)."""
    t = p.uniform("lcd_thickness", 0.0005, 0.0012)
    return Part("screen", "lcd_window", [cuboid_between((-length / 2, -width / 2, 0.0), (length / 2, width / 2, t),
                                                        role="lcd")])
