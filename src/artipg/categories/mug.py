"""Mugs with moving parts: lidded tea mugs, travel mugs and beer steins.

A plain mug has no moving part, so it is not a sub-category here: every mug of this
category has a lid or a drink-opening cover (the fixed body, handle and lid of a plain
mug are the same templates).
Parts: an open body (straight, widening towards the rim, or with a foot ring and rim
band) with a side handle (round C, moulded D or round loop ear; optional on travel
mugs). Lidded mugs carry a flat, knobbed or domed lid with a plug inside the rim,
hinged at the back, over the handle; beer steins a pewter lid (flat or domed) hinged on two cheeks standing on the
handle's top, with a thumb lever rising from the hinge knuckle; travel mugs a
screw-on lid (modelled fixed) with a raised deck and a drink opening under a slider
between two rails or a flip flap.
Joints: mug lid revolute about y at the back (75-97 deg); stein lid revolute about the
knuckle (80-110 deg, capped where the thumb lever meets the handle); travel slider
prismatic towards the back (12-20 mm), travel flap revolute (70-110 deg).
Sizes (metres): lidded mugs 0.09-0.12 tall, 0.075-0.095 across; travel mugs 0.15-0.21
tall, 0.06-0.075 across at the foot; steins 0.14-0.22 tall, 0.08-0.11 across.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.cookware import block_c_handle, c_handle
from artipg.templates.lids import mount_lid
from artipg.templates.mugs import (BODIES, PLUG_LIDS, conical_body, flip_cover, lever_stop, loop_handle, slide_cover,
                                   slide_rails, stein_bracket, stein_lid, straight_body, travel_lid, wall_radius)

TURN = rot_z(math.pi / 2)  # built with the handle at +x; turned so the front view (-x) shows the profile
HANDLES = {loop_handle: 2.0, c_handle: 1.5, block_c_handle: 1.0}
TRAVEL_BODIES = {conical_body: 2.0, straight_body: 1.0}
COVERS = {"slide": 1.0, "flip": 1.0}
# sub-category -> bottom radius, height, bodies, P(handle), handle span / height
SUBS = {"lidded_mug": ((0.037, 0.047), (0.09, 0.12), BODIES, 1.0, (0.45, 0.65)),
        "travel_mug": ((0.03, 0.037), (0.15, 0.21), TRAVEL_BODIES, 0.4, (0.35, 0.5)),
        "beer_stein": ((0.04, 0.055), (0.14, 0.22), BODIES, 1.0, (0.5, 0.7))}


def body(ctx):
    p = ctx.p
    rr, hr, bodies, p_handle, span = SUBS[ctx.sub]
    H = p.uniform("height", *hr)
    part = ctx.choose("body", bodies)(p.scope("shell"), p.uniform("radius", *rr), H)
    root = ctx.builder.create_link("body")
    root.add(part, TURN)
    lp = None
    if ctx.sub == "lidded_mug":  # chosen here: the handle stays below the lid's skirt
        # the wall's inner radius 10 mm under the rim (the plug's reach): a conical wall narrows downwards
        inner = wall_radius(part, H - 0.01) - part.anchors["wall"][0]
        lp = ctx.choose("lid", PLUG_LIDS)(p.scope("lid"), part.anchors["lip"][0], inner)
    if not p.flag("handle", p_handle):
        return root, part, None, lp
    # below a travel lid's skirt, or a mug lid's skirt and the handle's half thickness
    skirt = {"travel_mug": 0.022, "beer_stein": 0.015, "lidded_mug": 0.012}[ctx.sub]
    zt = H - skirt - p.uniform("top_gap", 0.008, 0.02)
    zb = max(zt - p.uniform("span", *span) * H, 0.022)  # the handle's lower bend stays off the table
    h = ctx.choose("handle", HANDLES)(p.scope("handle"), wall_radius(part, zt), zt, wall_radius(part, zb), zb)
    root.add(h, TURN)
    return root, part, h, lp


def lid(ctx):
    root, part, handle, lp = ctx.out["body"]
    p = ctx.p
    H, lip = part.anchors["rim"][2], part.anchors["lip"][0]
    rim = TURN @ translation(0, 0, H)
    if ctx.sub == "lidded_mug":
        mount_lid(ctx.builder, root, lp, rim, mode="flip", limit=p.uniform("open", 1.3, 1.7))
    elif ctx.sub == "beer_stein":
        _stein(ctx, root, part, handle, H, lip, rim)
    else:
        _travel(ctx, root, lip, rim)


def _stein(ctx, root, part, handle, H, lip, rim):
    p = ctx.p
    R = lip + 0.005  # bound of the lid's radius (its overhang is at most 5 mm)
    hx = max(R + 0.0045 + p.uniform("hinge_gap", 0.006, 0.01), handle.anchors["top"][0])
    beta = p.uniform("lever_lean", 0.2, 0.5)
    lp = stein_lid(p.scope("lid"), lip, hx, p.uniform("thumb", 0.015, 0.03), beta)
    zk = lp.anchors["hinge"][2]
    bracket = stein_bracket(p.scope("bracket"), lp, wall_radius(part, H), handle.anchors["top"][2] - H)
    root.add(bracket, rim)
    stop = lever_stop(lp, beta, bracket.anchors["top"][2], H + zk - handle.anchors["top"][2])
    link = ctx.builder.create_link("lid", root)
    link.set_joint("revolute", rim @ translation(hx, 0, zk), axis=(0.0, 1.0, 0.0),
                   limits=(0.0, max(0.5, min(p.uniform("open", 1.4, 1.9), stop))))
    link.add(lp, translation(-hx, 0, -zk))


def _travel(ctx, root, lip, rim):
    p = ctx.p
    lp = root.add(travel_lid(p.scope("lid"), lip), rim)
    z, rd = lp.anchors["top"][2], lp.anchors["deck"][0]
    w, L = p.uniform("cover_width", 0.45, 0.6) * rd, p.uniform("cover_length", 0.4, 0.55) * rd
    x0 = -rd + p.uniform("front_margin", 0.003, 0.008) + L  # the cover's back edge
    link = ctx.builder.create_link("flap", root)
    if p.choice("cover", COVERS) == "slide":
        cover = slide_cover(p.scope("slider"), L, w)
        root.add(slide_rails(L, w, cover.anchors["top"][2], translation(x0, 0, z)), rim, name="rails")
        link.set_joint("prismatic", rim @ translation(x0, 0, z), axis=(1.0, 0.0, 0.0),
                       limits=(0.0, min(p.uniform("travel", 0.012, 0.02), 0.8 * L)))
    else:
        cover = flip_cover(p.scope("flap"), L, w)
        link.set_joint("revolute", rim @ translation(x0, 0, z + cover.anchors["thickness"][0] + 0.0003),
                       axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("open", 1.2, 1.9)))
    link.add(cover)


RULE = Category(
    name="mug",
    subcategories={"lidded_mug": 2.0, "travel_mug": 2.0, "beer_stein": 1.5},
    materials={"body": "ceramic", "handle": "ceramic", "lid": "plastic", "hinge": "steel", "flap": "plastic"},
    mass_range=(0.1, 2.0),  # kg: travel mugs (~0.3 kg) to stoneware steins with pewter lids (~1.2 kg)
    slots=(Slot("body", body), Slot("lid", lid, after=("body",))),
)
