"""Lighters: flip-top (petrol) lighters, disposable gas lighters and long utility lighters.

Parts and joints per sub-category:
- flip-top: a metal bottom case with the insert's chimney and the flint wheel in two
  ears above it; a hollow lid on a side hinge (axis x along the +y side of the case
  top), revolute 0 (closed) to 2.7-3.05 rad (flipped over beside the case); the
  wheel continuous about its axle (x).
- disposable: a plastic tank (oval or rounded), a steel hood round the flint wheel
  (continuous about y) and the gas lever behind it, prismatic down 2-3 mm.
- utility: a handle with a trigger opening closed by a guard bar, the trigger
  prismatic back (+x) 4-7 mm, a child-lock slider on top prismatic back 3-4 mm, and
  a long metal nozzle forward (-x) from a collar; it lies on the handle's flat bottom.
Sizes (metres): flip-top cases 0.034-0.04 wide, 0.012-0.015 deep, about as tall, lids
0.45-0.55 of the width tall (Zippo: 38 x 13 x 57 mm); disposable tanks 0.052-0.072
tall (0.06-0.082 with hood and wheel: BIC J3-J6, Clipper), 0.02-0.026 wide,
0.011-0.015 deep; utility handles 0.09-0.12 long with nozzles 0.1-0.18 (0.2-0.3
overall).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.lighters import (TANKS, WHEELS, collar, flip_case, flip_lid, gas_lever, hood, lock_slider,
                                       nozzle, trigger, utility_handle)

CLEAR = 0.001  # moving parts off the fixed ones


def flip_top(ctx):
    p = ctx.p
    W, D = p.uniform("width", 0.034, 0.04), p.uniform("depth", 0.012, 0.015)
    H, hl = p.uniform("height", 0.95, 1.05) * W, p.uniform("lid_height", 0.45, 0.55) * W
    wall, gap, rh = p.uniform("lid_wall", 0.0007, 0.001), p.uniform("hinge_gap", 0.0008, 0.0012), 0.0012
    hy = W / 2 + gap  # the hinge axis, outside the case's +y side
    inner_top = H + hl - wall - 0.0015  # what stays under the closed lid
    rw = p.uniform("wheel_radius", 0.0035, 0.0045)
    ww = p.uniform("wheel_width", 0.25, 0.35) * D
    yw = W / 2 - wall - CLEAR - rw
    zw = min(H + rw + p.uniform("wheel_rise", 0.003, 0.006), inner_top - rw)
    # the lid's far wall swings up past the chimney's top corner: keep the chimney
    # in from it by the most that wall moves inward on the way (hc^2 / 4A)
    top = H + p.uniform("chimney", 0.75, 0.9) * (inner_top - H)
    A = W + gap - wall
    y0 = -W / 2 + wall + (top - H) ** 2 / (4 * A) + 0.0015
    y1 = yw - rw - CLEAR
    root = ctx.builder.create_link("case")
    root.add(flip_case(p, W, D, H, (y0, y1, top, p.uniform("chimney_wall", 0.0005, 0.0008)), rh, hy,
                       (ww / 2 + 0.0006, yw, zw + 0.3 * rw, 0.8 * rw)))
    wheel = ctx.builder.create_link("wheel", root)
    wheel.set_joint("continuous", translation(0.0, yw, zw) @ rot_z(math.pi / 2), axis=(0.0, 1.0, 0.0))  # axle along x
    wheel.add(ctx.choose("wheel", WHEELS)(p, rw, ww))
    lid = ctx.builder.create_link("lid", root)
    lid.set_joint("revolute", translation(0.0, hy, H), axis=(-1.0, 0.0, 0.0),
                  limits=(0.0, p.uniform("open", 2.7, 3.05)))
    lid.add(flip_lid(p, W, D, hl, wall, gap, rh))


def disposable(ctx):
    p = ctx.p
    W, D, H = p.uniform("width", 0.02, 0.026), p.uniform("depth", 0.011, 0.015), p.uniform("height", 0.052, 0.072)
    root = ctx.builder.create_link("body")
    root.add(ctx.choose("tank", TANKS)(p, W, D, H))
    rw = p.uniform("wheel_radius", 0.28, 0.33) * D
    inner = p.uniform("hood_gap", 0.19, 0.25) * W  # half the gap between the hood's plates
    ww = 2 * inner - 0.0008
    xw, zw = -D / 2 + rw + 0.0005, H + rw + 0.0008
    t = p.uniform("hood_thickness", 0.0004, 0.0006)
    root.add(hood(p, xw - rw - 0.0008, D / 2, inner, t, H - 0.004, zw + p.uniform("hood_top", 0.2, 0.5) * rw))
    wheel = ctx.builder.create_link("wheel", root)
    wheel.set_joint("continuous", translation(xw, 0.0, zw), axis=(0.0, 1.0, 0.0))
    wheel.add(ctx.choose("wheel", WHEELS)(p, rw, ww))
    travel = p.uniform("lever_travel", 0.002, 0.003)
    x0 = xw + rw + CLEAR
    lever = ctx.builder.create_link("lever", root)
    lever.set_joint("prismatic", translation(x0, 0.0, H + travel + 0.0005), axis=(0.0, 0.0, -1.0), limits=(0.0, travel))
    # the lever reaches a little past the tank's back (a thumb rest)
    lever.add(gas_lever(p, D / 2 + p.uniform("overhang", 0.001, 0.003) - x0, 2 * inner - 0.0006,
                        p.uniform("lever_thickness", 0.002, 0.003)))


def utility(ctx):
    p = ctx.p
    L, W, H = p.uniform("length", 0.09, 0.12), p.uniform("width", 0.018, 0.024), p.uniform("height", 0.03, 0.04)
    x0, lo = p.uniform("guard_front", 0.01, 0.015), p.uniform("opening", 0.018, 0.026)
    z0, z1 = p.uniform("guard_bar", 0.004, 0.006), p.uniform("opening_top", 0.45, 0.55) * H
    root = ctx.builder.create_link("handle")
    hf = p.uniform("front_height", 0.7, 0.85) * H  # the handle rises from its nose to the grip
    root.add(utility_handle(p, L, W, H, hf, (x0, x0 + lo, z0, z1)))
    zn = 0.5 * (z1 + hf)
    rn = p.uniform("nozzle_radius", 0.0035, 0.005)
    root.add(nozzle(p, p.uniform("nozzle_length", 0.1, 0.18), rn, 0.0006), translation(0.0, 0.0, zn))
    root.add(collar(p, rn), translation(0.0, 0.0, zn))
    travel = p.uniform("trigger_travel", 0.004, 0.007)
    trig = ctx.builder.create_link("trigger", root)
    trig.set_joint("prismatic", translation(x0 + 0.0005, 0.0, z0 + 0.0005), axis=(1.0, 0.0, 0.0), limits=(0.0, travel))
    trig.add(trigger(p, lo - travel - 0.0015, W - 0.003, z1 - z0 - 0.001))
    ls = p.uniform("lock_length", 0.008, 0.012)
    lt = p.uniform("lock_travel", 0.003, 0.004)
    lock = ctx.builder.create_link("lock", root)
    lock.set_joint("prismatic", translation(p.uniform("lock_at", 0.5, 0.65) * L, 0.0, H + 0.0002), axis=(1.0, 0.0, 0.0),
                   limits=(0.0, lt))
    lock.add(lock_slider(p, ls, p.uniform("lock_width", 0.3, 0.45) * W, p.uniform("lock_height", 0.002, 0.0035)))


def lighter(ctx):
    return {"flip_top": flip_top, "disposable": disposable, "utility": utility}[ctx.sub](ctx)


RULE = Category(
    name="lighter",
    subcategories={"disposable": 2.0, "flip_top": 1.5, "utility": 1.0},
    mass_range=(0.008, 0.15),  # kg: a mini disposable to a utility lighter
    materials={"body": "shell", "lid": "steel", "wheel": "steel", "nozzle": "aluminium", "lever": "plastic"},
    slots=(Slot("lighter", lighter),),
)
