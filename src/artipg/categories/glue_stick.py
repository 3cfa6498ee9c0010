"""Glue sticks: standard, jumbo and slim twist-up glue sticks.

Parts: a round tube (plain, with a raised label sleeve, or with a stop collar under
the cap), a twist base under it (plain, fluted, or with a flange), the glue column
inside, and a cap (flat, domed or ribbed) whose skirt slides over the tube's top.
Joints: cap prismatic straight up (its skirt length plus 10-20 mm); twist base
continuous about the axis; glue column prismatic up the tube. In a real stick the
twist drives the glue up a screw: a continuous joint coupled to a prismatic one
cannot be one URDF joint, so they are two independent joints here. The glue's travel
is the cap's headroom (5-12 mm): joint limits are independent of each other, and with
the cap on the glue can only rise that far (a real stick, uncapped, rises further).
Sizes (metres): standard 0.02-0.025 across, 0.085-0.1 tall; jumbo 0.028-0.034,
0.1-0.115; slim 0.015-0.018, 0.08-0.095 (8-43 g sticks).
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.glue import CAPS, CLEAR, TUBES, TWISTS, glue_column

# sub-category -> tube radius, overall height
SUBS = {"standard": ((0.01, 0.0125), (0.085, 0.1)), "jumbo": ((0.014, 0.017), (0.1, 0.115)),
        "slim": ((0.0075, 0.009), (0.08, 0.095))}


def body(ctx):
    p = ctx.p
    rr, hr = SUBS[ctx.sub]
    R, H = p.uniform("radius", *rr), p.uniform("height", *hr)
    hb = p.uniform("twist_height", 0.1, 0.16) * H
    skirt, head = p.uniform("skirt", 0.22, 0.32) * H, p.uniform("headroom", 0.006, 0.013)
    top = 0.003  # bound of the cap's top thickness
    Lt = H - hb - 0.0005 - head - top
    root = ctx.builder.create_link("body")
    tube = root.add(ctx.choose("tube", TUBES)(p.scope("tube"), R, Lt, Lt - skirt - 0.001), translation(0, 0, hb + 0.0005))
    twist = ctx.builder.create_link("knob", root)
    twist.set_joint("continuous", translation(0, 0, 0), axis=(0.0, 0.0, 1.0))
    twist.add(ctx.choose("twist", TWISTS)(p.scope("twist"), R, hb))
    return root, R, tube.anchors["radii"][1], hb + 0.0005, hb + 0.0005 + Lt, skirt, head


def glue(ctx):
    root, R, ri, z0, rim, _, head = ctx.out["body"]
    p = ctx.p
    zg = z0 + p.uniform("glue_floor", 0.002, 0.005)
    top = rim - p.uniform("glue_sunk", 0.0, 0.002)
    link = ctx.builder.create_link("glue", root)
    link.set_joint("prismatic", translation(0, 0, zg), axis=(0.0, 0.0, 1.0), limits=(0.0, rim + head - top - 0.0025))
    link.add(glue_column(p.scope("glue"), ri - CLEAR, top - zg))


def cap(ctx):
    root, R, _, _, rim, skirt, head = ctx.out["body"]
    p = ctx.p
    link = ctx.builder.create_link("cap", root)
    link.set_joint("prismatic", translation(0, 0, rim), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, skirt + p.uniform("pull", 0.01, 0.02)))
    link.add(ctx.choose("cap", CAPS)(p.scope("cap"), R, skirt, head))


RULE = Category(
    name="glue_stick",
    subcategories={"standard": 3.0, "jumbo": 1.5, "slim": 1.5},
    materials={"body": "plastic", "refill": "plastic"},
    mass_range=(0.008, 0.12),  # kg: 8 g slim sticks to 43 g jumbo ones with their tubes
    slots=(Slot("body", body), Slot("glue", glue, after=("body",)), Slot("cap", cap, after=("body",))),
)
