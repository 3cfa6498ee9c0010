"""Handles that turn about the normal of their mounting surface: door levers and knobs,
thumb turns, casement-window handles and safe spoke wheels.

Frame convention (as in :mod:`artipg.templates.controls`): the surface is the plane
x = 0 with outward normal **-x**, the origin is the turning axis on that surface, the
handle protrudes along -x and +z is up. Every template's rotating hub is round and
coaxial with the axis, so a handle link turns without touching its surface.
Anchor ``tip`` is the end of the lever (its y sign is the side the lever points to),
``reach`` = (r, 0, 0) the radius the handle sweeps about its axis; :func:`mount_turning`
turns levers tip-down for positive joint values.
"""

from __future__ import annotations

import copy
import math

import numpy as np

from artipg.geometry import cuboid, cylinder, frustum, sphere, tube
from artipg.geometry.tube import arc, line
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.rules.params import option_name

_X = Placer(rot_y(-math.pi / 2))  # local z -> -x
_Y = Placer(rot_x(-math.pi / 2))  # local z -> +y


def _disc(r: float, x0: float, x1: float, role: str):
    """Cylinder of radius ``r`` along x from x0 (back) to x1 (front, x1 < x0)."""
    return cylinder(r, x0 - x1, _X.at((x0 + x1) / 2, 0, 0), role=role)


