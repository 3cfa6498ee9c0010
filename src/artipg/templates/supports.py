"""Supports under a body: legs, plinths, casters and feet.

Frame: origin at the centre of the footprint on the floor (z = 0), +z up; the support
reaches up to ``height``, where the body's bottom rests. ``width`` (y) and ``depth``
(x) are the body's footprint the supports sit under.
"""

from __future__ import annotations

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum
from artipg.geometry.transforms import translation
from artipg.model.part import Part


def _corners(depth, width, inset):
    return [(sx * (depth / 2 - inset), sy * (width / 2 - inset)) for sx in (-1, 1) for sy in (-1, 1)]


def square_legs(p, depth: float, width: float, height: float) -> Part:
    """Four square legs at the corners."""
    s = p.uniform("leg_size", 0.025, 0.05)
    inset = s / 2 + p.uniform("inset", 0.0, 0.03)
    prims = [cuboid(s, s, height, translation(x, y, height / 2), role="leg") for x, y in _corners(depth, width, inset)]
    return Part("leg", "square_legs", prims)


def round_legs(p, depth: float, width: float, height: float) -> Part:
    """Four round legs at the corners."""
    r = p.uniform("leg_radius", 0.012, 0.025)
    inset = r + p.uniform("inset", 0.0, 0.03)
    prims = [cylinder(r, height, translation(x, y, height / 2), role="leg") for x, y in _corners(depth, width, inset)]
    return Part("leg", "round_legs", prims)


def tapered_legs(p, depth: float, width: float, height: float) -> Part:
    """Four tapered (frustum) legs, thin end on the floor (mid-century style)."""
    r = p.uniform("leg_radius", 0.015, 0.025)
    tip = p.uniform("tip_ratio", 0.4, 0.8) * r
    inset = r + p.uniform("inset", 0.0, 0.03)
    prims = [frustum(tip, r, height, translation(x, y, height / 2), role="leg") for x, y in _corners(depth, width, inset)]
    return Part("leg", "tapered_legs", prims)


def plinth(p, depth: float, width: float, height: float) -> Part:
    """Recessed kick plinth: a closed box set back from the front."""
    setback = p.uniform("setback", 0.02, 0.06)
    side = p.uniform("side_inset", 0.0, 0.02)
    return Part("base", "plinth", [cuboid_between((-depth / 2 + setback, -width / 2 + side, 0.0),
                                                  (depth / 2 - 0.01, width / 2 - side, height), role="plinth")])


def bun_feet(p, depth: float, width: float, height: float) -> Part:
    """Four short round feet."""
    r = p.uniform("foot_radius", 0.02, 0.035)
    inset = r + p.uniform("inset", 0.005, 0.03)
    prims = [frustum(r * 0.8, r, height, translation(x, y, height / 2), role="leg") for x, y in _corners(depth, width, inset)]
    return Part("leg", "bun_feet", prims)


SUPPORTS = {square_legs: 1.0, round_legs: 1.0, tapered_legs: 1.0, plinth: 2.0, bun_feet: 1.0}
