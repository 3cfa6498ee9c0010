"""Laptops: ultrabooks, mainstream and business notebooks and gaming laptops.

Parts: a base slab on round feet or rubber strips with one full-width hinge barrel or
two short ones along its back edge; on the deck a keyboard (raised rows, chiclet
blocks with an optional numeric keypad, or a key field in a surround), a touchpad and,
on business laptops, three touchpad buttons (prismatic, 1-1.5 mm down); optionally a
power button near the hinge (prismatic). The screen lid (shell, a rim that stands on
the deck and keeps the display clear of the keys, the display) turns on a revolute
hinge about the barrel axis: 0 = closed, opening to 1.9-2.4 rad, capped where the
lid's back edge would reach the table.
Joints: 1-5 movable. Sizes (metres): base 0.29-0.40 wide, 0.195-0.29 deep, 9-28 mm
thick; lid 4-12 mm.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.controls import button_bezel, mount_button, rect_button, round_button
from artipg.templates.laptop import KEYBOARDS, laptop_base, screen_lid, touchpad

# sub-category -> width, depth, base thickness, lid thickness, touchpad width / base width
# (widened on the development split: aspect ratios from 16:9 to 3:2, older thick bases)
SIZES = {"ultrabook": ((0.28, 0.34), (0.19, 0.245), (0.009, 0.016), (0.004, 0.006), (0.4, 0.55)),
         "mainstream": ((0.32, 0.39), (0.21, 0.27), (0.015, 0.028), (0.006, 0.009), (0.3, 0.45)),
         "business": ((0.3, 0.37), (0.2, 0.26), (0.015, 0.03), (0.006, 0.009), (0.28, 0.35)),
         "gaming": ((0.35, 0.41), (0.24, 0.3), (0.02, 0.035), (0.008, 0.012), (0.3, 0.4))}
_FACE_UP = Placer(rot_y(math.pi / 2))  # control frame (surface normal -x) -> surface normal +z


def base(ctx):
    p = ctx.p
    w, d, h, _, pad = SIZES[ctx.sub]
    W, D, H = p.uniform("width", *w), p.uniform("depth", *d), p.uniform("thickness", *h)
    power = p.flag("power_button", 0.5)  # behind the keyboard, clear of the lid's rim
    side, back = p.uniform("side_margin", 0.012, 0.03), p.uniform("back_margin", *((0.032, 0.04) if power else
                                                                                   (0.012, 0.03)))
    kd, kw = p.uniform("keyboard_depth", 0.38, 0.46) * D, W - 2 * side
    xk = D / 2 - back - kd  # keyboard front edge
    palm = xk + D / 2 - 0.008  # palm rest depth in front of it
    bw = p.uniform("pad_width", *pad) * W
    bd = p.uniform("button_depth", 0.008, 0.012) if ctx.sub == "business" else 0.0
    if bd:  # three touchpad buttons between the keyboard and the touchpad
        palm -= bd + 0.006
    pd = p.uniform("pad_depth", 0.55, 0.8) * palm
    pf = -D / 2 + p.uniform("pad_front", 0.25, 0.45) * (palm - pd) + 0.006  # touchpad front edge
    holes = [(xk, xk + kd, -kw / 2, kw / 2), (pf, pf + pd, -bw / 2, bw / 2)]
    root = ctx.builder.create_link("base")
    part = root.add(laptop_base(p, W, D, H, holes))
    z, sk = part.anchor("deck")[2], part.anchor("skin")[0]
    kh = p.uniform("key_height", 0.0008, 0.0015)
    root.add(ctx.choose("keyboard", KEYBOARDS)(p.scope("keyboard"), kw, kd, kh, sk), translation(xk + kd / 2, 0, z))
    root.add(touchpad(p.scope("touchpad"), bw, pd, sk), translation(pf + pd / 2, 0, z))
    tops = [kh]
    for i in range(3 if bd else 0):
        tops.append(_button(ctx, root, rect_button, p.scope(f"pad_button{i}"),
                            _FACE_UP.at(xk - 0.004 - bd / 2, (i - 1) * bw / 3, z), width=bw / 3 - 0.006,
                            height=bd))
    if power:
        y = p.choice("power_side", (1.0, -1.0)) * (W / 2 - max(side, 0.02) - 0.01)
        tops.append(_button(ctx, root, round_button, p.scope("power"), _FACE_UP.at(D / 2 - back / 2 - 0.003, y, z),
                            radius=p.uniform("power_radius", 0.003, 0.005)))
    return root, part, W, D, max(tops)


def _button(ctx, root, tmpl, q, pose, **size):
    """A low push button (1-1.5 mm travel) in a collar on the deck; returns its height."""
    travel = q.uniform("press_travel", 0.001, 0.0015)
    b = tmpl(q, reach=travel + q.uniform("reach", 0.0032, 0.004), travel=travel, **size)
    root.add(button_bezel(q.scope("bezel"), b), pose)
    mount_button(ctx.builder, root, b, pose, name="button")
    return -b.anchor("front")[0]


def screen(ctx):
    root, part, W, D, top = ctx.out["base"]
    p = ctx.p
    rim = top + p.uniform("rim_clearance", 0.0008, 0.0015)
    rb = part.anchor("barrel")[0]
    ax, _, az = part.anchor("hinge")
    t = p.uniform("lid_thickness", *SIZES[ctx.sub][3])
    lid = screen_lid(p, W, ax + D / 2, t, rim, rb)
    # the highest back corner of the lid swings below the axis past 90 degrees
    floor = math.acos(max(-1.0, -az / (rb + rim + t))) - 0.02
    lim = min(p.uniform("limit", 1.9, 3.0), floor)  # some real screens open flat (fit on the development split)
    link = ctx.builder.create_link("screen", root)
    link.set_joint("revolute", translation(ax, 0, az), axis=(0, 1, 0), limits=(0.0, lim))
    link.add(lid)


RULE = Category(
    name="laptop",
    subcategories={"mainstream": 3.0, "ultrabook": 2.0, "business": 1.5, "gaming": 1.0},
    materials={"base": "aluminium", "screen": "plastic"},
    mass_range=(0.7, 4.5),  # kg: ultrabooks (~1 kg) to gaming laptops (~3 kg)
    slots=(Slot("base", base), Slot("screen", screen, after=("base",))),
)
