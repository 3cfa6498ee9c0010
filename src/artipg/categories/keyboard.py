"""Computer keyboards lying on a desk: full-size (104 keys), tenkeyless (87) and compact
60 % boards (61), ANSI layouts with a standard or a Tsangan bottom row.

Parts: a case (a base slab on four pads, a rim around the key field and ribs filling
the gaps between key clusters: under the function row, beside the navigation cluster
and the numeric pad); one keycap per key, sized from its layout cell (1-7 units) less
the key gap; two fold-out feet under the back edge.
Joints: every key prismatic down (-z), 3-4 mm travel (1.5-2.5 mm on low-profile
boards); feet revolute about y, folding down 80-100 degrees from flat under the case.
Sizes (metres): key unit 18.5-19.5 mm, gaps 1.2-1.8 mm; full-size boards
0.43-0.47 x 0.14-0.17, tenkeyless 0.36-0.39 wide, compact 0.3-0.33 x 0.1-0.13;
18-35 mm tall over the keys.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.keyboard import GAP, MODS, ansi_layout, cell_boxes, fold_foot, keyboard_case, keycap

# sub-category -> (function row, navigation cluster, numeric pad)
SUBS = {"full_size": (True, True, True), "tenkeyless": (True, True, False), "compact": (False, False, False)}
BOTTOMS = tuple(MODS)


def case(ctx):
    p, b = ctx.p, ctx.builder
    cells, w_u, h_u = ansi_layout(*SUBS[ctx.sub], bottom=p.choice("bottom_row", BOTTOMS))
    u, g = p.uniform("unit", 0.0185, 0.0195), p.uniform("key_gap", 0.0012, 0.0018)
    keys, ribs = cell_boxes(cells, u, g, (w_u, h_u))
    low = p.flag("low_profile", 0.3)
    travel = p.uniform("travel", 0.0015, 0.0025) if low else p.uniform("travel", 0.003, 0.004)
    cap_h = p.uniform("cap_height", 0.003, 0.005) if low else p.uniform("cap_height", 0.006, 0.009)
    pad, slab = p.uniform("pad_height", 0.003, 0.005), p.uniform("slab", 0.004, 0.012)
    z0 = pad + slab
    zc = z0 + travel + p.uniform("clearance", 0.0005, 0.001)  # caps' bottoms at rest
    z1 = zc + p.uniform("rim_rise", 0.2, 0.6) * cap_h
    root = b.create_link("case")
    body = root.add(keyboard_case(p, (h_u * u, w_u * u), g, ribs, (z0, z1), pad))
    # one cap Part per key (parts are not shared between links); sizes repeat, geometry is cheap
    for x, y, sx, sy in keys.tolist():
        link = b.create_link("key", root)
        link.set_joint("prismatic", translation(x, y, zc), axis=(0.0, 0.0, -1.0), limits=(0.0, travel))
        link.add(keycap(sx, sy, cap_h))
    return root, body, pad


def feet(ctx):
    root, body, pad = ctx.out["case"]
    p = ctx.p
    X, Y, cx = body.anchors["size"]
    t = min(p.uniform("foot_thickness", 0.0015, 0.0025), pad - 2 * GAP)
    length, width = p.uniform("foot_length", 0.025, 0.04), p.uniform("foot_width", 0.02, 0.05)
    xh = cx + X / 2 - p.uniform("hinge_inset", 0.006, 0.012)
    ys = Y / 2 - p.uniform("foot_inset", 0.06, 0.1)
    limit = p.uniform("fold", 1.4, 1.75)
    for y in (-ys, ys):
        link = ctx.builder.create_link("foot", root)
        link.set_joint("revolute", translation(xh, y, pad - GAP - t / 2), axis=(0.0, -1.0, 0.0), limits=(0.0, limit))
        link.add(fold_foot(p.scope(f"foot{int(y > 0)}"), length, width, t))


RULE = Category(
    name="keyboard",
    subcategories={"full_size": 3.0, "tenkeyless": 2.0, "compact": 1.5},
    materials={"body": "plastic", "button": "plastic", "leg": "plastic"},
    mass_range=(0.2, 2.0),  # kg: compact boards ~0.4 kg to full-size steel-plate boards ~1.3 kg
    slots=(Slot("case", case), Slot("feet", feet, after=("case",))),
)
