"""Glue stick parts: the tube, the twist base, the glue column and the cap.

Frames (metres, +z up, on the stick's axis):
- twist bases: origin at the centre of the bottom on the floor, up to ``height``;
- tubes: origin at the tube's bottom end; anchors ``rim`` (top end) and ``radii``
  (outer, inner radius); decorations outside the outer radius stay below ``clear``
  (where the cap's skirt ends);
- ``glue_column``: origin at its bottom face;
- caps: origin at the centre of the tube's rim plane; a skirt hangs down over the
  tube and the closed top stands ``headroom`` above the rim.
"""

from __future__ import annotations

from artipg.geometry import cylinder, frustum, prism, ring, sphere
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region

CLEAR = 0.0008  # radial clearance of round parts sliding in round parts
_TURN = Region(("grip",))


def _z(z0: float, z1: float):
    return translation(0, 0, (z0 + z1) / 2)


def _twist(template, prims, height) -> Part:
    return Part("knob", template, prims, anchors={"top": (0.0, 0.0, height)},
                regions={"rotate": _TURN, "grasp": _TURN}, actionable="hinge_knob")


def plain_twist(p, radius: float, height: float) -> Part:
    """Plain round twist base as wide as the tube."""
    return _twist("plain_twist", [cylinder(radius, height, _z(0.0, height), role="grip")], height)


def fluted_twist(p, radius: float, height: float) -> Part:
    """Twist base with a many-sided (fluted) grip on a round foot."""
    foot = p.uniform("foot", 0.15, 0.3) * height
    n = p.integers("flutes", 12, 16)
    return _twist("fluted_twist", [cylinder(radius, foot, _z(0.0, foot), role="foot"),
                                   prism(radius, height - foot, n, _z(foot, height), role="grip")], height)


def flanged_twist(p, radius: float, height: float) -> Part:
    """Twist base with a wider flange at the bottom (stands steadier)."""
    f = p.uniform("flange", 0.0015, 0.003)
    tf = p.uniform("flange_height", 0.002, 0.003)
    return _twist("flanged_twist", [cylinder(radius + f, tf, _z(0.0, tf), role="foot"),
                                    cylinder(radius, height - tf, _z(tf, height), role="grip")], height)


TWISTS = {plain_twist: 2.0, fluted_twist: 1.5, flanged_twist: 1.0}


def _tube(template, p, radius, length, extra=()) -> Part:
    wall = p.uniform("wall", 0.001, 0.0018)
    prims = [ring(radius, radius - wall, length, pose=_z(0.0, length), role="tube"), *extra]
    return Part("body", template, prims, anchors={"rim": (0.0, 0.0, length), "radii": (radius, radius - wall, 0.0)},
                regions={"grasp": Region(("tube",)), "lift": Region(("tube",))})


def plain_tube(p, radius: float, length: float, clear: float) -> Part:
    """Plain round tube."""
    return _tube("plain_tube", p, radius, length)


def label_tube(p, radius: float, length: float, clear: float) -> Part:
    """Tube with a raised label sleeve on its lower part, below the cap's skirt."""
    h = p.uniform("label", 0.4, 0.8) * (clear - 0.004)
    z0 = p.uniform("label_gap", 0.0, 0.3) * (clear - 0.004 - h)
    band = ring(radius + p.uniform("label_thickness", 0.0004, 0.0008), radius - 0.0005, h, pose=_z(z0, z0 + h),
                role="label")
    return _tube("label_tube", p, radius, length, [band])


def collar_tube(p, radius: float, length: float, clear: float) -> Part:
    """Tube with a stop collar just below where the cap's skirt ends."""
    h = p.uniform("collar", 0.002, 0.004)
    z1 = clear - p.uniform("collar_gap", 0.0005, 0.0015)
    band = ring(radius + p.uniform("collar_thickness", 0.001, 0.002), radius - 0.0005, h, pose=_z(z1 - h, z1),
                role="collar")
    return _tube("collar_tube", p, radius, length, [band])


TUBES = {plain_tube: 2.0, label_tube: 1.5, collar_tube: 1.0}


def glue_column(p, radius: float, length: float) -> Part:
    """The glue: a round column (origin at its bottom), worn to a low cone at the top."""
    d = p.uniform("dome", 0.1, 0.3) * radius
    prims = [cylinder(radius, length - d, _z(0.0, length - d), role="glue"),
             frustum(radius, p.uniform("crown", 0.3, 0.6) * radius, d, _z(length - d, length), role="glue")]
    return Part("refill", "glue_column", prims, regions={"push": Region(("glue",))})


def _cap(template, p, radius, skirt, headroom, top) -> Part:
    ri = radius + CLEAR
    ro = ri + p.uniform("wall", 0.0008, 0.0015)
    prims = [ring(ro, ri, skirt + headroom, pose=_z(-skirt, headroom), role="skirt"), *top(ro, headroom)]
    return Part("cap", template, prims, anchors={"outer": (ro, 0.0, 0.0)},
                regions={"grasp": Region(("skirt",)), "pull": Region(("skirt",)), "lift": Region(("skirt",))},
                actionable="slider_lid")


def flat_cap(p, radius: float, skirt: float, headroom: float) -> Part:
    """Cap with a flat top."""
    t = p.uniform("top", 0.0015, 0.003)
    return _cap("flat_cap", p, radius, skirt, headroom, lambda ro, h: [cylinder(ro, t, _z(h, h + t), role="top")])


def domed_cap(p, radius: float, skirt: float, headroom: float) -> Part:
    """Cap with a low dome on top."""
    d = p.uniform("dome", 0.15, 0.4)

    def top(ro, h):
        dd = d * ro
        rs = (ro * ro + dd * dd) / (2 * dd)
        return [cylinder(ro, 0.001, _z(h, h + 0.001), role="top"),
                sphere(rs, rs - dd, rs, translation(0, 0, h + 0.001 + dd - rs), role="top")]
    return _cap("domed_cap", p, radius, skirt, headroom, top)


def ribbed_cap(p, radius: float, skirt: float, headroom: float) -> Part:
    """Flat-topped cap with grip ribs round its skirt."""
    t, n = p.uniform("top", 0.0015, 0.003), p.integers("ribs", 2, 4)
    rib = p.uniform("rib", 0.0004, 0.0008)

    def top(ro, h):
        pitch = (skirt + h) / (n + 1)
        return [cylinder(ro, t, _z(h, h + t), role="top"),
                *[ring(ro + rib, ro - 0.0003, 0.0012, pose=translation(0, 0, -skirt + (k + 1) * pitch), role="skirt")
                  for k in range(n)]]
    return _cap("ribbed_cap", p, radius, skirt, headroom, top)


CAPS = {flat_cap: 2.0, domed_cap: 1.0, ribbed_cap: 1.0}
