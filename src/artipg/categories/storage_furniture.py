"""Storage furniture: cabinets, dressers, wardrobes, sideboards and nightstands.

Parts: an optional support (legs, plinth or feet) under an open-front carcass whose
front is split into columns and rows by divider panels; every cell holds a drawer
(prismatic, slides out along -x), one door or a pair of doors (revolute about a
vertical hinge on the outer edges), or stays open with a shelf. Doors and drawers
carry a handle from the shared front-handle set (or none for slot drawers).
Joints: 1-20 movable (drawers and doors), all others fixed.
Sizes (metres): nightstand 0.35-0.6 wide, cabinet 0.4-1.2, dresser 0.6-1.6,
wardrobe 0.8-1.8 wide and 1.7-2.2 tall.
"""

from __future__ import annotations

import math

from artipg.geometry import RectRing, cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass
from artipg.templates.extents import span
from artipg.templates.handles import FRONT_HANDLES, MAX_HALF_WIDTH, knob_pull
from artipg.templates.mounting import free_edge_yz, front_thickness, handle_pose, mount_hinged, mount_sliding
from artipg.templates.panels import DOORS, DRAWERS, shelf_board
from artipg.templates.supports import SUPPORTS

# sub-category -> (width, depth, height) ranges, (columns, rows) ranges, P(drawer cell)
SIZES = {
    "nightstand": ((0.35, 0.6), (0.3, 0.45), (0.45, 0.7), (1, 1), (1, 3), 0.7),
    "cabinet": ((0.4, 1.2), (0.35, 0.6), (0.5, 1.0), (1, 3), (1, 3), 0.3),
    "dresser": ((0.6, 1.6), (0.4, 0.55), (0.7, 1.3), (1, 3), (3, 5), 0.9),
    "wardrobe": ((0.8, 1.8), (0.5, 0.65), (1.7, 2.2), (2, 3), (1, 2), 0.2),
    "sideboard": ((1.2, 2.0), (0.4, 0.5), (0.7, 0.9), (3, 4), (1, 3), 0.5),
}
ONE_HANDLE = {h: {h: 1.0} for h in FRONT_HANDLES}  # every front takes the same handle design


def support(ctx):
    w, d, h, *_ = SIZES[ctx.sub]
    size = (ctx.p.uniform("width", *w), ctx.p.uniform("depth", *d), ctx.p.uniform("height", *h))
    root = ctx.builder.create_link("base")
    if not ctx.p.flag("has_support", 0.75):
        return root, size, 0.0
    tmpl = ctx.choose("template", SUPPORTS)
    sh = ctx.p.uniform("support_height", 0.05, 0.2 if tmpl.__name__.endswith("legs") else 0.1)
    root.add(tmpl(ctx.p, size[1], size[0], sh))
    return root, size, sh


def body(ctx):
    root, (W, D, H), sh = ctx.out["support"]
    part = carcass(ctx.p, D, W, H - sh)
    pose = translation(0, 0, sh + (H - sh) / 2)
    root.add(part, pose)
    return root, part, pose


def _lifted(zb: float, x: float, y: float, z: float):
    """``translation(0, 0, zb) @ translation(x, y, z)`` (4, 4)."""
    return translation(x, y, z + zb)


def _stile(part) -> float:
    """Width of a framed panel's stile (its frame's side band), or inf for a slab:
    a handle on a framed door must sit on the stile, not on the recessed centre."""
    for prim in part.primitives:
        if prim.geom is RectRing:
            ox, oy, depth, ix, iy = prim.params
            return (oy - iy) / 2
    return math.inf


def _split(p, name, start, total, k, lo=0.6, hi=1.4):
    """Boundaries (k + 1 floats) of ``k`` random-width spans tiling [start, start + total]."""
    w = [p.uniform(f"{name}{i}", lo, hi) for i in range(k)]
    s = 0.0  # in order, not with sum(), which compensates (other last bits) since Python 3.12
    for x in w:
        s += x
    out, acc = [start], 0.0
    for x in w:
        acc += x / s * total
        out.append(start + acc)
    return out


