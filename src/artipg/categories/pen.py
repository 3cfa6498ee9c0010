"""Pens: click (retractable) ballpoints, capped pens and twist pens.

Parts: a barrel (straight with a short cone, with a slimmer grip waist, or with a long
slender nose) ending in a nose ring at the writing end; a pocket clip (flat strip or
round wire, with a ball at its free end) near the back end or on the cap; click pens
a plunger in a socket at the back end, capped pens a cap over the front and an end
plug as wide as the cap at the back, twist pens a separate back section. Click and
twist pens carry the refill point in the nose.
Joints: plunger prismatic into the barrel (3-6 mm); cap prismatic off the front (its
length plus 5-20 mm); twist section revolute about the pen's axis (70-145 deg);
refill point prismatic out of the nose (1-1.5 mm). A real click or twist mechanism
couples the point to the plunger or the twist; URDF joints are independent, so the
point has its own joint (same travel, documented coupling).
The pen lies on its side along y, rolled about its axis so that the clip's ball and
the barrel (or the cap and end plug) both touch the floor, as a real pen lies.
Sizes (metres): 0.125-0.15 long, 7.5-11.5 mm across; caps 30-50 mm long.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_x, translation
from artipg.rules import Category, Slot
from artipg.templates.pens import (BARRELS, CLEAR, CLIPS, end_plug, pen_cap, plunger, refill_point, roll_angle,
                                   rolled, twist_section)

FLIP = rot_x(math.pi)  # a clip built back-to-front (on a cap, rooted at its closed end)
LAY = rot_x(-math.pi / 2)  # the pen's axis (z) along +y
# sub-category -> barrel radius, length
SUBS = {"click_pen": ((0.004, 0.0058), (0.13, 0.15)), "capped_pen": ((0.0038, 0.005), (0.125, 0.15)),
        "twist_pen": ((0.0042, 0.0055), (0.125, 0.145))}


def body(ctx):
    """Every part is made first, then placed: how far the clip is turned about the
    pen's axis (so that it and the barrel or cap both touch the floor) depends on the
    clip, which sits on the barrel, the twist section or the cap."""
    p, b = ctx.p, ctx.builder
    rr, lr = SUBS[ctx.sub]
    R, L = p.uniform("radius", *rr), p.uniform("length", *lr)
    lc = p.uniform("clip_length", 0.032, 0.05)
    root = b.create_link("body")
    if ctx.sub == "click_pen":
        rp, travel = p.uniform("plunger_radius", 0.4, 0.55) * R, p.uniform("travel", 0.003, 0.006)
        inside, out = p.uniform("plunger_inside", 0.003, 0.006), p.uniform("plunger_out", 0.004, 0.009)
        barrel = ctx.choose("barrel", BARRELS)(p.scope("barrel"), R, L, (rp + CLEAR, inside + travel + 0.0015))
        moving = ("button", "prismatic", translation(0, 0, L), (0.0, 0.0, -1.0), travel,
                  plunger(p.scope("plunger"), rp, inside, out))
        clip_on, frame, r, z0, z1 = None, translation(0, 0, 0), R, L - lc, L
    elif ctx.sub == "twist_pen":
        zs = p.uniform("split", 0.45, 0.6) * L
        barrel = ctx.choose("barrel", BARRELS)(p.scope("barrel"), R, zs)
        Lb = L - zs - 0.0005
        moving = ("knob", "revolute", translation(0, 0, zs + 0.0005), (0.0, 0.0, 1.0), p.uniform("twist", 1.2, 2.5),
                  twist_section(p.scope("twist"), R, Lb))
        clip_on, frame, r, z0, z1 = "moving", translation(0, 0, 0), R, Lb - lc - 0.004, Lb - 0.004
    else:
        barrel = ctx.choose("barrel", BARRELS)(p.scope("barrel"), R, L)
        lcap = p.uniform("cap_length", 0.03, 0.05)
        cap = pen_cap(p.scope("cap"), R, lcap)
        r = cap.anchors["outer"][0]
        root.add(end_plug(p.scope("plug"), R, r), translation(0, 0, L))  # re-placed below
        moving = ("cap", "prismatic", translation(0, 0, lcap - 0.0012), (0.0, 0.0, -1.0),
                  lcap + p.uniform("pull", 0.005, 0.02), cap)
        z1 = -cap.anchors["outer"][2]  # the cap's closed end, in the flipped clip frame
        clip_on, frame, z0 = "moving", FLIP, z1 - min(lc, lcap - 0.004)
    c = ctx.choose("clip", CLIPS)(p.scope("clip"), r, z0, z1)
    # along +y; the clip turned about the axis to point down and to the front (-x)
    turn = math.pi / 2 + roll_angle(c, r)
    rolled(c, -turn if frame is FLIP else turn)
    for part in root.link.parts:
        part.pose = LAY @ part.pose
    root.add(barrel, LAY)
    name, kind, origin, axis, hi, part = moving
    link = b.create_link(name, root)
    link.set_joint(kind, LAY @ origin, axis=axis, limits=(0.0, hi))
    link.add(part)
    (link if clip_on else root).add(c, frame if clip_on else LAY)
    if ctx.sub != "capped_pen":  # the refill point in the nose
        bore, depth, _ = barrel.anchors["nose"]
        tip = b.create_link("refill", root)
        tip.set_joint("prismatic", LAY, axis=(0.0, 0.0, -1.0), limits=(0.0, p.uniform("point_travel", 0.001, 0.0015)))
        tip.add(refill_point(p.scope("refill"), bore, depth))


RULE = Category(
    name="pen",
    subcategories={"click_pen": 3.0, "capped_pen": 2.0, "twist_pen": 1.5},
    materials={"body": "plastic", "clip": "steel", "refill": "brass"},
    mass_range=(0.003, 0.06),  # kg: disposable ballpoints (~5 g) to metal twist pens (~30 g)
    slots=(Slot("body", body),),
)
