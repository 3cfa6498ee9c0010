"""Shampoo, conditioner and lotion bottles: squeeze bottles with a flip cap, with a disc
top, or with a lotion pump.

Parts: a body (an oval prism with a sloped oval shoulder, an oval that narrows or
widens towards the shoulder, or a round lathe-turned bottle with a rounded shoulder)
ending in a short neck. Flip and disc caps are snap-on: a cap base on the shoulder
(part of the body link) with a lid over a nozzle, or a disc rocking in a recess of its
top on a pin; lotion bottles carry a screw collar and a pump (stem, round or block
head, spout).
Joints: flip lids revolute about the hinge at the back of the cap (+y axis), 100-160
degrees; discs revolute about the pin across the cap (+y), 0.1-0.3 rad (the back
pressed down until it meets the recess floor); pump collars continuous about the
neck, pumps prismatic down by 5-10 mm, locking heads a further revolute about z.
Sizes (metres): bodies 0.05-0.09 wide, 0.5-0.8 of that deep (round ones as deep as
wide), 0.13-0.24 tall to the neck's top; caps 0.028-0.044 across; pump bottles
0.16-0.26 tall over all. Unlike :mod:`artipg.categories.dispenser` (rigid pump and
spray bottles), these are squeeze bottles with oval sections and snap-on caps.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.dispensers import HEADS, lotion_pump
from artipg.templates.squeeze import BODIES, disc_cap, flip_cap

# sub-category -> width, depth / width, height, neck radius, neck height
SUBS = {
    "flip_cap": ((0.05, 0.09), (0.5, 0.8), (0.13, 0.24), (0.009, 0.013), (0.008, 0.014)),
    "disc_top": ((0.05, 0.09), (0.5, 0.8), (0.13, 0.24), (0.009, 0.013), (0.008, 0.014)),
    "pump_lotion": ((0.055, 0.085), (0.55, 0.85), (0.12, 0.2), (0.011, 0.014), (0.014, 0.02)),
}


def body(ctx):
    p = ctx.p
    wr, fr, hr, nr, nh = SUBS[ctx.sub]
    w = p.uniform("width", *wr)
    part = ctx.choose("body", BODIES)(p, w, w * p.uniform("flatness", *fr), p.uniform("height", *hr),
                                      p.uniform("neck_radius", *nr), p.uniform("neck_height", *nh))
    root = ctx.builder.create_link("body")
    root.add(part)
    return root, part


def closure(ctx):
    root, part = ctx.out["body"]
    p, a = ctx.p, part.anchors
    rn, hn = a["neck_edge"][0], a["neck_top"][2] - a["neck_base"][2]
    if ctx.sub == "pump_lotion":
        lotion_pump(p, ctx.builder, root, translation(*a["neck_top"]), (rn, a["bore_edge"][0], hn),
                    ctx.choose("head", HEADS), curved=p.flag("curved", 0.3), lock=p.flag("lock", 0.5),
                    travel=(0.005, 0.01), stem=(0.006, 0.02), head_radius=(0.009, 0.014))
    elif ctx.sub == "flip_cap":
        flip_cap(p, ctx.builder, root, translation(*a["neck_base"]), rn, hn)
    else:
        disc_cap(p, ctx.builder, root, translation(*a["neck_base"]), rn, hn)


RULE = Category(
    name="shampoo",
    subcategories={"flip_cap": 3.0, "disc_top": 2.0, "pump_lotion": 1.5},
    materials={"body": "shell", "button": "plastic"},
    mass_range=(0.03, 1.2),  # kg: empty travel bottles to full 500 ml bottles
    slots=(Slot("body", body), Slot("closure", closure, after=("body",))),
)
