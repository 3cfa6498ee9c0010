"""Mug parts: open bodies, a loop handle, a beer stein's thumb-lever lid, and a travel
mug's lid with its sliding or flipping drink-opening cover.

Frames (metres, +z up):
- bodies: origin at the centre of the bottom on the floor; the wall's outer radius
  grows linearly from ``radii[0]`` at z = 0 to ``radii[1]`` at the rim (anchor
  ``rim``), see :func:`wall_radius`;
- ``loop_handle``: as the kettle side handles of :mod:`artipg.templates.cookware`:
  origin on the vessel axis at z = 0, joining the wall at (``r_top``, ``z_top``) and
  (``r_bot``, ``z_bot``) on the +x side;
- plug lids (``PLUG_LIDS``): origin at the centre of the rim plane, a disc on the rim
  and a plug ring inside the wall; anchors as :mod:`artipg.templates.lids` lids;
- ``stein_lid``: origin at the centre of the rim plane, lying on the rim; its hinge
  knuckle is on the axis (``hinge`` anchor) beyond the rim at +x, along y;
- ``travel_lid``: origin at the centre of the rim plane; the drink opening is at the
  front (-x) of its top face (anchor ``top``);
- ``slide_cover`` / ``flip_cover``: origin on their joint: the slider's back edge at
  rest, the flap's hinge line (its top back edge), on the lid's top face.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, ring, sphere, torus
from artipg.geometry.transforms import Placer, rot_x, rot_z, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.detail import lip_style, lipped_wall

_LOOP = rot_x(math.pi / 2) @ rot_z(-math.pi / 2)  # torus x-y plane -> x-z plane, arc from -z round +x
_ALONG_Y = Placer(rot_x(-math.pi / 2))  # local z -> +y
_UP = np.array([0.0, 0.0, 1.0])
CLEAR = 0.0008  # radial clearance of a plug inside a wall


def wall_radius(body: Part, z: float) -> float:
    """Outer radius (metres) of a mug body's wall at height ``z``."""
    r0, r1, _ = body.anchors["radii"]
    return r0 + (r1 - r0) * z / body.anchors["rim"][2]


def _body(template, radius, top_radius, height, wall, base, extra=(), lip=0.0, rim="flat") -> Part:
    walls = lipped_wall(radius, radius - wall, height - base, (height + base) / 2, rim, taper=top_radius - radius)
    prims = [walls[0], cylinder(radius - 0.5 * wall, base, translation(0, 0, base / 2), role="bottom"), *extra,
             *walls[1:]]
    return Part("body", template, prims, anchors={"rim": (0.0, 0.0, height), "radii": (radius, top_radius, 0.0),
                                                  "wall": (wall, 0.0, 0.0),
                                                  "lip": (top_radius + lip, 0.0, height)},
                regions={"grasp": Region(("wall",)), "lift": Region(("wall",))})


def straight_body(p, radius: float, height: float) -> Part:
    """Straight cylindrical wall on a flat bottom."""
    return _body("straight_body", radius, radius, height, p.uniform("wall", 0.003, 0.006),
                 p.uniform("base", 0.005, 0.01), rim=lip_style(p))


def conical_body(p, radius: float, height: float) -> Part:
    """Wall widening towards the rim (``radius`` at the bottom)."""
    top = radius + p.uniform("flare", 0.08, 0.25) * radius
    return _body("conical_body", radius, top, height, p.uniform("wall", 0.003, 0.006), p.uniform("base", 0.005, 0.01),
                 rim=lip_style(p))


def banded_body(p, radius: float, height: float) -> Part:
    """Straight wall with a raised foot ring and a rim band (steins, diner mugs)."""
    wall, base = p.uniform("wall", 0.003, 0.006), p.uniform("base", 0.006, 0.012)
    band = p.uniform("band", 0.002, 0.004)
    hf, hr = p.uniform("foot", 0.01, 0.02), p.uniform("rim_band", 0.006, 0.012)
    extra = [ring(radius + band, radius - 0.001, hf, pose=translation(0, 0, hf / 2), role="foot"),
             ring(radius + band, radius - 0.001, hr, pose=translation(0, 0, height - 0.004 - hr / 2), role="band")]
    return _body("banded_body", radius, radius, height, wall, base, extra, lip=band, rim=lip_style(p))


