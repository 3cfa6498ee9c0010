"""Washing machines: front loaders (full size and compact), top loaders and twin tubs.

Parts: front loaders: a cabinet on feet whose front is a porthole panel (a round
opening with a gasket) under a control strip holding a detergent drawer, a program
knob, push buttons and an optional display; a round door (flat, domed or with a
chrome rim) hinged on its left and a drum with lifters behind it. Top loaders: a
cabinet whose top has an opening over a basket with an agitator or an impeller, a
flat lid (solid or glass) hinged at the back, and a console at the back with knobs and
buttons. Twin tubs: a wash tub with an impeller and a spin basket side by side, each
under its own lid, timer knobs on the console.
Joints: round door revolute about a vertical axis on its rim (1.6-2.2 rad); detergent
drawer prismatic along -x; drum continuous about x, baskets and impellers continuous
about z; lids revolute about +y at their back edge (1.2-1.5 rad); knobs continuous;
buttons prismatic. Sizes (metres): front loader 0.6 x 0.55-0.65 x 0.85 (compact
0.5-0.55 wide, 0.65-0.7 tall); top loader 0.6-0.7 wide, 0.9-0.95 to the lid plus a
0.1-0.2 console; twin tub 0.7-0.8 wide, 0.4-0.46 deep, 0.8-0.9 tall.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between, cylinder, ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass
from artipg.templates.cells import add_door, add_drawer
from artipg.templates.controls import BUTTONS, KNOBS, dial_knob, mount_button_row, mount_knob
from artipg.templates.extents import span
from artipg.templates.handles import edge_pull, flat_bar_handle
from artipg.templates.panels import DRAWERS
from artipg.templates.supports import bun_feet
from artipg.templates.washer import IMPELLERS, LIDS, ROUND_DOORS, basket, drum, porthole_panel, pulsator

SUBS = {  # width, height, depth ranges, door radius range
    "front_loader": ((0.595, 0.6), (0.84, 0.86), (0.55, 0.65), (0.2, 0.25)),
    "compact": ((0.5, 0.55), (0.65, 0.7), (0.42, 0.5), (0.16, 0.2)),
    "top_loader": ((0.6, 0.7), (0.9, 0.95), (0.62, 0.7), None),
    "twin_tub": ((0.7, 0.8), (0.8, 0.9), (0.4, 0.46), None),
}
_ALONG_X = Placer(rot_y(math.pi / 2))
DOOR_HANDLES = {edge_pull: 1.0, flat_bar_handle: 1.0}
HINGES = {"+y": 4.0, "-y": 1.0}  # front-loader doors are mostly hinged on the left


def _box(lo, hi, role="panel"):
    return cuboid_between(lo, hi, role=role)


def body(ctx):
    p = ctx.p
    w, h, d, rd = SUBS[ctx.sub]
    W, H, D = p.uniform("width", *w), p.uniform("height", *h), p.uniform("depth", *d)
    zk = p.uniform("feet", 0.01, 0.03)
    root = ctx.builder.create_link("base")
    root.add(bun_feet(p.scope("feet"), 0.9 * D, 0.9 * W, zk))
    if rd is None:
        return _top_body(ctx, root, W, H, D, zk)
    box = carcass(p, D, W, H - zk)
    root.add(box, translation(0, 0, (H + zk) / 2))
    wall, back = box.primitives[1].params[1], box.primitives[0].params[0]
    tp, cs = p.uniform("panel", 0.008, 0.015), p.uniform("strip", 0.1, 0.14)
    zs = H - cs
    R = min(p.uniform("door_radius", *rd), W / 2 - 0.02, (zs - zk) / 2 - 0.012)
    hp, cz = (zs - zk) / 2, (zs + zk) / 2
    hole = R * p.uniform("hole", 0.72, 0.82)
    root.add(porthole_panel(p.scope("porthole"), W, 2 * hp, hole, tp), translation(-D / 2, 0, cz))
    gd, ro = p.uniform("gasket_depth", 0.04, 0.07), hole - p.uniform("gasket", 0.02, 0.035)
    gasket = ring(hole, ro, gd, pose=_ALONG_X.at(-D / 2 - tp + gd / 2, 0, cz), role="gasket")
    root.add(Part("body", "gasket", [gasket]))
    rdr = min(W / 2 - wall, cz - zk - wall, zs - cz) - 0.012
    x0, axle = -D / 2 - tp + gd + 0.005, 0.03
    dl = ctx.builder.create_link("drum", root)
    dl.set_joint("continuous", translation(x0, 0, cz), axis=(1, 0, 0))
    dl.add(drum(p.scope("drum"), rdr, D / 2 - back - axle - x0, axle))
    return root, ("front", W, H, D, zk, wall, tp, zs, cz, R, ro)


def _top_body(ctx, root, W, H, D, zk):
    """Closed cabinet with 1 (top loader) or 2 (twin tub) openings in its top, tubs below."""
    p = ctx.p
    wall, tt = p.uniform("wall", 0.01, 0.02), p.uniform("top", 0.015, 0.03)
    cd, ch = p.uniform("console_depth", 0.08, 0.14), p.uniform("console_height", 0.1, 0.2)
    xf, xb = -D / 2 + wall, D / 2 - cd
    xh = xb - 0.05  # lid hinge line, clear of the console's knobs
    prims = [_box((-D / 2, -W / 2, zk), (D / 2, W / 2, zk + wall)),
             _box((-D / 2, -W / 2, zk), (D / 2, -W / 2 + wall, H)), _box((-D / 2, W / 2 - wall, zk), (D / 2, W / 2, H)),
             _box((-D / 2, -W / 2, zk), (-D / 2 + wall, W / 2, H)), _box((D / 2 - wall, -W / 2, zk), (D / 2, W / 2, H)),
             _box((xb, -W / 2, H), (D / 2, W / 2, H + ch), "console")]
    twin = ctx.sub == "twin_tub"
    xc = (xf + xh) / 2
    if twin:
        split = W * p.uniform("wash_share", 0.55, 0.62)
        tubs = [(W / 2 - split / 2, split / 2 - wall), (-W / 2 + (W - split) / 2, (W - split) / 2 - wall)]
    else:
        tubs = [(0.0, W / 2 - wall)]
    r_lim = (xh - xf) / 2 - 0.02
    edges, holes = [-W / 2 + wall], []
    for i, (yc, half) in enumerate(tubs):
        R = min(half - 0.015, r_lim) * p.uniform(f"tub{i}", 0.85, 1.0)
        a = R * p.uniform(f"hole{i}", 0.75, 0.88)
        holes.append((yc, R, a, min(half + wall - 0.003, r_lim + 0.015) - a))
        edges += [yc - a, yc + a]
        prims += [_box((xf, yc - a, H - tt), (xc - a, yc + a, H)),  # top strips in front of and behind the hole
                  _box((xc + a, yc - a, H - tt), (D / 2 - wall, yc + a, H))]
    edges = sorted(edges + [W / 2 - wall])
    prims += [_box((xf, y0, H - tt), (D / 2 - wall, y1, H)) for y0, y1 in zip(edges[::2], edges[1::2]) if y1 > y0]
    root.add(Part("body", "cabinet", prims))
    zb = zk + wall
    for i, (yc, R, a, _) in enumerate(holes):
        q = p.scope(f"tub{i}")
        hb = H - tt - 0.02 - zb
        if twin and i == 0:  # fixed wash tub with an impeller on its floor
            wall_ = ring(R, R - 0.004, hb - 0.03, pose=translation(xc, yc, zb + 0.03 + (hb - 0.03) / 2), role="wall")
            root.add(Part("body", "tub", [wall_, cylinder(R, 0.03, translation(xc, yc, zb + 0.015), role="floor")]))
            imp = ctx.builder.create_link("arm", root)
            imp.set_joint("continuous", translation(xc, yc, zb + 0.03))
            imp.add(pulsator(q.scope("pulsator"), 0.5 * R, 0.03))
            continue
        bl = ctx.builder.create_link("basket", root)
        bl.set_joint("continuous", translation(xc, yc, zb))
        part = basket(q.scope("basket"), R, hb - 0.04, 0.04)
        bl.add(part)
        if not twin:
            imp = ctx.builder.create_link("arm", bl)
            imp.set_joint("continuous", translation(*part.anchors["floor"]))
            imp.add(ctx.choose("impeller", IMPELLERS)(q.scope("impeller"), 0.8 * (R - 0.01), 0.45 * hb))
    return root, ("top", W, H, D, zk, xb, xh, ch, xc, holes)


def fronts(ctx):
    root, (kind, W, H, D, zk, *rest) = ctx.out["body"]
    p = ctx.p
    if kind == "top":
        xb, xh, ch, xc, holes = rest
        for i, (yc, R, a, m_max) in enumerate(holes):
            q = p.scope(f"lid{i}")
            m = q.uniform("margin", 0.01, 0.05) if m_max > 0.05 else m_max
            # one name per tub: a twin tub's second choice must not share the first's name,
            # or overrides (repair) cannot reproduce the object
            lid = ctx.choose(f"lid{i}.template", LIDS)(q, xh - (xc - a - m), 2 * (a + m))
            link = ctx.builder.create_link("lid", root)
            bottom, top = span(lid.primitives, 2)
            link.set_joint("revolute", translation(xh, yc, H + top - bottom), axis=(0, 1, 0),
                           limits=(0.0, q.uniform("limit", 1.2, 1.5)))
            link.add(lid)
        _controls(ctx, root, translation(xb, 0, H + ch / 2), W, ch, len(holes) == 2)
        return
    wall, tp, zs, cz, R, ro = rest
    t = p.uniform("door_thickness", 0.03, 0.05)
    handle = ctx.choose("handle", DOOR_HANDLES)
    add_door(ctx, root, p.scope("door"), front_x=-D / 2 - tp, outer=(-R, R, cz - R, cz + R),
             side=p.choice("hinge", HINGES), limits=(0.0, p.uniform("door_limit", 1.6, 2.2)),
             template=ctx.choose("door", ROUND_DOORS), thickness=t, handle=handle, margin=t / 2, opening=ro,
             handle_length=p.uniform("handle_length", 0.06, 0.1))  # the handle sits on the rim
    x = -D / 2 - tp
    y1 = W / 2 - 0.03
    has_drawer = p.flag("drawer", 0.85 if ctx.sub == "front_loader" else 0.4)
    y0 = y1 - (p.uniform("drawer_width", 0.14, 0.2) if has_drawer else 0.0)
    z0, z1 = zs + 0.015, H - 0.015
    prims = [_box((x, -W / 2, zs), (x + tp, y0, H)), _box((x, y1, zs), (x + tp, W / 2, H))]
    if y1 > y0:
        prims += [_box((x, y0, zs), (x + tp, y1, z0)), _box((x, y0, z1), (x + tp, y1, H))]
        add_drawer(ctx, root, p.scope("drawer"), front_x=x, outer=(y0 - 0.006, y1 + 0.006, z0 - 0.006, z1 + 0.006),
                   inner=(y0, y1, z0, min(z1, H - wall) - 0.002), depth=p.uniform("drawer_depth", 0.25, 0.35),
                   template=ctx.choose("drawer", DRAWERS), handle=edge_pull)
    root.add(Part("panel", "control_strip", prims))
    _controls(ctx, root, translation(x, (y0 - 0.02 - W / 2) / 2, (zs + H) / 2), y0 - 0.02 + W / 2, H - zs, False)


def _controls(ctx, root, pose, w, h, twin):
    """A program knob at the right end and buttons (and a display) on a strip ``w`` x ``h``."""
    p = ctx.p.scope("controls")
    n = 2 + p.integers("extra_knobs", 0, 1) if twin else 1
    r = min(0.045, h / 2 - 0.015)
    knob = dial_knob if twin else ctx.choose("knob", KNOBS)
    for i in range(n):
        y = -w / 2 + 0.03 + r + i * (2 * r + 0.04) if twin else w / 2 - 0.03 - r
        mount_knob(ctx.builder, root, knob(p.scope(f"knob{i}"), radius=r), pose @ translation(0, y, 0), continuous=True)
    if twin:
        return
    lo, hi = -w / 2 + 0.03, w / 2 - 0.08 - 2 * r
    if hi - lo > 0.15 and p.flag("display", 0.6):
        screen = cuboid_between((-0.002, hi - 0.3 * (hi - lo), -h / 4), (0.0, hi, h / 4), role="screen")
        root.add(Part("screen", "display", [screen]), pose)
        hi -= 0.3 * (hi - lo) + 0.02
    tmpl, k = ctx.choose("button", BUTTONS), p.integers("buttons", 1, max(1, min(5, int((hi - lo) / 0.036))))
    mount_button_row(p, ctx.builder, root, tmpl, k, pose, lo, hi, 0.0, radius=0.008, square=(0.018, 0.012))


RULE = Category(
    name="washing_machine",
    subcategories={"front_loader": 3.0, "top_loader": 2.0, "compact": 1.0, "twin_tub": 1.0},
    materials={"body": "shell", "door": "shell", "leg": "shell", "drawer": "shell"},
    mass_range=(15.0, 100.0),  # kg: compact / twin-tub (~20 kg) to front loaders with counterweights
    slots=(Slot("body", body), Slot("fronts", fronts, after=("body",))),
)
