"""Pivoting hand parts: bucket bails (with their ear lugs) and faucet levers/handles.

Bails (``round_bail``, ``square_bail``, ``grip_bail``): origin at the midpoint between
the two pivots, pivot axis +y, the bail stands upright (+z) in the y-z plane with its
leg ends on the pivots at y = +-``span``; anchors ``apex`` / ``apex_inner`` (centre
line / underside of the top), ``pin_+y`` (where the pivot pins meet the lugs). ``clear`` = (radius, height) describes the
obstacle (rim, lid, knob) the bail must pass over when it swings: a cylinder of that
radius rising ``height`` above the pivot plane; the leg height is chosen so the swept
bail clears it by ``CLEARANCE``. ``ear_lugs`` are the matching bosses on the body.

Faucet levers: origin at the mount point on the top of a valve stem or column (the
surface faces +z), the hub rises +z and a lever arm points to -x (the front) at rest.
``lever_handle``, ``cross_handle`` and ``knob_handle`` turn about +z (``max_reach``
caps the radius they sweep, anchor ``reach`` = (r, 0, 0) is the radius drawn); ``joystick_lever`` is a cap of the
column's radius that lifts about the +y axis through its back bottom edge (anchor
``pivot``). ``side_lever`` follows the panel-control convention of
:mod:`artipg.templates.controls` (mounted on a surface facing -x, hub along -x, arm
rising +z, turns about +x).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, frustum, prism, sphere, tube
from artipg.geometry.transforms import Placer, rot_y, rot_z, rotation, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region

CLEARANCE = 0.006
_ALONG_Y = Placer(rotation((1.0, 0.0, 0.0), -math.pi / 2))  # local z -> +y
_ALONG_X = rot_y(math.pi / 2)                              # local z -> +x
_ALONG_MINUS_X = Placer(rot_y(-math.pi / 2))              # local z -> -x
_QUARTER_TURN = rot_z(math.pi / 2)
# gripper approaching -z (from above), jaws closing along x / along y
_TOP_JAW_X = np.array([[0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_TOP_JAW_Y = np.array([[-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def top_grasp(x: float, y: float, z: float, width: float, jaw: str = "x", open_dir=(0.0, 0.0, 1.0)) -> Grasp:
    """Grasp approaching from above (-z) at (x, y, z), jaws closing along ``jaw``."""
    T = (_TOP_JAW_X if jaw == "x" else _TOP_JAW_Y).copy()
    T[0, 3], T[1, 3], T[2, 3] = x, y, z
    return Grasp(T, width, np.asarray(open_dir, dtype=float))


def _bail_grasps(span: float, h: float, rc: float, rg: float) -> list[Grasp]:
    """Grasps from above on a bail's top, at a quarter span either side of the middle."""
    return [top_grasp(0.0, y, h + math.sqrt(rc * rc - max(0.0, abs(y) - span + rc) ** 2), 2 * rg + 0.02)
            for y in (-0.25 * span, 0.0, 0.25 * span)]


def _leg_height(span: float, rc: float, r: float, clear) -> float:
    """Leg height so a bail (half span, corner radius rc, tube radius r) clears ``clear``."""
    R, dz = clear
    y = np.linspace(0.0, min(R, span), 24)
    u = np.minimum(y + r, span) - (span - rc)  # shifted outward by the tube radius
    top = np.sqrt(np.maximum(rc * rc - np.maximum(u, 0.0) ** 2, 0.0))
    need = np.sqrt(np.maximum(R * R - y * y, 0.0) + dz * dz) + r + CLEARANCE - top
    return max(0.003, float(need.max()))


def _bail(p, template, span, clear, rc_frac, sleeve):
    r = p.uniform("wire_radius", 0.002, 0.005)
    rc = span * p.uniform("corner", *rc_frac)
    rg = p.uniform("sleeve_radius", 0.008, 0.014) if sleeve else r
    h = max(_leg_height(span, rc, rg, clear), p.uniform("leg_height", 0.0, 0.08))
    segs = [line(h), arc(rc, -math.pi / 2)]
    if span - rc > 1e-4:
        segs.append(line(2 * (span - rc)))
    segs += [arc(rc, -math.pi / 2), line(h)]
    prims = tube(r, segs, heading=math.pi / 2, pose=_QUARTER_TURN @ translation(-span, 0, 0), role="wire")
    # pivot pins through the leg ends, coaxial with the pivot axis: they meet the ear lugs
    # face to face (anchor pin_+y), which keeps the contact exact at any bail angle
    rp = p.uniform("pin_radius", 1.2, 1.8) * r
    lp = p.uniform("pin_length", 0.002, 0.004)
    for s in (-1.0, 1.0):
        prims.append(cylinder(rp, lp + 2 * r, _ALONG_Y.at(0, s * (span - lp / 2), 0), role="pin"))
    top = h + rc
    grip = ("wire",)
    if sleeve:
        L = min(2 * (span - rc), p.uniform("sleeve_length", 0.08, 0.13))
        prims.append(cylinder(rg, L, _ALONG_Y.at(0, 0, top), role="grip"))
        grip = ("grip",)
    return Part("handle", template, prims,
                anchors={"pivot_+y": (0.0, span, 0.0), "pivot_-y": (0.0, -span, 0.0), "apex": (0.0, 0.0, top),
                         "apex_inner": (0.0, 0.0, top - rg), "pin_+y": (0.0, span - r - lp, 0.0)},
                regions={"grasp": Region(grip), "lift": Region(grip)},
                grasps=Deferred(_bail_grasps, span, h, rc, rg),
                actionable="hinge_handle")


