"""Trash cans: pedal bins, swing-top bins, touch-top bins with a flip lid, and pull-out
or tilt-out bin cabinets.

Parts: a round (straight or tapered) or rectangular open body. Pedal bins: a lid
(flat, domed or stepped round lid; flat or raised rectangular lid) hinged behind the
rim (revolute about y, 0..1.1-1.45 rad, stopped by a hinge block below the axis) and
a foot pedal pivoting in brackets at the front bottom (revolute, the plate presses
down 0.15-0.35 rad). Swing-top bins: a hood on the rim with a flap in its front that
swings both ways about its horizontal centre line (revolute +-0.8-1.2 rad). Touch-top
bins: a collar on the rim, a flip lid inset in its opening hinged at the back (revolute
0..1.4-1.8 rad) and a release button on the collar's front (prismatic, pressed
down). Bin cabinets: a carcass on a plinth or legs with 1-3 compartments, each a
pull-out bin (prismatic along -x) or a tilt-out bin (revolute about the bottom front
edge, 0..0.35-0.55 rad) with a handle.
Joints: 1-3 movable. Sizes (metres): bins 0.2-0.4 across, 0.28-0.75 tall; cabinets
0.3-0.9 wide, 0.55-0.9 tall.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between
from artipg.geometry.lathe import frustum_dims
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bins import (ROUND_LIDS, flat_disc_lid, pedal, pedal_brackets, rect_collar, round_collar,
                                  swing_flap, swing_hood)
from artipg.templates.bodies import carcass, cylindrical_shell, tapered_shell
from artipg.templates.boxes import mount_lid, open_box, raised_lid, slab_lid
from artipg.templates.controls import button_bezel, mount_button, rect_button, round_button
from artipg.templates.frames import swing_clearance
from artipg.templates.handles import arch_handle, edge_pull, flat_bar_handle
from artipg.templates.mounting import front_thickness, handle_pose, mount_hinged, mount_sliding
from artipg.templates.panels import box_drawer, slot_drawer
from artipg.templates.supports import SUPPORTS

# sub-category -> radius / half width, height, P(round body)
SIZES = {"pedal_bin": ((0.1, 0.17), (0.28, 0.7), 0.6), "swing_bin": ((0.12, 0.2), (0.45, 0.75), 0.0),
         "touch_top_bin": ((0.12, 0.18), (0.45, 0.75), 0.5), "bin_cabinet": ((0.15, 0.45), (0.55, 0.9), 0.0)}
BODIES = {cylindrical_shell: 2.0, tapered_shell: 1.0}
HANDLES = {flat_bar_handle: 2.0, arch_handle: 2.0, edge_pull: 1.0}
LIDS = {slab_lid: 1.0, raised_lid: 1.0}
BUTTONS = {round_button: 1.0, rect_button: 1.0}
BINS = {box_drawer: 2.0, slot_drawer: 1.0}
_UP = rot_y(math.pi / 2)  # control frame (surface normal -x) -> surface normal +z


def body(ctx):
    p = ctx.p
    r, h, p_round = SIZES[ctx.sub]
    R, H = p.uniform("radius", *r), p.uniform("height", *h)
    root = ctx.builder.create_link("body")
    if ctx.sub == "bin_cabinet":
        return _cabinet(ctx, root, 2 * R, p.uniform("depth", 0.35, 0.55), H)
    if p.flag("round", p_round):
        part = root.add(ctx.choose("body", BODIES)(p.scope("shell"), R, H))
        return root, part, dict(round=True, D=2 * R, W=2 * R, H=H, R=R, r0=frustum_dims(part.primitives[0])[0])
    D = p.uniform("depth_ratio", 0.7, 1.0) * 2 * R
    part = root.add(open_box(p.scope("shell"), D, 2 * R, H, wall=p.uniform("wall", 0.003, 0.008)))
    return root, part, dict(round=False, D=D, W=2 * R, H=H, R=R, r0=D / 2)


def top(ctx):
    root, part, b = ctx.out["body"]
    if ctx.sub == "bin_cabinet":
        return
    p, H = ctx.p, b["H"]
    if ctx.sub == "pedal_bin":
        o = p.uniform("overhang", 0.003, 0.01)
        if b["round"]:
            lid, ax = ctx.choose("lid", ROUND_LIDS)(p.scope("lid"), b["R"] + o), b["R"] + o
        else:
            tmpl = ctx.choose("lid", LIDS)
            lid, ax = tmpl(p.scope("lid"), b["D"] + o, b["W"] + 2 * o), b["D"] / 2
        mount_lid(ctx.builder, root, lid, (ax, 0.0, H), "+x", (0.0, p.uniform("lid_limit", 1.1, 1.45)))
        bh = p.uniform("hinge_block", 0.02, 0.04)  # below the axis: the lid never reaches it below 90 degrees
        root.add(Part("hinge", "hinge_block", [cuboid_between((ax - 0.02, -0.03, H - bh), (ax, 0.03, H))]))
        return _pedal(ctx, root, b)
    if ctx.sub == "swing_bin":
        fw, fh = p.uniform("flap_width", 0.6, 0.8) * b["W"], p.uniform("flap_height", 0.08, 0.14)
        t = p.uniform("flap_thickness", 0.002, 0.004)
        c = t * t / (4 * fh) + 0.002  # the flap's corners swing on a radius a little over half its height
        hood = root.add(swing_hood(p.scope("hood"), b["D"], b["W"], fw + 0.004, fh + 2 * c), translation(0, 0, H))
        a = p.uniform("flap_limit", 0.8, 1.2)
        link = ctx.builder.create_link("flap", root)
        link.set_joint("revolute", translation(0, 0, H) @ translation(*hood.anchor("opening")), axis=(0, 1, 0),
                       limits=(-a, a))
        link.add(swing_flap(p.scope("flap"), fw, fh, thickness=t))
        return
    ch = p.uniform("collar_height", 0.02, 0.04)
    t = p.uniform("lid_thickness", 0.5, 0.9) * ch
    if b["round"]:
        ro = b["R"] - p.uniform("band", 0.03, 0.05)
        col = root.add(round_collar(p.scope("collar"), b["R"], ro, ch), translation(0, 0, H))
        lid = flat_disc_lid(p.scope("lid"), ro - swing_clearance(t, 2 * ro), thickness=t)
        ax = ro - 0.0015  # the lid's back edge sits just inside the opening
    else:
        od, ow = b["D"] - 0.09, b["W"] - 0.04
        col = root.add(rect_collar(p.scope("collar"), b["D"], b["W"], od, ow, 0.025, ch), translation(0, 0, H))
        L = od - 0.0015 - swing_clearance(t, od)
        lid = slab_lid(p.scope("lid"), L, ow - 0.004, thickness=t)
        ax = 0.025 + od / 2 - 0.0015
    mount_lid(ctx.builder, root, lid, (ax, 0.0, H + ch), "+x", (0.0, p.uniform("lid_limit", 1.4, 1.8)),
              pose=translation(0, 0, -t))  # flush in the collar, hinged on its top back edge
    q = p.scope("button")
    btn = ctx.choose("button", BUTTONS)(q, travel=q.uniform("press", 0.003, 0.005))
    pose = translation(0, 0, H) @ translation(*col.anchor("button")) @ _UP
    root.add(button_bezel(q.scope("bezel"), btn), pose)
    mount_button(ctx.builder, root, btn, pose)


def _pedal(ctx, root, b):
    p = ctx.p
    ped = pedal(p.scope("pedal"), width=min(0.12, 0.5 * b["W"]))
    r, y = ped.anchor("pin")[0], ped.anchor("pin")[1]
    z = p.uniform("pedal_height", 0.035, 0.06)
    rz = b["r0"] + (b["R"] - b["r0"]) * (z + r) / b["H"]  # wall radius at the pin (tapered bodies)
    x = -rz - r - 0.003
    wall_x = -math.sqrt(max(b["r0"] ** 2 - (y + 0.006) ** 2, 0.0)) if b["round"] else -b["r0"]
    root.add(pedal_brackets(ped, wall_x + 0.002 - x), translation(x, 0, z))
    link = ctx.builder.create_link("pedal", root)
    tip = -ped.anchor("tip")[0]
    lim = math.asin(min(0.9, (z + ped.anchor("tip")[2] - 0.004) / tip))
    link.set_joint("revolute", translation(x, 0, z), axis=(0, -1, 0), limits=(0.0, min(p.uniform("pedal_limit", 0.15,
                                                                                                  0.35), lim)))
    link.add(ped)


def _cabinet(ctx, root, W, D, H):
    p = ctx.p
    sh = p.uniform("support_height", 0.04, 0.1)
    root.add(ctx.choose("support", SUPPORTS)(p.scope("support"), D, W, sh))
    body = root.add(carcass(p.scope("carcass"), D, W, H - sh), translation(0, 0, sh + (H - sh) / 2))
    n = p.integers("compartments", 1, 3 if W > 0.5 else 2 if W > 0.35 else 1)
    lo, hi = body.anchor("cavity_lo"), body.anchor("cavity_hi")
    wall, g = float(body.primitives[1].params[1]), 0.003
    tilt = p.flag("tilt_out", 0.4)
    tmpl, bin_t = ctx.choose("handle", HANDLES), ctx.choose("bin", BINS)
    cw = (W - (n - 1) * g) / n
    z0, z1 = sh + (H - sh) / 2 + lo[2] - wall, sh + (H - sh) / 2 + hi[2] + wall
    for i in range(n):
        q = p.scope(f"bin{i}")
        y0 = -W / 2 + i * (cw + g)
        if i:  # divider between compartments
            root.add(Part("body", "divider", [cuboid_between((lo[0], y0 - g / 2 - wall / 2, z0 + wall),
                                                             (hi[0], y0 - g / 2 + wall / 2, z1 - wall))]))
        iy0 = (lo[1] if i == 0 else y0 - g / 2 + wall / 2) + 0.003
        iy1 = (hi[1] if i == n - 1 else y0 + cw + g / 2 - wall / 2) - 0.003
        cy, cz, fh = y0 + cw / 2, (z0 + z1) / 2, z1 - z0 - g
        Db, top = hi[0] - lo[0] - 0.01, z1 - wall - 0.003 - cz
        if tilt:  # a tilting bin's back rises: keep its diagonal (from the axis) under the top panel
            Hc = z1 - wall - 0.003 - z0
            Db = min(Db, 0.6 * Hc - 0.025)
            top = min(top, math.sqrt(Hc * Hc - (Db + 0.025) ** 2) + z0 - cz)
        opening = (iy0 - cy, iy1 - cy, z0 + wall + 0.003 - cz, top)
        dr = bin_t(q, cw, fh, Db, opening=opening)
        if tilt:
            link = mount_hinged(ctx.builder, root, dr, front_x=lo[0], center_yz=(cy, cz), size_yz=(cw, fh),
                                side="-z", limits=(0.0, q.uniform("limit", 0.35, 0.55)), name="bin")
        else:
            link = mount_sliding(ctx.builder, root, dr, origin=translation(lo[0], cy, cz),
                                 limits=(0.0, q.uniform("travel", 0.7, 0.9) * Db), name="bin")
        if "pull" not in dr.regions:
            h = tmpl(q.scope("handle"), length=min(0.3, 0.5 * cw))
            link.add(h, handle_pose(dr.pose, front_thickness(dr), 0.0, 0.3 * fh, True))
    return root, body, dict(round=False, D=D, W=W, H=H)


RULE = Category(
    name="trash_can",
    subcategories={"pedal_bin": 3.0, "swing_bin": 1.5, "touch_top_bin": 1.5, "bin_cabinet": 1.5},
    materials={"body": "shell", "flap": "shell", "drawer": "shell", "base": "shell", "leg": "shell"},
    mass_range=(0.5, 50.0),  # kg: plastic swing bins to wooden tilt-out bin cabinets
    slots=(Slot("body", body), Slot("top", top, after=("body",))),
)
