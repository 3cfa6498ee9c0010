"""Safes: combination-dial safes, electronic keypad safes, hotel (in-room) safes and
tall cabinet safes.

Parts: a thick-walled open-front body (optionally on feet) with 0-2 shelves inside;
a thick stepped door (a front plate over the whole front and a plug filling the
opening, optional barrel-hinge knuckles) hinged on the left or right front edge
(revolute about z, 0..1.5-2.2 rad); on the door a column (or, on short safes, a row)
of controls: a combination dial with a graduated ring (continuous about the door
normal), a keypad housing with a display and a 4 x 3 grid of keys (hotel safes also
4 x 4; each key prismatic, pressed 3-6 mm), and a handle that retracts the bolts: a
3-5 spoke wheel, a lever pointing to the hinge or a round knob (revolute about the
door normal, 0..1.2-1.6 rad).
Joints: 3-18 movable. Sizes (metres): 0.2-1.0 tall, 0.3-0.7 wide; walls 20-50 mm;
doors 35-95 mm thick.
"""

from __future__ import annotations

from artipg.geometry import ring
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass
from artipg.templates.controls import dial_knob, fluted_knob, mount_keypad, mount_knob, rect_button, round_knob
from artipg.templates.mounting import mount_hinged
from artipg.templates.panels import shelf_board
from artipg.templates.safes import keypad_housing, safe_door
from artipg.templates.supports import bun_feet
from artipg.templates.turn_handles import ball_knob, flat_lever, mount_turning, round_lever, spoke_wheel

# sub-category -> width, depth, height, wall, controls on the door
SIZES = {"dial_safe": ((0.35, 0.6), (0.35, 0.55), (0.4, 0.8), (0.025, 0.04), ("dial", "handle")),
         "keypad_safe": ((0.3, 0.5), (0.3, 0.45), (0.3, 0.6), (0.02, 0.035), ("keypad", "handle")),
         "hotel_safe": ((0.35, 0.45), (0.3, 0.4), (0.2, 0.3), (0.02, 0.03), ("keypad", "handle")),
         "cabinet_safe": ((0.45, 0.7), (0.4, 0.6), (0.7, 1.0), (0.03, 0.05), ("dial", "keypad", "handle"))}
HANDLES = {"dial_safe": {spoke_wheel: 3.0, round_lever: 1.0, flat_lever: 1.0},
           "keypad_safe": {round_lever: 2.0, flat_lever: 1.0, ball_knob: 1.0, spoke_wheel: 1.0},
           "hotel_safe": {round_lever: 1.0, flat_lever: 1.0, ball_knob: 2.0},
           "cabinet_safe": {spoke_wheel: 3.0, round_lever: 1.0}}
DIALS = {dial_knob: 2.0, fluted_knob: 1.0, round_knob: 1.0}
_Z = rot_y(-1.5707963267948966)  # ring axis (z) -> -x


def body(ctx):
    p = ctx.p
    w, d, h, t, _ = SIZES[ctx.sub]
    W, D, H, wall = p.uniform("width", *w), p.uniform("depth", *d), p.uniform("height", *h), p.uniform("wall", *t)
    root = ctx.builder.create_link("body")
    z0 = p.uniform("feet", 0.02, 0.05) if ctx.sub == "cabinet_safe" or p.flag("has_feet", 0.3) else 0.0
    if z0:
        root.add(bun_feet(p.scope("feet"), D, W, z0))
    root.add(carcass(p.scope("body"), D, W, H - z0, wall=wall, back=wall), translation(0, 0, z0 + (H - z0) / 2))
    n = p.integers("shelves", 0, 2 if H > 0.5 else 1)
    for i in range(n):
        z = z0 + wall + (i + 1) * (H - z0 - 2 * wall) / (n + 1)
        depth = D - 2 * wall - 0.08  # behind the door's plug
        root.add(shelf_board(p.scope(f"shelf{i}"), W - 2 * wall, depth, 0.012), translation(D / 2 - wall - depth / 2,
                                                                                             0, z))
    return root, dict(W=W, D=D, H=H - z0, z0=z0, wall=wall)


