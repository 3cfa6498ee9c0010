"""Chairs: office swivel chairs, bar stools, folding chairs and four-leg lounge chairs.

Parts and joints:
- office: a star base (4-6 arms) whose casters swivel (continuous about z) and roll
  (one or two wheels per caster, continuous about the axle); a gas column (prismatic
  seat-height lift, 0.06-0.11 m); the seat with its tilt mechanism swivelling on it
  (continuous about z); a height lever (revolute); optional armrests, fixed or
  height-adjustable (prismatic); a backrest on a spine that reclines (revolute about y);
- bar_stool: a column on a disc base with a footrest ring, or four legs with rungs;
  the seat swivels (continuous), with an optional gas lift and lever, and an optional
  low curved back;
- folding: bent-tube front frame carrying the backrest; the rear legs fold (revolute
  about y at their pivot on the front tubes) and the seat flips up (revolute about its
  rear edge);
- four_leg: seat on four legs, optional arms, a reclining backrest (revolute about y at
  the seat's rear edge, as on garden and Morris chairs).
Backrests: panel, frame with mesh, slats or ladder; seats: slab, cushion, waterfall or
round. Sizes (metres): seat height 0.42-0.5 (office, lowest), 0.6-0.8 (bar stools),
0.43-0.46 (folding), seats 0.38-0.52 wide; office bases 0.56-0.68 across.
"""

from __future__ import annotations

import copy
import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, rect_ring, ring, torus, tube
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.seating import (BACKS, CASTERS, SEATS, STOOL_SEATS, paddle_lever, star_base, wheel)
from artipg.templates.supports import round_legs, square_legs, tapered_legs

LEGS = {square_legs: 1.0, round_legs: 1.0, tapered_legs: 1.0}
_ALONG_Y = rot_x(math.pi / 2)


def _box(lo, hi, role="frame"):
    return cuboid_between(lo, hi, role=role)


def _lever(ctx, link, p, x, y, z, clearance):
    """Paddle lever on the -y face y = ``y`` of ``link``; ``clearance`` = free height above its bar."""
    part = paddle_lever(p)
    reach = -part.bounds()[0][1]
    lk = ctx.builder.create_link("lever", link)
    lk.set_joint("revolute", translation(x, y, z), axis=(-1, 0, 0),
                 limits=(0.0, min(0.35, math.asin((clearance - 0.004) / reach))))
    lk.add(part)


def _office(ctx):
    p = ctx.p
    n = p.choice("arms", {5: 8.0, 4: 1.0, 6: 1.0})
    reach, rw, ww = p.uniform("reach", 0.28, 0.34), p.uniform("wheel_radius", 0.024, 0.033), p.uniform("wheel_width", 0.014, 0.022)
    ah = p.uniform("arm_height", 0.03, 0.045)
    caster = ctx.choose("caster", CASTERS)(p.scope("caster"), rw, ww)
    za, (y0, y1, _) = caster.anchor("axle"), caster.anchor("wheel_y")
    z_arm = rw - za[2]
    root = ctx.builder.create_link("base")
    star = star_base(p.scope("star"), reach, n, ah)
    root.add(star, translation(0, 0, z_arm))
    for i in range(n):
        fork = ctx.builder.create_link("caster", root)
        fork.set_joint("continuous", rot_z(2 * math.pi * i / n) @ translation(reach, 0, z_arm))
        fork.add(copy.copy(caster))
        for y in ((y0,) if y0 == y1 else (y0, y1)):
            wl = ctx.builder.create_link("wheel", fork)
            wl.set_joint("continuous", translation(za[0], y, za[2]), axis=(0, 1, 0))
            wl.add(wheel(p.scope(f"wheel{i}{int(y > 0)}"), rw, ww))
    sd, sw = p.uniform("seat_depth", 0.42, 0.5), p.uniform("seat_width", 0.44, 0.52)
    seat = ctx.choose("seat", SEATS)(p.scope("seat"), sd, sw)
    st = seat.anchor("top")[2]
    mh, mw = p.uniform("mech_height", 0.04, 0.06), p.uniform("mech_width", 0.16, 0.24)
    hub_top = z_arm + star.anchor("hub_top")[2]
    travel = p.uniform("lift", 0.06, 0.11)
    z_pt = p.uniform("seat_height", 0.42, 0.5) - st - mh
    z_t = max(min(hub_top + p.uniform("tube_length", 0.12, 0.2), z_pt - 0.03), hub_top + travel + 0.03)
    ro = p.uniform("tube_radius", 0.024, 0.03)
    root.add(Part("base", "gas_tube", [ring(ro, ro - 0.004, z_t - hub_top, pose=translation(0, 0, (hub_top + z_t) / 2), role="tube")]))
    lift = ctx.builder.create_link("column", root)
    lift.set_joint("prismatic", translation(0, 0, z_pt), axis=(0, 0, 1), limits=(0.0, travel))
    L = z_pt - hub_top - 0.005
    lift.add(Part("base", "piston", [cylinder(ro - 0.0055, L, translation(0, 0, -L / 2), role="piston")]))
    sl = ctx.builder.create_link("seat", lift)
    sl.set_joint("continuous", translation(0, 0, 0))
    spine = p.uniform("spine", 0.03, 0.08)
    x_p = sd / 2 + 0.005
    sl.add(Part("base", "tilt_mechanism", [_box((-mw / 2, -mw / 2, 0), (mw / 2, mw / 2, mh)),
                                           _box((mw / 2, -0.035, 0), (x_p, 0.035, 0.8 * mh))]))
    sl.add(seat, translation(0, 0, mh))
    _lever(ctx, sl, p.scope("lever"), -mw / 2 + 0.025, -mw / 2, 0.018, mh - 0.018)
    if p.flag("armrests", 0.75):
        _office_arms(ctx, sl, p.scope("armrest"), mw, sw, mh + st, x_p - 0.01)
    return {"link": sl, "pivot": translation(x_p, 0, 0), "width": sw - 0.02, "height": (0.35, 0.65),
            "z0": mh + st, "spine": spine}


