"""Pen parts: barrels, pocket clips, the click plunger, the cap, and the refill point.

Frame (metres): every pen part is built along its local z axis, the writing end at
z = 0 and the back end at z = ``length``; a clip lies along +x. The category lays the
finished pen on its side.
- barrels: origin at the writing end on the axis; anchors ``back`` (z of the back
  end), ``socket`` (the back end's bore radius and depth, for a plunger), ``nose``
  (the writing end's bore radius and depth, for the refill point);
- ``flat_clip`` / ``wire_clip``: a bar parallel to the axis at ``radius`` + a gap on
  the +x side, held by a block at its back end ``z1``, with a ball at its free end
  ``z0``; anchors ``bar`` (outer radial distance, half width) and ``ball`` (centre's
  radial distance, radius), from which :func:`roll_angle` finds how the pen lies;
- ``pen_cap``: a tube closed at its front end, over the barrel's front;
- ``plunger`` and ``refill_point``: cylinders on the axis.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import BOX, cuboid_between, cylinder, frustum, ring, sphere
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region

CLEAR = 0.0008  # radial clearance of round parts sliding in round parts
POINT, POINT_CLEAR = 0.0004, 0.0012  # refill point radius; its bore's clearance (pybullet's 1 mm mesh margin)


def _z(z0: float, z1: float):
    """Pose of a primitive centred on the axis between z0 and z1."""
    return translation(0, 0, (z0 + z1) / 2)


def _barrel(template, p, radius, length, front, front_r, socket):
    """Nose ring, a front section from ``front_r`` to ``radius`` over ``front``, the
    main tube up to the back end, optionally hollowed there by ``socket`` (radius, depth)."""
    hn = p.uniform("nose_length", 0.002, 0.004)
    rn_out = p.uniform("nose_radius", 0.0022, 0.0028)
    bore = POINT + POINT_CLEAR
    prims = [ring(rn_out, bore, hn, pose=_z(0.0, hn), role="nose"),
             frustum(rn_out, front_r, front - hn, _z(hn, front), role="grip")]
    back = length
    if socket is not None:
        rs, ds = socket
        back = length - ds
        prims.append(ring(radius, rs, ds, pose=_z(back, length), role="barrel"))
    prims.append(cylinder(radius, back - front, _z(front, back), role="barrel"))
    return Part("body", template, prims, anchors={"back": (0.0, 0.0, length), "nose": (bore, hn, 0.0),
                                                  "socket": (*(socket or (0.0, 0.0)), 0.0)},
                regions={"grasp": Region(("barrel", "grip")), "lift": Region(("barrel",))})


def straight_barrel(p, radius: float, length: float, socket=None) -> Part:
    """Cylindrical barrel with a short conical front."""
    front = p.uniform("cone_length", 0.012, 0.02)
    return _barrel("straight_barrel", p, radius, length, front, radius, socket)


def waisted_barrel(p, radius: float, length: float, socket=None) -> Part:
    """Barrel with a slimmer grip section behind the cone (a rubber grip's waist)."""
    front = p.uniform("cone_length", 0.01, 0.016)
    rg = p.uniform("waist", 0.85, 0.94) * radius
    lg = p.uniform("grip_length", 0.02, 0.035)
    part = _barrel("waisted_barrel", p, radius, length, front, rg, socket)
    part.primitives.insert(2, cylinder(rg, lg, _z(front, front + lg), role="grip"))
    part.primitives.insert(3, frustum(rg, radius, 0.004, _z(front + lg, front + lg + 0.004), role="grip"))
    return part


def needle_barrel(p, radius: float, length: float, socket=None) -> Part:
    """Barrel with a long slender conical nose (gel and fineliner pens)."""
    front = p.uniform("cone_length", 0.022, 0.032)
    return _barrel("needle_barrel", p, radius, length, front, radius, socket)


BARRELS = {straight_barrel: 2.0, waisted_barrel: 1.5, needle_barrel: 1.0}


def _clip(template, bar, radius, gap, t, w, z0, z1, rb):
    a0, a1 = radius + gap, radius + gap + t
    prims = [bar,
             cuboid_between((radius - 0.0005, -w / 2, z1 - 0.006), (a1, w / 2, z1), role="root"),
             sphere(rb, pose=translation(a1 - rb + 0.0006, 0, z0), role="ball")]
    return Part("clip", template, prims, anchors={"bar": (a1, w / 2, 0.0), "ball": (a1 - rb + 0.0006, rb, 0.0)},
                regions={"grasp": Region(("bar", "root"))})


def flat_clip(p, radius: float, z0: float, z1: float) -> Part:
    """Flat spring-steel clip: a strip along the barrel."""
    gap, t, w = p.uniform("gap", 0.0006, 0.0012), p.uniform("thickness", 0.0006, 0.001), p.uniform("width", 0.003,
                                                                                                     0.005)
    rb = p.uniform("ball", 0.0012, 0.0018)
    bar = cuboid_between((radius + gap, -w / 2, z0), (radius + gap + t, w / 2, z1), role="bar")
    return _clip("flat_clip", bar, radius, gap, t, w, z0, z1, rb)


def wire_clip(p, radius: float, z0: float, z1: float) -> Part:
    """Round-wire clip: a rod along the barrel."""
    gap, rw = p.uniform("gap", 0.0006, 0.0012), p.uniform("wire", 0.0006, 0.001)
    rb = p.uniform("ball", 0.0014, 0.002)
    bar = cylinder(rw, z1 - z0, translation(radius + gap + rw, 0, (z0 + z1) / 2), role="bar")
    return _clip("wire_clip", bar, radius, gap, 2 * rw, 2 * rw, z0, z1, rb)


CLIPS = {flat_clip: 2.0, wire_clip: 1.0}


def roll_angle(clip: Part, radius: float) -> float:
    """Angle (radians) between the clip's direction and straight down when the pen
    lies with its round parts of ``radius`` and its clip both on the floor."""
    a1, h, _ = clip.anchors["bar"]
    d, rb, _ = clip.anchors["ball"]
    bar = math.atan2(h, a1) + math.acos(min(1.0, radius / math.hypot(a1, h)))
    ball = math.acos(min(1.0, (radius - rb) / d))
    return max(bar, ball)


def rolled(clip: Part, angle: float) -> Part:
    """``clip`` turned by ``angle`` (radians) about the pen's axis (z). Its round
    primitives (the ball, a wire rod along z) are only moved, not turned: the object's
    bounds of a turned sphere or cylinder are its turned bounding box, lower than the
    solid, and a pen is placed on the floor by its bounds."""
    c, s = math.cos(angle), math.sin(angle)
    R = np.array([[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    prims = []
    for q in clip.primitives:
        if q.geom is BOX:
            prims.append(q.placed(R))
        else:
            T = q.pose.copy()
            T[:3, 3] = R[:3, :3] @ q.pose[:3, 3]
            prims.append(q._replace(pose=T))
    clip.primitives = prims
    return clip


def plunger(p, radius: float, inside: float, out: float) -> Part:
    """Click button: a rod from ``inside`` below the back end to ``out`` above it (origin
    at the back end), with a rounded top."""
    rt = min(0.6 * radius, 0.0015)
    prims = [cylinder(radius, inside + out - rt / 2, _z(-inside, out - rt / 2), role="rod"),
             sphere(radius, 0.0, rt / 2, translation(0, 0, out - rt / 2), role="top")]
    return Part("button", "plunger", prims, regions={"press": Region(("top",))}, actionable="slider_button")


def pen_cap(p, radius: float, length: float) -> Part:
    """Cap over the barrel's front, closed by a rounded end (origin at its open end on
    the axis, the cap extends to -z); ``radius`` is the barrel's."""
    ri = radius + CLEAR
    ro = ri + p.uniform("wall", 0.0006, 0.001)
    te = p.uniform("end", 0.0015, 0.003)
    prims = [ring(ro, ri, length, pose=_z(-length, 0.0), role="shell"),
             frustum(ro * p.uniform("end_taper", 0.7, 1.0), ro, te, _z(-length - te, -length), role="end")]
    return Part("cap", "pen_cap", prims, anchors={"outer": (ro, 0.0, -length - te)},
                regions={"grasp": Region(("shell",)), "pull": Region(("shell", "end"))}, actionable="slider_lid")


def end_plug(p, radius: float, outer: float) -> Part:
    """Plug closing the back end, as wide as the cap (the pen lies on both)."""
    h = p.uniform("plug_length", 0.004, 0.008)
    return Part("body", "end_plug", [cylinder(outer, h, _z(0.0, h), role="plug")], anchors={"top": (0.0, 0.0, h)})


def refill_point(p, bore: float, depth: float) -> Part:
    """Refill tip in the nose's bore: origin at the front end of the bore (z = 0)."""
    r = bore - POINT_CLEAR
    L = 0.5 * depth
    return Part("refill", "refill_point", [cylinder(r, L, _z(0.0005, 0.0005 + L), role="point")])


def twist_section(p, radius: float, length: float) -> Part:
    """Back half of a twist pen's barrel (origin at its front end on the axis), with a
    rounded end."""
    te = p.uniform("end", 0.002, 0.004)
    prims = [cylinder(radius, length - te, _z(0.0, length - te), role="barrel"),
             frustum(radius, p.uniform("end_taper", 0.6, 0.9) * radius, te, _z(length - te, length), role="end")]
    return Part("knob", "twist_section", prims, regions={"rotate": Region(("barrel",)), "grasp": Region(("barrel",))},
                actionable="hinge_knob")
