"""Folding clothes-drying racks: gullwing racks, A-frame racks and tower racks.

Parts: tube frames (label ``frame``, 14-22 mm tubes) carrying rails (``rail``, 4-7 mm
wire, duplicated: their count varies), U-shaped swept leg frames (``leg``).
- gullwing: a horizontal central frame (0.7-0.95 m long, y; 0.5-0.6 m deep, x; at
  0.85-1.0 m) with 6-10 rails across; a wing (0.35-0.5 m, 3-6 rails) on each end,
  hinged on an x axis, hanging down at rest and raised to level or beyond
  (revolute 0..pi/2 + 0-0.3 rad); two nested U leg frames hinged either side of
  the middle, crossing in an X at rest (0.35-0.5 rad off vertical) and folding back
  towards their own ends (revolute, 0..0.55-0.8 rad, stopping 30 mm short of the
  hanging wings). Open: 1.4-1.95 m long.
- a_frame: two ladders (1.1-1.5 m, 0.6-1.0 m wide, 4-8 rails each) hinged at the
  top (y axis), one fixed, the other swinging shut towards it (revolute 0..2 beta
  minus the angle at which its tubes meet the other's rails; beta 0.22-0.35 rad is
  each ladder's lean). 1.0-1.45 m tall.
- tower: two side frames (0.35-0.5 m deep, 1.1-1.7 m tall, on foot bars) joined at
  2-4 tiers by 3-6 rails; a wing (0.18-0.3 m, 2-4 rails) on each long side of every
  tier, hanging at rest and raised to level (revolute 0..pi/2). 0.6-0.8 m wide.
Rest (all joints 0) is the state the rack stands in with its wings folded down; the
rack stands on the floor (not a fixture). Sizes from retailers' listings of gullwing
(about 1.8 x 0.55 x 1.0 m open), A-frame and three-tier tower airers.
"""

from __future__ import annotations

import copy
import math

import numpy as np

from artipg.geometry import cylinder
from artipg.geometry.transforms import rot_x, rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.drying_racks import evenly, frame_pose, ladder, leg_frame

X, Y, Z = np.eye(3)
C = 0.004  # clearance between tubes that move past each other
HINGE = 0.0015  # a hinged tube's gap to the tube it turns on (the validator wants touching within 2 mm)


def _tubes(p):
    return p.uniform("tube_radius", 0.007, 0.011), p.uniform("rail_radius", 0.002, 0.0035)


def _add(link, parts, pose):
    """Add copies of ``parts`` (a design used on several links) to ``link`` at ``pose``."""
    for part in parts:
        link.add(copy.copy(part), pose)


def gullwing(ctx, root, rf, rr):
    p, b = ctx.p, ctx.builder
    Lc, D, H = p.uniform("length", 0.7, 0.95), p.uniform("depth", 0.5, 0.6), p.uniform("height", 0.85, 1.0)
    _add(root, ladder(D, Lc, evenly(p.integers("rails", 6, 10), 0.0, Lc), rf, rr), translation(0.0, -Lc / 2, H))
    Lw, rw = p.uniform("wing_length", 0.35, 0.5), p.uniform("wing_tube", 0.8, 1.0) * rf
    wing = ladder(D, Lw, evenly(p.integers("wing_rails", 3, 6), 0.0, Lw), rw, rr)
    yh, up = Lc / 2 + rf + rw + HINGE, 0.5 * math.pi + p.uniform("gull", 0.0, 0.3)
    for s in (1.0, -1.0):  # hanging down at rest, raised outwards about x
        link = b.create_link("wing", root)
        link.set_joint("revolute", translation(0.0, s * yh, H), axis=(s, 0.0, 0.0), limits=(0.0, up))
        _add(link, wing, frame_pose((0.0, 0.0, 0.0), X, -Z))
    # legs: two nested inverted U frames hung under hinge bars either side of the middle,
    # crossing in an X; each folds back past the vertical towards its own end until its
    # feet come 30 mm short of the wing hanging there
    yp, rl, rh = p.uniform("pivot_offset", 0.06, 0.14), rf, 0.6 * rf
    wA = D - 4 * rf - 0.01
    wB = wA - 4 * rl - 2 * C
    z = H - rh - HINGE - rl
    bend = p.uniform("leg_bend", 1.5, 3.0) * rl
    room = Lc / 2 - 0.03  # the feet stay this far inside the frame ends
    a = min(p.uniform("cross", 0.35, 0.5), math.atan((room + yp) / z))
    L = z / math.cos(a)
    back = min(0.5 * math.pi - 0.02, math.asin(min(1.0, (room - yp) / L)))
    bars = [cylinder(rh, D - 2 * rf, translation(0.0, s * yp, H) @ rot_y(0.5 * math.pi), role="hinge")
            for s in (1.0, -1.0)]
    root.add(Part("frame", "leg_hinges", bars))
    for w, s in ((wA, 1.0), (wB, -1.0)):
        link = b.create_link("leg", root)
        link.set_joint("revolute", translation(0.0, s * yp, z) @ rot_x(-s * a), axis=(s, 0.0, 0.0),
                       limits=(0.0, a + back))
        link.add(leg_frame(w, L, rl, bend))


