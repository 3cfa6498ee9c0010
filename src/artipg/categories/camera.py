"""Cameras standing on a table, lens forward (-x): DSLRs with a kit zoom lens, compact
cameras with a telescoping zoom, and instant (film) cameras.

Parts: a body block with a battery pocket in its bottom (DSLR, compact) and, on DSLRs,
a hand grip on the front right (+y, the user's right), a pentaprism hump over the lens
axis and a rear LCD; a lens (fixed barrel sections, a zoom ring and on most lenses a
focus ring, the front glass) or telescoping zoom tubes (compact: 2-3 stages in a fixed
bezel; instant: one pop-up tube or a fixed barrel); a shutter button in a collar
(DSLR: on the grip; compact: on the top; instant: on the front) and 0-3 further top
buttons; a mode dial on the top plate; flash and viewfinder windows; doors.
Joints: zoom ring revolute about the optical axis (70-90 degrees); focus ring
continuous or revolute (up to 270 degrees); zoom tubes prismatic out of the front
(60-80 % of their length per stage); buttons prismatic down / in (1-1.5 mm); mode dial
continuous or revolute (300 degrees); DSLR screen fixed, tilting (hinged on its bottom
edge, 80-90 degrees) or vari-angle (hinged on its left edge, up to 180 degrees);
battery door revolute down about its front edge (90 degrees); instant cameras' film
door revolute about the back's left edge (90-115 degrees).
Sizes (metres, W x H x D of the body without lens): DSLR 0.122-0.148 x 0.075-0.092 x
0.045-0.058 (+ a 0.018-0.028 pentaprism hump and a 0.018-0.03 grip; Canon 250D 122 x 93 x
70 overall, Nikon D7500 136 x 104 x 73), lens 0.06-0.074 across, 0.05-0.095 long; compact
0.094-0.112 x 0.054-0.066 x 0.021-0.032; instant 0.1-0.15 x 0.105-0.125 x 0.06-0.095
(Instax Mini 104-108 x 121 x 66; Polaroid Now 150 x 112 x 94).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.cameras import (CLEAR, GAP, front_glass, grip_block, hinged_plate, lens_barrel, lens_ring,
                                      mode_dial, pocket_body, prism_hump, screen_panel, window, zoom_tube)
from artipg.templates.controls import button_bezel, mount_button, round_button

UP = rot_y(math.pi / 2)      # control frames (protruding -x) turned to protrude +z
DOWN = rot_y(math.pi / 2)    # plate frames (outer face +x) turned to face -z: bottom doors
# sub-category -> width, height, depth, edge radius
SUBS = {
    "dslr": ((0.122, 0.148), (0.075, 0.092), (0.045, 0.058), (0.004, 0.008)),
    "compact": ((0.094, 0.112), (0.054, 0.066), (0.021, 0.032), (0.003, 0.006)),
    "instant": ((0.1, 0.15), (0.105, 0.125), (0.06, 0.095), (0.006, 0.014)),
}
SCREENS = {"fixed": 1.0, "tilt": 1.5, "vari_angle": 1.5}


def _button(p, builder, root, pose, radius: float):
    """A round button of ``radius`` in a collar at mount ``pose`` (protruding along the
    pose's -x), 1-1.5 mm travel."""
    travel = p.uniform("travel", 0.001, 0.0015)
    cap = round_button(p, radius=radius, reach=travel + 0.002 + p.uniform("cap_height", 0.0015, 0.003), travel=travel)
    root.add(button_bezel(p.scope("collar"), cap, gap=0.0006), pose)
    mount_button(builder, root, cap, pose)


def body(ctx):
    p, b = ctx.p, ctx.builder
    wr, hr, dr, rr = SUBS[ctx.sub]
    W, H, D = p.uniform("width", *wr), p.uniform("height", *hr), p.uniform("depth", *dr)
    r = min(p.uniform("edge_radius", *rr), 0.3 * D)
    root = b.create_link("body")
    if ctx.sub == "instant":
        pocket = None
        root.add(pocket_body(p, W, H, D, r, None))
    else:
        t = p.uniform("bottom_layer", 0.003, 0.004)
        m = r + 0.003
        wd = p.uniform("door_width", 0.2, 0.3) * W
        pocket = (-D / 2 + m, D / 2 - m, W / 2 - m - wd, W / 2 - m, t)
        root.add(pocket_body(p, W, H, D, r, pocket))
    return root, (W, H, D, r, pocket)


def battery_door(ctx):
    root, (W, H, D, r, pocket) = ctx.out["body"]
    if pocket is None:
        return
    p, b = ctx.p, ctx.builder
    x0, x1, y0, y1, t = pocket
    door = hinged_plate(p, "door", y1 - y0 - 2 * GAP, x1 - x0 - 2 * GAP, t - 2 * GAP)
    link = b.create_link("battery_door", root)
    # plate frame: outer face down (z = GAP), hinge line along y at the pocket's front end
    link.set_joint("revolute", translation(x0 + GAP, y0 + GAP, GAP) @ DOWN, axis=(0.0, 1.0, 0.0),
                   limits=(0.0, p.uniform("open", 1.4, 1.65)))
    link.add(door)


def _lens_axis(p, sub, W, H, D, r, R, y_free):
    """(y, z) of the optical axis for a lens of outer radius ``R`` centred in the free
    span ``y_free`` of the front face."""
    y0, y1 = y_free
    y = (y0 + y1) / 2 + p.uniform("lens_offset", -0.3, 0.3) * max(0.0, (y1 - y0) / 2 - R - 0.003)
    z = max(p.uniform("lens_height", 0.42, 0.52) * H, R + 0.004)
    return y, min(z, H - r - R - 0.001) if sub != "dslr" else z


def dslr(ctx):
    root, (W, H, D, r, pocket) = ctx.out["body"]
    if ctx.sub != "dslr":
        return
    p, b = ctx.p, ctx.builder
    gd, gw = p.uniform("grip_depth", 0.018, 0.03), p.uniform("grip_width", 0.03, 0.04)
    gh = p.uniform("grip_height", 0.8, 0.92) * H
    gr = p.uniform("grip_radius", 0.003, 0.005)
    root.add(grip_block(p, -D / 2 - gd, -D / 2 + r, W / 2 - gw, W / 2, gh, gr))
    R = min(p.uniform("lens_radius", 0.03, 0.037), (W - gw) / 2 - 0.003)
    yl, zl = _lens_axis(p, "dslr", W, H, D, r, R, (-W / 2, W / 2 - gw))
    wh = min(p.uniform("hump_width", 0.05, 0.07), W - gw - 0.03)
    root.add(prism_hump(p.scope("hump"), wh, p.uniform("hump_height", 0.018, 0.028), 0.85 * D, H - 0.002, yl))
    # shutter on the grip top, towards the front
    rs = min(p.uniform("shutter_radius", 0.004, 0.0055), gd / 2 - 0.0045, gw / 2 - 0.0045)
    xs = -D / 2 - gd / 2
    _button(p.scope("shutter"), b, root, translation(xs, W / 2 - gw / 2, gh) @ UP, rs)
    # further buttons on the top plate right of the hump
    y_lo, y_hi = yl + wh / 2 + 0.002, W / 2 - r - 0.002
    k = p.integers("top_buttons", 1, 3)
    rb = min(0.0035, (y_hi - y_lo) / (2 * k) - 0.0037)
    if rb >= 0.002:
        xb = p.uniform("top_x", -0.1, 0.15) * D
        for i in range(k):
            _button(p.scope(f"top{i}"), b, root, translation(xb, y_lo + (y_hi - y_lo) * (i + 0.5) / k, H) @ UP, rb)
    # mode dial on the left shoulder
    span = (yl - wh / 2) - (-W / 2 + r)
    rd = min(p.uniform("dial_radius", 0.01, 0.015), span / 2 - 0.002, D / 2 - r - 0.002)
    dial = mode_dial(p.scope("dial"), rd, p.uniform("dial_height", 0.006, 0.01))
    link = b.create_link("mode_dial", root)
    pose = translation(p.uniform("dial_x", -0.1, 0.1) * D, -W / 2 + r + span / 2, H + GAP)
    if p.flag("dial_endless", 0.6):
        link.set_joint("continuous", pose, axis=(0.0, 0.0, 1.0))
    else:
        link.set_joint("revolute", pose, axis=(0.0, 0.0, 1.0), limits=(0.0, p.uniform("dial_turn", 4.5, 5.5)))
    link.add(dial)
    _kit_lens(ctx, R, yl, zl, -D / 2, D + gd)
    _rear_screen(ctx, W, H, D, r, pocket[4])


def _kit_lens(ctx, R, yl, zl, xf, depth):
    """Zoom lens on the axis (yl, zl) from the body's front face at x = ``xf``; at most
    1.05 x the body's ``depth`` (with its grip) long, so the camera stands on its base
    (longer lenses tip a real camera onto the lens)."""
    p, b = ctx.p.scope("lens"), ctx.builder
    root = ctx.out["body"][0]
    tr = p.uniform("ring_thickness", 0.0025, 0.004)
    rc = R - tr - CLEAR  # the core the rings turn on
    lf, lz = p.uniform("mount_length", 0.004, 0.007), p.uniform("zoom_length", 0.015, 0.03)
    focus = p.flag("focus_ring", 0.75)
    lo = p.uniform("focus_length", 0.008, 0.015) if focus else 0.0
    lfr = p.uniform("front_length", 0.008, 0.02)
    L = min(p.uniform("length", 0.05, 0.095), 1.05 * depth)
    gap = 0.0008
    lm = max(0.004, L - lf - lz - lo - lfr - 4 * gap)
    x = 0.0
    sections = [(-lf, 0.0, R - 0.001)]
    x = -lf - gap
    rings = [("zoom_ring", x, lz)]
    x -= lz + gap
    sections.append((x - lm, x, R - 0.001))
    x -= lm
    if focus:
        rings.append(("focus_ring", x - gap, lo))
        x -= lo + 2 * gap
    sections.append((x - lfr, x, R))
    x -= lfr
    sections.append((x, -lf, rc))  # the core under the rings
    root.add(lens_barrel(p, sections), translation(xf, yl, zl))
    root.add(front_glass(p, p.uniform("glass_ratio", 0.6, 0.8) * rc), translation(xf + x, yl, zl))
    for name, x0, length in rings:
        link = b.create_link(name, root)
        pose = translation(xf + x0, yl, zl)
        if name == "focus_ring" and p.flag("focus_endless", 0.5):
            link.set_joint("continuous", pose, axis=(-1.0, 0.0, 0.0))
        else:
            hi = p.uniform(f"{name}_turn", 1.2, 1.6) if name == "zoom_ring" else p.uniform("focus_turn", 2.0, 4.7)
            link.set_joint("revolute", pose, axis=(-1.0, 0.0, 0.0), limits=(0.0, hi))
        link.add(lens_ring(p.scope(name), rc + CLEAR, R, length))


def _rear_screen(ctx, W, H, D, r, t_bottom):
    p, b = ctx.p.scope("screen"), ctx.builder
    root = ctx.out["body"][0]
    ws, hs = p.uniform("width", 0.5, 0.62) * W, p.uniform("height", 0.55, 0.7) * H
    hs = min(hs, H - 2 * r - t_bottom - 0.008)
    t = p.uniform("thickness", 0.005, 0.009)
    y0, z0 = -W / 2 + r + p.uniform("left_margin", 0.003, 0.012), t_bottom + r + 0.003
    kind = ctx.choose("screen", SCREENS)
    panel = screen_panel(p, ws, hs, t)
    if kind == "fixed":
        root.add(panel, translation(D / 2 + t, y0, z0))
        return
    link = b.create_link("screen", root)
    pose = translation(D / 2 + GAP + t, y0, z0)
    if kind == "tilt":  # hinged on its bottom edge, the top swings back
        link.set_joint("revolute", pose, axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("tilt", 1.4, 1.57)))
    else:  # hinged on its left (-y) edge, the free edge swings back and round
        link.set_joint("revolute", pose, axis=(0.0, 0.0, -1.0), limits=(0.0, p.uniform("swing", 2.6, 3.1)))
    link.add(panel)


