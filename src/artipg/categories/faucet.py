"""Faucets (taps and mixers) for basins and kitchen sinks.

Parts: a deck plate (round or rectangular, optional under single-lever mixers; a long
plate under two-handle faucets)
under a body column (single-lever, pull-out, gooseneck) or a spout
hub and two valve bodies (two-handle); a spout -- a collar spout around the column
(straight tube or flat waterfall) for single-lever mixers, a top-mounted gooseneck,
arc or tube spout for the others -- fixed, or swivelling about z (revolute or
continuous); levers: a joystick cap on the column that lifts about a horizontal axis
(single-lever), a side lever turning about its hub (pull-out, gooseneck), or two valve
handles (lever, cross or fluted knob) turning a quarter turn outwards about z
(two-handle); pull-out faucets carry a spray head that slides out of the spout along
its outlet direction (prismatic). Spouts rise high enough to swivel over the levers.
Sizes (metres): 0.1-0.45 tall; spouts reach 0.06-0.3 forward.
"""

from __future__ import annotations

import copy
import math

from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.extents import span
from artipg.templates.levers import VALVE_HANDLES, joystick_lever, side_lever
from artipg.templates.spouts import (COLLAR_SPOUTS, DECKS, TOP_SPOUTS, arc_spout, column, gooseneck_spout, rect_deck,
                                     spray_head)

# sub-category -> column radius, column height, spout rise ranges (metres)
SUBS = {
    "single_lever": ((0.018, 0.028), (0.1, 0.22), None),
    "two_handle": ((0.014, 0.022), (0.015, 0.05), (0.04, 0.15)),
    "pull_out": ((0.02, 0.03), (0.06, 0.11), (0.1, 0.19)),
    "gooseneck": ((0.018, 0.028), (0.06, 0.11), (0.08, 0.19)),
}
SPOUTS = {"pull_out": {gooseneck_spout: 2.0, arc_spout: 1.0}, "gooseneck": {gooseneck_spout: 1.0}}  # else TOP_SPOUTS
C = 0.006  # clearance between parts that move past each other
SWIVELS = {"fixed": 1.0, "revolute": 1.0, "continuous": 0.6}
QUARTER_TURN = rot_z(math.pi / 2)


def base(ctx):
    p = ctx.p
    (r0, r1), (h0, h1), _ = SUBS[ctx.sub]
    rc, hc = p.uniform("column_radius", r0, r1), p.uniform("column_height", h0, h1)
    root = ctx.builder.create_link("base")
    valves = []
    if ctx.sub == "two_handle":
        spread = p.uniform("spread", 0.1, 0.2)
        rv = p.uniform("valve_radius", 0.012, 0.018)
        hv = p.uniform("valve_height", 0.015, 0.04)
        # one plate under all three (separate escutcheons would be disconnected parts)
        deck = root.add(rect_deck(p.scope("deck"), radius=max(rc, rv) + p.uniform("rim", 0.005, 0.012),
                                  length=spread + 2 * rv + p.uniform("end_margin", 0.01, 0.03)))
        zd = deck.anchor("top")[2]
        for i, s in enumerate((1, -1)):  # (valve top frame, side, largest handle reach)
            root.add(column(p.scope(f"valve{i}"), rv, hv), translation(0, s * spread / 2, zd))
            valves.append((translation(0, s * spread / 2, zd + hv), s, spread / 2 - rc - C))
    elif ctx.sub != "single_lever" or p.flag("has_deck", 0.5):  # many mixers stand on the sink without a plate
        deck = root.add(ctx.choose("deck", DECKS)(p.scope("deck"), radius=rc + p.uniform("rim", 0.008, 0.02)))
        zd = deck.anchor("top")[2]
    else:
        zd = 0.0
    root.add(column(p.scope("column"), rc, hc), translation(0, 0, zd))
    return root, rc, translation(0, 0, zd + hc), valves, hc


