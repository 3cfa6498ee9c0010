"""Shavers: electric foil shavers, rotary shavers and (cartridge) safety razors.

Parts: electric shavers have a body (a rounded box, a waisted grip under a shoulder
block, or an oval prism) with a power button on the front (-x) face. Foil shavers
carry a yoke on the body's top, a head pivoting on it with 1-3 foil cylinders across
it (y), a protective cover over the foils, and on most models a pop-up long-hair
trimmer on the back (+x) face. Rotary shavers carry a round head holder on the top
with 2-3 round cutter heads. Razors lie on their flat handle; a neck and hub at the
handle's end carry a cartridge with 2-5 blades.
Joints: foil heads revolute about y (+-0.15-0.35 rad, rest upright); covers prismatic
up (+z), lifted clear off the foils; trimmers prismatic up the back (10-20 mm);
power buttons prismatic into the front face; rotary holders revolute about the
front edge of the top (-y axis, flipping up and forward 75-110 degrees), each cutter
continuous about its own axis; razor cartridges revolute about the hub (y), 0.4-0.8
rad.
Sizes (metres): electric shavers 0.03-0.05 deep, 0.045-0.065 wide, bodies 0.1-0.15
tall (0.12-0.19 with the head); foil heads 0.04-0.075 wide; rotary holders 0.05-0.08
across; razors 0.1-0.14 long, cartridges 0.034-0.045 wide.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.controls import BUTTONS, mount_button_row
from artipg.templates.shavers import BODIES, foil_head, popup_trimmer, razor, rotary_head

# sub-category -> depth, width, body height (electric shavers)
SUBS = {
    "foil_shaver": ((0.03, 0.045), (0.045, 0.065), (0.1, 0.15)),
    "rotary_shaver": ((0.035, 0.05), (0.045, 0.065), (0.1, 0.15)),
}


def body(ctx):
    p, b = ctx.p, ctx.builder
    root = b.create_link("body")
    if ctx.sub == "safety_razor":
        razor(p, b, root, p.uniform("handle_length", 0.08, 0.11))
        return root, None
    dr, wr, hr = SUBS[ctx.sub]
    D, W, H = p.uniform("depth", *dr), p.uniform("width", *wr), p.uniform("height", *hr)
    root.add(ctx.choose("body", BODIES)(p, D, W, H))
    return root, (D, W, H)


def head(ctx):
    root, dims = ctx.out["body"]
    if dims is None:
        return
    D, W, H = dims
    p, b = ctx.p, ctx.builder
    if ctx.sub == "rotary_shaver":
        rotary_head(p, b, root, (0.0, 0.0, H), D, W)
        return
    _, _, reach = foil_head(p, b, root, (0.0, 0.0, H), D, W)
    if p.flag("trimmer", 0.7):
        popup_trimmer(p.scope("trimmer"), b, root, D, W, H, reach)


def controls(ctx):
    root, dims = ctx.out["body"]
    if dims is None:
        return
    D, W, H = dims
    p = ctx.p
    z = p.uniform("button_height", 0.5, 0.7) * H
    r = p.uniform("button_radius", 0.004, 0.007)
    mount_button_row(p.scope("power"), ctx.builder, root, ctx.choose("button", BUTTONS), 1,
                     translation(-D / 2, 0, 0), -0.01, 0.01, z, radius=r, square=(min(2 * r + 0.004, 0.5 * W), 2 * r))


RULE = Category(
    name="shaver",
    subcategories={"foil_shaver": 3.0, "rotary_shaver": 2.0, "safety_razor": 2.0},
    materials={"body": "shell", "handle": "aluminium"},
    mass_range=(0.01, 0.4),  # kg: plastic razors ~15 g to mains shavers ~250 g
    slots=(Slot("body", body), Slot("head", head, after=("body",)), Slot("controls", controls, after=("body",))),
)