def round_bail(p, span: float, clear=(0.0, 0.0)) -> Part:
    """Wire bail: straight legs and a semicircular top."""
    return _bail(p, "round_bail", span, clear, (1.0, 1.0), False)


def square_bail(p, span: float, clear=(0.0, 0.0)) -> Part:
    """Rounded-rectangle bail: legs, tight corners and a straight top bar."""
    return _bail(p, "square_bail", span, clear, (0.15, 0.4), False)


def grip_bail(p, span: float, clear=(0.0, 0.0)) -> Part:
    """Bail with a straight top carrying a cylindrical grip sleeve."""
    return _bail(p, "grip_bail", span, clear, (0.3, 0.5), True)


BAILS = {round_bail: 2.0, grip_bail: 2.0, square_bail: 1.0}


def ear_lugs(p, wall_y: float, end_y: float, radius: float | None = None) -> Part:
    """Two cylindrical bosses along y from the body wall (at +-``wall_y``) to the bail's
    pivot pins (at +-``end_y``, the bail's ``pin_+y`` anchor); origin at the pivot midpoint."""
    rl = p.uniform("lug_radius", 0.006, 0.012, fixed=radius)
    y0, y1 = wall_y - 0.0015, end_y
    prims = [cylinder(rl, y1 - y0, _ALONG_Y.at(0, s * (y0 + y1) / 2, 0), role="lug") for s in (-1, 1)]
    return Part("body", "ear_lugs", prims, anchors={"pin_+y": (0.0, end_y, 0.0), "pin_-y": (0.0, -end_y, 0.0)})


def _turn_part(template, prims, reach, grasps, actionable) -> Part:
    return Part("lever", template, prims, anchors={"reach": (reach, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))}, grasps=grasps,
                actionable=actionable)


def _upto(lo: float, hi: float, cap: float | None) -> tuple[float, float]:
    """The range (lo, hi) capped at ``cap`` (a parent's limit)."""
    if cap is None:
        return lo, hi
    hi = min(hi, cap)
    return min(lo, hi), hi


def lever_handle(p, max_reach: float | None = None) -> Part:
    """Valve lever: a round hub with a flat blade pointing to -x."""
    L = p.uniform("length", *_upto(0.04, 0.08, max_reach))
    rh = p.uniform("hub_radius", 0.01, 0.016)
    hh = p.uniform("hub_height", 0.015, 0.03)
    th, w = p.uniform("blade_thickness", 0.005, 0.01), p.uniform("blade_width", 0.01, 0.018)
    prims = [cylinder(rh, hh, translation(0, 0, hh / 2), role="hub"),
             cuboid(L - w / 2, w, th, translation(-(L - w / 2) / 2, 0, hh - th / 2), role="grip"),
             cylinder(w / 2, th, translation(-L + w / 2, 0, hh - th / 2), role="grip")]
    return _turn_part("lever_handle", prims, L,
                      Deferred.one(top_grasp, -L + w, 0.0, hh - th / 2, w + 0.02, "y", (0, 0, 0)), "hinge_handle")


def cross_handle(p, max_reach: float | None = None) -> Part:
    """Cross handle: a hub with 3-4 horizontal spokes ending in balls."""
    L = p.uniform("reach", *_upto(0.025, 0.045, max_reach))
    n = p.integers("spokes", 3, 4)
    rh, hh = p.uniform("hub_radius", 0.008, 0.014), p.uniform("hub_height", 0.02, 0.035)
    rs = p.uniform("spoke_radius", 0.003, 0.005)
    rb = p.uniform("ball_radius", 1.0, 1.6) * rs
    phase = p.uniform("phase", 0.0, 2 * math.pi / n)
    zs = hh - rb
    prims = [cylinder(rh, hh, translation(0, 0, hh / 2), role="hub")]
    for i in range(n):
        R = rot_z(phase + 2 * math.pi * i / n)
        prims.append(cylinder(rs, L - rb, R @ translation(-(L - rb) / 2, 0, zs) @ _ALONG_X, role="grip"))
        prims.append(sphere(rb, pose=R @ translation(-(L - rb), 0, zs), role="grip"))
    return _turn_part("cross_handle", prims, L, Deferred(_spoke_grasp, phase, L, rb, zs), "hinge_knob")


