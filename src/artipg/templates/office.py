"""Office-tool templates: the base, magazine and top arm of a stapler.

Base frame: origin at the centre of the footprint on the floor, length along x (the
striking nose at -x), top face at z = ``top``. Magazine and arm frame: origin on the
hinge axis (along y) at the back, the part reaching forward along -x; a magazine is a
``2 * radius`` tall channel centred on the axis, ending at the back in a knuckle of
that radius (so it turns in place) and carrying an axle out to ``span`` either side;
an arm covers the magazine from ``clear`` above it, with side skirts that end in
rings around the axle (``skirt`` gives their inner and outer y).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, ring, tri_prism
from artipg.geometry.lathe import ring_dims
from artipg.geometry.transforms import Placer, rot_x, rot_z, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.extents import span
from artipg.templates.levers import top_grasp

_Y = Placer(rot_x(math.pi / 2))  # local z -> object -y (cylinders and rings along y)
# arcs swept about x: local x -> y, local y -> z, local z -> x
_ALONG_X = Placer(np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]))


def flat_base(p, length: float, width: float, top: float) -> Part:
    """A plain rectangular base plate."""
    prims = [cuboid_between((-length / 2, -width / 2, 0.0), (length / 2, width / 2, top), role="plate")]
    return Part("base", "flat_base", prims, regions={"push": Region(("plate",))})


def rounded_base(p, length: float, width: float, top: float) -> Part:
    """A base plate with a rounded nose."""
    r = top / 2
    prims = [cuboid_between((-length / 2 + r, -width / 2, 0.0), (length / 2, width / 2, top), role="plate"),
             cylinder(r, width, _Y.at(-length / 2 + r, 0, r), role="plate")]
    return Part("base", "rounded_base", prims, regions={"push": Region(("plate",))})


def footed_base(p, length: float, width: float, top: float) -> Part:
    """A thin plate on a slightly smaller rubber pad."""
    pad = p.uniform("pad", 0.35, 0.6) * top
    inset = p.uniform("pad_inset", 0.002, 0.006)
    prims = [cuboid_between((-length / 2 + inset, -width / 2 + inset, 0.0),
                            (length / 2 - inset, width / 2 - inset, pad), role="pad"),
             cuboid_between((-length / 2, -width / 2, pad), (length / 2, width / 2, top), role="plate")]
    return Part("base", "footed_base", prims, regions={"push": Region(("plate",))})


BASES = {flat_base: 2.0, rounded_base: 2.0, footed_base: 1.0}


def _knuckle_axle(radius, width, axle_r, span):
    return [cylinder(radius, width, _Y.matrix, role="knuckle"), cylinder(axle_r, 2 * span, _Y.matrix, role="axle")]


def channel_magazine(p, length: float, width: float, radius: float, axle_r: float, span: float) -> Part:
    """Open-top U channel (bottom, two walls, front cap) that holds the staple strip."""
    t = p.uniform("wall", 0.0015, 0.0022)
    w2 = width / 2
    prims = [cuboid_between((-length, -w2, -radius), (0.0, w2, -radius + t), role="channel"),
             cuboid_between((-length, -w2, -radius + t), (0.0, -w2 + t, radius), role="channel"),
             cuboid_between((-length, w2 - t, -radius + t), (0.0, w2, radius), role="channel"),
             cuboid_between((-length, -w2 + t, -radius + t), (-length + t, w2 - t, radius), role="channel")]
    return Part("magazine", "channel_magazine", prims + _knuckle_axle(radius, width, axle_r, span))


def box_magazine(p, length: float, width: float, radius: float, axle_r: float, span: float) -> Part:
    """Closed magazine housing."""
    prims = [cuboid_between((-length, -width / 2, -radius), (0.0, width / 2, radius), role="channel")]
    return Part("magazine", "box_magazine", prims + _knuckle_axle(radius, width, axle_r, span))


MAGAZINES = {channel_magazine: 2.0, box_magazine: 1.0}


def _arm(name, top, p, length, width, radius, clear, skirt, axle_r, nose_gap):
    """Skirts with axle rings, a nose over the magazine's front and the ``top`` cover."""
    t = p.uniform("thickness", 0.0018, 0.003)
    hs = p.uniform("skirt_depth", 0.3, 0.8) * radius
    y0, y1 = skirt
    z1 = radius + clear + t
    x0 = -(length + nose_gap + t)  # front of the nose
    prims = list(top(x0, y1, radius + clear, t))
    for s in (1.0, -1.0):
        prims.append(cuboid_between((x0, min(s * y0, s * y1), -hs), (-axle_r - 0.0012, max(s * y0, s * y1), z1),
                                    role="skirt"))
        prims.append(ring(axle_r + 0.0026, axle_r + 0.0004, y1 - y0, pose=_Y.at(0, s * (y0 + y1) / 2, 0),
                          role="skirt"))
    prims.append(cuboid_between((x0, -y1, -radius + 0.001), (x0 + t, y1, z1), role="nose"))
    # from above near the nose, jaws closing across the arm's width outside the skirts
    grasp = Deferred.one(top_grasp, 0.7 * x0, 0.0, radius + clear, 2 * y1 + 0.02, "y")
    return Part("arm", name, prims, regions={"push": Region(("cover",)), "grasp": Region(("cover",))},
                grasps=grasp, actionable="hinge_handle")


