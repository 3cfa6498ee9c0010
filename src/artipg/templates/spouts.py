"""Faucet plumbing: deck plates, columns, spouts and pull-out spray heads.

Mounts: ``round_deck``/``rect_deck`` (Part "base": origin at the centre of the
footprint on the counter, top face at anchor ``top``) and ``column`` (Part "body":
origin at its base centre, +z up, anchor ``top``).

Spouts: origin on the swivel axis (+z) at the mount point; the spout reaches towards
-x, over the basin. Top-mounted spouts (``gooseneck_spout``, ``arc_spout``,
``tube_spout``) start at the origin heading +z, so a swivel about z is collision free;
``low`` is the height (above the origin) that everything beyond the riser must stay
over -- the riser grows to make it so (clearing levers and handles below). Collar
spouts (``collar_spout``, ``waterfall_spout``) wrap a column of radius ``mount``
with a ring centred on the origin and reach out from its side. Anchors: ``outlet``
(centre of the water exit) and ``outlet_dir`` (unit exit direction, stored as a point).

``spray_head``: origin at the dock point, body along +z; align +z with the spout's
outlet direction and slide it along +z (prismatic) to pull it out.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, frustum, ring, tube
from artipg.geometry.transforms import translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region


def round_deck(p, radius: float | None = None, length: float | None = None) -> Part:
    """Round deck plate (escutcheon), slightly domed (a frustum)."""
    r = p.uniform("radius", 0.025, 0.045, fixed=radius)
    h = p.uniform("height", 0.005, 0.014)
    return Part("base", "round_deck", [frustum(r, r * p.uniform("taper", 0.8, 1.0), h, translation(0, 0, h / 2),
                                                role="plate")], anchors={"top": (0.0, 0.0, h)})


def rect_deck(p, radius: float | None = None, length: float | None = None) -> Part:
    """Rectangular deck plate, ``length`` along y (spans a two-handle faucet)."""
    d = 2 * p.uniform("radius", 0.025, 0.04, fixed=radius)
    L = p.uniform("length", 0.06, 0.1, fixed=length)
    h = p.uniform("height", 0.006, 0.015)
    return Part("base", "rect_deck", [cuboid(d, L, h, translation(0, 0, h / 2), role="plate")],
                anchors={"top": (0.0, 0.0, h)})


DECKS = {round_deck: 2.0, rect_deck: 1.0}


def column(p, radius: float, height: float) -> Part:
    """Faucet body column, optionally with a flared foot."""
    prims = [cylinder(radius, height, translation(0, 0, height / 2), role="column")]
    if p.flag("flare", 0.4):
        fh = p.uniform("flare_height", 0.15, 0.35) * height
        prims.append(frustum(radius * p.uniform("flare_ratio", 1.15, 1.4), radius, fh, translation(0, 0, fh / 2),
                             role="column"))
    return Part("body", "column", prims, anchors={"top": (0.0, 0.0, height)})


def _spout(template, prims, outlet, direction, extra=None) -> Part:
    dx, dy, dz = direction
    n = math.sqrt(dx * dx + dy * dy + dz * dz)
    anchors = {"outlet": tuple(outlet), "outlet_dir": (dx / n, dy / n, dz / n)}
    return Part("spout", template, prims, anchors=anchors | (extra or {}),
                regions={"grasp": Region(("tube",)), "rotate": Region(("tube",))})


def _path_end(segments, a: float) -> tuple[float, float, float]:
    """End (x, z) and heading of a tube path starting at the origin with heading ``a``."""
    x = z = 0.0
    for seg in segments:
        if seg[0] == "line":
            x, z = x + math.cos(a) * seg[1], z + math.sin(a) * seg[1]
        else:
            sg = seg[1] if seg[2] > 0 else -seg[1]
            cx, cz = x - math.sin(a) * sg, z + math.cos(a) * sg
            a += seg[2]
            x, z = cx + math.sin(a) * sg, cz - math.cos(a) * sg
    return x, z, a


def _top_spout(p, r, segs_after, low, rise):
    """Riser + ``segs_after``; the riser is lengthened so the rest stays above ``low``
    (every design here ends at its lowest point)."""
    rise = p.uniform("rise", 0.03, 0.12, fixed=rise)
    x, z, a = _path_end(segs_after, math.pi / 2)  # the part after the riser, from the origin
    rise = max(rise, low, low + r - z)
    segs = (line(rise),) + tuple(segs_after)
    return tube(r, segs, math.pi / 2, role="tube"), (x, 0.0, z + rise), (math.cos(a), 0.0, math.sin(a))


def gooseneck_spout(p, radius: float | None = None, low: float = 0.0, rise: float | None = None) -> Part:
    """Tall riser bending over in a half circle, ending with a short drop."""
    r = p.uniform("radius", 0.008, 0.014, fixed=radius)
    R = p.uniform("bend_radius", 0.06, 0.12)
    turn = p.uniform("turn", 0.85, 1.0) * math.pi
    prims, end, d = _top_spout(p, r, [arc(R, turn), line(p.uniform("drop", 0.005, 0.04))], low, rise)
    return _spout("gooseneck_spout", prims, end, d)


def arc_spout(p, radius: float | None = None, low: float = 0.0, rise: float | None = None) -> Part:
    """Riser, a quarter bend, a straight run forward and a downward bend at the tip."""
    r = p.uniform("radius", 0.008, 0.014, fixed=radius)
    segs = [arc(p.uniform("bend_radius", 0.03, 0.07), math.pi / 2), line(p.uniform("run", 0.04, 0.14)),
            arc(p.uniform("tip_radius", 0.02, 0.05), p.uniform("tip_turn", 0.3, 0.5) * math.pi)]
    prims, end, d = _top_spout(p, r, segs, low, rise)
    return _spout("arc_spout", prims, end, d)


def tube_spout(p, radius: float | None = None, low: float = 0.0, rise: float | None = None) -> Part:
    """Riser, a tight elbow and a horizontal run with an aerator under its tip."""
    r = p.uniform("radius", 0.008, 0.014, fixed=radius)
    ha = p.uniform("aerator_height", 0.01, 0.02)
    segs = [arc(p.uniform("bend_radius", 0.015, 0.04), math.pi / 2), line(p.uniform("run", 0.06, 0.16))]
    prims, end, d = _top_spout(p, r, segs, low + ha, rise)
    x, z = end[0] + 1.05 * r, end[2] - r - ha / 2
    prims.append(cylinder(1.05 * r, ha + r, translation(x, 0, z + r / 2), role="tube"))
    return _spout("tube_spout", prims, (x, 0.0, z - ha / 2), (0.0, 0.0, -1.0))


TOP_SPOUTS = {gooseneck_spout: 2.0, arc_spout: 2.0, tube_spout: 1.0}


def _collar(p, mount: float):
    c = p.uniform("collar_height", 0.02, 0.04)
    t = p.uniform("collar_wall", 0.003, 0.006)
    ri = mount + p.uniform("collar_gap", 0.0005, 0.001)
    return c, t, ri, ring(ri + t, ri, c, role="collar")


def collar_spout(p, mount: float, max_tip: float = 0.04) -> Part:
    """Collar around a column with a tube reaching forward and turning down at the tip
    (tip bend radius at most ``max_tip``, which bounds how far the tip drops)."""
    c, t, ri, col = _collar(p, mount)
    r = min(p.uniform("radius", 0.007, 0.012), 0.45 * c, math.sqrt(ri * t + 0.7 * t * t))
    x0 = -(ri + t / 2)
    tip = p.uniform("tip_radius", min(0.015, max_tip), min(0.04, max_tip))
    segs = [line(p.uniform("run", 0.05, 0.14)), arc(tip, p.uniform("tip_turn", 0.3, 0.5) * math.pi)]
    T = translation(x0, 0, 0)
    x, z, a = _path_end(segs, math.pi)
    prims = [col] + tube(r, segs, math.pi, T, role="tube")
    return _spout("collar_spout", prims, (x + x0, 0.0, z), (math.cos(a), 0.0, math.sin(a)),
                  {"collar_top": (0.0, 0.0, c / 2)})


def waterfall_spout(p, mount: float, max_tip: float = 0.04) -> Part:
    """Collar with a flat, wide box spout (a waterfall lip) reaching forward; the lip
    does not drop (``max_tip`` is accepted so collar spouts are interchangeable)."""
    c, t, ri, col = _collar(p, mount)
    L = p.uniform("run", 0.06, 0.14)
    w = p.uniform("width", 0.03, 0.06)
    th = min(p.uniform("thickness", 0.008, 0.015), c)
    x0 = -(ri + t / 2)
    prims = [col, cuboid(L, w, th, translation(x0 - L / 2, 0, c / 2 - th / 2), role="tube")]
    return _spout("waterfall_spout", prims, (x0 - L + 0.01, 0.0, c / 2 - th), (0.0, 0.0, -1.0),
                  {"collar_top": (0.0, 0.0, c / 2)})


COLLAR_SPOUTS = {collar_spout: 2.0, waterfall_spout: 1.0}


def spray_head(p, radius: float) -> Part:
    """Pull-out spray head docked on a spout outlet: a frustum body along +z with a face
    plate; ``radius`` is the spout tube's radius (the head is wider)."""
    rh = radius * p.uniform("head_ratio", 1.4, 2.0)
    L = p.uniform("length", 0.05, 0.09)
    face = p.uniform("face_height", 0.004, 0.008)
    prims = [frustum(radius * 1.05, rh, L - face, translation(0, 0, (L - face) / 2), role="grip"),
             cylinder(rh, face, translation(0, 0, L - face / 2), role="face")]
    return Part("nozzle", "spray_head", prims, anchors={"outlet": (0.0, 0.0, L), "length": (0.0, 0.0, L)},
                regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred(_head_grasp, L, rh))


def _head_grasp(L: float, rh: float) -> list[Grasp]:
    """The grasp on a spray head ``L`` long of radius ``rh``: approaching from the
    part's -x side (along +x), jaws across the body (y)."""
    T = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.6 * L], [0.0, 0.0, 0.0, 1.0]])
    return [Grasp(T, 2 * rh + 0.02, np.array([0.0, 0.0, 1.0]))]
