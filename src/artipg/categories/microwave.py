"""Microwave ovens: countertop (knob, button or combo panels) and over-the-range.

Parts: a housing (open-front cavity on the left, control bay on the right) on optional
feet; a windowed door over the cavity, hinged on its left (+y) edge and swinging out
90-110 degrees, with an optional vertical handle near its free edge; a control panel
in front of the bay carrying a display and a keypad well of push buttons (prismatic,
pressed 3-6 mm along +x), one to three knobs (revolute timer dials or continuous
encoders), or both; a door-release button when the door has no handle; an optional
glass turntable (continuous about z) in the cavity. Over-the-range models add a vent
grille across the top and two rocker switches (revolute).
Sizes (metres): countertop 0.44-0.6 wide, 0.32-0.45 deep, 0.26-0.35 tall;
over-the-range 0.74-0.77 x 0.38-0.43 x 0.39-0.44.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.appliance import (appliance_housing, control_panel, display, stack_layout, turntable, vent_grille,
                                        window_door)
from artipg.templates.controls import (BUTTONS, KNOBS, button_bezel, dial_knob, mount_button, mount_keypad, mount_knob,
                                       mount_rocker, rect_button, rocker_switch)
from artipg.templates.handles import arch_handle, edge_pull, flat_bar_handle
from artipg.templates.mounting import free_edge_yz, handle_pose, mount_hinged
from artipg.templates.panels import glass_door
from artipg.templates.supports import bun_feet

# sub-category -> width, depth, height ranges, bay width fraction, (knobs lo, hi), keypad rows (lo, hi)
SIZES = {
    "knob_panel": ((0.44, 0.55), (0.32, 0.42), (0.26, 0.33), (0.2, 0.27), (1, 3), (0, 0)),
    "button_panel": ((0.45, 0.6), (0.33, 0.45), (0.27, 0.35), (0.2, 0.26), (0, 0), (3, 5)),
    "combo": ((0.45, 0.6), (0.33, 0.45), (0.27, 0.35), (0.2, 0.26), (1, 1), (2, 4)),
    "over_the_range": ((0.74, 0.77), (0.38, 0.43), (0.39, 0.44), (0.17, 0.21), (0, 0), (4, 5)),
}
HANDLES = {flat_bar_handle: 2.0, arch_handle: 1.5, edge_pull: 1.0}  # bar_handle: posts float (see report)
DOORS = {window_door: 3.0, glass_door: 1.0}
DIALS = {dial_knob: 1.0}


def body(ctx):
    p = ctx.p
    w, d, h, bay, *_ = SIZES[ctx.sub]
    W, D, H = p.uniform("width", *w), p.uniform("depth", *d), p.uniform("height", *h)
    root = ctx.builder.create_link("base")
    fh = p.uniform("foot_height", 0.008, 0.02) if ctx.sub != "over_the_range" and p.flag("feet", 0.7) else 0.0
    if fh:
        root.add(bun_feet(p.scope("feet"), 0.9 * D, 0.9 * W, fh))
    part = appliance_housing(p, D, W, H - fh, p.uniform("bay_width", *bay) * W)
    pose = translation(0, 0, fh + (H - fh) / 2)
    root.add(part, pose)
    t = p.uniform("front_thickness", 0.025, 0.04)
    z_top = H - (p.uniform("vent_height", 0.035, 0.06) if ctx.sub == "over_the_range" else 0.0)
    if z_top < H:
        root.add(vent_grille(p.scope("vent"), W, H - z_top, t), translation(-D / 2, 0, (H + z_top) / 2))
    return root, part, pose, (W, D, H, fh, z_top, t)


def door(ctx):
    root, part, pose, (W, D, H, fh, z_top, t) = ctx.out["body"]
    p = ctx.p
    gap = p.uniform("gap", 0.002, 0.004)
    y0, y1 = part.anchors["bay_hi"][1] + gap, W / 2  # door spans the cavity side of the front
    size = (y1 - y0, z_top - fh - 2 * gap)
    centre = ((y0 + y1) / 2, (z_top + fh) / 2)
    tmpl = ctx.choose("door", DOORS)
    dr = tmpl(p.scope("door"), *size, thickness=t)
    link = mount_hinged(ctx.builder, root, dr, front_x=-D / 2, center_yz=centre, size_yz=size, side="+y",
                        limits=(0.0, p.uniform("open_angle", 1.57, 1.92)))
    has_handle = ctx.sub == "over_the_range" or p.flag("has_handle", 0.5)
    if has_handle:
        h = ctx.choose("handle", HANDLES)(p.scope("handle"), length=p.uniform("handle_length", 0.5, 0.8) * size[1])
        hy, hz = free_edge_yz("+y", size, p.uniform("handle_margin", 0.025, 0.04))
        link.add(h, handle_pose(dr.pose, t, hy, 0.0, False))
    return has_handle


def panel(ctx):
    root, part, pose, (W, D, H, fh, z_top, t) = ctx.out["body"]
    p, b, sub = ctx.p, ctx.builder, ctx.sub
    *_, (k_lo, k_hi), (r_lo, r_hi) = SIZES[sub]
    y0, y1 = -W / 2, part.anchors["bay_hi"][1] - p.uniform("gap", 0.002, 0.004)
    pw, ph, pc = y1 - y0, z_top - fh, ((y0 + y1) / 2, (z_top + fh) / 2)
    m = p.uniform("margin", 0.012, 0.02)
    rows, n_knobs, release = p.integers("rows", r_lo, r_hi), p.integers("knobs", k_lo, k_hi), not ctx.out["door"]
    R = min(p.uniform("knob_radius", 0.014, 0.03), pw / 2 - m)
    pitch = p.uniform("key_pitch", 0.016, 0.026)
    blocks = [("display", p.uniform("display_height", 0.018, 0.03))] if rows else []
    blocks += [("knob", 2 * R)] * (n_knobs if sub == "knob_panel" else 0)
    blocks += [("well", (rows + release) * pitch)] if rows else [("release", pitch)] * release
    blocks += [("knob", 2 * R)] * (n_knobs if sub == "combo" else 0)
    blocks += [("rockers", 0.025)] if sub == "over_the_range" else []
    front, well, items = translation(-D / 2, *pc), None, []
    for (kind, _), (z, h) in zip(blocks, stack_layout([h for _, h in blocks], ph, m)[0]):
        if kind == "well":
            well = (-pw / 2 + m, pw / 2 - m, z - h, z)
        else:
            items.append((kind, z - h / 2, h))
    root.add(control_panel(p, pw, ph, t, keypad=well), front)
    knob_t = ctx.choose("knob", KNOBS if sub == "knob_panel" else DIALS) if n_knobs else None
    spin = p.flag("continuous", 0.4)
    for i, (kind, zc, h) in enumerate(items):
        q = p.scope(f"{kind}{i}")
        T = front @ translation(-t, 0, zc)
        if kind == "display":
            root.add(display(q, 0.75 * pw, h), T)
        elif kind == "knob":
            mount_knob(b, root, knob_t(q, radius=h / 2), T, continuous=spin, limits=(0.0, q.uniform("turn", 4.0, 5.8)))
        elif kind == "release":  # door-release button in a collar on the plate
            cap = rect_button(q, width=0.6 * pw, height=0.7 * h)
            root.add(button_bezel(q, cap), T)
            mount_button(b, root, cap, T)
        else:
            for j in (-1, 1):
                sw = rocker_switch(q.scope(f"rocker{j}"), width=0.3 * pw, height=h)
                mount_rocker(b, root, sw, T @ translation(0, j * 0.22 * pw, 0))
    if well is None:
        return
    cols = p.integers("cols", 2, 4 if pw > 0.14 else 3)
    g = p.uniform("key_gap", 0.001, 0.0018)  # keys touch their neighbours and the well (< 2 mm)
    cw, pitch = (well[1] - well[0]) / cols, (well[3] - well[2]) / (rows + release)
    reach = t + p.uniform("key_proud", 0.001, 0.003)
    key, q = ctx.choose("button", BUTTONS), p.scope("key")  # one key design, copied over the keypad
    if key is rect_button:
        cap, collar = rect_button(q, width=cw - g, height=pitch - g, reach=reach), None
    else:  # round keys leave wide gaps in their cells: each gets a collar
        cap = key(q, radius=(min(cw, pitch) - g) / 2 - 0.003, reach=reach)
        collar = button_bezel(q.scope("collar"), cap, gap=g / 2)
    centre = translation(-D / 2, pc[0] + (well[0] + well[1]) / 2, pc[1] + well[3] - rows * pitch / 2)
    mount_keypad(b, root, cap, centre, rows, cols, (cw, pitch), collar)
    if release:
        rel = rect_button(p.scope("release"), width=well[1] - well[0] - g, height=pitch - g, reach=reach)
        mount_button(b, root, rel, translation(-D / 2, pc[0], pc[1] + well[2] + pitch / 2))


def table(ctx):
    root, part, pose, _ = ctx.out["body"]
    if not ctx.p.flag("turntable", 0.75):
        return
    lo, hi = (pose @ [*part.anchors["cavity_lo"], 1.0]).tolist(), (pose @ [*part.anchors["cavity_hi"], 1.0]).tolist()
    r = min(hi[0] - lo[0], hi[1] - lo[1]) / 2 - ctx.p.uniform("margin", 0.01, 0.03)
    link = ctx.builder.create_link("turntable", root)
    link.set_joint("continuous", translation((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]))
    link.add(turntable(ctx.p, r))


RULE = Category(
    name="microwave",
    subcategories={"knob_panel": 2.0, "button_panel": 3.0, "combo": 2.0, "over_the_range": 1.0},
    materials={"body": "shell", "door": "shell", "leg": "shell", "base": "shell", "top": "shell", "drawer": "shell"},
    mass_range=(5.0, 30.0),  # kg: compact units (~10 kg) to over-the-range models (~25 kg)
    slots=(Slot("body", body), Slot("door", door, after=("body",)), Slot("panel", panel, after=("door",)),
           Slot("turntable", table, after=("body",))),
)
