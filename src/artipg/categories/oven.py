"""Ovens: freestanding ranges, single and double wall ovens, countertop (toaster) ovens.

Parts: an open-front carcass split by divider boards into one or two oven cavities
(each with a flat wire rack on side runners) and, on ranges, a storage-drawer bay; a
control strip above the doors (ranges and wall ovens) or a control bay beside the
door (countertop ovens, on feet); ranges stand on a toe-kick plinth and carry a
cooktop (gas burners under a grate, glass-ceramic or coil hobs), an optional
backguard and, behind it, an optional hinged glass lid. Doors (glass window or solid)
have a horizontal handle along the top.
Joints: doors revolute about the horizontal axis (-y) on their bottom front edge,
opening 83-90 degrees down; knobs continuous about their axis (one per burner plus
1-2 oven knobs on ranges, 2-4 elsewhere); push buttons prismatic (wall ovens);
storage drawer prismatic along -x; cooktop lid revolute about +y at its back edge.
Sizes (metres): ranges 0.5-0.9 wide, 0.85-0.93 to the cooktop, 0.6-0.66 deep; wall
ovens 0.56-0.6 wide, 0.58-0.6 tall (double: 0.88-1.05); countertop 0.4-0.55 wide,
0.22-0.34 tall, 0.3-0.42 deep.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import translated, translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.appliance import appliance_housing, control_panel, display
from artipg.templates.bodies import carcass
from artipg.templates.cells import add_door, add_drawer
from artipg.templates.controls import BUTTONS, KNOBS, mount_button_row, mount_knob, mount_poses
from artipg.templates.handles import arch_handle, bar_handle, edge_pull, flat_bar_handle
from artipg.templates.panels import box_drawer, glass_door, slab_door
from artipg.templates.racks import oven_rack
from artipg.templates.stove import COOKTOPS
from artipg.templates.supports import bun_feet, plinth

SUBS = {  # width, height, depth ranges
    "range": ((0.5, 0.9), (0.85, 0.93), (0.6, 0.66)),
    "wall_oven": ((0.56, 0.6), (0.58, 0.6), (0.55, 0.57)),
    "double_oven": ((0.56, 0.76), (0.88, 1.05), (0.55, 0.6)),
    "countertop": ((0.4, 0.55), (0.22, 0.34), (0.3, 0.42)),
}
HANDLES = {bar_handle: 2.0, flat_bar_handle: 2.0, arch_handle: 1.5, edge_pull: 1.0}
DOORS = {glass_door: 3.0, slab_door: 1.0}


def _rise(h, t):
    """Gap a drop-down door of height h and thickness t needs above it (its top back corner rises)."""
    return math.hypot(h, t) - h + 0.002


def _rack(p, root, x0, x1, y0, y1, z):
    """Flat oven rack resting on two side runners at height z."""
    root.add(oven_rack(p, x1 - x0 - 0.03, y1 - y0 - 0.004), translation((x0 + x1) / 2 + 0.01, (y0 + y1) / 2, z))
    runners = [cuboid_between((x0 + 0.02, y, z - 0.008), (x1, y + 0.01, z)) for y in (y0, y1 - 0.01)]
    root.add(Part("body", "runners", runners))


def _countertop(ctx, root, W, H, D):
    """Housing on feet, cavity on the left, control bay (a column of knobs) on the right."""
    p = ctx.p
    zf, bay, gap = p.uniform("feet", 0.01, 0.025), p.uniform("bay", 0.09, 0.14), 0.003
    root.add(bun_feet(p.scope("feet"), 0.9 * D, 0.9 * W, zf))
    hs = appliance_housing(p, D, W, H - zf, bay, "-y")
    root.add(hs, translation(0, 0, (H + zf) / 2))
    lo, hi = hs.anchors["cavity_lo"], hs.anchors["cavity_hi"]
    z = (H + zf) / 2 + 0.3 * (hi[2] - lo[2]) * p.uniform("rack_z", -1, 0)
    _rack(p.scope("rack0"), root, lo[0], hi[0], lo[1], hi[1], z)
    y0 = -W / 2 + bay
    cp = control_panel(p.scope("bay"), bay - gap, H - zf, p.uniform("panel_thickness", 0.008, 0.015))
    pose = translation(-D / 2, y0 - bay / 2 - gap / 2, (H + zf) / 2)
    root.add(cp, pose)
    return {"t": p.uniform("door_thickness", 0.02, 0.03), "doors": [(y0 + gap, W / 2, zf, H)],
            "panel": ("column", translated(pose, *cp.anchors["front"]), bay - gap, H - zf, 0)}


def _cooktop(ctx, root, W, H, D):
    """Cooktop plate (and backguard) on a range; returns the body's top and the lid spec."""
    p = ctx.p
    n = p.choice("burners", (5, 6)) if W > 0.75 else 4
    cook = ctx.choose("cooktop", COOKTOPS)(p.scope("cooktop"), D, W, n)
    zb = H - cook.anchors["surface"][2]
    root.add(cook, translation(0, 0, zb))
    if not p.flag("backguard", 0.6):
        return zb, n, None
    bt, bh = p.uniform("backguard_depth", 0.02, 0.04), p.uniform("backguard_height", 0.06, 0.2)
    guard = cuboid_between((D / 2 - bt, -W / 2, H), (D / 2, W / 2, H + bh), role="panel")
    root.add(Part("panel", "backguard", [guard]))
    return zb, n, (D / 2 - bt, H + cook.anchors["top"][2] - cook.anchors["surface"][2] + 0.004)


