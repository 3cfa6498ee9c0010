"""Bottles: water and sports bottles, wine bottles, pump (soap, lotion) bottles and
squeeze (shampoo, condiment) bottles.

Parts: a body (cylinder with a conical or rounded shoulder, a square, hexagonal or
octagonal prism, or a round flask) ending in a hollow neck, and a closure on the
neck: a screw cap, a T-stopper in the bore, a flip-top cap with a nozzle under a
hinged lid, a sport cap with a push-pull spout, or a pump (screw collar, stem, head
and nozzle).
Joints: screw caps and pump collars continuous about the axis; stoppers prismatic
along the axis (pulled out); flip lids revolute about a hinge at the back of the cap
(up to 100-150 deg); push-pull spouts prismatic up; pumps prismatic down (pressed).
Sizes (metres): water 0.18-0.3 tall, wine 0.28-0.33 with a 0.06-0.09 neck, pump
0.12-0.2, squeeze 0.12-0.22; body radius 0.025-0.05.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.bottles import flask_body, round_body, shouldered_body, square_body
from artipg.templates.caps import flip_top, pump_top, screw_top, sport_top, stopper_top

# sub-category -> radius, height, neck radius, neck height, body weights, closure weights
SUBS = {
    "water_bottle": ((0.03, 0.042), (0.18, 0.3), (0.012, 0.0145), (0.012, 0.02),
                     {round_body: 3.0, square_body: 1.0, shouldered_body: 1.0},
                     {screw_top: 3.0, sport_top: 2.0, flip_top: 1.0}),
    "wine_bottle": ((0.036, 0.045), (0.28, 0.33), (0.0125, 0.0155), (0.06, 0.09),
                    {shouldered_body: 2.0, round_body: 2.0}, {stopper_top: 2.0, screw_top: 1.0}),
    "pump_bottle": ((0.03, 0.05), (0.12, 0.2), (0.012, 0.016), (0.016, 0.025),
                    {round_body: 2.0, square_body: 2.0, flask_body: 1.0}, {pump_top: 1.0}),
    "squeeze_bottle": ((0.025, 0.04), (0.12, 0.22), (0.01, 0.014), (0.01, 0.016),
                       {round_body: 2.0, square_body: 1.0, shouldered_body: 1.0},
                       {flip_top: 3.0, screw_top: 1.0, sport_top: 0.5}),
}


def body(ctx):
    p = ctx.p
    rr, hr, nr, nh, bodies, _ = SUBS[ctx.sub]
    root = ctx.builder.create_link("body")
    size = (p.uniform("radius", *rr), p.uniform("height", *hr), p.uniform("neck_radius", *nr),
            p.uniform("neck_height", *nh))
    part = ctx.choose("body", bodies)(p, *size)
    root.add(part)
    return root, part


def closure(ctx):
    root, part = ctx.out["body"]
    neck = (part.anchors["neck_edge"][0], part.anchors["bore_edge"][0],
            part.anchors["neck_top"][2] - part.anchors["neck_base"][2])
    tmpl = ctx.choose("closure", SUBS[ctx.sub][5])
    tmpl(ctx.p, ctx.builder, root, translation(*part.anchor("neck_top")), neck)


RULE = Category(
    name="bottle",
    subcategories={"water_bottle": 3.0, "wine_bottle": 1.5, "pump_bottle": 1.5, "squeeze_bottle": 2.0},
    materials={"body": "shell"},
    mass_range=(0.05, 1.5),  # kg: empty plastic bottles to filled glass wine bottles
    slots=(Slot("body", body), Slot("closure", closure, after=("body",))),
)
