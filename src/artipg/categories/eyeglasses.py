"""Eyeglasses: round, rectangular and reading glasses, and sunglasses.

Parts: a frame front (full rims, half rims over the top of the lenses, or rimless
lenses held by the bridge and endpieces; straight or arched bridge; optional nose
pads) holding two lenses, and two temples (flat bars, tall paddles or metal wires
curling over the ear) on barrel hinges behind the endpieces.
Joints: two revolute temple hinges about vertical axes; 0 is open (as worn, spread
outwards by 0-11 degrees) and the upper limit folds the temple flat behind the front. The left temple folds
closer to the lenses and the right one stacks on it, as on real glasses; temples end
short of the opposite hinge so either folds with the other one open.
Sizes (metres): front 0.12-0.17 wide, lenses 0.042-0.062 wide, temples 0.085-0.15 long.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.eyewear import FRONTS, TEMPLE_SIZES, TEMPLES, full_rim_front, half_rim_front, lens, rimless_front

# sub-category -> lens shape, lens width, lens height (None: round), bridge, front and temple weights
SUBS = {
    "round": ("round", (0.042, 0.05), None, (0.017, 0.022), FRONTS, {t: w for t, w in TEMPLES.items() if w > 1}),
    "rectangular": ("rect", (0.045, 0.056), (0.026, 0.045), (0.015, 0.021), FRONTS, TEMPLES),
    "sunglasses": ("rect", (0.05, 0.062), (0.038, 0.056), (0.014, 0.02), {full_rim_front: 1.0}, TEMPLES),
    "reading": ("rect", (0.042, 0.05), (0.022, 0.034), (0.016, 0.022),
                {half_rim_front: 2.0, rimless_front: 2.0, full_rim_front: 1.0}, TEMPLES),
}
GAP = 0.0012  # clearance between the front, the knuckles and the two folded temples


def front(ctx):
    p = ctx.p
    shape, wr, hr, br, fronts, temples = SUBS[ctx.sub]
    w = p.uniform("lens_width", *wr)
    h = w if hr is None else p.uniform("lens_height", *hr)
    tmpl = ctx.choose("temple", temples)
    hr_, tr_ = TEMPLE_SIZES[tmpl]
    th, tt = p.uniform("temple_height", *hr_), p.uniform("temple_thickness", *tr_)
    rk = p.uniform("knuckle_radius", 0.0016, 0.0026)
    root = ctx.builder.create_link("frame")
    part = root.add(ctx.choose("front", fronts)(p, shape, w, h, p.uniform("bridge", *br), (th, tt), rk, GAP))
    lt = p.uniform("lens_thickness", 0.0015, 0.0025)
    for s in ("+y", "-y"):
        root.add(lens(p.scope(f"lens{s}"), shape, w, h, thickness=lt), translation(*part.anchor(f"lens_{s}")))
    return root, part, tmpl, th, tt, rk


def temples(ctx):
    root, part, tmpl, th, tt, rk = ctx.out["front"]
    p = ctx.p
    xh, yh, zh = part.anchor("hinge_+y")
    fold = float(part.anchor("fold")[0])
    offset = fold + tt / 2 - xh  # inner temple folds onto x = fold, the outer one tt + gap further back
    # end short of the other temple's hinge, so either one folds while the other is open
    # (the development split's temples reach 0.64-0.88 of the front's width)
    reach = min(2 * yh - max(rk, tt + GAP / 2) - 0.002, p.uniform("length", 0.085, 0.15))
    # open temples spread outwards a little, as worn; folding still ends flat behind the front
    splay = p.uniform("splay", 0.0, 0.2)
    for s, axis in ((1.0, (0.0, 0.0, -1.0)), (-1.0, (0.0, 0.0, 1.0))):
        link = ctx.builder.create_link("temple", root)
        link.set_joint("revolute", translation(xh, s * yh, zh) @ rot_z(s * splay), axis=axis,
                       limits=(0.0, math.pi / 2 + splay))
        link.add(tmpl(p.scope("left" if s > 0 else "right"), reach, th, tt, offset, rk))


RULE = Category(
    name="eyeglasses",
    subcategories={"rectangular": 3.0, "round": 2.0, "sunglasses": 2.0, "reading": 1.5},
    materials={"frame": "plastic"},
    mass_range=(0.01, 0.1),  # kg: rimless readers to acetate sunglasses
    slots=(Slot("front", front), Slot("temples", temples, after=("front",))),
)