def _office_arms(ctx, link, p, mw, sw, top, x_max):
    pw, ha = p.uniform("post", 0.025, 0.04), p.uniform("height", 0.18, 0.25)
    pl, pd, pt = p.uniform("pad_length", 0.2, 0.26), p.uniform("pad_width", 0.06, 0.09), 0.025
    xa = min(0.0, x_max - pl / 2)
    adjustable = p.flag("adjustable", 0.5)
    travel = min(p.uniform("travel", 0.04, 0.08), top - 0.025)
    for s in (-1, 1):
        yo = s * (sw / 2 + 0.015 + pw / 2)
        ya, yb = sorted((s * mw / 2, yo + s * pw / 2))
        prims = [_box((xa - pw / 2, ya, 0.0), (xa + pw / 2, yb, 0.015))]
        pad = _box((xa - pl / 2, yo - pd / 2, top + ha - pt), (xa + pl / 2, yo + pd / 2, top + ha), role="pad")
        post = ((xa - pw / 2, yo - pw / 2), (xa + pw / 2, yo + pw / 2))
        if not adjustable:
            link.add(Part("armrest", "post_arm", prims + [_box((*post[0], 0.0), (*post[1], top + ha - pt)), pad]))
            continue
        zs = top + 0.02  # sleeve top
        link.add(Part("armrest", "arm_sleeve", prims + [rect_ring(pw, pw, zs - 0.015, pw - 0.006, pw - 0.006,
                                                                   translation(xa, yo, (zs + 0.015) / 2), role="sleeve")]))
        up = ctx.builder.create_link("armrest", link)
        up.set_joint("prismatic", translation(xa, yo, 0), axis=(0, 0, 1), limits=(0.0, travel))
        c = pw / 2 - 0.004
        up.add(Part("armrest", "arm_pad", [_box((-c, -c, zs - travel - 0.02), (c, c, top + ha - pt)),
                                           pad.placed(translation(-xa, -yo, 0))], regions={"push": Region(("pad",))}))


