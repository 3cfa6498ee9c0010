"""Washing-machine parts: porthole front panel and gasket, round doors, drums and
baskets, agitators and pulsators, flat top lids.

Frames (metres):
- ``porthole_panel`` and round doors: the front-panel convention of
  :mod:`artipg.templates.panels` (origin at the centre of the back face, the plate in
  x in [-thickness, 0]); the porthole / door centre is the origin. Round doors take
  the panel doors' (width, height) signature (radius = min / 2) and expose the
  ``edge_+-y`` / ``edge_+-z`` anchors on their circle, so ``mount_hinged`` with size
  (2 R, 2 R) hinges them on the rim; ``opening`` is the radius of the hole behind the
  door that anything bulging past its back face must fit through;
- ``drum``: origin on the axis at the drum's open front rim, the drum extends along +x;
- ``basket``, ``agitator``, ``pulsator``: origin on the axis at the bottom, axis +z;
- top lids: origin on the hinge line at the lid's top back edge; the lid lies in
  x in [-depth, 0], z in [-thickness, 0], so a revolute joint about +y lifts its front.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, rect_ring, ring, sphere, torus, tri_prism
from artipg.geometry.transforms import Placer, rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region

_ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x
_QUARTERS = tuple(rot_x(i * math.pi / 2) for i in range(4))  # the porthole's four corners
_THIRDS = tuple(rot_x(2 * math.pi * i / 3) for i in range(3))  # the drum's three lifters
# a fin star of n fins (agitators 3-4, pulsators 4-6): rot_z(2 pi i / n), i < n
_STARS = {n: tuple(rot_z(2 * math.pi * i / n) for i in range(n)) for n in range(3, 7)}
_S2 = math.sqrt(0.5)
# tri prism frame for the (+y, +z) corner: base along (y, z) = (-1, 1), apex towards (1, 1)
_CORNER = np.array([[0.0, 0.0, -1.0, 0.0], [-_S2, _S2, 0.0, 0.0], [_S2, _S2, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def porthole_panel(p, width: float, height: float, hole: float, thickness: float) -> Part:
    """Front plate with a round opening of radius ``hole`` at its centre: a square
    frame and four corner wedges cut on the tangents at 45 degrees."""
    t = thickness
    prims = [rect_ring(height, width, t, 2 * hole, 2 * hole, _ALONG_X.at(-t / 2, 0, 0), role="plate")]
    k = hole * (math.sqrt(2) - 1)
    m = (hole + k) / 2
    for i in range(4):
        T = _QUARTERS[i] @ translation(-t / 2, m, m) @ _CORNER
        prims.append(tri_prism(math.sqrt(2) * (hole - k), (hole - k) * _S2, 0.0, t, T, role="plate"))
    return Part("panel", "porthole_panel", prims, anchors={"front": (-t, 0.0, 0.0)})


def _round_door(template, prims, R, t):
    front = np.array([[-t - 0.05, -R, -R], [-t + 1e-3, R, R]])
    return Part("door", template, prims, regions={"push": Region(("glass", "rim"), front)}, actionable="hinge_door",
                anchors={"edge_+y": (-t, R, 0.0), "edge_-y": (-t, -R, 0.0), "edge_+z": (-t, 0.0, R),
                         "edge_-z": (-t, 0.0, -R), "front": (-t, 0.0, 0.0)})


def ring_door(p, width: float, height: float, thickness: float | None = None, opening: float | None = None) -> Part:
    """Flat round door: a wide plastic ring around a flat glass disc."""
    radius = min(width, height) / 2
    t = p.uniform("thickness", 0.03, 0.05, fixed=thickness)
    ri = radius * p.uniform("glass_ratio", 0.6, 0.75)
    mid = _ALONG_X.at(-t / 2, 0, 0)
    return _round_door("ring_door", [ring(radius, ri, t, pose=mid, role="rim"), cylinder(ri, 0.006, mid, role="glass")],
                       radius, t)


def dome_door(p, width: float, height: float, thickness: float | None = None, opening: float | None = None) -> Part:
    """Ring with a glass bowl bulging into the drum (depth up to 0.4 of the glass radius)."""
    radius = min(width, height) / 2
    t = p.uniform("thickness", 0.03, 0.05, fixed=thickness)
    ri = radius * p.uniform("glass_ratio", 0.6, 0.72)
    if opening is not None:
        ri = min(ri, opening - 0.012)
    b = ri * p.uniform("bulge", 0.25, 0.4)
    Rs = (ri * ri + b * b) / (2 * b)  # sphere through the glass rim with sagitta b
    cap = sphere(Rs, Rs - b, Rs, pose=_ALONG_X.at(b - Rs, 0, 0), role="glass")
    rim = ring(radius, ri, t, pose=_ALONG_X.at(-t / 2, 0, 0), role="rim")
    return _round_door("dome_door", [rim, cap], radius, t)


def rim_door(p, width: float, height: float, thickness: float | None = None, opening: float | None = None) -> Part:
    """Chrome torus rim around an inner ring and flat glass (the classic porthole)."""
    radius = min(width, height) / 2
    t = p.uniform("thickness", 0.03, 0.05, fixed=thickness)
    rt = t / 2
    ri = radius * p.uniform("glass_ratio", 0.65, 0.8)
    prims = [torus(radius - rt, rt, pose=_ALONG_X.at(-rt, 0, 0), role="rim"),
             ring(radius - rt, ri, 0.6 * t, pose=_ALONG_X.at(-0.5 * t, 0, 0), role="rim"),
             cylinder(ri, 0.006, _ALONG_X.at(-0.5 * t, 0, 0), role="glass")]
    return _round_door("rim_door", prims, radius, t)


ROUND_DOORS = {ring_door: 2.0, dome_door: 1.5, rim_door: 1.0}


def drum(p, radius: float, length: float, axle: float) -> Part:
    """Stainless drum: an open cylinder with 3 lifters, a back wall and an axle ``axle`` long."""
    w = p.uniform("wall", 0.003, 0.006)
    lh = p.uniform("lifter", 0.03, 0.05)
    prims = [ring(radius, radius - w, length, pose=_ALONG_X.at(length / 2, 0, 0), role="wall"),
             cylinder(radius, w, _ALONG_X.at(length - w / 2, 0, 0), role="wall"),
             cylinder(0.025, axle, _ALONG_X.at(length + axle / 2, 0, 0), role="axle")]
    prims += [cuboid(length - w, 0.02, lh, R @ translation(length / 2, 0, radius - w - lh / 2), role="lifter")
              for R in _THIRDS]
    return Part("body", "drum", prims, regions={"rotate": Region(("wall",))})


def basket(p, radius: float, height: float, shaft: float) -> Part:
    """Top-loader / spinner basket: a perforated-drum wall on a floor, on a shaft ``shaft`` long."""
    w = p.uniform("wall", 0.003, 0.006)
    f = p.uniform("floor", 0.008, 0.015)
    prims = [cylinder(0.02, shaft, translation(0, 0, shaft / 2), role="shaft"),
             cylinder(radius, f, translation(0, 0, shaft + f / 2), role="floor"),
             ring(radius, radius - w, height - f, pose=translation(0, 0, shaft + f + (height - f) / 2), role="wall")]
    return Part("body", "basket", prims, anchors={"floor": (0.0, 0.0, shaft + f)},
                regions={"rotate": Region(("wall",))})


def agitator(p, radius: float, height: float) -> Part:
    """Central post (a frustum) with 3-4 low fins."""
    n = p.integers("fins", 3, 4)
    fh = p.uniform("fin_height", 0.05, 0.1)
    prims = [frustum(0.45 * radius, 0.25 * radius, height, translation(0, 0, height / 2), role="post")]
    prims += [cuboid(radius, 0.012, fh, R @ translation(radius / 2, 0, fh / 2), role="fin") for R in _STARS[n]]
    return Part("arm", "agitator", prims, regions={"rotate": Region(("post",))})


def pulsator(p, radius: float, height: float) -> Part:
    """Low impeller disc with 4-6 radial ribs (``height`` is ignored beyond the ribs)."""
    n = p.integers("ribs", 4, 6)
    t = p.uniform("disc", 0.01, 0.02)
    rh = min(height, p.uniform("rib_height", 0.015, 0.03))
    prims = [cylinder(radius, t, translation(0, 0, t / 2), role="disc")]
    prims += [cuboid(0.9 * radius, 0.012, rh, R @ translation(0.45 * radius, 0, t + rh / 2), role="fin")
              for R in _STARS[n]]
    return Part("arm", "pulsator", prims, regions={"rotate": Region(("disc",))})


IMPELLERS = {agitator: 1.5, pulsator: 1.0}


def _lid(template, prims, depth, width, t):
    lip = np.array([[-depth - 0.05, -width / 2, -t - 0.05], [-depth + 0.04, width / 2, 0.01]])
    return Part("lid", template, prims, regions={"lift": Region((), lip), "grasp": Region((), lip)},
                actionable="hinge_lid")


def solid_lid(p, depth: float, width: float) -> Part:
    """Painted panel with a finger lip along its front edge."""
    t = p.uniform("thickness", 0.015, 0.03)
    lip = p.uniform("lip", 0.01, 0.02)
    prims = [cuboid_between((-depth, -width / 2, -t), (0.0, width / 2, 0.0), role="panel"),
             cuboid_between((-depth - lip, -0.3 * width, -t), (-depth, 0.3 * width, -0.3 * t), role="lip")]
    return _lid("solid_lid", prims, depth, width, t)


def glass_lid(p, depth: float, width: float) -> Part:
    """Framed glass lid (rim and a tinted pane)."""
    t = p.uniform("thickness", 0.015, 0.025)
    rail = p.uniform("rail", 0.03, 0.06)
    c = translation(-depth / 2, 0, -t / 2)
    prims = [rect_ring(depth, width, t, depth - 2 * rail, width - 2 * rail, c, role="panel"),
             cuboid(depth - 2 * rail, width - 2 * rail, 0.005, c, role="glass")]
    return _lid("glass_lid", prims, depth, width, t)


LIDS = {solid_lid: 2.0, glass_lid: 1.5}
