"""Printer parts: a housing with paper slots, output trays and hinged plates (paper
supports, scanner and feeder lids, output flaps, tilting control panels).

Frames:
- ``slotted_housing``: the object frame (front at x = -depth / 2 facing -x, floor
  z = 0, centred on the z axis); each slot is a cavity open at the front.
- ``output_tray``: origin at the centre of its front lip's back face (the housing's
  front plane), the tray extends along +x; slide it along -x.
- ``hinged_plate``: the hinge frame, origin on the hinge axis (+y) at the plate's back
  edge, its top face on z = 0, the plate along -x from it; a positive turn lifts its
  front. Lying on a surface, put the axis ``thickness`` + a rest gap above it.
- ``tilt_panel``: front-panel convention (back face on x = 0, the plate in
  x in [-thickness, 0]); hinge it on its bottom edge with ``mount_hinged``.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid, cuboid_between
from artipg.geometry.transforms import translation
from artipg.model.part import Deferred, Grasp, Part, Region

# gripper approaching +x (a slab's front edge), jaws closing along z (pinch)
_EDGE = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_UP = np.array([0.0, 0.0, 1.0])


def _pinch(x: float, z: float, t: float) -> Grasp:
    T = _EDGE.copy()
    T[0, 3], T[2, 3] = x, z
    return Grasp(T, t + 0.02, _UP)


def slotted_housing(p, depth: float, width: float, height: float, slots) -> Part:
    """Box housing with cavities open at the front.

    ``slots`` = [(z0, z1, width, depth)] sorted by z, not overlapping: each is a
    cavity of that height range, centred in y, reaching ``depth`` back from the front.
    Anchors ``slot<i>`` = (front x, 0, z0) of each slot.
    """
    D, W = depth / 2, width / 2
    prims, z, anchors = [], 0.0, {"front": (-D, 0.0, 0.0), "top": (0.0, 0.0, height)}
    for i, (z0, z1, w, d) in enumerate(slots):
        if z0 > z:
            prims.append(cuboid_between((-D, -W, z), (D, W, z0), role="shell"))
        prims += [cuboid_between((-D, -W, z0), (D, -w / 2, z1), role="shell"),
                  cuboid_between((-D, w / 2, z0), (D, W, z1), role="shell"),
                  cuboid_between((-D + d, -w / 2, z0), (D, w / 2, z1), role="shell")]
        anchors[f"slot{i}"] = (-D, 0.0, z0)
        z = z1
    prims.append(cuboid_between((-D, -W, z), (D, W, height), role="shell"))
    return Part("body", "slotted_housing", prims, anchors=anchors,
                regions={"grasp": Region(("shell",)), "lift": Region(("shell",))})


def output_tray(p, depth: float, width: float, height: float) -> Part:
    """Output tray: a 2-4 mm plate ``depth`` x ``width`` with a front lip ``height``
    tall (6-10 mm thick) standing in front of the housing's front plane."""
    t = p.uniform("plate", 0.002, 0.004)
    lt = p.uniform("lip", 0.006, 0.01)
    prims = [cuboid_between((0.0, -width / 2, 0.0), (depth, width / 2, t), role="plate"),
             cuboid_between((-lt, -width / 2, 0.0), (0.0, width / 2, height), role="lip")]
    return Part("tray", "output_tray", prims, anchors={"front": (-lt, 0.0, height / 2)},
                regions={"pull": Region(("lip",)), "push": Region(("lip",)), "grasp": Region(("lip",))},
                grasps=Deferred.one(_pinch, -lt + 0.002, height / 2, height), actionable="slider_drawer")


def hinged_plate(p, semantic: str, length: float, width: float, thickness: float | None = None,
                 actionable: str = "hinge_lid") -> Part:
    """Plate ``length`` x ``width`` (4-12 mm thick) in the hinge frame, with a finger
    lip 3-6 mm proud under its front edge (a scanner lid, feeder cover, paper support
    or output flap)."""
    t = p.uniform("thickness", 0.004, 0.012, fixed=thickness)
    lt = p.uniform("lip", 0.004, 0.008)
    prims = [cuboid_between((-length, -width / 2, -t), (0.0, width / 2, 0.0), role="plate"),
             cuboid_between((-length - lt, -0.3 * width, -t), (-length, 0.3 * width, 0.0), role="lip")]
    box = np.array([[-length - lt - 1e-3, -0.3 * width, -t - 1e-3], [-length + 0.03, 0.3 * width, 1e-3]])
    return Part(semantic, "hinged_plate", prims, anchors={"front": (-length - lt, 0.0, -t / 2), "bottom": (0, 0, -t)},
                regions={"lift": Region(("plate", "lip"), box), "pull": Region(("lip",)), "grasp": Region(("lip",))},
                grasps=Deferred.one(_pinch, -length - lt + 0.003, -t / 2, t), actionable=actionable)


def tilt_panel(p, width: float, height: float) -> Part:
    """Control panel plate ``width`` x ``height``, 8-15 mm thick (front convention)."""
    t = p.uniform("thickness", 0.008, 0.015)
    front = np.array([[-t - 1e-4, -width / 2, -height / 2], [-t + 1e-4, width / 2, height / 2]])
    top = np.array([[-t - 1e-3, -width / 2, height / 2 - 0.01], [1e-3, width / 2, height / 2 + 1e-3]])
    return Part("panel", "tilt_panel", [cuboid(t, width, height, translation(-t / 2, 0, 0), role="plate")],
                anchors={"front": (-t, 0.0, 0.0), "edge_+z": (-t, 0.0, height / 2)},
                regions={"push": Region(("plate",), front), "pull": Region(("plate",), top)},
                grasps=Deferred.one(_pinch_top, -t / 2, height / 2, t), actionable="hinge_door")


def _pinch_top(x: float, z: float, t: float) -> Grasp:
    """A grasp from above on a vertical plate's top edge (jaws across its thickness)."""
    G = np.array([[0.0, 1.0, 0.0, x], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, z - 0.004], [0.0, 0.0, 0.0, 1.0]])
    return Grasp(G, t + 0.02, np.array([-1.0, 0.0, 0.0]))
