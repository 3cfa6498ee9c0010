"""Lids for vessels (buckets, pots, pails, trash cans, jars).

Frame: origin at the centre of the vessel's rim plane, +z up out of the vessel. A lid
rests on the rim (its underside at z = 0) and covers ``radius``, the rim's outer
radius (a round rim, or the circumradius of a ``prism_shell`` rim when ``sides`` = n:
polygon lids use the vertex orientation of :func:`artipg.geometry.prism`), plus an
overhang. An optional skirt hangs outside the rim below z = 0.
Anchors: ``top`` (highest point on the axis), ``hinge`` (bottom outer edge at +x, where
a flip hinge goes), ``front`` (outer edge at -x). Attach with :func:`mount_lid`, which
lifts the lid straight up (prismatic, ``slider_lid``) or flips it open about a +y hinge
at the back (revolute, ``hinge_lid``).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, prism, ring, sphere
from artipg.geometry.transforms import translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.detail import edge_radius, rounded_disc
from artipg.templates.levers import top_grasp

# gripper approaching +x (the lid's front edge), jaws closing along z (pinch)
_EDGE = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_UP = np.array([0.0, 0.0, 1.0])


def _disc(R: float, t: float, sides, z0: float = 0.0, role: str = "disc"):
    T = translation(0, 0, z0 + t / 2)
    return cylinder(R, t, T, role=role) if sides is None else prism(R, t, int(sides), T, role=role)


def _apothem(R: float, sides) -> float:
    return R if sides is None else R * math.cos(math.pi / sides)


def _edge_grasp(a: float, t: float, skirt: float) -> list[Grasp]:
    """A pinch on a lid's front edge (disc and skirt) at apothem ``a``."""
    T = _EDGE.copy()
    T[0, 3], T[2, 3] = -a + 0.01, (t - skirt) / 2
    return [Grasp(T, t + skirt + 0.02, _UP)]


def _lid(template, prims, R, t, skirt, top, sides, grip_roles=("disc",), grasps=None) -> Part:
    a = _apothem(R, sides)
    if grasps is None:
        grasps = Deferred(_edge_grasp, a, t, skirt)
    if grip_roles != ("disc",):
        regions = {"lift": Region(grip_roles), "grasp": Region(grip_roles)}
    else:  # the front edge
        edge = np.array([[-a - 1e-3, -0.4 * a, -skirt - 1e-3], [-a + 0.03, 0.4 * a, t + 1e-3]])
        regions = {"lift": Region(grip_roles), "grasp": Region(("disc", "skirt"), edge)}
    return Part("lid", template, prims, anchors={"top": (0.0, 0.0, top), "hinge": (a, 0.0, -skirt),
                                                  "front": (-a, 0.0, 0.0)},
                regions=regions, grasps=grasps)


def _base(p, radius, sides, skirt_p):
    R = radius + p.uniform("overhang", 0.002, 0.008)
    t = p.uniform("thickness", 0.003, 0.01)
    prims = []
    s = 0.0
    if sides is None and p.flag("skirt", skirt_p):
        s = p.uniform("skirt_length", 0.006, 0.015)
        # wall at least 1.5 mm (simulators reject thinner meshes), >= 1 mm off the rim
        R = max(R, radius + 0.0025)
        wall = max(0.0015, 0.5 * (R - radius))
        # hinged at the skirt's back bottom edge (mount_lid), the lid swings the front of
        # its skirt in towards the rim before the skirt clears it: the skirt is short
        # enough to stay 0.5 mm off the rim all the way (more than the simulators'
        # faceted rings cut inside round ones)
        g = R - wall - radius
        s = min(s, math.sqrt((g - 0.0005) * (2.0 * (R + radius) + g)))
        prims.append(ring(R, R - wall, s, pose=translation(0, 0, -s / 2), role="skirt"))
    # the disc keeps its sharp rim: a rounded one (a lathe) reaches the simulators as
    # a faceted hull that blocks tight kettle lids; the knob carries the detail
    return R, t, s, [_disc(R, t, sides)] + prims


def flat_lid(p, radius: float, sides: int | None = None) -> Part:
    """Flat disc (or polygon) lid, round ones optionally with a skirt over the rim."""
    R, t, s, prims = _base(p, radius, sides, 0.5)
    return _lid("flat_lid", prims, R, t, s, t, sides)


def domed_lid(p, radius: float, sides: int | None = None) -> Part:
    """Flat rim flange with a spherical dome rising from it."""
    R, t, s, prims = _base(p, radius, sides, 0.3)
    a = p.uniform("dome_ratio", 0.75, 0.95) * _apothem(R, sides)
    hd = p.uniform("dome_height", 0.15, 0.45) * a
    Rs = (a * a + hd * hd) / (2 * hd)
    prims.append(sphere(Rs, Rs - hd, Rs, translation(0, 0, t - Rs + hd), role="dome"))
    return _lid("domed_lid", prims, R, t, s, t + hd, sides)


