"""Clocks: wall clocks, mantel clocks and alarm clocks.

Parts: a case (body) around a dial with 4 or 12 hour marks, a glass, and the hands:
hour, minute and (mostly) second hands stacked on the dial axis in parallel planes
1.2-1.6 mm apart (no two can meet at any angle). Wall clocks: round, square or
octagonal (schoolhouse) cases 0.04-0.07 deep. Mantel clocks: a case (flat top, arched
top or tambour "Napoleon hat") on a plinth, a round bezel door with its glass over
the dial, and on some a pendulum swinging behind a glazed window in a compartment
under the dial. Alarm clocks: a round case with twin bells on posts and two feet,
or a box body; an alarm button (or snooze bar) on top, setting knobs at the back.
Joints: every hand continuous about the dial axis (x, the front is -x); the bezel door
revolute about a vertical hinge (0 to 85-105 deg); the pendulum revolute about x
(+-3-10 deg); alarm buttons prismatic down (3-6 mm); setting knobs continuous.
Sizes (metres, real ranges): wall clocks 0.22-0.42 across (dial 0.2-0.38), 0.04-0.07
deep; mantel clocks 0.18-0.45 wide, 0.2-0.45 tall, 0.12-0.18 deep (door and plinth
included), dials 0.1-0.18; alarm clocks 0.1-0.18 wide, 0.12-0.16 tall with bells,
0.07-0.1 deep with the knobs at the back.
Wall clocks hang on a nail in use. The category is not a fixture (its mantel and alarm
clocks stand on a shelf and are dropped on a floor in validation), so wall clocks are
generated standing as on a shelf: flat-bottomed cases on their bottom edge, round
ones in a low display cradle (a plate and two chocks touching the rim).
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cylinder, profile
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.clocks import (HANDS, WALL_CASES, bell, bezel_door, clock_dial, cradle, mount_hands, pendulum,
                                     round_case, x_disc, x_frame, x_ring, yz_extrusion)
from artipg.templates.controls import (BUTTONS, button_bezel, fluted_knob, mount_button, mount_knob, round_button,
                                       round_knob)

MARKS = {12: 3.0, 4: 1.0}
KNOBS = {round_knob: 1.0, fluted_knob: 1.0}
ROUND = {round_button: 1.0}


def _flat_top(p, R):
    """Rectangular mantel case: (outline, width, height, dial centre height)."""
    m = p.uniform("margin", 0.02, 0.04)
    W = 2 * (R + m) + p.uniform("extra_width", 0.0, 0.12)
    H = 2 * (R + m) + p.uniform("extra_height", 0.0, 0.06)
    return [profile.rectangle(W, H, centre=(0.0, H / 2))], W, H, H - m - R


def _arch_top(p, R):
    """Arched-top ('tombstone') mantel case: straight sides and a round top centred on the dial."""
    m = p.uniform("margin", 0.02, 0.035)
    W = 2 * (R + m) + p.uniform("extra_width", 0.0, 0.04)
    hs = R + m + p.uniform("extra_height", 0.0, 0.05)
    out = profile.polygon([[-W / 2, 0.0], [W / 2, 0.0], [W / 2, hs], [-W / 2, hs]])
    out[2, 2] = 1.0  # the top edge, right to left, is a half circle bulging up
    return [out], W, hs + W / 2, hs


def _tambour(p, R):
    """Tambour ('Napoleon hat') case: low shoulders and a round hump over the dial."""
    m = p.uniform("margin", 0.01, 0.025)
    rc = R + m
    W = 2 * rc + 2 * p.uniform("shoulder", 0.05, 0.1)
    hs = rc + p.uniform("extra_height", 0.01, 0.03)
    out = profile.polygon([[-W / 2, 0.0], [W / 2, 0.0], [W / 2, 0.55 * hs], [rc, hs], [-rc, hs], [-W / 2, 0.55 * hs]])
    out[3, 2] = 1.0
    return [out], W, hs + rc, hs


MANTEL_CASES = {_flat_top: 2.0, _arch_top: 2.0, _tambour: 1.0}


def _wall(ctx, root):
    p = ctx.p
    R = p.uniform("dial_radius", 0.1, 0.19)
    x_front = mount_hands(p.scope("hands"), ctx.builder, root, translation(0, 0, 0), R, p.flag("seconds", 0.85),
                          ctx.choose("hand", HANDS))
    front = -x_front + p.uniform("glass_gap", 0.003, 0.006) + 0.004
    back = p.uniform("movement_depth", 0.02, 0.045)
    tmpl = ctx.choose("case", WALL_CASES)
    dial = clock_dial(p.scope("dial"), R, ctx.choose("marks", MARKS))
    case, glass = tmpl(p.scope("case"), R, back, front, dial.anchors["back"][0])
    root.add(case)
    if p.flag("glass", 0.75):  # open-face designer clocks have none
        root.add(glass)
    root.add(dial)
    if tmpl is round_case:
        rb = case.anchors["bottom"][2]
        x_mid = (back - front) / 2
        root.add(cradle(p.scope("cradle"), -rb, front + back, x_mid), translation(0, 0, rb))


def _mantel(ctx, root):
    p = ctx.p
    R = p.uniform("dial_radius", 0.05, 0.09)
    loops, W, H, zd = ctx.choose("case", MANTEL_CASES)(p.scope("case"), R)
    D = p.uniform("depth", 0.09, 0.15)
    hp = p.uniform("plinth_height", 0.015, 0.04)
    lip = p.uniform("plinth_lip", 0.005, 0.02)
    has_pend = p.flag("pendulum", 0.5)
    hc = p.uniform("compartment_height", 0.08, 0.13) if has_pend else 0.0
    z0 = hp + hc  # bottom of the dial block
    root.add(Part("base", "clock_plinth", [cuboid(D + 2 * lip, W + 2 * lip, hp, translation(D / 2, 0, hp / 2),
                                                  role="plinth")], regions={"lift": Region(("plinth",))}))
    # the dial is a plug in a bore through the case, standing 0.5-0.9 mm proud of its front
    bore = profile.oriented(profile.circle(R, (0.0, zd)), ccw=False)
    root.add(Part("body", "mantel_case", [yz_extrusion([*loops, bore], 0.0, D, "case", z=z0)],
                  regions={"lift": Region(("case",)), "grasp": Region(("case",))}))
    # the bezel's back edge swings in just in front of the dial: it stands proud by little
    dial = clock_dial(p.scope("dial"), R - 0.0002, ctx.choose("marks", MARKS), (D + 0.0005, D + 0.0009))
    td = dial.anchors["back"][0] - D
    face = translation(-td, 0, z0 + zd)  # the dial stands proud of the case front (x = 0)
    root.add(dial, face)
    x_front = mount_hands(p.scope("hands"), ctx.builder, root, face, R, p.flag("seconds", 0.5),
                          ctx.choose("hand", HANDS))
    q = p.scope("door")
    tg = q.uniform("glass_thickness", 0.0015, 0.003)
    depth = -x_front + tg + q.uniform("glass_gap", 0.003, 0.006)
    door, glass = bezel_door(q, R, depth, tg)
    c = door.anchors["far"][1] / 2
    link = ctx.builder.create_link("door", root)
    link.set_joint("revolute", translation(-td - 0.001 - depth, -c, z0 + zd), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, math.radians(q.uniform("open", 85.0, 105.0))))
    link.add(door)
    link.add(glass)
    if has_pend:
        _compartment(p.scope("pendulum"), ctx.builder, root, W, D, hp, hc)


def _compartment(p, builder, root, W, D, hp, hc):
    """Pendulum compartment between the plinth and the dial block: back and side walls,
    a glazed front frame, and the pendulum hanging from a bracket under the block."""
    tw = p.uniform("wall", 0.006, 0.012)
    fw = p.uniform("frame_width", 0.008, 0.016)
    tf = p.uniform("frame_depth", 0.006, 0.012)
    zc = hp + hc / 2
    prims = [cuboid(tw, W, hc, translation(D - tw / 2, 0, zc), role="wall")]
    prims += [cuboid(D - tf, tw, hc, translation((D + tf) / 2, s * (W / 2 - tw / 2), zc), role="wall")
              for s in (-1.0, 1.0)]
    prims.append(x_frame(W, hc, W - 2 * fw, hc - 2 * fw, 0.0, tf, "frame", z=zc))
    root.add(Part("body", "pendulum_compartment", prims))
    root.add(Part("glass", "clock_glass", [cuboid(0.002, W - 2 * fw, hc - 2 * fw, translation(tf / 2, 0, zc),
                                                  role="glass")]))
    xp = tf + (D - tw - tf) * p.uniform("pivot_depth", 0.4, 0.6)
    zp = hp + hc - 0.01
    root.add(Part("body", "pendulum_bracket", [cuboid(D - tw - xp - 0.0035, 0.016, 0.02,
                                                      translation((xp + 0.0035 + D - tw) / 2, 0, zp), role="bracket")]))
    half = W / 2 - tw
    bob = min(p.uniform("bob_ratio", 0.16, 0.24) * hc, 0.35 * half)
    L = zp - hp - bob - p.uniform("floor_gap", 0.006, 0.012)
    swing = math.asin(min(0.99, (half - bob - 0.004) / L))
    A = min(swing, math.radians(p.uniform("swing", 3.0, 10.0)))
    link = builder.create_link("pendulum", root)
    link.set_joint("revolute", translation(xp, 0, zp), axis=(1.0, 0.0, 0.0), limits=(-A, A))
    link.add(pendulum(p, L, bob))


def _alarm(ctx, root):
    p = ctx.p
    bells = p.flag("twin_bell", 0.6)
    Rc = p.uniform("case_radius", 0.045, 0.065)
    bw = p.uniform("bezel", 0.003, 0.007)
    R = Rc - bw
    td = p.uniform("dial_thickness", 0.002, 0.003)
    x_front = mount_hands(p.scope("hands"), ctx.builder, root, translation(0, 0, 0), R, p.flag("seconds", 0.5),
                          ctx.choose("hand", HANDS))
    front = -x_front + p.uniform("glass_gap", 0.003, 0.005) + 0.004
    tg = p.uniform("glass_thickness", 0.0015, 0.0025)
    D = p.uniform("depth", 0.035, 0.055)
    root.add(Part("body", "alarm_bezel", [x_ring(Rc, R, -front, td, "bezel")]))
    if bells:
        body = Part("body", "bell_case", [x_disc(Rc, td, D, "case")], regions={"lift": Region(("case",)),
                                                                                "grasp": Region(("case",))})
        root.add(body)
        top = Rc
        back, half_w = D, Rc
    else:
        W = 2 * Rc + p.uniform("side_margin", 0.01, 0.04)
        H = 2 * Rc + p.uniform("top_margin", 0.008, 0.025)
        zc = -Rc - p.uniform("bottom_margin", 0.004, 0.012)  # the box bottom below the dial centre
        r = p.uniform("corner", 0.004, 0.012)
        box = rounded_box(D, W, H, r, translation(td + D / 2, 0, zc + H / 2), role="case")
        root.add(Part("body", "alarm_box", [box],
                      regions={"lift": Region(("case",)), "grasp": Region(("case",))}))
        top = zc + H
        back, half_w = td + D, W / 2
    if p.flag("glass", 0.8):
        root.add(Part("glass", "clock_glass", [x_disc(R - 0.0002, -front + 0.001, -front + 0.001 + tg, "glass")]))
    root.add(clock_dial(p.scope("dial"), R - 0.0002, ctx.choose("marks", MARKS)))
    xm = (td + back) / 2
    if bells:
        _bells_and_feet(p.scope("bells"), root, Rc, xm, D - td)
    # alarm button(s) on top: a boss, a bezel collar, the cap pressing down
    n = 1 if bells else p.integers("top_buttons", 1, 2)
    # a round alarm-off button between the bells; keys or a snooze bar on a flat top
    tmpl = ctx.choose("button", ROUND if bells else BUTTONS)
    span = 0.6 * half_w
    for i in range(n):
        q = p.scope(f"top{i}")
        y = 0.0 if n == 1 else (i - 0.5) * span
        pose = translation(xm, y, top + 0.001) @ rot_y(math.pi / 2)
        if tmpl.__name__ == "round_button":
            b = tmpl(q, radius=q.uniform("radius", 0.004, 0.006 if bells else 0.008))
        else:
            wmax = 1.2 * half_w if n == 1 else 0.8 * span  # a snooze bar, or two keys side by side
            b = tmpl(q, width=q.uniform("width", 0.5, 1.0) * wmax,
                     height=min(0.012, 0.6 * (back - td)))
        bez = button_bezel(q.scope("bezel"), b, gap=0.0009)
        root.add(bez, pose)
        if bells:  # the boss the collar stands on, sunk into the round case top
            root.add(Part("body", "button_boss", [cylinder(0.006 + 0.004, 0.006, translation(xm, y, top - 0.002),
                                                           role="boss")]))
        mount_button(ctx.builder, root, b, pose)
    # setting knobs at the back
    k = p.integers("knobs", 1, 3)
    knob = ctx.choose("knob", KNOBS)
    for i in range(k):
        q = p.scope(f"knob{i}")
        y = (i - (k - 1) / 2) * 0.5 * R
        pose = translation(back, y, -0.25 * R) @ rot_z(math.pi)
        mount_knob(ctx.builder, root, knob(q, radius=q.uniform("radius", 0.006, 0.011)), pose, continuous=True)


def _bells_and_feet(p, root, Rc, xm, D):
    """Twin bells on posts either side of the top, and two feet spanning the depth."""
    # bells wide apart enough that the alarm button between them clears their rims
    rb = p.uniform("bell_radius", 0.38, 0.5) * Rc
    phi = math.radians(p.uniform("bell_angle", 40.0, 48.0))
    dist = Rc + p.uniform("post", 0.004, 0.01)
    for s in (-1.0, 1.0):
        u = (s * math.sin(phi), math.cos(phi))
        pose = translation(xm, dist * u[0], dist * u[1]) @ rot_x(-s * phi)
        root.add(bell(p.scope("bell_l" if s < 0 else "bell_r"), rb), pose)
        lp = dist - Rc + 0.006  # from 6 mm inside the case to 1 mm into the bell
        root.add(Part("body", "bell_post", [cylinder(0.002, lp, pose @ translation(0, 0, -lp / 2 + 0.001), role="post")]))
    hf = p.uniform("foot_height", 0.008, 0.02)
    yf = p.uniform("foot_spread", 0.5, 0.7) * Rc
    zt = -math.sqrt(Rc * Rc - yf * yf) + 0.003
    wf = p.uniform("foot_width", 0.008, 0.014)
    for s in (-1.0, 1.0):
        h = zt - (-Rc - hf)
        root.add(Part("base", "clock_foot", [cuboid(D, wf, h, translation(xm, s * yf, zt - h / 2), role="foot")]))


SUBS = {"wall_clock": _wall, "mantel_clock": _mantel, "alarm_clock": _alarm}


def clock(ctx):
    root = ctx.builder.create_link("body")
    SUBS[ctx.sub](ctx, root)


RULE = Category(
    name="clock",
    subcategories={"wall_clock": 3.0, "mantel_clock": 2.0, "alarm_clock": 2.0},
    materials={"body": "shell", "base": "wood", "dial": "plastic", "door": "brass", "bell": "steel"},
    mass_range=(0.1, 10.0),  # kg: a travel alarm clock (~0.15) to a wooden mantel clock (3-8)
    slots=(Slot("clock", clock),),
)