def body(ctx):
    p = ctx.p
    w, h, d = SUBS[ctx.sub]
    W, H, D = p.uniform("width", *w), p.uniform("height", *h), p.uniform("depth", *d)
    root = ctx.builder.create_link("base")
    if ctx.sub == "countertop":
        return {"root": root, "W": W, "D": D, "drawer": None, "lid": None, **_countertop(ctx, root, W, H, D)}
    t = p.uniform("door_thickness", 0.04, 0.06)
    zk = p.uniform("kick", 0.03, 0.08) if ctx.sub == "range" else 0.0
    if zk:
        root.add(plinth(p.scope("plinth"), D, W, zk))
    zb, n, lid = _cooktop(ctx, root, W, H, D) if ctx.sub == "range" else (H, 0, None)
    box = carcass(p, D, W, zb - zk)
    root.add(box, translation(0, 0, (zb + zk) / 2))
    wall = box.primitives[1].params[1]
    cs, tc = p.uniform("strip", 0.07, 0.11), p.uniform("strip_thickness", 0.01, 0.02)
    root.add(control_panel(p.scope("strip"), W, cs, tc), translation(-D / 2, 0, zb - cs / 2))
    top, drawer = zb - cs, None
    if ctx.sub == "range" and p.flag("drawer", 0.6):
        zd = zk + p.uniform("drawer_height", 0.1, 0.16)
        drawer, bottoms = (zk, zd - 0.003, zk + wall, zd - wall), [zd]
    elif ctx.sub == "double_oven":
        hl = (top - zk) * p.uniform("split", 0.48, 0.55)
        bottoms = [zk, zk + hl + _rise(hl, t)]
    else:
        bottoms = [zk]
    doors, x0, x1, yi = [], -D / 2, D / 2 - box.primitives[0].params[0], W / 2 - wall
    for i, b in enumerate(bottoms):  # one cavity per door, closed by divider boards
        z1 = bottoms[i + 1] if i + 1 < len(bottoms) else top
        z1 -= _rise(z1 - b, t)
        doors.append((-W / 2 + 0.002, W / 2 - 0.002, b, z1))
        root.add(Part("body", "divider", [cuboid_between((x0, -yi, z1 - wall / 2), (x1, yi, z1))]))
        if b > zk:
            root.add(Part("body", "divider", [cuboid_between((x0, -yi, b - wall), (x1, yi, b))]))
        _rack(p.scope(f"rack{i}"), root, x0, x1, -yi, yi, b + (z1 - b) * p.uniform(f"rack_z{i}", 0.3, 0.55))
    return {"root": root, "W": W, "D": D, "t": t, "doors": doors, "drawer": drawer, "lid": lid,
            "panel": ("row", translation(-D / 2 - tc, 0, zb - cs / 2), W, cs, n)}