BODIES = {straight_body: 2.0, conical_body: 1.0, banded_body: 1.0}


def loop_handle(p, r_top: float, z_top: float, r_bot: float, z_bot: float) -> Part:
    """Round loop handle: a torus arc from the upper to the lower joint (classic mug ear)."""
    r = p.uniform("radius", 0.004, 0.007)
    a = (z_top - z_bot) / 2
    xc = max(r_top, r_bot) + 0.002
    bulge = p.uniform("bulge", 0.0, 0.012)
    # a half loop stretched out by ``bulge``: two quarter arcs joined by straight runs
    prims = [torus(a, r, math.pi / 2, translation(xc + bulge, 0, z_bot + a) @ _LOOP, role="grip"),
             torus(a, r, math.pi / 2, translation(xc + bulge, 0, z_bot + a) @ _LOOP @ rot_z(math.pi / 2),
                   role="grip")]
    for z, rw in ((z_top, r_top), (z_bot, r_bot)):
        prims.append(cuboid_between((rw - 0.0015, -r, z - r), (xc + bulge, r, z + r), role="grip"))
    x = xc + bulge + a
    grasp = Deferred.one(_side_grasp, x, z_bot + a, 2 * r + 0.02)
    return Part("handle", "loop_handle", prims, anchors={"top": (xc + bulge, 0.0, z_top + r), "tube": (r, 0.0, 0.0),
                                                         "outer": (x + r, 0.0, 0.0)},
                regions={"grasp": Region(("grip",)), "lift": Region(("grip",))}, grasps=grasp,
                actionable="line_fixed_handle")


def _side_grasp(x: float, z: float, width: float) -> Grasp:
    """A grasp on a handle's upright at (x, 0, z), approaching from +x, jaws along y."""
    T = np.array([[0.0, 0.0, -1.0, x], [0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, z], [0.0, 0.0, 0.0, 1.0]])
    return Grasp(T, width)


def stein_lid(p, radius: float, hinge_x: float, thumb: float, tilt: float) -> Part:
    """Pewter lid: a disc (optionally domed) over the rim, a tab out to the hinge
    knuckle at (``hinge_x``, 0, t / 2) and a thumb lever ``thumb`` long rising from
    the knuckle, leaning back (+x) by ``tilt`` radians."""
    R = radius + p.uniform("overhang", 0.002, 0.005)
    t = p.uniform("thickness", 0.003, 0.006)
    rk = t / 2 + p.uniform("knuckle", 0.001, 0.002)
    kl = p.uniform("knuckle_length", 0.012, 0.02)
    lw, lt = p.uniform("lever_width", 0.7, 1.0) * kl, p.uniform("lever_thickness", 0.002, 0.0035)
    prims = [cylinder(R, t, translation(0, 0, t / 2), role="disc"),
             cuboid_between((R * 0.8, -kl / 2, 0.0), (hinge_x, kl / 2, t), role="tab"),
             cylinder(rk, kl, _ALONG_Y.at(hinge_x, 0, t / 2), role="knuckle"),
             cuboid(lt, lw, thumb, translation(hinge_x, 0, t / 2) @ _lean(tilt) @ translation(0, 0, thumb / 2),
                    role="lever")]
    if p.flag("dome", 0.5):  # a spherical cap of base radius 0.8 R standing on the disc
        hd, a = p.uniform("dome_height", 0.12, 0.3) * R, 0.8 * R
        rs = (a * a + hd * hd) / (2 * hd)
        prims.append(sphere(rs, rs - hd, rs, translation(0, 0, t + hd - rs), role="disc"))
    top = np.array([[-R, -R, 0.0], [R, R, t + 0.2 * R]])
    return Part("lid", "stein_lid", prims, anchors={"hinge": (hinge_x, 0.0, t / 2), "knuckle": (rk, kl, 0.0)},
                regions={"lift": Region(("disc",), top), "push": Region(("lever",)), "press": Region(("lever",))},
                actionable="hinge_lid")


