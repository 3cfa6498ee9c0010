"""Displays: computer monitors and TVs on desk stands.

Parts: a stand base (rectangular plate, round disc or V of two splayed feet); a neck
(box, round post, or box with a cable opening); a tilt hinge (barrel, arm and round
mounting plate) and the screen (panel with a back housing and a display face, with an
even bezel, a chin, or a raised TV-style frame) with a control button under its edge. Height-adjustable monitors add a
carriage sliding on the front of a taller column.
Joints: swivel revolute about the vertical axis of the neck (+-20-45 deg, on a small
turntable); height prismatic along z (ergonomic monitors, 100-150 mm travel; rest is
the highest position, value 0, lowering is negative, so the portrait pivot is clear of
the base at rest); tilt revolute about y through the hinge barrel (-5 deg forward to
+14-23 deg back, capped where the screen would touch the neck or carriage); portrait
pivot revolute about x through the screen centre (0-90 deg). URDF limits are
independent: lowering an ergonomic monitor while it is in portrait would hit the
base (the real stand stops it there; no URDF joint can say so).
Sub-categories: fixed_monitor (tilt, sometimes swivel), ergonomic_monitor (height,
tilt, usually swivel and pivot), tv (swivel, sometimes tilt).
Sizes (metres): monitors 21.5-34 in (0.48-0.81 wide, 16:9, 16:10 or 21:9), bases
0.18-0.3 wide; TVs 32-55 in (0.72-1.25 wide, 16:9), bases 0.25-0.45 wide.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.displays import (BASES, NECKS, SCREENS, box_neck, control_button, height_carriage, slot_neck,
                                       tilt_hinge, turntable)

COLUMNS = {box_neck: 2.0, slot_neck: 1.0}  # a carriage needs a flat front face
MONITOR_ASPECTS, TV_ASPECTS = {16 / 9: 3.0, 16 / 10: 1.0, 21 / 9: 1.0}, {16 / 9: 1.0}
# sub-category -> screen width, base width, base depth, swivel limit, P(swivel), P(tilt), P(pivot)
SUBS = {"fixed_monitor": ((0.48, 0.72), (0.18, 0.26), (0.15, 0.22), (0.6, 0.8), 0.3, 1.0, 0.0),
        "ergonomic_monitor": ((0.48, 0.81), (0.2, 0.3), (0.17, 0.24), (0.6, 0.8), 0.85, 1.0, 0.7),
        "tv": ((0.72, 1.25), (0.25, 0.45), (0.2, 0.3), (0.25, 0.45), 1.0, 0.35, 0.0)}


def stand(ctx):
    """Base, optional swivel turntable, neck or column (+ height carriage); returns the
    link carrying the tilt hinge, the hinge position in it, and the screen's size."""
    p = ctx.p
    ws, wb, db, swivel, p_swivel, _, p_pivot = SUBS[ctx.sub]
    W = p.uniform("screen_width", *ws)
    H = W / p.choice("aspect", TV_ASPECTS if ctx.sub == "tv" else MONITOR_ASPECTS) + 0.01
    pivot = W < 0.65 and W / H < 2.0 and p.flag("pivot", p_pivot)  # 27 in at most, no ultrawides
    nw, nd = p.uniform("neck_width", 0.04, 0.08), p.uniform("neck_depth", 0.02, 0.045)
    rb = p.uniform("barrel_radius", 0.007, 0.012)
    ergo = ctx.sub == "ergonomic_monitor"
    reach = p.uniform("reach", 0.05, 0.09) if ergo else nd / 2 + p.uniform("reach", 0.02, 0.05)
    # the screen's centre of mass lies about ``ahead`` in front of the neck's axis; the
    # neck stands that far behind the base's centre, where the base allows
    ahead = reach + 0.025 + (nd / 2 + 0.026 + 2 * rb if ergo else 0.0)
    root = ctx.builder.create_link("base")
    base = root.add(ctx.choose("base", BASES)(p.scope("base"), p.uniform("base_width", *wb),
                                              p.uniform("base_depth", *db), 0.85 * ahead))
    xm, _, zt = base.anchors["mount"]
    link, ox, oz = root, 0.0, 0.0  # link carrying the neck, and its frame's origin
    z0 = zt  # foot of the neck
    if p.flag("swivel", p_swivel):
        link, ox, oz = ctx.builder.create_link("stand", root), xm, zt
        hi = p.uniform("swivel", *swivel)
        link.set_joint("revolute", translation(xm, 0, zt), axis=(0.0, 0.0, 1.0), limits=(-hi, hi))
        tt = link.add(turntable(p.scope("turntable"), 0.6 * max(nw, nd) + p.uniform("turntable_margin", 0.005, 0.015)))
        z0 = zt + tt.anchors["top"][2]
    gap = p.uniform("low_gap", 0.03, 0.1)  # the screen's bottom edge over the base, at its lowest
    if ctx.sub != "ergonomic_monitor":
        zh = zt + gap + H / 2  # tilt axis = screen centre height; the barrel sits on the neck
        link.add(ctx.choose("neck", NECKS)(p.scope("neck"), zh - rb - 0.0005 - z0, nw, nd),
                 translation(xm - ox, 0, z0 - oz))
        return link, (xm - ox, zh - oz), -nd / 2, reach, rb, W, H, pivot, 0.0  # nothing behind above the axis
    # at rest the turning screen's corners (half its diagonal from the axis) clear the base
    lo = max(0.1, math.hypot(W, H) / 2 - H / 2 - gap + 0.015) if pivot else 0.1
    travel = p.uniform("travel", lo, max(lo + 0.01, 0.15))
    ch = p.uniform("carriage_height", 0.06, 0.1)
    zh = zt + gap + H / 2 + travel  # rest: the highest position
    top = zh + ch / 2 + p.uniform("column_over", 0.0, 0.01)
    link.add(ctx.choose("neck", COLUMNS)(p.scope("neck"), top - z0, nw, nd), translation(xm - ox, 0, z0 - oz))
    carriage = ctx.builder.create_link("carriage", link)
    carriage.set_joint("prismatic", translation(xm - ox - nd / 2 - 0.0005, 0, zh - oz), axis=(0.0, 0.0, 1.0),
                       limits=(-travel, 0.0))
    xf = carriage.add(height_carriage(p.scope("carriage"), 0.9 * nw, ch)).anchors["front"][0]
    # the column stands up to ``over`` above the tilt axis (carriage at its lowest)
    over = top - zh + travel
    return carriage, (xf - rb - 0.0005, 0.0), rb + 0.0005, reach, rb, W, H, pivot, over


