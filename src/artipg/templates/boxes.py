"""Box parts: open-top box bodies (plain, with a drawer bay, grooved for a sliding lid),
hinged lids, carton flaps and the mounting of a lid on one edge of a box.

Frames: bodies have their origin at the centre of the footprint on the floor, +z up,
front towards -x; ``depth`` is along x, ``width`` along y. Hinged lids and flaps
have their origin on the hinge axis, which runs along their local y; closed, they
extend from the axis towards local -x (``length``) and up from z = 0, so a lid turns
open about +y (see :func:`mount_lid`).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, rect_ring, tri_prism
from artipg.geometry.transforms import IDENTITY, Placer, rot_x, rot_z, translation
from artipg.model.part import Part, Region

#: hinge edge of a box -> yaw of the lid frame (the lid extends towards its local -x)
EDGE_YAW = {"+x": 0.0, "+y": math.pi / 2, "-x": math.pi, "-y": -math.pi / 2}
_EDGE_TURN = {edge: Placer(rot_z(yaw)) for edge, yaw in EDGE_YAW.items()}
_FLAT = Placer(rot_x(math.pi / 2))  # a prism's triangle in the x-z plane


def open_box(p, depth: float, width: float, height: float, wall: float | None = None, z0: float = 0.0,
             bay: float = 0.0) -> Part:
    """Open-top box from ``z0`` up to ``z0 + height``.

    With ``bay`` > 0 the lowest ``bay`` metres form a drawer bay open at the front
    (-x): the front wall starts above it, a floor board closes the compartment above.
    Anchors ``bay_lo``/``bay_hi`` are the bay's inner corners.
    """
    t = p.uniform("wall", 0.006, 0.02, fixed=wall)
    D, W, z1 = depth / 2, width / 2, z0 + height
    prims = [cuboid_between((-D, -W, z0), (D, W, z0 + t), role="bottom"),
             cuboid_between((-D, -W, z0 + t), (D, -W + t, z1), role="wall"),
             cuboid_between((-D, W - t, z0 + t), (D, W, z1), role="wall"),
             cuboid_between((D - t, -W + t, z0 + t), (D, W - t, z1), role="wall"),
             cuboid_between((-D, -W + t, z0 + (bay or t)), (-D + t, W - t, z1), role="wall")]
    if bay:
        prims.append(cuboid_between((-D + t, -W + t, z0 + bay), (D - t, W - t, z0 + bay + t), role="bottom"))
    return Part("body", "open_box", prims, anchors={"top": (0.0, 0.0, z1), "bay_lo": (-D, -W + t, z0 + t),
                                                    "bay_hi": (D - t, W - t, z0 + bay)},
                regions={"lift": Region(("wall",))})


def grooved_box(p, depth: float, width: float, height: float, lid: float, wall: float | None = None) -> Part:
    """Open-top box for a sliding lid: grooves in the side walls (y = +-width/2) near
    the top hold a lid ``lid`` thick, the front wall is cut down to the groove so the
    lid slides out towards -x. Anchor ``groove``: (x of the back wall's inner face,
    distance from the centre to the groove bottoms, z of the groove floor)."""
    t = p.uniform("wall", 0.006, 0.015, fixed=wall)
    c = 0.001
    zg = height - p.uniform("lip", 0.5, 1.0) * t - lid - 2 * c  # groove floor
    g = p.uniform("groove_depth", 0.4, 0.6) * t
    D, W = depth / 2, width / 2
    prims = [cuboid_between((-D, -W, 0), (D, W, t), role="bottom"),
             cuboid_between((D - t, -W + t, t), (D, W - t, height), role="wall"),
             cuboid_between((-D, -W + t, t), (-D + t, W - t, zg), role="wall")]
    for s in (-1.0, 1.0):
        outer, inner = s * W, s * (W - t)
        prims += [cuboid_between((-D, min(outer, inner), t), (D, max(outer, inner), zg), role="wall"),
                  cuboid_between((-D, min(outer, outer - s * (t - g)), zg), (D, max(outer, outer - s * (t - g)),
                                                                               height), role="wall"),
                  cuboid_between((-D, min(outer, inner), zg + lid + 2 * c), (D, max(outer, inner), height),
                                 role="wall")]
    return Part("body", "grooved_box", prims, anchors={"groove": (D - t, W - t + g, zg), "top": (0.0, 0.0, height)},
                regions={"lift": Region(("wall",))})


def _lid(template, prims, length, width, top) -> Part:
    grip = np.array([[-length - 1e-3, -width / 2, 0.0], [-length + 0.02, width / 2, top]])
    return Part("lid", template, prims, anchors={"front": (-length, 0.0, top / 2), "top": (-length / 2, 0.0, top)},
                regions={"lift": Region((), grip), "grasp": Region((), grip)}, actionable="hinge_lid")


def slab_lid(p, length: float, width: float, thickness: float | None = None) -> Part:
    """Flat lid."""
    t = p.uniform("thickness", 0.006, 0.02, fixed=thickness)
    return _lid("slab_lid", [cuboid_between((-length, -width / 2, 0), (0, width / 2, t), role="top")],
                length, width, t)


def raised_lid(p, length: float, width: float, thickness: float | None = None) -> Part:
    """Flat lid with a raised (fielded) centre panel."""
    t = p.uniform("thickness", 0.006, 0.018, fixed=thickness)
    m = p.uniform("margin", 0.1, 0.2) * min(length, width)
    h = p.uniform("panel_height", 0.3, 0.8) * t
    prims = [cuboid_between((-length, -width / 2, 0), (0, width / 2, t), role="top"),
             cuboid_between((-length + m, -width / 2 + m, t), (-m, width / 2 - m, t + h), role="panel")]
    return _lid("raised_lid", prims, length, width, t + h)


def gable_lid(p, length: float, width: float, thickness: float | None = None) -> Part:
    """Lid with a low pitched top (a trunk or chest lid): a slab under a wedge."""
    t = p.uniform("thickness", 0.008, 0.02, fixed=thickness)
    h = p.uniform("pitch", 0.06, 0.15) * length
    prims = [cuboid_between((-length, -width / 2, 0), (0, width / 2, t), role="top"),
             tri_prism(length, h, 0.0, width, _FLAT.at(-length / 2, 0, t), role="top")]
    return _lid("gable_lid", prims, length, width, t + h)


def cap_lid(p, length: float, width: float, thickness: float | None = None, skirt: float | None = None,
            skirt_thickness: float | None = None) -> Part:
    """Lid with a skirt hanging down around the body (a shoebox-style cap). Closed, the
    skirt spans z in [0, skirt] and the top plate sits above it; ``length`` and
    ``width`` are the outer sizes, the axis is the skirt's bottom back edge."""
    t = p.uniform("thickness", 0.005, 0.015, fixed=thickness)
    sk = p.uniform("skirt", 0.015, 0.04, fixed=skirt)
    st = p.uniform("skirt_thickness", 0.004, 0.01, fixed=skirt_thickness)
    prims = [cuboid_between((-length, -width / 2, sk), (0, width / 2, sk + t), role="top"),
             rect_ring(length, width, sk, length - 2 * st, width - 2 * st, translation(-length / 2, 0, sk / 2),
                       role="skirt")]
    part = _lid("cap_lid", prims, length, width, sk + t)
    part.anchors["skirt"] = (st, 0.0, sk)
    return part


