"""Kitchen pots: stockpots, saucepans, saute pans and Dutch ovens.

Parts: an open body (straight cylinder, flared frustum, or a bellied pot whose wall
swells out and draws in to the rim), a lid resting on the rim (flat or gently domed
with a knob, a wire loop or a bridge handle; some with a skirt over the rim), and
either one long handle (straight tube, neck + thick grip with a hanging ring, or a
flat riveted bar) with an optional helper lug opposite, or a pair of side lugs (wire
loops, ears with a finger hole, or bent-wire D handles).
Joints: the lid is free to lift: prismatic along the pot's axis (0.08-0.2 m);
handles are fixed.
Sizes (metres): rim radius 0.08-0.16; stockpot 0.16-0.3 tall, saucepan 0.07-0.12,
saute pan 0.05-0.08, Dutch oven 0.09-0.15.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.bodies import cylindrical_shell, tapered_shell
from artipg.templates.cookware import LONG_HANDLES, SIDE_HANDLES, loop_lid
from artipg.templates.lids import bridge_lid, knobbed_lid, mount_lid
from artipg.templates.vessels import bellied_shell, wall_radius

# sub-category -> rim radius, height, body weights, handles ("long" or "side")
SUBS = {
    "stockpot": ((0.1, 0.16), (0.16, 0.3), {cylindrical_shell: 3.0, tapered_shell: 1.0}, "side"),
    "saucepan": ((0.08, 0.1), (0.07, 0.12), {cylindrical_shell: 2.0, tapered_shell: 1.0, bellied_shell: 1.0}, "long"),
    "saute_pan": ((0.11, 0.15), (0.05, 0.08), {cylindrical_shell: 2.0, tapered_shell: 2.0}, "long"),
    "dutch_oven": ((0.1, 0.15), (0.09, 0.15), {bellied_shell: 2.0, cylindrical_shell: 1.0, tapered_shell: 1.0}, "side"),
}
LIDS = {knobbed_lid: 3.0, loop_lid: 1.5, bridge_lid: 1.0}
LUG_CLEAR = 0.008  # half-height bound of the side lugs (wire or tab)
RIGHT, LEFT = rot_z(-math.pi / 2), rot_z(math.pi / 2)  # handles on the -y and +y sides


def body(ctx):
    p = ctx.p
    rr, hr, bodies, _ = SUBS[ctx.sub]
    R, H = p.uniform("radius", *rr), p.uniform("height", *hr)
    lid = ctx.choose("lid", LIDS)(p.scope("lid"), R)
    skirt = -float(lid.anchors["hinge"][2])  # depth the lid's skirt hangs over the rim
    tmpl = ctx.choose("body", bodies)
    if tmpl is bellied_shell:
        part = tmpl(p, R, H, band=skirt + 0.003 if skirt > 0 else 0.0)
    else:
        part = tmpl(p, R, H)
    root = ctx.builder.create_link("body")
    root.add(part)
    mount_lid(ctx.builder, root, lid, translation(0, 0, H), mode="lift", limit=p.uniform("lift", 0.08, 0.2))
    return root, part, H - skirt, R


def handles(ctx):
    root, part, top, R = ctx.out["body"]
    p = ctx.p
    kind = SUBS[ctx.sub][3]
    sides = [(RIGHT, "long")] if kind == "long" else [(RIGHT, "side"), (LEFT, "side")]
    if kind == "long" and p.flag("helper", 0.4 if ctx.sub == "saute_pan" else 0.15):
        sides.append((LEFT, "side"))
    drop = p.uniform("drop", 0.002, 0.02)
    lug = None
    for i, (turn, k) in enumerate(sides):
        q = p.scope(f"handle{i}")
        if k == "long":  # its height follows from how high it is near the wall
            h = ctx.choose("long_handle", LONG_HANDLES)(q, R)
            z = top - 0.0015 - float(h.anchors["clear"][2]) - drop
            r = wall_radius(part, z)
        else:  # lugs are at most 2 * LUG_CLEAR thick
            z = top - 0.0015 - LUG_CLEAR - drop
            lug = lug or ctx.choose("lug", SIDE_HANDLES)  # both lugs alike
            r = wall_radius(part, z)
            h = lug(q, r)
        root.add(h, turn @ translation(r, 0, z))


RULE = Category(
    name="kitchen_pot",
    subcategories={"stockpot": 2.0, "saucepan": 3.0, "saute_pan": 1.5, "dutch_oven": 1.5},
    materials={"body": "aluminium", "lid": "glass"},
    mass_range=(0.3, 6.0),  # kg: aluminium saucepans to cast-iron-heavy stockpots with lid
    slots=(Slot("body", body), Slot("handles", handles, after=("body",))),
)
