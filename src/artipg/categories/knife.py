"""Knives: single-blade folders, pocket knives, penknives, utility knives and multi-tools.

Parts: a handle of two scales (round at the pivot end) with a back spacer between
them; one to three steel blades (drop point, sheepsfoot or spey; a pocket knife's
second and third blades shorter) in layers between the scales; a pivot pin with a
head through the scales and the blades' round tangs.
Joints: each blade revolute about the pin (z), 0 = folded into the handle, pi = open
straight out.
Sizes (metres): folders 0.09-0.13 handles, blades 0.8-0.95 of it; pocket knives
0.08-0.1 with 2-3 blades; penknives 0.055-0.075 with 1-2 blades; handles 0.018-0.03
wide, 9-20 mm thick.
Utility knives: a channel handle (0.13-0.18 long, 25-36 mm tall, 13-22 mm wide)
whose blade carrier slides out of the nose (prismatic along x, 0 = blade in, 20-35
mm of travel: 15-30 mm of a 52-61 x 17-19 mm trapezoid blade comes out) pushed by a
thumb slider riding over the slotted top.
Multi-tools: a handle with a pivot at each end (0.07-0.095 between them): 2-3
tools on the front pivot (a drop-point blade first, then blades, saws, screwdrivers,
cap lifters) and 1-3 on the back pivot, each in its own layer, each revolute 0..pi
(the back ones about -z, opening backwards); tools 0.55-0.8 of the pivot spacing.
Frame: the handle along -x from the (front) pivot, blades open to +x; utility knives
along +x from the handle's back end.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.geometry.transforms import rot_y
from artipg.templates.folding_blades import BLADES, PIN_CLEAR, TOOLS, blade, pin, scales, tool
from artipg.templates.utility_knife import carrier, channel_handle, trapezoid_blade

# sub-category -> handle length, handle width, blade counts (min, max), blade thickness
SUBS = {
    "folder": ((0.09, 0.13), (0.022, 0.03), (1, 1), (0.0025, 0.0035)),
    "pocket": ((0.08, 0.1), (0.02, 0.026), (2, 3), (0.0015, 0.0022)),
    "penknife": ((0.055, 0.075), (0.016, 0.02), (1, 2), (0.0012, 0.0018)),
    "multitool": ((0.07, 0.095), (0.022, 0.028), (2, 3), (0.0012, 0.0018)),
}
FRONT_TOOLS = {**BLADES, **TOOLS}
GAP = 0.0005  # between blades and scales
HALF_Y = rot_y(math.pi)


def knife(ctx):
    if ctx.sub == "utility":
        return utility(ctx)
    p = ctx.p
    lr, wr, nr, tr = SUBS[ctx.sub]
    L, w, t = p.uniform("handle_length", *lr), p.uniform("handle_width", *wr), p.uniform("blade_thickness", *tr)
    n = p.integers("blades", *nr)  # both ends inclusive
    nb = p.integers("back_tools", 1, 3) if ctx.sub == "multitool" else 0
    ts = p.uniform("scale_thickness", 0.002, 0.004)
    inner = (n + nb) * t + (n + nb + 1) * GAP
    back = p.uniform("spacer", 0.15, 0.25) * w
    rp = p.uniform("pin_radius", 0.0015, 0.0022)
    r = w / 2
    spine = r - back - 0.0015
    root = ctx.builder.create_link("handle")
    root.add(scales(L, w, ts, inner, back, round_back=nb > 0))
    top = 2 * ts + inner
    head = rp + p.uniform("head", 0.001, 0.002), p.uniform("head_height", 0.0005, 0.001)
    root.add(pin(rp, top, *head))
    multi = ctx.sub == "multitool"
    if multi:  # the second pivot, at the back end
        root.add(pin(rp, top, *head), translation(-L, 0.0, 0.0))
    for k in range(n):
        q = p.scope(f"blade{k}")
        kind = ctx.choose(f"blade{k}", BLADES if k == 0 or not multi else FRONT_TOOLS)
        if multi:  # tools stop short of the other pivot's pin
            bl = q.uniform("length", 0.55, 0.8) * L
        else:
            bl = q.uniform("length", 0.8, 0.95) * L if k == 0 else q.uniform("length", 0.45, 0.7) * L
        wb = min(q.uniform("width", 0.6, 0.85) * w, spine + r - 0.001)
        link = ctx.builder.create_link(f"blade{k}", root)
        link.set_joint("revolute", translation(), axis=(0.0, 0.0, 1.0), limits=(0.0, math.pi))
        z0 = ts + GAP + k * (t + GAP)
        make = blade if kind in BLADES else tool
        link.add(make(kind, bl, wb, spine, t, z0, rp + PIN_CLEAR, min(r, 0.45 * w)))
    for k in range(nb):  # back tools: closed along +x from the back pivot, opening backwards about -z
        q = p.scope(f"back{k}")
        kind = ctx.choose(f"back{k}", TOOLS)
        bl = q.uniform("length", 0.55, 0.8) * L
        wb = min(q.uniform("width", 0.5, 0.75) * w, spine + r - 0.001)
        link = ctx.builder.create_link(f"tool{k}", root)
        link.set_joint("revolute", translation(-L, 0.0, 0.0), axis=(0.0, 0.0, -1.0), limits=(0.0, math.pi))
        zc = ts + GAP + (n + k) * (t + GAP) + t / 2
        # built closed along -x at mid-layer, then turned half a turn about y: along +x, spine still on +y
        link.add(tool(kind, bl, wb, spine, t, -t / 2, rp + PIN_CLEAR, min(r, 0.45 * w)),
                 translation(0.0, 0.0, zc) @ HALF_Y)


def utility(ctx):
    p = ctx.p
    L, wi, ts = p.uniform("handle_length", 0.13, 0.18), p.uniform("channel_width", 0.007, 0.01), p.uniform(
        "side_thickness", 0.003, 0.006)
    hb, lb = p.uniform("blade_height", 0.017, 0.019), p.uniform("blade_length", 0.052, 0.061)
    zb = p.uniform("floor", 0.004, 0.007)
    zt = zb + hb + 0.004
    H = zt + p.uniform("cover", 0.003, 0.005)
    nose, drop = p.uniform("nose", 0.015, 0.03), p.uniform("grip_drop", 0.003, 0.007)
    tip_in = p.uniform("tip_in", 0.003, 0.008)  # the blade's tip inside the nose at rest
    cf = L - tip_in - lb + 0.02  # carrier front: the blade's back 20 mm sits in the carrier
    travel = tip_in + p.uniform("exposed", 0.015, min(0.03, lb - 0.026))
    nl = p.uniform("neck_length", 0.006, 0.01)
    xn = min(cf - nl - 0.005, L - nose - 0.0095 - travel - nl)
    slot = (xn - 0.0015, xn + nl + travel + 0.0015)
    root = ctx.builder.create_link("handle")
    root.add(channel_handle(L, H, wi, ts, zb, zt, slot, nose, drop))
    link = ctx.builder.create_link("slider", root)
    link.set_joint("prismatic", translation(), axis=(1.0, 0.0, 0.0), limits=(0.0, travel))
    button = (p.uniform("thumb_length", 0.015, 0.022), wi + 2 * ts - 0.002, p.uniform("thumb_height", 0.004, 0.006), H)
    link.add(carrier(0.006, cf, wi, zb, zt, 0.0012, (xn, nl), button))
    link.add(trapezoid_blade(cf - 0.02, lb, zb + 0.002, zt - 0.002, p.uniform("blade_thickness", 0.0006, 0.0008)))


RULE = Category(
    name="knife",
    subcategories={"folder": 2.0, "pocket": 2.0, "penknife": 1.0, "utility": 1.5, "multitool": 1.5},
    mass_range=(0.01, 0.3),  # kg: penknives to large folders
    materials={"blade": "steel", "handle": "plastic", "hinge": "steel", "button": "plastic"},
    slots=(Slot("knife", knife),),
)