def fronts(ctx):
    root, part, pose = ctx.out["body"]
    p = ctx.p
    *_, cols, rows, p_drawer = SIZES[ctx.sub]
    lo, hi = part.anchors["cavity_lo"], part.anchors["cavity_hi"]
    W, H, D = hi[1] - lo[1], hi[2] - lo[2], hi[0] - lo[0]
    wall = float(part.primitives[1].params[1])  # side panel thickness
    front_x = lo[0]
    zb = float(pose[2, 3])  # the carcass is only lifted: fronts are placed by _lifted(zb, ...)
    nc = p.integers("columns", *cols)
    ybs = _split(p, "col_w", lo[1], W, nc)
    gap = p.uniform("gap", 0.002, 0.004)
    hinge_lim = p.uniform("door_limit", 1.5, 2.1)
    handles = FRONT_HANDLES if p.flag("mixed_handles", 0.2) else ONE_HANDLE[ctx.choose("handle", FRONT_HANDLES)]
    k = 0
    for c in range(nc):
        y0, y1 = ybs[c], ybs[c + 1]
        if c:  # vertical divider on the column boundary
            root.add(Part("body", "divider", [cuboid_between((front_x, y0 - wall / 2, lo[2]), (hi[0], y0 + wall / 2, hi[2]))]), pose)
        nr = p.integers(f"rows{c}", *rows)
        zbs = _split(p, f"row_h{c}_", lo[2], H, nr)
        for r in range(nr):
            z0, z1 = zbs[r], zbs[r + 1]
            if r:
                root.add(Part("shelf", "divider", [cuboid_between((front_x, y0 + (wall / 2 if c else 0), z0 - wall / 2), (hi[0], y1 - (wall / 2 if c < nc - 1 else 0), z0 + wall / 2))]), pose)
            # outer rectangle of the cell on the front plane: overlay fronts cover the
            # outer walls and meet their neighbours on the dividers' centre lines
            oy0 = y0 - (wall if c == 0 else 0.0) + gap / 2
            oy1 = y1 + (wall if c == nc - 1 else 0.0) - gap / 2
            oz0 = z0 - (wall if r == 0 else 0.0) + gap / 2
            oz1 = z1 + (wall if r == nr - 1 else 0.0) - gap / 2
            cell = f"cell{k}"  # parameter names are unique per cell, so overrides reproduce
            q = p.scope(cell)
            k += 1
            size = (oy1 - oy0, oz1 - oz0)
            centre = ((oy0 + oy1) / 2, (oz0 + oz1) / 2)
            iy0 = y0 + (wall / 2 if c else 0) + 0.004
            iy1 = y1 - (wall / 2 if c < nc - 1 else 0) - 0.004
            iz0 = z0 + (wall / 2 if r else 0) + 0.003
            iz1 = z1 - (wall / 2 if r < nr - 1 else 0) - 0.003
            if size[1] < 0.45 and q.flag("drawer", p_drawer):
                tmpl = ctx.choose(f"{cell}.drawer_template", DRAWERS)
                opening = (iy0 - centre[0], iy1 - centre[0], iz0 - centre[1], iz1 - centre[1])
                dr = tmpl(q, size[0], size[1], D - 0.01, opening=opening)
                link = mount_sliding(ctx.builder, root, dr, origin=_lifted(zb, front_x, *centre),
                                     limits=(0.0, q.uniform("travel", 0.6, 0.85) * (D - 0.01)), name="drawer")
                if "pull" not in dr.regions:
                    h = ctx.choose(f"{cell}.handle_template", handles)(q.scope("handle"), length=min(0.5 * size[0], 0.35))
                    link.add(h, handle_pose(dr.pose, front_thickness(dr), 0.0, q.uniform("handle_z", 0.0, 0.25) * size[1], True))
                continue
            if size[1] >= 0.45 and q.flag("shelf", 0.6):
                # the shelf spans the cell between its walls and rests against the back
                sy0, sy1 = y0 + (wall / 2 if c else 0.0), y1 - (wall / 2 if c < nc - 1 else 0.0)
                root.add(shelf_board(q, sy1 - sy0, D - 0.005, wall),
                         _lifted(zb, hi[0] - (D - 0.005) / 2, (sy0 + sy1) / 2, (z0 + z1) / 2))
            double = size[0] > 0.55 and q.flag("double", 0.8)
            sides = ("+y", "-y") if double else (q.choice("hinge", ("+y", "-y")),)
            w = size[0] / len(sides) - (gap / 2 if double else 0.0)
            tmpl = ctx.choose(f"{cell}.door_template", DOORS)
            for i, side in enumerate(sides):
                cy = centre[0] + ((w + gap) / 2 * (1 if side == "+y" else -1) if double else 0.0)
                door = tmpl(q.scope(f"door{i}"), w, size[1])
                # a hinge on a divider is shared with the neighbouring front: open only
                # until this door's handle (<= 6 cm proud, <= 7 cm from the free edge)
                # would cross into the neighbour's half-space
                outer = (side == "+y" and c == nc - 1) or (side == "-y" and c == 0)
                lim = hinge_lim if outer else min(hinge_lim, max(0.3, math.atan2(w - 0.07, 0.06)))
                link = mount_hinged(ctx.builder, root, door, front_x=front_x, center_yz=(cy, centre[1]),
                                    size_yz=(w, size[1]), side=side, limits=(0.0, lim), parent_pose=pose)
                hl = min(0.4 * size[1], 0.35)
                ht = ctx.choose(f"{cell}.handle{i}_template", handles)
                m = 0.03 if ht is not knob_pull else 0.04
                h = ht(q.scope(f"handle{i}"), length=hl)
                # no handle overhangs its free edge, where a double door's two handles meet
                # (two ball knobs on stiles narrower than they are would overlap): only a
                # stile narrower than the widest handle needs this handle's bounds
                margin = min(m, _stile(door) / 2)
                if margin < MAX_HALF_WIDTH + 0.0015:
                    ya, yb = span(h.primitives, 1)
                    margin = max(margin, max(abs(ya), abs(yb)) + 0.0015)
                hy, hz = free_edge_yz(side, (w, size[1]), margin)
                link.add(h, handle_pose(door.pose, front_thickness(door), hy, hz, False))


RULE = Category(
    name="storage_furniture",
    subcategories={"cabinet": 3.0, "dresser": 2.0, "wardrobe": 1.0, "sideboard": 1.0, "nightstand": 1.0},
    mass_range=(5.0, 200.0),  # kg: nightstands to wardrobes
    slots=(Slot("support", support), Slot("body", body, after=("support",)), Slot("fronts", fronts, after=("body",))),
)
