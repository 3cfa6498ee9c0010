"""Handle templates for fronts (doors, drawers, lids, appliance doors).

Frame convention shared by every template here, so they are interchangeable in any
handle slot: the origin is the centre of the mounting footprint on the surface, the
handle protrudes along **-x** (away from the surface) and its long axis is **+z**.
A caller mounts a horizontal handle by rotating the part about x by π/2.
Every template accepts ``length`` (grip span along z, metres) fixed by the parent;
the remaining parameters are drawn through the recorder ``p``.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, sphere, tube
from artipg.geometry.tube import arc, line
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.detail import edge_radius, rbox, rounded_disc

_X_AXIS = Placer(rot_y(math.pi / 2))  # local z -> object x


# gripper axes in the part frame: approach +z_g = +x (towards the surface), jaws close
# along +y_g = part y (across a vertical grip), x_g = -z completes the frame
_FRONT_GRASP = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_PULL = np.array([-1.0, 0.0, 0.0])


def front_grasp(x: float, y: float, z: float, width: float) -> Grasp:
    """A grasp approaching a front-mounted grip at (x, y, z) from -x, pulling along -x."""
    T = _FRONT_GRASP.copy()
    T[0, 3], T[1, 3], T[2, 3] = x, y, z
    return Grasp(T, width, _PULL)


def _grasps_along_z(x: float, z0: float, z1: float, width: float, k: int = 3) -> list[Grasp]:
    """``k`` front grasps spread along a vertical grip at depth x from z0 to z1."""
    return [front_grasp(x, 0.0, z0 + (z1 - z0) * i / (k - 1), width) for i in range(k)]


def _thirds_grasps(x: float, y: float, L: float, width: float) -> list[Grasp]:
    """Front grasps at (x, y) at -L/3, 0 and L/3 along z."""
    return [front_grasp(x, y, L * k / 3, width) for k in (-1, 0, 1)]


def bar_handle(p, length: float | None = None) -> Part:
    """Straight round bar on two posts (a "line fixed handle")."""
    L = p.uniform("length", 0.08, 0.35, fixed=length)
    r = p.uniform("bar_radius", 0.005, 0.009)
    post_r = min(r, p.uniform("post_radius", 0.004, 0.008))
    standoff = p.uniform("standoff", 0.025, 0.045)
    inset = p.uniform("post_inset", 0.0, 0.25) * L / 2
    x_bar = -standoff
    e = p.detail_uniform("end_round", 0.3, 0.8) * r  # domed bar ends, with detail
    prims = [rounded_disc(r, L, e, e, False, translation(x_bar, 0, 0), role="grip")]
    for s in (-1.0, 1.0):
        T = _X_AXIS.at(x_bar / 2 + r / 2, 0, s * (L / 2 - inset - post_r))  # spans x in [x_bar + r, 0]
        prims.append(cylinder(post_r, standoff - r, T, role="post"))
    return Part("handle", "bar_handle", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred(_grasps_along_z, x_bar, -L / 3, L / 3, 4 * r + 0.02),
                actionable="line_fixed_handle")


def arch_handle(p, length: float | None = None) -> Part:
    """Bent round-wire "D" handle: a tube with two rounded corners."""
    L = p.uniform("length", 0.08, 0.3, fixed=length)
    r = p.uniform("wire_radius", 0.004, 0.008)
    # the corners leave a straight grip of at least a fifth of the length
    bend = p.uniform("bend_radius", 1.5, max(1.5, min(3.0, 0.4 * L / r))) * r
    standoff = max(p.uniform("standoff", 0.025, 0.045), bend + 2 * r)
    segs = [line(standoff - bend), arc(bend, -math.pi / 2), line(L - 2 * bend), arc(bend, -math.pi / 2),
            line(standoff - bend)]
    # start at the lower mount point, heading -x (α = π), in the x-z plane
    prims = tube(r, segs, heading=math.pi, pose=translation(0, 0, -L / 2), role="grip")
    return Part("handle", "arch_handle", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred(_grasps_along_z, -standoff, -L / 4, L / 4, 4 * r + 0.02),
                actionable="line_fixed_handle")


def flat_bar_handle(p, length: float | None = None) -> Part:
    """Rectangular bar on two square posts (modern kitchen pull)."""
    L = p.uniform("length", 0.08, 0.4, fixed=length)
    t = p.uniform("bar_thickness", 0.008, 0.014)
    w = p.uniform("bar_width", 0.012, 0.025)
    standoff = p.uniform("standoff", 0.025, 0.04)
    prims = [rbox(t, w, L, edge_radius(p, t, hi=0.004, share=0.4), translation(-standoff + t / 2, 0, 0),
                  role="grip")]
    for s in (-1.0, 1.0):
        prims.append(cuboid(standoff - t, w * 0.8, w * 0.8, translation(-(standoff - t) / 2, 0, s * (L / 2 - w / 2)),
                            role="post"))
    return Part("handle", "flat_bar_handle", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred(_grasps_along_z, -standoff + t / 2, -L / 3, L / 3, w + 0.02),
                actionable="line_fixed_handle")


def knob_pull(p, length: float | None = None) -> Part:
    """Round mushroom knob on a stem (a "round fixed handle"); ``length`` is ignored."""
    R = p.uniform("head_radius", 0.012, 0.022)
    stem_r = p.uniform("stem_radius", 0.35, 0.6) * R
    stem = p.uniform("stem_length", 0.012, 0.025)
    head = p.uniform("head_height", 0.3, 0.8) * R
    e = edge_radius(p, head, "head_edge", lo=0.001, hi=0.005, share=0.4)  # rounded front rim, with detail
    prims = [cylinder(stem_r, stem, _X_AXIS.at(-stem / 2, 0, 0), role="stem"),
             rounded_disc(R, head, e, 0.0, False, _X_AXIS.at(-stem - head / 2, 0, 0), role="grip")]
    return Part("handle", "knob_pull", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred.one(front_grasp, -stem - head / 2, 0.0, 0.0, 2 * R + 0.02),
                actionable="round_fixed_handle")


def ball_knob_pull(p, length: float | None = None) -> Part:
    """Spherical knob on a short stem (a "round fixed handle")."""
    R = p.uniform("ball_radius", 0.01, 0.02)
    stem = p.uniform("stem_length", 0.01, 0.02)
    stem_r = 0.45 * R
    prims = [cylinder(stem_r, stem + 0.2 * R, _X_AXIS.at(-(stem + 0.2 * R) / 2, 0, 0), role="stem"),
             sphere(R, pose=translation(-stem - R, 0, 0), role="grip")]
    return Part("handle", "ball_knob_pull", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred.one(front_grasp, -stem - R, 0.0, 0.0, 2 * R + 0.02),
                actionable="round_fixed_handle")


def edge_pull(p, length: float | None = None) -> Part:
    """Thin ledge pull: a plate standing off the surface with a lip to hook fingers."""
    L = p.uniform("length", 0.08, 0.35, fixed=length)
    t = p.uniform("thickness", 0.004, 0.008)
    reach = p.uniform("reach", 0.02, 0.035)
    lip = p.uniform("lip", 0.012, 0.025)
    e = edge_radius(p, t, hi=0.003)
    prims = [cuboid(reach, t, L, translation(-reach / 2, 0, 0), role="mount"),
             rbox(t, lip, L, e, translation(-reach + t / 2, -lip / 2 + t / 2, 0), role="grip")]
    return Part("handle", "edge_pull", prims, regions={"grasp": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred(_thirds_grasps, -reach + t / 2, t / 2 - lip / 2, L, lip + 0.02),
                actionable="line_fixed_handle")


#: No front handle reaches further than this from its long axis (largest |y| of its
#: geometry in the handle frame), metres: a knob head or an edge-pull lip, 2.3 cm at most.
MAX_HALF_WIDTH = 0.025

#: Front handles, interchangeable (weights used by categories that do not override).
FRONT_HANDLES = {bar_handle: 3.0, arch_handle: 2.0, flat_bar_handle: 2.0, knob_pull: 1.5, ball_knob_pull: 1.0,
                 edge_pull: 1.0}
