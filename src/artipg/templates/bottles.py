"""Bottle bodies: solids of revolution (or prisms) ending in a hollow neck.

Frame: origin at the centre of the base on z = 0, axis +z. Every body ends in a
neck, a ring of outer radius ``neck_r`` and ``neck_h`` tall whose bore
(``bore_edge``) goes down to the shoulder, so stoppers and pump stems can sit inside
it and caps around it. Anchors: ``neck_top`` (0, 0, top), ``neck_edge`` (neck_r, 0,
top), ``bore_edge`` (bore radius, 0, top), ``neck_base`` (0, 0, top - neck_h).
"""

from __future__ import annotations

import math

from artipg.geometry import cylinder, frustum, prism, ring, sphere, torus
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region


_SIDES = {4: 3.0, 6: 1.0, 8: 1.0}  # polygon sides of square bodies


def _neck(p, z0, neck_r, neck_h, lip: bool):
    t = p.uniform("neck_wall", 0.0018, 0.0032)
    prims = [ring(neck_r, neck_r - t, neck_h, pose=translation(0, 0, z0 + neck_h / 2), role="neck")]
    if lip:  # tamper-evidence / support ring at the neck's base
        prims.append(torus(neck_r + 0.0004, 0.001, pose=translation(0, 0, z0 + 0.0016), role="neck"))
    anchors = {"neck_top": (0.0, 0.0, z0 + neck_h), "neck_edge": (neck_r, 0.0, z0 + neck_h),
               "bore_edge": (neck_r - t, 0.0, z0 + neck_h), "neck_base": (0.0, 0.0, z0)}
    return prims, anchors


def _body(name, prims, neck):
    return Part("body", name, prims + neck[0], anchors=neck[1],
                regions={"grasp": Region(("wall",)), "lift": Region(("wall",))})


def round_body(p, radius: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Cylinder with a conical shoulder (water bottles, Burgundy-style wine bottles)."""
    hs = p.uniform("shoulder", 0.12, 0.35) * (height - neck_h)
    hb = height - neck_h - hs
    prims = [cylinder(radius, hb, translation(0, 0, hb / 2), role="wall"),
             frustum(radius, neck_r, hs, translation(0, 0, hb + hs / 2), role="shoulder")]
    return _body("round_body", prims, _neck(p, hb + hs, neck_r, neck_h, p.flag("support_ring", 0.5)))


def shouldered_body(p, radius: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Cylinder with a rounded (spherical) shoulder (Bordeaux-style bottles)."""
    hs = math.sqrt(radius * radius - neck_r * neck_r)
    hb = max(height - neck_h - hs, 0.3 * height)
    prims = [cylinder(radius, hb, translation(0, 0, hb / 2), role="wall"),
             sphere(radius, 0.0, hs, translation(0, 0, hb), role="shoulder")]
    return _body("shouldered_body", prims, _neck(p, hb + hs, neck_r, neck_h, False))


def square_body(p, radius: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Prismatic body (square, hexagonal or octagonal) with a short conical shoulder;
    ``radius`` is the polygon's circumradius."""
    n = p.choice("sides", _SIDES)
    apothem = radius * math.cos(math.pi / n)
    hs = p.uniform("shoulder", 0.08, 0.2) * (height - neck_h)
    hb = height - neck_h - hs
    prims = [prism(radius, hb, n, translation(0, 0, hb / 2), role="wall"),
             frustum(apothem, neck_r, hs, translation(0, 0, hb + hs / 2), role="shoulder")]
    return _body("square_body", prims, _neck(p, hb + hs, neck_r, neck_h, False))


def flask_body(p, radius: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Round flask or decanter: a sphere flattened at the bottom, then the neck
    (its height follows from ``radius``)."""
    lo = p.uniform("flat_bottom", 0.55, 0.85) * radius
    hi = math.sqrt(radius * radius - neck_r * neck_r)
    prims = [sphere(radius, -lo, hi, translation(0, 0, lo), role="wall")]
    return _body("flask_body", prims, _neck(p, lo + hi, neck_r, neck_h, False))


BODIES = {round_body: 3.0, shouldered_body: 2.0, square_body: 1.5, flask_body: 1.0}
