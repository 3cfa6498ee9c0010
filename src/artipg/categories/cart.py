"""Carts standing on the floor, front towards -x: shopping carts, platform (utility)
carts and hand trucks.

Parts: shopping carts a chassis (two side rails on four casters, a lower tray), a wire
basket (floor, four wire walls with 4-10 duplicated wires each) on uprights, a push
handle (arms and a grip bar) behind it and a child-seat flap hanging outside the
basket's back wall; platform carts a deck (with or without a side lip) on four
casters and a U-shaped folding handle (two tube posts and a grip) hinged at its back
end; hand trucks two tube rails with 2-4 duplicated cross tubes and a grip on top, a
nose plate on the floor in front, two wheels on an axle behind the rails.
Casters are a fork on a swivel with a wheel on its axle (luggage templates); the
rear pair of a shopping or platform cart is sometimes fixed (no swivel). Wheels are
solid, tyred (a torus on a hub; casters only) or disc wheels (a flat tyre round a
hub).
Joints: swivels continuous about z, wheels continuous about their axles (y); child
seat flap revolute out towards the handle (90 degrees); platform handle revolute from
folded flat on the deck (rest) to upright (90 degrees); hand-truck nose plate revolute
about its back edge, folding up (90 degrees).
Sizes (metres): shopping cart 0.75-0.98 long, 0.5-0.6 wide, 0.95-1.1 to the grip,
casters 0.1-0.125 across; platform cart deck 0.6-0.9 x 0.4-0.6 at 0.13-0.22 over the
floor, casters 0.08-0.125 across, handle 0.65-0.85 long; hand truck 1.05-1.3 tall,
rails 0.32-0.42 apart, nose plate 0.18-0.3 deep, wheels 0.2-0.26 across.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cylinder
from artipg.geometry.transforms import rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.carts import (TRUCK_WHEELS, WHEELS, bar, caster_reach, deck, grip_bar, hinged_plate, mount_caster,
                                    tube_frame, wire_wall)
from artipg.templates.luggage import GAP
from artipg.model.part import Part

HANG = rot_y(-math.pi / 2)  # plate frames (hinge on the top edge, plate along local -x) turned to hang down


def _casters(ctx, xs, ys, r, tb, rear_fixed):
    """Four casters under the corners (xs front / back, ys) of the chassis, their forks'
    top blocks ``tb`` thick reaching up to GAP under it."""
    p, b = ctx.p, ctx.builder
    root = ctx.out["frame"][0]
    ww, plate = p.uniform("wheel_width", 0.022, 0.035), p.uniform("fork_plate", 0.003, 0.005)
    drop = r + GAP + tb
    tmpl = ctx.choose("wheel", WHEELS)
    for i, (x, y) in enumerate((x, y) for x in xs for y in (-ys, ys)):
        mount_caster(p.scope(f"caster{i}"), b, root, x, y, r, ww, plate, drop, swivel=not (rear_fixed and x == xs[1]),
                     tmpl=tmpl)
    return drop, caster_reach(r, ww, plate)


def frame(ctx):
    """Every sub-category's root: chassis, deck or rails (the casters and handles follow)."""
    root = ctx.builder.create_link("frame")
    return root, {"shopping": _shopping, "platform": _platform, "hand_truck": _hand_truck}[ctx.sub](ctx, root)


