"""Lamps: desk arm lamps, table lamps and floor lamps.

Parts: a base (flat disc, turned dome or square block); desk lamps: a turret swivelling
on the base, two arm links (a fork-shaped lower arm straddling a single-rod upper
arm, as on balanced-arm lamps), a reflector head (cone or dome) with its bulb, a push
switch on the base; table lamps: a turned body (vase, column, candlestick), a socket,
a bulb, a harp and spider holding an open shade (drum, empire or bell) and a switch
(pull chain, rotary knob on the socket, or a push button on the base); floor lamps:
a pole to a drum shade, a torchiere bowl, or an adjustable reading neck with a head.
Joints: desk lamps: turret revolute about z (+-150 deg), shoulder and elbow revolute
about y (+-20-30 deg round the balanced pose), head revolute about y; pull chains
prismatic down (6-12 mm); rotary switches revolute (90 deg) about their radial axis;
push buttons prismatic (3-6 mm); torchiere dimmer knobs revolute (270 deg); the
reading lamp's neck revolute about y.
Sizes (metres, real ranges): desk lamps 0.35-0.6 tall at rest, arms 0.25-0.42 per
link, bases 0.15-0.22 across, heads 0.1-0.18 across; table lamps 0.35-0.75 tall,
shades 0.2-0.45 across; floor lamps 1.3-1.85 tall, bases 0.25-0.4 across, shades
0.3-0.5 across.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cylinder, ring
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.controls import button_bezel, mount_button, mount_knob, round_button, round_knob
from artipg.templates.lamps import BASES, BODIES, HEADS, SHADES, arm_link, bulb, disc_base, domed_base

_ALONG_Y = rot_x(-math.pi / 2)  # local z -> +y
SWITCHES = {"pull_chain": 2.0, "rotary": 2.0, "button": 1.0}
FLOOR_TOPS = {"drum": 2.0, "torchiere": 1.0, "reading": 1.5}
FLOOR_SWITCHES = {"pull_chain": 1.0, "rotary": 1.0}
FLOOR_BASES = {disc_base: 1.0, domed_base: 1.0}


def _base_button(p, b, root, base, r: float | None = None):
    """Round push switch on the base's flat ledge (at radius ``r``, default the
    ledge's), in front, with its bezel collar."""
    r0, _, z = base.anchors["ledge"]
    pose = translation(-(r0 if r is None else r), 0, z) @ rot_y(math.pi / 2)
    btn = round_button(p, radius=p.uniform("radius", 0.005, 0.008))
    root.add(button_bezel(p.scope("bezel"), btn, gap=0.0009), pose)
    mount_button(b, root, btn, pose)


# ---------------------------------------------------------------- desk arm lamp

