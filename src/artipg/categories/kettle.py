"""Kettles: electric jugs, stovetop kettles and pour-over (gooseneck) kettles.

Parts: a body closed at the top but for a filling opening with a collar (straight or
gently tapered, wide-based cone, or round belly), on a power base for electric ones;
a lid on the collar; a spout on one side (+y: a short beak, a straight cone, or a thin
gooseneck; stovetop ones may carry a whistle cap) and the handle on the other (-y),
so the front view (-x) shows the kettle's profile: a side C handle (round tube,
moulded D, or thin frame with a grip sleeve) or, on stovetop kettles, a swinging wire
bail on two lugs or a fixed arch over the lid. Electric jugs have an on/off lever
under the handle and a lid-release button on it, electric pour-over kettles a power
button on the base.
Joints: lid revolute about a hinge on the handle side (electric, 70-90 deg) or
prismatic along the axis (lifted off, clear of any handle above it); bail revolute
(folds away from the spout); whistle cap revolute (flips up); on/off lever revolute
(+-17-26 deg); buttons prismatic.
Sizes (metres): electric 0.18-0.26 tall, radius 0.065-0.085; stovetop 0.13-0.2
tall, radius 0.08-0.12; pour-over 0.1-0.15 tall, radius 0.055-0.075.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid
from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.controls import mount_button, round_button
from artipg.templates.cookware import KETTLE_HANDLES, arch_top_handle
from artipg.templates.levers import BAILS, ear_lugs
from artipg.templates.lids import domed_lid, flat_lid, knobbed_lid, mount_lid
from artipg.templates.pour_spouts import cone_spout, gooseneck_spout, lip_spout, mount_pose, whistle_cap
from artipg.templates.vessels import (bellied_kettle_body, conical_kettle_body, power_base, straight_kettle_body,
                                      wall_radius, wall_slope)
from artipg.templates.wall_switch import button_bezel, toggle_module

TURN = rot_z(-math.pi / 2)
HALF_TURN = rot_z(math.pi)
UP = rot_y(math.pi / 2)  # a button's -x (out of its surface) points up
# sub-category -> radius, height, opening (fraction of radius), bodies, lids, spouts, P(power base)
SUBS = {
    "electric": ((0.065, 0.085), (0.18, 0.26), (0.5, 0.68), {straight_kettle_body: 1.0},
                 {flat_lid: 1.0, domed_lid: 1.0}, {lip_spout: 1.0}, 1.0),
    "stovetop": ((0.08, 0.12), (0.13, 0.2), (0.3, 0.36), {conical_kettle_body: 3.0, bellied_kettle_body: 2.0},
                 {knobbed_lid: 1.0}, {cone_spout: 2.0, gooseneck_spout: 1.0}, 0.0),
    "gooseneck": ((0.055, 0.075), (0.1, 0.15), (0.55, 0.66), {straight_kettle_body: 1.0},
                  {knobbed_lid: 2.0, flat_lid: 1.0}, {gooseneck_spout: 1.0}, 0.5),
}


def body(ctx):
    p = ctx.p
    rr, hr, orr, bodies, lids, _, p_base = SUBS[ctx.sub]
    R, H = p.uniform("radius", *rr), p.uniform("height", *hr)
    opening = p.uniform("opening", *orr) * R
    lid = ctx.choose("lid", lids)(p.scope("lid"), opening)
    part = ctx.choose("body", bodies)(p, R, H, opening, skirt=-float(lid.anchors["hinge"][2]))
    root = ctx.builder.create_link("body")
    zb, base = 0.0, None
    if p.flag("power_base", p_base):
        base = root.add(power_base(p.scope("base"), R))
        zb = float(base.anchors["top"][2])
    root.add(part, _at(zb))
    return root, part, zb, lid, base


def handle(ctx):
    root, part, zb, lid, _ = ctx.out["body"]
    p = ctx.p
    H = float(part.anchors["shoulder"][2])
    rim = float(part.anchors["rim"][2])
    if ctx.sub != "stovetop":
        r = 0.012  # bound of the handle's half thickness
        zt = H - p.uniform("top_gap", 0.02, 0.04) - r
        zl = min(max(p.uniform("low", 0.12, 0.3) * H, 0.05 if ctx.sub == "electric" else 0.0), zt - 0.045)
        h = ctx.choose("handle", KETTLE_HANDLES)(p, wall_radius(part, zt), zt, wall_radius(part, zl), zl)
        root.add(h, _at(zb))
        return h, zl, None
    lift = p.uniform("lift", 0.02, 0.05)
    # lifted lid plus room for fingers on its knob (a gripper reaching in from the side)
    above = rim + float(lid.anchors["top"][2]) + lift + 0.015
    d = (wall_radius(part, H) + float(lid.anchors["hinge"][0])) / 2
    if wall_radius(part, H) - d > 0.012 and p.flag("fixed_arch", 0.35):
        root.add(arch_top_handle(p, d, above - H), _at(zb + H))
        return None, 0.0, lift
    zp = H - p.uniform("pivot_drop", 0.003, 0.015)
    wy = wall_radius(part, zp)
    span = wy + p.uniform("lug_length", 0.012, 0.018)
    bail = ctx.choose("bail", BAILS)(p, span, clear=(max(float(lid.anchors["hinge"][0]), wall_radius(part, H)) + 0.003,
                                                      above - zp))
    root.add(ear_lugs(p, wy, float(bail.anchors["pin_+y"][1])), _at(zb + zp))
    link = ctx.builder.create_link("bail", root)
    link.set_joint("revolute", _at(zb + zp), axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("fold", 1.2, 1.5)))
    link.add(bail)
    return None, 0.0, lift


def lid(ctx):
    root, part, zb, lid, _ = ctx.out["body"]
    rim = _at(zb + float(part.anchors["rim"][2]))
    if ctx.sub == "electric":
        mount_lid(ctx.builder, root, lid, rim, mode="flip", limit=ctx.p.uniform("open", 1.2, 1.55))
    else:
        lift = ctx.out["handle"][2]  # limited by a handle over the lid, else free
        mount_lid(ctx.builder, root, lid, rim, mode="lift", limit=lift or ctx.p.uniform("lift", 0.04, 0.12))


def spout(ctx):
    root, part, zb, *_ = ctx.out["body"]
    p = ctx.p
    H = float(part.anchors["rim"][2])
    tmpl = ctx.choose("spout", SUBS[ctx.sub][5])
    z = H - p.uniform("drop", 0.03, 0.045) if tmpl is lip_spout else p.uniform("low", 0.12, 0.3) * H
    s = tmpl(p, rise=H - z + p.uniform("over", -0.01, 0.02))
    T = _at(zb) @ HALF_TURN @ translation(wall_radius(part, z), 0, z) @ rot_y(math.atan(wall_slope(part, z)))
    root.add(s, T)
    if tmpl is not lip_spout and p.flag("whistle", 0.5):
        cap = whistle_cap(p.scope("whistle"), float(s.anchors["tip_r"][0]))
        d = s.anchors["tip_dir"]
        link = ctx.builder.create_link("whistle", root)
        hinge = mount_pose(s.anchors["tip"], math.atan2(d[2], d[0]), float(cap.anchors["radius"][0]))
        link.set_joint("revolute", T @ hinge, axis=(0.0, -1.0, 0.0), limits=(0.0, p.uniform("open", 1.2, 1.7)))
        link.add(cap)


def controls(ctx):
    root, part, zb, _, base = ctx.out["body"]
    h, zl, _ = ctx.out["handle"]
    p = ctx.p
    if ctx.sub == "electric" and p.flag("switch", 0.85):  # on/off lever under the handle
        z = zl - float(h.anchors["tube"][0]) - 0.016
        tilt = rot_y(math.atan(wall_slope(part, z)))  # along the wall's outward normal
        pose = _at(zb + z) @ translation(wall_radius(part, z), 0, 0) @ tilt @ HALF_TURN
        toggle_module(p.scope("switch"), ctx.builder, root, pose, 0.014, 0.022)
    if ctx.sub == "electric" and p.flag("release", 0.6):  # lid-release button on top of the handle
        x, _, z = h.anchors["top"]
        r = float(h.anchors["tube"][0])
        # the pressed cap (radius <= 0.6 r) stays 1 mm off the body's wall
        x = max(x, wall_radius(part, z) + 0.6 * r + 0.001)
        pad = p.uniform("pad", 0.003, 0.005)
        root.add(Part("handle", "button_pad", [cuboid(0.022, 2 * r, pad, translation(x, 0, z + pad / 2 - 0.001),
                                                      role="pad")]), _at(zb), name="pad")
        _button(p.scope("release"), ctx.builder, root, _at(zb) @ translation(x, 0, z + pad - 0.001) @ UP, 0.6 * r)
    if base is not None and ctx.sub == "gooseneck":  # power button on the base's front
        r, _, z = base.anchors["edge"]
        _button(p.scope("power"), ctx.builder, root, _at(0.0) @ translation(-r, 0, z), min(0.005, z - 0.0045))


def _at(z):
    """Pose of the kettle's build frame at height z: built with the spout at -x and the
    handle at +x, a kettle is turned so that they point to +y and -y (side profile).

    The same matrix as ``TURN @ translation(0, 0, z)``, made without the product: TURN
    turns about z, so its third row is (0, 0, 1, 0) and it has no translation; the
    product's sum turns a -0.0 into +0.0, and so does ``+ 0.0``."""
    T = TURN.copy()
    T[2, 3] = z + 0.0
    return T


def _button(p, builder, root, pose, radius):
    b = round_button(p, radius=p.uniform("radius", 0.6, 1.0) * radius)
    root.add(button_bezel(p, b, pose, True), name="bezel")
    mount_button(builder, root, b, pose)


RULE = Category(
    name="kettle",
    subcategories={"electric": 3.0, "stovetop": 2.0, "gooseneck": 1.5},
    materials={"body": "plastic", "base": "plastic"},
    mass_range=(0.3, 3.0),  # kg: plastic electric kettles with base to stovetop kettles
    slots=(Slot("body", body), Slot("handle", handle, after=("body",)), Slot("lid", lid, after=("handle",)),
           Slot("spout", spout, after=("body",)), Slot("controls", controls, after=("handle",))),
)
