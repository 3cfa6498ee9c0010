"""Toilet parts: bowls on a pedestal or hung from a wall, cisterns (tanks) and their lids,
seat rings and seat lids, the flush lever, and the swing limit of hinged seats.

Frames (every template here): the object frame, +z up, the user faces +x standing at
-x (the bowl's front is at -x, the hinge and the tank at +x), the bowl's centre on the
z axis, the floor at z = 0.
- Bowl outlines are superellipses ``|x / a|^n + |y / b|^n = 1`` (``a`` the half
  length along x, ``b`` the half width); :data:`BOWLS` draws (a, b, n).
- ``seat_ring`` / ``seat_lid``: in the hinge frame (origin on the hinge axis, axis +y;
  the part lies along -x from it). A positive rotation about +y lifts the front.
- ``flush_lever``: mount frame on the tank's front face (outward normal -x), the
  joint axis is +x through the hub, the arm reaches along -y (towards the middle).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder
from artipg.geometry.extrusion import extrusion
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region

_ALONG_X = Placer(rot_y(math.pi / 2))
_ALONG_Y = rot_x(-math.pi / 2)
# gripper approaching +x (a slab's front edge), jaws closing along z (pinch)
_EDGE = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_UP = np.array([0.0, 0.0, 1.0])
_K = 20  # vertices of a bowl outline


def superellipse(a: float, b: float, n: float, k: int = _K, t0: float = -math.pi, t1: float = math.pi,
                 closed: bool = True) -> np.ndarray:
    """Vertices (k, 3) ``(x, y, bulge = 0)`` of the superellipse of half axes ``a`` (x),
    ``b`` (y) and exponent ``n``, counter-clockwise from angle ``t0`` to ``t1``."""
    t = np.linspace(t0, t1, k, endpoint=not closed)
    c, s = np.cos(t), np.sin(t)
    e = 2.0 / n
    return np.stack([a * np.sign(c) * np.abs(c) ** e, b * np.sign(s) * np.abs(s) ** e, np.zeros(k)], axis=1)


def round_bowl(p):
    """Round-front bowl outline (a, b, n): 0.36-0.42 m long, 0.34-0.38 m wide."""
    return p.uniform("half_length", 0.18, 0.21), p.uniform("half_width", 0.17, 0.19), 2.0


def elongated_bowl(p):
    """Elongated bowl outline: 0.43-0.5 m long, 0.34-0.39 m wide, a slightly full oval."""
    return p.uniform("half_length", 0.215, 0.25), p.uniform("half_width", 0.17, 0.195), p.uniform("exponent", 2.0, 2.4)


def square_bowl(p):
    """Square-design bowl outline: a rounded rectangle (exponent 3-4.5), 0.4-0.48 m long."""
    return p.uniform("half_length", 0.2, 0.24), p.uniform("half_width", 0.165, 0.185), p.uniform("exponent", 3.0, 4.5)


BOWLS = {round_bowl: 1.0, elongated_bowl: 2.0, square_bowl: 1.0}


def _bands(a, b, n, wall, z0, z1, s0, s1, k, role, dx=0.0) -> list:
    """A tapering superellipse solid (or shell of ``wall``) from z0 (outline scaled by
    s0) to z1 (scaled by s1) as ``k`` straight bands, each scaled at its mid-height:
    straight extrusions keep the distance field exact."""
    out, h = [], (z1 - z0) / k
    for i in range(k):
        f = s0 + (s1 - s0) * (i + 0.5) / k
        loops = [superellipse(a * f, b * f, n)]
        if wall is not None:
            loops.append(superellipse(a * f - wall, b * f - wall, n))
        out.append(extrusion(loops, h, 1.0, translation(dx, 0, z0 + h * (i + 0.5)), role=role))
    return out


def toilet_bowl(p, outline, rim: float, depth: float, foot: bool, back: float, deck_width: float,
                deck_floor: float) -> Part:
    """Ceramic bowl of outline ``outline`` = (a, b, n) whose rim is at height ``rim``.

    The bowl is a tapered shell ``depth`` deep (walls 18-30 mm at the rim); with
    ``foot`` a pedestal (trapway) carries it from the floor. A rear deck ``deck_width``
    wide, from ``deck_floor`` up to the rim, joins it to x = ``back`` (the tank's back
    or the wall). Anchors: ``rim`` (0, 0, rim), ``rear`` (a, 0, rim), ``bottom`` (the
    bowl's lowest z).
    """
    a, b, n = outline
    t = p.uniform("wall", 0.018, 0.03)
    s = p.uniform("flare", 1.35, 1.7)  # rim outline / bowl-bottom outline
    z0 = rim - depth
    prims = _bands(a, b, n, t, z0, rim, 1.0 / s, 1.0, 3, "bowl")
    if foot:
        f = p.uniform("foot_flare", 1.05, 1.25)  # floor outline / top of the foot
        dx = p.uniform("foot_shift", 0.0, 0.03)  # the trapway sits towards the back
        prims += _bands(0.9 * a, 0.9 * b, n, None, 0.0, z0, f / s, 1.0 / s, 2, "foot", dx)
    x0 = 0.6 * a
    prims.append(cuboid_between((x0, -deck_width / 2, deck_floor), (back, deck_width / 2, rim), role="deck"))
    return Part("body", "toilet_bowl", prims, anchors={"rim": (0.0, 0.0, rim), "rear": (a, 0.0, rim),
                                                       "bottom": (0.0, 0.0, 0.0 if foot else z0)},
                regions={"grasp": Region(("bowl",)), "push": Region(("bowl",))})


def _tank(name, prim, x0, z0, height) -> Part:
    return Part("body", name, [prim], anchors={"front": (x0, 0.0, z0 + height), "top": (x0, 0.0, z0 + height)},
                regions={"grasp": Region(("tank",))})


def box_tank(p, x0: float, z0: float, depth: float, width: float, height: float) -> Part:
    """Rectangular cistern from x0 (front face) to x0 + depth, z0 to z0 + height."""
    prim = cuboid_between((x0, -width / 2, z0), (x0 + depth, width / 2, z0 + height), role="tank")
    return _tank("box_tank", prim, x0, z0, height)


def rounded_tank(p, x0: float, z0: float, depth: float, width: float, height: float) -> Part:
    """Cistern with rounded edges (radius 15-45 % of its depth, capped by its size)."""
    r = min(p.uniform("corner", 0.15, 0.45) * depth, 0.45 * min(depth, height))
    prim = rounded_box(depth, width, height, r, translation(x0 + depth / 2, 0, z0 + height / 2), role="tank")
    return _tank("rounded_tank", prim, x0, z0, height)


TANKS = {box_tank: 2.0, rounded_tank: 1.0}


def _edge_grasps(x_front: float, z: float, t: float, ys) -> list[Grasp]:
    """Pinches of a slab's front edge at ``x_front`` (height z, thickness t) at each y."""
    out = []
    for y in ys:
        T = _EDGE.copy()
        T[0, 3], T[1, 3], T[2, 3] = x_front + 0.01, y, z
        out.append(Grasp(T, t + 0.02, _UP))
    return out


def tank_lid(p, depth: float, width: float) -> Part:
    """Cistern lid resting on the tank: origin at the centre of its underside, overhang
    3-10 mm; a slab (or a rounded slab) 18-35 mm thick."""
    o = p.uniform("overhang", 0.003, 0.01)
    t = p.uniform("thickness", 0.018, 0.035)
    r = p.uniform("edge_radius", 0.0, 0.45) * t
    D, W = depth + 2 * o, width + 2 * o
    box = np.array([[-D / 2 - 1e-3, -W / 2, -1e-3], [D / 2 + 1e-3, W / 2, t + 1e-3]])
    return Part("lid", "tank_lid", [rounded_box(D, W, t, r, translation(0, 0, t / 2), role="slab")],
                anchors={"top": (0.0, 0.0, t), "size": (D, W, t)},
                regions={"lift": Region(("slab",), box), "grasp": Region(("slab",), box)},
                grasps=Deferred(_edge_grasps, -D / 2, t / 2, t, (-W / 4, W / 4)), actionable="slider_lid")


def _slab(outline, hinge_x: float, z0: float, t: float, tail: float, c: float, role: str, open_front=0.0) -> list:
    """A seat-shaped slab in the hinge frame: the outline (a, b, n, hole) centred at
    x = -hinge_x, z in [z0, z0 + t], and a tail ``tail`` wide up to ``c`` before the axis."""
    a, b, n, hole = outline
    T = translation(-hinge_x, 0, z0 + t / 2)
    if hole is None:
        loops = [superellipse(a, b, n)]
    elif open_front:  # a U: the outer edge round the back, then the inner edge back again
        g = open_front
        outer = superellipse(a, b, n, 20, -math.pi + g, math.pi - g, closed=False)
        inner = superellipse(hole[0], hole[1], n, 20, math.pi - 1.3 * g, -math.pi + 1.3 * g, closed=False)
        loops = [np.concatenate([outer, inner])]
    else:
        loops = [superellipse(a, b, n), superellipse(hole[0], hole[1], n)]
    prims = [extrusion(loops, t, 1.0, T, role=role)]
    x_tail = -hinge_x + a - 0.02
    if x_tail < -c:
        prims.append(cuboid_between((x_tail, -tail / 2, z0), (-c, tail / 2, z0 + t), role=role))
    return prims


def hinge_barrel(p, drop: float, radius: float, length: float) -> Part:
    """Hinge barrel on the body in the hinge frame: a pin of ``radius`` along y on the
    axis, ``length`` long, on a post reaching ``drop`` down to the deck. Seat and lid
    tails end ``radius`` + 1.5 mm from the axis, so they turn round it touching."""
    prims = [cylinder(radius, length, _ALONG_Y, role="barrel"),
             cuboid_between((-0.7 * radius, -length / 2, -drop), (0.7 * radius, length / 2, 0.0), role="post")]
    return Part("hinge", "hinge_barrel", prims)


def seat_ring(p, outline, hinge_x: float, thickness: float, open_front: bool = False, axis_gap: float = 0.006) -> Part:
    """Seat ring of outline (a, b, n) in the hinge frame, its top face at z = 0 (the axis
    height); ring 50-75 mm wide; open-front (U) seats leave a 60-100 mm gap at the front.
    ``hinge_x`` is the distance from the outline's centre back to the axis."""
    a, b, n = outline
    w = p.uniform("ring_width", 0.05, 0.075)
    g = p.uniform("front_gap", 0.35, 0.5) if open_front else 0.0
    tail = p.uniform("tail_width", 0.06, 0.12)
    prims = _slab((a, b, n, (a - w, b - w)), hinge_x, -thickness, thickness, tail, axis_gap, "ring", g)
    x_f = -hinge_x - a
    box = np.array([[x_f - 1e-3, -0.4 * b, -thickness - 1e-3], [x_f + 0.05, 0.4 * b, 1e-3]])
    return Part("seat", "open_front_seat" if open_front else "seat_ring", prims,
                anchors={"front": (x_f, 0.0, -thickness / 2)},
                regions={"lift": Region(("ring",), box), "grasp": Region(("ring",), box)},
                grasps=Deferred(_edge_grasps, x_f, -thickness / 2, thickness, (-0.3 * b, 0.3 * b)),
                actionable="hinge_lid")


def flat_seat_lid(p, outline, hinge_x: float, thickness: float, gap: float, axis_gap: float) -> Part:
    """Flat seat lid (cover) in the hinge frame, resting ``gap`` above z = 0; its tail
    ends ``axis_gap`` before the axis."""
    return _seat_lid("flat_seat_lid", outline, hinge_x, thickness, gap, 1.0, axis_gap)


def domed_seat_lid(p, outline, hinge_x: float, thickness: float, gap: float, axis_gap: float) -> Part:
    """Seat lid with a crown 85-95 % of its outline over a thin plate (a domed cover)."""
    return _seat_lid("domed_seat_lid", outline, hinge_x, thickness, gap, p.uniform("dome", 0.85, 0.95), axis_gap)


SEAT_LIDS = {flat_seat_lid: 2.0, domed_seat_lid: 1.0}


def _seat_lid(name, outline, hinge_x, t, gap, scale, c) -> Part:
    a, b, n = outline
    if scale == 1.0:
        prims = _slab((a, b, n, None), hinge_x, gap, t, 0.08, c, "cover")
    else:  # a thin full plate under a smaller crown
        prims = _slab((a, b, n, None), hinge_x, gap, 0.45 * t, 0.08, c, "cover")
        prims.append(extrusion([superellipse(a * scale, b * scale, n)], 0.55 * t, 1.0,
                               translation(-hinge_x, 0, gap + 0.725 * t), role="cover"))
    x_f = -hinge_x - a
    box = np.array([[x_f - 1e-3, -0.4 * b, gap - 1e-3], [x_f + 0.05, 0.4 * b, gap + t + 1e-3]])
    return Part("lid", name, prims, anchors={"front": (x_f, 0.0, gap + t / 2), "top": (0.0, 0.0, gap + t)},
                regions={"lift": Region(("cover",), box), "grasp": Region(("cover",), box)},
                grasps=Deferred(_edge_grasps, x_f, gap + t / 2, t, (-0.3 * b, 0.3 * b)), actionable="hinge_lid")


def flush_lever(p, reach: float | None = None) -> Part:
    """Trip lever: a round hub on the tank face and a flat arm along -y (mount frame:
    outward normal -x, hub axis +x through the origin). Anchor ``tip`` is the arm's end."""
    rh = p.uniform("hub_radius", 0.012, 0.02)
    hd = p.uniform("hub_depth", 0.008, 0.015)
    L = p.uniform("reach", 0.05, 0.09, fixed=reach)
    at, ah = p.uniform("arm_thickness", 0.005, 0.009), p.uniform("arm_height", 0.01, 0.016)
    prims = [cylinder(rh, hd, _ALONG_X.at(-hd / 2 - 0.0005, 0, 0), role="hub"),
             cuboid_between((-hd - 0.0005, -L, -ah / 2), (-hd - 0.0005 + at, 0.0, ah / 2), role="arm")]
    T = _EDGE.copy()  # a pinch on the arm's end, approaching the tank face
    T[0, 3], T[1, 3] = -hd - 0.0005 + at / 2, -0.8 * L
    return Part("lever", "flush_lever", prims, anchors={"tip": (-hd, -L, 0.0), "reach": (L, rh, hd + 0.0005)},
                regions={"grasp": Region(("arm",)), "push": Region(("arm",))},
                grasps=[Grasp(T, ah + 0.02, np.array([0.0, 0.0, -1.0]))], actionable="hinge_handle")


def swing_limit(rects, obstacles, upper: float, margin: float = 0.004, steps: int = 240) -> float:
    """Largest angle in [0, ``upper``] (radians) a part may turn about the hinge axis
    (+y through the origin; positive lifts its front, -x) before touching an obstacle.

    ``rects`` are the part's extents in the xz plane, ((u0, u1), (w0, w1)) each;
    ``obstacles`` boxes (x0, z0, z1): x >= x0, z0 <= z <= z1 (all across the part's
    width). Checks the rotated corners against the boxes and the boxes' corners against
    the rotated rectangles, on a grid of ``steps`` angles. Returns the last clear angle.
    """
    th = np.linspace(0.0, upper, steps)
    c, s = np.cos(th)[:, None], np.sin(th)[:, None]
    hit = np.zeros(steps, dtype=bool)
    for (u0, u1), (w0, w1) in rects:
        U = np.array([u0, u0, u1, u1])
        W = np.array([w0, w1, w0, w1])
        X, Z = c * U + s * W, -s * U + c * W  # (steps, 4)
        for x0, z0, z1 in obstacles:
            hit |= ((X > x0 - margin) & (Z > z0 - margin) & (Z < z1 + margin)).any(axis=1)
            for zc in (z0, z1):  # the obstacle's front corners in the part's frame
                uc, wc = c * x0 - s * zc, s * x0 + c * zc
                hit |= ((uc > u0 - margin) & (uc < u1 + margin) & (wc > w0 - margin) & (wc < w1 + margin))[:, 0]
    bad = np.flatnonzero(hit)
    return float(upper if not len(bad) else th[max(bad[0] - 2, 0)])
