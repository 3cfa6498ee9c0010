"""Fan parts: rotors with pitched blades, wire guards, motor housings, box-fan grilles.

Head frame (metres): origin on the rotor axis in the plane of the blades, the axis
along x, air blown towards **-x** (the object's front), +z up.

- rotors (``paddle_rotor``, ``rounded_rotor``, ``scimitar_rotor``): (hub, blades) parts,
  ``n`` blades pitched about their radial axis within ``radius`` of the axis; anchors
  ``front`` / ``back`` (x extent of both) and ``hub_back``; the rotor link turns
  continuously about +x;
- guards (``ring_guard``, ``spoke_guard``): the rear grille at x = ``rear`` > 0, the
  front grille at x = ``-front``, a rim band joining them at ``radius``, and the
  central boss behind the hub that the rotor spins in front of;
- ``motor_housing``: a can behind the rear grille from x = ``x0`` backwards with a
  rounded back; anchors ``length`` (of the can, x) and ``back`` (its rearmost point).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, frustum, profile, ring, sphere, torus
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation
from artipg.model.part import Part, Region

_ALONG_X = rot_y(math.pi / 2)  # local z -> +x
# outline plane (u, v) -> world (y, z), extrusion axis -> world x
_YZ = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_SPIN = Region()


def _xcyl(r: float, x0: float, x1: float, role: str, y: float = 0.0, z: float = 0.0):
    return cylinder(r, abs(x1 - x0), translation((x0 + x1) / 2, y, z) @ _ALONG_X, role=role)


def _rotor(template, p, radius: float, n: int, hub: float, outline_fn):
    """Hub plus ``n`` copies of one blade outline (drawn with radial = +v), pitched;
    returns (hub part, blades part)."""
    pitch = math.radians(p.uniform("pitch", 18.0, 32.0))
    t = p.uniform("blade_thickness", 0.0015, 0.003)
    hd = p.uniform("hub_depth", 0.02, 0.035)
    loops, wmax = outline_fn(p, radius, n, hub)
    e = 0.5 * wmax * math.sin(pitch) + 0.5 * t * math.cos(pitch)  # the blades' half depth along x
    half = max(e, hd / 2)
    hub_prims = [_xcyl(hub, -hd / 2, hd / 2, "hub"),
                 sphere(hub, 0.0, 0.7 * hub, translation(-hd / 2, 0, 0) @ rot_y(-math.pi / 2), role="hub")]
    blade = translation(-t / 2, 0, 0) @ _YZ
    blades = [extrusion(loops, t, pose=rot_x(2 * math.pi * k / n) @ rot_z(pitch) @ blade, role="blade")
              for k in range(n)]
    front = hd / 2 + 0.7 * hub
    anchors = {"half_depth": (half, 0.0, 0.0), "front": (-max(e, front), 0.0, 0.0), "back": (max(e, hd / 2), 0.0, 0.0),
               "hub_back": (hd / 2, 0.0, 0.0)}
    hub_part = Part("rotor", template, hub_prims, anchors=anchors,
                    regions={"rotate": _SPIN, "push": _SPIN})
    return hub_part, Part("blade", template, blades, regions={"rotate": _SPIN, "push": _SPIN})


def _paddle(p, radius, n, hub):
    w = p.uniform("blade_width", 0.45, 0.7) * min(2 * math.pi * radius / n * 0.55, 0.6 * radius)
    r0 = 0.7 * hub
    out = profile.rectangle(w, radius - r0, p.uniform("corner", 0.2, 0.45) * w, centre=(0.0, (radius + r0) / 2))
    return [out], w


def paddle_rotor(p, radius: float, n: int, hub: float) -> Part:
    """Straight paddle blades with rounded corners (desk and box fans)."""
    return _rotor("paddle_rotor", p, radius, n, hub, _paddle)


def _rounded(p, radius, n, hub):
    w = p.uniform("blade_width", 0.55, 0.85) * min(2 * math.pi * radius / n * 0.55, 0.7 * radius)
    r0 = 0.7 * hub
    neck = p.uniform("neck", 0.25, 0.45) * w
    L = radius - r0
    out = profile.polygon([[-neck / 2, r0], [neck / 2, r0], [w / 2, r0 + 0.45 * L], [w / 2, radius - w / 2],
                           [-w / 2, radius - w / 2], [-w / 2, r0 + 0.45 * L]])
    out[3, 2] = 1.0  # a round tip: the top edge is a half circle
    return [out], w


def rounded_rotor(p, radius: float, n: int, hub: float) -> Part:
    """Petal blades: narrow at the hub, widening to a round tip (pedestal fans)."""
    return _rotor("rounded_rotor", p, radius, n, hub, _rounded)


def _scimitar(p, radius, n, hub):
    w = p.uniform("blade_width", 0.45, 0.7) * min(2 * math.pi * radius / n * 0.55, 0.6 * radius)
    r0 = 0.7 * hub
    sweep = p.uniform("sweep", 0.15, 0.35) * w
    out = profile.polygon([[-w / 4, r0], [w / 4, r0], [w / 2 + sweep, radius - 0.1 * w], [sweep, radius],
                           [-w / 2 + sweep, radius - 0.1 * w]])
    return [out], w + 2 * sweep


def scimitar_rotor(p, radius: float, n: int, hub: float) -> Part:
    """Swept blades, widening and leaning towards the direction of turn."""
    return _rotor("scimitar_rotor", p, radius, n, hub, _scimitar)


ROTORS = {paddle_rotor: 2.0, rounded_rotor: 2.0, scimitar_rotor: 1.0}


def _grille_rings(x: float, radius: float, wire: float, rings: int, role: str) -> list:
    return [torus(radius * (k + 1) / (rings + 1), wire, pose=translation(x, 0, 0) @ _ALONG_X, role=role)
            for k in range(rings)]


def _spokes(x: float, r0: float, r1: float, wire: float, n: int, role: str) -> list:
    L = r1 - r0
    return [cylinder(wire, L, rot_x(2 * math.pi * k / n) @ translation(x, 0, (r0 + r1) / 2), role=role)
            for k in range(n)]


def _guard(template, p, radius: float, rear: float, front: float, boss: float, rings: int, spokes: int) -> Part:
    wire = p.uniform("wire", 0.0012, 0.002)
    band = p.uniform("band", 0.003, 0.006)
    xr, xf = rear, -front
    badge = p.uniform("badge", 0.2, 0.3) * radius
    prims = [ring(radius + band, radius, front + rear + 2 * wire, pose=translation((xr + xf) / 2, 0, 0) @ _ALONG_X,
                  role="rim")]
    for x in (xr, xf):
        prims += _grille_rings(x, radius, wire, rings, "grille")
        prims += _spokes(x, 0.0 if x == xf else 0.5 * boss, radius + 0.5 * band, wire, spokes, "grille")
    prims.append(_xcyl(badge, xf - 0.002, xf + wire, "badge"))
    return Part("guard", template, prims, anchors={"radius": (radius + band, 0.0, 0.0)},
                regions={"lift": Region(("rim",)), "grasp": Region(("rim",))})


def ring_guard(p, radius: float, rear: float, front: float, boss: float) -> Part:
    """Guard of concentric wire rings on a few spokes (pedestal and desk fans)."""
    return _guard("ring_guard", p, radius, rear, front, boss, p.integers("rings", 3, 5), p.integers("spokes", 4, 8))


def spoke_guard(p, radius: float, rear: float, front: float, boss: float) -> Part:
    """Guard of many radial wires and one or two rings (older metal fans)."""
    return _guard("spoke_guard", p, radius, rear, front, boss, p.integers("rings", 1, 2), p.integers("spokes", 12, 18))


GUARDS = {ring_guard: 2.0, spoke_guard: 1.0}


def motor_housing(p, radius: float, x0: float, boss: float, hub_back: float) -> Part:
    """Motor can behind the rear grille: from x = ``x0`` backwards, a domed back, and a
    boss reaching forward to 1.5 mm behind the rotor hub (x = ``hub_back``)."""
    L = p.uniform("length", 0.06, 0.11)
    dome = p.uniform("dome", 0.2, 0.5) * radius
    prims = [_xcyl(radius, x0, x0 + L, "can"),
             sphere(radius, 0.0, dome, translation(x0 + L, 0, 0) @ _ALONG_X, role="can"),
             _xcyl(boss, hub_back + 0.0015, x0 + 0.002, "boss")]
    return Part("body", "motor_housing", prims, anchors={"length": (L, 0.0, 0.0), "back": (x0 + L + dome, 0, 0)},
                regions={"lift": Region(("can",)), "grasp": Region(("can",))})


# ---------------------------------------------------------------- bases (origin on the floor, +z up)

def disc_base(p, radius: float) -> Part:
    """Round weighted base: a low frustum; anchor ``top``."""
    h = p.uniform("height", 0.025, 0.05)
    prim = frustum(radius, p.uniform("taper", 0.85, 1.0) * radius, h, translation(0, 0, h / 2), role="base")
    return Part("base", "disc_base", [prim], anchors={"top": (0.0, 0.0, h)}, regions={"lift": Region()})


def square_base(p, radius: float) -> Part:
    """Rounded square base (``radius`` is half its side); anchor ``top``."""
    h = p.uniform("height", 0.025, 0.05)
    prim = rounded_box(2 * radius, 2 * radius, h, min(0.006, h / 2 - 1e-4), translation(0, 0, h / 2), role="base")
    return Part("base", "square_base", [prim], anchors={"top": (0.0, 0.0, h)}, regions={"lift": Region()})


def cross_base(p, radius: float) -> Part:
    """Four legs in a cross from a central hub, pads under their ends; anchor ``top``."""
    h = p.uniform("height", 0.03, 0.05)
    w = p.uniform("leg_width", 0.03, 0.05)
    prims = [cylinder(0.06, h, translation(0, 0, h / 2), role="hub")]
    for k in range(4):
        a = math.pi / 4 + k * math.pi / 2
        prims.append(cuboid(radius, w, 0.6 * h, translation(0.5 * radius * math.cos(a), 0.5 * radius * math.sin(a),
                                                            0.3 * h) @ rot_z(a), role="leg"))
    return Part("base", "cross_base", prims, anchors={"top": (0.0, 0.0, h)}, regions={"lift": Region(("hub",))})


BASES = {disc_base: 2.0, square_base: 1.0, cross_base: 1.0}
