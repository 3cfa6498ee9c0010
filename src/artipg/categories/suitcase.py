"""Hard-shell suitcases standing upright: carry-on spinners, large (checked) spinners
and two-wheel (upright) cases.

Parts: a hollow back shell and a hollow front shell (the lid) meeting at the zip seam;
a telescopic handle (two posts through holes in the top, a grip bar across them); a
fold-flat carry handle on the top and, on most cases, one on the side opposite the lid
hinge, each turning between two fixed mounts; spinners four swivel casters (a fork on
a vertical swivel, a wheel on its axle), two-wheel cases two wheels in fixed forks at
the back corners and two feet at the front.
Joints: lid revolute about the vertical front edge on the +y side (85-140 degrees);
telescopic handle prismatic up (0.2-0.45 m); carry handles revolute up to 90 degrees;
wheels continuous about their axles, casters continuous about z.
Sizes (metres): carry-on 0.5-0.56 tall (over the wheels), 0.34-0.4 wide, 0.2-0.25
deep; large 0.65-0.8 x 0.44-0.52 x 0.26-0.32; two-wheel 0.55-0.75 x 0.36-0.48 x
0.22-0.3. Shell walls 2.5-3.5 mm.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.luggage import (GAP, MOUNT_LENGTH, back_shell, flip_grip, fork, front_shell, grip_mounts,
                                      telescopic_handle, wheel)
from artipg.templates.mounting import mount_hinged

# sub-category -> height, width, depth, wheel radius
SUBS = {
    "carry_on": ((0.5, 0.56), (0.34, 0.4), (0.2, 0.25), (0.022, 0.03)),
    "large_spinner": ((0.65, 0.8), (0.44, 0.52), (0.26, 0.32), (0.025, 0.035)),
    "two_wheel": ((0.55, 0.75), (0.36, 0.48), (0.22, 0.3), (0.035, 0.05)),
}
# a carry handle on the -y side face: grip along x, its outward normal -y, hinged on its lower edge
SIDE = np.array([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def shell(ctx):
    p, b = ctx.p, ctx.builder
    hr, wr, dr, rr = SUBS[ctx.sub]
    H, W, D, r = p.uniform("height", *hr), p.uniform("width", *wr), p.uniform("depth", *dr), p.uniform("wheel", *rr)
    ww, plate, tb = p.uniform("wheel_width", 0.015, 0.025), p.uniform("fork_plate", 0.003, 0.005), \
        p.uniform("fork_top", 0.008, 0.014)
    zb = 2 * r + GAP + tb + GAP  # the shells' bottom
    wall, post = p.uniform("wall", 0.0025, 0.0035), p.uniform("post", 0.012, 0.02)
    seam = -D / 2 + p.uniform("lid_depth", 0.35, 0.5) * D
    hs = post / 2 + GAP
    xc, yc = D / 2 - wall - hs - p.uniform("post_clearance", 0.004, 0.01), p.uniform("post_span", 0.3, 0.4) * W
    root = b.create_link("body")
    root.add(back_shell(p, seam, D / 2, W, zb, H, wall, (xc, yc, hs)))
    lid = front_shell(p.scope("lid"), seam + D / 2, W, H - zb, wall)
    mount_hinged(b, root, lid, front_x=seam, center_yz=(0.0, (zb + H) / 2), size_yz=(W, H - zb),
                 side="+y", limits=(0.0, p.uniform("lid_open", 1.5, 2.4)), name="lid")
    return root, (H, W, D, r, ww, plate, tb, zb, seam, xc, yc, post)


def handles(ctx):
    root, (H, W, D, r, ww, plate, tb, zb, seam, xc, yc, post) = ctx.out["shell"]
    p, b = ctx.p, ctx.builder
    Lp = min(p.uniform("post_length", 0.3, 0.5), 0.85 * (H - zb))
    tele = telescopic_handle(p.scope("telescopic"), 2 * yc, post, Lp)
    link = b.create_link("telescopic", root)
    link.set_joint("prismatic", translation(xc, 0, H + GAP), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, Lp - p.uniform("post_overlap", 0.06, 0.1)))
    link.add(tele)
    xh = xc - tele.anchors["grip_width"][0] / 2 - 0.01
    grips = [("top", translation(xh, 0, H), min(p.uniform("top_width", 0.025, 0.035), xh - seam - 0.01),
              p.uniform("top_length", 0.12, 0.18))]
    if ctx.sub == "large_spinner" or p.flag("side_handle", 0.7):
        # the handle and its mounts stay on the back shell: the lid's free edge sweeps out
        # past the side face as it opens, so nothing on that face may reach over the seam
        reach = GAP + MOUNT_LENGTH[1] + 0.005  # beyond either end of the grip
        length = min(p.uniform("side_length", 0.12, 0.16), D / 2 - seam - 2 * reach)
        play = (D / 2 - seam) / 2 - reach - length / 2
        x_s = (seam + D / 2) / 2 + p.uniform("side_offset", -0.5, 0.5) * play
        grips.append(("side", translation(x_s, -W / 2, (zb + H) / 2 - 0.015) @ SIDE, 0.03, length))
    for name, pose, w, length in grips:
        q = p.scope(name)
        grip = flip_grip(q, length, width=w)
        t = grip.anchors["thickness"][0]
        T = pose @ translation(0, 0, GAP + t / 2)
        root.add(grip_mounts(q, length, w, t), T)
        link = b.create_link(f"{name}_handle", root)
        link.set_joint("revolute", T, axis=(0.0, 1.0, 0.0), limits=(0.0, q.uniform("lift", 1.3, 1.57)))
        link.add(grip)


def wheels(ctx):
    root, (H, W, D, r, ww, plate, tb, zb, seam, xc, yc, post) = ctx.out["shell"]
    p, b = ctx.p, ctx.builder
    drop = 2 * r + GAP + tb - r  # the fork's top over the axle
    spin = ctx.sub != "two_wheel"
    inset = p.uniform("wheel_inset", 0.005, 0.015)
    xs = (-D / 2 + r + inset, D / 2 - r - inset) if spin else (D / 2 - r - inset,)
    ys = W / 2 - ww / 2 - plate - GAP - inset
    for i, (x, y) in enumerate((x, y) for x in xs for y in (-ys, ys)):
        parent = root
        fk = fork(p.scope(f"fork{i}"), r, ww, drop, plate)
        if spin:
            parent = b.create_link("caster", root)
            parent.set_joint("continuous", translation(x, y, r), axis=(0.0, 0.0, 1.0))
            parent.add(fk)
            origin = np.eye(4)
        else:
            root.add(fk, translation(x, y, r))
            origin = translation(x, y, r)
        link = b.create_link("wheel", parent)
        link.set_joint("continuous", origin, axis=(0.0, 1.0, 0.0))
        link.add(wheel(p, r, ww))
    if not spin:  # two skids under the front, reaching under the back shell
        f = p.uniform("foot", 0.02, 0.035)
        yf = ys - ww / 2 - plate - f / 2 - 0.01  # inboard of the wheels' forks
        prims = [cuboid_between((-D / 2 + inset, s * yf - f / 2, 0.0), (seam + 0.02, s * yf + f / 2, zb - GAP),
                                role="foot") for s in (-1, 1)]
        root.add(Part("leg", "front_feet", prims))


RULE = Category(
    name="suitcase",
    subcategories={"carry_on": 2.0, "large_spinner": 2.0, "two_wheel": 1.5},
    materials={"body": "plastic", "lid": "plastic", "handle": "plastic", "base": "plastic", "leg": "plastic"},
    mass_range=(1.5, 8.0),  # kg: carry-on shells ~2.5 kg to large cases ~5 kg
    slots=(Slot("shell", shell), Slot("handles", handles, after=("shell",)), Slot("wheels", wheels, after=("shell",))),
)