def _desk(ctx, root):
    p, b = ctx.p, ctx.builder
    rb = p.uniform("base_radius", 0.075, 0.11)
    base = root.add(ctx.choose("base", BASES)(p.scope("base"), rb))
    zt = base.anchors["top"][2]
    rk = p.uniform("knuckle_radius", 0.008, 0.012)
    lk = p.uniform("knuckle_length", 0.026, 0.036)
    rt = min(p.uniform("turret_radius", 0.01, 0.016), lk / 2 - 0.002)
    ht = p.uniform("turret_height", 0.03, 0.07)
    turret = b.create_link("turret", root)
    turret.set_joint("revolute", translation(0, 0, zt + 0.0008), axis=(0.0, 0.0, 1.0),
                     limits=(-math.radians(150.0), math.radians(150.0)))
    turret.add(Part("stand", "lamp_turret", [cylinder(rt, ht, translation(0, 0, ht / 2), role="turret"),
                                             cylinder(rk, lk, translation(0, 0, ht) @ _ALONG_Y, role="knuckle")],
                    regions={"rotate": Region()}))
    # the balanced pose: the lower arm leans back, the upper arm reaches forward
    L1, L2 = p.uniform("lower_arm", 0.25, 0.42), p.uniform("upper_arm", 0.25, 0.42)
    beta = math.radians(p.uniform("lean", 10.0, 25.0))
    delta = math.radians(p.uniform("reach_up", 0.0, 20.0))
    tw = p.uniform("tine", 0.004, 0.006)
    rw = lk  # the upper arm passes between the tines (lk + 2 mm apart) with 1 mm either side
    lower = b.create_link("lower_arm", turret)
    lower.set_joint("revolute", translation(0, 0, ht) @ rot_y(beta), axis=(0.0, 1.0, 0.0),
                    limits=(-math.radians(p.uniform("shoulder", 20.0, 30.0)), math.radians(15.0)))
    lower.add(arm_link(p.scope("lower"), L1, rk, tw, fork=lk + 0.002))
    upper = b.create_link("upper_arm", lower)
    upper.set_joint("revolute", translation(0, 0, L1) @ rot_y(-(math.pi / 2 - delta) - beta), axis=(0.0, 1.0, 0.0),
                    limits=(-math.radians(p.uniform("elbow", 20.0, 30.0)), math.radians(25.0)))
    rk2 = 0.8 * rk
    upper.add(arm_link(p.scope("upper"), L2, rk2, rw))
    # head: a fork round the upper rod's end disc, a neck, the reflector opening down
    rod = rw
    ch = 0.004
    drop = rk2 + 0.02  # the reflector hangs low enough to tip back under the arm
    yc = rod / 2 + 0.001 + ch / 2
    head = b.create_link("head", upper)
    head.set_joint("revolute", translation(0, 0, L2) @ rot_y(math.pi / 2 - delta), axis=(0.0, 1.0, 0.0),
                   limits=(-math.radians(p.uniform("head_back", 20.0, 30.0)),
                           math.radians(p.uniform("head_fwd", 30.0, 45.0))))
    R = p.uniform("head_radius", 0.05, 0.09)
    shade = ctx.choose("head", HEADS)(p.scope("shade"), R)
    neck = p.uniform("neck", 0.015, 0.035)
    yoke = [cuboid(2 * rk2, ch, drop, translation(0, s * yc, -drop / 2), role="fork") for s in (-1.0, 1.0)]
    yoke += [cylinder(rk2, ch, translation(0, s * yc, 0) @ _ALONG_Y, role="fork") for s in (-1.0, 1.0)]
    yoke += [cuboid(0.01, 2 * yc + ch, 0.004, translation(0, 0, -drop - 0.002), role="fork"),
             cylinder(0.006, neck + 0.001, translation(0, 0, -drop - 0.004 - neck / 2), role="neck")]
    head.add(shade, translation(0, 0, -drop - 0.004 - neck))
    head.add(Part("stand", "lamp_head_fork", yoke))
    rbulb = min(0.6 * shade.anchors["top_radius"][0], 0.025)
    head.add(bulb(p.scope("bulb"), rbulb, down=True), translation(0, 0, -drop - 0.004 - neck - 0.002))
    _base_button(p.scope("switch"), b, root, base)


# ---------------------------------------------------------------- table lamp

def _socket_shade(ctx, p, parent, z_socket: float, r_neck: float, shade_tmpl, R: float, Hs: float):
    """Socket, bulb, harp and spider holding an open shade over them; returns the socket radius."""
    rs = max(r_neck + p.uniform("socket_overhang", 0.008, 0.012), 0.015)
    hs = p.uniform("socket_height", 0.03, 0.045)
    parent.add(Part("body", "lamp_socket", [cylinder(rs, hs, translation(0, 0, z_socket + hs / 2), role="socket")]))
    rb = p.uniform("bulb_radius", 0.025, 0.035)
    bl = parent.add(bulb(p.scope("bulb"), rb), translation(0, 0, z_socket + hs))
    top_bulb = z_socket + hs + bl.anchors["tip"][2]
    shade = shade_tmpl(p.scope("shade"), R, Hs)
    z_shade = top_bulb + p.uniform("bulb_clearance", 0.015, 0.03) - Hs  # the spider sits just above the bulb
    z_shade = max(z_shade, z_socket - 0.3 * Hs)
    parent.add(shade, translation(0, 0, z_shade))
    # harp: two uprights from the socket to a finial above the bulb; spider: rods to the top rim
    zs = z_shade + Hs - 0.004
    rr = 0.0018
    yh = rb + 0.008  # the harp's uprights pass either side of the bulb
    z0 = z_socket + 0.5 * hs
    hub = [cylinder(0.006, 0.012, translation(0, 0, zs), role="spider"),
           cuboid(0.006, 2 * yh + 2 * rr, 0.005, translation(0, 0, z0), role="harp"),
           cuboid(0.006, 2 * yh + 2 * rr, 0.004, translation(0, 0, zs), role="harp")]
    hub += [cylinder(rr, zs - z0, translation(0, s * yh, (zs + z0) / 2), role="harp") for s in (-1.0, 1.0)]
    r_in = shade.anchors["top_radius"][0]
    for k in range(3):
        a = 2 * math.pi * k / 3
        L = r_in - 0.006 + 0.001
        hub.append(cylinder(rr, L, rot_z(a) @ translation(0.006 + L / 2 - 0.0005, 0, zs) @ rot_y(math.pi / 2),
                            role="spider"))
    parent.add(Part("stand", "lamp_harp", hub))
    return rs, hs


