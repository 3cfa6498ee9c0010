"""Remote controls lying on a table: TV remotes, air-conditioner remotes and slim media
(streaming) remotes.

Parts: a flat handset body (IR end at +x, a dark IR window on that end) with a battery
pocket in its bottom at the -x end; a sliding battery cover in the pocket; push
buttons on the top face, each in a collar: a power button, on TV remotes a 3 x 4
number grid, a navigation cross (select button and four arrows), volume and channel
keys and 1-3 rows of function keys; on air-conditioner remotes an LCD window over a
2-3 x 2-4 grid of large keys; on media remotes a large navigation cross over a
2-column grid of 1-2 rows.
Joints: every button prismatic into the body (1-2 mm travel); battery cover prismatic
out of the -x end (40-80 % of its length).
Sizes (metres): TV 0.045-0.058 wide, 18-26 mm thick, 0.16-0.24 long (from its keys);
air-conditioner 0.05-0.065 wide, 0.12-0.19 long; media 0.033-0.042 wide, 0.1-0.17 long.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.controls import BUTTONS, button_bezel, mount_button, mount_keypad, rect_button, round_button
from artipg.templates.remote import GAP, battery_cover, end_window, handset, lcd_window

UP = rot_y(math.pi / 2)  # control frames (protruding -x, "up" +z) turned to protrude +z with "up" towards +x
# sub-category -> width, thickness, key pitch along x, grid (cols, rows lo, rows hi), blocks from the IR end
SUBS = {
    "tv": ((0.045, 0.058), (0.018, 0.026), (0.011, 0.014), (3, 4, 4), ("power", "grid", "nav", "rockers", "extra")),
    "air_conditioner": ((0.05, 0.065), (0.018, 0.025), (0.013, 0.017), (3, 2, 4), ("screen", "power", "grid")),
    "media": ((0.033, 0.042), (0.014, 0.02), (0.011, 0.014), (2, 1, 2), ("power", "nav", "grid")),
}


def _key(p, kind, cell, height, fill):
    """One push-button cap filling ``fill`` of its ``cell`` (y, x extents, metres; round
    caps take the smaller), and its collar: caps stay 4.5 mm inside the cell, so a
    neighbour's collar (0.6 mm gap, walls up to 3 mm) never reaches them."""
    size = [min(fill * c, c - 0.0045) for c in cell]
    size = [min(size)] * 2 if kind is round_button else size
    travel = p.uniform("key_travel", 0.001, 0.002)
    reach = height + travel + 0.002  # the cap's height over the stand-off (travel + a clearance up to 2 mm)
    cap = round_button(p, radius=size[0] / 2, reach=reach, travel=travel) if kind is round_button else \
        rect_button(p, width=size[0], height=size[1], reach=reach, travel=travel)
    return cap, button_bezel(p.scope("collar"), cap, gap=0.0006)


def body(ctx):
    p, b = ctx.p, ctx.builder
    wr, tr, pr, (cols, r_lo, r_hi), blocks = SUBS[ctx.sub]
    W, T, pitch = p.uniform("width", *wr), p.uniform("thickness", *tr), p.uniform("pitch", *pr)
    Wu = W - 2 * p.uniform("side_margin", 0.005, 0.008)
    rows = p.integers("rows", r_lo, r_hi)
    nav = min(Wu, p.uniform("nav_size", 0.03, 0.042))
    heights = {"power": pitch, "screen": p.uniform("screen_length", 0.03, 0.045), "grid": rows * pitch, "nav": nav,
               "rockers": p.uniform("rocker_length", 0.025, 0.035), "extra": p.integers("extra_rows", 1, 3) * pitch}
    gap = p.uniform("block_gap", 0.005, 0.01)
    top, grip = p.uniform("top_margin", 0.008, 0.015), p.uniform("grip_length", 0.02, 0.045)
    L = top + sum(heights[k] for k in blocks) + gap * (len(blocks) - 1) + grip
    pocket = (p.uniform("cover_length", 0.35, 0.5) * L, W - 2 * p.uniform("rim", 0.004, 0.006),
              p.uniform("pocket_depth", 0.0025, 0.0035))
    root = b.create_link("body")
    root.add(handset(p, L, W, T, pocket))
    root.add(end_window(p, p.uniform("window_width", 0.4, 0.7) * W, 0.5 * T), translation(L / 2, 0, T / 2))
    x, layout = L / 2 - top, []
    for k in blocks:
        layout.append((k, x - heights[k] / 2, heights[k]))
        x -= heights[k] + gap
    return root, (L, W, T, Wu, pitch, cols, rows, pocket), layout


def keys(ctx):
    root, (L, W, T, Wu, pitch, cols, rows, _), layout = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    kind = ctx.choose("key", BUTTONS)
    cap_h = p.uniform("cap_height", 0.0015, 0.003)
    fill = p.uniform("key_fill", 0.6, 0.8)  # cap size over pitch; the collars fill the rest
    for name, xc, h in layout:
        q = p.scope(name)
        pose = translation(xc, 0, T) @ UP
        if name == "power":
            y = q.uniform("offset", 0.0, 0.35) * Wu
            cap, collar = _key(q, round_button, (min(h, Wu / 3),) * 2, cap_h, fill)
            root.add(collar, translation(0, y, 0) @ pose)
            mount_button(b, root, cap, translation(0, y, 0) @ pose)
        elif name == "screen":
            root.add(lcd_window(q, h, q.uniform("screen_width", 0.7, 0.85) * W), translation(xc, 0, T))
        elif name in ("grid", "extra"):
            n_rows, n_cols = (rows, cols) if name == "grid" else (round(h / pitch), cols + 1)
            cw = Wu / n_cols
            cap, collar = _key(q, kind, (cw, pitch), cap_h, fill)
            mount_keypad(b, root, cap, pose, n_rows, n_cols, (cw, pitch), collar)
        elif name == "nav":
            s = h / 3  # select in the middle, arrows around it on a 3 x 3 grid
            for i, (dy, dz) in enumerate(((0, 0), (0, s), (0, -s), (s, 0), (-s, 0))):
                cap, collar = _key(q.scope(f"k{i}"), round_button if i == 0 else rect_button, (s, s), cap_h, fill)
                T_k = pose @ translation(0, dy, dz)
                root.add(collar, T_k)
                mount_button(b, root, cap, T_k)
        else:  # volume and channel keys, long along x
            for i, y in enumerate((-Wu / 4, Wu / 4)):
                cap, collar = _key(q.scope(f"k{i}"), rect_button, (Wu / 2, h), cap_h, 0.8)
                T_k = translation(0, y, 0) @ pose
                root.add(collar, T_k)
                mount_button(b, root, cap, T_k)


def cover(ctx):
    root, (L, W, T, *_, (pl, pw, pd)), _ = ctx.out["body"]
    link = ctx.builder.create_link("cover", root)
    link.set_joint("prismatic", translation(-L / 2, 0, GAP), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, ctx.p.uniform("slide", 0.4, 0.8) * pl))
    link.add(battery_cover(ctx.p, pl - GAP, pw - 2 * GAP, pd - 2 * GAP))


RULE = Category(
    name="remote",
    subcategories={"tv": 3.0, "air_conditioner": 2.0, "media": 1.5},
    materials={"body": "shell", "cover": "plastic", "button": "rubber"},
    mass_range=(0.03, 0.3),  # kg without batteries: slim media remotes ~40 g to large TV remotes ~150 g
    slots=(Slot("body", body), Slot("keys", keys, after=("body",)), Slot("cover", cover, after=("body",))),
)
