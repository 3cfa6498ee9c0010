"""Chair frames: bar-stool bases, a stool's curved back, four-leg chair arms, and the
folding chair's bent-tube front frame and rear legs.

Frames (metres, +z up, the sitter faces -x):
- stool bases: origin on the floor under the seat axis, reaching up to ``top`` (where
  the seat's swivel bearing sits); ``column_stool_base`` exposes ``bore`` = (inner
  radius of its gas-lift tube, 0, height of the tube's bottom) when ``gas`` is set;
- ``ring_back``: in the seat link, origin on the swivel axis at the bearing's bottom;
- ``post_arms``: in the chair's frame, the seat of ``depth`` x ``width`` centred on the
  z axis with its top at ``z``; the arms end ``clear`` short of the seat's rear edge;
- ``folding_frame``: origin on the floor below the seat's rear top edge; anchors
  ``seat_pivot`` (the seat's rear top edge) and ``leg_pivot`` (where the rear legs
  hinge on the front tubes, on their centre line);
- ``folding_rear_legs``: origin on the leg pivot; the legs run to ``foot`` = (dx, dz)
  from it; anchor ``crossbar`` = (distance from the pivot, radius, 0).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, ring, torus, tube
from artipg.geometry.transforms import Placer, rot_x, rot_y, rot_z, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Part, Region
from artipg.templates.extents import span
from artipg.templates.seating import turns

_ALONG_Y = Placer(rot_x(math.pi / 2))


def _box(lo, hi, role):
    return cuboid_between(lo, hi, role=role)


def column_stool_base(p, top: float, gas: bool = False) -> Part:
    """Round foot (disc or dome), a column (a gas-lift tube when ``gas``) and a
    footrest ring on three spokes."""
    rb, th = p.uniform("base_radius", 0.19, 0.25), p.uniform("base_height", 0.02, 0.05)
    ro, zf = p.uniform("column_radius", 0.022, 0.035), p.uniform("footrest_z", 0.25, 0.35)
    rf = p.uniform("footrest_radius", 0.15, 0.2)
    prims = [frustum(rb, rb * p.uniform("dome", 0.6, 1.0), th, translation(0, 0, th / 2), role="foot"),
             torus(rf, 0.01, pose=translation(0, 0, zf), role="footrest")]
    spoke = translation((rf + ro - 0.002) / 2, 0, zf)  # from inside the column's wall to the ring
    prims += [cuboid(rf - ro + 0.002, 0.012, 0.012, T, role="spoke") for T in turns(3) @ spoke]
    anchors = {"top": (0.0, 0.0, top)}
    if gas:  # the tube stops short of the seat: the piston shows above it
        zt = top - p.uniform("exposed", 0.04, 0.08)
        prims.append(ring(ro, ro - 0.004, zt - th, pose=translation(0, 0, (zt + th) / 2), role="column"))
        anchors["bore"] = (ro - 0.004, 0.0, th)
    else:
        prims.append(cylinder(ro, top - th, translation(0, 0, (top + th) / 2), role="column"))
    return Part("base", "column_stool_base", prims, anchors=anchors)


def leg_stool_frame(p, legs: Part, footprint: float, top: float) -> Part:
    """Top plate (down to the legs' tops) and a ring of rungs for four stool ``legs``
    (a supports template part)."""
    tp = top - span(legs.primitives, 2)[1]
    b = legs.primitives[0].bounds()
    c, zr = -(b[0] + b[1]) / 2, p.uniform("rung_z", 0.22, 0.32)
    prims = [_box((-c[0], s * c[1] - 0.01, zr), (c[0], s * c[1] + 0.01, zr + 0.02), "rung") for s in (-1, 1)]
    prims += [_box((s * c[0] - 0.01, -c[1], zr), (s * c[0] + 0.01, c[1], zr + 0.02), "rung") for s in (-1, 1)]
    prims.append(cuboid(footprint, footprint, tp, translation(0, 0, top - tp / 2), role="plate"))
    return Part("base", "leg_stool_frame", prims, anchors={"plate": (0.0, 0.0, top - tp)})


def ring_back(p, radius: float, z0: float, z_seat: float) -> Part:
    """Low curved back: a ring arc centred behind the axis on two posts rising from z0."""
    t, h = p.uniform("thickness", 0.012, 0.02), p.uniform("height", 0.06, 0.12)
    a = p.uniform("arc", 1.4, 2.2)
    zb = z_seat + p.uniform("gap", 0.1, 0.2)
    posts = [cylinder(0.01, zb - z0, rot_z(s * a / 3) @ translation(radius - t / 2, 0, (zb + z0) / 2), role="post")
             for s in (-1, 1)]
    board = ring(radius, radius - t, h, a, rot_z(-a / 2) @ translation(0, 0, zb + h / 2), role="board")
    return Part("backrest", "ring_back", posts + [board], regions={"push": Region(("board",))})


def post_arms(p, depth: float, width: float, z: float, clear: float = 0.006) -> Part:
    """Two arms, each a front and a rear post on the seat and a rail on top."""
    pw, ha, e = p.uniform("post", 0.025, 0.04), p.uniform("height", 0.18, 0.25), p.uniform("inset", 0.02, 0.06)
    prims = []
    for s in (-1, 1):
        y0, y1 = sorted((s * width / 2, s * (width / 2 - pw)))
        prims += [_box((-depth / 2 + e, y0, z), (-depth / 2 + e + pw, y1, z + ha), "post"),
                  _box((depth / 2 - pw - clear, y0, z), (depth / 2 - clear, y1, z + ha), "post"),
                  _box((-depth / 2 - 0.02, y0 - 0.01, z + ha), (depth / 2 - clear, y1 + 0.01, z + ha + 0.025), "pad")]
    return Part("armrest", "post_arms", prims, regions={"push": Region(("pad",))})


def folding_frame(p, seat_height: float, seat_depth: float, seat_width: float, tube_radius: float,
                  seat_thickness: float) -> Part:
    """Two bent tubes (front legs rising into the back posts) joined by a back board,
    with flat hinge plates where the seat and the rear legs bear on them."""
    hs, sw, rp, st = seat_height, seat_width, tube_radius, seat_thickness
    lo, up = p.uniform("leg_angle", 0.45, 0.65), p.uniform("back_angle", 0.1, 0.25)
    hb = p.uniform("back_top", 0.35, 0.45)
    zb, rb = hs - st / 2, 0.05
    d = rb * math.tan((lo - up) / 2)
    fx = -zb * math.tan(lo)
    path = [line(zb / math.cos(lo) - d), arc(rb, lo - up), line((hb + st / 2) / math.cos(up) - d)]
    prims = [pr for s in (-1, 1) for pr in tube(rp, path, math.pi / 2 - lo, translation(fx, s * (sw / 2 + rp), 0),
                                                  role="tube")]
    bh, tb = p.uniform("back_height", 0.12, 0.2), p.uniform("back_thickness", 0.01, 0.02)
    zc = hs + hb - 0.02 - bh / 2  # the board sits behind the tubes, clear of the flipped-up seat
    xc = (zc - zb) * math.tan(up) + 0.3 * rp + tb / 2
    prims.append(cuboid(tb, sw + 2 * rp, bh, translation(xc, 0, zc) @ rot_y(up), role="board"))
    f = p.uniform("pivot", 0.45, 0.7)
    q = (fx * (1 - f), zb * f)
    for s in (-1, 1):
        prims += [_box((-0.025, min(s * sw / 2, s * (sw / 2 + rp)), zb - 0.02),
                       (0.015, max(s * sw / 2, s * (sw / 2 + rp)), zb + 0.02), "hinge"),
                  _box((q[0] - 0.02, min(s * (sw / 2 + rp), s * (sw / 2 + 2 * rp)), q[1] - 0.02),
                       (q[0] + 0.02, max(s * (sw / 2 + rp), s * (sw / 2 + 2 * rp)), q[1] + 0.02), "hinge")]
    return Part("frame", "folding_frame", prims,
                anchors={"seat_pivot": (0.0, 0.0, hs), "leg_pivot": (q[0], 0.0, q[1]), "front_foot": (fx, 0.0, 0.0)})


def folding_rear_legs(p, foot, y: float, tube_radius: float) -> Part:
    """Two square-tube legs from the pivot to ``foot`` = (dx, dz) at y = +-``y``, joined
    near the floor by a round crossbar."""
    u = np.asarray(foot, dtype=float)
    L, gc = float(np.hypot(*u)), p.uniform("crossbar", 0.75, 0.9)
    R = rot_y(math.atan2(u[0], u[1]))
    r = tube_radius
    prims = [cuboid(2 * r, 2 * r, L, translation(u[0] / 2, s * y, u[1] / 2) @ R, role="leg") for s in (-1, 1)]
    prims.append(cylinder(0.9 * r, 2 * y, _ALONG_Y.at(gc * u[0], 0, gc * u[1]), role="crossbar"))
    return Part("leg", "folding_rear_legs", prims, anchors={"crossbar": (gc * L, 0.9 * r, 0.0)})