def _switch(ctx, p, root, kind: str, z_socket: float, rs: float, hs: float, r_neck: float, base, drop: float,
            body_r: float = 0.0):
    """The lamp's switch: a pull chain hanging ``drop`` at most under the socket, a
    rotary knob on the socket, or a push button on the base's ledge clear of a body
    of radius ``body_r`` (a rotary knob where the body leaves no room)."""
    b = ctx.builder
    r_btn = max(base.anchors["ledge"][0], body_r + 0.016)
    if kind == "button" and r_btn > base.anchors["radius"][0] - 0.013:
        kind = "rotary"
    if kind == "pull_chain":
        L = p.uniform("chain", 0.6, 1.0) * (drop - 0.028)  # the pulled bob stays 4 mm off the body
        y = 0.5 * (rs + r_neck) + 0.001
        link = b.create_link("chain", root)
        link.set_joint("prismatic", translation(0, y, z_socket - 0.0008), axis=(0.0, 0.0, -1.0),
                       limits=(0.0, p.uniform("pull", 0.006, 0.012)))
        pull = Region(("pull",))
        link.add(Part("switch", "pull_chain", [cylinder(0.0008, L, translation(0, 0, -L / 2), role="chain"),
                                               cylinder(0.003, 0.012, translation(0, 0, -L - 0.005), role="pull")],
                      regions={"pull": pull, "grasp": pull, "press": pull}, actionable="slider_button"))
    elif kind == "rotary":
        knob = round_knob(p.scope("knob"), radius=p.uniform("knob_radius", 0.005, 0.008))
        mount_knob(b, root, knob, translation(-rs, 0, z_socket + 0.5 * hs), continuous=False,
                   limits=(0.0, math.pi / 2))
    else:
        _base_button(p.scope("button"), b, root, base, r_btn)


def _table(ctx, root):
    p = ctx.p
    R = p.uniform("shade_radius", 0.1, 0.22)
    rb = p.uniform("base_radius", 0.45, 0.7) * R
    base = root.add(ctx.choose("base", BASES)(p.scope("base"), rb))
    zt = base.anchors["top"][2]
    H = p.uniform("body_height", 0.18, 0.42)
    body = root.add(ctx.choose("body", BODIES)(p.scope("body"), H, rb * p.uniform("body_ratio", 0.6, 0.95)),
                    translation(0, 0, zt - 0.0005))  # seated 0.5 mm into the base
    # a riser from the body's top to the socket leaves room for a pull chain
    r_neck = min(body.anchors["radius"][0], p.uniform("riser_radius", 0.008, 0.012))
    riser = p.uniform("riser", 0.05, 0.09)
    root.add(Part("stand", "lamp_riser", [cylinder(r_neck, riser + 0.002, translation(0, 0, zt + H - 0.001 + riser / 2),
                                                   role="riser")]))
    z_socket = zt + H + riser
    Hs = p.uniform("shade_height", 0.6, 0.9) * R + 0.05
    rs, hs = _socket_shade(ctx, p, root, z_socket, r_neck, ctx.choose("shade", SHADES), R, Hs)
    _switch(ctx, p.scope("switch"), root, p.choice("switch", SWITCHES), z_socket, rs, hs, r_neck, base, riser,
            float(abs(body.bounds()[:, :2]).max()))


# ---------------------------------------------------------------- floor lamp

