"""Toilets: two-piece (close-coupled cistern), one-piece and wall-hung.

Parts: a vitreous-china body -- a tapered bowl on a pedestal (floor-standing) or hung
from a wall panel (wall-hung), a rear deck that carries the cistern or meets the wall;
a cistern (tank) with a lid lifted straight off (two-piece, one-piece); a seat ring
(closed or open-front) and a seat lid (cover) hinged about one rear axis, the lid
resting on the seat; flush controls: a trip lever on the tank's front (two-piece), one
or two push buttons on the tank lid (one-piece, some two-piece) or a flush plate with
one or two buttons on the wall (wall-hung).
Joints: seat and seat lid revolute about one rear hinge axis (+y), both children of
the body: the lid rises 100-110 degrees or until it rests a finger's width off the tank
or wall; the seat (under the lid) rises until just before the open lid, so raising it
with the lid down needs the lid opened first; tank lid prismatic up (0.1-0.2 m); lever
revolute about the axis normal to the tank face (30-45 degrees); flush buttons
prismatic (3-6 mm).
Sizes (metres): rim 0.38-0.44 above the floor; bowls 0.36-0.5 long, 0.33-0.39 wide;
two-piece 0.7-0.8 tall, 0.63-0.78 deep, tanks 0.4-0.52 wide; one-piece 0.54-0.72 tall;
wall-hung bowls 0.5-0.6 from the wall, the wall panel 1.0-1.25 tall.
Toilets are fixtures (bolted to the floor or hung on a wall carrier): ``fixed_base``.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.controls import BUTTONS, mount_button_row, round_button
from artipg.templates.toilets import (BOWLS, SEAT_LIDS, TANKS, flush_lever, hinge_barrel, seat_ring, swing_limit,
                                      tank_lid, toilet_bowl)

# sub-category -> rim height, bowl depth, hinge-to-tank (or wall) gap, tank (depth, width, height) ranges
SUBS = {
    "two_piece": ((0.38, 0.44), (0.17, 0.23), (0.08, 0.12), ((0.16, 0.22), (0.4, 0.52), (0.28, 0.36))),
    "one_piece": ((0.38, 0.44), (0.17, 0.23), (0.075, 0.11), ((0.18, 0.25), (0.34, 0.44), (0.15, 0.26))),
    "wall_hung": ((0.38, 0.43), (0.24, 0.31), (0.09, 0.13), None),
}
FLUSH = {"lever": 3.0, "top_buttons": 1.0}
SEATS = {"closed": 5.0, "open_front": 1.0}
TOP_BUTTONS = {round_button: 1.0}
LID_ON_TOP = 0.0005  # the tank lid's rest gap
STOP = 0.04  # open seats and lids stop this far off the tank or wall: room for a finger behind them


def body(ctx):
    p, b = ctx.p, ctx.builder
    rim_r, depth_r, gap_r, tank_r = SUBS[ctx.sub]
    outline = ctx.choose("bowl", BOWLS)(p.scope("outline"))
    a, bw, n = outline
    rim = p.uniform("rim_height", *rim_r)
    x_h = a + p.uniform("hinge_setback", 0.015, 0.04)
    x_t = x_h + p.uniform("tank_gap", *gap_r)
    root = b.create_link("body")
    obstacles = []  # boxes (x0, z0, z1) the seat and lid must not swing into
    if tank_r is None:  # wall-hung: a wall panel to the floor, the bowl cantilevered from it
        tw, ww = p.uniform("wall_depth", 0.02, 0.05), p.uniform("wall_width", 0.5, 0.65)
        hw = p.uniform("wall_height", 1.0, 1.25)
        root.add(Part("body", "wall_panel", [cuboid(tw, ww, hw, translation(x_t + tw / 2, 0, hw / 2), role="wall")]))
        depth = p.uniform("bowl_depth", *depth_r)
        root.add(toilet_bowl(p.scope("bowl"), outline, rim, depth, False, x_t, 1.6 * bw, rim - 0.75 * depth))
        obstacles.append((x_t, 0.0, hw))
        return root, outline, rim, x_h, x_t, None, obstacles
    D, W, H = (p.uniform(k, *r) for k, r in zip(("tank_depth", "tank_width", "tank_height"), tank_r))
    floor = 0.0 if ctx.sub == "one_piece" and p.flag("skirted", 0.6) else rim - p.uniform("deck", 0.08, 0.14)
    root.add(toilet_bowl(p.scope("bowl"), outline, rim, p.uniform("bowl_depth", *depth_r), True, x_t + D,
                         min(0.8 * W, 1.5 * bw), floor))
    root.add(ctx.choose("tank", TANKS)(p.scope("tank"), x_t, rim, D, W, H))
    lid = tank_lid(p.scope("tank_lid"), D, W)
    top = rim + H + LID_ON_TOP
    link = b.create_link("tank_lid", root)
    link.set_joint("prismatic", translation(x_t + D / 2, 0, top), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, p.uniform("lid_lift", 0.1, 0.2)))
    link.add(lid)
    obstacles += [(x_t, rim, top), (x_t - lid.anchors["size"][0] / 2 + D / 2, top, top + lid.anchors["top"][2])]
    return root, outline, rim, x_h, x_t, (D, W, H, link, lid), obstacles


def flush(ctx):
    """Flush controls; returns the obstacle boxes they add in front of the tank or wall."""
    root, outline, rim, x_h, x_t, tank, obstacles = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    if tank is None:  # a flush plate on the wall, 0.5-0.7 m above the rim
        t, w, h = p.uniform("plate_depth", 0.006, 0.012), p.uniform("plate_width", 0.15, 0.25), p.uniform(
            "plate_height", 0.1, 0.16)
        z = rim + p.uniform("plate_rise", 0.5, 0.7)
        root.add(Part("panel", "flush_plate", [cuboid(t, w, h, translation(x_t - t / 2, 0, z), role="plate")]))
        k = p.integers("buttons", 1, 2)
        pitch = (w - 0.03) / k
        mount_button_row(p.scope("plate"), b, root, ctx.choose("button", BUTTONS), k, translation(x_t - t, 0, z),
                         -(w - 0.03) / 2, (w - 0.03) / 2, 0.0, radius=min(0.03, pitch / 2 - 0.006, h / 2 - 0.015),
                         square=(pitch - 0.012, h - 0.03))
        return [(x_t - t - 0.012, z - h / 2, z + h / 2)]
    D, W, H, lid_link, lid = tank
    kind = "top_buttons" if ctx.sub == "one_piece" else ctx.choose("flush", FLUSH)
    if kind == "top_buttons":
        k = p.integers("buttons", 1, 2)
        r = p.uniform("button_radius", 0.018, 0.03) if k == 1 else p.uniform("button_radius", 0.012, 0.018)
        pose = translation(0, 0, lid.anchors["top"][2]) @ rot_y(math.pi / 2)  # presses down (-z)
        half = k * (r + 0.006)
        mount_button_row(p.scope("top"), b, lid_link, ctx.choose("button", TOP_BUTTONS), k, pose, -half, half, 0.0,
                         radius=r, square=(2 * r, 2 * r))
        return [(x_t - 0.012, rim + H, rim + H + 0.06)]
    lever = flush_lever(p.scope("lever"))
    L, rh, reach = lever.anchors["reach"]
    y = W / 2 - p.uniform("lever_inset", 0.03, 0.06) - rh
    z = rim + H - p.uniform("lever_drop", 0.035, 0.07)
    turn = p.uniform("lever_turn", 0.5, 0.8)
    link = b.create_link("lever", root)
    link.set_joint("revolute", translation(x_t, y, z), axis=(1.0, 0.0, 0.0), limits=(0.0, turn))
    link.add(lever)
    return [(x_t - reach - 0.01, z - L * math.sin(turn) - rh, z + rh)]


def seat(ctx):
    root, (a, bw, n), rim, x_h, x_t, tank, obstacles = ctx.out["body"]
    obstacles = obstacles + ctx.out["flush"]
    p, b = ctx.p, ctx.builder
    ts, k = p.uniform("thickness", 0.015, 0.025), p.uniform("scale", 0.96, 1.01)
    z_h = rim + 0.001 + ts  # the hinge axis at the seat's top face
    so = (a * k, bw * k, n)
    open_front = ctx.choose("seat", SEATS) == "open_front"
    r = p.uniform("pin_radius", 0.005, 0.008)
    c = r + 0.0015
    ring = seat_ring(p.scope("ring"), so, x_h, ts, open_front, c)
    root.add(hinge_barrel(p.scope("hinge"), z_h - rim, r, p.uniform("hinge_length", 0.04, 0.06)),
             translation(x_h, 0, z_h))
    rel = [(x0 - x_h, z0 - z_h, z1 - z_h) for x0, z0, z1 in obstacles]
    hinge = translation(x_h, 0, z_h)
    upper = swing_limit([((-x_h - so[0], -c), (-ts, 0.0))], rel, p.uniform("seat_swing", 1.75, 1.92), STOP)
    if not open_front or p.flag("open_front_lid", 0.2):
        tl, gap, kl = p.uniform("lid_thickness", 0.012, 0.022), 0.001, p.uniform("lid_width", 0.98, 1.02)
        sb = p.uniform("lid_setback", 0.025, 0.04)  # the seat's front lip stays free to lift it by
        lo = (so[0] - sb / 2, so[1] * kl, n)
        cover = ctx.choose("lid", SEAT_LIDS)(p.scope("lid"), lo, x_h - sb / 2, tl, gap, c)
        lid_upper = swing_limit([((-x_h - so[0] + sb, -c), (gap, gap + tl))], rel,
                                p.uniform("lid_swing", 1.75, 1.92), STOP)
        # the seat (under the lid, on the same axis) stops just before the open lid:
        # raising it with the lid down needs the lid opened first
        upper = min(upper, lid_upper - 0.02)
        lid_link = b.create_link("seat_lid", root)
        lid_link.set_joint("revolute", hinge, axis=(0.0, 1.0, 0.0), limits=(0.0, lid_upper))
        lid_link.add(cover)
    link = b.create_link("seat", root)
    link.set_joint("revolute", hinge, axis=(0.0, 1.0, 0.0), limits=(0.0, upper))
    link.add(ring)


RULE = Category(
    name="toilet",
    subcategories={"two_piece": 3.0, "one_piece": 2.0, "wall_hung": 2.0},
    fixed_base=True,  # bolted to the floor or hung on an in-wall carrier: simulated mounted
    # vitreous china bodies are hollow (8-12 mm walls): 'shell' averages them over the solid; seats are plastic
    materials={"body": "shell", "lid": "shell", "seat": "plastic", "panel": "plastic"},
    mass_range=(8.0, 70.0),  # kg: wall-hung bowls ~15-25 kg, two-piece toilets 30-50 kg
    slots=(Slot("body", body), Slot("flush", flush, after=("body",)), Slot("seat", seat, after=("body", "flush"))),
)
