"""Globe parts: the sphere, meridians, desk plinths and posts, and the floor stand.

Frames (metres, +z up):
- ``globe_sphere``: origin at the sphere's centre, local z = the spin axis;
- meridians: origin at the sphere's centre, the ring in the local x-z plane (the
  meridian plane), local z = the spin axis; a half meridian runs from the south pole
  (-z) round the +x side to the north pole, a full one all round. Each carries the two
  axle pins from the ring to just off the poles. Anchor ``bottom_r``: the radius of
  the ring's centre line (its outer edge is ``bottom_r + half thickness``);
- plinths: origin at the centre of the footprint on the floor, anchor ``top``;
- posts: origin at the centre of the bottom face, anchor ``top``;
- ``floor_stand``: origin on the floor under the sphere's centre; legs up to a
  horizon ring at the centre's height ``zc`` and a cradle under the meridian.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, frustum, ring, sphere, torus
from artipg.geometry.transforms import rot_x, rot_z, rotation, translation
from artipg.model.part import Part, Region

# torus / ring local x-y plane -> the meridian (x-z) plane, arc starting at the south pole
_MERIDIAN = rot_x(math.pi / 2) @ rot_z(-math.pi / 2)
_SPIN = Region(("ball",))


def globe_sphere(p, radius: float) -> Part:
    """The globe: a ball spinning about its local z axis."""
    return Part("sphere", "globe_sphere", [sphere(radius, role="ball")], anchors={"north": (0.0, 0.0, radius)},
                regions={"rotate": _SPIN, "push": _SPIN})


def _pins(R: float, Rm: float, rp: float) -> list:
    """Axle pins from the ring's centre line to 0.5 mm off the poles."""
    L = Rm - R - 0.0005
    return [cylinder(rp, L, translation(0, 0, s * (R + 0.0005 + L / 2)), role="pin") for s in (-1.0, 1.0)]


def _meridian(template, prim, R, Rm, half) -> Part:
    return Part("frame", template, [prim, *_pins(R, Rm, max(0.002, 0.6 * half))],
                anchors={"bottom_r": (Rm, half, 0.0)}, regions={"grasp": Region(("ring",))})


def round_meridian(p, radius: float, full: bool) -> Part:
    """Meridian of round wire (a torus arc) around a sphere of ``radius``."""
    r = p.uniform("wire_radius", 0.003, 0.006)
    Rm = radius + p.uniform("gap", 0.004, 0.01) + r
    return _meridian("round_meridian", torus(Rm, r, 2 * math.pi if full else math.pi, _MERIDIAN, role="ring"),
                     radius, Rm, r)


def band_meridian(p, radius: float, full: bool) -> Part:
    """Meridian of flat metal band (a ring arc): a strip lying in the meridian plane."""
    w, t = p.uniform("band_width", 0.006, 0.012), p.uniform("band_thickness", 0.002, 0.004)
    Rm = radius + p.uniform("gap", 0.004, 0.01) + w / 2
    prim = ring(Rm + w / 2, Rm - w / 2, t, 2 * math.pi if full else math.pi, _MERIDIAN, role="ring")
    return _meridian("band_meridian", prim, radius, Rm, w / 2)


MERIDIANS = {round_meridian: 2.0, band_meridian: 1.0}


def disc_plinth(p, radius: float) -> Part:
    """Round base: a flat disc with a low domed step on it."""
    t = p.uniform("thickness", 0.012, 0.025)
    h2 = p.uniform("dome_height", 0.008, 0.02)
    prims = [cylinder(radius, t, translation(0, 0, t / 2), role="plinth"),
             frustum(0.8 * radius, 0.35 * radius, h2, translation(0, 0, t + h2 / 2), role="plinth")]
    return Part("base", "disc_plinth", prims, anchors={"top": (0.0, 0.0, t + h2)}, regions={"lift": Region()})


def stepped_plinth(p, radius: float) -> Part:
    """Two stacked discs, the upper one smaller."""
    t1, t2 = p.uniform("thickness", 0.01, 0.02), p.uniform("step", 0.01, 0.02)
    prims = [cylinder(radius, t1, translation(0, 0, t1 / 2), role="plinth"),
             cylinder(p.uniform("step_ratio", 0.55, 0.75) * radius, t2, translation(0, 0, t1 + t2 / 2), role="plinth")]
    return Part("base", "stepped_plinth", prims, anchors={"top": (0.0, 0.0, t1 + t2)}, regions={"lift": Region()})


