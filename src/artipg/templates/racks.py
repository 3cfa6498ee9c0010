"""Racks, trays and bins inside appliances: refrigerator door bins, dishwasher wire
racks and cutlery trays, spray arms, flat oven racks.

Frames (metres):
- ``door_bins``: in the front-panel frame of the door they hang on (origin at the
  centre of the door's back face, the cabinet behind it at x > 0); the bins fill the
  rectangle (y0, y1, z0, z1) of that frame and reach ``depth`` into the cabinet;
- ``wire_rack``, ``cutlery_tray`` and ``oven_rack``: origin at the centre of the rack's underside,
  depth along x (front at -x), width along y, wires up to ``height``;
- ``spray_arm``: origin on the rotation axis at the underside of its hub, axis +z.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring
from artipg.geometry.transforms import Placer, rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region


_YZ = Placer(rot_y(math.pi / 2))  # rect ring in the y-z plane: local x -> -z (height), y -> y
_XZ = Placer(rot_x(math.pi / 2))  # rect ring in the x-z plane: local x -> x, local y -> z
# a spray arm's first and second bar: turn @ translation(0, 0, z) as turn.at(0, 0, z) (a turn
# about z commutes with a shift along z, and Placer makes that product bit for bit)
_ARM_TURNS = (Placer(rot_z(0.0)), Placer(rot_z(math.pi / 2)))


def door_bins(p, y0: float, y1: float, z0: float, z1: float, depth: float, n: int | None = None) -> Part:
    """1-4 balcony shelves (a floor and a front lip each) on the back of a door."""
    k = p.integers("count", 1, 4, fixed=n)
    lip = p.uniform("lip", 0.04, 0.09)
    t = 0.004
    prims = []
    for i in range(k):
        zb = z0 + (z1 - z0 - lip) * (i + 0.5) / k
        prims += [cuboid_between((0.0, y0, zb), (depth, y1, zb + t), role="floor"),
                  cuboid_between((depth - t, y0, zb), (depth, y1, zb + lip), role="lip")]
    return Part("shelf", "door_bins", prims, regions={"lift": Region(("lip",))})


def _wire_box(x0, x1, y0, y1, z0, z1, r, role):
    """Rectangular wire loop (a rect ring lying flat) at height z0..z1."""
    return rect_ring(x1 - x0, y1 - y0, z1 - z0, x1 - x0 - 2 * r, y1 - y0 - 2 * r,
                     translation((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), role=role)


def wire_rack(p, depth: float, width: float, height: float, tines: bool | None = None) -> Part:
    """Basket of wire: a bottom frame with 3-6 cross wires (optionally carrying plate
    tines) and four wire-loop walls."""
    r = p.uniform("wire", 0.003, 0.005)
    n = p.integers("cross_wires", 3, 6)
    tines = p.flag("tines", 0.6, fixed=tines)
    D, W = depth / 2, width / 2
    prims = [_wire_box(-D, D, -W, W, 0.0, 2 * r, 2 * r, "frame")]
    for sx in (-1, 1):  # front and back walls (loops in the y-z plane), then the sides (x-z plane)
        prims.append(rect_ring(height, width, 2 * r, height - 4 * r, width - 4 * r,
                               _YZ.at(sx * (D - r), 0, height / 2), role="rim"))
    for sy in (-1, 1):
        prims.append(rect_ring(depth, height, 2 * r, depth - 4 * r, height - 4 * r,
                               _XZ.at(0, sy * (W - r), height / 2), role="rim"))
    for i in range(n):
        y = -W + width * (i + 1) / (n + 1)
        prims.append(cuboid(depth - 2 * r, 2 * r, 2 * r, translation(0, y, r), role="wire"))
        if tines:  # plate tines standing on the cross wires
            prims.append(cuboid(2 * r, 1.2 * r, 0.5 * height, translation(0, y, 2 * r + 0.25 * height), role="wire"))
    return Part("tray", "wire_rack", prims, anchors={"top": (0.0, 0.0, height)},
                regions={"pull": Region(("rim",)), "grasp": Region(("rim",))}, actionable="slider_drawer")


def cutlery_tray(p, depth: float, width: float, height: float) -> Part:
    """Shallow third-level tray: a flat floor in a low wire rim."""
    r = p.uniform("wire", 0.0025, 0.004)
    D, W = depth / 2, width / 2
    prims = [cuboid(depth, width, 0.003, translation(0, 0, 0.0015), role="floor"),
             _wire_box(-D, D, -W, W, 0.0, height, 2 * r, "rim")]
    return Part("tray", "cutlery_tray", prims, anchors={"top": (0.0, 0.0, height)},
                regions={"pull": Region(("rim",)), "grasp": Region(("rim",))}, actionable="slider_drawer")


RACKS = {wire_rack: 3.0, cutlery_tray: 1.0}


def spray_arm(p, radius: float, height: float) -> Part:
    """Rotating spray arm: a hub and a flat bar of ``radius`` (half length), ``height`` tall."""
    hub_r = p.uniform("hub_radius", 0.015, 0.03)
    w = p.uniform("bar_width", 0.025, 0.045)
    bars = p.choice("bars", (1, 2))
    prims = [cylinder(hub_r, height, translation(0, 0, height / 2), role="hub")]
    for i in range(bars):
        prims.append(cuboid(2 * radius, w, 0.6 * height, _ARM_TURNS[i].at(0, 0, 0.7 * height),
                            role="arm"))
    return Part("arm", "spray_arm", prims, regions={"rotate": Region(("arm",))})


def oven_rack(p, depth: float, width: float) -> Part:
    """Flat oven shelf: a wire frame with 6-12 wires across, resting on side runners."""
    r = p.uniform("wire", 0.0025, 0.004)
    n = p.integers("wires", 4, 8)
    D, W = depth / 2, width / 2
    prims = [_wire_box(-D, D, -W, W, 0.0, 2 * r, 2 * r, "frame")]
    prims += [cuboid(2 * r, width - 2 * r, 2 * r, translation(-D + depth * (i + 1) / (n + 1), 0, r), role="wire")
              for i in range(n)]
    return Part("tray", "oven_rack", prims, regions={"pull": Region(("frame",)), "grasp": Region(("frame",))})