def _grasp(x: float, y: float, width: float) -> Grasp:
    # approach along +x (towards the surface), jaws closing along z across the lever
    T = np.array([[0.0, 0.0, 1.0, x], [1.0, 0.0, 0.0, y], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    return Grasp(T, width)


def _lever_grasps(x: float, side: float, L: float, grip_w: float) -> list[Grasp]:
    """Grasps at half and 0.8 of a lever's length."""
    return [_grasp(x, side * f * L, grip_w + 0.02) for f in (0.5, 0.8)]


def _rose_and_neck(p, neck_r: float):
    R = p.uniform("rose_radius", 0.022, 0.03)
    rt = p.uniform("rose_thickness", 0.006, 0.012)
    nl = p.uniform("neck_length", 0.035, 0.055)
    return [_disc(R, 0.0, -rt, "rose"), _disc(neck_r, -rt, -rt - nl, "neck")], -rt - nl


def _lever(template, prims, x, side, L, grip_w) -> Part:
    reach = float(np.hypot(L, grip_w / 2))
    return Part("handle", template, prims, anchors={"tip": (x, side * L, 0.0), "front": (x, 0.0, 0.0),
                                                    "reach": (reach, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "push": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred(_lever_grasps, x, side, L, grip_w), actionable="hinge_handle")


def round_lever(p, side: float = 1.0) -> Part:
    """Door lever: a round bar on a neck and rose, pointing towards ``side`` (+1: +y)."""
    r = p.uniform("bar_radius", 0.007, 0.01)
    L = p.uniform("lever_length", 0.1, 0.14)
    prims, x = _rose_and_neck(p, p.uniform("neck_radius", 1.0, 1.3) * r)
    prims.append(cylinder(r, L, _Y.at(x + r, side * L / 2, 0), role="grip"))
    return _lever("round_lever", prims, x + r, side, L, 2 * r)


def flat_lever(p, side: float = 1.0) -> Part:
    """Door lever with a flat rectangular bar."""
    t = p.uniform("bar_thickness", 0.007, 0.012)
    h = p.uniform("bar_height", 0.012, 0.022)
    L = p.uniform("lever_length", 0.1, 0.14)
    prims, x = _rose_and_neck(p, p.uniform("neck_radius", 0.008, 0.011))
    prims.append(cuboid(t, L, h, translation(x + t / 2, side * L / 2, 0), role="grip"))
    return _lever("flat_lever", prims, x + t / 2, side, L, h)


def return_lever(p, side: float = 1.0) -> Part:
    """Lever whose end bends back towards the door (a "return to door" lever)."""
    r = p.uniform("bar_radius", 0.007, 0.009)
    L = p.uniform("lever_length", 0.09, 0.12)
    bend = p.uniform("bend_radius", 2.0, 3.0) * r
    prims, x = _rose_and_neck(p, 1.2 * r)
    # the return stops 4 mm short of the door; on a short neck there is no room for it
    back = min(p.uniform("return_length", 0.01, 0.025), -x - bend - 2 * r - 0.004)
    # path in local (x, z) = (side*y, x): along the lever, then curling towards the door
    T = np.array([[0.0, 0.0, 1.0, x + r], [side, 0.0, 0.0, 0.0], [0.0, side, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    path = [line(L - bend), arc(bend, math.pi / 2)] + ([line(back)] if back > 1e-3 else [])
    prims += tube(r, path, pose=T, role="grip")
    return _lever("return_lever", prims, x + r, side, L, 2 * r)


def ball_knob(p, side: float = 1.0) -> Part:
    """Round door knob: a ball on a neck and rose (``side`` is ignored)."""
    R = p.uniform("knob_radius", 0.022, 0.03)
    prims, x = _rose_and_neck(p, p.uniform("neck_radius", 0.008, 0.012))
    prims.append(sphere(R, pose=translation(x - 0.8 * R, 0, 0), role="grip"))
    return Part("handle", "ball_knob", prims, anchors={"tip": (x - 0.8 * R, 0.0, 0.0), "front": (x - 1.8 * R, 0, 0),
                                                       "reach": (R, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred.one(_grasp, x - 0.8 * R, 0.0, 2 * R + 0.02), actionable="hinge_knob")


def flared_knob(p, side: float = 1.0) -> Part:
    """Door knob flaring from the neck to a flat round face (``side`` is ignored)."""
    R = p.uniform("knob_radius", 0.022, 0.03)
    d = p.uniform("knob_depth", 0.025, 0.04)
    prims, x = _rose_and_neck(p, p.uniform("neck_radius", 0.008, 0.012))
    prims.append(frustum(0.5 * R, R, 0.7 * d, _X.at(x - 0.35 * d + 0.001, 0, 0), role="grip"))
    prims.append(_disc(R, x - 0.7 * d, x - d, "grip"))
    return Part("handle", "flared_knob", prims, anchors={"tip": (x - d, 0.0, 0.0), "front": (x - d, 0.0, 0.0),
                                                         "reach": (R, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred.one(_grasp, x - 0.85 * d, 0.0, 2 * R + 0.02), actionable="hinge_knob")


DOOR_LEVERS = {round_lever: 3.0, flat_lever: 2.0, return_lever: 1.5}
DOOR_KNOBS = {ball_knob: 2.0, flared_knob: 1.0}


def thumb_turn(p, side: float = 1.0) -> Part:
    """Deadbolt thumb turn: a small rose with a flat wing grip."""
    R = p.uniform("rose_radius", 0.018, 0.026)
    rt = p.uniform("rose_thickness", 0.005, 0.01)
    w, d = p.uniform("wing_length", 0.03, 0.045), p.uniform("wing_depth", 0.015, 0.022)
    prims = [_disc(R, 0.0, -rt, "rose"), cuboid(d, 0.008, w, translation(-rt - d / 2, 0, 0), role="grip")]
    return Part("knob", "thumb_turn", prims, anchors={"tip": (-rt - d, 0.0, w / 2), "reach": (R, 0.0, 0.0)},
                regions={"rotate": Region(("grip",)), "grasp": Region(("grip",))},
                grasps=Deferred.one(_grasp, -rt - d / 2, 0.0, 0.03), actionable="hinge_knob")


def casement_handle(p, side: float = 1.0):
    """Window handle: a fixed oblong base plate and a lever pointing down at rest.

    Returns
    -------
    (Part, Part)
        The base (add it to the sash; its front face is at x = -base depth) and the
        lever in the convention above, to be mounted on the base's front face.
    """
    bw, bh = p.uniform("base_width", 0.028, 0.036), p.uniform("base_height", 0.07, 0.09)
    bd = p.uniform("base_depth", 0.006, 0.012)
    base = Part("base", "casement_handle", [cuboid(bd, bw, bh, translation(-bd / 2, 0, 0), role="base")],
                anchors={"mount": (-bd, 0.0, 0.0)})
    r = p.uniform("hub_radius", 0.011, 0.014)
    hd = p.uniform("hub_depth", 0.02, 0.03)
    L = p.uniform("lever_length", 0.09, 0.12)
    gt = p.uniform("grip_thickness", 0.012, 0.018)
    prims = [_disc(r, 0.0, -hd, "hub"), cuboid(gt, 0.016, L, translation(-hd + gt / 2, 0, -L / 2), role="grip")]
    lever = Part("handle", "casement_handle", prims, anchors={"tip": (-hd, 0.0, -L), "reach": (L, 0.0, 0.0)},
                 regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                 grasps=Deferred(_casement_grasps, hd, gt, L), actionable="hinge_handle")
    return base, lever


def _casement_grasps(hd: float, gt: float, L: float) -> list[Grasp]:
    """Grasps on a casement lever's hanging grip: approach +x, jaws closing along y."""
    return [Grasp(np.array([[0.0, 0.0, 1.0, -hd + gt / 2], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, -f * L],
                            [0.0, 0.0, 0.0, 1.0]]), 0.036) for f in (0.55, 0.8)]


def spoke_wheel(p, side: float = 1.0, radius: float | None = None) -> Part:
    """Safe handle: a hub with 3-5 spokes ending in balls (a ship's-wheel handle);
    ``side`` is ignored."""
    n = p.integers("spokes", 3, 5)
    L = p.uniform("spoke_length", 0.06, 0.12, fixed=radius)
    r = p.uniform("spoke_radius", 0.006, 0.01)
    hub_r = p.uniform("hub_radius", 0.02, 0.035)
    ball = p.uniform("ball_radius", 1.3, 1.9) * r
    hub_d = max(p.uniform("hub_depth", 0.02, 0.035), 2 * ball + 0.006)  # the balls clear the surface
    x = -hub_d / 2
    prims = [_disc(hub_r, 0.0, -hub_d, "hub")]
    a0 = p.uniform("phase", 0.0, math.pi / n)
    for i in range(n):
        a = a0 + 2 * math.pi * i / n
        c, s = math.cos(a), math.sin(a)
        R = np.array([[1.0, 0.0, 0.0, x], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]])
        prims.append(cylinder(r, L, R @ translation(0, 0, L / 2), role="grip"))
        prims.append(sphere(ball, pose=R @ translation(0, 0, L), role="grip"))
    return Part("handle", "spoke_wheel", prims, anchors={"tip": (x, 0.0, L), "front": (-hub_d, 0.0, 0.0),
                                                         "reach": (L + ball, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "rotate": Region(("grip",))},
                grasps=Deferred(_wheel_grasps, a0, n, x, L, ball), actionable="hinge_handle")


def _wheel_grasps(a0: float, n: int, x: float, L: float, ball: float) -> list[Grasp]:
    """Grasps on the balls of a :func:`spoke_wheel`: pinched from the front, jaws
    closing across each spoke."""
    grasps = []
    for i in range(n):
        a = a0 + 2 * math.pi * i / n
        c, s = math.cos(a), math.sin(a)
        T = np.array([[0.0, 0.0, 1.0, x], [s, c, 0.0, -s * L], [-c, s, 0.0, c * L], [0.0, 0.0, 0.0, 1.0]])
        grasps.append(Grasp(T, 2 * ball + 0.02))
    return grasps


SIDELESS = frozenset((ball_knob, flared_knob, thumb_turn))  # templates that ignore ``side``


def mount_turning(builder, parent, part, pose: np.ndarray, limits, name: str = "handle", axis=None):
    """Attach ``part`` on a revolute joint about the mount frame's x axis.

    By default the axis sign makes positive values turn a lever's tip downwards (a
    lever pointing to +y turns about -x), and a lever hanging down towards +y; pass
    ``axis`` (3,) to choose it.
    """
    tip_y = float(part.anchors.get("tip", (0.0, 0.0, 0.0))[1])
    link = builder.create_link(name, parent)
    link.set_joint("revolute", pose, axis=axis or (-1.0 if tip_y > 0 else 1.0, 0.0, 0.0), limits=limits)
    link.add(part)
    return link


class _Replay:
    """Stand-in recorder returning the values already recorded under the same names,
    so a template called again builds the same design (nothing is drawn or recorded)."""

    def __init__(self, record: dict, prefix: str):
        self.record, self.prefix = record, prefix

    def _value(self, name, fixed):
        return fixed if fixed is not None else self.record[f"{self.prefix}.{name}" if self.prefix else name].value

    def scope(self, name: str) -> "_Replay":
        return _Replay(self.record, f"{self.prefix}.{name}" if self.prefix else name)

    def uniform(self, name, lo, hi, fixed=None):
        return float(self._value(name, fixed))

    def integers(self, name, lo, hi, fixed=None):
        return int(self._value(name, fixed))

    def flag(self, name, prob, fixed=None):
        return bool(self._value(name, fixed))

    # detail draws (:mod:`artipg.rules.detail`): the recorded value, or the "off" value
    # where the first build drew none (detail off)
    def _detail(self, name):
        return self.record.get(f"{self.prefix}.{name}" if self.prefix else name)

    def detail_uniform(self, name, lo, hi, off=0.0):
        rec = self._detail(name)
        return off if rec is None else float(rec.value)

    def detail_choice(self, name, options, off):
        rec = self._detail(name)
        if rec is None:
            return off
        return next(o for o in options if option_name(o) == rec.value)

    def detail_flag(self, name, prob):
        rec = self._detail(name)
        return False if rec is None else bool(rec.value)


def replay(p) -> _Replay:
    """A recorder that replays what ``p`` (a scoped recorder) has already drawn: pass it
    to a template that was built with ``p`` to build the same design again."""
    return _Replay(p.record, p.prefix)


def matching(template, p, sides) -> list:
    """One handle design built for each lever direction in ``sides`` (a set of door
    hardware: the same lever on both faces and both leaves); parameters are drawn and
    recorded once, by the first build. A direction built already (any direction, for
    the templates in :data:`SIDELESS`) gets a copy of that part."""
    built, out = {}, []
    for s in sides:
        key = None if template in SIDELESS else s
        part = built.get(key)
        if part is None:
            part = built[key] = template(replay(p) if built else p, side=s)
        else:
            part = copy.copy(part)
        out.append(part)
    return out
