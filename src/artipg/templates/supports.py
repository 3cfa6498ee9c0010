"""Supports under a body: legs, plinths, casters and feet.

Frame: origin at the centre of the footprint on the floor (z = 0), +z up; the support
reaches up to ``height``, where the body's bottom rests. ``width`` (y) and ``depth``
(x) are the body's footprint the supports sit under.
"""

from __future__ import annotations

from artipg.geometry import cylinder, frustum
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.templates.detail import edge_radius, rbox, rbox_between


def _corners(depth, width, inset):
    return [(sx * (depth / 2 - inset), sy * (width / 2 - inset)) for sx in (-1, 1) for sy in (-1, 1)]


def square_legs(p, depth: float, width: float, height: float) -> Part:
    """Four square legs at the corners."""
    s = p.uniform("leg_size", 0.025, 0.05)
    inset = s / 2 + p.uniform("inset", 0.0, 0.03)
    r = edge_radius(p, s)
    prims = [rbox(s, s, height, r, translation(x, y, height / 2), role="leg")
             for x, y in _corners(depth, width, inset)]
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


#: Plinth styles (a detail choice): a plain box, or a box under a moulded band (a
#: rounded strip along the plinth's top, standing forward of it).
PLINTHS = {"plain": 1.0, "moulded": 1.0}


def plinth(p, depth: float, width: float, height: float) -> Part:
    """Recessed kick plinth: a closed box set back from the front; with detail its
    edges are rounded and it may carry a moulded band (:data:`PLINTHS`) that stays
    within the footprint and below ``height``."""
    setback = p.uniform("setback", 0.02, 0.06)
    side = p.uniform("side_inset", 0.0, 0.02)
    lo, hi = (-depth / 2 + setback, -width / 2 + side, 0.0), (depth / 2 - 0.01, width / 2 - side, height)
    r = edge_radius(p, min(hi[0] - lo[0], hi[1] - lo[1], height))
    prims = [rbox_between(lo, hi, r, role="plinth")]
    if p.detail_choice("style", PLINTHS, "plain") == "moulded":
        bh = min(p.detail_uniform("band_height", 0.012, 0.03), 0.5 * height)
        reach = p.detail_uniform("band_reach", 0.4, 0.8) * (setback - 0.002)
        band_lo = (lo[0] - reach, lo[1], height - bh)
        rb = min(0.45 * reach, 0.3 * bh, 0.004) if reach > 0 else 0.0
        prims.append(rbox_between(band_lo, (lo[0] + 0.01, hi[1], height), rb, role="plinth"))
    return Part("base", "plinth", prims)


def bun_feet(p, depth: float, width: float, height: float) -> Part:
    """Four short round feet."""
    r = p.uniform("foot_radius", 0.02, 0.035)
    inset = r + p.uniform("inset", 0.005, 0.03)
    prims = [frustum(r * 0.8, r, height, translation(x, y, height / 2), role="leg") for x, y in _corners(depth, width, inset)]
    return Part("leg", "bun_feet", prims)


SUPPORTS = {square_legs: 1.0, round_legs: 1.0, tapered_legs: 1.0, plinth: 2.0, bun_feet: 1.0}
