"""Boxes: keepsake and jewellery boxes, double-lid storage boxes, cartons with flaps,
sliding-lid boxes and blanket chests.

Parts: an open-top body (optionally on a support for chests); lids from four
templates (flat, raised panel, pitched, or a cap with a skirt around the body) hinged
on the body's back edge (revolute about y, 0..1.6-2.0 rad), or two lids meeting in the
middle hinged on opposite edges; cartons have four flaps on the top edges
(revolute, opening outwards 0..1.8-2.8 rad), the long ones meeting in the middle and
the short ones folding in at the ends; a sliding lid runs in grooves of the side walls
over a cut-down front wall (prismatic along -x, 60-85 % of its length) and has a knob
or a finger ridge. Keepsake boxes and chests may have a drawer bay with one or two
drawers (prismatic, knob or pull handles); boxes may have a front clasp on the lid and
chests side handles.
Joints: 1-4 movable. Sizes (metres): keepsake 0.12-0.4 wide, cartons 0.2-0.6, chests
0.6-1.2 wide and 0.35-0.6 tall, sliding boxes 0.18-0.4 long.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import Placer, rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.boxes import HINGED_LIDS, cap_lid, flap, grooved_box, mount_lid, open_box, raised_lid, slab_lid
from artipg.templates.handles import arch_handle, ball_knob_pull, flat_bar_handle, knob_pull
from artipg.templates.mounting import front_thickness, handle_pose, mount_sliding
from artipg.templates.panels import box_drawer
from artipg.templates.supports import SUPPORTS

# sub-category -> depth / width, width, height, wall
SIZES = {"hinged_box": ((0.55, 0.8), (0.12, 0.4), (0.05, 0.2), (0.006, 0.015)),
         "double_lid_box": ((0.5, 0.8), (0.25, 0.6), (0.1, 0.35), (0.008, 0.018)),
         "flap_box": ((0.55, 0.9), (0.2, 0.6), (0.1, 0.45), (0.003, 0.006)),
         "sliding_lid_box": ((1.3, 3.5), (0.06, 0.25), (0.03, 0.15), (0.006, 0.012)),
         "chest": ((0.45, 0.7), (0.6, 1.2), (0.35, 0.6), (0.015, 0.025))}
LIDS = {"hinged_box": HINGED_LIDS, "chest": {slab_lid: 2.0, raised_lid: 1.0}, "double_lid_box": {slab_lid: 2.0,
                                                                                              raised_lid: 1.0}}
KNOBS = {knob_pull: 2.0, ball_knob_pull: 1.0, arch_handle: 1.0}
ROUND_KNOBS = {knob_pull: 1.0, ball_knob_pull: 1.0}
SIDE_HANDLES = {arch_handle: 1.0, flat_bar_handle: 1.0}
ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x
FLAT = rot_x(math.pi / 2)  # a handle's long axis along y
SIDE_TURN = {s: Placer(rot_z(-s * math.pi / 2)) for s in (1.0, -1.0)}  # a side handle facing out of side s (+-y)


def body(ctx):
    p = ctx.p
    d, w, h, t = SIZES[ctx.sub]
    W = p.uniform("width", *w)
    D = min(0.55 if ctx.sub == "chest" else 0.4, p.uniform("depth_ratio", *d) * W)
    H, t = p.uniform("height", *h), p.uniform("wall", *t)
    root = ctx.builder.create_link("body")
    z0 = 0.0
    if ctx.sub == "chest" and p.flag("has_support", 0.7):
        z0 = p.uniform("support_height", 0.03, 0.12)
        root.add(ctx.choose("support", SUPPORTS)(p.scope("support"), D, W, z0))
    if ctx.sub == "sliding_lid_box":
        lid_t = p.uniform("lid_thickness", 0.004, min(0.01, 0.2 * H))
        return root, root.add(grooved_box(p.scope("shell"), D, W, H, lid_t, wall=t)), (D, W, H, t, 0.0, lid_t)
    bay = p.uniform("bay", 0.3, 0.45) * H if ctx.sub in ("hinged_box", "chest") and H > 0.1 and p.flag(
        "drawers", 0.4) else 0.0
    return root, root.add(open_box(p.scope("shell"), D, W, H, wall=t, z0=z0, bay=bay)), (D, W, H + z0, t, z0, bay)


def lids(ctx):
    root, part, (D, W, top, t, z0, extra) = ctx.out["body"]
    p = ctx.p
    if ctx.sub == "sliding_lid_box":
        return _sliding(ctx, root, part, D, W, extra)
    if ctx.sub == "flap_box":
        s, g, th = p.uniform("minor_flap", 0.2, 0.35) * W, 0.003, p.uniform("flap_thickness", 0.003, 0.005)
        lim = (0.0, p.uniform("limit", 1.8, 2.8))
        for i, sg in enumerate((1.0, -1.0)):  # long flaps meet in the middle, short ones fold in at the ends
            mount_lid(ctx.builder, root, flap(p.scope(f"flap{i}"), D / 2 - g / 2, W - 2 * s - 2 * g, th),
                      (sg * D / 2, 0.0, top), "+x" if sg > 0 else "-x", lim, name="flap")
            mount_lid(ctx.builder, root, flap(p.scope(f"flap{i + 2}"), s, D, th), (0.0, sg * W / 2, top),
                      "+y" if sg > 0 else "-y", lim, name="flap")
        return None
    tmpl = ctx.choose("lid", LIDS[ctx.sub])
    lim = (0.0, p.uniform("limit", 1.6, 2.0))
    o = p.uniform("overhang", 0.0, 0.012)
    if ctx.sub == "double_lid_box":
        along_x = p.flag("hinges_front_back", 0.6)
        L, Wl = (D, W) if along_x else (W, D)
        edges = ("+x", "-x") if along_x else ("+y", "-y")
        for i, (e, sg) in enumerate(zip(edges, (1.0, -1.0))):
            ax = (sg * L / 2, 0.0, top) if along_x else (0.0, sg * L / 2, top)
            mount_lid(ctx.builder, root, tmpl(p.scope(f"lid{i}"), L / 2 - 0.0015, Wl + 2 * o), ax, e, lim)
        return None
    if tmpl is cap_lid:  # the skirt needs room to swing past the front wall's top edge
        sk, st = p.uniform("skirt", 0.015, min(0.04, 0.4 * (top - z0))), p.uniform("skirt_thickness", 0.004, 0.01)
        g = max(0.002, sk * sk / (2 * D) + 0.0015)
        e = g + st
        lid = cap_lid(p.scope("lid"), D + 2 * e, W + 2 * e, skirt=sk, skirt_thickness=st)
        return mount_lid(ctx.builder, root, lid, (D / 2 + e, 0.0, top - sk), "+x", lim), lid
    lid = tmpl(p.scope("lid"), D + o, W + 2 * o)
    return mount_lid(ctx.builder, root, lid, (D / 2, 0.0, top), "+x", lim), lid


def _sliding(ctx, root, part, D, W, lid_t):
    p = ctx.p
    xb, yg, zg = part.anchor("groove")
    L, Wl = xb - 0.001 + D / 2, 2 * (yg - 0.001)
    lid = Part("lid", "sliding_lid", [cuboid_between((0, -Wl / 2, 0), (L, Wl / 2, lid_t), role="top")],
               regions={"push": Region(("top",))}, actionable="slider_lid")
    link = mount_sliding(ctx.builder, root, lid, origin=translation(-D / 2, 0, zg + 0.001),
                         limits=(0.0, p.uniform("travel", 0.6, 0.85) * L), name="lid")
    if p.flag("has_knob", 0.5):
        k = ctx.choose("knob", ROUND_KNOBS)(p.scope("knob"))
        link.add(k, ALONG_X.at(0.15 * L, 0, lid_t))
    else:
        link.add(Part("handle", "finger_ridge", [cuboid_between((0.04 * L, -0.3 * Wl, lid_t), (0.04 * L + 0.006,
                                                                                               0.3 * Wl, lid_t + 0.003),
                                                                role="grip")], regions={"push": Region()}))


def extras(ctx):
    root, part, (D, W, top, t, z0, bay) = ctx.out["body"]
    p = ctx.p
    if ctx.sub in ("hinged_box", "chest") and p.flag("clasp", 0.4 if ctx.sub == "hinged_box" else 0.2):
        link, lid = ctx.out["lids"]
        cw, ch = p.uniform("clasp_width", 0.012, 0.03), p.uniform("clasp_drop", 0.01, 0.025)
        x = lid.anchor("front")[0]  # a plate on the lid's front face hanging over the body
        plate = cuboid_between((x - 0.003, -cw / 2, -ch), (x, cw / 2, 0.8 * lid.anchor("top")[2]), role="grip")
        link.add(Part("handle", "clasp", [plate], regions={"lift": Region(("grip",))}))
    if ctx.sub == "chest" and p.flag("side_handles", 0.6):
        tmpl = ctx.choose("side_handle", SIDE_HANDLES)
        hl = p.uniform("side_handle_length", 0.1, 0.16)
        for i, s in enumerate((1.0, -1.0)):
            pose = SIDE_TURN[s].at(0, s * W / 2, top - 0.12) @ FLAT
            root.add(tmpl(p.scope(f"side_handle{i}"), length=hl), pose)
    if ctx.sub not in ("hinged_box", "chest") or not bay:
        return
    lo, hi = part.anchor("bay_lo"), part.anchor("bay_hi")
    n = p.integers("drawer_count", 1, 2 if W > 0.3 else 1)
    g, tf = 0.002, p.uniform("front_thickness", 0.006, 0.015)
    fw, fh = (hi[1] - lo[1] - (n + 1) * g) / n, hi[2] - lo[2] - 2 * g
    knob = ctx.choose("drawer_handle", KNOBS)
    for i in range(n):
        q = p.scope(f"drawer{i}")
        cy = lo[1] + g + fw / 2 + i * (fw + g)
        dr = box_drawer(q, fw, fh, hi[0] - lo[0] - tf - 0.004, opening=(-fw / 2 + 0.001, fw / 2 - 0.001, -fh / 2 - g,
                                                                        fh / 2), thickness=tf)  # box on the floor
        link = mount_sliding(ctx.builder, root, dr, origin=translation(lo[0] + tf, cy, (lo[2] + hi[2]) / 2),
                             limits=(0.0, q.uniform("travel", 0.6, 0.85) * (hi[0] - lo[0])), name="drawer")
        link.add(knob(q.scope("handle"), length=min(0.1, 0.5 * fw)), handle_pose(dr.pose, front_thickness(dr), 0.0,
                                                                                  0.0, True))


RULE = Category(
    name="box",
    subcategories={"hinged_box": 3.0, "double_lid_box": 1.0, "flap_box": 2.0, "sliding_lid_box": 1.0, "chest": 1.5},
    materials={"lid": "wood"},
    mass_range=(0.2, 60.0),  # kg: cardboard-light boxes to solid-wood blanket chests
    slots=(Slot("body", body), Slot("lids", lids, after=("body",)), Slot("extras", extras, after=("lids",))),
)
