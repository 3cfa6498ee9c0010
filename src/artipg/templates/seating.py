"""Seating parts: seats, backrests, swivel-chair star bases, caster forks and wheels.

Frames (metres, +z up, the sitter faces -x):
- seats: origin at the centre of the seat's underside, top surface at z = thickness
  (anchor ``top``); depth along x, width along y;
- backrests: origin on the recline pivot line (along y); the whole back lies in
  x >= 0 and is built leaning back by ``lean`` radians, so a revolute joint about +y
  at the origin reclines it away from a seat lying in x <= 0. The back board spans
  ``z0`` .. ``z0 + height`` above the pivot (before leaning); it is carried either by
  two side posts rising from the pivot or, with ``spine`` > 0, by a central L-shaped
  spine reaching ``spine`` metres back from the pivot (office chairs);
- ``star_base``: origin on the axis at the underside of the arms; anchor ``hub_top``;
  the arm ends (caster mounts) lie at radius ``reach`` on the x axis rotated by
  2*pi*i/n;
- casters: origin on the swivel axis at the top of the stem (touching the arm), the
  wheel axle is at (trail, 0, -drop) along local y (anchors ``axle`` and
  ``wheel_y`` = lateral offsets of the wheels); wheels: origin at the wheel centre,
  axis along y.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import Primitive, cuboid, cuboid_between, cylinder, frustum, rect_ring
from artipg.geometry.transforms import Placer, rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region

_Y_AXIS = Placer(rot_x(math.pi / 2))  # local z -> -y: cylinders lying along y
_X_AXIS = rot_y(math.pi / 2)
_X_AXIS_PLACER = Placer(_X_AXIS)  # translation(x, y, z) @ _X_AXIS as _X_AXIS_PLACER.at(x, y, z)


def _turn_table(n: int) -> np.ndarray:
    T = np.stack([rot_z(2 * math.pi * i / n) for i in range(n)])
    T.flags.writeable = False
    return T


# a star of n arms is placed by one stacked product (whose slices are the products made
# one by one), with the rotations made once for the usual arm counts
_TURNS = {n: _turn_table(n) for n in (3, 4, 5, 6)}


def turns(n: int) -> np.ndarray:
    """Rotations (n, 4, 4) about +z by 2*pi*i/n radians, i = 0 .. n-1 (read-only)."""
    T = _TURNS.get(n)
    return T if T is not None else _turn_table(n)


def _seat(template, prims, t):
    return Part("seat", template, prims, anchors={"top": (0.0, 0.0, t)},
                regions={"push": Region(("cushion",))})


def slab_seat(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Flat upholstered slab."""
    t = p.uniform("thickness", 0.03, 0.08, fixed=thickness)
    return _seat("slab_seat", [cuboid(depth, width, t, translation(0, 0, t / 2), role="cushion")], t)


