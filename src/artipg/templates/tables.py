"""Table parts: tops, aprons and table bases (pedestal column, trestle, panel ends).

Frames (metres, +z up, front faces -x):
- tops: origin at the centre of the underside, the top surface at z = thickness; the
  anchor ``apron`` = (a_x, a_y, 0) gives the half extents of the largest centred
  rectangle a frame (apron, legs, pedestals) may occupy under the top, inset by the
  drawn overhang;
- ``apron``: origin at the centre of its footprint on the underside of the top, the
  boards hang down to z = -height, the front board's outer face is at x = -depth/2;
- bases: origin on the floor under the centre of the top, reaching up to ``height``
  (the underside of the top).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, prism
from artipg.geometry.transforms import rot_z, translation
from artipg.model.part import Part, Region
from artipg.templates.detail import edge_profile, edge_radius, rbox, rounded_disc

_SQRT_HALF = math.sqrt(0.5)
_CROSS = (rot_z(math.pi / 4), rot_z(-math.pi / 4))  # the two bars of a cross foot


def _top(template, prims, ax, ay, t):
    top = ((-ax * 4, -ay * 4, t - 1e-4), (ax * 4, ay * 4, t + 1e-4))
    return Part("top", template, prims, anchors={"apron": (ax, ay, 0.0), "surface": (0.0, 0.0, t)},
                regions={"push": Region(("top",), np.array(top))})


def _overhang(p, depth, width):
    return min(p.uniform("overhang", 0.02, 0.1), 0.12 * min(depth, width))


def slab_top(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Rectangular board ``depth`` (x) by ``width`` (y)."""
    t = p.uniform("thickness", 0.02, 0.045, fixed=thickness)
    ov = _overhang(p, depth, width)
    r = edge_radius(p, t)
    return _top("slab_top", [rbox(depth, width, t, r, translation(0, 0, t / 2), role="top")],
                depth / 2 - ov, width / 2 - ov, t)