def stein_bracket(p, lid: Part, wall: float, handle_top: float) -> Part:
    """Hinge bracket for a :func:`stein_lid` (rim-plane frame): a block from the wall
    (outer radius ``wall``) over the handle's top (``handle_top``, below the rim) up to
    just under the knuckle, and two cheeks on it either side of the knuckle. Anchor
    ``top``: the block's top (z)."""
    rk, kl, _ = lid.anchors["knuckle"]
    hx, _, zk = lid.anchors["hinge"]
    yc = kl / 2 + 0.0008 + p.uniform("cheek", 0.002, 0.003)
    zb = zk - rk - 0.0012  # clear of the knuckle
    prims = [cuboid_between((wall - 0.002, -yc, min(handle_top, zb - 0.005) - 0.002), (hx + rk, yc, zb), role="bracket"),
             *[cuboid_between((hx - rk, lo, zb - 0.0005), (hx + rk, hi, zk + 0.5 * rk), role="cheek")
               for lo, hi in ((-yc, -kl / 2 - 0.0008), (kl / 2 + 0.0008, yc))]]
    return Part("hinge", "stein_bracket", prims, anchors={"top": (0.0, 0.0, zb)})


def lever_stop(lid: Part, beta: float, bracket_top: float, handle_drop: float) -> float:
    """Largest opening (radians) of a :func:`stein_lid` before its thumb lever, leaning
    back by ``beta``, comes within 1.5 mm of the bracket's top (for x <= the knuckle's
    radius behind the axis) or of the handle's top, ``handle_drop`` below the axis."""
    rk = lid.anchors["knuckle"][0]
    zk = lid.anchors["hinge"][2]
    lt, _, L = lid.primitives[3].params[:3]  # the lever box (sx, sy, sz)
    floor_b = zk - bracket_top
    th = np.linspace(0.0, math.pi, 181)
    phi = beta + th
    c, sn = np.cos(phi), np.maximum(np.sin(phi), 1e-9)
    low = -lt / 2 * sn  # the lever's lower face dips by half its thickness
    ok = ((np.minimum(0.0, np.minimum(L, rk / sn) * c) + low > 0.0015 - floor_b)
          & (L * c + low > 0.0015 - handle_drop))
    bad = np.flatnonzero(~ok)
    return float(th[max(bad[0] - 1, 0)]) if len(bad) else math.pi


def _lean(a: float) -> np.ndarray:
    """Rotation about y by ``a``: +z leans towards +x."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]])


def travel_lid(p, radius: float) -> Part:
    """Screw-on lid: a skirt over the rim, a raised top deck and, at the front of the
    deck, a low drinking spout ridge."""
    R = radius + p.uniform("overhang", 0.001, 0.003)
    hs, hd = p.uniform("skirt", 0.012, 0.02), p.uniform("deck", 0.006, 0.012)
    rd = p.uniform("deck_ratio", 0.8, 0.92) * R
    prims = [ring(R, radius + 0.0008, hs, pose=translation(0, 0, -hs / 2 + 0.002), role="skirt"),
             cylinder(R, 0.002 + 0.001, translation(0, 0, 0.0015), role="skirt"),
             frustum(R, rd, hd, translation(0, 0, 0.003 + hd / 2), role="deck")]
    z = 0.003 + hd
    return Part("lid", "travel_lid", prims, anchors={"top": (0.0, 0.0, z), "deck": (rd, 0.0, 0.0)},
                regions={"grasp": Region(("skirt",))})


def slide_cover(p, length: float, width: float) -> Part:
    """Thin slider plate between two rails (the rails belong to the lid's link: see
    :func:`slide_rails`); origin at its back edge's centre on the deck, extending to -x."""
    t = p.uniform("thickness", 0.002, 0.003)
    prims = [cuboid_between((-length, -width / 2, 0.0003), (0.0, width / 2, t), role="slider"),
             cuboid_between((-0.35 * length, -0.15 * width, t), (-0.2 * length, 0.15 * width, t + 0.002), role="tab")]
    return Part("flap", "slide_cover", prims, anchors={"top": (0.0, 0.0, t + 0.002)},
                regions={"push": Region(("tab", "slider")), "pull": Region(("tab",))}, actionable="slider_lid")


