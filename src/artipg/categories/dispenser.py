"""Dispensers: soap and lotion pump bottles, trigger spray bottles and wall-mounted soap
dispensers.

Parts: pump and spray bottles have a body (a turned cylinder with a conical or
rounded shoulder, a square or hexagonal prism, a round flask, or a flat oval) ending in a
neck; a screw collar on the neck carries either a pump (a stem and a round or block
head with a straight or down-bent spout) or a spray head (a shroud tower and nose, a
trigger hanging under the nose, a square, hexagonal or round nozzle cap at its front).
Wall units have a housing (its lower front recessed), a back mounting plate, a nozzle
under the front, an optional level window, a push plate in the recess and a refill lid
on top.
Joints: collars continuous about the neck axis (screwing); pumps prismatic down by
8-16 mm, their heads on some models a further revolute about z (a quarter to
three-eighths turn, the lock); triggers revolute about the horizontal pivot under
the nose, 0.3-0.6 rad; nozzle caps revolute about their axis, 90-180 degrees (off /
spray / stream); wall push plates prismatic into the housing by 6-12 mm or hinged at
their top edge (revolute, as far); refill lids revolute about the back top edge,
70-100 degrees.
Sizes (metres): pump bottles 0.12-0.25 tall over all, bodies 0.06-0.13 across;
spray bottles 0.2-0.31 tall (round-flask ones 0.12-0.2), 0.1-0.14 deep with the
nozzle, bodies 0.065-0.1 across (flat ones 0.03-0.075), spray heads 0.07-0.11 tall;
wall units 0.07-0.12 deep, 0.09-0.14 wide, 0.15-0.28 tall.
Wall units are simulated standing on their back plate and nozzle (the category is
not a fixture: the bottles stand free).
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.bottles import flask_body, square_body
from artipg.templates.dispensers import HEADS, lotion_pump, oval_body, trigger_sprayer, turned_body, wall_dispenser

# sub-category -> body radius, body height (to the neck's top), neck radius, neck height, body weights
SUBS = {
    "pump_dispenser": ((0.03, 0.065), (0.09, 0.17), (0.011, 0.016), (0.014, 0.022),
                       {turned_body: 3.0, square_body: 1.5, oval_body: 1.5, flask_body: 1.0}),
    "trigger_sprayer": ((0.032, 0.05), (0.15, 0.23), (0.012, 0.016), (0.014, 0.04),
                        {turned_body: 4.0, oval_body: 2.0, flask_body: 0.5}),
}
#: flatness (depth / width) of oval bodies per sub-category
FLAT = {"pump_dispenser": (0.5, 0.85), "trigger_sprayer": (0.45, 0.75)}
SPOUTS = {"straight": 2.0, "curved": 1.0}
PLATES = {"slide": 2.0, "hinge": 1.0}


def body(ctx):
    p = ctx.p
    root = ctx.builder.create_link("body")
    if ctx.sub == "wall_dispenser":
        D, W, H = p.uniform("depth", 0.07, 0.12), p.uniform("width", 0.09, 0.14), p.uniform("height", 0.15, 0.28)
        wall_dispenser(p, ctx.builder, root, D, W, H, p.choice("push_plate", PLATES))
        return root, None
    rr, hr, nr, nh, bodies = SUBS[ctx.sub]
    size = (p.uniform("radius", *rr), p.uniform("height", *hr), p.uniform("neck_radius", *nr),
            p.uniform("neck_height", *nh))
    tmpl = ctx.choose("body", bodies)
    part = tmpl(p, *size, flat=FLAT[ctx.sub]) if tmpl is oval_body else tmpl(p, *size)
    root.add(part)
    return root, part


def head(ctx):
    root, part = ctx.out["body"]
    if part is None:
        return
    neck = (part.anchors["neck_edge"][0], part.anchors["bore_edge"][0],
            part.anchors["neck_top"][2] - part.anchors["neck_base"][2])
    pose = translation(*part.anchor("neck_top"))
    p = ctx.p
    if ctx.sub == "trigger_sprayer":
        trigger_sprayer(p, ctx.builder, root, pose, neck)
    else:
        lotion_pump(p, ctx.builder, root, pose, neck, ctx.choose("head", HEADS),
                    curved=p.choice("spout", SPOUTS) == "curved", lock=p.flag("lock", 0.4))


RULE = Category(
    name="dispenser",
    subcategories={"pump_dispenser": 3.0, "trigger_sprayer": 3.0, "wall_dispenser": 0.7},
    materials={"body": "shell", "nozzle": "plastic", "lever": "plastic", "button": "plastic"},
    mass_range=(0.05, 2.0),  # kg: empty pump bottles ~0.05 to a filled 1 l wall unit ~1.5
    slots=(Slot("body", body), Slot("head", head, after=("body",))),
)
