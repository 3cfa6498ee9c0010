"""Trash-can parts: round lids, foot pedals, swing-top hoods with their flap, and the
collars that hold a flip lid.

Frames:
- round lids (``ROUND_LIDS``) use the hinged-lid frame of :mod:`artipg.templates.boxes`:
  origin on the hinge axis (along y), the closed lid extends towards -x and up from
  z = 0, so it opens about +y;
- ``pedal``: origin on the pivot axis (along y); the arm and the foot plate extend
  towards -x; positive joint values about -y press the plate down;
- ``swing_hood``: origin at the centre of its bottom face (it sits on the body's rim),
  front towards -x; anchor ``opening`` is the centre of the flap opening on the front
  face's mid-plane, ``flap_size`` its (width, height);
- ``swing_flap``: origin on its swing axis (along y, through its centre);
- collars: origin at the centre of their bottom face; anchor ``opening`` (radius or
  half sizes of the hole), ``button`` the mount point of a release button on the top.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring, ring, sphere
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.model.part import Part, Region
from artipg.templates.detail import edge_radius, rounded_disc

_Y = Placer(rot_x(math.pi / 2))  # local z -> -y
_X = Placer(rot_y(math.pi / 2))  # local z -> +x


def _round_lid(template, prims, R, top) -> Part:
    grip = np.array([[-2 * R - 1e-3, -R / 2, 0.0], [-2 * R + 0.02, R / 2, top]])
    return Part("lid", template, prims, anchors={"front": (-2 * R, 0.0, top / 2), "top": (-R, 0.0, top)},
                regions={"lift": Region((), grip), "grasp": Region((), grip)}, actionable="hinge_lid")


def flat_disc_lid(p, radius: float, thickness: float | None = None) -> Part:
    """Flat round lid."""
    t = p.uniform("thickness", 0.008, 0.02, fixed=thickness)
    edge = edge_radius(p, t)
    return _round_lid("flat_disc_lid", [rounded_disc(radius, t, edge, 0.0, False, translation(-radius, 0, t / 2),
                                                     role="top")], radius, t)


def domed_lid(p, radius: float, thickness: float | None = None) -> Part:
    """Round lid with a shallow dome (a spherical cap) on a flat rim."""
    t = p.uniform("thickness", 0.006, 0.012, fixed=thickness)
    h = p.uniform("dome", 0.12, 0.3) * radius
    rs = p.uniform("dome_ratio", 0.85, 0.97) * radius  # base radius of the cap
    Rs = (rs * rs + h * h) / (2 * h)  # sphere radius of a cap of base rs and height h
    prims = [cylinder(radius, t, translation(-radius, 0, t / 2), role="top"),
             sphere(Rs, Rs - h, Rs, pose=translation(-radius, 0, t - (Rs - h)), role="top")]
    return _round_lid("domed_lid", prims, radius, t + h)


def stepped_lid(p, radius: float, thickness: float | None = None) -> Part:
    """Round lid with a raised centre disc."""
    t = p.uniform("thickness", 0.006, 0.012, fixed=thickness)
    r2 = p.uniform("step_ratio", 0.6, 0.85) * radius
    t2 = p.uniform("step_height", 0.006, 0.02)
    e1, e2 = edge_radius(p, t), edge_radius(p, t2, "step_edge")
    prims = [rounded_disc(radius, t, e1, 0.0, False, translation(-radius, 0, t / 2), role="top"),
             rounded_disc(r2, t2, e2, 0.0, False, translation(-radius, 0, t + t2 / 2), role="top")]
    return _round_lid("stepped_lid", prims, radius, t + t2)


ROUND_LIDS = {flat_disc_lid: 2.0, domed_lid: 2.0, stepped_lid: 1.0}


def pedal(p, width: float | None = None) -> Part:
    """Foot pedal: a pivot pin, an arm reaching forward and a wide foot plate."""
    w = p.uniform("width", 0.06, 0.12, fixed=width)
    L = p.uniform("length", 0.06, 0.1)
    r = p.uniform("pin_radius", 0.004, 0.007)
    aw, at = p.uniform("arm_width", 0.3, 0.6) * w, p.uniform("arm_thickness", 0.004, 0.008)
    pl, pt = p.uniform("plate_length", 0.03, 0.05), p.uniform("plate_thickness", 0.006, 0.012)
    prims = [cylinder(r, aw + 0.02, _Y.matrix, role="pin"),
             cuboid_between((-L, -aw / 2, -at / 2), (0.0, aw / 2, at / 2), role="arm"),
             cuboid_between((-L - pl, -w / 2, -at / 2), (-L + 0.002, w / 2, -at / 2 + pt), role="plate")]
    top = np.array([[-L - pl, -w / 2, -at / 2 + pt - 1e-4], [-L, w / 2, -at / 2 + pt + 1e-4]])
    return Part("pedal", "pedal", prims, anchors={"tip": (-L - pl, 0.0, -at / 2), "pin": (r, aw / 2 + 0.01, 0.0)},
                regions={"push": Region(("plate",), top), "press": Region(("plate",), top)})


def swing_hood(p, depth: float, width: float, flap_width: float, flap_height: float, wall: float | None = None) -> Part:
    """Box hood of a swing-top bin: top, back and side walls, a front wall with an
    opening for the swing flap, open at the bottom."""
    t = p.uniform("wall", 0.003, 0.008, fixed=wall)
    rise = p.uniform("rise", 0.02, 0.05)  # band below and above the opening
    h = flap_height + 2 * rise
    D, W = depth / 2, width / 2
    prims = [cuboid_between((-D, -W, h), (D, W, h + t), role="top"),
             cuboid_between((D - t, -W, 0), (D, W, h), role="wall"),
             cuboid_between((-D, -W, 0), (D - t, -W + t, h), role="wall"),
             cuboid_between((-D, W - t, 0), (D - t, W, h), role="wall"),
             rect_ring(h, width - 2 * t, t, flap_height, flap_width, _X.at(-D + t / 2, 0, h / 2),
                       role="wall")]
    return Part("body", "swing_hood", prims, anchors={"opening": (-D + t / 2, 0.0, h / 2), "top": (0.0, 0.0, h + t),
                                                      "thickness": (t, 0.0, 0.0)})


def swing_flap(p, width: float, height: float, thickness: float | None = None, pin: float = 0.002) -> Part:
    """Swing flap: a plate turning about the horizontal axis through its centre, on
    pivot pins reaching ``pin`` metres past its side edges."""
    t = p.uniform("thickness", 0.002, 0.004, fixed=thickness)
    face = np.array([[-t / 2 - 1e-4, -width / 2, -height / 2], [-t / 2 + 1e-4, width / 2, height / 2]])
    pins = [cylinder(0.003, pin + 0.004, _Y.at(0, s * (width / 2 + pin / 2 - 0.002), 0), role="pin")
            for s in (-1.0, 1.0)]
    return Part("flap", "swing_flap", [cuboid(t, width, height, role="plate"), *pins],
                regions={"push": Region((), face)}, actionable="hinge_lid")


def round_collar(p, radius: float, opening: float, height: float | None = None) -> Part:
    """Ring collar on a round bin's rim around a round lid opening."""
    h = p.uniform("height", 0.02, 0.04, fixed=height)
    return Part("body", "round_collar", [ring(radius, opening, h, pose=translation(0, 0, h / 2), role="collar")],
                anchors={"opening": (opening, opening, h), "button": (-(radius + opening) / 2, 0.0, h)})