def levers(ctx):
    root, rc, top, valves, _ = ctx.out["base"]
    p, b = ctx.p, ctx.builder
    if ctx.sub == "single_lever":
        # the lever's cap sits 0.5 mm inside the column's rim, about which it tilts: it
        # lifts clear at once instead of rolling on a rim line, a contact MuJoCo's convex
        # collider misreads as 20 mm deep at some angles
        lv = joystick_lever(p, rc - 0.0005)
        link = b.create_link("lever", root)
        link.set_joint("revolute", top @ translation(rc, 0, 0), axis=(0.0, 1.0, 0.0),
                       limits=(0.0, p.uniform("lift", 0.3, 0.6)))
        link.add(lv, translation(-rc, 0, 0))
        return 0.0
    if ctx.sub == "two_handle":
        tmpl = ctx.choose("handle", VALVE_HANDLES)
        turn = p.uniform("turn", 1.2, 1.6)
        h0 = tmpl(p.scope("handle"), max_reach=valves[0][2])
        # a matching pair: the second handle is a copy of the first (copy.copy, unlike dataclasses.replace,
        # leaves the template's grasps unbuilt)
        for i, (T, s, _) in enumerate(valves):
            link = b.create_link("lever", root)
            link.set_joint("revolute", T, axis=(0.0, 0.0, -s), limits=(0.0, turn))
            link.add(copy.copy(h0) if i else h0)
        return valves[0][0][2, 3] + span(h0.primitives, 2)[1] - top[2, 3]  # handle tops above the spout hub
    lv = side_lever(p)
    zm = -p.uniform("lever_drop", 0.012, 0.025)
    link = b.create_link("lever", root)
    link.set_joint("revolute", top @ translation(0, -rc, zm) @ QUARTER_TURN, axis=(1.0, 0.0, 0.0),
                   limits=(0.0, p.uniform("swing", 0.8, 1.4)))
    link.add(lv)
    return zm + lv.anchor("reach")[2]


def spout(ctx):
    root, rc, top, _, hc = ctx.out["base"]
    p, b = ctx.p, ctx.builder
    r = min(rc, p.uniform("tube_radius", 0.008, 0.014))
    if ctx.sub == "single_lever":
        sp = ctx.choose("template", COLLAR_SPOUTS)(p, rc, max_tip=0.25 * hc, run=(0.08, 0.22))
        z = -p.uniform("collar_drop", 0.005, 0.3 * hc - 0.02) - sp.anchor("collar_top")[2]
        origin = top @ translation(0, 0, z)
    else:
        low = max(ctx.out["levers"], 0.0) + C
        rise = p.uniform("rise", *SUBS[ctx.sub][2])
        sp = ctx.choose("template", SPOUTS.get(ctx.sub, TOP_SPOUTS))(p.scope("tube"), radius=r, low=low, rise=rise)
        origin = top
    kind = p.choice("swivel", SWIVELS)
    if kind == "fixed":
        root.add(sp, origin)
        return root, origin, sp, r
    link = b.create_link("spout", root)
    a = p.uniform("swivel_angle", 0.6, 1.6)
    link.set_joint(kind, origin, axis=(0.0, 0.0, 1.0), limits=(-a, a))
    link.add(sp)
    return link, translation(0, 0, 0), sp, r


def head(ctx):
    if ctx.sub != "pull_out":
        return
    link, T, sp, r = ctx.out["spout"]
    o, d = sp.anchor("outlet"), sp.anchor("outlet_dir")
    hd = spray_head(ctx.p, r)
    L = hd.anchor("length")[2]
    z_out = (ctx.out["base"][2] @ [*o, 1.0])[2]  # outlet height above the counter
    room = (z_out - 0.02) / max(-d[2], 1e-3) - L
    hl = ctx.builder.create_link("nozzle", link)
    hl.set_joint("prismatic", T @ translation(*o) @ rot_y(math.atan2(d[0], d[2])), axis=(0.0, 0.0, 1.0),
                 limits=(0.0, min(ctx.p.uniform("travel", 0.1, 0.25), room)))
    hl.add(hd)


RULE = Category(
    name="faucet",
    # single-lever mixers are the most common (5 of the 6 real faucets of the development split)
    subcategories={"single_lever": 5.0, "two_handle": 1.5, "pull_out": 1.5, "gooseneck": 1.0},
    fixed_base=True,  # mounted on a sink or counter: simulated mounted, not dropped on a floor
    materials={"body": "shell", "base": "shell"},
    mass_range=(0.3, 5.0),  # kg: brass taps with their mounting body
    slots=(Slot("base", base), Slot("levers", levers, after=("base",)), Slot("spout", spout, after=("levers",)),
           Slot("head", head, after=("spout",))),
)
