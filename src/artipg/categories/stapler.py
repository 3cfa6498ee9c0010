"""Staplers: desktop, mini, heavy-duty and long-reach.

Parts: a base (flat plate, plate with a rounded nose, or a plate on a rubber pad)
with an anvil under the nose and two hinge cheeks at the back; a staple magazine
(open U channel or closed housing) ending at the back in a knuckle with an axle held
between the cheeks; a top arm (flat, rounded half-pipe or humped cover) whose side
skirts end in rings around the same axle and whose nose covers the magazine's front.
Joints: magazine revolute about the rear axle (y), raising its nose off the base
(up to 25-45 deg, for tacking and jams); top arm revolute about the same axle
relative to the magazine (opens 70-95 deg to load staples). At rest everything is
closed, with a paper slot between the magazine and the base.
Sizes (metres): mini 0.08-0.11 long, desktop 0.14-0.2, heavy-duty 0.22-0.3 (taller,
wider), long-reach 0.3-0.45.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.office import ARMS, BASES, MAGAZINES, arm_top

# sub-category -> length, base width, magazine width, hinge radius (half the magazine's height)
SUBS = {
    "desktop": ((0.14, 0.2), (0.04, 0.055), (0.02, 0.026), (0.006, 0.009)),
    "mini": ((0.08, 0.11), (0.025, 0.035), (0.013, 0.017), (0.005, 0.0065)),
    "heavy_duty": ((0.22, 0.3), (0.06, 0.08), (0.026, 0.034), (0.009, 0.013)),
    "long_reach": ((0.3, 0.45), (0.05, 0.065), (0.02, 0.026), (0.006, 0.008)),
}
SKIRT_GAP = 0.001  # between the magazine's sides and the arm's skirts


def base(ctx):
    p = ctx.p
    lr, wr, mr, rr = SUBS[ctx.sub]
    L, wm, rk = p.uniform("length", *lr), p.uniform("magazine_width", *mr), p.uniform("hinge_radius", *rr)
    axle = p.uniform("axle_radius", 0.0015, 0.0025)
    skirt = (wm / 2 + SKIRT_GAP, wm / 2 + SKIRT_GAP + p.uniform("skirt_thickness", 0.0015, 0.0022))
    span = skirt[1] + 0.0008  # axle half-length = inner face of the cheeks
    tc = p.uniform("cheek_thickness", 0.002, 0.004)
    W = max(p.uniform("width", *wr), 2 * (span + tc) + 0.004)
    top = p.uniform("base_thickness", 0.7, 1.3) * rk
    gap = p.uniform("paper_gap", 0.003, 0.008)
    zh = top + gap + rk
    rc = max(0.7 * rk, axle + 0.003)  # cheek half-length
    xh = L / 2 - rc - p.uniform("tail", 0.002, 0.012)
    front = -L / 2 + p.uniform("nose_setback", 0.004, 0.015)  # the magazine's front
    root = ctx.builder.create_link("base")
    root.add(ctx.choose("base", BASES)(p.scope("plate"), L, W, top))
    anvil = cuboid_between((front + 0.002, -0.3 * wm, top - 0.0005), (front + 0.014, 0.3 * wm, top + 0.0015),
                           role="anvil")
    root.add(Part("base", "anvil", [anvil]), name="anvil")
    cheeks = [cuboid_between((xh - rc, y0, top - 0.0005), (xh + rc, y0 + tc, zh + 0.5 * rk), role="cheek")
              for y0 in (span, -span - tc)]
    root.add(Part("hinge", "cheeks", cheeks))
    return root, (xh, zh, gap), (xh - front, wm, rk, axle, span, skirt)


def magazine(ctx):
    root, (xh, zh, _), (lm, wm, rk, axle, span, _) = ctx.out["base"]
    p = ctx.p
    link = ctx.builder.create_link("magazine", root)
    up = p.uniform("open", 0.45, 0.8)
    link.set_joint("revolute", translation(xh, 0, zh), axis=(0.0, 1.0, 0.0), limits=(0.0, up))
    link.add(ctx.choose("magazine", MAGAZINES)(p, lm, wm, rk, axle, span))
    return link, up


def arm(ctx):
    _, (_, _, gap), (lm, wm, rk, axle, span, skirt) = ctx.out["base"]
    mag, mag_up = ctx.out["magazine"]
    p = ctx.p
    part = ctx.choose("arm", ARMS)(p, lm, wm, rk, p.uniform("clearance", 0.001, 0.003), skirt, axle,
                                   p.uniform("nose_gap", 0.001, 0.002))
    # opened past upright (with the magazine up too) the arm's back swings down behind
    # the axle, at most its height above the axle times |cos(angle)|: keep it off the base
    top = arm_top(part)
    up = min(p.uniform("open", 1.2, 1.65), math.pi / 2 + math.asin(min(1.0, (rk + gap - 0.001) / top)) - mag_up)
    link = ctx.builder.create_link("arm", mag)
    link.set_joint("revolute", translation(), axis=(0.0, 1.0, 0.0), limits=(0.0, up))
    link.add(part)


RULE = Category(
    name="stapler",
    subcategories={"desktop": 3.0, "mini": 1.5, "heavy_duty": 1.0, "long_reach": 1.0},
    materials={"base": "shell"},
    mass_range=(0.05, 2.0),  # kg: mini staplers to heavy-duty desk staplers
    slots=(Slot("base", base), Slot("magazine", magazine, after=("base",)), Slot("arm", arm, after=("magazine",))),
)