def rect_collar(p, depth: float, width: float, opening_depth: float, opening_width: float, front: float,
                height: float | None = None) -> Part:
    """Rectangular collar around a lid opening set ``front`` metres back from the
    middle (a wider band in front carries the release button)."""
    h = p.uniform("height", 0.02, 0.04, fixed=height)
    D, W, od, ow = depth / 2, width / 2, opening_depth / 2, opening_width / 2
    x0, x1 = front - od, front + od
    prims = [cuboid_between(lo, hi, role="collar") for lo, hi in (((-D, -W, 0), (x0, W, h)), ((x1, -W, 0), (D, W, h)),
                                                                 ((x0, -W, 0), (x1, -ow, h)), ((x0, ow, 0), (x1, W, h)))]
    return Part("body", "rect_collar", prims, anchors={"opening": (od, ow, h), "button": ((x0 - D) / 2, 0.0, h)})


def pedal_brackets(pedal_part: Part, reach: float) -> Part:
    """Two plates holding the ends of a pedal's pivot pin, reaching ``reach`` metres
    back (+x) from the pivot axis into the body's wall; in the pedal's pivot frame,
    for the body's link."""
    r, y = pedal_part.anchor("pin")[0], pedal_part.anchor("pin")[1]
    prims = [cuboid_between((-r, lo, -r), (reach, lo + 0.006, r), role="bracket") for lo in (y, -y - 0.006)]
    return Part("hinge", "pedal_brackets", prims)
