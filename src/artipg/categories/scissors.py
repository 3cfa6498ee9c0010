"""Scissors: office, kitchen, children's and pinking shears.

Parts: two halves lying flat, each a steel blade with a boss round the pivot and a
tang out to its handle; handles (plastic round loops, a round thumb loop with a long
finger loop, or bent metal loops) span the full thickness of the pair, side by side
when closed; a pivot screw with a head holds the halves together. Children's
scissors have round tips; pinking shears thick blades with a zigzag edge.
Joint: the upper half turns about the screw (revolute, z), 0 = closed, opening
0.75-1.1 rad (PartNet-Mobility scissors open 0.72-1.26 rad).
Sizes (metres): office 0.15-0.2 long, kitchen 0.18-0.22, children's 0.1-0.13,
pinking 0.18-0.22; blades 1.2-4 mm thick, handles 6-12 mm thick.
Frame: blades point +y, handles -y (as PartNet-Mobility's scissors), the pivot on z.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.cutters import HANDLES, HOLE_CLEAR, blade_half, handle, handle_size, screw

# sub-category -> blade length, blade width at the pivot, blade thickness, tip, shank length, loop scale
SUBS = {
    "office": ((0.085, 0.11), (0.013, 0.017), (0.0015, 0.002), "pointed", (0.03, 0.042), 1.0),
    "kitchen": ((0.1, 0.12), (0.018, 0.024), (0.002, 0.0028), "pointed", (0.035, 0.05), 1.1),
    "children": ((0.056, 0.068), (0.011, 0.014), (0.0012, 0.0016), "round", (0.014, 0.022), 0.85),
    "pinking": ((0.1, 0.12), (0.02, 0.026), (0.003, 0.004), "pinking", (0.035, 0.05), 1.1),
}
GAP = 0.0006  # between the two blades' faces
ALONG_Y = rot_z(math.pi / 2)  # halves are built along x; blades point +y as in PartNet-Mobility


def halves(ctx):
    p = ctx.p
    lr, wr, tr, tip, sr, scale = SUBS[ctx.sub]
    Lb, wb, t = p.uniform("blade_length", *lr), p.uniform("blade_width", *wr), p.uniform("blade_thickness", *tr)
    kind = ctx.choose("handle", HANDLES)
    extra = p.uniform("handle_extra", 0.0008, 0.005) if kind != "metal_loops" else p.uniform("bend", 0.0004, 0.001)
    height = 2 * t + GAP + extra
    rs = p.uniform("screw_radius", 0.0015, 0.0022)
    hole = rs + HOLE_CLEAR
    wb = max(wb, 2 * hole + 0.006)
    root = ctx.builder.create_link("lower_half")
    out = []
    for i, hand in enumerate((1.0, -1.0)):
        q = p.scope("lower" if i == 0 else "upper")
        w, h, wall = (v * scale for v in handle_size(kind, q, finger=i == 1))
        shank = q.uniform("shank", *sr)
        loop = (-(shank + wb / 2 + w / 2), hand * (h / 2 + 0.0008))
        ws_t, ws = 0.7 * wb, 0.9 * wall + 0.004
        start = min(0.85, (ws / 2 + ws_t / 2 + 0.002) / (2 * abs(loop[1])) + 0.05)
        out.append((q, hand, loop, (w, h, wall), start))
    for i, (q, hand, loop, size, start) in enumerate(out):
        link = root
        if i == 1:
            link = ctx.builder.create_link("upper_half", root)
            link.set_joint("revolute", translation(), axis=(0.0, 0.0, 1.0), limits=(0.0, p.uniform("open", 0.75, 1.1)))
        z0 = 0.0 if i == 0 else t + GAP
        # the tang reaches 1.5 mm into the grip sleeve, or into the near wall of a metal loop
        rim = (loop[0] + size[0] / 2 - size[2] / 2, loop[1])
        if kind != "metal_loops":
            f = start + 0.0015 / math.hypot(*rim)
            rim = (f * rim[0], f * rim[1])
        link.add(blade_half(q, hand, tip, Lb, wb, t, z0, hole if i == 1 else 0.0, rim), pose=ALONG_Y, name=f"blade{i}")
        link.add(handle(kind, loop, size, height, start, "hinge_handle" if i == 1 else "none"), ALONG_Y,
                 name=f"handle{i}")
    top = 2 * t + GAP + 0.0008
    root.add(screw(rs, top, rs + p.uniform("head", 0.0015, 0.003), p.uniform("head_height", 0.0008, 0.0015)))


RULE = Category(
    name="scissors",
    subcategories={"office": 3.0, "kitchen": 1.5, "children": 1.5, "pinking": 1.0},
    mass_range=(0.01, 0.35),  # kg: children's scissors to steel pinking shears
    materials={"blade": "steel", "handle": "plastic", "hinge": "steel"},
    slots=(Slot("halves", halves),),
)