def flat_arm(p, length, width, radius, clear, skirt, axle_r, nose_gap) -> Part:
    """Flat cover plate."""
    def top(x0, y1, z0, t):
        return [cuboid_between((x0, -y1, z0), (0.0, y1, z0 + t), role="cover")]
    return _arm("flat_arm", top, p, length, width, radius, clear, skirt, axle_r, nose_gap)


def rounded_arm(p, length, width, radius, clear, skirt, axle_r, nose_gap) -> Part:
    """Cover plate under a shallow barrel vault (a ring arc along x), closed at the nose."""
    half = p.uniform("vault_angle", 0.6, 1.1)  # half the arc's opening angle

    def top(x0, y1, z0, t):
        R = y1 / math.sin(half)
        T = _ALONG_X.at(x0 / 2, 0, z0 + t - (R - t) * math.cos(half)) @ rot_z(math.pi / 2 - half)
        cap = (R - t) * math.cos(half) - 0.0005
        return [cuboid_between((x0, -y1, z0), (0.0, y1, z0 + t), role="cover"),
                ring(R, R - t, -x0, 2 * half, T, role="cover"),
                ring(R - t / 2, cap, t, 2 * half, T @ translation(0, 0, x0 / 2 + t / 2), role="cover")]
    return _arm("rounded_arm", top, p, length, width, radius, clear, skirt, axle_r, nose_gap)


def humped_arm(p, length, width, radius, clear, skirt, axle_r, nose_gap) -> Part:
    """Flat cover with a wedge-shaped palm rest rising towards the back."""
    hl = p.uniform("hump_length", 0.35, 0.6) * length
    hh = p.uniform("hump_height", 0.3, 0.7) * radius

    def top(x0, y1, z0, t):
        wedge = tri_prism(hl, hh, hl * p.uniform("hump_peak", 0.1, 0.4), 2 * y1,
                          _Y.at(-hl / 2 - 0.002, 0, z0 + t), role="cover")
        return [cuboid_between((x0, -y1, z0), (0.0, y1, z0 + t), role="cover"), wedge]
    return _arm("humped_arm", top, p, length, width, radius, clear, skirt, axle_r, nose_gap)


ARMS = {flat_arm: 2.0, rounded_arm: 2.0, humped_arm: 1.0}


def arm_top(part: Part) -> float:
    """Highest z of an arm part (the top of its bounds), metres above the axle."""
    # the skirts' rings around the axle stay below the cover: leave them out
    return span([pr for pr in part.primitives if not (pr.role == "skirt" and ring_dims(pr) is not None)], 2)[1]