def _shopping(ctx, root):
    p = ctx.p
    r, tb = p.uniform("caster_radius", 0.05, 0.0625), p.uniform("fork_top", 0.01, 0.018)
    zc = r + (r + GAP + tb) + GAP  # the rails' bottom over the forks
    W, Lb = p.uniform("width", 0.5, 0.6), p.uniform("basket_length", 0.6, 0.75)
    hb = p.uniform("basket_height", 0.3, 0.4)
    zb = p.uniform("basket_bottom", 0.45, 0.55)
    x0, x1 = -Lb / 2, Lb / 2
    wire = p.uniform("wire", 0.005, 0.008)
    Wc = p.uniform("chassis_ratio", 0.75, 0.9) * W
    rail = 0.03
    xf, xb = x0 + 0.02, x1 - 0.02
    prims = [bar((xf, s * Wc / 2 - rail / 2, zc), (xb, s * Wc / 2 + rail / 2, zc + 0.025), "rail") for s in (-1, 1)]
    prims.append(bar((xf, -Wc / 2, zc), (xf + rail, Wc / 2, zc + 0.025), "rail"))
    for x in (xf + 0.06, xb - 0.06):  # uprights from the rails to the basket floor
        prims += [bar((x - 0.01, s * Wc / 2 - 0.01, zc + 0.025), (x + 0.01, s * Wc / 2 + 0.01, zb), "post")
                  for s in (-1, 1)]
    root.add(Part("body", "cart_chassis", prims))
    root.add(Part("shelf", "cart_tray", [bar((xf + rail + 0.05, -Wc / 2 + 0.005, zc + 0.025),
                                               (xb - 0.05, Wc / 2 - 0.005, zc + 0.035), "tray")]))
    root.add(Part("shelf", "basket_floor", [bar((x0, -W / 2, zb), (x1, W / 2, zb + 0.006), "floor")]))
    zt = zb + hb
    n_side, n_end = p.integers("side_wires", 6, 10), p.integers("end_wires", 4, 7)
    for s in (-1, 1):
        root.add(wire_wall(p, "body", 0, x0, x1, s * (W / 2 - wire / 2), zb + 0.006, zt, wire, n_side))
    for x in (x0 + wire / 2, x1 - wire / 2):
        root.add(wire_wall(p, "body", 1, -W / 2 + wire, W / 2 - wire, x, zb + 0.006, zt, wire, n_end))
    # push handle: arms back along the top of the side walls, then up, and the grip
    xh, zh, rg = x1 + p.uniform("handle_reach", 0.12, 0.2), zt + p.uniform("handle_rise", 0.05, 0.12), \
        p.uniform("grip_radius", 0.015, 0.02)
    arms = []
    for s in (-1, 1):
        y = s * (W / 2 - 0.01)
        arms += [bar((x1 - 0.02, y - 0.01, zt - 0.02), (xh + 0.01, y + 0.01, zt), "arm"),
                 bar((xh - 0.01, y - 0.01, zt - 0.02), (xh + 0.01, y + 0.01, zh), "arm")]
    root.add(Part("body", "handle_arms", arms))
    root.add(grip_bar(p, xh, -W / 2 - 0.01, W / 2 + 0.01, zh + rg - 0.005, rg))
    # child-seat flap hanging outside the back wall, folding out towards the handle
    zf = zt - p.uniform("flap_drop", 0.02, 0.05)
    lf = min(p.uniform("flap_length", 0.18, 0.25), xh - rg - x1 - 0.04, zf - zb - 0.02)
    wf = p.uniform("flap_width", 0.6, 0.75) * W
    flap = hinged_plate(p, "seat", lf, wf, p.uniform("flap_thickness", 0.006, 0.012), actionable="hinge_lid")
    link = ctx.builder.create_link("seat_flap", root)
    link.set_joint("revolute", translation(x1 + GAP, 0, zf) @ HANG, axis=(0.0, -1.0, 0.0),
                   limits=(0.0, math.pi / 2))
    link.add(flap)
    return dict(r=r, tb=tb, xs=(xf + 0.08, xb - 0.08), ys=Wc / 2)


def _platform(ctx, root):
    p = ctx.p
    r, tb = p.uniform("caster_radius", 0.04, 0.0625), p.uniform("fork_top", 0.01, 0.018)
    z0 = r + (r + GAP + tb) + GAP
    L, W, t = p.uniform("length", 0.6, 0.9), p.uniform("width", 0.4, 0.6), p.uniform("deck_thickness", 0.02, 0.04)
    lip = p.uniform("lip", 0.008, 0.02) if p.flag("has_lip", 0.5) else 0.0
    z1 = z0 + t
    root.add(deck(p, "top", -L / 2, L / 2, W, z0, z1, lip))
    # folding handle: lies on the deck at rest, hinged near the back end
    rt, wt = p.uniform("tube_radius", 0.011, 0.015), 0.0015
    rg = rt + 0.003
    Wh = W - 2 * (0.012 + rt + 0.01)
    Lh = min(p.uniform("handle_length", 0.65, 0.85), L - 0.06)
    xh, zh = L / 2 - 0.03, z1 + rg + GAP
    yb0, yb1 = Wh / 2 + rt + GAP, Wh / 2 + rt + GAP + 0.006
    root.add(Part("hinge", "handle_brackets", [bar((xh - 0.02, y0, z1), (xh + 0.02, y1, zh + rt), "bracket")
                                               for y0, y1 in ((-yb1, -yb0), (yb0, yb1))]))
    link = ctx.builder.create_link("handle", root)
    link.set_joint("revolute", translation(xh, 0, zh), axis=(0.0, 1.0, 0.0), limits=(0.0, math.pi / 2))
    link.add(tube_frame(p, "handle", [((-Lh + rg, s * Wh / 2, 0.0), (0.0, s * Wh / 2, 0.0)) for s in (-1, 1)], rt, wt))
    link.add(grip_bar(p, -Lh, -Wh / 2 - rt, Wh / 2 + rt, 0.0, rg, actionable="hinge_handle"))
    return dict(r=r, tb=tb, L=L, W=W)


