"""Display parts: stand bases, necks, the height carriage, the tilt hinge and screens.

Frames (metres, +z up, front towards -x):
- bases: origin at the centre of the footprint on the floor; anchors ``top`` (top
  face on the axis) and ``mount`` (where the neck stands, towards the back, +x);
- necks: origin at the centre of the bottom face; anchors ``top`` and ``front``
  (the centre of the front face at z = 0);
- ``height_carriage``: origin at the centre of its back face, which slides on a
  neck's front face; it extends towards -x; anchor ``front``;
- ``tilt_hinge``: origin on the tilt axis (along y) through a barrel; an arm reaches
  forward to a round mounting plate whose front face (anchor ``mount``) carries the
  screen;
- screens: origin at the centre of the back face (the mounting point), the panel
  extends towards -x, width along y, height along z; anchors ``front``, ``bottom``
  (the panel's x range and its bottom edge's z) and ``width``; ``control_button``
  hangs under the bottom edge, in the screen's frame.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring
from artipg.geometry.transforms import Placer, rot_y, rot_z, translation
from artipg.model.part import Part, Region

_ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x
_ALONG_Y = Placer(np.array([[1.0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]))  # local z -> +y
_LIFT = Region(("plate", "foot", "hub"))


def plate_base(p, width: float, depth: float, mount: float) -> Part:
    """Rectangular plate base; the neck stands ``mount`` behind its centre (at most
    30 mm from the back edge)."""
    t = p.uniform("thickness", 0.008, 0.02)
    xm = min(mount, depth / 2 - 0.03)
    return Part("base", "plate_base", [cuboid(depth, width, t, translation(0, 0, t / 2), role="plate")],
                anchors={"top": (0.0, 0.0, t), "mount": (xm, 0.0, t)}, regions={"lift": _LIFT})


def disc_base(p, width: float, depth: float, mount: float) -> Part:
    """Round disc base of diameter ``max(width, depth)``; the neck stands ``mount``
    behind its centre (at most 30 mm from the edge)."""
    r = max(width, depth) / 2
    t = p.uniform("thickness", 0.008, 0.018)
    xm = min(mount, r - 0.03)
    return Part("base", "disc_base", [cylinder(r, t, translation(0, 0, t / 2), role="plate")],
                anchors={"top": (0.0, 0.0, t), "mount": (xm, 0.0, t)}, regions={"lift": _LIFT})


def v_base(p, width: float, depth: float, mount: float) -> Part:
    """Two feet splayed forward from a round hub at the back (a V seen from above);
    the neck stands on the hub (``mount`` is not used)."""
    t = p.uniform("thickness", 0.01, 0.02)
    fw = p.uniform("foot_width", 0.025, 0.045)
    rh = p.uniform("hub_radius", 0.03, 0.045)
    xh = depth / 2 - rh
    prims = [cylinder(rh, t, translation(xh, 0, t / 2), role="hub")]
    for s in (-1.0, 1.0):
        x1, y1 = -depth / 2 + fw / 2, s * (width / 2 - fw / 2)
        L = math.hypot(xh - x1, y1)
        a = math.atan2(y1, x1 - xh)
        T = translation((xh + x1) / 2, y1 / 2, t / 2) @ rot_z(a)
        prims.append(cuboid(L + fw / 2, fw, t, T, role="foot"))
    return Part("base", "v_base", prims, anchors={"top": (0.0, 0.0, t), "mount": (xh, 0.0, t)},
                regions={"lift": _LIFT})


BASES = {plate_base: 2.0, disc_base: 1.0, v_base: 1.0}


def box_neck(p, height: float, width: float, depth: float) -> Part:
    """Rectangular column."""
    return Part("stand", "box_neck", [cuboid(depth, width, height, translation(0, 0, height / 2), role="neck")],
                anchors={"top": (0.0, 0.0, height), "front": (-depth / 2, 0.0, 0.0)})


def round_neck(p, height: float, width: float, depth: float) -> Part:
    """Round post of diameter ``min(width, depth)``."""
    r = min(width, depth) / 2
    return Part("stand", "round_neck", [cylinder(r, height, translation(0, 0, height / 2), role="neck")],
                anchors={"top": (0.0, 0.0, height), "front": (-r, 0.0, 0.0)})


def slot_neck(p, height: float, width: float, depth: float) -> Part:
    """Rectangular column with a cable-management opening through it (front to back)."""
    lo = p.uniform("slot_low", 0.15, 0.3) * height
    hs = p.uniform("slot_height", 0.25, 0.4) * height
    band = p.uniform("slot_band", 0.18, 0.3) * width
    hi = lo + hs
    prims = [cuboid_between((-depth / 2, -width / 2, 0.0), (depth / 2, width / 2, lo), role="neck"),
             rect_ring(hs, width, depth, hs - 2 * band, width - 2 * band, _ALONG_X.at(0, 0, lo + hs / 2),
                       role="neck"),
             cuboid_between((-depth / 2, -width / 2, hi), (depth / 2, width / 2, height), role="neck")]
    return Part("stand", "slot_neck", prims, anchors={"top": (0.0, 0.0, height), "front": (-depth / 2, 0.0, 0.0)})


NECKS = {box_neck: 2.0, round_neck: 1.0, slot_neck: 1.0}


def turntable(p, radius: float) -> Part:
    """Low swivel disc under a neck (origin at the centre of its bottom face)."""
    t = p.uniform("thickness", 0.004, 0.008)
    return Part("stand", "turntable", [cylinder(radius, t, translation(0, 0, t / 2), role="turntable")],
                anchors={"top": (0.0, 0.0, t)})


def height_carriage(p, width: float, height: float) -> Part:
    """Sliding block on the front of a height-adjustable column."""
    d = p.uniform("depth", 0.012, 0.025)
    return Part("stand", "height_carriage", [cuboid(d, width, height, translation(-d / 2, 0, 0), role="carriage")],
                anchors={"front": (-d, 0.0, 0.0)}, regions={"push": Region(("carriage",))})


def tilt_hinge(p, reach: float, barrel: float) -> Part:
    """Barrel on the tilt axis (y), an arm reaching ``reach`` forward to a round
    mounting plate whose front face is the anchor ``mount``."""
    lb = p.uniform("barrel_length", 0.04, 0.08)
    rp = p.uniform("plate_radius", 0.03, 0.05)
    tp = p.uniform("plate_thickness", 0.004, 0.008)
    ta = 0.8 * barrel
    prims = [cylinder(barrel, lb, _ALONG_Y.at(0, 0, 0), role="barrel"),
             cuboid_between((-reach + tp, -0.3 * lb, -ta / 2), (-0.5 * barrel, 0.3 * lb, ta / 2), role="arm"),
             cylinder(rp, tp, _ALONG_X.at(-reach + tp / 2, 0, 0), role="plate")]
    return Part("hinge", "tilt_hinge", prims, anchors={"mount": (-reach, 0.0, 0.0), "plate": (rp, 0.0, 0.0)})


def _screen(template, p, width, height, face_lo, face_hi, extra=()) -> Part:
    """Panel with a back housing, and the display face between ``face_lo`` and
    ``face_hi`` (y, z corners, part frame) on its front; returns the part."""
    hd = p.uniform("housing_depth", 0.01, 0.04)
    hw, hh = p.uniform("housing_width", 0.45, 0.75) * width, p.uniform("housing_height", 0.45, 0.75) * height
    t = p.uniform("panel_thickness", 0.008, 0.02)
    x0 = -hd - t
    prims = [cuboid_between((-hd, -hw / 2, -hh / 2), (0.0, hw / 2, hh / 2), role="housing"),
             cuboid_between((x0, -width / 2, -height / 2), (-hd, width / 2, height / 2), role="panel"),
             cuboid_between((x0 - 0.0008, face_lo[0], face_lo[1]), (x0, face_hi[0], face_hi[1]), role="display"),
             *extra]
    face = np.array([[x0 - 0.001, face_lo[0], face_lo[1]], [x0 + 1e-4, face_hi[0], face_hi[1]]])
    return Part("screen", template, prims, anchors={"front": (x0 - 0.0008, 0.0, 0.0), "bottom": (x0, -hd, -height / 2),
                                                    "width": (width, 0.0, 0.0)},
                regions={"push": Region(("display",), face), "grasp": Region(("panel",))})


def bezel_screen(p, width: float, height: float) -> Part:
    """Flat panel with an even thin bezel around the display."""
    b = p.uniform("bezel", 0.004, 0.02)
    return _screen("bezel_screen", p, width, height, (-width / 2 + b, -height / 2 + b), (width / 2 - b, height / 2 - b))


def chin_screen(p, width: float, height: float) -> Part:
    """Panel with a thin bezel on three sides and a deeper chin strip at the bottom."""
    b, chin = p.uniform("bezel", 0.003, 0.008), p.uniform("chin", 0.02, 0.05)
    return _screen("chin_screen", p, width, height, (-width / 2 + b, -height / 2 + chin),
                   (width / 2 - b, height / 2 - b))


def framed_screen(p, width: float, height: float) -> Part:
    """Panel whose display sits inside a raised frame (a TV-style bezel)."""
    b = p.uniform("frame_band", 0.008, 0.025)
    rise = p.uniform("frame_rise", 0.002, 0.005)
    s = _screen("framed_screen", p, width, height, (-width / 2 + b, -height / 2 + b), (width / 2 - b, height / 2 - b))
    x0 = s.anchors["front"][0] + 0.0008  # the panel's front face
    s.primitives.append(rect_ring(height, width, rise, height - 2 * b, width - 2 * b, _ALONG_X.at(x0 - rise / 2, 0, 0),
                                  role="frame"))
    s.anchors["front"] = (x0 - rise, 0.0, 0.0)
    return s


SCREENS = {bezel_screen: 2.0, chin_screen: 1.0, framed_screen: 1.0}


def control_button(p, screen: Part) -> Part:
    """Menu / power button under the screen's bottom edge, towards one side (in the
    screen's frame)."""
    x0, x1, zb = screen.anchors["bottom"]
    w = screen.anchors["width"][0]
    y = p.uniform("offset", 0.0, 0.4) * w
    s = p.uniform("size", 0.006, 0.012)
    d = min(s, x1 - x0)
    return Part("button", "control_button",
                [cuboid_between(((x0 + x1 - d) / 2, y - s / 2, zb - 0.003), ((x0 + x1 + d) / 2, y + s / 2, zb), role="cap")],
                regions={"press": Region(("cap",))})