def _spoke_grasp(phase: float, L: float, rb: float, zs: float) -> list[Grasp]:
    """The grasp across the first spoke of a :func:`cross_handle`, near its ball."""
    g = top_grasp(0.0, 0.0, 0.0, 2 * rb + 0.02, "y", (0, 0, 0))
    g.pose[:] = rot_z(phase) @ translation(-(L - 2 * rb), 0, zs) @ g.pose
    return [g]


def knob_handle(p, max_reach: float | None = None) -> Part:
    """Fluted round handle: a many-sided prism under a domed cap."""
    R = p.uniform("radius", *_upto(0.015, 0.025, max_reach))
    n = p.integers("flutes", 6, 12)
    h = p.uniform("height", 0.02, 0.04)
    cap = p.uniform("cap_height", 0.2, 0.5) * R
    Rs = (R * R + cap * cap) / (2 * cap)  # sphere radius of the cap dome
    prims = [prism(R, h, n, translation(0, 0, h / 2), role="grip"),
             sphere(Rs, Rs - cap, Rs, translation(0, 0, h - Rs + cap), role="grip")]
    ap = R * math.cos(math.pi / n)
    return _turn_part("knob_handle", prims, R, Deferred.one(top_grasp, 0, 0, h / 2, 2 * ap + 0.02, "x", (0, 0, 0)),
                      "hinge_knob")


VALVE_HANDLES = {lever_handle: 2.0, cross_handle: 1.5, knob_handle: 1.0}


def joystick_lever(p, radius: float) -> Part:
    """Single-lever mixer handle: a cap of the column's ``radius`` with an arm rising
    forward (-x); it lifts about +y through the anchor ``pivot`` (back bottom edge)."""
    hc = p.uniform("cap_height", 0.015, 0.035)
    L = p.uniform("arm_length", 0.06, 0.12)
    rise = p.uniform("arm_rise", 0.0, 0.35)
    th = p.uniform("arm_thickness", 0.3, 0.6) * hc
    w = min(p.uniform("arm_width", 0.012, 0.025), 1.6 * radius)
    x0, z0 = -0.3 * radius, hc - th / 2
    arm = cuboid(L, w, th, translation(x0, 0, z0) @ rot_y(rise) @ translation(-L / 2, 0, 0), role="grip")
    prims = [cylinder(radius, hc, translation(0, 0, hc / 2), role="cap"), arm]
    tip = (x0 - (L - 0.015) * math.cos(rise), 0.0, z0 + (L - 0.015) * math.sin(rise))
    g = Deferred.one(top_grasp, *tip, w + 0.02, "y", (0.0, 0.0, 1.0))
    return Part("lever", "joystick_lever", prims, anchors={"pivot": (radius, 0.0, 0.0), "tip": tip},
                regions={"grasp": Region(("grip",)), "lift": Region(("grip",)), "push": Region(("grip",))},
                grasps=g, actionable="hinge_handle")


def side_lever(p, radius: float | None = None) -> Part:
    """Side lever (panel-control frame): a short hub along -x and an arm rising +z."""
    rh = p.uniform("hub_radius", 0.008, 0.014, fixed=radius)
    hl = p.uniform("hub_length", 0.01, 0.02)
    L = p.uniform("arm_length", 0.035, 0.07)
    ra = min(p.uniform("arm_radius", 0.35, 0.6) * rh, 0.45 * hl)
    prims = [frustum(rh, 0.9 * rh, hl, _ALONG_MINUS_X.at(-hl / 2, 0, 0), role="hub"),
             cylinder(ra, L, translation(-hl + ra, 0, L / 2), role="grip"),
             sphere(1.3 * ra, pose=translation(-hl + ra, 0, L), role="grip")]
    return Part("lever", "side_lever", prims, anchors={"reach": (0.0, 0.0, L + 1.3 * ra)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred(_side_lever_grasp, hl, ra, L), actionable="hinge_handle")


def _side_lever_grasp(hl: float, ra: float, L: float) -> list[Grasp]:
    """The grasp across a :func:`side_lever`'s arm, approaching the panel (+x)."""
    return [Grasp(np.array([[0.0, 0.0, 1.0, -hl + ra], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.8 * L],
                            [0.0, 0.0, 0.0, 1.0]]), 2.6 * ra + 0.02)]
