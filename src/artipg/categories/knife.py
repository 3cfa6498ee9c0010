"""Folding knives: single-blade folders, pocket knives and penknives.

Parts: a handle of two scales (round at the pivot end) with a back spacer between
them; one to three steel blades (drop point, sheepsfoot or spey; a pocket knife's
second and third blades shorter) in layers between the scales; a pivot pin with a
head through the scales and the blades' round tangs.
Joints: each blade revolute about the pin (z), 0 = folded into the handle, pi = open
straight out.
Sizes (metres): folders 0.09-0.13 handles, blades 0.8-0.95 of it; pocket knives
0.08-0.1 with 2-3 blades; penknives 0.055-0.075 with 1-2 blades; handles 0.018-0.03
wide, 9-20 mm thick.
Frame: the handle along -x from the pivot, blades open to +x.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.folding_blades import BLADES, PIN_CLEAR, blade, pin, scales

# sub-category -> handle length, handle width, blade counts (min, max), blade thickness
SUBS = {
    "folder": ((0.09, 0.13), (0.022, 0.03), (1, 1), (0.0025, 0.0035)),
    "pocket": ((0.08, 0.1), (0.02, 0.026), (2, 3), (0.0015, 0.0022)),
    "penknife": ((0.055, 0.075), (0.016, 0.02), (1, 2), (0.0012, 0.0018)),
}
GAP = 0.0005  # between blades and scales


def knife(ctx):
    p = ctx.p
    lr, wr, nr, tr = SUBS[ctx.sub]
    L, w, t = p.uniform("handle_length", *lr), p.uniform("handle_width", *wr), p.uniform("blade_thickness", *tr)
    n = p.integers("blades", nr[0], nr[1] + 1)
    ts = p.uniform("scale_thickness", 0.002, 0.004)
    inner = n * t + (n + 1) * GAP
    back = p.uniform("spacer", 0.15, 0.25) * w
    rp = p.uniform("pin_radius", 0.0015, 0.0022)
    r = w / 2
    spine = r - back - 0.0015
    root = ctx.builder.create_link("handle")
    root.add(scales(L, w, ts, inner, back))
    top = 2 * ts + inner
    root.add(pin(rp, top, rp + p.uniform("head", 0.001, 0.002), p.uniform("head_height", 0.0005, 0.001)))
    for k in range(n):
        q = p.scope(f"blade{k}")
        kind = ctx.choose(f"blade{k}", BLADES)
        bl = q.uniform("length", 0.8, 0.95) * L if k == 0 else q.uniform("length", 0.45, 0.7) * L
        wb = min(q.uniform("width", 0.6, 0.85) * w, spine + r - 0.001)
        link = ctx.builder.create_link(f"blade{k}", root)
        link.set_joint("revolute", translation(), axis=(0.0, 0.0, 1.0), limits=(0.0, math.pi))
        z0 = ts + GAP + k * (t + GAP)
        link.add(blade(kind, bl, wb, spine, t, z0, rp + PIN_CLEAR, min(r, 0.45 * w)))


RULE = Category(
    name="knife",
    subcategories={"folder": 2.0, "pocket": 2.0, "penknife": 1.0},
    mass_range=(0.01, 0.3),  # kg: penknives to large folders
    materials={"blade": "steel", "handle": "plastic", "hinge": "steel"},
    slots=(Slot("knife", knife),),
)
