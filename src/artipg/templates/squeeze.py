"""Squeeze bottles (shampoo, conditioner, lotion): oval and round bodies and their
snap-on dispensing caps.

Bodies: origin at the centre of the base on z = 0, axis +z; each ends in a round neck
ring; the wide face of oval ones faces front (-x). Anchors as
:mod:`artipg.templates.bottles`: ``neck_top``, ``neck_edge``, ``bore_edge``,
``neck_base`` (the shoulder's top, where caps sit). Regions: grasp / lift on the wall.

Caps (:func:`flip_cap`, :func:`disc_cap`) are snap-on: their base is a part of the body
link (``parent``) standing on the shoulder around the neck; the moving part is a child
link. Frame of the cap functions: ``pose`` at the neck's base on the axis.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cylinder, frustum, ring
from artipg.geometry.extrusion import extrusion
from artipg.geometry.lathe import lathe
from artipg.geometry.transforms import Placer, rot_x, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates import dispensers
from artipg.templates.caps import CLEAR
from artipg.templates.levers import top_grasp

_ALONG_Y = Placer(rot_x(math.pi / 2))  # local z -> -y


def oval(a: float, b: float, end: float) -> np.ndarray:
    """Counter-clockwise four-arc oval, ``a`` half width along x, ``b`` along y (b >= a):
    flat arcs on the +-x faces, ends of radius ``end`` (< a) at +-y, tangent where they
    meet (the draughtsman's four-centre oval)."""
    R = (a * a + (b - end) ** 2 - end * end) / (2 * (a - end))  # face radius, centred at (a - R, 0)
    cx, cy = a - R, b - end  # face centre (cx, 0), end centre (0, cy)
    d = math.hypot(cx, cy)
    px, py = -cx * end / d, cy + cy * end / d  # tangent point on the +x +y quadrant
    phi = math.atan2(py, px - cx)  # half the turn of a face arc
    face, tip = math.tan(phi / 2), math.tan((math.pi - 2 * phi) / 4)
    return np.array([[px, -py, face], [px, py, tip], [-px, py, face], [-px, -py, tip]])


def _neck(p, z0: float, neck_r: float, neck_h: float, sink: float = 0.0):
    """Neck ring from ``z0`` up ``neck_h`` (its foot sunk ``sink`` into the shoulder)
    and the bottle anchors."""
    t = p.uniform("neck_wall", 0.0015, 0.0025)
    top = z0 + neck_h
    prim = ring(neck_r, neck_r - t, neck_h + sink, pose=translation(0, 0, top - (neck_h + sink) / 2), role="neck")
    anchors = {"neck_top": (0.0, 0.0, top), "neck_edge": (neck_r, 0.0, top),
               "bore_edge": (neck_r - t, 0.0, top), "neck_base": (0.0, 0.0, z0)}
    return prim, anchors


def _body(name, prims, neck):
    return Part("body", name, prims + [neck[0]], anchors=neck[1],
                regions={"grasp": Region(("wall",)), "lift": Region(("wall",))})


def oval_body(p, width: float, depth: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Oval squeeze bottle: a four-arc oval prism ``width`` (y: its wide face looks front,
    -x) by ``depth`` (x) with a flat top and a round sloped boss under the neck."""
    a, b = depth / 2, width / 2
    hs = p.uniform("shoulder", 0.02, 0.07) * height
    hb = height - neck_h - hs
    neck_r = min(neck_r, 0.7 * a)
    rb = max(p.uniform("boss", 0.75, 0.95) * a, neck_r + 0.003)
    end = p.uniform("end_radius", 0.35, 0.8) * a
    prims = [extrusion([oval(a, b, end)], hb, pose=translation(0, 0, hb / 2), role="wall"),
             frustum(rb, neck_r + p.uniform("boss_top", 0.001, 0.004), hs, translation(0, 0, hb + hs / 2),
                     role="shoulder")]
    return _body("oval_squeeze_body", prims, _neck(p, hb + hs, neck_r, neck_h, 0.002))


def flat_body(p, width: float, depth: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Flat bottle with rounded shoulders: :func:`artipg.templates.dispensers.oval_body`
    turned so its wide face looks front (-x)."""
    return dispensers.oval_body(p, width / 2, height, min(neck_r, 0.35 * depth), neck_h,
                                flat=(depth / width, depth / width), across=True)


def round_body(p, width: float, depth: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Round lotion bottle: a lathe profile with a straight wall and a rounded shoulder
    (``depth`` unused: round in plan). No barrelled wall: a near-straight arc costs
    ten times the point-sampling time of the whole object."""
    R = width / 2
    hs = p.uniform("shoulder", 0.08, 0.18) * height
    hb = height - neck_h - hs
    rt = neck_r + p.uniform("shoulder_top", 0.003, 0.008)
    loop = [(0.0, 0.0, 0.0), (R, 0.0, 0.0), (R, hb, p.uniform("shoulder_bulge", 0.15, 0.35)),
            (rt, hb + hs, 0.0), (0.0, hb + hs, 0.0)]
    return _body("round_squeeze_body", [lathe(loop, role="wall")], _neck(p, hb + hs, neck_r, neck_h, 0.002))


BODIES = {oval_body: 3.0, flat_body: 2.0, round_body: 1.0}


def cap_base(p, neck_r: float, neck_h: float, radius=(0.014, 0.022), top=(0.006, 0.014)):
    """Snap-on cap body: a cylinder over the neck (which it hides) standing on the
    shoulder, ``top`` m above the neck. Frame: origin at the neck's base. Returns
    (part, radius, height)."""
    R = max(p.uniform("cap_radius", *radius), neck_r + 0.002)
    h = neck_h + p.uniform("cap_top", *top)
    prims = [cylinder(R, h, translation(0, 0, h / 2), role="skirt")]
    return Part("cap", "snap_cap", prims, regions={"grasp": Region(("skirt",))}), R, h


def flip_cap(p, builder, parent, pose, neck_r: float, neck_h: float, open_range=(1.8, 2.8)):
    """Flip-top cap: a snap-on base with a nozzle on top under a lid hinged at the back
    (+x) edge (revolute about +y, ``open_range`` rad). Returns the lid link."""
    base, R, h = cap_base(p, neck_r, neck_h)
    hl = p.uniform("lid_skirt", 0.004, 0.009)
    tl = p.uniform("lid_top", 0.0015, 0.0025)
    hz = hl - p.uniform("nozzle_clearance", 0.001, 0.002)
    rz = p.uniform("nozzle_radius", 0.002, 0.004)
    base.primitives.append(cylinder(rz, hz, translation(-p.uniform("nozzle_offset", 0.0, 0.4) * (R - rz - 0.003), 0,
                                                         h + hz / 2), role="nozzle"))
    parent.add(base, pose)
    lid = Part("lid", "flip_lid", [ring(R, R - 0.0015, hl, pose=translation(-R, 0, -tl - hl / 2), role="lid"),
                                   cylinder(R, tl, translation(-R, 0, -tl / 2), role="lid")],
               regions={"lift": Region(("lid",)), "push": Region(("lid",))},
               grasps=Deferred.one(top_grasp, -R, 0.0, -(tl + hl) / 2, 2 * R + 0.02, "y"), actionable="hinge_lid")
    link = builder.create_link("lid", parent)
    link.set_joint("revolute", pose @ translation(R, 0, h + hl + tl), axis=(0.0, 1.0, 0.0),
                   limits=(0.0, p.uniform("lid_open", *open_range)))
    link.add(lid)
    return link


def disc_cap(p, builder, parent, pose, neck_r: float, neck_h: float):
    """Disc-top cap: a disc in a recess of the cap's top rocking on a pin across it
    (revolute about +y): pressing its back (+x) down tips its front, with the orifice,
    up. Returns the disc link."""
    base, R, h = cap_base(p, neck_r, neck_h, top=(0.01, 0.018))
    depth = p.uniform("recess", 0.004, 0.007)
    rim = p.uniform("rim", 0.0015, 0.003)
    rd = R - rim - CLEAR - 0.0005
    rp = min(p.uniform("pin_radius", 0.0012, 0.002), (depth - 0.0015) / 2)
    td = depth - 2 * rp + p.uniform("proud", 0.0, 0.0015)  # flush with the rim or a little proud
    z_floor = h - depth
    base.primitives = [cylinder(R, z_floor, translation(0, 0, z_floor / 2), role="skirt"),
                       ring(R, rd + CLEAR + 0.001, depth, pose=translation(0, 0, z_floor + depth / 2), role="skirt")]
    parent.add(base, pose)
    tilt = math.asin(min((2 * rp - 0.0005) / rd, 0.3))  # the back edge stops short of the floor
    disc = Part("button", "tilt_disc", [cylinder(rd, td, translation(0, 0, rp + td / 2), role="disc"),
                                        cylinder(rp, 1.2 * rd, _ALONG_Y.at(), role="pin"),
                                        cylinder(0.25 * rd, 0.001, translation(-0.6 * rd, 0, rp + td + 0.0005),
                                                 role="orifice")],
                regions={"press": Region(("disc",)), "push": Region(("disc",))})
    link = builder.create_link("disc", parent)
    link.set_joint("revolute", pose @ translation(0, 0, z_floor + rp), axis=(0.0, 1.0, 0.0), limits=(0.0, tilt))
    link.add(disc)
    return link
