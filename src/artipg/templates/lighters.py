"""Lighter parts: flip-top case, lid and chimney, disposable-lighter body, hood and gas
lever, utility-lighter handle, trigger, lock and nozzle, and the flint wheels.

Frames (metres):
- flip-top case: the bottom case standing on z = 0, ``width`` along y, ``depth``
  along x, its top at z = ``height``; the insert's chimney rises above it; the
  hinge axis (+x) runs along the +y side at the case top (anchor ``hinge``).
- lid: origin on the hinge axis, the lid a box open at the bottom reaching from
  y = -``reach`` to y = -``gap`` (towards the case) and up to z = ``height``.
- wheel: origin on its axle (local +y), centred, ``width`` long along it.
- disposable body: standing on z = 0, its top face at z = ``height``, centred.
- utility handle: lying along x from x = 0 (front) to ``length`` (back), its
  bottom on z = 0, with a trigger opening at the front bottom; nozzle and collar
  along -x from their root on the handle's front face.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, frustum, prism, rect_ring, ring
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.levers import top_grasp

_ALONG_Y = Placer(rot_x(-math.pi / 2))  # local z -> +y
_ALONG_X = Placer(rot_y(math.pi / 2))   # local z -> +x
_XZ = rot_x(math.pi / 2)                # outline (x, y) -> object (x, z), extruded along y


# ---------------------------------------------------------------- flint wheels
def knurled_wheel(p, radius: float, width: float) -> Part:
    """A finely knurled wheel (16-sided prism) on its axle."""
    return Part("wheel", "knurled_wheel", [prism(radius, width, 16, _ALONG_Y.matrix, role="wheel")],
                regions={"rotate": Region(("wheel",))})


def coarse_wheel(p, radius: float, width: float) -> Part:
    """A coarsely ridged wheel (10-sided prism)."""
    return Part("wheel", "coarse_wheel", [prism(radius, width, 10, _ALONG_Y.matrix, role="wheel")],
                regions={"rotate": Region(("wheel",))})


def twin_wheel(p, radius: float, width: float) -> Part:
    """Two knurled rims on a thinner hub (the flint rubs between them)."""
    rim = p.uniform("rim", 0.3, 0.4) * width
    prims = [prism(radius, rim, 16, _ALONG_Y.at(0.0, s * (width - rim) / 2, 0.0), role="wheel") for s in (1.0, -1.0)]
    prims.append(cylinder(0.7 * radius, width - 2 * rim + 0.0002, _ALONG_Y.matrix, role="hub"))
    return Part("wheel", "twin_wheel", prims, regions={"rotate": Region(("wheel",))})


WHEELS = {knurled_wheel: 2.0, twin_wheel: 1.5, coarse_wheel: 1.0}


# ---------------------------------------------------------------- flip-top
def flip_case(p, width: float, depth: float, height: float, chimney: tuple, hinge_r: float, hinge_y: float,
              ears: tuple) -> Part:
    """Bottom case, the insert's chimney (``chimney`` = (y0, y1, top, wall): its span
    across y, its top and wall thickness), the ears holding the wheel (``ears`` =
    (half gap along x, y, z top, half length along y)) and the hinge's case knuckle."""
    r = min(0.2 * depth, 0.003)
    y0, y1, top, wall = chimney
    d = depth - 2 * 0.002  # inside the lid's front and back walls
    prims = [rounded_box(depth, width, height, r, translation(0.0, 0.0, height / 2), role="case"),
             rect_ring(d, y1 - y0, top - height, d - 2 * wall, y1 - y0 - 2 * wall,
                       translation(0.0, 0.5 * (y0 + y1), 0.5 * (height + top)), role="chimney")]
    prims.append(cylinder(hinge_r, 0.4 * depth, _ALONG_X.at(0.0, hinge_y, height), role="knuckle"))
    gx, ye, ze, hy = ears
    te = 0.0015  # thick enough for the simulators' collision margins
    prims += [cuboid_between((gx, ye - hy, height), (gx + te, ye + hy, ze), role="ear"),
              cuboid_between((-gx - te, ye - hy, height), (-gx, ye + hy, ze), role="ear")]
    return Part("body", "flip_case", prims, anchors={"hinge": (0.0, hinge_y, height)},
                regions={"grasp": Region(("case",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, 0.5 * height, width + 0.02, "y", (0.0, 0.0, 0.0)))


def flip_lid(p, width: float, depth: float, height: float, wall: float, gap: float, hinge_r: float) -> Part:
    """Hollow lid (top and four walls, open at the bottom) hinged on the origin; its
    knuckles sit either side of the case's along x."""
    y0, y1 = -gap - width, -gap
    x0, x1 = -depth / 2, depth / 2
    prims = [cuboid_between((x0, y0, height - wall), (x1, y1, height), role="lid"),
             cuboid_between((x0, y0, 0.0), (x1, y0 + wall, height - wall), role="lid"),
             cuboid_between((x0, y1 - wall, 0.0), (x1, y1, height - wall), role="lid"),
             cuboid_between((x0, y0 + wall, 0.0), (x0 + wall, y1 - wall, height - wall), role="lid"),
             cuboid_between((x1 - wall, y0 + wall, 0.0), (x1, y1 - wall, height - wall), role="lid")]
    kl = 0.3 * depth - 0.0005
    for s in (1.0, -1.0):
        prims.append(cylinder(hinge_r, kl, _ALONG_X.at(s * (0.2 * depth + 0.0005 + kl / 2), 0.0, 0.0), role="knuckle"))
    g = Deferred.one(top_grasp, 0.0, y0 + 0.3 * width, height - wall / 2, depth + 0.02, "x", (0.0, 0.0, 1.0))
    return Part("lid", "flip_lid", prims, regions={"lift": Region(("lid",)), "grasp": Region(("lid",))},
                grasps=g, actionable="hinge_lid")


# ---------------------------------------------------------------- disposable
def oval_body(p, width: float, depth: float, height: float) -> Part:
    """An oval tank (a 16-gon stretched to ``depth`` x ``width``) standing on a flat
    foot plate (the bottom's flat; a box also gives the simulators a stable footprint)."""
    a = np.linspace(0.0, 2 * math.pi, 17)[:-1]
    loop = profile.polygon(np.column_stack([0.5 * depth * np.cos(a), 0.5 * width * np.sin(a)]))
    foot = 0.0006
    prims = [extrusion([loop], height - foot, pose=translation(0.0, 0.0, (height + foot) / 2), role="tank"),
             cuboid_between((-0.35 * depth, -0.35 * width, 0.0), (0.35 * depth, 0.35 * width, foot + 0.0002),
                            role="tank")]
    return Part("body", "oval_body", prims, regions={"grasp": Region(("tank",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, 0.5 * height, width + 0.02, "y", (0.0, 0.0, 0.0)))


def rounded_body(p, width: float, depth: float, height: float) -> Part:
    """A rounded rectangular tank, standing on a flat foot plate."""
    r = p.uniform("edge", 0.12, 0.25) * depth
    foot = 0.0006
    prims = [rounded_box(depth, width, height - foot, r, translation(0.0, 0.0, (height + foot) / 2), role="tank"),
             cuboid_between((-0.3 * depth, -0.3 * width, 0.0), (0.3 * depth, 0.3 * width, foot + 0.0002), role="tank")]
    return Part("body", "rounded_body", prims, regions={"grasp": Region(("tank",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, 0.5 * height, width + 0.02, "y", (0.0, 0.0, 0.0)))


TANKS = {oval_body: 2.0, rounded_body: 1.0}


def hood(p, x0: float, x1: float, inner: float, t: float, z0: float, z1: float) -> Part:
    """The steel hood round the wheel: two side plates (inner faces at y = +-``inner``)
    from x0 to x1 and z0 to z1, joined by a front plate."""
    prims = [cuboid_between((x0, -inner - t, z0), (x1, -inner, z1), role="hood"),
             cuboid_between((x0, inner, z0), (x1, inner + t, z1), role="hood")]
    prims.append(cuboid_between((x0 - t, -inner - t, z0), (x0, inner + t, 0.5 * (z0 + z1)), role="hood"))
    return Part("cover", "hood", prims)


def gas_lever(p, length: float, width: float, thickness: float) -> Part:
    """The gas lever's pad (x from 0 to ``length``, bottom on z = 0) with the nozzle
    hole's boss at its front; pressed down."""
    prims = [cuboid_between((0.0, -width / 2, 0.0), (length, width / 2, thickness), role="pad"),
             cylinder(0.2 * width, 0.6 * thickness, translation(0.25 * length, 0.0, thickness + 0.3 * thickness),
                      role="nozzle")]
    return Part("lever", "gas_lever", prims, regions={"press": Region(("pad",))}, actionable="slider_button")


# ---------------------------------------------------------------- utility
def utility_handle(p, length: float, width: float, height: float, front: float, trigger: tuple) -> Part:
    """Handle with a trigger opening at the front bottom, closed below by a guard
    bar; ``trigger`` = (x0, x1, z0, z1) the opening. Its top rises from ``front``
    high at the nose to ``height`` at 0.35 of its length and rounds off at the back."""
    x0, x1, z0, z1 = trigger
    w2 = width / 2
    side = profile.polygon([(0.0, z1), (length, z1), (length, 0.9 * height), (0.93 * length, height),
                            (0.35 * length, height), (0.0, front)])
    prims = [extrusion([side], width, pose=_XZ, role="grip"),
             cuboid_between((x1, -w2, 0.0), (length, w2, z1), role="grip"),
             cuboid_between((0.0, -w2, 0.0), (x0, w2, z1), role="guard"),
             cuboid_between((x0, -w2, 0.0), (x1, w2, z0), role="guard")]
    return Part("body", "utility_handle", prims, regions={"grasp": Region(("grip",))},
                grasps=Deferred.one(top_grasp, 0.6 * length, 0.0, 0.5 * height, width + 0.02, "y", (0.0, 0.0, 0.0)))


def nozzle(p, length: float, radius: float, wall: float) -> Part:
    """The long nozzle: a tube along -x from the origin with a flared tip."""
    tip = p.uniform("tip", 0.008, 0.015)
    prims = [ring(radius, radius - wall, length, pose=_ALONG_X.at(-length / 2, 0.0, 0.0), role="tube"),
             frustum(1.15 * radius, radius, tip, _ALONG_X.at(-length - tip / 2, 0.0, 0.0), role="tip")]
    return Part("nozzle", "nozzle", prims)


def collar(p, radius: float) -> Part:
    """The handle's plastic collar round the nozzle's root (along -x from the origin)."""
    c = p.uniform("collar", 0.01, 0.018)
    prims = [frustum(radius, p.uniform("collar_radius", 1.4, 1.8) * radius, c, _ALONG_X.at(-c / 2, 0.0, 0.0),
                     role="collar")]
    return Part("body", "nozzle_collar", prims)


def trigger(p, length: float, width: float, height: float) -> Part:
    """The trigger block (x from 0 to ``length``, bottom on z = 0), pulled back +x."""
    prims = [cuboid_between((0.0, -width / 2, 0.0), (length, width / 2, height), role="trigger")]
    return Part("button", "trigger", prims, regions={"press": Region(("trigger",)), "pull": Region(("trigger",))},
                actionable="slider_button")


def lock_slider(p, length: float, width: float, height: float) -> Part:
    """The child-lock slider on the handle's top (bottom on z = 0), pushed along +-x."""
    prims = [cuboid_between((-length / 2, -width / 2, 0.0), (length / 2, width / 2, height), role="slider")]
    return Part("switch", "lock_slider", prims, regions={"press": Region(("slider",)), "push": Region(("slider",))},
                actionable="slider_button")