def _stool(ctx):
    p = ctx.p
    hs, d = p.uniform("seat_height", 0.6, 0.8), p.uniform("seat_size", 0.32, 0.42)
    seat = ctx.choose("seat", STOOL_SEATS)(p.scope("seat"), d, d)
    gas = p.flag("gas_lift", 0.45)
    bh, br = p.uniform("bearing", 0.04, 0.06) if gas else p.uniform("bearing", 0.015, 0.03), p.uniform("bearing_radius", 0.06, 0.1)
    z_sw = hs - seat.anchor("top")[2] - bh
    root = ctx.builder.create_link("base")
    parent, origin = root, translation(0, 0, z_sw)
    if gas or p.flag("column", 0.6):
        rb, th = p.uniform("base_radius", 0.19, 0.25), p.uniform("base_height", 0.02, 0.05)
        ro, zf = p.uniform("column_radius", 0.022, 0.035), p.uniform("footrest_z", 0.25, 0.35)
        Rf = p.uniform("footrest_radius", 0.15, 0.2)
        prims = [frustum(rb, rb * p.uniform("dome", 0.6, 1.0), th, translation(0, 0, th / 2), role="foot"),
                 torus(Rf, 0.01, pose=translation(0, 0, zf), role="footrest")]
        prims += [cuboid(Rf - ro + 0.002, 0.012, 0.012, rot_z(2 * math.pi * i / 3) @ translation((Rf + ro - 0.002) / 2, 0, zf),
                         role="spoke") for i in range(3)]
        if gas:
            travel, z_t = p.uniform("lift", 0.08, 0.15), z_sw - p.uniform("exposed", 0.04, 0.08)
            prims.append(ring(ro, ro - 0.004, z_t - th, pose=translation(0, 0, (z_t + th) / 2), role="column"))
            parent = ctx.builder.create_link("column", root)
            parent.set_joint("prismatic", origin, axis=(0, 0, 1), limits=(0.0, travel))
            parent.add(Part("base", "piston", [cylinder(ro - 0.0055, z_sw - th - 0.005, translation(0, 0, -(z_sw - th - 0.005) / 2))]))
            origin = translation(0, 0, 0)
        else:
            prims.append(cylinder(ro, z_sw - th, translation(0, 0, (z_sw + th) / 2), role="column"))
        root.add(Part("base", "column_base", prims))
    else:
        fw, tp = p.uniform("footprint", 0.34, 0.44), p.uniform("plate", 0.02, 0.03)
        legs = ctx.choose("legs", LEGS)(p.scope("legs"), fw, fw, z_sw - tp)
        b = legs.primitives[0].bounds()
        c, zr = -(b[0] + b[1]) / 2, p.uniform("rung_z", 0.22, 0.32)
        rungs = [_box((-c[0], s * c[1] - 0.01, zr), (c[0], s * c[1] + 0.01, zr + 0.02), "rung") for s in (-1, 1)]
        rungs += [_box((s * c[0] - 0.01, -c[1], zr), (s * c[0] + 0.01, c[1], zr + 0.02), "rung") for s in (-1, 1)]
        root.add(legs)
        root.add(Part("base", "stool_frame", rungs + [cuboid(fw, fw, tp, translation(0, 0, z_sw - tp / 2), role="plate")]))
    sl = ctx.builder.create_link("seat", parent)
    sl.set_joint("continuous", origin)
    sl.add(Part("base", "bearing", [cylinder(br, bh, translation(0, 0, bh / 2), role="bearing")]))
    sl.add(seat, translation(0, 0, bh))
    if gas:
        _lever(ctx, sl, p.scope("lever"), 0.0, -br, 0.02, bh - 0.02)
    if p.flag("back", 0.4):
        ro, t, h, a = 0.47 * d, p.uniform("back_thickness", 0.012, 0.02), p.uniform("back_height", 0.06, 0.12), p.uniform("back_arc", 1.4, 2.2)
        zb = bh + seat.anchor("top")[2] + p.uniform("back_gap", 0.1, 0.2)
        posts = [cylinder(0.01, zb - bh, rot_z(s * a / 3) @ translation(ro - t / 2, 0, (zb + bh) / 2), role="post") for s in (-1, 1)]
        sl.add(Part("backrest", "ring_back", posts + [ring(ro, ro - t, h, a, rot_z(-a / 2) @ translation(0, 0, zb + h / 2), role="board")]))
    return {}


