"""Pouring spouts of kettles and jugs, and the flip cap of a whistling spout.

Spout frame: origin at the mount point on the vessel's outer wall, +x along the wall's
outward normal, +z up the wall; the spout leaves from a short boss whose inner face
sits inside the wall's thickness.
``rise`` is how high above the mount the tip should end. Anchors: ``tip`` (centre of
the outlet face), ``tip_dir`` (unit outlet direction, stored as a point) and
``tip_r`` (outlet radius, as (r, 0, 0)).

Whistle cap frame: origin on its hinge line, which lies across the top of the outlet
face; +x along the outlet direction, +z the outlet's "up" normal, hinge axis -y
(opening lifts the cap up and away from the outlet).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, ring, tube
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region

_EMBED = 0.0008  # the spout's inner face sits this deep in the wall (walls are >= 1.5 mm)
_WALL = 0.0015  # sheet thickness of the hollow straight spouts (a solid one would outweigh the kettle)
_ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x


def _spout(name, prims, tip, heading, r) -> Part:
    d = (math.cos(heading), 0.0, math.sin(heading))
    return Part("spout", name, prims, anchors={"tip": tuple(tip), "tip_dir": d, "tip_r": (r, 0.0, 0.0)},
                regions={"grasp": Region(("spout",))})


def _neck(r, length):
    """Short horizontal tube from inside the wall (its inner end sits within the wall's
    thickness) out to x = ``length``, which the spout leaves from."""
    return ring(r, r - _WALL, length + _EMBED, pose=_ALONG_X.at((length - _EMBED) / 2, 0, 0),
                role="spout")


def _cone(p, name, base_r, tip_ratio, length, tilt, rise):
    rb = p.uniform("base_radius", *base_r)
    rt = p.uniform("tip_ratio", *tip_ratio) * rb
    a = p.uniform("tilt", *tilt)
    L = min(max(length[0], rise / math.sin(a)), length[1]) if rise is not None else p.uniform("length", *length)
    n = 2 * rb * math.sin(a) + 0.001  # the tilted base disc lies inside the neck
    x0 = n / 2 - 0.0005
    T = translation(x0, 0, 0) @ rot_y(math.pi / 2 - a)  # local z along the spout
    tip = (x0 + L * math.cos(a), 0.0, L * math.sin(a))
    cone = ring(rb, rb - _WALL, L, pose=T @ translation(0, 0, L / 2), role="spout", taper=rt - rb)
    return _spout(name, [_neck(rb, n), cone], tip, a, rt)


def cone_spout(p, rise: float | None = None) -> Part:
    """Straight tapered spout leaving the lower body at 35-55 deg (stovetop kettles)."""
    return _cone(p, "cone_spout", (0.012, 0.02), (0.35, 0.55), (0.06, 0.12), (0.6, 0.95), rise)


def lip_spout(p, rise: float | None = None) -> Part:
    """Short wide beak near the top of the wall (electric jugs)."""
    return _cone(p, "lip_spout", (0.012, 0.018), (0.55, 0.75), (0.02, 0.035), (0.25, 0.5), None)


def _path_end(segs, a: float):
    """End (x, z) and heading of a tube path of :func:`line` / :func:`arc` segments."""
    x = z = 0.0
    for kind, *v in segs:
        if kind == "line":
            x, z = x + v[0] * math.cos(a), z + v[0] * math.sin(a)
        else:
            s = math.copysign(v[0], v[1])
            x, z, a = x + s * (math.sin(a + v[1]) - math.sin(a)), z + s * (math.cos(a) - math.cos(a + v[1])), a + v[1]
    return x, z, a


def gooseneck_spout(p, rise: float | None = None) -> Part:
    """Thin S-shaped tube rising from the bottom of the body (pour-over kettles)."""
    r = p.uniform("radius", 0.0035, 0.006)
    a0 = p.uniform("start_angle", 0.2, 0.5)
    a1 = p.uniform("rise_angle", 1.0, 1.3)
    a2 = -p.uniform("tip_drop", 0.1, 0.5)
    segs = [line(p.uniform("root", 0.01, 0.02)), arc(p.uniform("bend", 0.015, 0.03), a1 - a0), line(0.0),
            arc(p.uniform("neck_bend", 0.015, 0.03), a2 - a1), line(p.uniform("tip", 0.01, 0.025))]
    z0 = _path_end(segs, a0)[1]
    segs[2] = line(max(0.01, ((rise or 0.1) - z0) / math.sin(a1)))  # the riser reaches ``rise``
    rn = r + p.uniform("boss", 0.001, 0.003)
    n = 2 * rn * math.sin(a0) + 0.001
    x, z, heading = _path_end(segs, a0)
    x0 = n / 2 - 0.0005
    prims = [_neck(rn, n)] + tube(r, segs, a0, translation(x0, 0, 0), role="spout")
    return _spout("gooseneck_spout", prims, (x0 + x, 0.0, z), heading, r)


SPOUTS = {cone_spout: 1.0, lip_spout: 1.0, gooseneck_spout: 1.0}


def whistle_cap(p, tip_radius: float) -> Part:
    """Flip cap over a spout's outlet with a thumb tab on top."""
    rc = tip_radius + p.uniform("wall", 0.0015, 0.003)
    L = p.uniform("length", 0.01, 0.018)
    tab = p.uniform("tab", 0.006, 0.012)
    prims = [cylinder(rc, L, _ALONG_X.at(0.0005 + L / 2, 0, -rc), role="cap"),
             cuboid(tab, 0.5 * rc, 0.002, translation(0.0005 + L / 2, 0, 0.0008), role="tab")]
    return Part("cap", "whistle_cap", prims, anchors={"radius": (rc, 0.0, 0.0)},
                regions={"push": Region(("tab",)), "lift": Region(("tab", "cap"))},
                grasps=Deferred(_cap_grasp, 0.0005 + L - 0.004, rc), actionable="hinge_lid")


def _cap_grasp(x: float, rc: float) -> list[Grasp]:
    """The grasp on a cap of radius ``rc``, approaching its outer end along -x at
    (x, 0, -rc), jaws closing along y (clear of the spout behind the hinge at any opening)."""
    T = np.array([[0.0, 0.0, -1.0, x], [0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, -rc], [0.0, 0.0, 0.0, 1.0]])
    return [Grasp(T, 2 * rc + 0.02)]


def mount_pose(tip, heading: float, cap_radius: float):
    """Hinge frame of a whistle cap on an outlet at ``tip`` (3,) heading ``heading``
    (radians above +x in the spout's x-z plane), in the spout frame."""
    return translation(*tip) @ rot_y(-heading) @ translation(0, 0, cap_radius)
