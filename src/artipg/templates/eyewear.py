"""Eyewear templates: lenses, frame fronts and temples of a pair of glasses.

Front frame: the front stands in the y-z plane facing -x; origin at the bridge centre
on the front's back face (x = 0), z = 0 at the lens centres; it spans x in
[-depth, 0] except for its hinge knuckles, which sit behind it. Anchors
``hinge_+y``/``hinge_-y`` are the hinge axes' points at the temples' mid-height and
``lens_+y``/``lens_-y`` the lens centres.

Temple frame: origin on the (vertical) hinge axis at the temple's mid-height; the
temple runs along +x (open, as worn), its knuckle is a cylinder about the axis and its
bar is offset sideways by ``offset`` (local y), which lets the two folded temples
stack behind the front without touching. ``reach`` bounds its extent along x.
Temples are ``height`` tall at the hinge and ``thickness`` thick (local y).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring, ring, torus, tube
from artipg.geometry.tube import arc, line
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part, Region

_AX = Placer(rot_y(math.pi / 2))  # local z -> object x (a disc or ring facing -x)
# ring / torus arcs swept from +y over +z to -y (local x -> y, y -> z, z -> x)
_ARC_YZ = Placer(np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]))


def lens(p, shape: str, width: float, height: float, thickness: float | None = None) -> Part:
    """A lens centred on its origin, facing -x: a disc (``shape="round"``) or a slab."""
    t = p.uniform("thickness", 0.0015, 0.0025, fixed=thickness)
    prim = (cylinder(width / 2, t, _AX.matrix, role="lens") if shape == "round"
            else cuboid(t, width, height, role="lens"))
    return Part("lens", f"{shape}_lens", [prim])


def _round_edge(r):
    """Outline of a round lens (or rim) of radius r: half-width at height z."""
    return lambda z: math.sqrt(max(r * r - z * z, 0.0))


def _front(p, template, width, height, bridge, depth, rim, rims, edge, temple, knuckle_r, gap, zh=None, zb=None):
    """Shared assembly: ``rims(yc)`` primitives, bridge, endpieces, hinge knuckles and
    optional nose pads; ``edge(z)`` is the half-width of a rimmed lens at height z.

    The hinges sit far enough back that the inner folded temple clears the nose pads
    by ``gap`` (anchor ``fold``: x of its plane) and the outer one stacks on it.
    """
    temple_h, temple_t = temple
    a, b = width / 2, height / 2
    yc = bridge / 2 + max(rim, 0.0) + a
    kh = max(0.0025, 0.6 * temple_h)  # front knuckle height
    top = temple_h / 2 + gap + kh  # endpiece top above the hinge
    if zh is None:
        zh = min(p.uniform("hinge_z", 0.15, 0.55) * b, 0.85 * b - top)
    yh = yc + edge(0.0) + p.uniform("endpiece", 0.003, 0.008)
    y0 = yc + edge(min(max(0.0, zh - temple_h / 2), zh + top)) - 0.0005  # outermost rim point in the band
    prims = list(rims(yc))
    if zb is None:
        zb = p.uniform("bridge_z", 0.1, 0.45) * b
    yb = yc - edge(zb) + 0.0005
    bh = p.uniform("bridge_height", 0.0018, 0.004)
    if template == "full_rim_front" and edge(b) < 0.5 * a and p.flag("arched_bridge", 0.5):
        prims.append(torus(yb, bh / 2, math.pi, _ARC_YZ.at(-depth / 2, 0, zb), role="bridge"))
    else:
        bd = max(0.6 * depth, 0.0016)
        prims.append(cuboid_between((-(depth + bd) / 2, -yb, zb - bh / 2), ((bd - depth) / 2, yb, zb + bh / 2),
                                    role="bridge"))
    for s in (1.0, -1.0):
        prims.append(cuboid_between((-depth, min(s * y0, s * yh), zh - temple_h / 2),
                                    (0.0, max(s * y0, s * yh), zh + top), role="endpiece"))
    if p.flag("nose_pads", 0.6):
        rp = p.uniform("pad_radius", 0.003, 0.0045)
        zp = min(-p.uniform("pad_z", 0.1, 0.35) * b, zh - temple_h / 2 - 0.0015 - rp)
        xp = p.uniform("pad_x", 0.004, 0.007)
        yp = yc - edge(zp) + 0.0035
        for s in (1.0, -1.0):
            prims.append(cuboid_between((-depth / 2, s * yp - 0.0008, zp - 0.0008), (xp, s * yp + 0.0008, zp + 0.0008),
                                        role="pad"))
            prims.append(cylinder(rp, 0.0016, _AX.at(xp + 0.0008, s * (yp + rp * 0.6), zp), role="pad"))
        fold = xp + 0.0016 + gap
    else:
        fold = gap + p.uniform("fold_gap", 0.0, 0.003)
    xh = max(fold + temple_t + gap / 2, knuckle_r + gap)
    for s in (1.0, -1.0):
        zk = zh + temple_h / 2 + gap + kh / 2
        prims.append(cuboid_between((-0.0005, s * yh - 0.7 * knuckle_r, zk - kh / 2),
                                    (xh, s * yh + 0.7 * knuckle_r, zk + kh / 2), role="endpiece"))
        prims.append(cylinder(knuckle_r, kh, translation(xh, s * yh, zk), role="hinge"))
    anchors = {"hinge_+y": (xh, yh, zh), "hinge_-y": (xh, -yh, zh), "fold": (fold, 0.0, 0.0),
               "lens_+y": (-depth / 2, yc, 0.0),
               "lens_-y": (-depth / 2, -yc, 0.0)}
    return Part("frame", template, prims, anchors=anchors, regions={"grasp": Region(("rim", "endpiece"))})


def full_rim_front(p, shape, width, height, bridge, temple, knuckle_r, gap) -> Part:
    """Rims all around both lenses (round rings or rectangular frames)."""
    d = p.uniform("depth", 0.0025, 0.006)
    rim = p.uniform("rim", 0.0015, 0.005)
    if shape == "round":
        def rims(yc):
            return [ring(width / 2 + rim, width / 2, d, pose=_AX.at(-d / 2, s * yc, 0), role="rim")
                    for s in (1, -1)]
        edge = _round_edge(width / 2 + rim / 2)
    else:
        def rims(yc):
            return [rect_ring(height + 2 * rim, width + 2 * rim, d, height, width,
                              _AX.at(-d / 2, s * yc, 0), role="rim") for s in (1, -1)]
        edge = lambda z: width / 2 + rim / 2  # noqa: E731
    return _front(p, "full_rim_front", width, height, bridge, d, rim, rims, edge, temple, knuckle_r, gap)


def half_rim_front(p, shape, width, height, bridge, temple, knuckle_r, gap) -> Part:
    """Browline / semi-rimless: a rim over the top of each lens only."""
    d = p.uniform("depth", 0.003, 0.006)
    rim = p.uniform("rim", 0.002, 0.005)
    if shape == "round":
        def rims(yc):
            return [ring(width / 2 + rim, width / 2, d, math.pi, _ARC_YZ.at(-d / 2, s * yc, 0), role="rim")
                    for s in (1, -1)]
        return _front(p, "half_rim_front", width, height, bridge, d, rim, rims, _round_edge(width / 2 + rim / 2),
                      temple, knuckle_r, gap)

    def brows(yc):
        return [cuboid_between((-d, s * yc - width / 2 - rim, height / 2),
                               (0.0, s * yc + width / 2 + rim, height / 2 + rim), role="rim") for s in (1, -1)]
    top = temple[0] / 2 + gap + max(0.0025, 0.6 * temple[0])
    return _front(p, "half_rim_front", width, height, bridge, d, rim, brows, lambda z: width / 2 + rim / 2,
                  temple, knuckle_r, gap, zh=height / 2 + rim - top, zb=height / 2 + rim / 2)


def rimless_front(p, shape, width, height, bridge, temple, knuckle_r, gap) -> Part:
    """Rimless: bridge and endpieces fixed straight to the lenses."""
    d = p.uniform("depth", 0.002, 0.003)
    edge = _round_edge(width / 2 - 0.001) if shape == "round" else (lambda z: width / 2 - 0.001)
    return _front(p, "rimless_front", width, height, bridge, d, 0.0, lambda yc: [], edge, temple, knuckle_r, gap)


FRONTS = {full_rim_front: 3.0, half_rim_front: 1.0, rimless_front: 1.0}


def _temple(name, prims, knuckle_r, height):
    prims.append(cylinder(knuckle_r, height, role="hinge"))
    return Part("temple", name, prims, regions={"grasp": Region(("bar",))}, actionable="none")


def bar_temple(p, reach: float, height: float, thickness: float, offset: float, knuckle_r: float) -> Part:
    """Flat (acetate) temple: a straight bar and an earpiece bent down at an angle."""
    beta = p.uniform("bend", 0.35, 0.7)
    he = 0.75 * height
    le = p.uniform("earpiece", 0.025, 0.04)
    ls = reach - le * math.cos(beta) - he / 2 * math.sin(beta)
    ear = translation(ls, offset, 0) @ rot_y(beta) @ translation(le / 2, 0, 0)
    prims = [cuboid_between((0.0, offset - thickness / 2, -height / 2), (ls, offset + thickness / 2, height / 2),
                            role="bar"),
             cuboid(le, thickness, he, ear, role="bar")]
    return _temple("bar_temple", prims, knuckle_r, height)


def paddle_temple(p, reach: float, height: float, thickness: float, offset: float, knuckle_r: float) -> Part:
    """Temple with a tall paddle at the hinge, a slimmer bar and a bent earpiece."""
    beta = p.uniform("bend", 0.35, 0.7)
    hb = p.uniform("bar_height", 0.45, 0.65) * height
    lp = p.uniform("paddle_length", 0.015, 0.03)
    le = p.uniform("earpiece", 0.025, 0.04)
    ls = reach - le * math.cos(beta) - hb / 2 * math.sin(beta)
    y0, y1 = offset - thickness / 2, offset + thickness / 2
    prims = [cuboid_between((0.0, y0, -height / 2), (lp, y1, height / 2), role="bar"),
             cuboid_between((lp - 0.001, y0, -hb / 2), (ls, y1, hb / 2), role="bar"),
             cuboid(le, thickness, hb, translation(ls, offset, 0) @ rot_y(beta) @ translation(le / 2, 0, 0),
                    role="bar")]
    return _temple("paddle_temple", prims, knuckle_r, height)


def wire_temple(p, reach: float, height: float, thickness: float, offset: float, knuckle_r: float) -> Part:
    """Metal temple: a hinge block and a round wire curling down over the ear."""
    r = p.uniform("wire_radius", 0.0008, 0.0012)
    lb = p.uniform("block_length", 0.008, 0.012)
    bend = p.uniform("bend_radius", 0.02, 0.035)
    turn = p.uniform("turn", 0.6, 1.1)
    tail = p.uniform("tail", 0.01, 0.025)
    x0 = lb - 0.002
    ls = reach - x0 - bend * math.sin(turn) - tail * math.cos(turn) - r
    prims = [cuboid_between((0.0, offset - thickness / 2, -height / 2), (lb, offset + thickness / 2, height / 2),
                            role="bar")]
    prims += tube(r, [line(ls), arc(bend, -turn), line(tail)], 0.0, translation(x0, offset, 0), role="bar")
    return _temple("wire_temple", prims, knuckle_r, height)


TEMPLES = {bar_temple: 2.0, wire_temple: 2.0, paddle_temple: 1.0}
#: temple template -> ranges of (height at the hinge, thickness), metres
TEMPLE_SIZES = {bar_temple: ((0.004, 0.007), (0.0025, 0.004)), wire_temple: ((0.003, 0.004), (0.002, 0.003)),
                paddle_temple: ((0.007, 0.011), (0.0025, 0.004))}