def fronts(ctx):
    b = ctx.out["body"]
    root, W, D, t, doors = b["root"], b["W"], b["D"], b["t"], b["doors"]
    p = ctx.p
    tmpl, handle = ctx.choose("door", DOORS), ctx.choose("handle", HANDLES)
    m = p.uniform("handle_margin", 0.03, 0.05)
    for i, outer in enumerate(doors):
        add_door(ctx, root, p.scope(f"door{i}"), front_x=-D / 2, outer=outer, side="-z", template=tmpl, handle=handle,
                 limits=(0.0, p.uniform(f"limit{i}", 1.45, 1.57)), thickness=t, margin=m,
                 handle_length=min(0.6, 0.7 * (outer[1] - outer[0])))
    if b["drawer"] is not None:  # the drawer's handle must stay short of the opened door's handle
        z0, z1, iz0, iz1 = b["drawer"]
        f = min(0.8, (t + doors[0][3] - doors[0][2] - m - 0.12) / (D - 0.1))
        add_drawer(ctx, root, p.scope("drawer"), front_x=-D / 2, outer=(-W / 2 + 0.002, W / 2 - 0.002, z0, z1),
                   inner=(-W / 2 + 0.03, W / 2 - 0.03, iz0, iz1), depth=D - 0.1, template=box_drawer, handle=handle,
                   travel=(0.6 * f, f), handle_z=0.2)
    _controls(ctx, root, b["panel"])
    if b["lid"] is not None and p.flag("lid", 0.4):  # glass cover hinged on the backguard
        xb, zl = b["lid"]
        tl = p.uniform("lid_thickness", 0.006, 0.01)
        link = ctx.builder.create_link("lid", root)
        link.set_joint("revolute", translation(xb, 0, zl + tl), axis=(0, 1, 0),
                       limits=(0.0, p.uniform("lid_limit", 1.3, 1.5)))
        glass = cuboid_between((-(xb + D / 2 - 0.005), -W / 2 + 0.005, -tl), (0.0, W / 2 - 0.005, 0.0), role="glass")
        link.add(Part("lid", "glass_lid", [glass], regions={"lift": Region(("glass",))}, actionable="hinge_lid"))


def _controls(ctx, root, panel):
    """Knobs (on wall ovens also push buttons and a display) on the control strip or bay."""
    kind, pose, w, h, burners = panel
    p = ctx.p.scope("controls")
    if kind == "column":  # countertop: knobs stacked in the bay
        n = p.integers("knobs", 2, 4)
        r = min(0.022, w / 2 - 0.01, h / n / 2 - 0.006)
        spots = [(0.0, h / 2 - h * (i + 0.5) / n) for i in range(n)]
    elif burners:  # ranges: one knob per burner and one or two for the oven, evenly spread
        n = burners + p.integers("oven_knobs", 1, 2)
        r = min(0.026, h / 2 - 0.01, (w - 0.1) / (2 * n) - 0.006)
        spots = [(-w / 2 + 0.05 + (w - 0.1) * (i + 0.5) / n, 0.0) for i in range(n)]
    else:  # wall ovens: knobs at both ends
        n = p.integers("knobs", 2, 3)
        r = min(0.026, h / 2 - 0.01)
        pitch = 2 * r + 0.025
        spots = [(s * (w / 2 - 0.05 - r - (i // 2) * pitch), 0.0) for i, s in zip(range(n), (-1, 1, -1))]
    knob = ctx.choose("knob", KNOBS)
    for i, T in enumerate(mount_poses(pose, spots)):
        mount_knob(ctx.builder, root, knob(p.scope(f"knob{i}"), radius=r), T, continuous=True)
    if kind == "column" or burners:
        return
    lo, hi = -w / 2 + 0.05 + (2 * r + 0.025) * (1 + (n > 2)) + 0.02, w / 2 - 0.05 - 2 * r - 0.045
    if p.flag("display", 0.7):
        root.add(display(p.scope("display"), 0.3 * (hi - lo), 0.5 * h), translated(pose, 0, (lo + hi) / 2, h / 5))
    tmpl, k = ctx.choose("button", BUTTONS), p.integers("buttons", 2, max(2, min(5, int((hi - lo) / 0.034))))
    mount_button_row(p, ctx.builder, root, tmpl, k, pose, lo, hi, -h / 4, radius=0.007, square=(0.016, 0.011))


RULE = Category(
    name="oven",
    subcategories={"range": 3.0, "wall_oven": 2.0, "double_oven": 1.0, "countertop": 1.0},
    materials={"body": "shell", "door": "shell", "leg": "shell", "base": "shell", "top": "shell", "drawer": "shell"},
    mass_range=(10.0, 130.0),  # kg: countertop ovens to free-standing ranges
    slots=(Slot("body", body), Slot("fronts", fronts, after=("body",))),
)