def door(ctx):
    root, b = ctx.out["body"]
    p, W, H = ctx.p, b["W"], b["H"]
    side = p.choice("hinge", ("+y", "-y"))
    s = 1.0 if side == "+y" else -1.0
    part = safe_door(p.scope("door"), W, H, b["wall"], s)
    link = mount_hinged(ctx.builder, root, part, front_x=-b["D"] / 2, center_yz=(0.0, b["z0"] + H / 2),
                        size_yz=(W, H), side=side, limits=(0.0, p.uniform("limit", 1.5, 2.2)))
    return link, part, s


def controls(ctx):
    link, part, s = ctx.out["door"]
    p, b = ctx.p, ctx.out["body"][1]
    items = []  # (kind, half width, half height, what to mount)
    for kind in SIZES[ctx.sub][4]:
        q = p.scope(kind)
        if kind == "dial":
            rd = q.uniform("dial_radius", 0.028, 0.045)
            dial = ctx.choose("dial", DIALS)(q, radius=rd)
            dial.semantic = "dial"
            r = rd + 0.015  # with its graduated ring
            items.append((kind, r, r, dial))
        elif kind == "keypad":
            rows, cols = 4, q.integers("columns", 3, 4 if ctx.sub == "hotel_safe" else 3)  # phone layout
            pitch, g, reach = q.uniform("pitch", 0.013, 0.02), q.uniform("gap", 0.001, 0.0018), q.uniform(
                "reach", 0.01, 0.014)
            key = rect_button(q.scope("key"), width=pitch - g, height=0.8 * pitch - g, reach=reach)
            stand = -key.anchors["back"][0]  # the frame rises past the keys' back faces, g / 2 around them
            frame, screen = keypad_housing(q, cols * pitch, rows * 0.8 * pitch, stand + 0.4 * (reach - stand), g / 2)
            _, hw, lo = frame.anchors["corner"]
            hi = screen.anchors["top"][2]  # the housing spans -lo..hi about the key field's centre
            items.append((kind, hw, (lo + hi) / 2, (key, frame, screen, rows, cols, pitch, (hi - lo) / 2)))
        else:  # levers point towards the hinge
            h = ctx.choose("handle", HANDLES[ctx.sub])(q, side=s)
            r = h.anchors["reach"][0] + 0.005
            items.append((kind, r, r, h))
    # a column towards the free edge, or a row across the door when it is short
    gap, W, H = 0.02, b["W"], b["H"]
    column = sum(2 * it[2] for it in items) + gap * (len(items) - 1) < 0.8 * H
    k = 2 if column else 1
    cur = (sum(2 * it[k] for it in items) + gap * (len(items) - 1)) / 2
    yc = -s * p.uniform("offset", 0.0, 0.15) * W if column else 0.0
    tf = -part.anchors["front"][0]
    for kind, hw, hh, obj in items:
        half = hh if column else hw
        y, z = (yc, cur - half) if column else (-s * (cur - half), 0.0)  # rows run from the free side
        cur -= 2 * half + gap
        T = part.pose @ translation(-tf, y, z)
        if kind == "dial":
            rd = hw - 0.015
            link.add(Part("panel", "dial_ring", [ring(rd + 0.012, rd + 0.002, 0.003, pose=T @ translation(-0.0015, 0, 0)
                                                      @ _Z, role="ring")]))
            mount_knob(ctx.builder, link, obj, T, continuous=True, name="dial")
        elif kind == "keypad":
            key, frame, screen, rows, cols, pitch, off = obj
            Tk = T @ translation(0, 0, -off)  # the key field's centre
            link.add(frame, Tk)
            link.add(screen, Tk)
            mount_keypad(ctx.builder, link, key, Tk, rows, cols, (pitch, 0.8 * pitch))
        else:
            mount_turning(ctx.builder, link, obj, T, (0.0, p.uniform("handle_limit", 1.2, 1.6)))


RULE = Category(
    name="safe",
    subcategories={"dial_safe": 2.0, "keypad_safe": 2.0, "hotel_safe": 1.0, "cabinet_safe": 1.0},
    materials={"body": "shell", "door": "shell", "leg": "shell", "shelf": "shell"},
    mass_range=(5.0, 150.0),  # kg: hotel safes to cabinet safes
    slots=(Slot("body", body), Slot("door", door, after=("body",)), Slot("controls", controls, after=("door",))),
)
