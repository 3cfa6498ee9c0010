"""Computer mice lying on a desk, buttons forward (-x): office, gaming and travel
(compact) mice.

Parts: a base shell (a top-view outline with straight sides, a semicircular back and a
rounded nose) with a well for the scroll wheel and a bracket in it; a palm dome over
the back half; two main buttons over the front, split by the wheel slot; a scroll wheel
(plain, ribbed or tyred); on office mice 0-2 and on gaming mice 2-5 side (thumb)
buttons in collars on the left (-y) side.
Joints: main buttons revolute about their bottom rear edge (the front drops 0.8-1.5
mm) or prismatic down; scroll wheel continuous about y; side buttons prismatic into
the side (1-2 mm).
Sizes (metres, L x W x H): office 0.1-0.125 x 0.058-0.07 x 0.034-0.042 (Logitech M185
99 x 60 x 39), gaming 0.115-0.132 x 0.062-0.075 x 0.038-0.045 (G502 132 x 75 x 40,
DeathAdder 127 x 62 x 43), travel 0.082-0.1 x 0.05-0.06 x 0.026-0.034 (Pebble 107 x
59 x 27, M187 82 x 57 x 34). Scroll wheels 16-22 mm across, 6-9 mm wide.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.controls import BUTTONS, button_bezel, mount_button, rect_button, round_button
from artipg.templates.mice import WHEELS, base_shell, bracket, main_button, palm_dome, profile_top

CL = 0.001  # running clearance of the wheel in its slot and well
# sub-category -> length, width, height, side buttons (lo, hi)
SUBS = {
    "office": ((0.1, 0.125), (0.058, 0.07), (0.034, 0.042), (0, 2)),
    "gaming": ((0.115, 0.132), (0.062, 0.075), (0.038, 0.045), (2, 5)),
    "travel": ((0.082, 0.1), (0.05, 0.06), (0.026, 0.034), (0, 0)),
}
MAIN = {"hinged": 3.0, "sliding": 1.0}
SIDE = rot_z(math.pi / 2)  # control frames (protruding -x) turned to protrude -y


def body(ctx):
    p, b = ctx.p, ctx.builder
    lr, wr, hr, _ = SUBS[ctx.sub]
    L, W, H = p.uniform("length", *lr), p.uniform("width", *wr), p.uniform("height", *hr)
    hb = p.uniform("base_ratio", 0.36, 0.46) * H
    nose = p.uniform("nose", 0.1, 0.35) * W / 2
    xc = L / 2 - W / 2  # the palm dome's centre: the back semicircle's
    # main buttons from behind the nose to the dome
    travel = p.uniform("travel", 0.0008, 0.0015)
    zb = hb + travel + 0.0006
    xb0 = -L / 2 + nose + 0.0005
    Lb = xc - 0.0008 - xb0
    rise = H - hb
    R = (W * W / 4 + rise * rise) / (2 * rise)
    zc = hb - (R - rise)  # the dome sphere's centre height

    def dome(y):  # the dome's top over the buttons' bottom at |y|
        return zc + math.sqrt(R * R - y * y) - zb
    front = p.uniform("front_ratio", 0.55, 0.8)
    sag = p.uniform("sag", 0.0015, 0.003)
    # scroll wheel in the slot between the buttons
    ww = p.uniform("wheel_width", 0.006, 0.009)
    Rw = p.uniform("wheel_radius", 0.008, 0.011)
    t = p.uniform("wheel_at", 0.25, 0.4)
    xw = max(xb0 + t * Lb, xb0 + Rw + CL + 0.002)
    ys = ww / 2 + CL
    y_out = min(W / 2 - 0.0005, math.sqrt(R * R - (zb + 0.004 - zc) ** 2))
    edges = [ys + (y_out - ys) * i / 3 for i in range(4)]
    strips = [(edges[i], edges[i + 1], front * dome(edges[i + 1]), dome(edges[i + 1])) for i in range(3)]
    top = zb + profile_top(Lb, *strips[0][2:], sag, xw - (xc - 0.0008)) + p.uniform("wheel_proud", 0.001, 0.003)
    Rw = min(Rw, (top - 0.004) / 2)
    zw = top - Rw
    well = (xw - Rw - CL, xw + Rw + CL, ys)
    root = b.create_link("body")
    root.add(base_shell(p, L, W, hb, nose, well))
    root.add(palm_dome(p, xc, W / 2, hb - 0.0005, rise + 0.0005))
    root.add(bracket(p, well[0], well[1], ys, zw - Rw - CL))
    return root, (L, W, H, hb, nose, xc, zb, xb0, Lb, (strips, sag), travel, xw, zw, Rw, ww, ys)


def buttons(ctx):
    root, (L, W, H, hb, nose, xc, zb, xb0, Lb, (strips, sag), travel, *_, ys) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    kind = ctx.choose("main", MAIN)
    for name, s in (("left", 1.0), ("right", -1.0)):
        part = main_button(p.scope(name), Lb, [(s * y0, s * y1, f, r) for y0, y1, f, r in strips], sag)
        link = b.create_link("button", root)
        if kind == "hinged":  # about the bottom rear edge: the front drops by ``travel``
            link.set_joint("revolute", translation(xc - 0.0008, 0, zb), axis=(0.0, -1.0, 0.0),
                           limits=(0.0, travel / Lb))
        else:
            link.set_joint("prismatic", translation(xc - 0.0008, 0, zb), axis=(0.0, 0.0, -1.0), limits=(0.0, travel))
        link.add(part)


def wheel(ctx):
    root, (*_, xw, zw, Rw, ww, ys) = ctx.out["body"]
    tmpl = ctx.choose("wheel", WHEELS)
    link = ctx.builder.create_link("scroll_wheel", root)
    link.set_joint("continuous", translation(xw, 0, zw), axis=(0.0, 1.0, 0.0))
    link.add(tmpl(ctx.p, Rw, ww))


def side_buttons(ctx):
    root, (L, W, H, hb, nose, xc, *_) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    lo, hi = SUBS[ctx.sub][3]
    k = p.integers("count", lo, hi)
    hs = min(p.uniform("height", 0.005, 0.008), hb - 2 * 0.0036 - 0.002)
    if k == 0 or hs < 0.003:
        return
    tmpl = ctx.choose("kind", BUTTONS)
    ls = p.uniform("length", 0.01, 0.016)
    x0, x1 = -L / 2 + nose + 0.004, xc - 0.004  # the straight part of the side
    pitch = ls + 2 * 0.0036 + 0.0015
    k = min(k, int((x1 - x0) // pitch))
    if tmpl is round_button:
        ls = hs = min(ls, hs)
    xm = (x0 + x1) / 2 + p.uniform("offset", -0.3, 0.3) * ((x1 - x0) - k * pitch) / 2
    travel = p.uniform("travel", 0.001, 0.002)
    reach = travel + 0.002 + p.uniform("cap_height", 0.0015, 0.0025)
    for i in range(k):
        q = p.scope(f"b{i}")
        cap = round_button(q, radius=hs / 2, reach=reach, travel=travel) if tmpl is round_button else \
            rect_button(q, width=ls, height=hs, reach=reach, travel=travel)
        pose = translation(xm + (i - (k - 1) / 2) * pitch, -W / 2, hb / 2) @ SIDE
        root.add(button_bezel(q.scope("collar"), cap, gap=0.0006), pose)
        mount_button(b, root, cap, pose, name="side_button")


RULE = Category(
    name="mouse",
    subcategories={"office": 2.0, "gaming": 1.5, "travel": 1.0},
    materials={"body": "shell", "button": "plastic", "wheel": "rubber"},
    mass_range=(0.03, 0.2),  # kg: travel mice ~55 g (no battery) to gaming mice ~120 g
    slots=(Slot("body", body), Slot("buttons", buttons, after=("body",)), Slot("wheel", wheel, after=("body",)),
           Slot("side_buttons", side_buttons, after=("body",))),
)
