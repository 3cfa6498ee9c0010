"""Body (shell) templates: the static housing that other parts attach to.

Frame conventions:
- box bodies (``carcass``): origin at the centre of the outer box, front face at
  x = -depth/2, anchors ``cavity_lo``/``cavity_hi`` give the inner opening's corners;
- vessel bodies (``cylindrical_shell``, ``prism_shell``, ``tapered_shell``): origin at
  the centre of the base, axis +z, anchor ``rim`` (0, 0, height); ``rim_radius`` is
  exposed as the anchor ``rim_edge`` (rim_radius, 0, height) so lids and handles can
  follow the body.
"""

from __future__ import annotations

import math


from artipg.geometry import cuboid_between, cylinder, frustum, prism
from artipg.geometry.transforms import rot_z, translation
from artipg.model.part import Part, Region
from artipg.templates.detail import edge_radius, lip_style, lipped_wall, rbox_between


def carcass(p, depth: float, width: float, height: float, semantic: str = "body",
            wall: float | None = None, back: float | None = None) -> Part:
    """Open-front box: back, two sides, top and bottom panels (with detail, the
    sides, top and bottom have rounded edges; the panels still meet face to face)."""
    w = p.uniform("wall", 0.015, 0.022, fixed=wall)
    b = p.uniform("back", 0.006, 0.012, fixed=back)
    D, W, H = depth / 2, width / 2, height / 2
    r = edge_radius(p, w)
    prims = [
        cuboid_between((D - b, -W + w, -H + w), (D, W - w, H - w), role="back"),
        rbox_between((-D, -W, -H), (D, -W + w, H), r, role="side"),
        rbox_between((-D, W - w, -H), (D, W, H), r, role="side"),
        rbox_between((-D, -W + w, -H), (D, W - w, -H + w), r, role="bottom"),
        rbox_between((-D, -W + w, H - w), (D, W - w, H), r, role="top"),
    ]
    return Part(semantic, "carcass", prims,
                anchors={"cavity_lo": (-D, -W + w, -H + w), "cavity_hi": (D - b, W - w, H - w),
                         "front": (-D, 0.0, 0.0), "top": (0.0, 0.0, H)})


def _vessel_anchors(r_rim: float, h: float) -> dict:
    return {"rim": (0.0, 0.0, h), "rim_edge": (r_rim, 0.0, h), "base": (0.0, 0.0, 0.0)}


def cylindrical_shell(p, radius: float, height: float, wall: float | None = None) -> Part:
    """Open cylinder (bucket, pot, can): a ring wall on a disc bottom."""
    t = p.uniform("wall", 0.002, 0.006, fixed=wall)
    bottom = max(t, p.uniform("bottom", 0.003, 0.01))
    prims = [cylinder(radius, bottom, translation(0, 0, bottom / 2), role="bottom"),
             *lipped_wall(radius, radius - t, height - bottom, bottom + (height - bottom) / 2, lip_style(p))]
    return Part("body", "cylindrical_shell", prims, anchors=_vessel_anchors(radius, height),
                regions={"lift": Region(("wall",))})


def tapered_shell(p, radius: float, height: float, taper: float | None = None, wall: float | None = None) -> Part:
    """Open frustum vessel, wider at the rim; ``radius`` is the rim radius."""
    t = p.uniform("wall", 0.002, 0.006, fixed=wall)
    tp = p.uniform("taper", 0.08, 0.25, fixed=taper) * radius
    bottom = max(t, p.uniform("bottom", 0.003, 0.01))
    r0 = radius - tp  # outer radius at the bottom
    hw = height - bottom
    prims = [frustum(r0, r0 + tp * bottom / height, bottom, translation(0, 0, bottom / 2), role="bottom"),
             *lipped_wall(r0 + tp * bottom / height, r0 + tp * bottom / height - t, hw, bottom + hw / 2, lip_style(p),
                          taper=tp * hw / height)]
    return Part("body", "tapered_shell", prims, anchors=_vessel_anchors(radius, height),
                regions={"lift": Region(("wall",))})


def prism_shell(p, radius: float, height: float, sides: int | None = None, wall: float | None = None) -> Part:
    """Open regular-polygon vessel: ``sides`` wall panels on a prism bottom.

    ``radius`` is the circumradius of the outer polygon.
    """
    n = p.integers("sides", 4, 8, fixed=sides)
    t = p.uniform("wall", 0.003, 0.008, fixed=wall)
    bottom = max(t, p.uniform("bottom", 0.003, 0.01))
    apothem = radius * math.cos(math.pi / n)
    side = 2 * radius * math.sin(math.pi / n)
    prims = [prism(radius, bottom, n, translation(0, 0, bottom / 2), role="bottom")]
    hw = height - bottom
    r = edge_radius(p, t, hi=0.5 * t)  # the panels' outer corners meet: only a small rounding
    for i in range(n):
        a = 2 * math.pi * (i + 1) / n  # direction of the i-th edge's midpoint
        # full-length panels with their outer faces on the polygon edges: they meet at
        # the outer corners and overlap slightly inside, leaving no gap
        T = rot_z(a) @ translation(apothem - t / 2, 0.0, bottom + hw / 2)
        prims.append(rbox_between((-t / 2, -side / 2, -hw / 2), (t / 2, side / 2, hw / 2), r,
                                  role="wall").placed(T))
    return Part("body", "prism_shell", prims, anchors=_vessel_anchors(apothem, height),
                regions={"lift": Region(("wall",))})


VESSELS = {cylindrical_shell: 3.0, tapered_shell: 2.0, prism_shell: 1.0}
