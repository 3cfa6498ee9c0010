"""Doors: framed single and double doors, glazed French doors and sliding barn doors.

Parts: a frame standing on the floor (jambs, head, stops behind the closed leaves,
optional front casing); one or two leaves (flush slab, stile-and-rail panelled, or
glazed with glass lites) inset flush with the frame front, each hinged on a jamb
(revolute about the vertical front edge on the hinge side, opening towards the viewer,
-x, 0..1.45-1.9 rad); on each leaf a lever or a round knob on both faces at 0.9-1.05 m
(revolute about the leaf normal: levers turn tip-down 0..0.6-0.9 rad, knobs
±0.8-1.3 rad) and, on single doors, an optional deadbolt thumb turn on the back face
(revolute 0..pi/2) with a fixed key cylinder on the front. A barn door is a leaf hung
in front of a cased opening by straps and rollers on a rail over a header board; it
slides sideways (prismatic along y, about one leaf width) and has a fixed pull.
Joints: 1-6 movable. Sizes (metres): leaves 0.7-0.95 x 1.95-2.1 (double doors
0.55-0.9 per leaf), 35-45 mm thick; barn doors 0.8-1.1 wide.
"""

from __future__ import annotations

import math
from dataclasses import replace

from artipg.geometry import cuboid_between, cylinder
from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.frames import barn_hardware, door_frame, glazed_panel, panel_leaf, swing_clearance
from artipg.templates.handles import arch_handle, flat_bar_handle
from artipg.templates.mounting import free_edge_yz, mount_hinged, mount_sliding
from artipg.templates.panels import slab_door
from artipg.templates.turn_handles import DOOR_KNOBS, DOOR_LEVERS, matching, mount_turning, thumb_turn

# sub-category -> leaves (lo, hi), leaf width, leaf height
SIZES = {"single_door": ((1, 1), (0.7, 0.95), (1.95, 2.1)), "double_door": ((2, 2), (0.55, 0.9), (1.95, 2.2)),
         "french_door": ((1, 2), (0.6, 0.9), (1.95, 2.1)), "barn_door": ((1, 1), (0.8, 1.1), (1.95, 2.15))}
HANDLES = {**DOOR_LEVERS, **DOOR_KNOBS}
PULLS = {arch_handle: 1.0, flat_bar_handle: 1.0}  # long barn-door pulls
HALF_TURN = rot_z(math.pi)
ALONG_X = rot_y(math.pi / 2)  # local z -> +x


def glazed_leaf(p, width, height, thickness=None):
    """A French-door leaf: wide stiles and rails around a grid of glass lites."""
    rail = p.uniform("stile_width", 0.1, 0.14)
    return glazed_panel(p, width, height, thickness, "door", rows=p.integers("rows", 1, 5),
                        cols=p.integers("cols", 1, 3 if width > 0.6 else 2), rail=rail)


LEAVES = {"single_door": {slab_door: 3.0, panel_leaf: 3.0, glazed_leaf: 1.0},
          "double_door": {slab_door: 2.0, panel_leaf: 3.0, glazed_leaf: 1.0},
          "french_door": {glazed_leaf: 1.0}, "barn_door": {slab_door: 1.0, panel_leaf: 2.0}}


def frame(ctx):
    p = ctx.p
    n, w, h = SIZES[ctx.sub]
    n = p.integers("leaves", *n)
    W, H, t = p.uniform("leaf_width", *w), p.uniform("leaf_height", *h), p.uniform("thickness", 0.035, 0.045)
    root = ctx.builder.create_link("frame")
    if ctx.sub == "barn_door":
        Wo, Ho = W - 2 * p.uniform("overlap", 0.03, 0.06), H - p.uniform("top_overlap", 0.03, 0.06)
        part = root.add(door_frame(p.scope("frame"), Wo, Ho, t, casing=None, stops=False))
        return root, dict(n=1, W=W, H=H, t=t, Wo=Wo, Ho=Ho, under=p.uniform("undercut", 0.008, 0.015),
                          x_wall=part.anchor("front")[0], top=part.anchor("top")[2])
    ch, cf = p.uniform("hinge_gap", 0.002, 0.004), swing_clearance(t, W, p.uniform("edge_gap", 0.002, 0.003))
    under, top = p.uniform("undercut", 0.006, 0.015), p.uniform("top_gap", 0.002, 0.004)
    Wo = n * W + 2 * ch + n * cf
    root.add(door_frame(p.scope("frame"), Wo, H + under + top, t))
    return root, dict(n=n, W=W, H=H, t=t, Wo=Wo, ch=ch, under=under)


def _leaf(tmpl, q, W, H, t):
    out = tmpl(q, W, H, thickness=t)
    return out if isinstance(out, tuple) else (out, None)


