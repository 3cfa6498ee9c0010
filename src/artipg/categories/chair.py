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

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, rect_ring, ring
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region
from artipg.rules import Category, Slot
from artipg.templates.chair_frames import (column_stool_base, folding_frame, folding_rear_legs, leg_stool_frame,
                                           post_arms, ring_back)
from artipg.templates.extents import span
from artipg.templates.seating import BACKS, CASTERS, SEATS, STOOL_SEATS, paddle_lever, star_base, turns, wheel
from artipg.templates.supports import round_legs, square_legs, tapered_legs

LEGS = {square_legs: 1.0, round_legs: 1.0, tapered_legs: 1.0}
STAR_ARMS = {5: 8.0, 4: 1.0, 6: 1.0}  # office chair bases: nearly always five casters
_new = object.__new__


def _clone(part: Part) -> Part:
    """``copy.copy(part)`` (a shallow copy: template knowledge shared, name, pose and
    parameter span set when added) without the copy protocol's reduce round trip."""
    c = _new(Part)
    c.__dict__.update(part.__dict__)
    return c


def _box(lo, hi, role="frame"):
    return cuboid_between(lo, hi, role=role)


def _lever(ctx, link, p, x, y, z, clearance):
    """Paddle lever on the -y face y = ``y`` of ``link``; ``clearance`` = free height above its bar."""
    part = paddle_lever(p)
    reach = -span(part.primitives, 1)[0]
    lk = ctx.builder.create_link("lever", link)
    lk.set_joint("revolute", translation(x, y, z), axis=(-1, 0, 0),
                 limits=(0.0, min(0.35, math.asin((clearance - 0.004) / reach))))
    lk.add(part)


def _office(ctx):
    p = ctx.p
    n = p.choice("arms", STAR_ARMS)
    reach, rw = p.uniform("reach", 0.28, 0.34), p.uniform("wheel_radius", 0.024, 0.033)
    ww = p.uniform("wheel_width", 0.014, 0.022)
    ah = p.uniform("arm_height", 0.03, 0.045)
    caster = ctx.choose("caster", CASTERS)(p.scope("caster"), rw, ww)
    za, (y0, y1, _) = caster.anchors["axle"], caster.anchors["wheel_y"]
    z_arm = rw - za[2]
    root = ctx.builder.create_link("base")
    star = star_base(p.scope("star"), reach, n, ah)
    root.add(star, translation(0, 0, z_arm))
    tyre = wheel(p.scope("wheel"), rw, ww)  # one caster and one wheel design, copied
    axles = [translation(za[0], y, za[2]) for y in ((y0,) if y0 == y1 else (y0, y1))]  # the same in every fork
    for T in turns(n) @ translation(reach, 0, z_arm):
        fork = ctx.builder.create_link("caster", root)
        fork.set_joint("continuous", T)
        fork.add(_clone(caster))
        for A in axles:
            wl = ctx.builder.create_link("wheel", fork)
            wl.set_joint("continuous", A.copy(), axis=(0, 1, 0))
            wl.add(_clone(tyre))
    sd, sw = p.uniform("seat_depth", 0.42, 0.5), p.uniform("seat_width", 0.44, 0.52)
    seat = ctx.choose("seat", SEATS)(p.scope("seat"), sd, sw)
    st = seat.anchors["top"][2]
    mh, mw = p.uniform("mech_height", 0.04, 0.06), p.uniform("mech_width", 0.16, 0.24)
    hub_top = z_arm + star.anchors["hub_top"][2]
    travel = p.uniform("lift", 0.06, 0.11)
    z_pt = p.uniform("seat_height", 0.42, 0.5) - st - mh
    z_t = max(min(hub_top + p.uniform("tube_length", 0.12, 0.2), z_pt - 0.03), hub_top + travel + 0.03)
    ro = p.uniform("tube_radius", 0.024, 0.03)
    tube = ring(ro, ro - 0.004, z_t - hub_top, pose=translation(0, 0, (hub_top + z_t) / 2), role="tube")
    root.add(Part("base", "gas_tube", [tube]))
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
        sleeve = rect_ring(pw, pw, zs - 0.015, pw - 0.006, pw - 0.006, translation(xa, yo, (zs + 0.015) / 2),
                           role="sleeve")
        link.add(Part("armrest", "arm_sleeve", prims + [sleeve]))
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
    bh = p.uniform("bearing", 0.04, 0.06) if gas else p.uniform("bearing", 0.015, 0.03)
    br = p.uniform("bearing_radius", 0.06, 0.1)
    z_sw = hs - seat.anchors["top"][2] - bh
    root = ctx.builder.create_link("base")
    parent, origin = root, translation(0, 0, z_sw)
    if gas or p.flag("column", 0.6):
        base = column_stool_base(p.scope("base"), z_sw, gas)
        root.add(base)
        if gas:  # the piston slides in the tube's bore
            r, _, z0 = base.anchors["bore"]
            parent = ctx.builder.create_link("column", root)
            parent.set_joint("prismatic", origin, axis=(0, 0, 1), limits=(0.0, p.uniform("lift", 0.08, 0.15)))
            L = z_sw - z0 - 0.005
            parent.add(Part("base", "piston", [cylinder(r - 0.0015, L, translation(0, 0, -L / 2), role="piston")]))
            origin = translation(0, 0, 0)
    else:
        fw = p.uniform("footprint", 0.34, 0.44)
        legs = ctx.choose("legs", LEGS)(p.scope("legs"), fw, fw, z_sw - p.uniform("plate", 0.02, 0.03))
        root.add(legs)
        root.add(leg_stool_frame(p.scope("frame"), legs, fw, z_sw))
    sl = ctx.builder.create_link("seat", parent)
    sl.set_joint("continuous", origin)
    sl.add(Part("base", "bearing", [cylinder(br, bh, translation(0, 0, bh / 2), role="bearing")]))
    sl.add(seat, translation(0, 0, bh))
    if gas:
        _lever(ctx, sl, p.scope("lever"), 0.0, -br, 0.02, bh - 0.02)
    if p.flag("back", 0.4):
        sl.add(ring_back(p.scope("back"), 0.47 * d, bh, bh + seat.anchors["top"][2]))
    return {}