def _knob(p, z0: float):
    """A lid knob standing on z0: stem and a cap; returns prims, top z and grasps: from
    above, and from the side (-y) for when a handle arches over the lid."""
    rs = p.uniform("stem_radius", 0.006, 0.012)
    hs = p.uniform("stem_height", 0.008, 0.02)
    rk = p.uniform("knob_radius", 1.3, 2.2) * rs
    hk = p.uniform("knob_height", 0.01, 0.02)
    # with detail the cap's top rim is rounded (a softer grip), up to 40 % of its height
    e = edge_radius(p, hk, "knob_edge", lo=0.001, hi=0.005, share=0.4)
    prims = [cylinder(rs, hs + 0.001, translation(0, 0, z0 + hs / 2 - 0.0005), role="stem"),
             rounded_disc(rk, hk, e, 0.0, False, translation(0, 0, z0 + hs + hk / 2), role="knob")]
    return prims, z0 + hs + hk, Deferred(_knob_grasps, z0 + hs + hk / 2, rk)


def _knob_grasps(zc: float, rk: float) -> list[Grasp]:
    """Grasps on a lid knob of radius ``rk`` centred at height ``zc``: from above and from -y."""
    side = np.array([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, zc], [0.0, 0.0, 0.0, 1.0]])
    return [top_grasp(0.0, 0.0, zc, 2 * rk + 0.02, "x"), Grasp(side, 2 * rk + 0.02, np.array([0.0, 0.0, 1.0]))]


def knobbed_lid(p, radius: float, sides: int | None = None) -> Part:
    """Flat or gently domed lid with a central knob."""
    R, t, s, prims = _base(p, radius, sides, 0.3)
    z0 = t
    if p.flag("domed", 0.5):
        a = p.uniform("dome_ratio", 0.75, 0.95) * _apothem(R, sides)
        hd = p.uniform("dome_height", 0.08, 0.25) * a
        Rs = (a * a + hd * hd) / (2 * hd)
        prims.append(sphere(Rs, Rs - hd, Rs, translation(0, 0, t - Rs + hd), role="dome"))
        z0 = t + hd - 0.001
    kp, top, grasps = _knob(p, z0)
    return _lid("knobbed_lid", prims + kp, R, t, s, top, sides, grip_roles=("knob",), grasps=grasps)


def bridge_lid(p, radius: float, sides: int | None = None) -> Part:
    """Flat lid with a bridge handle (two posts and a bar along y) across its top."""
    R, t, s, prims = _base(p, radius, sides, 0.3)
    L = p.uniform("handle_length", 0.3, 0.6) * _apothem(R, sides)
    hp = p.uniform("post_height", 0.015, 0.03)
    w = p.uniform("bar_width", 0.01, 0.02)
    th = p.uniform("bar_thickness", 0.005, 0.01)
    prims += [cuboid(w, w, hp, translation(0, y, t + hp / 2), role="post") for y in (-(L - w) / 2, (L - w) / 2)]
    prims.append(cuboid(w, L, th, translation(0, 0, t + hp + th / 2), role="grip"))
    g = Deferred.one(top_grasp, 0.0, 0.0, t + hp + th / 2, w + 0.02, "x")
    return _lid("bridge_lid", prims, R, t, s, t + hp + th, sides, grip_roles=("grip",), grasps=g)


LIDS = {flat_lid: 2.0, knobbed_lid: 2.0, domed_lid: 1.0, bridge_lid: 1.0}


def mount_lid(builder, parent, lid: Part, rim_pose: np.ndarray, *, mode: str, limit: float, name: str = "lid"):
    """Attach ``lid`` at ``rim_pose`` (its frame in the parent link).

    ``mode`` = "lift": prismatic along +z, limits (0, ``limit``) metres (slider_lid);
    "flip": revolute about +y through the ``hinge`` anchor, opening the front upwards,
    limits (0, ``limit``) radians (hinge_lid).
    """
    link = builder.create_link(name, parent)
    if mode == "lift":
        link.set_joint("prismatic", rim_pose, axis=(0.0, 0.0, 1.0), limits=(0.0, limit))
        link.add(lid)
        lid.actionable = "slider_lid"
    else:
        h = lid.anchor("hinge")
        link.set_joint("revolute", rim_pose @ translation(*h), axis=(0.0, 1.0, 0.0), limits=(0.0, limit))
        link.add(lid, translation(*(-h)))
        lid.actionable = "hinge_lid"
    return link