def compact(ctx):
    root, (W, H, D, r, pocket) = ctx.out["body"]
    if ctx.sub != "compact":
        return
    p, b = ctx.p, ctx.builder
    R0 = min(p.uniform("bezel_radius", 0.017, 0.025), H / 2 - r - 0.002)
    yl, zl = _lens_axis(p, "compact", W, H, D, r, R0, (-W / 2 + r, W / 2 - r - 0.012))
    wall, wt = p.uniform("bezel_wall", 0.0015, 0.0025), p.uniform("tube_wall", 0.0012, 0.0016)
    l0 = p.uniform("tube_length", 0.008, 0.014)
    xf = -D / 2
    root.add(zoom_tube(p, R0, R0 - wall, l0, False, moving=False), translation(xf, yl, zl))
    n = p.integers("stages", 2, 3)
    parent, ro, pose = root, R0 - wall - CLEAR, translation(xf - GAP, yl, zl)
    for i in range(n):
        closed = i == n - 1
        link = b.create_link("zoom_tube", parent)
        link.set_joint("prismatic", pose, axis=(-1.0, 0.0, 0.0),
                       limits=(0.0, p.uniform(f"extend{i}", 0.6, 0.8) * l0))
        link.add(zoom_tube(p.scope(f"tube{i}"), ro, ro - wt, l0 - GAP, closed))
        if closed:
            link.add(front_glass(p, p.uniform("glass_ratio", 0.55, 0.75) * ro), translation(-l0 + GAP, 0, 0))
        parent, ro, pose = link, ro - wt - CLEAR, translation(0, 0, 0)
    # flash window on the front, above the lens on the far side from the shutter
    fw, fh = p.uniform("flash_width", 0.012, 0.02), p.uniform("flash_height", 0.006, 0.01)
    yf = min(W / 2 - r - fw / 2 - 0.002, max(yl + R0 + fw / 2 + 0.003, p.uniform("flash_y", 0.15, 0.35) * W))
    root.add(window(p, "glass", fw, fh, 0.0008), translation(xf, yf, H - r - fh / 2 - 0.002))
    # shutter and power on the top, right end
    rs = min(p.uniform("shutter_radius", 0.0035, 0.005), D / 2 - r - 0.004)
    ys = W / 2 - r - 0.006 - rs
    _button(p.scope("shutter"), b, root, translation(0, ys, H) @ UP, rs)
    if p.flag("power_button", 0.8):
        rp = min(0.003, rs)
        _button(p.scope("power"), b, root, translation(0, ys - rs - rp - 0.009, H) @ UP, rp)
    root.add(window(p.scope("lcd"), "screen", 0.75 * W, 0.7 * H, 0.0008),
             translation(D / 2, -W / 2 + r + 0.38 * W + 0.003, H / 2) @ rot_z(math.pi))


