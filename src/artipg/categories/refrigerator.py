"""Refrigerators: top freezer, bottom freezer, side-by-side, French door and single door.

Parts: an insulated carcass (walls 4-6 cm) on a recessed plinth, split into a fridge
and a freezer compartment by a horizontal or vertical mullion, with glass shelves;
thick doors (slab, framed panel-ready, or glass on beverage fridges) carrying 1-4
door bins on their inner face (solid doors) and a long vertical handle near the free edge; freezer
drawers with horizontal handles; hinge covers on the top; on side-by-side and French
door models an optional water dispenser (a recess on a door with a push paddle).
Joints: doors revolute about vertical hinges on their outer edges (1.6-2.1 rad; French
and side-by-side doors open away from each other), freezer drawers prismatic along -x
(0.6-0.85 of their depth), the dispenser paddle revolute about a horizontal axis.
1-5 movable joints. Sizes (metres): 0.48-0.92 wide, 0.55-0.8 deep, 0.82-1.9 tall.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass
from artipg.templates.cells import add_door, add_drawer
from artipg.templates.handles import arch_handle, bar_handle, edge_pull, flat_bar_handle
from artipg.templates.panels import box_drawer, framed_door, glass_door, slab_door
from artipg.templates.racks import door_bins
from artipg.templates.supports import plinth

# sub-category -> width, height, depth ranges, freezer share of height (or width), layout
SUBS = {  # widths, heights and depths widened to the development split's wide, low fridges
    "top_freezer": ((0.55, 0.84), (1.25, 1.8), (0.55, 0.75), (0.25, 0.33), "top"),
    "bottom_freezer": ((0.6, 0.84), (1.5, 1.9), (0.58, 0.75), (0.28, 0.36), "bottom"),
    "side_by_side": ((0.84, 1.0), (1.45, 1.85), (0.6, 0.8), (0.38, 0.45), "side"),
    "french_door": ((0.75, 1.0), (1.45, 1.9), (0.6, 0.8), (0.28, 0.36), "french"),
    "single_door": ((0.45, 0.6), (0.5, 1.5), (0.45, 0.65), (0.0, 0.0), "single"),
}
HANDLES = {bar_handle: 2.0, flat_bar_handle: 2.0, arch_handle: 1.5, edge_pull: 1.0}
DOORS = {slab_door: 3.0, framed_door: 1.0}
BEVERAGE_DOORS = {slab_door: 3.0, framed_door: 1.0, glass_door: 1.5}
GAP = 0.004


def body(ctx):
    p = ctx.p
    w, h, d, f, layout = SUBS[ctx.sub]
    W, H, D = p.uniform("width", *w), p.uniform("height", *h), p.uniform("depth", *d)
    zp = p.uniform("plinth", 0.02, 0.06)
    root = ctx.builder.create_link("base")
    root.add(plinth(p.scope("plinth"), D, W, zp))
    wall = p.uniform("wall", 0.04, 0.06)
    root.add(carcass(p, D, W, H - zp, wall=wall, back=p.uniform("back", 0.04, 0.07)), translation(0, 0, (H + zp) / 2))
    x0, x1, ci = -D / 2, D / 2 - 0.05, (-W / 2 + wall, W / 2 - wall, zp + wall, H - wall)
    share = p.uniform("freezer", *f)
    if layout in ("top", "bottom", "french"):
        zs = zp + (H - zp) * (1 - share if layout == "top" else share)
        root.add(Part("body", "mullion", [cuboid_between((x0, ci[0], zs - wall / 2), (x1, ci[1], zs + wall / 2))]))
        lower, upper = (*ci[:3], zs - wall / 2), (*ci[:2], zs + wall / 2, ci[3])
        comps = [(lower, (zp, zs)), (upper, (zs, H))]
    elif layout == "side":
        ys = W / 2 - W * share
        root.add(Part("body", "mullion", [cuboid_between((x0, ys - wall / 2, ci[2]), (x1, ys + wall / 2, ci[3]))]))
        comps = [((ci[0], ys - wall / 2, *ci[2:]), (zp, H)), ((ys + wall / 2, *ci[1:]), (zp, H))]
    else:
        comps = [(ci, (zp, H))]
    return root, (W, H, D, zp, wall, layout), comps


def _shelves(p, root, D, inner, depth, bins):
    """1-4 glass shelves across a compartment, behind the door bins' reach."""
    y0, y1, z0, z1 = inner
    n = p.integers("count", 1, max(1, min(4, int((z1 - z0) / 0.28))))
    for i in range(n):
        z = z0 + (z1 - z0) * (i + 1) / (n + 1)
        glass = cuboid_between((-D / 2 + bins + 0.02, y0, z), (depth, y1, z + 0.006), role="glass")
        root.add(Part("shelf", "glass_shelf", [glass]))


