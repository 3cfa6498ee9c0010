"""Mobile phones lying on a table, display up, earpiece end at +x: flip (clamshell)
phones, slider phones, bar (candy-bar) keypad phones and smartphones.

Parts: flip phones a lower half with a navigation row and a 3 x 4 keypad
and an upper half (the lid) with an inner display facing the keypad and often an outer
one, joined by hinge knuckles (two on the lower half, one on the lid); slider phones a
lower half with a 3 x 4 keypad between two slide rails and an upper half (the lid)
carrying the display and a navigation row; bar phones one body with a display, a
navigation row and a 3 x 4 keypad; smartphones one slab with a display covering most of
the top. Side keys (volume up / down, power) on the sides.
Joints: flip lid revolute about the hinge axis (y) up to 150-165 degrees; slider lid
prismatic along +x far enough to uncover the keypad (0.035-0.05 m); keys prismatic
into the face (0.5-1 mm); side keys prismatic into the side (0.4-0.7 mm).
Sizes (metres, L x W x T): smartphone 0.14-0.165 x 0.066-0.078 x 0.007-0.009 (iPhone
15 148 x 72 x 7.8); bar phone 0.105-0.13 x 0.045-0.055 x 0.012-0.018 (Nokia 105 120
x 50 x 14.5); flip (closed) 0.08-0.1 x 0.045-0.054 x 0.019-0.025 (Motorola RAZR V3
98 x 53 x 14, Samsung E1150 90 x 46 x 19); slider (closed) 0.09-0.11 x 0.046-0.055 x
0.019-0.025 (Nokia N95 99 x 53 x 21). Keys are flat (standing 0.3 mm off their face,
0.6-1.2 mm proud) so they need no collars.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.controls import mount_button, mount_keypad
from artipg.templates.phones import KEYS, display, knuckles, rails, round_key, side_key, slab

UP = rot_y(math.pi / 2)  # control frames (protruding -x, "up" +z) turned to protrude +z, "up" towards +x
FACE_DOWN = rot_x(math.pi)
GAP = 0.0005
SUBS = {  # width, thickness (of a half for flip / slider), edge radius
    "smartphone": ((0.066, 0.078), (0.007, 0.009), (0.0015, 0.003)),
    "bar": ((0.045, 0.055), (0.012, 0.018), (0.002, 0.004)),
    "flip": ((0.045, 0.054), (0.007, 0.01), (0.0015, 0.003)),
    "slider": ((0.046, 0.055), (0.007, 0.01), (0.0015, 0.003)),
}


def _pad(p, b, parent, kind, x, z, rows, cols, cell, travel, fill):
    """A ``rows`` x ``cols`` keypad of flat keys filling ``fill`` of their ``cell``
    (y, x extents), centred at (x, 0) on the face z of ``parent``."""
    key = kind(p, fill * cell[0], fill * cell[1], travel)
    mount_keypad(b, parent, key, translation(x, 0, z) @ UP, rows, cols, cell, name="key")


def body(ctx):
    p, b = ctx.p, ctx.builder
    wr, tr, rr = SUBS[ctx.sub]
    W, T = p.uniform("width", *wr), p.uniform("thickness", *tr)
    r = min(p.uniform("edge_radius", *rr), (T - 0.004) / 2)  # leaves a flat side of >= 4 mm for the side keys
    travel = p.uniform("key_travel", 0.0005, 0.001)
    reach = travel + 0.0015  # the highest a key's top stands over its face (side_key: stand-off + proud)
    pitch = p.uniform("key_pitch", 0.008, 0.0105)
    Wu = W - 2 * r - 2 * p.uniform("side_margin", 0.002, 0.004)
    root = b.create_link("body")
    dims = dict(W=W, T=T, r=r, travel=travel, reach=reach, pitch=pitch, Wu=Wu)
    if ctx.sub == "smartphone":
        L = p.uniform("length", 0.14, 0.165)
        root.add(slab(p, "body", L, W, T, r))
        m = p.uniform("bezel", 0.002, 0.005)
        root.add(display(p, L - 2 * m - 0.006, W - 2 * m), translation(-0.002, 0, T))
        dims.update(L=L, side_z=T / 2, side_h=T - 2 * r - 0.001)
    elif ctx.sub == "bar":
        nav, gap = p.uniform("nav_pitch", 0.01, 0.013), p.uniform("block_gap", 0.004, 0.008)
        ls, top, bottom = p.uniform("screen_length", 0.03, 0.045), p.uniform("top", 0.01, 0.015), \
            p.uniform("bottom", 0.006, 0.012)
        L = top + ls + gap + nav + gap + 4 * pitch + bottom
        root.add(slab(p, "body", L, W, T, r))
        x = L / 2 - top
        root.add(display(p, ls, p.uniform("screen_width", 0.75, 0.9) * Wu), translation(x - ls / 2, 0, T))
        x -= ls + gap
        _pad(p.scope("nav"), b, root, round_key if p.flag("round_nav", 0.5) else side_key, x - nav / 2, T, 1, 3,
             (Wu / 3, nav), travel, 0.75)
        x -= nav + gap
        _pad(p.scope("grid"), b, root, ctx.choose("key", KEYS), x - 2 * pitch, T, 4, 3, (Wu / 3, pitch),
             travel, p.uniform("key_fill", 0.65, 0.8))
        dims.update(L=L, side_z=T / 2, side_h=min(0.005, T - 2 * r - 0.001))
    return root, dims


def flip(ctx):
    root, d = ctx.out["body"]
    if ctx.sub != "flip":
        return
    p, b = ctx.p, ctx.builder
    W, t1, r, reach, travel, pitch, Wu = d["W"], d["T"], d["r"], d["reach"], d["travel"], d["pitch"], d["Wu"]
    t2 = p.uniform("lid_thickness", 0.006, 0.009)
    gk = reach + 0.0018  # the keys' caps and the inner display's glass clear each other when closed
    rb = t2 / 2 + 0.5 * gk
    zh = t1 + gk + t2 / 2
    nav, gap = p.uniform("nav_pitch", 0.01, 0.013), p.uniform("block_gap", 0.003, 0.006)
    top, bottom = rb + p.uniform("top", 0.006, 0.012), p.uniform("bottom", 0.01, 0.02)
    L1 = top + nav + gap + 4 * pitch + bottom
    xh = L1 / 2  # the hinge axis over the lower half's +x end
    root.add(slab(p, "body", L1 + rb, W, t1, r), translation(rb / 2, 0, 0))  # reaches under the knuckles
    yc = p.uniform("centre_knuckle", 0.4, 0.6) * W / 2
    side = ((yc + 0.001, W / 2 - r), (-(W / 2 - r), -yc - 0.001))
    root.add(knuckles(p, "hinge", rb, side), translation(xh, 0, zh))
    root.add(Part("hinge", "knuckle_blocks", [cuboid_between((xh - 0.6 * rb, y0, t1 - 0.0005), (xh + 0.6 * rb, y1, zh),
                                                                            role="block")
                                              for y0, y1 in side]))
    x = xh - top
    _pad(p.scope("nav"), b, root, side_key, x - nav / 2, t1, 1, 3, (Wu / 3, nav), travel, 0.75)
    x -= nav + gap
    _pad(p.scope("grid"), b, root, ctx.choose("key", KEYS), x - 2 * pitch, t1, 4, 3, (Wu / 3, pitch), travel,
         p.uniform("key_fill", 0.65, 0.8))
    lid = b.create_link("lid", root)
    lid.set_joint("revolute", translation(xh, 0, zh), axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("open", 2.6, 2.9)))
    Ll = L1 - rb - 0.001 - r  # the lid slab stops short of the side knuckles' reach
    lid.add(slab(p.scope("lid"), "lid", Ll, W, t2, min(r, t2 / 2 - 0.0005), actionable="hinge_lid"),
            translation(-rb - 0.001 - Ll / 2, 0, -t2 / 2))
    lid.add(knuckles(p, "hinge", rb, ((-yc, yc),)))
    tongue = cuboid_between((-rb - 0.002, -yc + 0.001, -0.4 * t2), (0.0, yc - 0.001, 0.4 * t2), role="block")
    lid.add(Part("hinge", "knuckle_tongue", [tongue]))
    ls = min(p.uniform("inner_screen", 0.7, 0.85) * Ll, Ll - 0.006)
    lid.add(display(p.scope("inner"), ls, 0.85 * Wu), translation(-rb - 0.001 - Ll / 2, 0, -t2 / 2) @ FACE_DOWN)
    if p.flag("outer_screen", 0.6):
        lo = p.uniform("outer_screen", 0.2, 0.35) * Ll
        lid.add(display(p.scope("outer"), lo, 0.5 * Wu), translation(-rb - 0.001 - 0.3 * Ll, 0, t2 / 2))
    d.update(L=L1, side_z=t1 / 2, side_h=min(0.005, t1 - 2 * r - 0.001), x_shift=rb / 2)


def slider(ctx):
    root, d = ctx.out["body"]
    if ctx.sub != "slider":
        return
    p, b = ctx.p, ctx.builder
    W, t1, r, reach, travel, pitch = d["W"], d["T"], d["r"], d["reach"], d["travel"], d["pitch"]
    t2 = p.uniform("lid_thickness", 0.006, 0.01)
    g = reach + 0.001
    L = p.uniform("length", 0.09, 0.11)
    root.add(slab(p, "body", L, W, t1, r))
    yo = W / 2 - r
    yi = yo - p.uniform("rail_width", 0.002, 0.004)
    root.add(rails(p, L - 2 * r, yi, yo, g - GAP), translation(0, 0, t1))
    Wu = 2 * yi - 0.004
    Lk = 4 * pitch
    xk = -L / 2 + r + 0.004 + Lk / 2
    _pad(p.scope("grid"), b, root, ctx.choose("key", KEYS), xk, t1, 4, 3, (Wu / 3, pitch), travel,
         p.uniform("key_fill", 0.65, 0.8))
    lid = b.create_link("lid", root)
    lid.set_joint("prismatic", translation(0, 0, t1 + g), axis=(1.0, 0.0, 0.0), limits=(0.0, Lk + 0.008))
    lid.add(slab(p.scope("lid"), "lid", L, W, t2, min(r, t2 / 2 - 0.0005), actionable="slider_lid"))
    nav = p.uniform("nav_pitch", 0.009, 0.012)
    ls = L - 2 * r - nav - 0.012
    lid.add(display(p, ls, 0.9 * (W - 2 * r)), translation(L / 2 - r - 0.004 - ls / 2, 0, t2))
    _pad(p.scope("nav"), b, lid, side_key, -L / 2 + r + 0.003 + nav / 2, t2, 1, 3, ((W - 2 * r - 0.004) / 3, nav),
         travel, 0.75)
    d.update(L=L, side_z=t1 / 2, side_h=min(0.005, t1 - 2 * r - 0.001))


def side_keys(ctx):
    root, d = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    L, W, z, h = d["L"], d["W"], d["side_z"], d["side_h"]
    xs = d.get("x_shift", 0.0)
    travel = p.uniform("travel", 0.0004, 0.0007)
    lk = p.uniform("key_length", 0.008, 0.014)
    n_vol = p.integers("volume_keys", 1, 2)  # a rocker or an up / down pair
    vol_len = lk * (1.8 if n_vol == 1 else 1.0)
    left = p.flag("volume_left", 0.5)  # volume on the +y side, power on the -y side; else both on -y
    x0 = L / 2 * p.uniform("volume_at", 0.2, 0.5)
    keys = [(+1 if left else -1, x0 - i * (lk + 0.003), vol_len) for i in range(n_vol)]
    if ctx.sub == "smartphone" or p.flag("power_key", 0.4):
        keys.append((-1, L / 2 * p.uniform("power_at", 0.3, 0.5) - (0 if left else 0.5 * L), lk))
    for i, (s, x, length) in enumerate(keys):
        key = side_key(p.scope(f"key{i}"), length, h, travel)
        pose = translation(x + xs, s * W / 2, z) @ rot_z(-s * math.pi / 2)
        mount_button(b, root, key, pose, name="side_key")


RULE = Category(
    name="phone",
    subcategories={"smartphone": 2.0, "bar": 1.0, "flip": 1.5, "slider": 1.0},
    materials={"body": "plastic", "lid": "plastic", "hinge": "plastic", "button": "rubber"},
    mass_range=(0.03, 0.3),  # kg: keypad phones 70-120 g, smartphones 140-230 g (modelled as solid plastic)
    slots=(Slot("body", body), Slot("flip", flip, after=("body",)), Slot("slider", slider, after=("body",)),
           Slot("side_keys", side_keys, after=("body", "flip", "slider"))),
)
