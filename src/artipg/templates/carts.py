"""Cart parts: wire walls, tube frames, decks, plates, push handles and casters.

Frames: walls, frames and decks are built in the object frame (front -x, z up, the
floor z = 0) from corner coordinates given by the caller. A caster's origin is its
wheel's axle centre; :func:`mount_caster` puts it on a swivel (continuous about z
through the axle) or fixes it, and turns the wheel on its axle (continuous about y).
A hinged plate spans local x in [-length, 0] from its hinge line (local y), local z in
[-thickness, 0] (the hinge on its top edge), so it folds up about +y.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, ring, torus
from artipg.geometry.transforms import rot_x, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.luggage import GAP, fork, wheel

_AXLE_Y = rot_x(math.pi / 2)  # a lathe's z along y


def bar(lo, hi, role: str = "wire"):
    """A square bar between corners ``lo`` and ``hi`` (object frame, metres)."""
    return cuboid_between(lo, hi, role=role)


def wire_wall(p, semantic: str, axis: int, x0: float, x1: float, across: float, z0: float, z1: float,
              wire: float, n: int) -> Part:
    """A wire wall in a vertical plane: a frame of square bars ``wire`` thick from
    ``x0`` to ``x1`` along object axis ``axis`` (0: x, 1: y) at ``across`` on the other
    horizontal axis, from z0 to z1, with ``n`` evenly spaced vertical wires inside."""
    o = 1 - axis
    h = wire / 2

    def box(a0, a1, b0, b1):
        lo, hi = [0.0, 0.0, b0], [0.0, 0.0, b1]
        lo[axis], hi[axis] = a0, a1
        lo[o], hi[o] = across - h, across + h
        return bar(lo, hi)
    prims = [box(x0, x1, z0, z0 + wire), box(x0, x1, z1 - wire, z1),
             box(x0, x0 + wire, z0, z1), box(x1 - wire, x1, z0, z1)]
    for i in range(1, n + 1):
        a = x0 + (x1 - x0) * i / (n + 1)
        prims.append(box(a - h * 0.6, a + h * 0.6, z0 + wire, z1 - wire))
    return Part(semantic, "wire_wall", prims)


def tube_frame(p, semantic: str, segments, radius: float, wall: float) -> Part:
    """Hollow round tubes (``wall`` thick, ``radius`` outer) along the axis-aligned
    ``segments`` [(start (3,), end (3,)), ...] of the object frame."""
    prims = []
    for a, b in segments:
        a, b = np.asarray(a, float), np.asarray(b, float)
        d = b - a
        k = int(np.argmax(np.abs(d)))
        L = float(abs(d[k]))
        c = (a + b) / 2
        T = translation(*c)
        if k == 0:
            T = T @ np.array([[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1.0]])
        elif k == 1:
            T = T @ _AXLE_Y
        prims.append(ring(radius, radius - wall, L, pose=T, role="tube"))
    return Part(semantic, "tube_frame", prims)


def _grip_grasps(x: float, y0: float, y1: float, z: float, r: float) -> list:
    """Grasps on a horizontal grip bar along y: approaching from +x, jaws closing
    along z, at three points of the bar."""
    out = []
    for t in (0.25, 0.5, 0.75):
        T = np.array([[0.0, 0.0, -1.0, x], [-1.0, 0.0, 0.0, y0 + (y1 - y0) * t], [0.0, 1.0, 0.0, z],
                      [0.0, 0.0, 0.0, 1.0]])
        out.append(Grasp(T, 2 * r + 0.02))
    return out


def grip_bar(p, x: float, y0: float, y1: float, z: float, radius: float, actionable: str = "line_fixed_handle") -> Part:
    """A push grip: a round bar of ``radius`` along y from y0 to y1 at (x, z), with
    grasps (approach from +x)."""
    T = translation(x, (y0 + y1) / 2, z) @ _AXLE_Y
    grip = Region(("grip",))
    regions = {"grasp": grip, "pull": grip, "push": grip}
    return Part("handle", "grip_bar", [cylinder(radius, y1 - y0, T, role="grip")], regions=regions,
                grasps=Deferred(_grip_grasps, x, y0, y1, z, radius), actionable=actionable)


def deck(p, semantic: str, x0: float, x1: float, width: float, z0: float, z1: float, lip: float) -> Part:
    """A platform deck from x0 to x1, ``width`` wide, z0 to z1, with a raised ``lip``
    (metres) round its top edge."""
    W2 = width / 2
    prims = [cuboid_between((x0, -W2, z0), (x1, W2, z1), role="deck")]
    if lip > 0:
        e = 0.012
        prims += [cuboid_between((x0, -W2, z1), (x1, -W2 + e, z1 + lip), role="lip"),
                  cuboid_between((x0, W2 - e, z1), (x1, W2, z1 + lip), role="lip")]
    return Part(semantic, "deck", prims, regions={"push": Region(("deck",)), "lift": Region(("deck",))})


def hinged_plate(p, semantic: str, length: float, width: float, thickness: float, actionable: str = "none") -> Part:
    """A plate hinged on its top edge along local y (see the module docstring)."""
    prim = cuboid_between((-length, -width / 2, -thickness), (0.0, width / 2, 0.0), role="plate")
    face = Region(("plate",))
    regions = {"lift": face, "push": face, "pull": face}
    return Part(semantic, "hinged_plate", [prim], regions=regions, actionable=actionable)


def solid_wheel(p, radius: float, width: float) -> Part:
    """A solid rubber wheel: a cylinder ``radius`` x ``width`` along y (origin at its centre)."""
    return wheel(p, radius, width)


def tyred_wheel(p, radius: float, width: float) -> Part:
    """A hub with a round tyre (a torus) on its rim, within ``radius`` and ``width``."""
    r = min(width / 2, 0.3 * radius)
    return Part("wheel", "tyred_wheel", [cylinder(radius - r, width, _AXLE_Y, role="hub"),
                                         torus(radius - r, r, pose=_AXLE_Y, role="tyre")])


def disc_wheel(p, radius: float, width: float) -> Part:
    """A narrower flat tyre (a ring) round a hub ``width`` wide (its faces carry the
    wheel on its axle or fork), within ``radius``."""
    ri = p.uniform("rim_ratio", 0.55, 0.7) * radius
    return Part("wheel", "disc_wheel", [ring(radius, ri, p.uniform("tyre_ratio", 0.6, 0.9) * width, pose=_AXLE_Y,
                                             role="tyre"),
                                        cylinder(ri + 0.001, width, _AXLE_Y, role="hub")])


WHEELS = {solid_wheel: 1.0, tyred_wheel: 1.5, disc_wheel: 1.0}
#: Two-wheel trucks stand on their wheels and plate alone: flat-tread wheels only.
TRUCK_WHEELS = {solid_wheel: 1.0, disc_wheel: 1.5}


def mount_caster(p, builder, parent, x: float, y: float, radius: float, width: float, plate: float, drop: float,
                 swivel: bool, tmpl=solid_wheel) -> None:
    """A caster under ``parent`` with its axle at (x, y, ``radius``): a fork reaching
    ``drop`` above the axle (see :func:`artipg.templates.luggage.fork`) on a swivel
    (continuous about z) or fixed, and a wheel (template ``tmpl``) continuous about its
    axle (y)."""
    fk = fork(p, radius, width, drop, plate)
    origin = translation(x, y, radius)
    if swivel:
        link = builder.create_link("caster", parent)
        link.set_joint("continuous", origin, axis=(0.0, 0.0, 1.0))
        link.add(fk)
        parent, origin = link, np.eye(4)
    else:
        parent.add(fk, origin)
    w = builder.create_link("wheel", parent)
    w.set_joint("continuous", origin, axis=(0.0, 1.0, 0.0))
    w.add(tmpl(p, radius, width))


def caster_reach(radius: float, width: float, plate: float) -> float:
    """Horizontal radius (metres) a swivel caster's fork and wheel sweep about its axis."""
    return math.hypot(radius, width / 2 + GAP + plate)
