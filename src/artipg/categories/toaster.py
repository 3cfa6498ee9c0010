"""Pop-up toasters: two-slot, four-slot (four slots in a row) and long-slot models.

Parts: a housing whose bread slots run front to back (x) and open at the top, over a
pocket for the crumb tray, on optional bun feet; one carriage lever per pair of slots,
its stem running in a vertical slot of the front (-x) end wall; a control column on
that wall with a browning knob (two on four-slot models, one per pair) above a row of
0-3 push buttons (cancel, bagel, defrost), each in a bezel; a crumb tray whose lip
closes the pocket at the bottom of the front wall.
Joints: levers prismatic down (-z) by 0.05-0.09 m (limited by the wall's height);
browning knobs revolute about x, 240-300 degrees; buttons prismatic into the wall
(3-6 mm); crumb tray prismatic out of the front (-x), 50-90 % of its length.
Sizes (metres): two-slot 0.24-0.3 deep, 0.13-0.19 wide, 0.17-0.21 tall; four-slot
0.26-0.32 x 0.22-0.31 x 0.18-0.21; long-slot 0.37-0.45 deep, 0.1-0.22 wide.
Slots 28-40 mm wide.
"""

from __future__ import annotations

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.appliance import stack_layout
from artipg.templates.controls import BUTTONS, KNOBS, mount_button_row, mount_knob
from artipg.templates.supports import bun_feet
from artipg.templates.toaster import GAP, carriage_lever, crumb_tray, toaster_housing

# sub-category -> slots (lo, hi), depth, height, side wall, wall between slots, knobs
SUBS = {
    "two_slot": ((2, 2), (0.24, 0.3), (0.17, 0.21), (0.025, 0.04), (0.02, 0.035), 1),
    "four_slot": ((4, 4), (0.26, 0.32), (0.18, 0.21), (0.025, 0.04), (0.018, 0.03), 2),
    "long_slot": ((1, 2), (0.37, 0.45), (0.17, 0.21), (0.035, 0.05), (0.025, 0.045), 1),
}


def body(ctx):
    p, b = ctx.p, ctx.builder
    (n_lo, n_hi), dr, hr, sr, ir, _ = SUBS[ctx.sub]
    n = p.integers("slots", n_lo, n_hi)
    D, H, s = p.uniform("depth", *dr), p.uniform("height", *hr), p.uniform("slot_width", 0.028, 0.04)
    side = p.uniform("side_wall", *sr)
    wi = p.uniform("inner_wall", *ir)
    W = 2 * side + n * s + (n - 1) * wi
    slots = [(-W / 2 + side + i * (s + wi), -W / 2 + side + i * (s + wi) + s) for i in range(n)]
    fh = p.uniform("foot_height", 0.005, 0.012) if p.flag("feet", 0.6) else 0.0
    floor, pocket = p.uniform("floor", 0.003, 0.006), p.uniform("pocket", 0.012, 0.02)
    zp = floor + pocket
    cols = ["lever", "controls", "lever"] if n == 4 else (["controls", "lever"] if p.flag("lever_right", 0.5)
                                                          else ["lever", "controls"])
    cw = W / len(cols)
    levers = []
    for i, kind in enumerate(cols):
        if kind != "lever":
            continue
        q = p.scope(f"lever{len(levers)}")
        yc = -W / 2 + cw * (i + 0.5)
        t = q.uniform("thickness", 0.01, 0.018)
        z = H - q.uniform("top_margin", 0.018, 0.035) - t / 2
        travel = min(q.uniform("travel", 0.05, 0.09), z - zp - 0.015 - t / 2)
        sw, sh = q.uniform("stem_width", 0.004, 0.008), 0.7 * t
        levers.append((q, yc, z, travel, (sw, sh, t)))
    wf_slots = [(yc, sw / 2 + GAP, z - travel - sh / 2 - GAP, z + sh / 2 + GAP)
                for _, yc, z, travel, (sw, sh, _) in levers]
    root = b.create_link("body")
    if fh:
        root.add(bun_feet(p.scope("feet"), 0.9 * D, 0.9 * W, fh))
    part = root.add(toaster_housing(p, D, W, H - fh, slots, side, floor, pocket, wf_slots), translation(0, 0, fh))
    wf = part.anchors["front_wall"][0]
    for q, yc, z, travel, (sw, sh, t) in levers:
        lever = carriage_lever(q, (wf - 0.002, sw, sh), max_width=cw - 0.012, thickness=t)
        link = b.create_link("lever", root)
        link.set_joint("prismatic", translation(-D / 2, yc, fh + z), axis=(0.0, 0.0, -1.0), limits=(0.0, travel))
        link.add(lever)
    return root, part, (D, W, H, fh, zp, cw, cols)


def controls(ctx):
    root, part, (D, W, H, fh, zp, cw, cols) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    yc = -W / 2 + cw * (cols.index("controls") + 0.5)
    R = min(p.uniform("knob_radius", 0.014, 0.022), cw / 2 - 0.008)
    n_knobs = SUBS[ctx.sub][5]
    k = p.integers("buttons", 0, 3)
    blocks = [2 * R] * n_knobs + ([p.uniform("button_row", 0.016, 0.02)] if k else [])
    span = H - fh - zp
    layout, _ = stack_layout(blocks, span, p.uniform("margin", 0.012, 0.02))
    front = translation(-D / 2, yc, fh + zp + span / 2)
    knob_t = ctx.choose("knob", KNOBS)
    for i, (z, h) in enumerate(layout[:n_knobs]):
        q = p.scope(f"knob{i}")
        mount_knob(b, root, knob_t(q, radius=h / 2), front @ translation(0, 0, z - h / 2), continuous=False,
                   limits=(0.0, q.uniform("turn", 4.2, 5.2)))
    if k:
        z, h = layout[-1]
        pitch = (cw - 0.01) / k
        mount_button_row(p.scope("buttons"), b, root, ctx.choose("button", BUTTONS), k, front,
                         -(cw - 0.01) / 2, (cw - 0.01) / 2, z - h / 2, radius=min(0.007, pitch / 2 - 0.004),
                         square=(min(0.016, pitch - 0.008), min(0.01, h - 0.006)))


def tray(ctx):
    root, part, (D, W, H, fh, zp, cw, cols) = ctx.out["body"]
    lo, hi = part.anchors["pocket_lo"], part.anchors["pocket_hi"]
    length, width = hi[0] - lo[0] - GAP, hi[1] - lo[1] - 2 * GAP
    wf = part.anchors["front_wall"][0]
    link = ctx.builder.create_link("tray", root)
    link.set_joint("prismatic", translation(-D / 2, 0, fh + lo[2] + GAP), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, ctx.p.uniform("pull", 0.5, 0.9) * length))
    link.add(crumb_tray(ctx.p, length, width, (wf, hi[2] - lo[2] - 2 * GAP)))


RULE = Category(
    name="toaster",
    subcategories={"two_slot": 3.0, "four_slot": 2.0, "long_slot": 1.0},
    # the housing's walls are double sheet-metal skins around the elements: ~250 kg/m^3 averaged over the solid
    materials={"body": "insulated", "lever": "plastic", "tray": "plastic", "leg": "rubber"},
    mass_range=(0.8, 5.0),  # kg: two-slot ~1-2 kg to four-slot steel models ~3.5 kg
    slots=(Slot("body", body), Slot("controls", controls, after=("body",)), Slot("tray", tray, after=("body",))),
)
