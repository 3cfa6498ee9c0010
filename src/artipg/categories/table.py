"""Tables: dining, coffee, side tables and desks, with drawers and cabinet doors.

Parts: a top (rectangular, oval, round or polygonal) on a base: four legs (square,
round or tapered) joined by an apron, a pedestal column on a disc / cone / cross foot,
a trestle (two end frames and a stretcher), or two panel ends; coffee and side tables
on legs may have a lower shelf. The apron's front board holds 1-3 drawers. Desks may
instead stand on one or two drawer pedestals (carcasses with 1-3 overlay drawers or a
door each, the other side on a panel end) with an optional centre drawer; side tables
may be nightstands, one such carcass as wide as the top (as several tables of the
PartNet-Mobility development split are).
Joints: drawers prismatic along -x (0.6-0.85 of their depth), pedestal doors revolute
about their outer vertical edge (1.5-2.0 rad); 1-6 movable joints, all others fixed.
Sizes (metres, width along y): dining 0.9-2.2 x 0.75-1.05, 0.72-0.78 tall; coffee
0.8-1.4 x 0.45-0.8, 0.35-0.5 tall; side 0.4-0.65 square, 0.5-0.75 tall; desk
1.0-1.8 x 0.55-0.8, 0.72-0.78 tall.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass
from artipg.templates.cells import add_door, add_drawer
from artipg.templates.extents import span
from artipg.templates.handles import FRONT_HANDLES
from artipg.templates.panels import DOORS, DRAWERS
from artipg.templates.supports import round_legs, square_legs, tapered_legs
from artipg.templates.tables import TOPS, apron, column_base, panel_ends, slab_top, trestle_base

# sub-category -> width (y), depth (x), height ranges, base weights, max apron drawers
SUBS = {
    "dining": ((0.9, 2.2), (0.75, 1.05), (0.72, 0.78), {"legs": 3.0, "pedestal": 1.0, "trestle": 1.5}, 2),
    "coffee": ((0.8, 1.4), (0.45, 0.8), (0.35, 0.5), {"legs": 3.0, "panels": 1.5, "pedestal": 0.5}, 2),
    "desk": ((1.0, 1.8), (0.55, 0.8), (0.72, 0.78), {"legs": 1.5, "pedestals": 3.0, "panels": 1.0}, 3),
    "side": ((0.4, 0.65), (0.4, 0.65), (0.5, 0.75), {"legs": 3.0, "pedestal": 1.0, "cabinet": 2.5}, 1),
}
LEGS = {square_legs: 1.0, round_legs: 1.0, tapered_legs: 1.0}
DESK_TOPS = {slab_top: 1.0}
GAP = 0.003  # between neighbouring fronts


def top(ctx):
    p = ctx.p
    w, d, h, *_ = SUBS[ctx.sub]
    W, D, H = p.uniform("width", *w), p.uniform("depth", *d), p.uniform("height", *h)
    part = ctx.choose("top", DESK_TOPS if ctx.sub == "desk" else TOPS)(p, D, W)
    zu = H - part.anchors["surface"][2]  # the anchor tuples hold floats: no numpy scalars downstream
    root = ctx.builder.create_link("base")
    root.add(part, translation(0, 0, zu))
    ax, ay, _ = part.anchors["apron"]
    return root, zu, ax, ay


def _apron_drawers(ctx, root, zu, ax, ay, y_free, depth, n_max, handle, drawer):
    """Apron under the top with ``n`` drawers side by side in |y| < y_free."""
    p = ctx.p
    ah = p.uniform("apron_height", 0.08, min(0.16, 0.3 * zu))
    n = p.integers("drawers", 1, max(1, min(n_max, int(2 * y_free / 0.35))))
    z0, z1 = -ah + p.uniform("rail", 0.01, 0.02), -p.uniform("top_rail", 0.0, 0.015)
    pitch = 2 * y_free / n
    dw = min(p.uniform("drawer_width", 0.3, 0.6), pitch - 0.04)
    openings = [(-y_free + pitch * (i + 0.5) - dw / 2, -y_free + pitch * (i + 0.5) + dw / 2) for i in range(n)]
    st = pitch - dw  # board left between neighbouring openings
    part = apron(p, 2 * ax, 2 * ay, ah, openings, (z0, z1))
    pose = translation(0, 0, zu)
    root.add(part, pose)
    m = p.uniform("overlay", 0.0, 1.0) * min(0.012, st / 2 - GAP)
    for i, (a, b) in enumerate(openings):
        add_drawer(ctx, root, p.scope(f"drawer{i}"), front_x=-ax, outer=(a - m, b + m, z0 - m, min(z1 + m, -GAP)),
                   inner=(a, b, z0, z1), depth=depth, template=drawer,
                   handle=handle, parent_pose=pose)


def _desk(ctx, root, zu, ax, ay, handle, drawer, full=False):
    """Drawer pedestals under a desk top, or (``full``) one carcass as wide as the top:
    a cabinet side table (nightstand)."""
    p = ctx.p
    if full:
        wp, sides = 2 * ay, (1,)
    else:
        wp = min(p.uniform("pedestal_width", 0.35, 0.45), 0.4 * ay)
        sides = (-1, 1) if p.flag("two_pedestals", 0.5) else (p.choice("pedestal_side", (-1, 1)),)
    kick = p.uniform("kick", 0.03, 0.08)
    door = ctx.choose("door", DOORS)
    k = 0
    for s in sides:
        q = p.scope(f"pedestal{s:+d}")
        body = carcass(q, 2 * ax, wp, zu)
        yc = s * (ay - wp / 2)
        root.add(body, translation(0, yc, zu / 2))
        rows = q.integers("rows", 1, 3)
        hs = np.array([q.uniform(f"row{r}", 0.6, 1.4) for r in range(rows)])
        zb = (kick + np.concatenate([[0.0], np.cumsum(hs / hs.sum())]) * (zu - kick - GAP)).tolist()
        wall = body.primitives[1].params[1]
        iy = (yc - wp / 2 + wall, yc + wp / 2 - wall)
        for r in range(rows):
            outer = (yc - wp / 2 + GAP, yc + wp / 2 - GAP, zb[r] + GAP / 2, zb[r + 1] - GAP / 2)
            if outer[3] - outer[2] > 0.42 and q.flag(f"door{r}", 0.6):
                add_door(ctx, root, q.scope(f"cell{r}"), front_x=-ax, outer=outer, side="+y" if s > 0 else "-y",
                         limits=(0.0, q.uniform(f"limit{r}", 1.5, 2.0)), template=door, handle=handle)
            else:
                inner = (*iy, max(zb[r], wall) + GAP, min(zb[r + 1], zu - wall) - GAP)
                add_drawer(ctx, root, q.scope(f"cell{r}"), front_x=-ax, outer=outer, inner=inner,
                           depth=2 * ax - 0.03, template=drawer, handle=handle)
            k += 1
    if full:
        return
    if len(sides) == 1:  # the other end stands on a panel
        t = p.uniform("panel_thickness", 0.025, 0.05)
        y = -sides[0] * ay
        root.add(Part("leg", "panel_end", [cuboid_between((-ax, min(y, y + sides[0] * t), 0.0),
                                                          (ax, max(y, y + sides[0] * t), zu), role="panel")]))
        y_lo, y_hi = sorted((y + sides[0] * t, sides[0] * (ay - wp)))
    else:
        y_lo, y_hi = -ay + wp, ay - wp
    if k < 6 and y_hi - y_lo > 0.5 and p.flag("centre_drawer", 0.7):
        _centre(ctx, root, zu, ax, (y_hi - y_lo) / 2, (y_lo + y_hi) / 2, handle, drawer)


def _centre(ctx, root, zu, ax, half, yc, handle, drawer):
    p = ctx.p.scope("centre")
    ah = p.uniform("apron_height", 0.07, 0.12)
    st = max(p.uniform("stile", 0.05, 0.15) * half, 0.03, half - p.uniform("drawer_half_width", 0.22, 0.35))
    z0, z1 = -ah + p.uniform("rail", 0.01, 0.02), -p.uniform("top_rail", 0.0, 0.012)
    part = apron(p, 2 * ax, 2 * half, ah, [(-half + st, half - st)], (z0, z1))
    pose = translation(0, yc, zu)
    root.add(part, pose)
    add_drawer(ctx, root, p.scope("drawer"), front_x=-ax,
               outer=(-half + st - 0.01, half - st + 0.01, z0 - 0.005, z1 - GAP),
               inner=(-half + st, half - st, z0, z1), depth=2 * ax - 0.04, template=drawer, handle=handle,
               parent_pose=pose)


def base(ctx):
    root, zu, ax, ay = ctx.out["top"]
    p = ctx.p
    *_, weights, n_max = SUBS[ctx.sub]
    kind = p.choice("base", weights)
    handle = ctx.choose("handle", FRONT_HANDLES)
    drawer = ctx.choose("drawer", DRAWERS)
    if kind in ("pedestals", "cabinet"):
        return _desk(ctx, root, zu, ax, ay, handle, drawer, full=kind == "cabinet")
    board = 0.025  # upper bound of the apron board thickness
    if kind == "legs":
        legs = ctx.choose("legs", LEGS)(p.scope("legs"), 2 * ax, 2 * ay, zu)
        root.add(legs)
        leg = legs.primitives[:1]  # front-left leg
        (x0, x1), (y0, y1) = span(leg, 0), span(leg, 1)
        y_free, depth = -y1 - GAP, 2 * ax - board - GAP
        if ctx.sub in ("coffee", "side") and p.flag("shelf", 0.5):
            cx, cy = -(x0 + x1) / 2, -(y0 + y1) / 2
            zs, ts = p.uniform("shelf_z", 0.08, 0.2), p.uniform("shelf_thickness", 0.015, 0.025)
            rails = [cuboid_between((-cx, s * cy - 0.01, zs - 0.03), (cx, s * cy + 0.01, zs), role="rail")
                     for s in (-1, 1)]
            shelf = cuboid_between((x1, -cy, zs), (-x1, cy, zs + ts), role="board")
            root.add(Part("shelf", "lower_shelf", rails + [shelf]))
    elif kind == "pedestal":
        col = column_base(p.scope("pedestal"), zu, 1.3 * min(ax, ay))
        root.add(col)
        y_free, depth = ay - board - GAP, ax - col.anchors["column"][0] - GAP
    else:
        tmpl = trestle_base if kind == "trestle" else panel_ends
        part = tmpl(p.scope(kind), 2 * ax, 2 * ay, zu)
        root.add(part)
        y_free, depth = part.anchors["inner"][1] - GAP, 2 * ax - 2 * board - GAP
    _apron_drawers(ctx, root, zu, ax, ay, y_free, depth, n_max, handle, drawer)


RULE = Category(
    name="table",
    subcategories={"dining": 3.0, "coffee": 2.0, "desk": 2.0, "side": 2.5},
    mass_range=(3.0, 120.0),  # kg: side tables to solid dining tables
    slots=(Slot("top", top), Slot("base", base, after=("top",))),
)
