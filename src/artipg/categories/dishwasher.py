"""Dishwashers: freestanding, slimline, fully integrated (built-in) and countertop.

Parts: a tub (open-front carcass) on a recessed toe-kick plinth (countertop models on
feet), a worktop on freestanding models; a thick drop-down door with a horizontal
handle; the controls (a program knob and push buttons with bezels, optionally a
display) on a strip along the top of the door front, on the door's top edge (built-in
models, buttons pressed down) or on a fixed strip above the door (countertop); inside,
1-3 racks (wire baskets with or without plate tines, and a cutlery tray on top) on
rails along the tub walls, a lower spray arm on the tub floor and an upper spray arm
under the middle rack.
Joints: door revolute about the horizontal axis (-y) on its bottom front edge, opening
90 degrees down; racks prismatic along -x (0.55-0.8 of their depth, over the opened
door); spray arms continuous about z; knob continuous about its axis; buttons
prismatic into the panel (3-6 mm). Sizes (metres): 0.6 or 0.45 wide, 0.82-0.875 tall,
0.55-0.62 deep; countertop 0.55 x 0.5 x 0.44.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import rot_y, translated, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.appliance import control_panel, display
from artipg.templates.bodies import carcass
from artipg.templates.cells import add_door, choose
from artipg.templates.controls import BUTTONS, KNOBS, mount_button_row, mount_knob
from artipg.templates.handles import arch_handle, bar_handle, edge_pull, flat_bar_handle
from artipg.templates.mounting import mount_sliding
from artipg.templates.panels import framed_door, slab_door
from artipg.templates.racks import cutlery_tray, spray_arm, wire_rack
from artipg.templates.supports import bun_feet, plinth

# sub-category -> width, height, depth ranges, racks (lo, hi), where the controls are
SUBS = {
    "freestanding": ((0.595, 0.6), (0.82, 0.87), (0.58, 0.62), (2, 3), "door_front"),
    "slimline": ((0.445, 0.45), (0.82, 0.87), (0.58, 0.62), (2, 3), "door_front"),
    "built_in": ((0.595, 0.6), (0.815, 0.875), (0.55, 0.57), (2, 3), "door_top"),
    "countertop": ((0.54, 0.56), (0.43, 0.46), (0.48, 0.52), (1, 1), "body"),
}
HANDLES = {bar_handle: 2.0, flat_bar_handle: 2.0, arch_handle: 1.5, edge_pull: 1.0}
PANEL_DOORS = {slab_door: 1.0, framed_door: 1.0}  # integrated models take the kitchen's door panel
_UP = rot_y(math.pi / 2)  # controls on the door's top edge: the panel's outward normal (-x) -> +z


def body(ctx):
    p = ctx.p
    w, h, d, _, ctrl = SUBS[ctx.sub]
    W, H, D = p.uniform("width", *w), p.uniform("height", *h), p.uniform("depth", *d)
    root = ctx.builder.create_link("base")
    if ctrl == "body":
        zf = p.uniform("feet", 0.01, 0.02)
        root.add(bun_feet(p.scope("feet"), 0.9 * D, 0.9 * W, zf))
    else:
        zf = p.uniform("toe_kick", 0.08, 0.12)
        root.add(plinth(p.scope("plinth"), D, W, zf))
    wt = p.uniform("worktop", 0.02, 0.03) if ctx.sub == "freestanding" else 0.0
    if wt:  # flush with the tub front: the opening door never reaches under it
        root.add(Part("top", "worktop", [cuboid_between((-D / 2, -W / 2, H - wt), (D / 2, W / 2, H), role="top")]))
    tub = carcass(p, D, W, H - zf - wt)
    root.add(tub, translation(0, 0, (H - wt + zf) / 2))
    return root, (W, H - wt, D, zf, tub.primitives[1].params[1], tub.primitives[0].params[0])


def door(ctx):
    root, (W, Ht, D, zf, wall, back) = ctx.out["body"]
    p = ctx.p
    ctrl = SUBS[ctx.sub][4]
    t = p.uniform("door_thickness", 0.035, 0.05) if ctrl == "body" else p.uniform("door_thickness", 0.05, 0.07)
    cs = p.uniform("strip", 0.07, 0.1)
    top = Ht
    if ctrl == "body":  # fixed strip above the door; the door's top back corner rises sqrt(h^2+t^2)-h
        tc = p.uniform("strip_thickness", 0.01, 0.02)
        h = Ht - cs - zf
        top = Ht - cs - (math.hypot(h, t) - h + 0.002)
        strip = control_panel(p.scope("strip"), W, cs, tc)
        root.add(strip, translation(-D / 2, 0, Ht - cs / 2))
        panel_pose = translation(-D / 2 - tc, 0, Ht - cs / 2)
    tmpl = slab_door if ctrl != "door_top" else choose(ctx, p, "door", PANEL_DOORS)
    if ctrl == "door_front":  # the handle goes under the control strip
        margin = cs + p.uniform("handle_gap", 0.03, 0.045)
    else:
        margin = p.uniform("handle_margin", 0.035, 0.06)
    link = add_door(ctx, root, p.scope("door"), front_x=-D / 2, outer=(-W / 2 + 0.002, W / 2 - 0.002, zf, top),
                    side="-z", limits=(0.0, math.pi / 2), template=tmpl, handle=ctx.choose("handle", HANDLES),
                    thickness=t,
                    handle_length=min(0.45, 0.7 * W), margin=margin)
    dp = link.link.parts[0]
    hd = (top - zf) / 2
    if ctrl == "door_front":
        panel_pose, parent = translated(dp.pose, -t, 0, hd - cs / 2), link
    elif ctrl == "door_top":
        panel_pose, parent = translated(dp.pose, -t / 2, 0, hd) @ _UP, link
    else:
        parent = root
    _controls(ctx, parent, panel_pose, W, cs if ctrl != "door_top" else t, ctrl)
    return link, t


def _controls(ctx, parent, pose, W, band, ctrl):
    """A knob at one end and a row of buttons along the band (width W, height ``band``)."""
    p = ctx.p.scope("controls")
    y = W / 2 - 0.06
    if ctrl != "door_top" and p.flag("knob", 0.7):
        r = min(0.03, band / 2 - 0.008)
        knob = ctx.choose("knob", KNOBS)(p.scope("knob"), radius=r)
        s = p.choice("knob_side", (-1, 1))
        mount_knob(ctx.builder, parent, knob, translated(pose, 0, s * (W / 2 - 0.03 - r), 0), continuous=True)
        y = W / 2 - 0.08 - 2 * r
        lo, hi = (-y, W / 2 - 0.06) if s < 0 else (-(W / 2 - 0.06), y)
    else:
        lo, hi = -y, y
    if ctrl != "door_top" and p.flag("display", 0.5):
        dw = 0.25 * (hi - lo)
        parent.add(display(p.scope("display"), dw, 0.5 * band), translated(pose, 0, hi - dw / 2, 0))
        hi -= dw + 0.02
    tmpl = ctx.choose("button", BUTTONS)
    size = min(0.02, band - 0.02)
    n = p.integers("buttons", 2, max(2, min(6, int((hi - lo) / (size + 0.014)))))
    mount_button_row(p, ctx.builder, parent, tmpl, n, pose, lo, hi, 0.0, radius=size / 2 * 0.8,
                     square=(size, 0.7 * size))


def racks(ctx):
    root, (W, Ht, D, zf, wall, back) = ctx.out["body"]
    _, t = ctx.out["door"]
    p = ctx.p
    n = p.integers("racks", *SUBS[ctx.sub][3])
    x0, x1 = -D / 2 + 0.012, D / 2 - back - 0.015
    yi, z_floor, z_top = W / 2 - wall, zf + wall, Ht - wall - 0.01
    sh = p.uniform("spray_height", 0.018, 0.028)
    z = max(zf + t + 0.012, z_floor + sh + 0.012)  # lower rack clears the opened door
    hs = [p.uniform("lower", 0.15, 0.22), p.uniform("upper", 0.12, 0.16), p.uniform("tray", 0.035, 0.05)][:n]
    gaps = [0.0, 0.015 + sh + 0.012, 0.012][:n]
    scale = min(1.0, (z_top - z - sum(gaps)) / sum(hs))
    extra = (z_top - z - sum(gaps) - scale * sum(hs)) * p.uniform("spread", 0.3, 0.8) / n  # spread the racks
    xc, dr, wr = (x0 + x1) / 2, x1 - x0, 2 * yi - 0.006
    R = min(dr, wr) / 2 - 0.045
    arm = ctx.builder.create_link("arm", root)
    arm.set_joint("continuous", translation(xc, 0, z_floor))
    arm.add(spray_arm(p.scope("spray0"), R, sh))
    for i in range(n):
        z += gaps[i] + (extra if i else 0.0)
        q = p.scope(f"rack{i}")
        rack = (cutlery_tray if i == 2 else wire_rack)(q, dr, wr, hs[i] * scale)
        ctx.templates.setdefault(ctx.slot, []).append(rack.template)
        rails = [cuboid_between((x0, min(s * yi, s * (yi - 0.012)), z - 0.01), (x1, max(s * yi, s * (yi - 0.012)), z),
                                role="rail") for s in (-1, 1)]
        root.add(Part("body", "rails", rails))
        link = mount_sliding(ctx.builder, root, rack, origin=translation(xc, 0, z), name="tray",
                             limits=(0.0, q.uniform("travel", 0.55, 0.8) * dr))
        if i == 1:  # upper spray arm, fed by a tube under the middle rack
            feed = cuboid_between((0.0, -0.012, -0.015), (dr / 2, 0.012, 0.0), role="tube")
            link.add(Part("tray", "feed_tube", [feed]))
            up = ctx.builder.create_link("arm", link)
            up.set_joint("continuous", translation(0, 0, -0.015 - sh))
            up.add(spray_arm(p.scope("spray1"), R, sh))
        z += hs[i] * scale


RULE = Category(
    name="dishwasher",
    subcategories={"freestanding": 2.0, "built_in": 2.0, "slimline": 1.0, "countertop": 1.0},
    materials={"body": "shell", "door": "shell", "leg": "shell", "base": "shell", "top": "shell", "drawer": "shell"},
    mass_range=(10.0, 80.0),  # kg: countertop units (~20 kg) to full-size built-ins (~50 kg)
    slots=(Slot("body", body), Slot("door", door, after=("body",)), Slot("racks", racks, after=("body", "door"))),
)
