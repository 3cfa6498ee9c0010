"""Lamp parts: turned bases and bodies, shades (lathe shells), bulbs, harps, arm links.

Frames (metres, +z up, the front is -x):
- bases and bodies (``disc_base``, ``domed_base``, ``square_base``; ``vase_body``,
  ``column_body``, ``candlestick_body``): origin at the centre of the bottom face;
  anchors ``top`` (centre of the top face), ``radius`` (bases: the largest radius;
  bodies: the top's) and, on bases, ``ledge`` (radius, 0, height) of a flat ring
  where a switch can stand;
- shades (``drum_shade``, ``empire_shade``, ``bell_shade``): thin shells of
  revolution about z, origin at the centre of the bottom rim, open at both ends
  (table and floor lamps) or, for the arm lamps' reflectors (``cone_head``,
  ``dome_head``), origin at the centre of the closed top, opening along -z;
  anchors ``top`` / ``bottom`` and ``top_radius`` / ``bottom_radius`` (inner);
- ``bulb``: origin at the base of its neck, the glass above it along +z (below it
  along -z when ``down``);
- ``arm_link``: a rod of ``length`` along +z from a knuckle on the y axis at the
  origin to a knuckle at (0, 0, length); ``fork`` puts two parallel tines either side
  of y = 0 (a fork straddling the next link's single rod).
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cylinder, frustum, ring, sphere
from artipg.geometry.lathe import lathe
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import rot_x, translation
from artipg.model.part import Part, Region

_ALONG_Y = rot_x(-math.pi / 2)  # local z -> +y
_LIFT = Region()


# ---------------------------------------------------------------- bases

def disc_base(p, radius: float) -> Part:
    """Flat round base with a bevelled top edge."""
    h = p.uniform("height", 0.012, 0.03)
    prim = frustum(radius, p.uniform("bevel", 0.85, 0.97) * radius, h, translation(0, 0, h / 2), role="base")
    return Part("base", "disc_base", [prim], anchors={"top": (0.0, 0.0, h), "radius": (radius, 0, 0),
                                                      "ledge": (0.65 * radius, 0.0, h)},
                regions={"lift": _LIFT})


def domed_base(p, radius: float) -> Part:
    """Turned round base: a rim and a dome rising to the stem (a lathe profile)."""
    h = p.uniform("height", 0.015, 0.03)
    hd = p.uniform("dome", 0.01, 0.03)
    rs = p.uniform("stem_ratio", 0.2, 0.3) * radius
    loop = [[0.0, 0.0, 0.0], [radius, 0.0, 0.0], [radius, h, 0.0], [0.6 * radius, h, p.uniform("bulge", 0.1, 0.25)],
            [rs, h + hd, 0.0], [0.0, h + hd, 0.0]]
    return Part("base", "domed_base", [lathe(loop, role="base")], anchors={"top": (0.0, 0.0, h + hd),
                                                                          "radius": (radius, 0, 0),
                                                                          "ledge": (0.8 * radius, 0.0, h)},
                regions={"lift": _LIFT})


def square_base(p, radius: float) -> Part:
    """Square block base with rounded edges (``radius`` is half its side)."""
    h = p.uniform("height", 0.015, 0.035)
    prim = rounded_box(2 * radius, 2 * radius, h, min(0.004, h / 2 - 1e-4), translation(0, 0, h / 2), role="base")
    return Part("base", "square_base", [prim], anchors={"top": (0.0, 0.0, h), "radius": (radius, 0, 0),
                                                        "ledge": (0.65 * radius, 0.0, h)},
                regions={"lift": _LIFT})


BASES = {disc_base: 2.0, domed_base: 2.0, square_base: 1.0}


# ---------------------------------------------------------------- table-lamp bodies

def _body(template, loop, h, r_top) -> Part:
    return Part("body", template, [lathe(loop, role="body")], anchors={"top": (0.0, 0.0, h), "radius": (r_top, 0, 0)},
                regions={"lift": Region(), "grasp": Region()})


def vase_body(p, height: float, radius: float) -> Part:
    """Bulging vase (ginger jar): a foot, a belly arc and a short neck."""
    rf = p.uniform("foot", 0.5, 0.7) * radius
    rn = p.uniform("neck", 0.25, 0.4) * radius
    hn = p.uniform("neck_height", 0.04, 0.08) * height
    b = p.uniform("belly", 0.3, 0.45)
    loop = [[0.0, 0.0, 0.0], [rf, 0.0, b], [rn, height - hn, 0.0], [rn, height, 0.0], [0.0, height, 0.0]]
    return _body("vase_body", loop, height, rn)


def column_body(p, height: float, radius: float) -> Part:
    """Straight or slightly tapered column."""
    r0 = p.uniform("bottom", 0.5, 0.8) * radius
    r1 = p.uniform("taper", 0.7, 1.0) * r0
    return _body("column_body", [[0.0, 0.0, 0.0], [r0, 0.0, 0.0], [r1, height, 0.0], [0.0, height, 0.0]], height, r1)


def candlestick_body(p, height: float, radius: float) -> Part:
    """Thin turned stem with a knot (a ball) a third of the way up."""
    rs = min(p.uniform("stem", 0.12, 0.2) * radius, 0.018)
    rk = p.uniform("knot", 1.8, 2.6) * rs
    zk = max(p.uniform("knot_height", 0.25, 0.45) * height, rk + 0.01)  # the ball clears the foot
    hf = p.uniform("foot", 0.06, 0.12) * height
    prims = [frustum(min(2.2 * rs, radius), rs, hf, translation(0, 0, hf / 2), role="body"),
             cylinder(rs, height, translation(0, 0, height / 2), role="body"),
             sphere(rk, pose=translation(0, 0, zk), role="body")]
    return Part("body", "candlestick_body", prims, anchors={"top": (0.0, 0.0, height), "radius": (rs, 0, 0)},
                regions={"lift": Region(), "grasp": Region()})


BODIES = {vase_body: 2.0, column_body: 2.0, candlestick_body: 1.0}


# ---------------------------------------------------------------- shades (open shells)

def _shell(template, r_bot: float, r_top: float, h: float, t: float, bulge: float = 0.0) -> Part:
    """Open shell from radius ``r_bot`` at z = 0 to ``r_top`` at ``h`` (outer radii), wall ``t``."""
    if bulge == 0.0:
        prim = ring(r_bot, r_bot - t, h, pose=translation(0, 0, h / 2), taper=r_top - r_bot, role="shade")
    else:
        loop = [[r_bot - t, 0.0, 0.0], [r_bot, 0.0, bulge], [r_top, h, 0.0], [r_top - t, h, -bulge]]
        prim = lathe(loop, role="shade")
    anchors = {"top": (0.0, 0.0, h), "bottom": (0.0, 0.0, 0.0), "top_radius": (r_top - t, 0.0, 0.0),
               "bottom_radius": (r_bot - t, 0.0, 0.0)}
    return Part("shade", template, [prim], anchors=anchors,
                regions={"lift": Region(), "grasp": Region()})


def drum_shade(p, radius: float, height: float) -> Part:
    """Drum: a straight cylinder of fabric."""
    return _shell("drum_shade", radius, radius, height, p.uniform("wall", 0.0015, 0.003))


def empire_shade(p, radius: float, height: float) -> Part:
    """Empire: a truncated cone, wide at the bottom."""
    return _shell("empire_shade", radius, p.uniform("top_ratio", 0.5, 0.75) * radius, height,
                  p.uniform("wall", 0.0015, 0.003))


def bell_shade(p, radius: float, height: float) -> Part:
    """Bell: the cone's side curved outwards (a lathe arc)."""
    return _shell("bell_shade", radius, p.uniform("top_ratio", 0.45, 0.65) * radius, height,
                  p.uniform("wall", 0.0015, 0.003), p.uniform("flare", 0.08, 0.18))


