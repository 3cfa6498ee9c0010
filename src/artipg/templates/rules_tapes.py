"""Measuring-tool parts: folding-rule segments, and a tape measure's case, blade,
lock slider and belt clip.

Segment frame: the pivot it turns about at the origin, the segment lying along +x
with its far pivot at x = ``pitch``, its bottom face on z = 0, ``thickness`` thick,
``width`` across (y); its ends reach half the width past the pivots; a rivet head
on the top face over the origin (anchor ``next`` = the far pivot on the top face).

Tape case frame: the case stands on z = 0, its mouth at the front (x = 0, the case
reaching back along +x to ``length``), ``width`` along y, centred; the blade leaves
through a slot ``slot`` = (z_bottom, z_top) high across the middle ``channel`` of the
width. Blade frame: the hook's inner face at x = 0 (against the case front at rest),
the strip along +x in the slot, its bottom face on z = 0. Slider frame: the front
face (x = 0) of the case, the slider's back face on it, sliding down (-z). Metres.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import Placer, rot_x, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.levers import top_grasp

RIVET_HEAD = 0.0005  # rivet head height on a segment's top face
_XZ = Placer(rot_x(math.pi / 2))  # outline (x, y) -> object (x, z), extruded along y


def _outline(pitch: float, r: float, ends: str) -> np.ndarray:
    """Plan outline round the pivots (0, 0) and (``pitch``, 0), reaching ``r`` past
    each along x and across y; ``ends`` "round" (4-chord half-polygons: polygons keep
    the caps' sampling exact), "chamfered" or "square"."""
    if ends == "round":
        a = np.linspace(-0.5 * math.pi, 0.5 * math.pi, 5)
        cap = np.column_stack([r * np.cos(a), r * np.sin(a)])
    elif ends == "chamfered":
        cap = np.array([[0.6 * r, -r], [r, -0.4 * r], [r, 0.4 * r], [0.6 * r, r]])
    else:
        cap = np.array([[r, -r], [r, r]])
    return profile.polygon(np.vstack([cap + [pitch, 0.0], -cap]))


SEGMENT_ENDS = {"round": 3.0, "chamfered": 1.0, "square": 1.0}


def segment(p, ends: str, semantic: str, pitch: float, width: float, thickness: float, rivet: float,
            reach: float) -> Part:
    """A flat rule segment (see module docstring) with a rivet head of radius
    ``rivet`` over its pivot (0: none); grasped from above at ``reach`` along it."""
    prims = [extrusion([_outline(pitch, width / 2, ends)], thickness, pose=translation(0.0, 0.0, thickness / 2),
                       role="segment")]
    if rivet > 0:
        prims.append(cylinder(rivet, RIVET_HEAD, translation(0.0, 0.0, thickness + RIVET_HEAD / 2), role="rivet"))
    g = Deferred.one(top_grasp, reach, 0.0, thickness / 2, width + 0.02, "y", (0.0, 0.0, 0.0))
    return Part(semantic, f"{ends}_segment", prims, anchors={"next": (pitch, 0.0, thickness)},
                regions={"grasp": Region(("segment",)), "rotate": Region(("segment",))}, grasps=g,
                actionable="hinge_handle")


def _case_outline(length: float, height: float, rc: float, z0: float, rb: float) -> np.ndarray:
    """Side outline (x, z) of a tape case from z = ``z0`` up: square front-bottom
    corner (the mouth), top corners rounded by ``rc``, back-bottom corner by ``rb``."""
    def corner(cx, cz, r, a0):
        a = a0 + np.linspace(0.0, 0.5 * math.pi, 4)
        return list(zip(cx + r * np.cos(a), cz + r * np.sin(a)))
    pts = [(0.0, z0), *corner(length - rb, z0 + rb, rb, -0.5 * math.pi), *corner(length - rc, height - rc, rc, 0.0),
           *corner(rc, height - rc, rc, 0.5 * math.pi)]
    return profile.polygon(pts)


def tape_case(p, length: float, width: float, height: float, slot: tuple, channel: float) -> Part:
    """A tape-measure case: two cheeks, the core above the blade slot and the floor
    below it (see module docstring); regions ``grasp`` on the cheeks."""
    tc = 0.5 * (width - channel)
    rc = p.uniform("corner", 0.2, 0.35) * height
    rb = min(p.uniform("back_corner", 0.1, 0.3) * height, 0.9 * slot[1])
    z0, z1 = slot
    cheek = _case_outline(length, height, rc, 0.0, rb)
    prims = [extrusion([cheek], tc, pose=_XZ.at(0.0, s * (channel + tc) / 2, 0.0), role="shell") for s in (1.0, -1.0)]
    core = _case_outline(length, height, rc, z1, min(rb, 0.5 * rc))
    prims.append(extrusion([core], channel, pose=_XZ.matrix, role="shell"))
    prims.append(cuboid_between((0.0, -channel / 2, 0.0), (length - rb, channel / 2, z0), role="floor"))
    g = Deferred.one(top_grasp, 0.5 * length, 0.0, height, width + 0.02, "y", (0.0, 0.0, 0.0))
    # front_top: where the front face's rounding starts; top_flat: the flat top's length
    return Part("body", "tape_case", prims, anchors={"front_top": (0.0, 0.0, height - rc),
                                                     "top_flat": (length - 2 * rc, 0.0, height)},
                regions={"grasp": Region(("shell",))}, grasps=g)


def tape_blade(p, strip: float, width: float, thickness: float, hook: tuple, grip: float) -> Part:
    """The blade: a ``strip`` long steel strip (``thickness`` thick, bottom on z = 0)
    along +x and the end hook in front of x = 0, ``hook`` = (depth, drop, rise) its
    thickness along x, reach below the strip and above it; grasped from above across
    the strip at x = ``grip`` (out of the case when pulled)."""
    hd, drop, rise = hook
    prims = [cuboid_between((0.0, -width / 2, 0.0), (strip, width / 2, thickness), role="strip"),
             cuboid_between((-hd, -width / 2, -drop), (0.0, width / 2, thickness + rise), role="hook")]
    g = Deferred.one(top_grasp, grip, 0.0, thickness / 2, width + 0.02, "y", (-1.0, 0.0, 0.0))
    return Part("blade", "tape_blade", prims, regions={"grasp": Region(("hook", "strip")), "pull": Region(("hook",))},
                grasps=g, actionable="slider_drawer")


def lock_slider(p, width: float, height: float, depth: float) -> Part:
    """A lock button on the case front (its back face on x = 0), ``width`` along y."""
    prims = [cuboid_between((-depth, -width / 2, -height / 2), (0.0, width / 2, height / 2), role="button")]
    return Part("switch", "lock_slider", prims, regions={"press": Region(("button",)), "push": Region(("button",))},
                actionable="slider_button")


def belt_clip(p, length: float, height: float, gap: float, t: float) -> Part:
    """A spring belt clip on a case side (its root face on y = 0, the clip outward
    along +y): a block at the top and a plate hanging down ``gap`` off the side."""
    root = min(0.3 * height, 0.012)
    prims = [cuboid_between((-length / 2, 0.0, -root), (length / 2, gap, 0.0), role="clip"),
             cuboid_between((-length / 2, gap, -height), (length / 2, gap + t, 0.0), role="clip")]
    return Part("clip", "belt_clip", prims)
