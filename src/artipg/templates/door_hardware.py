"""Door hardware: roses, back plates, levers, knobs, thumb turns and lock cylinders.

Frame (as :mod:`artipg.templates.turn_handles`): the mounting face is the plane x = 0
with outward normal **-x**, the origin is the spindle axis on that face, parts
protrude along -x, +z is up. Fixed parts (roses, plates, cylinders) lie in
-depth <= x <= 0 and give anchor ``front`` = (-depth, 0, 0); a turning part is built in
the frame of its own face (the fixed part's front), starts ``gap`` in front of it and
turns about the x axis. Levers point to ``side`` (+1: +y) and give anchors ``tip``
(the lever end) and ``reach`` = (r, 0, 0), the radius swept about the axis. Every size
range comes from the caller as a dict of (lo, hi) ranges in metres (``dims``).
Levers and knobs are swept tubes and lathe profiles (:mod:`artipg.geometry.sweep`,
:mod:`artipg.geometry.lathe`).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cylinder, profile, sphere
from artipg.geometry.extrusion import extrusion
from artipg.geometry.lathe import lathe
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.sweep import sweep
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region

_X = Placer(rot_y(-math.pi / 2))  # local z -> -x
QUARTER = math.tan(math.pi / 8)  # bulge of a quarter-circle profile arc


def _revolve(loop, role: str, x0: float = 0.0):
    """Lathe of a (ρ, depth, bulge) profile about the x axis, depth measured from x0 towards -x."""
    return lathe(loop, pose=_X.at(x0, 0.0, 0.0), role=role)


def _cap_bulge(r: float, z0: float, z1: float) -> float:
    """Bulge of the profile arc from (r, z0) to the axis point (0, z1) on a sphere centred on the axis."""
    zc = (r * r + z0 * z0 - z1 * z1) / (2.0 * (z0 - z1))
    return math.tan(math.atan2(r * (z1 - zc), (z0 - zc) * (z1 - zc)) / 4.0)


def _front_grasp(x: float, y: float, z: float, width: float) -> Grasp:
    """Approach +x (towards the door), jaws closing along z."""
    return Grasp(np.array([[0.0, 0.0, 1.0, x], [1.0, 0.0, 0.0, y], [0.0, 1.0, 0.0, z], [0.0, 0.0, 0.0, 1.0]]), width)


def _lever_grasps(x: float, side: float, L: float, w: float) -> list[Grasp]:
    return [_front_grasp(x, side * f * L, 0.0, w + 0.02) for f in (0.5, 0.8)]


# ----------------------------------------------------------------- fixed parts

def rose(p, dims: dict) -> Part:
    """Round rose: a disc of ``dims["radius"]`` and ``dims["thickness"]`` with a rounded front edge."""
    R, t = p.uniform("radius", *dims["radius"]), p.uniform("thickness", *dims["thickness"])
    e = p.uniform("edge", 0.3, 0.6) * t
    loop = [(0.0, 0.0, 0.0), (R, 0.0, 0.0), (R, t - e, QUARTER), (R - e, t, 0.0), (0.0, t, 0.0)]
    return Part("base", "round_rose", [_revolve(loop, "rose")],
                anchors={"front": (-t, 0.0, 0.0)})


def back_plate(p, dims: dict, below: float) -> Part:
    """Long back plate (escutcheon): ``dims["width"]`` wide, ``dims["thickness"]`` deep,
    reaching ``dims["above"]`` above the spindle and ``below`` + ``dims["margin"]``
    below it (``below``: the lowest fitting's centre under the spindle)."""
    w, t = p.uniform("width", *dims["width"]), p.uniform("thickness", *dims["thickness"])
    top, bot = p.uniform("above", *dims["above"]), below + p.uniform("margin", *dims["margin"])
    r = p.uniform("round", 0.2, 0.5) * t
    prim = rounded_box(t, w, top + bot, r, translation(-t / 2, 0.0, (top - bot) / 2), role="plate")
    return Part("base", "back_plate", [prim], anchors={"front": (-t, 0.0, 0.0)})


def euro_cylinder(p, dims: dict) -> Part:
    """Profile (euro) lock cylinder face: a round plug over a narrower stem, protruding
    ``dims["proud"]`` from x = 0; its plug centre is the origin."""
    rc, ws = p.uniform("plug_radius", *dims["plug_radius"]), p.uniform("stem_width", *dims["stem_width"])
    hs, d = p.uniform("stem_length", *dims["stem_length"]), p.uniform("proud", *dims["proud"])
    ys = ws / 2
    zs = -math.sqrt(rc * rc - ys * ys)
    outline = profile.polygon([(ys, -hs), (ys, zs), (-ys, zs), (-ys, -hs)])
    outline[1, 2] = math.tan((math.pi + 2.0 * math.acos(ys / rc)) / 4.0)  # the plug's arc over the top
    # outline (y, z), extruded along local z -> x (the extrusion is centred, so either sign)
    T = np.array([[0.0, 0.0, 1.0, -d / 2], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    return Part("lock", "euro_cylinder", [extrusion([outline], d, pose=T, role="cylinder")],
                anchors={"front": (-d, 0.0, 0.0)})


# ----------------------------------------------------------------- levers

def _hub(p, dims: dict, gap: float, depth: float):
    """Round collar of the lever from ``gap`` to ``depth`` in front of its face."""
    rh = p.uniform("hub_radius", *dims["hub_radius"])
    e = min(0.3 * rh, 0.3 * (depth - gap))
    loop = [(0.0, gap, 0.0), (rh, gap, 0.0), (rh, depth - e, QUARTER), (rh - e, depth, 0.0), (0.0, depth, 0.0)]
    return _revolve(loop, "hub"), rh


def _lever(template, prims, D, side, L, w, reach) -> Part:
    return Part("handle", template, prims,
                anchors={"tip": (-D, side * L, 0.0), "front": (-D, 0.0, 0.0), "reach": (reach, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "push": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred(_lever_grasps, -D, side, L, w), actionable="hinge_handle")


def _bar_pose(x0: float, side: float) -> np.ndarray:
    """Sweep frame: path x -> -x (out of the door), path z -> ``side`` * y."""
    return np.array([[-1.0, 0.0, 0.0, x0], [0.0, 0.0, side, 0.0], [0.0, side, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def _bar_start(p, dims, gap):
    """Shared draws of the swept levers: bar radius, length, standoff, bend radius, hub."""
    r, L = p.uniform("bar_radius", *dims["bar_radius"]), p.uniform("length", *dims["length"])
    D = p.uniform("standoff", *dims["standoff"])  # face to the lever's centre line
    b = p.uniform("bend", 1.6, 2.6) * r
    hub, rh = _hub(p, dims, gap, D - b)
    return r, L, D, b, hub, rh


def bar_lever(p, side: float, dims: dict, gap: float) -> Part:
    """Round bar lever: a collar, a quarter bend out of it and a straight bar ending in a dome."""
    r, L, D, b, hub, rh = _bar_start(p, dims, gap)
    x0 = -(D - b) + 0.6 * (D - b - gap)  # the tube starts inside the collar
    path = [line(D - b + x0), arc(b, math.pi / 2), line(L - b)]
    prims = [hub, sweep(r, path, pose=_bar_pose(x0, side), role="grip"),
             sphere(r, 0.0, r, pose=_tip_pose(-D, side * L, side), role="grip")]
    return _lever("bar_lever", prims, D, side, L, 2 * r, math.hypot(L + r, r))


def _tip_pose(x: float, y: float, side: float) -> np.ndarray:
    """Frame at a bar's end whose +z points along ``side`` * y (for a dome cap)."""
    return np.array([[1.0, 0.0, 0.0, x], [0.0, 0.0, side, y], [0.0, -side, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def return_lever(p, side: float, dims: dict, gap: float) -> Part:
    """Return-to-door lever: the bar's end bends back towards the door (safety lever)."""
    r, L, D, b, hub, rh = _bar_start(p, dims, gap)
    x0 = -(D - b) + 0.6 * (D - b - gap)
    b2 = p.uniform("return_bend", 1.6, 2.4) * r
    back = p.uniform("return", 0.3, 0.6) * (D - b2 - r - 0.006)  # stops >= 6 mm off the door
    path = [line(D - b + x0), arc(b, math.pi / 2), line(L - b - b2), arc(b2, math.pi / 2), line(back)]
    prims = [hub, sweep(r, path, pose=_bar_pose(x0, side), role="grip")]
    return _lever("return_lever", prims, D, side, L - b2, 2 * r, math.hypot(L + r, r))


def crescent_lever(p, side: float, dims: dict, gap: float) -> Part:
    """Curved lever: after the bend the bar curves gently back towards the door."""
    r, L, D, b, hub, rh = _bar_start(p, dims, gap)
    x0 = -(D - b) + 0.6 * (D - b - gap)
    phi = p.uniform("curve", 0.25, 0.45)
    Rc = (L - b) / math.sin(phi)  # the curve ends L from the axis
    phi = min(phi, math.acos(min(1.0, 1.0 - (D - r - 0.008) / Rc)))  # and >= 8 mm off the door
    path = [line(D - b + x0), arc(b, math.pi / 2), arc(Rc, phi)]
    prims = [hub, sweep(r, path, pose=_bar_pose(x0, side), role="grip")]
    reach = b + Rc * math.sin(phi)
    return _lever("crescent_lever", prims, D - 0.5 * Rc * (1 - math.cos(phi)), side, 0.8 * reach,
                  2 * r, math.hypot(reach + r, r))


def paddle_lever(p, side: float, dims: dict, gap: float) -> Part:
    """Flat lever: a rounded rectangular bar on a round collar."""
    L, D = p.uniform("length", *dims["length"]), p.uniform("standoff", *dims["standoff"])
    t = p.uniform("bar_thickness", *dims["bar_thickness"])
    h = p.uniform("bar_height", *dims["bar_height"])
    hub, rh = _hub(p, dims, gap, D)
    y0 = -0.6 * rh
    bar = rounded_box(t, L - y0, h, p.uniform("bar_round", 0.25, 0.5) * min(t, h),
                      translation(-D - t / 2 + 0.002, side * (L + y0) / 2, 0.0), role="grip")
    return _lever("paddle_lever", [hub, bar], D + 0.5 * t, side, L, h, math.hypot(L, h / 2))


LEVERS = {bar_lever: 3.0, return_lever: 1.5, crescent_lever: 1.5, paddle_lever: 2.0}


# ----------------------------------------------------------------- knobs and turns

def _knob(template, prims, depth, R, neck_end) -> Part:
    x = -(neck_end + depth)
    return Part("handle", template, prims,
                anchors={"tip": (x, 0.0, 0.0), "front": (x, 0.0, 0.0), "reach": (R, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred.one(_front_grasp, -(neck_end + 0.5 * depth), 0.0, 0.0, 2 * R + 0.02),
                actionable="hinge_knob")


def _neck(p, dims, gap):
    rn, nl = p.uniform("neck_radius", *dims["neck_radius"]), p.uniform("neck_length", *dims["neck_length"])
    return rn, gap + nl


def ball_knob(p, dims: dict, gap: float) -> Part:
    """Ball knob: a sphere on a round neck."""
    R = p.uniform("radius", *dims["radius"])
    rn, z1 = _neck(p, dims, gap)
    zc = z1 + math.sqrt(R * R - rn * rn)
    # five vertices, not four: a four-vertex profile closed on the axis is taken for a
    # frustum by ``lathe.frustum_dims`` (which reads only the first side's bulge)
    loop = [(0.0, gap, 0.0), (rn, gap, 0.0), (rn, 0.5 * (gap + z1), 0.0), (rn, z1, _cap_bulge(rn, z1 - zc, R)),
            (0.0, zc + R, 0.0)]
    return _knob("ball_knob", [_revolve(loop, "grip")], zc + R - z1, R, z1)


def flared_knob(p, dims: dict, gap: float) -> Part:
    """Flared (tulip) knob: a cone flaring from the neck to a flat face with a rounded rim."""
    R, d = p.uniform("radius", *dims["radius"]), p.uniform("depth", *dims["depth"])
    rn, z1 = _neck(p, dims, gap)
    e = p.uniform("rim", 0.15, 0.3) * d
    k = p.uniform("flare", 0.45, 0.7)
    loop = [(0.0, gap, 0.0), (rn, gap, 0.0), (rn, z1, 0.0), (R * k, z1 + 0.45 * d, 0.0), (R, z1 + d - e, QUARTER),
            (R - e, z1 + d, 0.0), (0.0, z1 + d, 0.0)]
    return _knob("flared_knob", [_revolve(loop, "grip")], d, R, z1)


def beehive_knob(p, dims: dict, gap: float) -> Part:
    """Beehive knob: a drum with a domed face over a short neck."""
    R, d = p.uniform("radius", *dims["radius"]), p.uniform("depth", *dims["depth"])
    rn, z1 = _neck(p, dims, gap)
    top = z1 + d
    z2 = max(z1 + p.uniform("drum", 0.35, 0.55) * d, top - 0.9 * R)  # the dome stays under a half sphere
    loop = [(0.0, gap, 0.0), (rn, gap, 0.0), (rn, z1, 0.0), (R, z1 + 0.15 * d, 0.0), (R, z2, _cap_bulge(R, z2, top)),
            (0.0, top, 0.0)]
    return _knob("beehive_knob", [_revolve(loop, "grip")], d, R, z1)


KNOBS = {ball_knob: 2.0, flared_knob: 1.5, beehive_knob: 1.0}


def thumb_turn(p, dims: dict, gap: float) -> Part:
    """Thumb turn: a round boss and a flat wing standing vertically at rest."""
    rb = p.uniform("boss_radius", *dims["boss_radius"])
    db = gap + p.uniform("boss_depth", *dims["boss_depth"])
    w, d, t = (p.uniform(k, *dims[k]) for k in ("wing_length", "wing_depth", "wing_thickness"))
    boss = cylinder(rb, db - gap, _X.at(-0.5 * (gap + db), 0.0, 0.0), role="boss")
    wing = rounded_box(d, t, w, 0.45 * t, translation(-db - d / 2 + 0.001, 0.0, 0.0), role="grip")
    return Part("knob", "thumb_turn", [boss, wing],
                anchors={"tip": (-db - d, 0.0, w / 2), "reach": (math.hypot(w / 2, t / 2), 0.0, 0.0)},
                regions={"rotate": Region(("grip",)), "grasp": Region(("grip",))},
                grasps=Deferred.one(_front_grasp, -db - d / 2, 0.0, 0.0, t + 0.02), actionable="hinge_knob")
