"""Fans: desk fans, pedestal fans and box fans.

Parts: a rotor (hub and 3-6 pitched blades: paddle, petal or swept) inside a wire
guard (concentric rings or many spokes, a rim band, a badge), a motor housing behind
it; desk fans stand on a base (disc, square or cross) with a column, speed buttons
(piano keys) or a speed knob on the base; pedestal fans have a lower tube on the base
and a telescopic upper pole, and a speed knob at the back of the motor; box fans
have a square frame with a round opening, bar grilles front and back, a motor held
by struts, a carry handle and one or two knobs on top.
Joints: the rotor continuous about the fan axis (x, blowing towards -x); desk and
pedestal heads oscillate, revolute about z (+-35-60 deg) on a collar, and tilt,
revolute about y (-11 to +17-25 deg); the pedestal pole slides up, prismatic
(0.15-0.35 m); speed keys prismatic (3-5 mm); knobs revolute (0-270 deg) or
continuous.
Sizes (metres, real ranges): desk fans 0.4-0.65 tall (12-16 in models), guards 0.22-0.36
across (9-14 in); pedestal fans 1.0-1.45 tall at rest, guards 0.36-0.48 (14-18 in), bases 0.3-0.5;
box fans 0.4-0.58 square, 0.09-0.14 deep (16-20 in).
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cylinder, profile, ring
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.clocks import x_disc, yz_extrusion
from artipg.templates.controls import (fluted_knob, mount_button_row, mount_knob, pointer_knob, rect_button,
                                       round_knob)
from artipg.templates.fans import BASES, GUARDS, ROTORS, cross_base, motor_housing

KNOBS = {round_knob: 1.0, pointer_knob: 1.5, fluted_knob: 1.0}
BLADES = {3: 2.0, 4: 1.0, 5: 2.0, 6: 0.5}
DESK_BASES = {k: v for k, v in BASES.items() if k is not cross_base}


def _rotor_and_guard(ctx, p, Rb):
    """Rotor parts and guard for blades of radius ``Rb``: (hub, blades, guard, rear, front, hub_back)."""
    n = ctx.p.choice("blades", BLADES)
    hub_r = p.uniform("hub_radius", 0.12, 0.18) * Rb
    hub, blades = ctx.choose("rotor", ROTORS)(p.scope("rotor"), Rb, n, hub_r)
    rear = hub.anchors["back"][0] + p.uniform("rear_gap", 0.005, 0.012)
    front = -hub.anchors["front"][0] + p.uniform("front_gap", 0.008, 0.02)
    Rg = Rb + p.uniform("tip_gap", 0.008, 0.02)
    guard = ctx.choose("guard", GUARDS)(p.scope("guard"), Rg, rear, front, 0.55 * hub_r)
    return hub, blades, guard, rear, front, 0.55 * hub_r, hub.anchors["hub_back"][0]


def _head(ctx, parent, top, Rb):
    """Oscillating collar on ``parent`` at height ``top`` (its frame), tilting head,
    rotor. Returns (tilt link, motor housing part, head frame in the tilt link)."""
    p = ctx.p.scope("head")
    b = ctx.builder
    hub, blades, guard, rear, front, boss, hub_back = _rotor_and_guard(ctx, p, Rb)
    rm = p.uniform("motor_radius", 0.3, 0.4) * Rb
    x0 = rear + 0.002
    motor = motor_housing(p.scope("motor"), rm, x0, boss, hub_back)
    L, back = motor.anchors["length"][0], motor.anchors["back"][0]
    rc = p.uniform("collar_radius", 0.014, 0.022)
    hc = p.uniform("collar_height", 0.015, 0.03)
    k = p.uniform("knuckle_radius", 0.008, 0.012)
    lk = p.uniform("knuckle_length", 0.02, 0.035)
    up, down = math.radians(p.uniform("tilt_up", 17.0, 25.0)), math.radians(p.uniform("tilt_down", 8.0, 11.0))
    # the tilt pivot sits under the can far enough back that the guard's rim, hanging
    # below it, clears the collar when the head tilts down; the stem lifts the can so
    # its ends clear the cheeks at either limit
    clear = rc + 0.01
    d = max(0.6 * L, clear + 0.012)  # rim's rear edge (x0) to the pivot
    xp = x0 + d - 0.002
    far = max(d, back - xp)
    s = k + far * math.sin(up) + 0.012
    dz = max(0.0, guard.anchors["radius"][0] - s - rm)
    D = math.hypot(d, dz)
    down = max(0.05, min(down, math.acos(min(1.0, clear / D)) - math.atan2(dz, d)))
    ch = 0.006
    zk = hc + k + 0.004  # knuckle axis above the collar bottom
    osc = b.create_link("neck", parent)
    osc.set_joint("revolute", translation(0, 0, top + 0.0008), axis=(0.0, 0.0, 1.0),
                  limits=(-(a := math.radians(p.uniform("oscillation", 35.0, 60.0))), a))
    cheeks = [cuboid(2 * k, ch, zk + 0.7 * k - hc + 0.001,
                     translation(0, sy * (lk / 2 + 0.001 + ch / 2), (hc + zk + 0.7 * k) / 2 - 0.0005), role="cheek")
              for sy in (-1.0, 1.0)]
    osc.add(Part("stand", "fan_collar", [cylinder(rc, hc, translation(0, 0, hc / 2), role="collar"),
                                         cuboid(2 * k, lk + 2 * ch + 0.002, 0.004, translation(0, 0, hc + 0.0015),
                                                role="yoke"), *cheeks]))
    tilt = b.create_link("head", osc)
    tilt.set_joint("revolute", translation(0, 0, zk), axis=(0.0, 1.0, 0.0), limits=(-down, up))
    H = translation(-xp, 0, s + rm)  # head frame (rotor axis) in the tilt link
    tilt.add(motor, H)
    tilt.add(Part("stand", "fan_knuckle", [cylinder(k, lk, rot_x(math.pi / 2), role="knuckle"),
                                           cylinder(0.7 * k, s + 0.003, translation(0, 0, (s + 0.003) / 2),
                                                    role="stem")]))
    tilt.add(guard, H)
    rot = b.create_link("rotor", tilt)
    rot.set_joint("continuous", H, axis=(1.0, 0.0, 0.0))
    rot.add(hub)
    rot.add(blades)
    return tilt, motor, H


def _desk(ctx, root):
    p = ctx.p
    Rb = p.uniform("blade_radius", 0.1, 0.16)
    base = ctx.choose("base", DESK_BASES)(
        p.scope("base"), p.uniform("base_radius", 0.8, 1.05) * Rb)
    # the base reaches forward under the head, which hangs in front of the column
    xo = -p.uniform("base_forward", 0.2, 0.35) * Rb
    root.add(base, translation(xo, 0, 0))
    zt = base.anchors["top"][2]
    rcol = p.uniform("column_radius", 0.01, 0.016)
    hcol = Rb + p.uniform("column_extra", 0.03, 0.12)
    root.add(Part("stand", "fan_column", [cylinder(rcol, hcol, translation(0, 0, zt + hcol / 2), role="column")]))
    _head(ctx, root, zt + hcol, Rb)
    # speed control on the base's front
    xb = xo - p.uniform("control_reach", 0.55, 0.7) * base.bounds()[1, 0]
    if p.flag("keys", 0.6):
        k = p.integers("keys_n", 3, 4)
        pose = translation(xb, 0, zt) @ rot_y(math.pi / 2)
        span = min(0.09, 0.9 * base.bounds()[1, 1])
        mount_button_row(p.scope("keys"), ctx.builder, root, rect_button, k, pose, -span / 2, span / 2, 0.0, 0.0,
                         (p.uniform("key_width", 0.55, 0.8) * span / k, 0.012))
    else:
        knob = ctx.choose("knob", KNOBS)(p.scope("knob"), radius=p.uniform("knob_radius", 0.012, 0.018))
        mount_knob(ctx.builder, root, knob, translation(xb, 0, zt) @ rot_y(math.pi / 2), continuous=False,
                   limits=(0.0, math.radians(p.uniform("knob_sweep", 180.0, 270.0))))


def _pedestal(ctx, root):
    p = ctx.p
    Rb = p.uniform("blade_radius", 0.16, 0.21)
    base = ctx.choose("base", BASES)(p.scope("base"), p.uniform("base_radius", 0.16, 0.24))
    root.add(base)
    zt = base.anchors["top"][2]
    ru = p.uniform("pole_radius", 0.009, 0.013)
    wall = p.uniform("tube_wall", 0.002, 0.004)
    travel = p.uniform("travel", 0.15, 0.35)
    insert = travel + p.uniform("overlap", 0.05, 0.1)
    hl = max(p.uniform("tube_height", 0.45, 0.65), insert + 0.015)
    root.add(Part("stand", "fan_tube", [ring(ru + 0.001 + wall, ru + 0.001, hl, pose=translation(0, 0, zt + hl / 2),
                                             role="tube"),
                                        cylinder(ru + 0.001, 0.01, translation(0, 0, zt + 0.005), role="tube")]))
    hu = p.uniform("pole_height", 0.3, 0.45)
    pole = ctx.builder.create_link("pole", root)
    pole.set_joint("prismatic", translation(0, 0, zt + hl), axis=(0.0, 0.0, 1.0), limits=(0.0, travel))
    pole.add(Part("stand", "fan_pole", [cylinder(ru, insert + hu, translation(0, 0, (hu - insert) / 2), role="pole")],
                  regions={"grasp": Region(("pole",)), "pull": Region(("pole",))}))
    tilt, motor, H = _head(ctx, pole, hu, Rb)
    # speed knob on the back of the motor can, facing +x
    back = motor.anchors["back"][0]
    knob = ctx.choose("knob", KNOBS)(p.scope("knob"), radius=p.uniform("knob_radius", 0.012, 0.018))
    mount_knob(ctx.builder, tilt, knob, H @ translation(back, 0, 0) @ rot_z(math.pi), continuous=False,
               limits=(0.0, math.radians(p.uniform("knob_sweep", 180.0, 270.0))))


def _box(ctx, root):
    p = ctx.p
    S = p.uniform("size", 0.4, 0.56)
    Rh = 0.5 * S - p.uniform("frame_margin", 0.015, 0.03)
    Rb = Rh - p.uniform("tip_gap", 0.01, 0.02)
    bar = p.uniform("bar", 0.003, 0.005)
    n = ctx.p.choice("blades", BLADES)
    hub_r = p.uniform("hub_radius", 0.15, 0.2) * Rb
    hub, blades = ctx.choose("rotor", ROTORS)(p.scope("rotor"), Rb, n, hub_r)
    f, bk = -hub.anchors["front"][0], hub.anchors["back"][0]
    # front bars, 4 mm, the rotor, 4 mm, the struts (6 mm), 2 mm, the rear bars
    D = max(p.uniform("depth", 0.09, 0.13), 2 * bar + f + bk + 0.016)
    corner = p.uniform("corner", 0.0, 0.06)
    outer = profile.rectangle(S, S, corner)
    hole = profile.oriented(profile.circle(Rh), ccw=False)
    zc = S / 2 + p.uniform("foot_height", 0.01, 0.02)
    root.add(Part("body", "box_fan_frame", [yz_extrusion([outer, hole], -D / 2, D / 2, "frame", z=zc)],
                  regions={"lift": Region(("frame",))}))
    for s in (-1.0, 1.0):  # feet widening the stance front to back
        hf = zc - S / 2 + 0.002
        root.add(Part("base", "box_fan_foot", [cuboid(1.5 * D, 0.06, hf, translation(0, s * 0.3 * S, hf / 2), role="foot")]))
    # grilles: vertical bars across the opening, front and back
    nb = p.integers("bars", 9, 15)
    grille = []
    for x in (-D / 2 + bar / 2, D / 2 - bar / 2):
        for i in range(nb):
            y = (i + 0.5 - nb / 2) * 2 * Rh / nb
            L = 2 * math.sqrt(Rh * Rh - y * y) + 0.004
            grille.append(cuboid(bar, bar, L, translation(x, y, zc), role="bar"))
    root.add(Part("guard", "bar_grille", grille))
    # rotor in the opening, the motor behind it on three struts from the frame
    xr = -D / 2 + bar + 0.004 + f
    xm0 = xr + hub.anchors["hub_back"][0] + 0.0015
    xs = xr + bk + 0.004  # the struts' front
    xm1 = max(xs + 0.006, xm0 + 0.01)
    rm = 0.6 * hub_r  # inside the blades' roots
    motor = [x_disc(rm, xm0, xm1, "motor", z=zc)]
    motor += [cuboid(0.006, 0.012, Rh - rm + 0.004, translation(xs + 0.003, 0, zc) @ rot_x(2 * math.pi * k / 3)
                     @ translation(0, 0, (Rh + rm) / 2), role="strut") for k in range(3)]
    root.add(Part("body", "box_fan_motor", motor))
    rot = ctx.builder.create_link("rotor", root)
    rot.set_joint("continuous", translation(xr, 0, zc), axis=(1.0, 0.0, 0.0))
    rot.add(hub)
    rot.add(blades)
    # carry handle and knobs on the top face
    top = zc + S / 2
    hw = p.uniform("handle_width", 0.1, 0.16)
    hh = p.uniform("handle_height", 0.025, 0.04)
    post = 0.012
    handle = [cuboid(0.02, post, hh, translation(0, s * (hw / 2 - post / 2), top + hh / 2 - 0.001), role="post")
              for s in (-1.0, 1.0)]
    handle.append(cuboid(0.02, hw, 0.01, translation(0, 0, top + hh + 0.004), role="grip"))
    root.add(Part("handle", "box_fan_handle", handle, regions={"grasp": Region(("grip",)), "lift": Region(("grip",))}))
    k = p.integers("knobs", 1, 2)
    knob = ctx.choose("knob", KNOBS)
    for i in range(k):
        q = p.scope(f"knob{i}")
        y = (hw / 2 + 0.035 + 0.045 * i) * (1 if i == 0 else -1)
        mount_knob(ctx.builder, root, knob(q, radius=q.uniform("radius", 0.012, 0.017)),
                   translation(0, y, top) @ rot_y(math.pi / 2), continuous=False,
                   limits=(0.0, math.radians(q.uniform("sweep", 180.0, 270.0))))


SUBS = {"desk_fan": _desk, "pedestal_fan": _pedestal, "box_fan": _box}


def fan(ctx):
    root = ctx.builder.create_link("base")
    SUBS[ctx.sub](ctx, root)


RULE = Category(
    name="fan",
    subcategories={"desk_fan": 3.0, "pedestal_fan": 2.0, "box_fan": 1.5},
    materials={"body": "shell", "base": "plastic", "stand": "aluminium", "blade": "plastic", "guard": "steel"},
    mass_range=(0.8, 12.0),  # kg: a 9 in desk fan (~1) to an 18 in pedestal fan on a cast base (~8)
    slots=(Slot("fan", fan),),
)
