"""USB flash drives: capped, swivel-cover and retractable drives.

Parts: a body (plain box, round-backed, or with a key-ring loop) and a plug (USB-A
12 x 4.5 mm shell or USB-C 8.3 x 2.5 mm, each with its tongue) at the front; capped
drives a cap as wide and thick as the body over the plug; swivel drives a U-shaped
metal strap over and under the body, joined by a bridge in front of the plug, with a
rivet on the pivot; retractable drives a hollow sleeve, open at the front, in which a
carriage with the plug slides, pushed by a thumb tab that rises through a slot on top.
Joints: cap prismatic off the plug (its length plus 5-15 mm); swivel cover revolute
about the vertical pivot near the back (0-180 deg); retractable carriage prismatic
out of the front (the plug's length plus 1-3 mm).
Sizes (metres): bodies 0.03-0.055 long, 0.014-0.022 wide, 6-12 mm thick.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.usb import BODIES, CONNECTORS, GAP, carriage, sleeve, swivel_cover, usb_cap

TURN = rot_z(math.pi / 2)  # built along x with the plug at -x; turned to lie along y, plug at -y


def drive(ctx):
    p, b = ctx.p, ctx.builder
    conn = ctx.choose("connector", CONNECTORS)(p.scope("plug"))
    Lc, wc, tc = conn.anchors["size"]
    root = b.create_link("body")
    if ctx.sub == "retractable":
        return _retractable(ctx, root, conn)
    L = p.uniform("length", 0.03, 0.055)
    w, t = p.uniform("width", max(0.014, wc + 0.003), 0.022), p.uniform("thickness", max(0.006, tc + 0.0015), 0.01)
    body = root.add(ctx.choose("body", BODIES)(p.scope("body"), L, w, t), TURN)
    root.add(conn, TURN)
    if ctx.sub == "capped":
        link = b.create_link("cap", root)
        link.set_joint("prismatic", TURN @ translation(-0.0005, 0, 0), axis=(-1.0, 0.0, 0.0),
                       limits=(0.0, Lc + p.uniform("pull", 0.005, 0.015)))
        link.add(usb_cap(p.scope("cap"), (Lc, wc, tc), w, t))
        return
    xp = L - p.uniform("pivot", 0.3, 0.45) * w  # the pivot, near the back
    link = b.create_link("cover", root)
    link.set_joint("revolute", TURN @ translation(xp, 0, 0), axis=(0.0, 0.0, 1.0), limits=(0.0, math.pi))
    # the bridge clears the plug in front, and a key ring behind, as it swings round
    reach = max(xp + Lc + p.uniform("bridge_gap", 0.0012, 0.002), body.anchors["back"][0] - xp + 0.003)
    link.add(swivel_cover(p.scope("cover"), reach, w, t, p.uniform("tail", 0.3, 0.5) * w))


def _retractable(ctx, root, conn):
    p, b = ctx.p, ctx.builder
    Lc, wc, tc = conn.anchors["size"]
    w = p.uniform("width", max(0.016, wc + 0.0048), 0.022)
    t = p.uniform("thickness", max(0.0085, tc + 0.0048), 0.012)
    lcar = p.uniform("carriage_length", 0.024, 0.038)
    travel = Lc + p.uniform("overtravel", 0.001, 0.003)
    xc = Lc + 0.001  # the carriage's front; the plug stays 1 mm inside at rest
    xt, tl = p.uniform("tab_at", 0.35, 0.65) * lcar, p.uniform("tab_length", 0.004, 0.006)
    sw = p.uniform("slot_width", 0.004, 0.006)
    slot = (xc + xt - tl / 2 - travel - GAP, xc + xt + tl / 2 + GAP, sw)
    s = sleeve(p.scope("sleeve"), xc + lcar + GAP + 0.0018, w, t, slot)
    root.add(s, TURN)
    _, cw, ch = s.anchors["cavity"]
    wall = s.anchors["wall"][0]
    link = b.create_link("carriage", root)
    link.set_joint("prismatic", TURN @ translation(xc, 0, 0), axis=(-1.0, 0.0, 0.0), limits=(0.0, travel))
    link.add(carriage(p.scope("carriage"), lcar, cw - 2 * GAP, ch - 2 * GAP, (xt, tl, sw - 2 * GAP, wall + GAP + 0.0012)))
    link.add(conn)


RULE = Category(
    name="usb",
    subcategories={"capped": 2.0, "swivel": 2.0, "retractable": 1.5},
    materials={"body": "plastic", "connector": "steel", "cover": "steel"},
    mass_range=(0.002, 0.05),  # kg: plastic sticks (~5 g) to metal swivel drives (~20 g)
    slots=(Slot("drive", drive),),
)