def square_plinth(p, radius: float) -> Part:
    """Square wooden block base (``radius`` is half its side)."""
    t = p.uniform("thickness", 0.02, 0.04)
    s = 2 * radius * 0.9
    return Part("base", "square_plinth", [cuboid(s, s, t, translation(0, 0, t / 2), role="plinth")],
                anchors={"top": (0.0, 0.0, t)}, regions={"lift": Region()})


PLINTHS = {disc_plinth: 2.0, stepped_plinth: 1.5, square_plinth: 1.0}


def straight_post(p, height: float) -> Part:
    """Plain round post."""
    r = p.uniform("radius", 0.006, 0.012)
    return Part("stand", "straight_post", [cylinder(r, height, translation(0, 0, height / 2), role="post")],
                anchors={"top": (0.0, 0.0, height), "radius": (r, 0.0, 0.0)})


def baluster_post(p, height: float) -> Part:
    """Turned post: a tapered foot, a ball knot and a thin neck."""
    r = p.uniform("radius", 0.006, 0.01)
    rk = p.uniform("knot", 1.8, 2.5) * r
    hf = p.uniform("foot", 0.3, 0.45) * height
    zk = hf + 0.7 * rk
    prims = [frustum(1.8 * r, r, hf, translation(0, 0, hf / 2), role="post"),
             sphere(rk, pose=translation(0, 0, zk), role="post"),
             cylinder(r, height - zk, translation(0, 0, (zk + height) / 2), role="post")]
    return Part("stand", "baluster_post", prims, anchors={"top": (0.0, 0.0, height), "radius": (1.8 * r, 0.0, 0.0)})


POSTS = {straight_post: 2.0, baluster_post: 1.0}


def swivel_collar(p, radius: float, height: float) -> Part:
    """Collar on top of a post that carries a swivelling meridian (origin at its bottom)."""
    return Part("frame", "swivel_collar", [cylinder(radius, height, translation(0, 0, height / 2), role="collar")],
                anchors={"top": (0.0, 0.0, height)})


def _rod(a, b, r: float, role: str):
    """Cylinder of radius ``r`` from point ``a`` to point ``b`` (3,)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    d = b - a
    L = float(np.linalg.norm(d))
    axis = np.cross((0.0, 0.0, 1.0), d)
    n = float(np.linalg.norm(axis))
    R = rotation(axis, math.acos(max(-1.0, min(1.0, d[2] / L)))) if n > 1e-12 else np.eye(4)
    m = (a + b) / 2
    return cylinder(r, L, translation(*m) @ R, role=role)


def floor_stand(p, zc: float, horizon: float, cradle: float) -> Part:
    """Three or four splayed legs up to a horizon ring of centre-line radius ``horizon``
    at height ``zc``, a stretcher ring low down and spokes to a central cradle whose
    top is at height ``cradle`` (under the meridian)."""
    n = p.integers("legs", 3, 4)
    rl = p.uniform("leg_radius", 0.012, 0.02)
    rh = p.uniform("horizon_thickness", 0.008, 0.015)
    foot = p.uniform("foot_spread", 0.9, 1.15) * horizon
    zs = p.uniform("stretcher_height", 0.12, 0.22)
    rs = 0.6 * rl
    phase = math.pi / n if n == 4 else 0.0
    prims = [torus(horizon, rh, pose=translation(0, 0, zc), role="horizon")]
    ring_r = foot + (horizon - foot) * zs / zc  # the legs' radius at the stretcher's height
    for k in range(n):
        c, s = math.cos(2 * math.pi * k / n + phase), math.sin(2 * math.pi * k / n + phase)
        prims.append(_rod((foot * c, foot * s, 0.0), (horizon * c, horizon * s, zc), rl, "leg"))
        prims.append(_rod((ring_r * c, ring_r * s, zs), (0.0, 0.0, zs), rs, "stretcher"))
    hub = max(2 * rs, 0.02)
    prims += [cylinder(hub, 2 * rs + 0.004, translation(0, 0, zs), role="stretcher"),
              cylinder(0.6 * hub, cradle - zs, translation(0, 0, (zs + cradle) / 2), role="cradle")]
    return Part("stand", "floor_stand", prims, anchors={"top": (0.0, 0.0, zc)}, regions={"lift": Region(("leg",))})
