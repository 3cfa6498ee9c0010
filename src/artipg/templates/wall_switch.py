"""Wall-switch templates: cover plates, rocker paddles with their bezels, and toggles.

Plate frame (plates and surface-mounted boxes): the plate stands in the y-z plane,
back face on the wall at x = 0,
front facing -x, centred on y = z = 0; anchor ``face`` is the centre of the surface
that switch modules mount on (x < 0).

Rocker frame: origin on the pivot axis (+y), at the centre of the paddle's back face;
the paddle spans x in [-depth, 0]. Toggle frame: origin at the centre of the pivot
ball, the lever points along -x. Both are mounted by :func:`mount_tilting`, which
tilts them to ``-tilt`` at rest (one side pressed) with limits (0, 2 tilt), like
real two-position switches. :func:`rocker_module` and :func:`toggle_module` build a
whole module (fixed bezel or escutcheon on the plate plus the moving part) and
derive the largest tilt that keeps every edge off the plate.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, frustum, rect_ring, ring, sphere, tri_prism
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part, Region

_X = Placer(rot_y(math.pi / 2))   # local z -> object x (rings facing -x)
_MX = Placer(rot_y(-math.pi / 2))   # local z -> object -x (frustums pointing out of the wall)
# tri-prism wedge: triangle base along z, apex towards -x, extruded along y
_WEDGE = Placer(np.array([[0.0, -1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]))


def _plate(name, prims, face_x):
    return Part("body", name, prims, anchors={"face": (face_x, 0.0, 0.0)}, regions={"grasp": Region(("plate",))})


def flat_plate(p, width: float, height: float) -> Part:
    """Plain cover plate."""
    t = p.uniform("thickness", 0.003, 0.008)
    return _plate("flat_plate", [cuboid(t, width, height, translation(-t / 2, 0, 0), role="plate")], -t)


def stepped_plate(p, width: float, height: float) -> Part:
    """Plate with a raised, slightly smaller centre panel."""
    t = p.uniform("thickness", 0.003, 0.006)
    t2 = p.uniform("step", 0.0015, 0.003)
    m = p.uniform("step_inset", 0.002, 0.005)
    return _plate("stepped_plate", [cuboid(t, width, height, translation(-t / 2, 0, 0), role="plate"),
                                    cuboid(t2, width - 2 * m, height - 2 * m, translation(-t - t2 / 2, 0, 0),
                                           role="plate")], -t - t2)


def framed_plate(p, width: float, height: float) -> Part:
    """European style: a deep frame around a flush-mounted insert."""
    tf = p.uniform("frame_depth", 0.008, 0.011)
    fw = p.uniform("frame_width", 0.005, 0.009)
    ti = tf - p.uniform("recess", 0.001, 0.003)
    return _plate("framed_plate", [rect_ring(height, width, tf, height - 2 * fw, width - 2 * fw,
                                             _X.at(-tf / 2, 0, 0), role="plate"),
                                   cuboid(ti, width - 2 * fw, height - 2 * fw, translation(-ti / 2, 0, 0),
                                          role="insert")], -ti)


def surface_box(p, width: float, height: float, depth: float = 0.05) -> Part:
    """Surface-mounted switch box: a deep box (``depth`` metres out of the wall) with a
    cover plate a little larger than the box on its front."""
    t = p.uniform("cover_thickness", 0.003, 0.006)
    lip = p.uniform("cover_lip", 0.001, 0.004)
    box = cuboid(depth - t, width - 2 * lip, height - 2 * lip, translation(-(depth - t) / 2, 0, 0), role="box")
    return _plate("surface_box", [box, cuboid(t, width, height, translation(t / 2 - depth, 0, 0), role="plate")],
                  -depth)


PLATES = {flat_plate: 2.0, stepped_plate: 1.5, framed_plate: 1.5}
#: plate template -> margin it needs around the switch modules (metres)
PLATE_MARGIN = {flat_plate: 0.008, stepped_plate: 0.01, framed_plate: 0.012, surface_box: 0.01}


def flat_rocker(p, width: float, height: float) -> Part:
    """Flat rocker paddle."""
    d = p.uniform("depth", 0.004, 0.007)
    return Part("switch", "flat_rocker", [cuboid(d, width, height, translation(-d / 2, 0, 0), role="cap")],
                anchors={"front": (-d, 0.0, 0.0)}, regions={"press": Region(("cap",)), "push": Region(("cap",))})


def crowned_rocker(p, width: float, height: float) -> Part:
    """Rocker paddle with a ridge across its middle (the classic see-saw profile)."""
    d = p.uniform("depth", 0.003, 0.005)
    ridge = p.uniform("ridge", 0.0015, 0.003)
    prims = [cuboid(d, width, height, translation(-d / 2, 0, 0), role="cap"),
             tri_prism(height, ridge, 0.0, width, _WEDGE.at(-d, 0, 0), role="cap")]
    return Part("switch", "crowned_rocker", prims, anchors={"front": (-d - ridge, 0.0, 0.0)},
                regions={"press": Region(("cap",)), "push": Region(("cap",))})


ROCKERS = {flat_rocker: 1.0, crowned_rocker: 1.0}


def toggle_lever(p, length: float | None = None) -> Part:
    """Toggle: a pivot ball and a tapered bat lever."""
    rb = p.uniform("ball_radius", 0.003, 0.0045)
    L = p.uniform("length", 0.01, 0.018, fixed=length)
    r0 = p.uniform("lever_radius", 0.45, 0.7) * rb
    r1 = max(0.00085, p.uniform("tip_ratio", 0.55, 1.0) * r0)
    prims = [sphere(rb, role="pivot"), frustum(r0, r1, L, _MX.at(-L / 2, 0, 0), role="lever")]
    return Part("switch", "toggle_lever", prims, anchors={"front": (-L, 0.0, 0.0), "ball": (rb, 0.0, 0.0)},
                regions={"push": Region(("lever",)), "grasp": Region(("lever",))})


def mount_tilting(builder, parent, part, pose: np.ndarray, tilt: float, name: str = "switch"):
    """Attach ``part`` revolute about the pose's +y, resting at ``-tilt``, limits (0, 2 tilt)."""
    link = builder.create_link(name, parent)
    link.set_joint("revolute", pose @ rot_y(-tilt), axis=(0.0, 1.0, 0.0), limits=(0.0, 2 * tilt))
    link.add(part)
    return link