SHADES = {drum_shade: 2.0, empire_shade: 2.0, bell_shade: 1.0}


def _head(template, loop, h, r_open, r_top) -> Part:
    return Part("shade", template, [lathe(loop, role="shade")],
                anchors={"top": (0.0, 0.0, 0.0), "bottom": (0.0, 0.0, -h), "bottom_radius": (r_open, 0, 0),
                         "top_radius": (r_top, 0, 0)},
                regions={"grasp": Region(), "push": Region(), "rotate": Region()})


def cone_head(p, radius: float) -> Part:
    """Conical reflector with a closed top, opening downwards (origin at the top centre)."""
    h = p.uniform("height", 0.9, 1.3) * radius
    rt = p.uniform("top", 0.2, 0.35) * radius
    t = p.uniform("wall", 0.0012, 0.002)
    loop = [[0.0, 0.0, 0.0], [0.0, -t, 0.0], [rt - t, -t, 0.0], [radius - t, -h, 0.0], [radius, -h, 0.0],
            [rt, 0.0, 0.0]]
    return _head("cone_head", loop, h, radius - t, rt)


def dome_head(p, radius: float) -> Part:
    """Dome reflector: a curved bell with a closed top, opening downwards."""
    h = p.uniform("height", 0.6, 0.9) * radius
    rt = p.uniform("top", 0.25, 0.4) * radius
    t = p.uniform("wall", 0.0012, 0.002)
    b = p.uniform("curve", 0.12, 0.22)
    loop = [[0.0, 0.0, 0.0], [0.0, -t, 0.0], [rt - t, -t, -b], [radius - t, -h, 0.0], [radius, -h, b],
            [rt, 0.0, 0.0]]
    return _head("dome_head", loop, h, radius - t, rt)


HEADS = {cone_head: 1.0, dome_head: 1.0}


def bulb(p, radius: float, down: bool = False) -> Part:
    """A bulb: a neck (the screw base) and a glass ball; origin at the neck's base."""
    rn = 0.55 * radius
    hn = p.uniform("neck", 0.6, 0.9) * radius
    s = -1.0 if down else 1.0
    prims = [cylinder(rn, hn, translation(0, 0, s * hn / 2), role="neck"),
             sphere(radius, pose=translation(0, 0, s * (hn + 0.85 * radius)), role="glass")]
    return Part("bulb", "bulb", prims, anchors={"tip": (0.0, 0.0, s * (hn + 1.85 * radius))})


def arm_link(p, length: float, knuckle: float, width: float, fork: float | None = None) -> Part:
    """An arm link along +z from the y axis at the origin to (0, 0, ``length``).

    Single rod: a bar ``width`` thick (y) with knuckle discs along y at both ends.
    ``fork`` (the gap between the tines, y): two tines of thickness ``width`` either
    side of it, each with its end discs.
    """
    bx = 1.2 * knuckle
    if fork is None:
        ys = (0.0,)
    else:
        ys = (-(fork / 2 + width / 2), fork / 2 + width / 2)
    prims = []
    for y in ys:
        prims.append(cuboid(bx, width, length, translation(0, y, length / 2), role="rod"))
        prims += [cylinder(knuckle, width, translation(0, y, z) @ _ALONG_Y, role="knuckle") for z in (0.0, length)]
    return Part("arm", "arm_link", prims, anchors={"end": (0.0, 0.0, length)},
                regions={"grasp": Region(("rod",)), "push": Region(("rod",))})
