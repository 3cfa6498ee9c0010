"""Clips: binder clips, bag clips and clothes pegs.

Clips without a moving part (paper clips, one-piece plastic clips that flex) are
left out: every sub-category here has a hinge or pivot.

Parts and joints per sub-category:
- binder clip: a body folded from one steel sheet (spine, two side plates pressed
  together at the mouth, a rolled edge along each side of the mouth) and two wire
  levers (square or round loops) whose bent ends turn in the curls. Each lever is
  revolute about its curl (y): 0 = folded back along its side plate (a lever longer
  than the plate rests on the floor beside the spine), upper limit = standing
  upright over the mouth (the position that squeezes the jaws open).
- bag clip and clothes peg: two legs (jaw in front of the pivot, handle behind it)
  on a spring coil; the fixed leg carries the coil, the other leg is revolute about
  the coil's axis, 0 = jaws closed, opening until the handles meet (0.15-0.35 rad).
  Pegs are wooden (label ``leg``) or plastic (``jaw``); bag clips plastic.
Sizes (metres): binder clips 0.015-0.051 wide (19, 25, 32, 41, 51 mm stock sizes),
mouth 0.45-0.6 of the width deep, spine 0.3-0.5 of it, levers 0.75-1.0 of it long;
clothes pegs 0.065-0.08 long, legs 8-11 mm wide and 4.5-6 mm thick; bag clips
0.07-0.15 long, 12-25 mm wide, legs 4.5-7 mm thick. Spring clips lie on a side face (pivot axis z);
binder clips stand on their spine (and folded levers).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.clips import COIL_CLEAR, FACE_GAP, LEG_SHAPES, LEVERS, binder_body, coil, curl_x, spring_leg

# spring clips: length, jaw fraction, width (z), leg thickness, handle taper (rad)
SPRING = {
    "clothes_peg": ((0.065, 0.08), (0.36, 0.45), (0.008, 0.011), (0.0045, 0.006), (0.07, 0.12)),
    "bag_clip": ((0.07, 0.15), (0.58, 0.72), (0.012, 0.025), (0.0045, 0.007), (0.08, 0.14)),
}
LEVER_GAP = 0.0004  # a folded lever's grip bar off its side plate


def binder(ctx):
    p = ctx.p
    W = p.uniform("width", 0.015, 0.051)
    H, s = p.uniform("depth", 0.45, 0.6) * W, p.uniform("spine", 0.3, 0.5) * W
    t = p.uniform("sheet", 0.011, 0.013) * W
    r = p.uniform("wire", max(0.018 * W, 0.0005), max(0.022 * W, 0.0006))  # wire radius
    root = ctx.builder.create_link("body")
    root.add(binder_body(p, W, s, H, t, r))
    xc = curl_x(t, r)
    alpha = math.atan2(s / 2 - t, H)  # the side plates' lean from vertical
    reach = p.uniform("lever_length", 0.75, 1.0) * W
    gap = (xc - t) * math.cos(alpha) - r  # a folded lever's bar off the plate, untilted
    tilt = math.asin(max(0.0, (LEVER_GAP - gap) / reach))
    # a lever longer than the side plate rests with its grip bar on the floor, beside
    # the spine (the clip stands on both: a bar alone is a line contact that rocks)
    down = math.acos(min(1.0, (H - r) / reach))
    rest = math.pi - max(alpha + tilt, down)
    insert = p.uniform("insert", 0.08, 0.15) * W
    kind = ctx.choose("lever", LEVERS)
    for side in (1.0, -1.0):
        link = ctx.builder.create_link("lever", root)
        link.set_joint("revolute", translation(side * xc, 0.0, H) @ rot_y(side * rest), axis=(0.0, -side, 0.0),
                       limits=(0.0, rest))
        q = p.scope("lever_p" if side > 0 else "lever_n")
        link.add(kind(q, r, W / 2 + q.uniform("end_gap", 0.0015, 0.002), reach, insert, -side))


def spring_clip(ctx):
    p = ctx.p
    lr, fr, wr, tr, kr = SPRING[ctx.sub]
    L, w, T = p.uniform("length", *lr), p.uniform("width", *wr), p.uniform("thickness", *tr)
    jaw = p.uniform("jaw_fraction", *fr) * L
    taper = p.uniform("taper", *kr)
    rs = p.uniform("coil_radius", 0.18, 0.26) * T
    end = p.uniform("end_thickness", 0.6, 0.85) * T
    semantic = "leg" if ctx.sub == "clothes_peg" and p.flag("wooden", 0.65) else "jaw"
    kind = ctx.choose("leg", LEG_SHAPES)
    notch = rs + COIL_CLEAR + FACE_GAP  # centred on the pivot before the leg moves off it
    root = ctx.builder.create_link("fixed_leg")
    groove = p.uniform("groove", 0.25, 0.4) * T if ctx.sub == "clothes_peg" else 0.0
    root.add(spring_leg(kind, semantic, -1.0, jaw, L - jaw, w, T, taper, notch, end, groove, False))
    root.add(coil(rs, w))
    # the upper leg turns until its handle's inner face meets the lower one's
    k = math.tan(taper)
    meet = math.asin(k / math.sqrt(1.0 + k * k)) + math.atan(k)
    link = ctx.builder.create_link("moving_leg", root)
    link.set_joint("revolute", translation(), axis=(0.0, 0.0, -1.0), limits=(0.0, p.uniform("open", 0.55, 0.75) * meet))
    link.add(spring_leg(kind, semantic, 1.0, jaw, L - jaw, w, T, taper, notch, end, groove, True))


def clip(ctx):
    return (binder if ctx.sub == "binder_clip" else spring_clip)(ctx)


RULE = Category(
    name="clip",
    subcategories={"binder_clip": 2.0, "bag_clip": 1.0, "clothes_peg": 1.5},
    mass_range=(0.0005, 0.06),  # kg: a 15 mm binder clip (~1 g) to a large bag clip or 51 mm binder clip
    materials={"body": "steel", "lever": "steel", "jaw": "plastic", "hinge": "steel"},
    slots=(Slot("clip", clip),),
)
