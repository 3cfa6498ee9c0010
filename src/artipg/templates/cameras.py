"""Camera parts: bodies with a battery pocket, lens barrels and rings, telescoping
zoom tubes, mode dials, screens and hinged doors.

Frames (every template here):

- bodies are built in the object frame: front (lens side) towards -x, width along y,
  the bottom on z = 0;
- round lens parts lie on the optical axis, which is local -x (the direction the lens
  points); the origin is the centre of the part's back face, the part spans local x in
  [-length, 0];
- a dial's origin is the centre of its bottom face, on the surface it stands on; it
  rises along local +z and turns about it;
- flat plates (screens, doors) span local x in [-thickness, 0] (x = 0 is the outer
  face), y in [0, width] from the hinge edge and z in [0, height]; their origin is the
  outer corner on the hinge line, which keeps their swing clear of the face they lie on.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid, cuboid_between, cylinder, prism, ring
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Part, Region

CLEAR = 0.001  # radial running clearance of rings and tubes on their barrels (> the 0.5 mm sector sagitta)
GAP = 0.0006   # clearance of plates and doors in their pockets
_ALONG_X = rot_y(math.pi / 2)  # a lathe's z along x


def _along_x(x0: float, x1: float):
    """Pose of a centred lathe primitive spanning local x in [x0, x1] (x1 > x0)."""
    T = _ALONG_X.copy()
    T[0, 3] = 0.5 * (x0 + x1)
    return T


def pocket_body(p, width: float, height: float, depth: float, radius: float, pocket) -> Part:
    """Camera body block: a box ``depth`` (x) x ``width`` (y) x ``height`` (z) with edges
    rounded by ``radius``, standing on a bottom layer (inset by up to 2 mm) that has a rectangular battery
    pocket ``pocket`` = (x0, x1, y0, y1, layer thickness) open downwards (None: a plain
    rounded block).

    Frame: the object frame (front -x, bottom on z = 0, centred on x and y).
    Anchors: ``top`` (centre of the top face), ``back`` (centre of the back face).
    """
    x0, x1, y0, y1, t = pocket if pocket is not None else (0.0, 0.0, 0.0, 0.0, 0.0)
    e = min(radius, 0.002)  # the layer reaches almost to the block's outline: the feet are wide
    X, Y = depth / 2 - e, width / 2 - e
    prims = [rounded_box(depth, width, height - t, radius, translation(0, 0, t + (height - t) / 2), role="shell")]
    if pocket is not None:
        prims += [cuboid_between((-X, -Y, 0.0), (x0, Y, t), role="shell"),
                  cuboid_between((x1, -Y, 0.0), (X, Y, t), role="shell"),
                  cuboid_between((x0, -Y, 0.0), (x1, y0, t), role="shell"),
                  cuboid_between((x0, y1, 0.0), (x1, Y, t), role="shell")]
    return Part("body", "pocket_body", prims, anchors={"top": (0.0, 0.0, height), "back": (depth / 2, 0.0, height / 2)},
                regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def grip_block(p, x0: float, x1: float, y0: float, y1: float, height: float, radius: float) -> Part:
    """Hand grip on the body's front: a rounded block over x in [x0, x1], y in
    [y0, y1], z in [0, ``height``] (object frame)."""
    r = min(radius, 0.45 * min(x1 - x0, y1 - y0))
    prim = rounded_box(x1 - x0, y1 - y0, height, r, translation((x0 + x1) / 2, (y0 + y1) / 2, height / 2), role="grip")
    return Part("body", "grip_block", [prim], regions={"grasp": Region(("grip",))})


def prism_hump(p, width: float, height: float, depth: float, base_z: float, y: float) -> Part:
    """Viewfinder (pentaprism) housing on the top plate: a block ``width`` (y) x
    ``depth`` (x) under a narrower flash/shoe block; origin of the object frame, its
    bottom on z = ``base_z``, centred on y = ``y``."""
    top = p.uniform("shoe_ratio", 0.45, 0.65)
    h0 = p.uniform("lower_ratio", 0.55, 0.7) * height
    prims = [rounded_box(depth, width, h0 + 0.002, 0.002, translation(0, y, base_z + (h0 - 0.002) / 2), role="shell"),
             rounded_box(0.85 * depth, top * width, height - h0, 0.002,
                         translation(-0.05 * depth, y, base_z + h0 + (height - h0) / 2), role="shell")]
    return Part("body", "prism_hump", prims)


def lens_barrel(p, sections) -> Part:
    """Fixed lens barrel: ``sections`` = [(x0, x1, radius), ...] cylinders along the
    optical axis (local x, x0 < x1 <= 0; see the module docstring)."""
    prims = [cylinder(r, x1 - x0, _along_x(x0, x1), role="barrel") for x0, x1, r in sections]
    return Part("lens", "lens_barrel", prims, regions={"grasp": Region(("barrel",))})


def lens_ring(p, r_in: float, r_out: float, length: float) -> Part:
    """Zoom or focus ring: a ribbed ring ``length`` long between ``r_in`` and
    ``r_out`` on the optical axis (local x in [-length, 0]); it turns about that axis."""
    rib = p.uniform("rib_ratio", 0.4, 0.7) * length
    ro = r_out - p.uniform("rib_height", 0.0005, 0.0012)
    prims = [ring(ro, r_in, length, pose=_along_x(-length, 0.0), role="ring"),
             ring(r_out, ro - 0.0002, rib, pose=_along_x(-(length + rib) / 2, -(length - rib) / 2), role="grip")]
    grip = Region(("grip", "ring"))
    return Part("lens", "lens_ring", prims, regions={"rotate": grip, "grasp": grip}, actionable="hinge_knob")


def zoom_tube(p, r_out: float, r_in: float, length: float, closed: bool, moving: bool = True) -> Part:
    """One stage of a telescoping zoom barrel, or the fixed bezel it slides in
    (``moving`` False): a tube on the optical axis (local x in [-length, 0]); the
    innermost stage is ``closed`` (solid, with the front glass on it)."""
    T = _along_x(-length, 0.0)
    prim = cylinder(r_out, length, T, role="tube") if closed else ring(r_out, r_in, length, pose=T, role="tube")
    reg = Region(("tube",))
    if not moving:
        return Part("lens", "lens_bezel", [prim], regions={"grasp": reg})
    return Part("lens", "zoom_tube", [prim], regions={"pull": reg, "push": reg, "grasp": reg},
                actionable="slider_drawer")


def front_glass(p, radius: float, thickness: float = 0.001) -> Part:
    """The front lens element: a glass disc ``radius`` on the optical axis, local x in
    [-thickness, 0]."""
    return Part("glass", "front_glass", [cylinder(radius, thickness, _along_x(-thickness, 0.0), role="glass")])


def mode_dial(p, radius: float, height: float) -> Part:
    """Knurled mode dial: a many-sided prism ``radius`` x ``height`` rising along
    local +z from its origin with a thin top disc; it turns about local z."""
    n = p.integers("flutes", 12, 16)
    cap = p.uniform("cap_ratio", 0.2, 0.35) * height
    prims = [prism(radius, height - cap, n, translation(0, 0, (height - cap) / 2), role="grip"),
             cylinder(0.92 * radius, cap, translation(0, 0, height - cap / 2), role="top")]
    grip = Region(("grip",))
    return Part("dial", "mode_dial", prims, anchors={"top": (0.0, 0.0, height)},
                regions={"rotate": grip, "grasp": grip}, actionable="hinge_knob")


def screen_panel(p, width: float, height: float, thickness: float) -> Part:
    """Rear LCD panel: a housing plate with the display on its outer face (local x in
    [-thickness, 0], y in [0, width], z in [0, height]; see the module docstring)."""
    lcd = p.uniform("lcd_ratio", 0.82, 0.92)
    m = (1 - lcd) / 2
    prims = [cuboid_between((-thickness, 0.0, 0.0), (-0.0003, width, height), role="housing"),
             cuboid_between((-0.0003, m * width, m * height), (0.0, (1 - m) * width, (1 - m) * height), role="lcd")]
    face = Region(("housing", "lcd"))
    return Part("screen", "screen_panel", prims, regions={"pull": face, "push": face}, actionable="hinge_door")


def hinged_plate(p, semantic: str, width: float, height: float, thickness: float) -> Part:
    """A door plate (battery or film door) in the plate frame of the module docstring."""
    prim = cuboid_between((-thickness, 0.0, 0.0), (0.0, width, height), role="plate")
    face = Region(("plate",))
    return Part(semantic, "hinged_plate", [prim], regions={"pull": face, "push": face}, actionable="hinge_door")


def window(p, semantic: str, size_y: float, size_z: float, thickness: float) -> Part:
    """A flat window (flash, viewfinder, display) standing on a face whose outward
    normal is local -x: local x in [-thickness, 0], centred on y and z."""
    return Part(semantic, "window", [cuboid(thickness, size_y, size_z, translation(-thickness / 2, 0, 0),
                                            role="window")])