def _folding(ctx):
    p = ctx.p
    hs, sd = p.uniform("seat_height", 0.43, 0.46), p.uniform("seat_depth", 0.36, 0.42)
    sw = p.uniform("seat_width", 0.38, 0.44)
    rp, st = p.uniform("tube_radius", 0.009, 0.0125), p.uniform("seat_thickness", 0.015, 0.03)
    frame = folding_frame(p.scope("frame"), hs, sd, sw, rp, st)
    root = ctx.builder.create_link("base")
    root.add(frame)
    seat = ctx.builder.create_link("seat", root)  # flips up about its rear edge, staying in front of it
    seat.set_joint("revolute", translation(*frame.anchors["seat_pivot"]), axis=(0, 1, 0),
                   limits=(0.0, p.uniform("seat_fold", 1.35, 1.5)))
    seat.add(Part("seat", "folding_seat", [_box((-sd, -sw / 2, -st), (0.0, sw / 2, 0.0), "cushion")],
                  regions={"lift": Region(("cushion",))}))
    q, fx = frame.anchors["leg_pivot"], frame.anchors["front_foot"][0]
    u = np.array([p.uniform("rear_foot", 0.05, 0.15) - q[0], -q[2]])  # pivot -> rear foot
    # all four feet on the floor: the rear legs (square tubes cut square to their axis)
    # reach down with a corner as far as the front tubes (cut square too) with their rim
    drop = rp * math.sin(math.atan2(-fx, hs - st / 2))
    for _ in range(2):
        u[1] = -q[2] + rp * abs(math.sin(math.atan2(u[0], u[1]))) - drop
    v = np.array([fx - q[0], -q[2]])  # pivot -> front foot
    legs = folding_rear_legs(p.scope("rear"), u, sw / 2 + 3 * rp, rp)  # outside the tubes and their plates
    lc, rc, _ = legs.anchors["crossbar"]
    alpha = math.acos(float(u @ v) / float(np.hypot(*u)) / float(np.hypot(*v)))
    rear = ctx.builder.create_link("leg", root)  # folds forward until the crossbar nears the front tubes
    rear.set_joint("revolute", translation(*q), axis=(0, 1, 0), limits=(0.0, alpha - math.asin((rc + rp + 0.004) / lc)))
    rear.add(legs)
    return {}


def _four_leg(ctx):
    p = ctx.p
    hs, sd = p.uniform("seat_height", 0.42, 0.48), p.uniform("seat_depth", 0.4, 0.5)
    sw = p.uniform("seat_width", 0.4, 0.5)
    seat = ctx.choose("seat", SEATS)(p.scope("seat"), sd, sw)
    st = seat.anchors["top"][2]
    root = ctx.builder.create_link("base")
    root.add(ctx.choose("legs", LEGS)(p.scope("legs"), sd, sw, hs - st))
    root.add(seat, translation(0, 0, hs - st))
    if p.flag("arms", 0.4):  # they end in front of the reclining back's pivot
        root.add(post_arms(p.scope("arms"), sd, sw, hs))
    return {"link": root, "pivot": translation(sd / 2, 0, hs - st), "width": sw, "height": (0.3, 0.5), "z0": st,
            "spine": 0.0}


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
    mass_range=(2.0, 25.0),  # kg: folding chairs to office chairs with a five-star base
    slots=(Slot("frame", frame), Slot("back", back, after=("frame",))),
)