def cushion_seat(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """A thin seat board with a slightly inset cushion on top."""
    t = p.uniform("thickness", 0.05, 0.1, fixed=thickness)
    b = p.uniform("board", 0.012, 0.02)
    i = p.uniform("inset", 0.003, 0.015)
    return _seat("cushion_seat", [cuboid(depth, width, b, translation(0, 0, b / 2), role="board"),
                                  cuboid(depth - 2 * i, width - 2 * i, t - b, translation(0, 0, b + (t - b) / 2),
                                         role="cushion")], t)


def waterfall_seat(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Slab whose front edge rolls down (a half-round front), as on office seats."""
    t = p.uniform("thickness", 0.04, 0.09, fixed=thickness)
    r = t / 2
    return _seat("waterfall_seat", [cuboid(depth - r, width, t, translation(r / 2, 0, t / 2), role="cushion"),
                                    cylinder(r, width, _Y_AXIS.at(-depth / 2 + r, 0, r), role="cushion")],
                 t)


def round_seat(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Round stool seat of diameter min(depth, width)."""
    t = p.uniform("thickness", 0.04, 0.09, fixed=thickness)
    r = min(depth, width) / 2
    return _seat("round_seat", [cylinder(r, t, translation(0, 0, t / 2), role="cushion")], t)


SEATS = {slab_seat: 1.0, cushion_seat: 1.5, waterfall_seat: 1.0}
STOOL_SEATS = {round_seat: 2.0, cushion_seat: 1.0, slab_seat: 1.0}


def _carrier(p, width, z0, spine, t):
    """Posts (spine == 0) or a central L spine; returns (primitives, x of the board front)."""
    if spine <= 0.0:
        s = p.uniform("post", 0.02, 0.035)
        return [cuboid_between((0.0, sy * width / 2 - (s if sy > 0 else 0), 0.0),
                               (s, sy * width / 2 + (s if sy < 0 else 0), z0 + 0.05), role="post")
                for sy in (-1, 1)], 0.0
    w = p.uniform("spine_width", 0.04, 0.07)
    h = p.uniform("spine_thickness", 0.015, 0.025)
    return [cuboid_between((0.0, -w / 2, 0.0), (spine, w / 2, h), role="post"),
            cuboid_between((spine - h, -w / 2, h), (spine, w / 2, z0 + 0.05), role="post")], spine


def _back(template, prims, lean, top):
    # leaned back in one stacked product (its slices are the products pr.placed would make)
    poses = rot_y(lean) @ np.concatenate([pr.pose for pr in prims]).reshape(-1, 4, 4)
    new = tuple.__new__  # Primitive(...) without the NamedTuple's Python-level __new__
    prims = [new(Primitive, (pr.geom, pr.params, T, pr.role)) for pr, T in zip(prims, poses)]
    return Part("backrest", template, prims, anchors={"top": (top * math.sin(lean), 0.0, top * math.cos(lean))},
                regions={"push": Region(("board",))})


def panel_back(p, width: float, height: float, z0: float, lean: float = 0.0, spine: float = 0.0) -> Part:
    """One solid board on posts or a spine."""
    t = p.uniform("thickness", 0.015, 0.05)
    prims, x = _carrier(p, width, z0, spine, t)
    prims.append(cuboid_between((x, -width / 2, z0), (x + t, width / 2, z0 + height), role="board"))
    return _back("panel_back", prims, lean, z0 + height)


def frame_back(p, width: float, height: float, z0: float, lean: float = 0.0, spine: float = 0.0) -> Part:
    """A rectangular frame with a thin mesh (or cane) panel across it."""
    t = p.uniform("thickness", 0.015, 0.03)
    rail = p.uniform("rail", 0.02, 0.05)
    prims, x = _carrier(p, width, z0, spine, t)
    c = _X_AXIS_PLACER.at(x + t / 2, 0.0, z0 + height / 2)
    prims += [rect_ring(height, width, t, height - 2 * rail, width - 2 * rail, c, role="board"),
              cuboid(0.004, width - 2 * rail, height - 2 * rail, translation(x + t / 2, 0.0, z0 + height / 2),
                     role="board")]
    return _back("frame_back", prims, lean, z0 + height)


def slat_back(p, width: float, height: float, z0: float, lean: float = 0.0, spine: float = 0.0) -> Part:
    """Top and bottom rails joined by 3-6 vertical slats."""
    t = p.uniform("thickness", 0.015, 0.03)
    rail = p.uniform("rail", 0.03, 0.07)
    n = p.integers("slats", 3, 6)
    sw = p.uniform("slat_width", 0.2, 0.5) * (width - 2 * rail) / n
    prims, x = _carrier(p, width, z0, spine, t)
    prims += [cuboid_between((x, -width / 2, z), (x + t, width / 2, z + rail), role="board")
              for z in (z0, z0 + height - rail)]
    for i in range(n):
        yc = -width / 2 + (i + 0.5) * width / n
        prims.append(cuboid_between((x + 0.2 * t, yc - sw / 2, z0 + rail),
                                    (x + 0.8 * t, yc + sw / 2, z0 + height - rail), role="board"))
    return _back("slat_back", prims, lean, z0 + height)


def ladder_back(p, width: float, height: float, z0: float, lean: float = 0.0, spine: float = 0.0) -> Part:
    """Two stiles joined by 3-5 horizontal rails."""
    t = p.uniform("thickness", 0.02, 0.035)
    s = p.uniform("stile", 0.025, 0.04)
    n = p.integers("rails", 3, 5)
    rh = p.uniform("rail_height", 0.03, 0.06)
    prims, x = _carrier(p, width, z0, spine, t)
    prims += [cuboid_between((x, min(sy * width / 2, sy * (width / 2 - s)), z0),
                             (x + t, max(sy * width / 2, sy * (width / 2 - s)), z0 + height), role="board")
              for sy in (-1, 1)]
    for i in range(n):
        z = z0 + height - rh - i * (height - rh) / n
        prims.append(cuboid_between((x, -width / 2 + s, z), (x + t, width / 2 - s, z + rh), role="board"))
    return _back("ladder_back", prims, lean, z0 + height)


BACKS = {panel_back: 2.0, frame_back: 1.5, slat_back: 1.0, ladder_back: 1.0}


def star_base(p, reach: float, n: int, arm_height: float) -> Part:
    """Hub with ``n`` radial arms (box section or tapered round), arms' underside at z = 0."""
    hub_r = p.uniform("hub_radius", 0.035, 0.055)
    hub_h = arm_height + p.uniform("hub_extra", 0.01, 0.03)
    w = p.uniform("arm_width", 0.035, 0.055)
    round_arms = p.flag("round_arms", 0.4)
    prims = [cylinder(hub_r, hub_h, translation(0, 0, hub_h / 2), role="hub")]
    L = reach + 0.02 - hub_r * 0.5
    R = turns(n)
    arm = R @ translation(hub_r * 0.5 + L / 2, 0, arm_height / 2)
    if round_arms:
        prims += [frustum(arm_height / 2, 0.6 * arm_height / 2, L, T, role="arm") for T in arm @ _X_AXIS]
        # sockets under the tapered ends for the caster stems
        prims += [cylinder(0.012, arm_height / 2, T, role="arm") for T in R @ translation(reach, 0, arm_height / 4)]
    else:
        prims += [cuboid(L, w, arm_height, T, role="arm") for T in arm]
    return Part("base", "star_base", prims, anchors={"hub_top": (0.0, 0.0, hub_h)})


def single_caster(p, wheel_r: float, wheel_w: float) -> Part:
    """Fork (stem, hood, two side plates) around one wheel."""
    trail = p.uniform("trail", 0.015, 0.03)
    stem = p.uniform("stem", 0.01, 0.025)
    hood = p.uniform("hood", 0.006, 0.012)
    plate = 0.004
    zt = -stem  # hood top
    za = zt - hood - 0.002 - wheel_r  # axle height
    yo = wheel_w / 2 + 0.0015
    prims = [cylinder(0.006, stem, translation(0, 0, -stem / 2), role="stem"),
             cuboid_between((-0.008, -yo - plate, zt - hood), (trail + wheel_r * 0.6, yo + plate, zt), role="fork")]
    prims += [cuboid_between((trail - wheel_r * 0.3, s * yo - (plate if s < 0 else 0), za - 0.004),
                             (trail + wheel_r * 0.6, s * yo + (plate if s > 0 else 0), zt - hood), role="fork")
              for s in (-1, 1)]
    return Part("base", "single_caster", prims, anchors={"axle": (trail, 0.0, za), "wheel_y": (0.0, 0.0, 0.0)})


def twin_caster(p, wheel_r: float, wheel_w: float) -> Part:
    """Central housing between two wheels (the common twin-wheel office caster)."""
    trail = p.uniform("trail", 0.015, 0.03)
    stem = p.uniform("stem", 0.01, 0.025)
    hw = p.uniform("housing_width", 0.012, 0.02)
    zt = -stem
    za = zt - 0.004 - wheel_r
    prims = [cylinder(0.006, stem, translation(0, 0, -stem / 2), role="stem"),
             cuboid_between((-0.01, -hw / 2, za - 0.3 * wheel_r), (trail + 0.8 * wheel_r, hw / 2, zt), role="fork")]
    yo = hw / 2 + 0.0015 + wheel_w / 2
    return Part("base", "twin_caster", prims, anchors={"axle": (trail, 0.0, za), "wheel_y": (-yo, yo, 0.0)})


CASTERS = {twin_caster: 2.0, single_caster: 1.0}


def paddle_lever(p, length: float | None = None) -> Part:
    """Seat-height lever: a flat bar reaching along -y from its pivot, with a paddle tip.

    Origin on the pivot axis (along x) at the mounting face (y = 0); the bar hangs
    below the pivot line (z <= 0), so a revolute joint about -x lifts the tip without
    entering the face it is mounted on (which lies in y >= 0).
    """
    L = p.uniform("length", 0.1, 0.16, fixed=length)
    t = p.uniform("thickness", 0.006, 0.01)
    tip = p.uniform("tip", 0.03, 0.05)
    prims = [cuboid_between((-0.008, -L, -t), (0.008, 0.0, 0.0), role="bar"),
             cuboid_between((-0.02, -L - tip, -1.6 * t), (0.012, -L, 0.0), role="grip")]
    return Part("lever", "paddle_lever", prims, regions={"grasp": Region(("grip",)), "lift": Region(("grip",))},
                actionable="hinge_handle")


def wheel(p, radius: float, width: float) -> Part:
    """Wheel (tyre) of ``radius`` and ``width`` about local y."""
    return Part("wheel", "wheel", [cylinder(radius, width, _Y_AXIS.matrix, role="tyre")],
                regions={"rotate": Region(("tyre",))})