def _floor(ctx, root):
    p, b = ctx.p, ctx.builder
    rb = p.uniform("base_radius", 0.13, 0.2)
    base = root.add(ctx.choose("base", FLOOR_BASES)(p.scope("base"), rb))
    zt = base.anchors["top"][2]
    rp = p.uniform("pole_radius", 0.009, 0.014)
    Hp = p.uniform("pole_height", 1.1, 1.5)
    root.add(Part("stand", "lamp_pole", [cylinder(rp, Hp, translation(0, 0, zt + Hp / 2), role="pole")],
                  regions={"grasp": Region(), "lift": Region()}))
    top = zt + Hp
    kind = p.choice("top", FLOOR_TOPS)
    if kind == "drum":
        R = p.uniform("shade_radius", 0.16, 0.25)
        Hs = p.uniform("shade_height", 0.22, 0.35)
        rs, hs = _socket_shade(ctx, p, root, top, rp, ctx.choose("shade", SHADES), R, Hs)
        _switch(ctx, p.scope("switch"), root, p.choice("switch", FLOOR_SWITCHES), top, rs, hs,
                rp, base, 0.1)
    elif kind == "torchiere":
        R = p.uniform("bowl_radius", 0.15, 0.23)
        h = p.uniform("bowl_height", 0.08, 0.15)
        t = 0.002
        r0 = p.uniform("bowl_bottom", 0.2, 0.35) * R
        bowl = [ring(r0, r0 - t, h, pose=translation(0, 0, top + h / 2), taper=R - r0, role="shade"),
                cylinder(r0, t, translation(0, 0, top + t / 2), role="shade")]
        root.add(Part("shade", "torchiere_bowl", bowl, regions={"lift": Region()}))
        root.add(bulb(p.scope("bulb"), min(0.03, 0.7 * r0)), translation(0, 0, top + t))
        knob = round_knob(p.scope("dimmer"), radius=p.uniform("dimmer_radius", 0.01, 0.015))
        zk = zt + p.uniform("dimmer_height", 0.7, 1.0)
        root.add(Part("stand", "dimmer_box", [cuboid(0.03, 0.04, 0.06, translation(-rp - 0.012, 0, zk), role="box")]))
        mount_knob(b, root, knob, translation(-rp - 0.027, 0, zk), continuous=False,
                   limits=(0.0, math.radians(270.0)))
    else:  # reading lamp: an adjustable neck from the pole top, a head at its end
        rk = p.uniform("knuckle_radius", 0.009, 0.012)
        lk = 2 * rp + 0.004
        root.add(Part("stand", "neck_knuckle", [cylinder(rk, lk, translation(0, 0, top) @ _ALONG_Y, role="knuckle")]))
        L = p.uniform("neck_length", 0.2, 0.35)
        up = math.radians(p.uniform("neck_rise", 20.0, 40.0))
        tw = 0.004
        neck = b.create_link("neck", root)
        neck.set_joint("revolute", translation(0, 0, top) @ rot_y(-(math.pi / 2 - up)), axis=(0.0, 1.0, 0.0),
                       limits=(-math.radians(p.uniform("neck_down", 20.0, 30.0)),
                               math.radians(p.uniform("neck_up", 15.0, 25.0))))
        neck.add(arm_link(p.scope("neck"), L, rk, tw, fork=lk + 0.002))
        R = p.uniform("head_radius", 0.06, 0.1)
        shade = ctx.choose("head", HEADS)(p.scope("shade"), R)
        # the head hangs below the neck's end, world-aligned at rest
        hang = translation(0, 0, L) @ rot_y(math.pi / 2 - up)
        drop = rk + 0.01
        stem = [cuboid(0.008, lk + 0.002 + 2 * tw, 0.006, hang @ translation(0, 0, -rk - 0.003), role="stem"),
                cylinder(0.005, drop, hang @ translation(0, 0, -rk - 0.003 - drop / 2), role="stem")]
        neck.add(Part("stand", "head_stem", stem))
        neck.add(shade, hang @ translation(0, 0, -rk - 0.003 - drop))
        neck.add(bulb(p.scope("bulb"), min(0.6 * shade.anchors["top_radius"][0], 0.025), down=True),
                 hang @ translation(0, 0, -rk - 0.005 - drop))
        _base_button(p.scope("switch"), b, root, base)


SUBS = {"desk_lamp": _desk, "table_lamp": _table, "floor_lamp": _floor}


def lamp(ctx):
    root = ctx.builder.create_link("base")
    SUBS[ctx.sub](ctx, root)


RULE = Category(
    name="lamp",
    subcategories={"desk_lamp": 2.0, "table_lamp": 2.0, "floor_lamp": 1.5},
    materials={"base": "aluminium", "body": "shell", "stand": "aluminium", "shade": "plastic", "arm": "aluminium"},
    mass_range=(0.4, 15.0),  # kg: a small table lamp (~0.8) to a floor lamp on a heavy base (4-10)
    slots=(Slot("lamp", lamp),),
)