def a_frame(ctx, root, rf, rr):
    p, b = ctx.p, ctx.builder
    W, Lf, beta = p.uniform("width", 0.6, 1.0), p.uniform("length", 1.1, 1.5), p.uniform("lean", 0.22, 0.35)
    H, n = Lf * math.cos(beta), p.integers("rails", 4, 8)
    sb, cb = math.sin(beta), math.cos(beta)
    top = (0.0, 0.0, H)
    _add(root, ladder(W, Lf, evenly(n, 0.0, Lf), rf, rr), frame_pose(top, Y, np.array([-sb, 0.0, -cb])))
    wB, s0 = W - 4 * rf - 3 * C, 2 * rf + HINGE  # nested inside the fixed ladder, its top bar on the hinge
    link = b.create_link("frame", root)
    a1 = min(Lf / (n + 1), s0 + (Lf - s0) / (n + 1))
    shut = 2 * beta - math.asin((rf + max(rf, rr) + 2 * C) / a1)  # its tubes stop clear of the other's rails
    link.set_joint("revolute", translation(*top), axis=(0.0, 1.0, 0.0), limits=(0.0, shut))
    _add(link, ladder(wB, Lf, evenly(n, s0, Lf), rf, rr, start=s0), frame_pose((0.0, 0.0, 0.0), Y,
                                                                             np.array([sb, 0.0, -cb])))


def tower(ctx, root, rf, rr):
    p, b = ctx.p, ctx.builder
    W, D, H = p.uniform("width", 0.6, 0.8), p.uniform("depth", 0.35, 0.5), p.uniform("height", 1.1, 1.7)
    Ww = p.uniform("wing_length", 0.18, 0.3)
    z1 = Ww + p.uniform("bottom", 0.1, 0.2)
    n = max(2, min(p.integers("tiers", 2, 4), 1 + int((H - z1) / (Ww + 0.06))))
    tiers = np.linspace(z1, H, n)
    ext = p.uniform("foot_overhang", 0.05, 0.12)
    side = ladder(D, H, tiers[:-1], rf, rf, first_bar=False, rail_label="frame")
    for s in (1.0, -1.0):  # side frames on foot bars
        _add(root, side, frame_pose((0.0, s * W / 2, 0.0), X, Z))
    feet = [cylinder(rf, D + 2 * ext, translation(0.0, s * W / 2, rf) @ rot_y(0.5 * math.pi), role="foot")
            for s in (1.0, -1.0)]
    root.add(Part("frame", "foot_bars", feet))
    xs = evenly(p.integers("tier_rails", 3, 6), -(D / 2 - rf), D / 2 - rf)
    rails = [cylinder(rr, W, translation(x, 0.0, z) @ rot_x(0.5 * math.pi), role="rail") for z in tiers for x in xs]
    root.add(Part("rail", "tier_rails", rails))
    rw = p.uniform("wing_tube", 0.7, 0.9) * rf
    wing = ladder(W, Ww, evenly(p.integers("wing_rails", 2, 4), 0.0, Ww), rw, rr)
    xh = D / 2 + rw + HINGE  # on the uprights' outer faces
    for z in tiers:
        for s in (1.0, -1.0):  # hanging at rest, raised outwards about y
            link = b.create_link("wing", root)
            link.set_joint("revolute", translation(s * xh, 0.0, z), axis=(0.0, -s, 0.0), limits=(0.0, 0.5 * math.pi))
            _add(link, wing, frame_pose((0.0, 0.0, 0.0), Y, -Z))


BUILD = {"gullwing": gullwing, "a_frame": a_frame, "tower": tower}


def rack(ctx):
    root = ctx.builder.create_link("frame")
    BUILD[ctx.sub](ctx, root, *_tubes(ctx.p))


RULE = Category(
    name="folding_rack",
    subcategories={"gullwing": 2.0, "a_frame": 1.5, "tower": 1.5},
    # thin-walled steel tubes modelled solid average to a hollow shell's density (a 19 mm
    # tube with a 0.6 mm wall is an eighth steel); coated wire rails to about aluminium's
    materials={"frame": "shell", "leg": "shell", "rail": "aluminium"},
    mass_range=(0.8, 12.0),  # kg: a small A-frame airer to a four-tier tower
    slots=(Slot("rack", rack),),
)