def _door(ctx, root, q, outer, side, inner, obstacle, dims, tmpl, handle, limit):
    """A door on ``outer`` with bins inside; ``obstacle``: distance from its hinge to the
    nearest thing across its free edge (mullion, other door, far wall). A bin corner at
    distance R from the hinge swings through |y| <= R, so the bins end where R reaches it."""
    D, t, b = dims
    link = add_door(ctx, root, q, front_x=-D / 2, outer=outer, side=side, limits=(0.0, limit), template=tmpl,
                    handle=handle, thickness=t, handle_length=min(0.8, 0.45 * (outer[3] - outer[2])),
                    margin=q.uniform("handle_margin", 0.04, 0.07))
    door = link.link.parts[0]
    cy, cz = (outer[0] + outer[1]) / 2, (outer[2] + outer[3]) / 2
    hy = outer[1] if side == "+y" else outer[0]
    reach = math.sqrt(max(0.0, (obstacle - 0.006) ** 2 - (t + b) ** 2))
    ya, yb = sorted((hy - math.copysign(reach, hy - cy), inner[1] - 0.01 if side == "+y" else inner[0] + 0.01))
    ya, yb = max(ya, inner[0] + 0.01), min(yb, inner[1] - 0.01)
    if yb - ya > 0.1 and inner[3] - inner[2] > 0.2 and door.template != "glass_door":  # no bins on glass doors
        n = q.integers("bins", 1, max(1, min(4, int((inner[3] - inner[2]) / 0.3))))
        bins = door_bins(q.scope("bins"), ya - cy, yb - cy, inner[2] + 0.01 - cz, inner[3] - 0.01 - cz, b, n)
        link.add(bins, door.pose)
    return link, door


def _drawers(ctx, root, q, inner, z0, z1, W, D, t, handle):
    """1-2 stacked freezer drawers over the compartment's front (z0..z1)."""
    n = q.integers("drawers", 1, 2 if z1 - z0 > 0.5 else 1)
    zb = [z0 + (z1 - z0) * i / n for i in range(n + 1)]
    for i in range(n):
        oz = (zb[i] + (GAP / 2 if i else 0), zb[i + 1] - GAP / 2)
        iz = (max(inner[2], oz[0]) + 0.005, min(inner[3], oz[1]) - 0.005)
        add_drawer(ctx, root, q.scope(f"drawer{i}"), front_x=-D / 2, outer=(-W / 2, W / 2, *oz),
                   inner=(*inner[:2], *iz), depth=D - 0.12, template=box_drawer, handle=handle, handle_z=0.35,
                   thickness=t)


