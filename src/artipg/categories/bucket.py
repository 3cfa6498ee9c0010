"""Buckets and pails: cylindrical, tapered and polygonal vessels with a swinging bail.

Parts: an open vessel body (cylindrical, tapered or n-gon prism shell); two ear lugs on
the outer wall a little below the rim; a bail handle (round, square-topped or with a
grip sleeve) pivoting on the lugs about the y axis (revolute): at rest it lies folded
down to the back (+x), and it swings up over the top and down to the front, some
180-200 degrees in all; its legs are tall enough that it clears the rim and any lid.
An optional lid (flat, domed, knobbed or bridge-handled; round or polygonal to match
the rim) lifts straight off (prismatic) or flips open on a hinge at the back (revolute).
Sub-categories: cylindrical_bucket, tapered_bucket, prism_bucket, paint_pail (small
cylindrical pail with a lid). Sizes (metres): 0.15-0.4 tall, rim radius 0.1-0.2.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.bodies import cylindrical_shell, prism_shell, tapered_shell
from artipg.templates.levers import BAILS, CLEARANCE, ear_lugs
from artipg.templates.lids import LIDS, mount_lid

# sub-category -> body template, height range, rim radius range, P(lid)
SUBS = {
    "cylindrical_bucket": (cylindrical_shell, (0.2, 0.4), (0.1, 0.2), 0.3),
    "tapered_bucket": (tapered_shell, (0.18, 0.4), (0.11, 0.2), 0.3),
    "prism_bucket": (prism_shell, (0.18, 0.38), (0.11, 0.2), 0.3),
    "paint_pail": (cylindrical_shell, (0.15, 0.24), (0.1, 0.14), 0.9),
}
ONLY = {t: {t: 1.0} for t in (cylindrical_shell, tapered_shell, prism_shell)}  # one body each, still recorded


def body(ctx):
    p = ctx.p
    tmpl, hr, rr, _ = SUBS[ctx.sub]
    H, R = p.uniform("height", *hr), p.uniform("rim_radius", *rr)
    root = ctx.builder.create_link("base")
    kw = {}
    if tmpl is tapered_shell:
        kw["taper"] = p.uniform("taper", 0.08, 0.25)
    elif tmpl is prism_shell:
        kw["sides"] = p.integers("sides", 4, 8)
    part = root.add(ctx.choose("body", ONLY[tmpl])(p.scope("shell"), R, H, **kw))
    taper = kw.get("taper", 0.0) * R
    n = kw.get("sides")

    def wall_y(z):  # distance from the axis to the outer wall along +y at height z
        if n is None:
            return R - taper * (1.0 - z / H)
        # prism_shell face normals point at angles 2 pi k / n
        return R * math.cos(math.pi / n) / max(math.cos(math.pi / 2 - 2 * math.pi * k / n) for k in range(n))

    return root, part, H, R, n, wall_y


def lid(ctx):
    root, part, H, R, n, _ = ctx.out["body"]
    p = ctx.p
    if not p.flag("has_lid", SUBS[ctx.sub][3]):
        return None
    lp = ctx.choose("template", LIDS)(p, R, sides=n)
    flip = p.flag("flip", 0.3)
    mount_lid(ctx.builder, root, lp, translation(0, 0, H), mode="flip" if flip else "lift",
              limit=p.uniform("open_angle", 1.6, 2.0) if flip else p.uniform("lift", 0.1, 0.25))
    return lp


def bail(ctx):
    root, part, H, R, n, wall_y = ctx.out["body"]
    lp = ctx.out["lid"]
    p = ctx.p
    rl = p.uniform("lug_radius", 0.006, 0.012)
    skirt = 0.0 if lp is None else -lp.anchor("hinge")[2]  # the lugs stay below a lid's skirt
    drop = p.uniform("ear_drop", max(0.02, skirt + rl + 0.003), 0.05 + skirt)
    zp = H - drop
    # obstacle above the pivot plane: the rim (R is the circumradius for prisms) and the
    # lid (at most 8 mm overhang), as a cylinder
    reach = R if lp is None else R + 0.008
    rise = drop if lp is None else drop + lp.anchor("top")[2]
    span = reach + p.uniform("lug_reach", 0.012, 0.025)
    handle = ctx.choose("template", BAILS)(p, span, clear=(reach, rise))
    ear = ear_lugs(p.scope("ears"), wall_y(zp), handle.anchor("pin_+y")[1], radius=rl)
    root.add(ear, translation(0, 0, zp))
    # rest: folded down to the back, a little past horizontal if the body allows it
    top, inner = handle.anchor("apex")[2], handle.anchor("apex_inner")[2]
    fold = math.pi / 2 + min(p.uniform("droop", 0.0, 0.25), math.asin(min(1.0, zp / top)),
                             math.acos(min(1.0, (R + CLEARANCE) / inner)))
    link = ctx.builder.create_link("handle", root)
    link.set_joint("revolute", translation(0, 0, zp) @ rot_y(fold), axis=(0.0, -1.0, 0.0), limits=(0.0, 2 * fold))
    link.add(handle)


RULE = Category(
    name="bucket",
    subcategories={"cylindrical_bucket": 3.0, "tapered_bucket": 3.0, "prism_bucket": 1.5, "paint_pail": 1.0},
    materials={"body": "plastic"},
    mass_range=(0.2, 4.0),  # kg: plastic pails to steel paint buckets with lids
    slots=(Slot("body", body), Slot("lid", lid, after=("body",)), Slot("bail", bail, after=("body", "lid"))),
)