def racetrack_top(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Oval (stadium) board: a rectangle with half-round ends on the y sides."""
    t = p.uniform("thickness", 0.02, 0.045, fixed=thickness)
    width = max(width, depth * 1.2)
    ov = _overhang(p, depth, width)
    r = depth / 2
    prims = [cuboid(depth, width - depth, t, translation(0, 0, t / 2), role="top")]
    prims += [cylinder(r, t, translation(0, s * (width / 2 - r), t / 2), role="top") for s in (-1, 1)]
    # apron corner at 0.8 of the usable half depth, inside the end circles
    ax = 0.8 * (r - ov)
    return _top("racetrack_top", prims, ax, width / 2 - r + 0.6 * (r - ov), t)


def round_top(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Round board of diameter min(depth, width)."""
    t = p.uniform("thickness", 0.02, 0.045, fixed=thickness)
    r = min(depth, width) / 2
    a = (r - _overhang(p, depth, width)) * _SQRT_HALF
    edge = edge_profile(p, t)
    return _top("round_top", [rounded_disc(r, t, *edge, translation(0, 0, t / 2), role="top")], a, a, t)


def polygon_top(p, depth: float, width: float, thickness: float | None = None) -> Part:
    """Regular hexagonal or octagonal board whose inscribed circle spans min(depth, width)."""
    t = p.uniform("thickness", 0.02, 0.045, fixed=thickness)
    n = p.choice("sides", (6, 8))
    a = min(depth, width) / 2
    inner = (a - _overhang(p, depth, width)) * _SQRT_HALF
    return _top("polygon_top", [prism(a / math.cos(math.pi / n), t, n, translation(0, 0, t / 2), role="top")],
                inner, inner, t)


TOPS = {slab_top: 4.0, racetrack_top: 1.0, round_top: 1.5, polygon_top: 0.7}


def apron(p, depth: float, width: float, height: float, openings=(), opening_z=(0.0, 0.0),
          thickness: float | None = None) -> Part:
    """Four boards under a top; the front board is cut by ``openings`` [(y0, y1), ...]
    (sorted, inside the board) over the height range ``opening_z`` = (z0, z1)."""
    t = p.uniform("board", 0.018, 0.025, fixed=thickness)
    D, W = depth / 2, width / 2
    prims = [cuboid_between((D - t, -W + t, -height), (D, W - t, 0.0), role="board"),
             cuboid_between((-D, -W, -height), (D, -W + t, 0.0), role="board"),
             cuboid_between((-D, W - t, -height), (D, W, 0.0), role="board")]
    z0, z1 = opening_z
    if not openings:
        prims.append(cuboid_between((-D, -W + t, -height), (-D + t, W - t, 0.0), role="board"))
    else:
        if z0 > -height:
            prims.append(cuboid_between((-D, -W + t, -height), (-D + t, W - t, z0), role="board"))
        if z1 < 0.0:
            prims.append(cuboid_between((-D, -W + t, z1), (-D + t, W - t, 0.0), role="board"))
        edges = [-W + t] + [y for o in openings for y in o] + [W - t]
        for y0, y1 in zip(edges[::2], edges[1::2]):
            if y1 - y0 > 1e-4:
                prims.append(cuboid_between((-D, y0, z0), (-D + t, y1, z1), role="board"))
    return Part("frame", "apron", prims, anchors={"front": (-D, 0.0, 0.0)})


def column_base(p, height: float, max_radius: float) -> Part:
    """Pedestal: a round column on a disc, a cone or four cross feet."""
    rc = p.uniform("column_radius", 0.035, 0.08)
    rf = min(max_radius, p.uniform("foot_radius", 0.2, 0.35))
    foot = p.choice("foot", ("disc", "cone", "cross"))
    fh = p.uniform("foot_height", 0.02, 0.05)
    if foot == "disc":
        prims = [cylinder(rf, fh, translation(0, 0, fh / 2), role="foot")]
    elif foot == "cone":
        fh = p.uniform("cone_height", 0.08, 0.2)
        prims = [frustum(rf, rc * 1.2, fh, translation(0, 0, fh / 2), role="foot")]
    else:
        fw = p.uniform("foot_width", 0.04, 0.07)
        prims = [cuboid(2 * rf, fw, fh, R @ translation(0, 0, fh / 2), role="foot") for R in _CROSS]
    prims.append(cylinder(rc, height - fh, translation(0, 0, fh + (height - fh) / 2), role="column"))
    return Part("base", "column_base", prims, anchors={"column": (rc, 0.0, 0.0)})


def trestle_base(p, depth: float, width: float, height: float) -> Part:
    """Two end frames (foot, upright, cleat under the top) joined by a low stretcher;
    the frames stand at y = +-width/2 (outer faces)."""
    ut = p.uniform("upright_thickness", 0.04, 0.08)
    uw = p.uniform("upright_width", 0.06, 0.14)
    fh = p.uniform("foot_height", 0.04, 0.08)
    ch = p.uniform("cleat_height", 0.03, 0.06)
    sz = p.uniform("stretcher_z", 0.12, 0.3) * height
    sh = p.uniform("stretcher_height", 0.04, 0.08)
    prims = []
    for s in (-1, 1):
        y0, y1 = sorted((s * width / 2, s * (width / 2 - ut)))
        prims += [cuboid_between((-depth / 2, y0, 0.0), (depth / 2, y1, fh), role="foot"),
                  cuboid_between((-uw / 2, y0, fh), (uw / 2, y1, height - ch), role="upright"),
                  cuboid_between((-depth / 2, y0, height - ch), (depth / 2, y1, height), role="cleat")]
    prims.append(cuboid_between((-0.4 * uw, -width / 2 + ut, sz), (0.4 * uw, width / 2 - ut, sz + sh),
                                role="stretcher"))
    return Part("base", "trestle_base", prims, anchors={"inner": (0.0, width / 2 - ut, 0.0)})


def panel_ends(p, depth: float, width: float, height: float) -> Part:
    """Two solid side panels (waterfall / sled ends), optional back modesty panel."""
    t = p.uniform("panel_thickness", 0.025, 0.05)
    prims = [cuboid_between((-depth / 2, s * width / 2 - (t if s > 0 else 0), 0.0),
                            (depth / 2, s * width / 2 + (t if s < 0 else 0), height), role="panel")
             for s in (-1, 1)]
    if p.flag("modesty_panel", 0.5):
        mh = p.uniform("modesty_height", 0.25, 0.5) * height
        prims.append(cuboid_between((depth / 2 - 0.02, -width / 2 + t, height - mh), (depth / 2, width / 2 - t, height),
                                    role="panel"))
    return Part("base", "panel_ends", prims, anchors={"inner": (0.0, width / 2 - t, 0.0)})