def _hand_truck(ctx, root):
    p, b = ctx.p, ctx.builder
    S, rt, Hr = p.uniform("rail_span", 0.32, 0.42), p.uniform("rail_radius", 0.012, 0.016), \
        p.uniform("height", 1.05, 1.3)
    Ln, t = p.uniform("plate_depth", 0.18, 0.3), p.uniform("plate_thickness", 0.006, 0.01)
    Wn = S + 2 * rt + p.uniform("plate_overhang", 0.0, 0.01)  # as wide as the frame: the wheels stay outside
    xh = -0.05  # the nose plate's hinge (its top back edge); rails behind it
    xr = xh + GAP + rt
    zr = t + GAP
    k = p.integers("cross_tubes", 2, 4)
    segs = [((xr, s * S / 2, zr), (xr, s * S / 2, Hr)) for s in (-1, 1)]
    segs += [((xr, -S / 2 + rt, z), (xr, S / 2 - rt, z)) for z in
             (zr + 0.15 + (Hr - zr - 0.3) * i / max(1, k - 1) for i in range(k))]
    root.add(tube_frame(p, "body", segs, rt, 0.0015))
    root.add(Part("body", "toe_bar", [bar((xr - rt, -S / 2, zr), (xr + rt + 0.01, S / 2, zr + 0.03), "bar")]))
    rw, ww = p.uniform("wheel_radius", 0.1, 0.13), p.uniform("wheel_width", 0.05, 0.08)
    xa = xr + p.uniform("axle_back", 0.03, 0.07)
    yw = S / 2 + rt + GAP + 0.01 + ww / 2
    ra = p.uniform("axle_radius", 0.008, 0.012)
    parts = [bar((xr, s * S / 2 - 0.008, rw - 0.012), (xa, s * S / 2 + 0.008, rw + 0.012), "bracket") for s in (-1, 1)]
    root.add(Part("body", "axle_brackets", parts))
    T = translation(xa, 0, rw) @ np.array([[1.0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]])
    root.add(Part("body", "axle", [cylinder(ra, 2 * (yw - ww / 2 - GAP), T, role="axle")]))
    tmpl = ctx.choose("wheel", TRUCK_WHEELS)
    for i, s in enumerate((-1, 1)):
        link = b.create_link("wheel", root)
        link.set_joint("continuous", translation(xa, s * yw, rw), axis=(0.0, 1.0, 0.0))
        link.add(tmpl(p.scope(f"wheel{i}"), rw, ww))
    rg = p.uniform("grip_radius", 0.014, 0.018)
    root.add(grip_bar(p, xr, -S / 2 - rt - 0.03, S / 2 + rt + 0.03, Hr + rg - rt, rg))
    plate = hinged_plate(p, "flap", Ln, Wn, t)
    link = b.create_link("nose_plate", root)
    link.set_joint("revolute", translation(xh, 0, t), axis=(0.0, 1.0, 0.0), limits=(0.0, math.pi / 2))
    link.add(plate)
    return {}


def casters(ctx):
    root, d = ctx.out["frame"]
    if ctx.sub == "hand_truck":
        return
    p = ctx.p
    rear_fixed = p.flag("rear_fixed", 0.5)
    if ctx.sub == "shopping":
        _casters(ctx, d["xs"], d["ys"], d["r"], d["tb"], rear_fixed)
    else:  # keep the swivel sweep under the deck
        reach = caster_reach(d["r"], 0.035, 0.005) + 0.01
        _casters(ctx, (-d["L"] / 2 + reach, d["L"] / 2 - reach), d["W"] / 2 - reach, d["r"], d["tb"], rear_fixed)


RULE = Category(
    name="cart",
    subcategories={"platform": 1.5, "shopping": 2.0, "hand_truck": 1.5},
    materials={"body": "steel", "base": "steel", "shelf": "plastic", "seat": "plastic", "flap": "steel",
               "handle": "steel", "hinge": "steel", "top": "wood"},
    mass_range=(4.0, 45.0),  # kg: platform carts 8-20, hand trucks 10-20, shopping carts 15-35
    slots=(Slot("frame", frame), Slot("casters", casters, after=("frame",))),
)