def instant(ctx):
    root, (W, H, D, r, _) = ctx.out["body"]
    if ctx.sub != "instant":
        return
    p, b = ctx.p, ctx.builder
    R0 = min(p.uniform("bezel_radius", 0.026, 0.036), H / 2 - r - 0.003, W / 2 - r - 0.003)
    yl, zl = _lens_axis(p, "instant", W, H, D, r, R0, (-W / 2 + r, W / 2 - r - 0.03))
    xf = -D / 2
    wall = p.uniform("bezel_wall", 0.002, 0.004)
    l0 = p.uniform("tube_length", 0.012, 0.02)
    root.add(zoom_tube(p, R0, R0 - wall, l0, False, moving=False), translation(xf, yl, zl))
    ro = R0 - wall - CLEAR
    if p.flag("pop_up", 0.7):
        link = b.create_link("lens_tube", root)
        link.set_joint("prismatic", translation(xf - GAP, yl, zl), axis=(-1.0, 0.0, 0.0),
                       limits=(0.0, p.uniform("extend", 0.55, 0.8) * l0))
    else:
        link = root
    tube = zoom_tube(p.scope("tube"), ro, 0.0, l0 - GAP, True, moving=link is not root)
    glass = front_glass(p, p.uniform("glass_ratio", 0.35, 0.55) * ro)
    if link is root:
        link.add(tube, translation(xf - GAP, yl, zl))
        link.add(glass, translation(xf - l0, yl, zl))
    else:
        link.add(tube)
        link.add(glass, translation(-l0 + GAP, 0, 0))
    # shutter on the front right (+y), flash and viewfinder on the front top
    rs = p.uniform("shutter_radius", 0.005, 0.008)
    ys = min(W / 2 - r - rs - 0.006, yl + R0 + rs + 0.008)
    zs = min(zl + p.uniform("shutter_z", -0.2, 0.2) * R0, H - r - rs - 0.006)
    _button(p.scope("shutter"), b, root, translation(xf, ys, zs), rs)
    fw, fh = p.uniform("flash_width", 0.02, 0.035), p.uniform("flash_height", 0.012, 0.02)
    root.add(window(p, "glass", fw, fh, 0.001), translation(xf, -W / 2 + r + fw / 2 + 0.004, H - r - fh / 2 - 0.003))
    vf = p.uniform("finder_size", 0.008, 0.012)
    root.add(window(p.scope("finder"), "lens", vf, vf, 0.002), translation(xf, W / 2 - r - vf / 2 - 0.004,
                                                                          H - r - vf / 2 - 0.004))
    # film door on the back, hinged on its -y edge
    t = p.uniform("door_thickness", 0.003, 0.005)
    wd, hd = W - 2 * r - 0.006, p.uniform("door_height", 0.75, 0.9) * (H - 2 * r)
    door = hinged_plate(p, "door", wd, hd, t)
    link = b.create_link("film_door", root)
    link.set_joint("revolute", translation(D / 2 + GAP + t, -wd / 2, r + p.uniform("door_z", 0.01, 0.05) * H),
                   axis=(0.0, 0.0, -1.0), limits=(0.0, p.uniform("door_open", 1.6, 2.0)))
    link.add(door)


RULE = Category(
    name="camera",
    subcategories={"instant": 1.0, "compact": 1.5, "dslr": 2.0},
    materials={"body": "shell", "lens": "shell", "door": "plastic", "screen": "plastic", "dial": "plastic"},
    mass_range=(0.08, 1.6),  # kg: compacts ~0.15-0.3, instant cameras ~0.3-0.5, DSLRs with kit lens 0.6-1.2
    slots=(Slot("body", body), Slot("battery_door", battery_door, after=("body",)),
           Slot("dslr", dslr, after=("body",)), Slot("compact", compact, after=("body",)),
           Slot("instant", instant, after=("body",))),
)