def _tilt_limit(L, b, e):
    """Largest tilt (radians) that keeps a screen corner ``b`` above or below the axis,
    ``L`` in front of it, 3 mm in front of an obstacle at x >= ``e`` (axis frame)."""
    R = math.hypot(L, b)
    return math.acos(max(-1.0, min(1.0, (0.003 - e) / R))) - math.atan2(b, L)


def screen(ctx):
    link, (xh, zh), e, L, rb, W, H, pivot, over = ctx.out["stand"]
    p = ctx.p
    hinge = tilt_hinge(p.scope("hinge"), L, rb)
    scr = ctx.choose("screen", SCREENS)(p.scope("screen"), W, H)
    at = translation(xh, 0, zh)
    if p.flag("tilt", SUBS[ctx.sub][5]):
        back = p.uniform("tilt_back", 0.26, 0.4)
        if over:  # the screen's top edge swings back towards the column
            back = min(back, _tilt_limit(L, min(max(H, W if pivot else H) / 2, over), e))
        fwd = min(p.uniform("tilt_forward", 0.05, 0.09), _tilt_limit(L, H / 2, e))
        tilt = ctx.builder.create_link("hinge", link)
        tilt.set_joint("revolute", at, axis=(0.0, 1.0, 0.0), limits=(-max(fwd, 0.0), back))
        link, at = tilt, translation(0, 0, 0)
    mount = at @ translation(*hinge.anchors["mount"])
    link.add(hinge, at)
    if pivot:
        turn = ctx.builder.create_link("screen", link)
        turn.set_joint("revolute", mount, axis=(1.0, 0.0, 0.0), limits=(0.0, math.pi / 2))
        link, mount = turn, translation(0, 0, 0)
    link.add(scr, mount)
    link.add(control_button(p.scope("button"), scr), mount)


RULE = Category(
    name="display",
    subcategories={"fixed_monitor": 2.0, "ergonomic_monitor": 2.0, "tv": 1.5},
    materials={"screen": "plastic", "base": "aluminium", "stand": "aluminium"},
    mass_range=(1.0, 45.0),  # kg: 22 in monitors (~3 kg) to 55 in TVs on their stands (~20 kg)
    slots=(Slot("stand", stand), Slot("screen", screen, after=("stand",))),
)