def rocker_module(p, builder, plate_link, pose: np.ndarray, width: float, height: float, template):
    """A rocker paddle ``width`` x ``height`` in a bezel; ``pose`` is the mount point on
    the plate's face (x = 0 there, -x out of the wall)."""
    paddle = template(p, width, height)
    depth = -float(paddle.anchors["front"][0])
    stand = p.uniform("stand_off", 0.003, 0.006)
    tilt = min(p.uniform("tilt", 0.1, 0.22), 0.9 * math.atan(stand / (height / 2)))
    cz = depth * math.sin(tilt) + 0.0008  # top / bottom clearance of the tilting paddle
    fb = p.uniform("bezel_width", 0.002, 0.004)
    bd = stand + 0.5 * depth
    bezel = rect_ring(height + 2 * (cz + fb), width + 2 * (0.0006 + fb), bd, height + 2 * cz, width + 0.0012,
                      pose @ translation(-bd / 2, 0, 0) @ _X.matrix, role="bezel")
    plate_link.add(Part("body", "rocker_bezel", [bezel]), name="bezel")
    return mount_tilting(builder, plate_link, paddle, pose @ translation(-stand, 0, 0), tilt)


def toggle_module(p, builder, plate_link, pose: np.ndarray, width: float, height: float):
    """A toggle lever on a small escutcheon boss (``width`` x ``height`` at most)."""
    lever = toggle_lever(p)
    rb = float(lever.anchors["ball"][0])
    t = p.uniform("boss_depth", 0.0015, 0.003)
    bw, bh = min(width, p.uniform("boss_width", 0.01, 0.016)), min(height, p.uniform("boss_height", 0.02, 0.03))
    # threaded bushing around the back half of the pivot ball
    gap, wall = 0.0004, p.uniform("bushing_wall", 0.0015, 0.0025)
    hb = rb + 0.0008
    bushing = ring(rb + gap + wall, rb + gap, hb, pose=pose @ translation(-t - hb / 2, 0, 0) @ _X.matrix, role="boss")
    plate_link.add(Part("body", "toggle_boss", [cuboid(t, bw, bh, pose @ translation(-t / 2, 0, 0), role="boss"),
                                                bushing]), name="boss")
    return mount_tilting(builder, plate_link, lever, pose @ translation(-t - rb - 0.0008, 0, 0),
                         p.uniform("tilt", 0.3, 0.45))


def button_bezel(p, part: Part, pose: np.ndarray, round_cap: bool) -> Part:
    """Fixed bezel around a push-button cap mounted at ``pose`` (see
    :mod:`artipg.templates.controls`): it surrounds the back half of the cap with
    0.5 mm clearance (round ones 0.8 mm: more than the 0.5 mm by which the simulators'
    faceted rings cut inside round ones), so the cap slides in it without touching."""
    lo, hi = part.bounds()
    depth = -(lo[0] + hi[0]) / 2  # from the surface to the cap's middle
    w = p.uniform("bezel_width", 0.0015, 0.003)
    T = pose @ translation(-depth / 2, 0, 0) @ _X.matrix
    if round_cap:
        r = max(hi[1], hi[2]) + 0.0008
        prim = ring(r + w, r, depth, pose=T, role="bezel")
    else:
        iy, iz = hi[1] - lo[1] + 0.001, hi[2] - lo[2] + 0.001
        prim = rect_ring(iz + 2 * w, iy + 2 * w, depth, iz, iy, T, role="bezel")
    return Part("body", "button_bezel", [prim])
