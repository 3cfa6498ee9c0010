"""Computer-mouse parts: the base with its wheel well, the palm dome, the main buttons
and the scroll wheel.

Frames: the base and the palm are built in the object frame (the mouse lies on z = 0,
its front, where the buttons and the cable are, towards -x, centred on y). A main
button's origin is on its hinge line: the bottom rear edge of the button; the button
spans local x in [-length, 0], its strips' y spans (the caller's side of the slot) and
rises along +z from z = 0. The scroll wheel's origin is its centre, its axle along y.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, prism, torus
from artipg.geometry.extrusion import extrusion
from artipg.geometry.lathe import lathe
from artipg.geometry.transforms import rot_x, rot_z, translation
from artipg.model.part import Part, Region

_AXLE_Y = rot_x(math.pi / 2)  # a lathe's z along y
_PROFILE = rot_x(math.pi / 2)  # an outline's (x, y) to (x, z), extruded along y


def _arc_points(cx: float, cy: float, r: float, a0: float, a1: float, n: int) -> list:
    """``n`` + 1 points (x, y, 0) on the circle about (cx, cy) from angle a0 to a1."""
    return [[cx + r * math.cos(a0 + (a1 - a0) * i / n), cy + r * math.sin(a0 + (a1 - a0) * i / n), 0.0]
            for i in range(n + 1)]


def outline(length: float, width: float, nose: float) -> np.ndarray:
    """Top-view outline (n, 3) of (x, y, bulge) rows, counter-clockwise: straight sides
    ``width`` apart, a semicircular back (radius ``width / 2``) and a front arc of
    sagitta ``nose``, the arcs as polylines (caps sample as triangle cells); the front
    tip at x = -length / 2."""
    x1, w = length / 2 - width / 2, width / 2
    back = _arc_points(x1, 0.0, w, -math.pi / 2, math.pi / 2, 8)
    r = (w * w + nose * nose) / (2 * nose)  # the nose arc's circle, centre on the axis behind the tip
    a = math.asin(w / r)
    front = _arc_points(-length / 2 + r, 0.0, r, math.pi - a, math.pi + a, 4)
    return np.array(back + front)


def base_shell(p, length: float, width: float, height: float, nose: float, well) -> Part:
    """Lower shell: the top-view :func:`outline` extruded from z = 0 to ``height``, with
    a rectangular wheel well ``well`` = (x0, x1, y half width) through it."""
    x0, x1, yw = well
    hole = np.array([[x0, -yw, 0.0], [x0, yw, 0.0], [x1, yw, 0.0], [x1, -yw, 0.0]])
    prim = extrusion([outline(length, width, nose), hole], height, pose=translation(0, 0, height / 2), role="shell")
    return Part("body", "mouse_base", [prim], regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def palm_dome(p, x_centre: float, radius: float, z0: float, rise: float) -> Part:
    """Palm rest: the rear half (x >= ``x_centre``) of a spherical cap whose base circle
    (``radius``) lies on z = ``z0`` and whose top is ``rise`` above it (its meridian a
    polyline of six chords, so the cut face samples as triangle cells)."""
    R = (radius ** 2 + rise ** 2) / (2 * rise)
    a = math.asin(radius / R)
    meridian = [[R * math.sin(a * (1 - i / 6)), R * math.cos(a * (1 - i / 6)) - (R - rise), 0.0] for i in range(7)]
    loop = [[0.0, 0.0, 0.0]] + meridian
    T = translation(x_centre, 0, z0) @ rot_z(-math.pi / 2)
    prim = lathe(loop, math.pi, pose=T, role="shell")
    return Part("body", "palm_dome", [prim], regions={"grasp": Region(("shell",))})


def bracket(p, x0: float, x1: float, y: float, top: float) -> Part:
    """Wheel bracket filling the well's footprint from the floor up to ``top``."""
    return Part("body", "wheel_bracket", [cuboid_between((x0, -y, 0.0), (x1, y, top), role="bracket")])


def main_button(p, length: float, strips, sag: float) -> Part:
    """A main button made of side-by-side strips, each a side profile (flat bottom on
    z = 0, ``front`` high at x = -length and ``rear`` high at x = 0, joined by an arc
    bulging up by ``sag``, as a polyline through three chords: collision hulls keep its
    volume) extruded over its y span: ``strips`` = [(y0, y1, front,
    rear), ...] from the slot outwards, so the top steps down towards the outer edge as
    the palm dome does. Press region: the front half of the top."""
    prims = []
    for y0, y1, front, rear in strips:
        arc = [[-length * t, profile_top(length, front, rear, sag, -length * t), 0.0] for t in (1 / 3, 2 / 3)]
        loop = np.array([[-length, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, rear, 0.0], *arc, [-length, front, 0.0]])
        T = translation(0, (y0 + y1) / 2, 0) @ _PROFILE  # profile (x, z) in local (x, y), extruded along y
        prims.append(extrusion([loop], abs(y1 - y0), pose=T, role="cap"))
    ys = [v for s in strips for v in s[:2]]
    top = np.array([[-length - 1e-4, min(ys), 0.0], [-0.5 * length, max(ys), max(s[3] for s in strips) + sag]])
    cap = Region(("cap",), top)
    return Part("button", "mouse_button", prims, regions={"press": cap, "push": cap}, actionable="slider_button")


def profile_top(length: float, front: float, rear: float, sag: float, x: float) -> float:
    """Height of a :func:`main_button` strip's top at ``x`` (in [-length, 0]): the arc
    through (-length, front) and (0, rear) bulging ``sag`` over its chord."""
    (xa, za), (xb, zb) = (-length, front), (0.0, rear)
    c = math.hypot(xb - xa, zb - za)
    r = (c * c / 4 + sag * sag) / (2 * sag)
    mx, mz = (xa + xb) / 2, (za + zb) / 2
    nx, nz = -(zb - za) / c, (xb - xa) / c  # the chord's upward normal
    cx, cz = mx - nx * (r - sag), mz - nz * (r - sag)
    return cz + math.sqrt(max(r * r - (x - cx) ** 2, 0.0))


def plain_wheel(p, radius: float, width: float) -> Part:
    """Scroll wheel: a rubber-tyred cylinder."""
    return Part("wheel", "plain_wheel", [cylinder(radius, width, _AXLE_Y, role="tyre")],
                regions={"rotate": Region(("tyre",))}, actionable="hinge_knob")


def ribbed_wheel(p, radius: float, width: float) -> Part:
    """Scroll wheel with a ribbed (polygonal) tread on a round hub."""
    n = p.integers("ribs", 12, 16)
    prims = [prism(radius, width, n, _AXLE_Y, role="tyre"),
             cylinder(0.8 * radius, width * 1.0, _AXLE_Y, role="hub")]
    return Part("wheel", "ribbed_wheel", prims, regions={"rotate": Region(("tyre",))}, actionable="hinge_knob")


def tyre_wheel(p, radius: float, width: float) -> Part:
    """Scroll wheel: a hub with a round rubber tyre (a torus) on its rim."""
    r = min(width / 2, 0.3 * radius)
    prims = [cylinder(radius - r, width, _AXLE_Y, role="hub"), torus(radius - r, r, pose=_AXLE_Y, role="tyre")]
    return Part("wheel", "tyre_wheel", prims, regions={"rotate": Region(("tyre",))}, actionable="hinge_knob")


WHEELS = {plain_wheel: 1.0, ribbed_wheel: 1.5, tyre_wheel: 1.0}