HINGED_LIDS = {slab_lid: 3.0, raised_lid: 2.0, cap_lid: 1.5, gable_lid: 1.0}


def flap(p, length: float, width: float, thickness: float | None = None) -> Part:
    """Carton flap: a thin board folding about its hinge edge."""
    t = p.uniform("thickness", 0.003, 0.006, fixed=thickness)
    grip = np.array([[-length - 1e-3, -width / 2, 0.0], [-length + 0.02, width / 2, t]])
    return Part("flap", "flap", [cuboid_between((-length, -width / 2, 0), (0, width / 2, t), role="board")],
                regions={"lift": Region((), grip), "grasp": Region((), grip)}, actionable="hinge_lid")


def mount_lid(builder, parent, part, axis_point, edge: str, limits, name: str = "lid", pose=None):
    """Hinge a lid or flap (frame as in the module docstring) on the ``edge`` ("+x",
    "-x", "+y", "-y") of a box: the joint frame sits at ``axis_point`` (3,), yawed so
    that the lid extends inwards from that edge; positive values lift it. ``pose``
    (4, 4) places the part in the joint frame (e.g. lowered for a lid set flush in an
    opening, whose axis is its top back edge)."""
    link = builder.create_link(name, parent)
    link.set_joint("revolute", _EDGE_TURN[edge].at(*axis_point), axis=(0.0, 1.0, 0.0), limits=limits)
    link.add(part, IDENTITY if pose is None else pose)
    return link