def fronts(ctx):
    root, (W, H, D, zp, wall, layout), comps = ctx.out["body"]
    p = ctx.p
    t, b = p.uniform("door_thickness", 0.045, 0.07), p.uniform("bin_depth", 0.07, 0.12)
    tmpl = ctx.choose("door", BEVERAGE_DOORS if layout == "single" else DOORS)
    handle = ctx.choose("handle", HANDLES)
    limit = p.uniform("door_limit", 1.6, 2.1)
    hinge = p.choice("hinge", ("+y", "-y"))
    wn = min(W / 2 - comps[-1][0][0], comps[0][0][1] + W / 2) if layout == "side" else W / 2
    gc = max(GAP, math.hypot(wn, t) - wn + 0.002)  # the free corner of a door swings past its edge
    plan = []  # (recorder, outer, hinge side, obstacle distance, compartment)
    for k, (inner, (z0, z1)) in enumerate(comps):
        q = p.scope(f"c{k}")
        if layout in ("bottom", "french") and k == 0:
            _drawers(ctx, root, q, inner, z0, z1, W, D, t, handle)
            continue
        zs = (z0 + (GAP / 2 if k else 0), z1 - (GAP / 2 if k < len(comps) - 1 else 0))
        if layout == "side":  # right (-y) fridge door, left (+y) freezer door, split at the mullion
            ys = inner[1] + wall / 2 if k == 0 else inner[0] - wall / 2
            outer = (-W / 2, ys - gc / 2, *zs) if k == 0 else (ys + gc / 2, W / 2, *zs)
            face = inner[1] - outer[0] if k == 0 else outer[1] - inner[0]
            plan.append((q, outer, "-y" if k == 0 else "+y", face, inner))
        elif layout == "french" and k == 1:
            plan += [(q.scope("door0"), (-W / 2, -gc / 2, *zs), "-y", W / 2 + gc / 2, inner),
                     (q.scope("door1"), (gc / 2, W / 2, *zs), "+y", W / 2 + gc / 2, inner)]
        else:
            plan.append((q, (-W / 2, W / 2, *zs), hinge, W - wall, inner))
        _shelves(q.scope("shelves"), root, D, inner, D / 2 - 0.05, b)
    doors = [_door(ctx, root, q, outer, side, inner, obst, (D, t, b), tmpl, handle, limit)
             for q, outer, side, obst, inner in plan]
    for side in sorted({s for _, _, s, _, _ in plan}):  # hinge covers on the top
        y = W / 2 - 0.05 if side == "+y" else -W / 2
        cover = cuboid_between((-D / 2 - t, y, H), (-D / 2 + 0.05, y + 0.05, H + 0.012))
        root.add(Part("hinge", "hinge_cover", [cover]))
    if layout in ("side", "french") and p.flag("dispenser", 0.6):
        _dispenser(ctx, p.scope("dispenser"), *doors[-1], t)


def _dispenser(ctx, q, link, door, t):
    """Recessed dispenser panel with a push paddle (revolute about -y) on ``door``."""
    w = 2 * door.anchors["edge_+y"][1]
    pw = min(q.uniform("width", 0.16, 0.22), w - 0.2)
    ph, pt, d = q.uniform("height", 0.22, 0.32), 0.012, q.uniform("reach", 0.03, 0.05)
    z = q.uniform("z", 1.0, 1.2) - link.link.joint.origin[2, 3] - door.pose[2, 3]
    P = door.pose
    recess = cuboid_between((-t - pt, -pw / 2, z - ph), (-0.002, pw / 2, z), role="panel")
    hood = cuboid_between((-t - pt - d - 0.012, -pw / 4, z - 0.04), (-t - pt, pw / 4, z))
    link.add(Part("panel", "dispenser", [recess, hood]), P)
    L = q.uniform("paddle", 0.08, 0.12)
    pad = ctx.builder.create_link("lever", link)  # the paddle's lower end swings in, short of the panel
    pad.set_joint("revolute", P @ translation(-t - pt - d, 0, z - 0.04), axis=(0, -1, 0),
                  limits=(0.0, math.asin((d - 0.006) / L)))
    pad.add(Part("lever", "paddle", [cuboid_between((-0.01, -pw / 5, -L), (0.0, pw / 5, 0.0), role="paddle")],
                 regions={"push": Region(("paddle",))}))


RULE = Category(
    name="refrigerator",
    subcategories={"top_freezer": 2.0, "bottom_freezer": 2.0, "side_by_side": 2.0, "french_door": 2.0,
                   "single_door": 1.0},
    materials={"body": "insulated", "door": "insulated", "drawer": "insulated", "shelf": "glass",
               "base": "shell"},
    mass_range=(30.0, 160.0),  # kg: single-door (~40 kg) to side-by-side (~130 kg)
    slots=(Slot("body", body), Slot("fronts", fronts, after=("body",))),
)