def slide_rails(length: float, width: float, height: float, pose: np.ndarray) -> Part:
    """Two rails along x either side of a slider of ``width``, ``length`` long."""
    w = 0.0025
    y0, y1 = width / 2 + 0.0006, width / 2 + 0.0006 + w
    prims = [cuboid_between((-length, lo, 0.0), (length * 0.25, hi, height), role="rail")
             for lo, hi in ((-y1, -y0), (y0, y1))]
    prims = [q.placed(pose) for q in prims]
    return Part("lid", "slide_rails", prims)


def flip_cover(p, length: float, width: float) -> Part:
    """Flap over the drink opening, hinged along its top back edge (origin), lying
    flat towards -x below it."""
    t = p.uniform("thickness", 0.002, 0.003)
    prims = [cuboid_between((-length, -width / 2, -t), (0.0, width / 2, 0.0), role="flap"),
             cuboid_between((-length - 0.004, -0.25 * width, -t), (-length, 0.25 * width, -t + 0.0015), role="tab")]
    return Part("flap", "flip_cover", prims, anchors={"thickness": (t, 0.0, 0.0)},
                regions={"lift": Region(("tab", "flap")), "push": Region(("flap",))}, actionable="hinge_lid")


def _plug_lid(template, p, outer: float, inner: float, extra) -> Part:
    """A disc over the rim with a plug ring inside the wall (origin at the rim plane's
    centre; hinge anchor at the disc's bottom back edge, +x, as :mod:`lids` lids)."""
    R = outer + p.uniform("overhang", 0.001, 0.003)
    t = p.uniform("thickness", 0.003, 0.005)
    d = p.uniform("plug", 0.004, 0.008)
    rp = inner - CLEAR
    prims = [cylinder(R, t, translation(0, 0, t / 2), role="disc"),
             ring(rp, rp - 0.0015, d, pose=translation(0, 0, -d / 2), role="plug"), *extra(R, t)]
    edge = np.array([[-R - 1e-3, -0.4 * R, -1e-3], [-R + 0.02, 0.4 * R, t + 1e-3]])
    return Part("lid", template, prims, anchors={"top": (0.0, 0.0, t), "hinge": (R, 0.0, 0.0), "front": (-R, 0.0, 0.0)},
                regions={"lift": Region(("disc", "knob")), "grasp": Region(("disc",), edge)},
                grasps=Deferred.one(_edge_grasp, R, t))


def _edge_grasp(R: float, t: float) -> Grasp:
    """A pinch on the lid's front edge, approaching +x, jaws closing along z."""
    T = np.array([[0.0, 1.0, 0.0, -R + 0.008], [0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, t / 2], [0.0, 0.0, 0.0, 1.0]])
    return Grasp(T, t + 0.02, _UP)


def plug_lid(p, outer: float, inner: float) -> Part:
    """Flat ceramic lid with a plug inside the rim."""
    return _plug_lid("plug_lid", p, outer, inner, lambda R, t: [])


def knob_plug_lid(p, outer: float, inner: float) -> Part:
    """Plug lid with a small round knob in the middle."""
    rk, hk = p.uniform("knob_radius", 0.005, 0.008), p.uniform("knob_height", 0.006, 0.01)
    return _plug_lid("knob_plug_lid", p, outer, inner,
                     lambda R, t: [cylinder(0.6 * rk, hk, translation(0, 0, t + hk / 2), role="knob"),
                                   sphere(rk, 0.0, rk, translation(0, 0, t + hk - 0.001), role="knob")])


def dome_plug_lid(p, outer: float, inner: float) -> Part:
    """Plug lid with a low spherical dome."""
    f = p.uniform("dome", 0.15, 0.3)

    def dome(R, t):
        a, hd = 0.85 * R, f * R
        rs = (a * a + hd * hd) / (2 * hd)
        return [sphere(rs, rs - hd, rs, translation(0, 0, t + hd - rs), role="disc")]
    return _plug_lid("dome_plug_lid", p, outer, inner, dome)


PLUG_LIDS = {plug_lid: 2.0, knob_plug_lid: 2.0, dome_plug_lid: 1.0}