def leaves(ctx):
    root, d = ctx.out["frame"]
    p, t, W, H = ctx.p, d["t"], d["W"], d["H"]
    if ctx.sub == "barn_door":
        return _barn(ctx, root, d)
    sides = ("+y", "-y") if d["n"] == 2 else (p.choice("hinge", ("+y", "-y")),)
    lim = p.uniform("limit", 1.45, 1.9)
    leaf0, glass0 = _leaf(ctx.choose("leaf", LEAVES[ctx.sub]), p.scope("leaf"), W, H, t)
    out = []
    for i, side in enumerate(sides):  # a pair of doors has two identical leaves
        s = 1.0 if side == "+y" else -1.0
        cy = s * (d["Wo"] / 2 - d["ch"] - W / 2)
        leaf, glass = (leaf0, glass0) if i == 0 else (replace(leaf0), glass0 and replace(glass0))
        link = mount_hinged(ctx.builder, root, leaf, front_x=t, center_yz=(cy, d["under"] + H / 2), size_yz=(W, H),
                            side=side, limits=(0.0, lim), name="leaf")
        if glass is not None:
            link.add(glass, leaf.pose)
        out.append((link, leaf, side, s))
    return out


def hardware(ctx):
    if ctx.sub == "barn_door":
        return
    p, d = ctx.p, ctx.out["frame"][1]
    tmpl = ctx.choose("handle", HANDLES)
    lever = tmpl in DOOR_LEVERS
    a = p.uniform("lever_limit", 0.6, 0.9) if lever else p.uniform("knob_limit", 0.8, 1.3)
    lim = (0.0, a) if lever else (-a, a)
    hz = p.uniform("handle_height", 0.9, 1.05) - d["under"] - d["H"] / 2
    leaves, backset = ctx.out["leaves"], p.uniform("backset", 0.06, 0.07)
    # deadbolts on solid leaves only: a glazed leaf's muntins leave no room for a grip
    lock = d["n"] == 1 and all(leaf.template != "glazed_leaf" for _, leaf, _, _ in leaves) and p.flag("deadbolt", 0.4)
    # one hardware design on both faces of every leaf, levers pointing to the hinges
    handles = iter(matching(tmpl, p.scope("handle"), [sg * s for *_, s in leaves for sg in (1.0, -1.0)]))
    for link, leaf, side, s in leaves:
        hy, _ = free_edge_yz(side, (d["W"], d["H"]), backset)
        front = leaf.pose @ translation(-d["t"], hy, hz)
        back = leaf.pose @ translation(0.0, hy, hz) @ HALF_TURN
        for T in (front, back):
            mount_turning(ctx.builder, link, next(handles), T, lim, name="handle")
        if lock:
            dz = p.uniform("deadbolt_offset", 0.12, 0.18)
            mount_turning(ctx.builder, link, thumb_turn(p.scope("thumb_turn")), back @ translation(0, 0, dz),
                          (0.0, math.pi / 2), name="thumb_turn")
            r = p.uniform("cylinder_radius", 0.014, 0.02)
            link.add(Part("handle", "key_cylinder", [cylinder(r, 0.008, front @ translation(0.004 - 0.008, 0, dz)
                                                              @ ALONG_X, role="rose")]))


def _barn(ctx, root, d):
    p, t, W, H = ctx.p, d["t"], d["W"], d["H"]
    travel, s = W + p.uniform("extra_travel", 0.0, 0.05), p.choice("direction", (1.0, -1.0))
    span = sorted((-s * (W / 2 + 0.05), s * (W / 2 + travel + 0.05)))
    zt = d["under"] + H  # leaf top
    track, hangers = barn_hardware(p.scope("track"), W, t, span, zt - d["top"] + 0.05)
    xb = d["x_wall"] - track.anchor("wall")[0]  # leaf back face
    root.add(track, translation(xb, 0.0, zt))
    y = s * (d["Wo"] + d["top"] - d["Ho"]) / 2  # a floor guide on the jamb the leaf slides to
    root.add(Part("frame", "floor_guide", [cuboid_between((xb, y - 0.01, 0.0), (d["x_wall"], y + 0.01, 0.05))]))
    leaf, _ = _leaf(ctx.choose("leaf", LEAVES[ctx.sub]), p.scope("leaf"), W, H, t)
    link = mount_sliding(ctx.builder, root, leaf, origin=translation(xb, 0.0, zt - H / 2), axis=(0.0, s, 0.0),
                         limits=(0.0, travel), name="leaf")
    link.add(hangers, translation(0, 0, H / 2))
    pull = ctx.choose("handle", PULLS)(p.scope("pull"), length=p.uniform("pull_length", 0.2, 0.35))
    py = leaf.anchors.get("stile", (0.0, W / 2 - 0.08, 0.0))[1]
    link.add(pull, translation(-t, -s * py, p.uniform("pull_height", 0.95, 1.1) - d["under"] - H / 2))
    return [(link, leaf, None, s)]


RULE = Category(
    name="door",
    subcategories={"single_door": 3.0, "double_door": 1.5, "french_door": 1.0, "barn_door": 1.0},
    fixed_base=True,  # set in a wall opening: simulated mounted, not dropped on a floor
    mass_range=(10.0, 150.0),  # kg: frame + leaves: hollow-core interior doors to glazed double doors
    slots=(Slot("frame", frame), Slot("leaves", leaves, after=("frame",)),
           Slot("hardware", hardware, after=("leaves",))),
)