def _folding(ctx):
    p = ctx.p
    hs, sd, sw = p.uniform("seat_height", 0.43, 0.46), p.uniform("seat_depth", 0.36, 0.42), p.uniform("seat_width", 0.38, 0.44)
    rp, st = p.uniform("tube_radius", 0.009, 0.0125), p.uniform("seat_thickness", 0.015, 0.03)
    lo, up, hb = p.uniform("leg_angle", 0.45, 0.65), p.uniform("back_angle", 0.1, 0.25), p.uniform("back_top", 0.35, 0.45)
    zb, Rb = hs - st / 2, 0.05
    d = Rb * math.tan((lo - up) / 2)
    fx = -zb * math.tan(lo)
    path = [line(zb / math.cos(lo) - d), arc(Rb, lo - up), line((hb + st / 2) / math.cos(up) - d)]
    root = ctx.builder.create_link("base")
    prims = [pr for s in (-1, 1) for pr in tube(rp, path, math.pi / 2 - lo, translation(fx, s * (sw / 2 + rp), 0), role="tube")]
    bh, tb = p.uniform("back_height", 0.12, 0.2), p.uniform("back_thickness", 0.01, 0.02)
    zc = hs + hb - 0.02 - bh / 2
    T = translation((zc - zb) * math.tan(up) + 0.3 * rp + tb / 2, 0, zc) @ rot_y(up)
    prims.append(cuboid(tb, sw + 2 * rp, bh, T, role="board"))
    root.add(Part("frame", "folding_frame", prims))
    seat = ctx.builder.create_link("seat", root)
    seat.set_joint("revolute", translation(0, 0, hs), axis=(0, 1, 0), limits=(0.0, p.uniform("seat_fold", 1.35, 1.5)))
    seat.add(Part("seat", "folding_seat", [_box((-sd, -sw / 2, -st), (0.0, sw / 2, 0.0), "cushion")], regions={"lift": Region(("cushion",))}))
    f = p.uniform("pivot", 0.45, 0.7)
    Q = np.array([fx * (1 - f), zb * f])
    R = np.array([p.uniform("rear_foot", 0.05, 0.15), 0.0])
    u, v = R - Q, np.array([fx, 0.0]) - Q
    Lr, gc = float(np.hypot(*u)), p.uniform("crossbar", 0.75, 0.9)
    alpha = math.acos(float(u @ v) / Lr / float(np.hypot(*v)))
    rear = ctx.builder.create_link("leg", root)
    rear.set_joint("revolute", translation(Q[0], 0, Q[1]), axis=(0, 1, 0),
                   limits=(0.0, alpha - math.asin((0.9 * rp + rp + 0.004) / (gc * Lr))))
    yl = sw / 2 + 3 * rp
    legs = [cylinder(rp, Lr, translation(u[0] / 2, s * yl, u[1] / 2) @ rot_y(math.atan2(u[0], u[1])), role="leg") for s in (-1, 1)]
    legs.append(cylinder(0.9 * rp, 2 * yl, translation(gc * u[0], 0, gc * u[1]) @ _ALONG_Y, role="crossbar"))
    rear.add(Part("leg", "rear_legs", legs))
    return {}


def _four_leg(ctx):
    p = ctx.p
    hs, sd, sw = p.uniform("seat_height", 0.42, 0.48), p.uniform("seat_depth", 0.4, 0.5), p.uniform("seat_width", 0.4, 0.5)
    seat = ctx.choose("seat", SEATS)(p.scope("seat"), sd, sw)
    st = seat.anchor("top")[2]
    root = ctx.builder.create_link("base")
    root.add(ctx.choose("legs", LEGS)(p.scope("legs"), sd, sw, hs - st))
    root.add(seat, translation(0, 0, hs - st))
    if p.flag("arms", 0.4):
        pw, ha, e = p.uniform("arm_post", 0.025, 0.04), p.uniform("arm_height", 0.18, 0.25), p.uniform("arm_inset", 0.02, 0.06)
        prims = []
        for s in (-1, 1):
            y0, y1 = sorted((s * sw / 2, s * (sw / 2 - pw)))
            prims += [_box((-sd / 2 + e, y0, hs), (-sd / 2 + e + pw, y1, hs + ha)),
                      _box((sd / 2 - pw - 0.006, y0, hs), (sd / 2 - 0.006, y1, hs + ha)),
                      _box((-sd / 2 - 0.02, y0 - 0.01, hs + ha), (sd / 2 - 0.006, y1 + 0.01, hs + ha + 0.025), "pad")]
        root.add(Part("armrest", "post_arms", prims, regions={"push": Region(("pad",))}))
    return {"link": root, "pivot": translation(sd / 2, 0, hs - st), "width": sw, "height": (0.3, 0.5), "z0": st, "spine": 0.0}


BUILD = {"office": _office, "bar_stool": _stool, "folding": _folding, "four_leg": _four_leg}


def frame(ctx):
    return BUILD[ctx.sub](ctx)


def back(ctx):
    f = ctx.out["frame"]
    if "pivot" not in f:
        return
    p = ctx.p
    bw = min(p.uniform("width", 0.36, 0.5), f["width"])
    part = ctx.choose("back", BACKS)(p, bw, p.uniform("height", *f["height"]), f["z0"] + p.uniform("gap", 0.02, 0.1),
                                     p.uniform("lean", 0.05, 0.2), f["spine"])
    link = ctx.builder.create_link("backrest", f["link"])
    link.set_joint("revolute", f["pivot"], axis=(0, 1, 0), limits=(0.0, p.uniform("recline", 0.2, 0.45)))
    link.add(part)


RULE = Category(
    name="chair",
    subcategories={"office": 6.0, "four_leg": 1.5, "folding": 1.5, "bar_stool": 1.0},
    slots=(Slot("frame", frame), Slot("back", back, after=("frame",))),
)
