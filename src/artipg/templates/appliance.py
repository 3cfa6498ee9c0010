"""Appliance parts: a housing with a cavity and a control bay, front control panels,
windowed doors, turntables, displays and vent grilles (microwaves, ovens, dishwashers).

Frames:
- ``appliance_housing``: origin at the centre of the outer box, front face at
  x = -depth/2 (the front plane); anchors ``cavity_lo``/``cavity_hi`` (inner corners of
  the cavity, open at the front) and ``bay_lo``/``bay_hi`` (the control bay's front
  face rectangle on the front plane, x = -depth/2).
- front plates (``control_panel``, ``vent_grille``, ``window_door``, ``display``): the
  front-panel convention of :mod:`artipg.templates.panels` -- origin at the centre of
  the back face, the plate spans x in [-thickness, 0], width along y, height along z.
- ``turntable``: origin at the centre of the cavity floor, rotation axis +z.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.detail import edge_radius, rbox_between
from artipg.templates.panels import door_edge_grasps

_FRAME_TO_X = Placer(rot_y(np.pi / 2))  # rect ring's z (thickness) -> x


def appliance_housing(p, depth: float, width: float, height: float, bay_width: float, bay_side: str = "-y") -> Part:
    """Closed box with an open-front cavity on one side and a control bay on the other.

    The bay (``bay_width`` wide, on the ``bay_side`` of the front) is closed by a front
    wall; a divider separates it from the cavity.
    """
    w = p.uniform("wall", 0.008, 0.018)
    top = p.uniform("top", 0.015, 0.04)
    bot = p.uniform("bottom", 0.012, 0.025)
    back = p.uniform("back", 0.02, 0.06)
    fw = p.uniform("bay_wall", 0.003, 0.008)
    D, W, H = depth / 2, width / 2, height / 2
    s = -1.0 if bay_side == "-y" else 1.0
    yb = s * (W - bay_width)  # divider's cavity-side face
    lo_y, hi_y = sorted((-s * (W - w), yb))
    by0, by1 = sorted((yb, s * W))
    r = edge_radius(p, w)  # the outer shell's edges (top, bottom, sides)
    prims = [
        rbox_between((-D, -W, -H), (D, W, -H + bot), r, role="bottom"),
        rbox_between((-D, -W, H - top), (D, W, H), r, role="top"),
        rbox_between((-D, -W, -H + bot - r), (D, -W + w, H - top + r), r, role="side"),
        rbox_between((-D, W - w, -H + bot - r), (D, W, H - top + r), r, role="side"),
        cuboid_between((D - back, -W + w, -H + bot), (D, W - w, H - top), role="back"),
        cuboid_between((-D, min(yb, yb + s * w), -H + bot), (D - back, max(yb, yb + s * w), H - top), role="divider"),
        cuboid_between((-D, by0 + (w if s < 0 else 0), -H + bot), (-D + fw, by1 - (w if s > 0 else 0), H - top),
                       role="bay_front"),
    ]
    return Part("body", "appliance_housing", prims,
                anchors={"cavity_lo": (-D, lo_y, -H + bot), "cavity_hi": (D - back, hi_y, H - top),
                         "bay_lo": (-D, by0, -H), "bay_hi": (-D, by1, H), "front": (-D, 0.0, 0.0),
                         "top": (0.0, 0.0, H)},
                regions={"lift": Region(("side",))})


def control_panel(p, width: float, height: float, thickness: float, keypad=None) -> Part:
    """Front plate of a control bay; with ``keypad`` = (y0, y1, z0, z1) (plate frame) it
    leaves that rectangle open as a well for push buttons (its floor is the bay front)."""
    t, w2, h2 = thickness, width / 2, height / 2
    if keypad is None:
        prims = [cuboid(t, width, height, translation(-t / 2, 0, 0), role="plate")]
    else:
        y0, y1, z0, z1 = keypad
        prims = [cuboid_between((-t, -w2, z1), (0.0, w2, h2), role="plate"),
                 cuboid_between((-t, -w2, -h2), (0.0, w2, z0), role="plate"),
                 cuboid_between((-t, -w2, z0), (0.0, y0, z1), role="plate"),
                 cuboid_between((-t, y1, z0), (0.0, w2, z1), role="plate")]
    front = np.array([[-t - 1e-4, -w2, -h2], [-t + 1e-4, w2, h2]])
    return Part("panel", "control_panel", prims, anchors={"front": (-t, 0.0, 0.0)},
                regions={"push": Region(("plate",), front)})


def display(p, width: float, height: float) -> Part:
    """Display window: a thin dark pane standing proud of a plate (front convention)."""
    t = p.uniform("thickness", 0.001, 0.003)
    return Part("screen", "display", [cuboid(t, width, height, translation(-t / 2, 0, 0), role="screen")],
                anchors={"front": (-t, 0.0, 0.0)})


def vent_grille(p, width: float, height: float, thickness: float) -> Part:
    """Fixed front strip with horizontal louvres (over-the-range vents)."""
    t = thickness
    n = p.integers("louvres", 2, 5)
    lt = p.uniform("louvre_depth", 0.002, 0.005)
    prims = [cuboid(t, width, height, translation(-t / 2, 0, 0), role="plate")]
    for i in range(n):
        z = -height / 2 + height * (i + 1) / (n + 1)
        prims.append(cuboid(lt, 0.8 * width, 0.15 * height / n + 0.002, translation(-t - lt / 2, 0, z), role="louvre"))
    return Part("panel", "vent_grille", prims, anchors={"front": (-t, 0.0, 0.0)})


def window_door(p, width: float, height: float, thickness: float | None = None, latch_side: str = "-y") -> Part:
    """Appliance door: a frame around an off-centre glass window, with a wider latch
    strip on ``latch_side`` (front-panel convention; hinge it on the other side)."""
    t = p.uniform("thickness", 0.025, 0.045, fixed=thickness)
    rail = min(p.uniform("rail_width", 0.03, 0.06), 0.25 * min(width, height))
    latch = p.uniform("latch_width", 0.0, 0.25) * width
    s = -1.0 if latch_side == "-y" else 1.0
    fw = width - latch
    cy = -s * latch / 2  # centre of the framed part
    frame = rect_ring(height, fw, t, height - 2 * rail, fw - 2 * rail,
                      _FRAME_TO_X.at(-t / 2, cy, 0), role="panel")
    gt = p.uniform("glass_thickness", 0.004, 0.008)
    prims = [frame, cuboid(gt, fw - 2 * rail, height - 2 * rail, translation(-t / 2, cy, 0), role="glass")]
    if latch > 1e-3:
        prims.append(cuboid(t, latch + 1e-3, height, translation(-t / 2, s * (width - latch - 1e-3) / 2, 0),
                            role="panel"))
    front = np.array([[-t - 1e-4, -width / 2, -height / 2], [-t + 1e-4, width / 2, height / 2]])
    return Part("door", "window_door", prims,
                anchors={"edge_+y": (-t, width / 2, 0.0), "edge_-y": (-t, -width / 2, 0.0),
                         "edge_+z": (-t, 0.0, height / 2), "edge_-z": (-t, 0.0, -height / 2), "front": (-t, 0.0, 0.0)},
                regions={"push": Region(("panel", "glass"), front)},
                grasps=Deferred(door_edge_grasps, t, width, height),
                actionable="hinge_door")


def stack_layout(heights, span: float, margin: float) -> tuple[list[tuple[float, float]], float]:
    """Stack blocks of ``heights`` from the top of a panel ``span`` tall (z in
    [-span/2, span/2]) with ``margin`` above, between and below them, shrinking them
    all by one factor when they do not fit. Returns ((z_top, height) per block, factor)."""
    f = min(1.0, (span - margin * (len(heights) + 1)) / max(sum(heights), 1e-9))
    z, out = span / 2 - margin, []
    for h in heights:
        out.append((z, h * f))
        z -= h * f + margin
    return out, f


def turntable(p, radius: float) -> Part:
    """Glass turntable plate on a drive hub; the hub stands on the cavity floor (z = 0)."""
    t = p.uniform("plate_thickness", 0.004, 0.008)
    hub_r = p.uniform("hub_radius", 0.015, 0.03)
    hub_h = p.uniform("hub_height", 0.008, 0.02)
    prims = [cylinder(hub_r, hub_h, translation(0, 0, hub_h / 2), role="hub"),
             cylinder(radius, t, translation(0, 0, hub_h + t / 2), role="plate")]
    # no grasp: the plate sits 8-20 mm above the cavity floor, too low for a finger
    # under its rim; it is turned by pushing its top (rotate region)
    return Part("turntable", "turntable", prims, anchors={"top": (0.0, 0.0, hub_h + t)},
                regions={"rotate": Region(("plate",))})
