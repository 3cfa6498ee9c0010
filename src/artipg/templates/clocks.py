"""Clock parts: dials, hands, cases, bezel doors, pendulums and alarm-clock bells.

Face frame (every template here unless said otherwise; metres): origin at the centre
of the dial on its front surface, the dial in the plane x = 0 facing **-x** (the
object's front), +z up (12 o'clock), the hands' axis along x. Hands turn about +x:
a positive angle is clockwise seen from the front.

- ``clock_dial``: a disc behind x = 0 (x in [0, thickness]) with hour markers
  protruding ``mark`` (< the first hand gap) in front of it;
- hands (``baton_hand``, ``leaf_hand``, ``arrow_hand``, ``second_hand``): origin on the
  axis on the hand's back face, the hand in x in [-thickness, 0], pointing +z at
  rest, a hub disc on the axis; anchor ``front`` is its front face;
- :func:`mount_hands` stacks the hour, minute and (optional) second hands along -x in
  parallel planes with gaps (they never meet at any angle) and returns the x of the
  stack's front;
- cases (``round_case``, ``square_case``, ``octagon_case``): a wall from the back of
  the case (x = ``back`` > 0) to its front rim (x = ``-front``) around a dial of
  ``radius``, with a back plate, and a glass pane inside the rim's front;
  anchor ``bottom`` is the lowest point of the case;
- ``bezel_door``: origin on its hinge axis (vertical, +z) at the door's front outer
  edge on the -y side; the ring and glass lie on the +y side in x in [0, depth];
- ``pendulum``: origin on its pivot axis (+x), the rod hanging along -z;
- ``bell``: origin at the centre of the bell's rim circle, the dome along +z.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, profile, rect_ring, ring, sphere
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import rot_x, rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region

_ALONG_X = rot_y(math.pi / 2)  # local z -> +x
# outline plane (u, v) -> world (y, z), extrusion axis -> world x (a proper rotation)
_YZ = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_SPIN = Region(("hand",))


def x_disc(r: float, x0: float, x1: float, role: str, y: float = 0.0, z: float = 0.0):
    """Cylinder of radius ``r`` along x between ``x0`` and ``x1`` centred on (y, z)."""
    return cylinder(r, abs(x1 - x0), translation((x0 + x1) / 2, y, z) @ _ALONG_X, role=role)


def x_ring(r_out: float, r_in: float, x0: float, x1: float, role: str, y: float = 0.0, z: float = 0.0):
    """Ring wall along x between ``x0`` and ``x1`` centred on (y, z)."""
    return ring(r_out, r_in, abs(x1 - x0), pose=translation((x0 + x1) / 2, y, z) @ _ALONG_X, role=role)


def yz_extrusion(loops, x0: float, x1: float, role: str, y: float = 0.0, z: float = 0.0):
    """Outline ``loops`` drawn in the (y, z) plane, extruded along x from ``x0`` to ``x1``."""
    return extrusion(loops, abs(x1 - x0), pose=translation((x0 + x1) / 2, y, z) @ _YZ, role=role)


def x_frame(ox: float, oz: float, ix: float, iz: float, x0: float, x1: float, role: str, z: float = 0.0):
    """Rectangular frame in the (y, z) plane (outer ``ox`` x ``oz``, centred hole ``ix`` x
    ``iz``) between ``x0`` and ``x1``, centred on (0, z)."""
    return rect_ring(ox, oz, abs(x1 - x0), ix, iz, translation((x0 + x1) / 2, 0, z) @ _YZ, role=role)


# ---------------------------------------------------------------- dial

def clock_dial(p, radius: float, marks: int, thickness=(0.002, 0.004)) -> Part:
    """Dial disc of ``radius`` behind x = 0 (its thickness drawn in the ``thickness``
    range, metres) with ``marks`` (4 or 12) hour bars in front."""
    t = p.uniform("thickness", *thickness)
    h = p.uniform("mark_height", 0.0003, 0.0006)
    L = p.uniform("mark_length", 0.06, 0.12) * radius
    w = p.uniform("mark_width", 0.012, 0.03) * radius
    rm = radius * p.uniform("mark_radius", 0.8, 0.88)
    prims = [x_disc(radius, 0.0, t, "face")]
    for k in range(marks):
        a = 2 * math.pi * k / marks
        wide = 1.8 if k % (marks // 4) == 0 else 1.0  # quarter marks are bolder
        prims.append(cuboid(h, w * wide, L, translation(-h / 2, rm * math.sin(a), rm * math.cos(a)) @ rot_x(-a),
                            role="mark"))
    return Part("dial", "clock_dial", prims, anchors={"front": (-h, 0.0, 0.0), "back": (t, 0.0, 0.0)})


# ---------------------------------------------------------------- hands

def _hand(template, outline, t: float, hub: float, length: float) -> Part:
    prims = [yz_extrusion(outline, -t, 0.0, "hand"), x_disc(hub, -t, 0.0, "hub")]
    return Part("hand", template, prims, anchors={"front": (-t, 0.0, 0.0), "tip": (-t / 2, 0.0, length)},
                regions={"rotate": _SPIN, "push": _SPIN})


def baton_hand(p, length: float, width: float, t: float) -> Part:
    """Straight bar hand with a short tail."""
    tail = p.uniform("tail", 0.1, 0.2) * length
    return _hand("baton_hand", [profile.rectangle(width, length + tail, centre=(0.0, (length - tail) / 2))],
                 t, 0.9 * width, length)


def leaf_hand(p, length: float, width: float, t: float) -> Part:
    """Leaf (spade-less 'dauphine') hand: widest at about 0.4 of its length, pointed."""
    tail = p.uniform("tail", 0.08, 0.15) * length
    m = p.uniform("widest", 0.3, 0.5) * length
    w = 0.75 * width
    out = profile.polygon([[-0.35 * w, -tail], [0.35 * w, -tail], [w, m], [0.0, length], [-w, m]])
    return _hand("leaf_hand", [out], t, 0.9 * w, length)


def arrow_hand(p, length: float, width: float, t: float) -> Part:
    """Thin shaft ending in an arrow head."""
    head = p.uniform("head", 0.18, 0.28) * length
    ws = 0.35 * width
    out = profile.polygon([[-ws, -0.1 * length], [ws, -0.1 * length], [ws, length - head], [width, length - head],
                           [0.0, length], [-width, length - head], [-ws, length - head]])
    return _hand("arrow_hand", [out], t, 0.9 * width, length)


HANDS = {baton_hand: 2.0, leaf_hand: 1.5, arrow_hand: 1.0}


def second_hand(p, length: float, width: float, t: float) -> Part:
    """Needle second hand with a counterweight tail (a disc on the tail)."""
    tail = p.uniform("tail", 0.2, 0.3) * length
    w = max(0.0008, 0.25 * width)
    out = [profile.rectangle(w, length + tail, centre=(0.0, (length - tail) / 2))]
    part = _hand("second_hand", out, t, 1.5 * w + 0.001, length)
    part.primitives.append(x_disc(2.5 * w + 0.001, -t, 0.0, "hand", z=-0.8 * tail))
    return part


def mount_hands(p, builder, parent, face: np.ndarray, radius: float, seconds: bool, shape) -> float:
    """Hour, minute and (if ``seconds``) second hands on continuous joints about +x of
    the face frame ``face`` (in ``parent``'s frame), for a dial of ``radius``.

    The hands lie in parallel planes in front of the dial, each ``gap`` in front of the
    one behind (every hand touches its neighbour within 2 mm, none can meet another at
    any angle); the rest pose shows a time drawn here. Returns the x (face frame) of the
    front of the stack (negative).
    """
    t = p.uniform("hand_thickness", 0.001, 0.0014)
    g = p.uniform("hand_gap", 0.0012, 0.0016)
    w = p.uniform("hand_width", 0.025, 0.045) * radius
    hours = p.uniform("time_h", 0.0, 12.0)
    specs = [("hour", shape, p.uniform("hour_length", 0.5, 0.62) * radius, w, hours / 12),
             ("minute", shape, p.uniform("minute_length", 0.74, 0.84) * radius, 0.75 * w, hours % 1.0)]
    if seconds:
        specs.append(("second", second_hand, p.uniform("second_length", 0.86, 0.9) * radius, 0.75 * w,
                      p.uniform("time_s", 0.0, 1.0)))
    x = 0.0
    for name, tmpl, L, wk, turn in specs:
        x -= g
        link = builder.create_link(f"{name}_hand", parent)
        link.set_joint("continuous", face @ translation(x, 0, 0) @ rot_x(2 * math.pi * turn), axis=(1.0, 0.0, 0.0))
        link.add(tmpl(p.scope(name), L, wk, t))
        x -= t
    return x


# ---------------------------------------------------------------- cases

def _case(template, wall, back_plate, glass, bottom: float, front: float, half_w: float) -> Part:
    return Part("body", template, [wall, back_plate], anchors={"bottom": (0.0, 0.0, -bottom), "front": (-front, 0, 0),
                                                              "half_width": (0.0, half_w, 0.0)},
                regions={"lift": Region(("case",)), "grasp": Region(("case",))}), glass


def _glass(shape_loops, x0, x1) -> Part:
    return Part("glass", "clock_glass", [yz_extrusion(shape_loops, x0, x1, "glass")])


def round_case(p, radius: float, back: float, front: float, dial_back: float | None = None):
    """Round case: a ring wall around the dial from x = ``back`` to x = ``-front``, a
    back disc, and a glass disc just inside the rim's front. Returns (case, glass)."""
    wall = p.uniform("wall", 0.004, 0.012)
    tb = p.uniform("back_plate", 0.002, 0.005)
    tg = p.uniform("glass_thickness", 0.0015, 0.003)
    R = radius + 0.0002
    case, glass = _case("round_case", x_ring(R + wall, R, back, -front, "case"),
                        x_disc(R + wall, back, back + tb, "case"), None, R + wall, front, R + wall)
    return case, Part("glass", "clock_glass", [x_disc(R, -front + 0.001, -front + 0.001 + tg, "glass")])


def square_case(p, radius: float, back: float, front: float, dial_back: float | None = None):
    """Square case: a rectangular frame wall (corners rounded) around the dial, a
    square dial board behind the dial (from x = ``dial_back``), a back plate and a
    square glass pane. Returns (case, glass)."""
    wall = p.uniform("wall", 0.006, 0.02)
    s = radius + p.uniform("margin", 0.0, 0.03)
    r = p.uniform("corner", 0.0, 0.5) * s
    tb = p.uniform("back_plate", 0.002, 0.005)
    tg = p.uniform("glass_thickness", 0.0015, 0.003)
    outer = profile.rectangle(2 * (s + wall), 2 * (s + wall), r + wall if r > 0 else 0.0)
    inner = profile.oriented(profile.rectangle(2 * s, 2 * s, r), ccw=False)
    case, _ = _case("square_case", yz_extrusion([outer, inner], -front, back, "case"),
                    yz_extrusion([outer], back, back + tb, "case"), None, s + wall, front, s + wall)
    # a square dial board right behind the round dial (x from ``board`` on) fills the frame
    board = p.uniform("board", 0.002, 0.004, fixed=dial_back)
    case.primitives.append(yz_extrusion([profile.rectangle(2 * s, 2 * s, r)], board, board + 0.003, "board"))
    return case, _glass([profile.rectangle(2 * s, 2 * s, r)], -front + 0.001, -front + 0.001 + tg)


def octagon_case(p, radius: float, back: float, front: float, dial_back: float | None = None):
    """Schoolhouse octagon: an octagonal frame with a round opening, a back plate and
    a round glass. Returns (case, glass)."""
    wall = p.uniform("wall", 0.01, 0.03)
    tb = p.uniform("back_plate", 0.002, 0.005)
    tg = p.uniform("glass_thickness", 0.0015, 0.003)
    R = radius + 0.0002
    ro = (R + wall) / math.cos(math.pi / 8)  # circumradius: the flats are ``wall`` off the opening
    outer = profile.regular_polygon(ro, 8, math.pi / 8)
    hole = profile.oriented(profile.circle(R), ccw=False)
    case, _ = _case("octagon_case", yz_extrusion([outer, hole], -front, back, "case"),
                    yz_extrusion([outer], back, back + tb, "case"), None, R + wall, front, R + wall)
    return case, Part("glass", "clock_glass", [x_disc(R, -front + 0.001, -front + 0.001 + tg, "glass")])


WALL_CASES = {round_case: 3.0, square_case: 1.5, octagon_case: 1.0}


def cradle(p, radius: float, depth: float, x_mid: float) -> Part:
    """Display cradle for a round case of outer ``radius`` resting on it: a plate on the
    floor and two chocks whose inner top edges touch the rim (origin under the case's
    lowest point, x = ``x_mid`` the case's middle in depth)."""
    t = p.uniform("plate", 0.006, 0.012)
    d = p.uniform("chock_spread", 0.35, 0.5) * radius
    w = p.uniform("chock_width", 0.02, 0.035)
    h = radius - math.sqrt(radius * radius - d * d)  # the rim's height above its lowest point at y = d
    W = 2 * (d + w) + 0.01
    prims = [cuboid(depth, W, t, translation(x_mid, 0, -t / 2), role="plate")]
    prims += [cuboid(depth, w, h, translation(x_mid, s * (d + w / 2), h / 2), role="chock") for s in (-1.0, 1.0)]
    return Part("base", "clock_cradle", prims, regions={"lift": Region(("plate",))})


# ---------------------------------------------------------------- mantel / alarm parts

def bezel_door(p, radius: float, depth: float, tg: float):
    """Round hinged bezel over a dial of ``radius`` and its glass (see module docstring
    for the frame); ``depth`` (x) clears the hands, ``tg`` is the glass thickness.
    Returns (bezel, glass)."""
    wall = p.uniform("wall", 0.003, 0.006)
    R = radius + wall
    prims = [x_ring(R + wall, R - 0.0005, 0.0, depth, "bezel", y=R + wall)]
    knob = p.uniform("tab", 0.004, 0.007)
    prims.append(x_disc(knob, -0.004, 0.0, "tab", y=2 * (R + wall) + knob * 0.5))
    grip = Region(("tab", "bezel"))
    door = Part("door", "bezel_door", prims, anchors={"far": (0.0, 2 * (R + wall), 0.0)},
                regions={"pull": grip, "push": grip}, actionable="hinge_door",
                grasps=Deferred(_rim_grasp, 2 * (R + wall), depth))
    return door, Part("glass", "clock_glass", [x_disc(R - 0.0005, 0.0005, 0.0005 + tg, "glass", y=R + wall)])


def _rim_grasp(y: float, depth: float) -> list:
    """Pinch across the bezel's depth at its far edge (``y``), approaching towards the
    hinge (-y), jaws closing along x."""
    T = np.eye(4)
    T[:3, :3] = np.column_stack([(0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (0.0, -1.0, 0.0)])
    T[:3, 3] = (depth / 2, y - 0.004, 0.0)
    return [Grasp(T, depth + 0.02)]


def pendulum(p, length: float, bob: float) -> Part:
    """Pendulum: a pivot hub, a rod of ``length`` along -z and a bob disc of radius
    ``bob`` facing the front (pivot axis +x)."""
    rr = p.uniform("rod_width", 0.003, 0.006)
    tb = p.uniform("bob_thickness", 0.003, 0.006)
    prims = [x_disc(0.006, -0.002, 0.002, "hub"), cuboid(0.002, rr, length, translation(0, 0, -length / 2), role="rod"),
             x_disc(bob, -tb / 2, tb / 2, "bob", z=-length)]
    return Part("pendulum", "pendulum", prims, anchors={"bottom": (0.0, 0.0, -length - bob)},
                regions={"push": Region(("bob",))})


def bell(p, radius: float) -> Part:
    """Alarm bell: a dome of ``radius`` over its rim (origin at the rim's centre), a
    nut on top."""
    h = p.uniform("height", 0.55, 0.8) * radius
    Rs = (radius * radius + h * h) / (2 * h)  # the sphere through the rim and the apex
    prims = [sphere(Rs, Rs - h, Rs, translation(0, 0, h - Rs), role="bell"),
             cylinder(0.15 * radius, 0.2 * radius, translation(0, 0, h + 0.1 * radius - 0.001), role="nut")]
    return Part("bell", "bell", prims, anchors={"top": (0.0, 0.0, h + 0.2 * radius)})
