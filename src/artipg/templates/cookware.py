"""Cookware handles: long pan handles, pairs of side lugs, kettle side handles, fixed
arch handles over a kettle, and a loop-handled pot lid.

Wall-mounted handles (``LONG_HANDLES``, ``SIDE_HANDLES``): origin at the mount point
on the vessel's outer wall, +x pointing radially out, +z up; ``radius`` is the wall's
radius there (side lugs span it tangentially, so they sink in by the wall's sagitta).
Kettle side handles (``KETTLE_HANDLES``): origin on the vessel axis at z = 0, +x
towards the handle; they join the wall at (``r_top``, ``z_top``) and (``r_bot``,
``z_bot``). :func:`arch_top_handle`: origin on the axis at the top plate (z = 0),
posts at x = -+``d``, arching over the lid along x; anchor ``under`` is the
underside of the arch on the axis.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring, torus, tube
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.extents import span
from artipg.templates.handles import arch_handle
from artipg.templates.lids import flat_lid
from artipg.templates.levers import top_grasp

_EMBED = 0.0015  # how deep a handle's root sinks into the wall
# handles.py frame (protrude -x, long axis +z) -> outward +x, long axis along y
_SIDEWAYS = Placer(np.array([[-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]]))
_LIFT = np.array([0.0, 0.0, 1.0])  # fixed handles lift the vessel
_LIFT.flags.writeable = False
_ALONG_X = rot_y(math.pi / 2)  # local z -> +x
_XZ_TO_XY = rot_x(-math.pi / 2)  # tube plane x-z -> x-y


def _grasp(x: float, y: float, z: float, approach, jaw, width: float) -> Grasp:
    """A grasp at (x, y, z) (part frame) approaching along the unit vector ``approach``
    with the jaws closing along the unit vector ``jaw`` (perpendicular to it)."""
    (jx, jy, jz), (ax, ay, az) = jaw, approach
    T = np.array(((jy * az - jz * ay, jx, ax, x), (jz * ax - jx * az, jy, ay, y), (jx * ay - jy * ax, jz, az, z),
                  (0.0, 0.0, 0.0, 1.0)))  # x axis: jaw x approach
    return Grasp(T, width, _LIFT)


def _side_grasps(a: float, s, width: float) -> list[Grasp]:
    """Grasps on a straight handle rising at angle ``a`` from (-_EMBED, 0, 0), at the
    distances ``s`` along it: approaching from -y, jaws closing across the handle in
    the x-z plane."""
    c, n = math.cos(a), math.sin(a)
    return [_grasp(-_EMBED + si * c, 0.0, si * n, (0.0, 1.0, 0.0), (-n, 0.0, c), width) for si in s]


def _radial_grasp(x: float, width: float) -> Grasp:
    """A grasp on a side lug's outer bar at (x, 0, 0), approaching towards the wall
    (-x) with the jaws closing vertically."""
    return _grasp(x, 0.0, 0.0, (-1.0, 0.0, 0.0), (0.0, 0.0, 1.0), width)


def _lifted(T: np.ndarray, grasps) -> list[Grasp]:
    """``grasps`` (a list, or the :class:`Deferred` building it) moved by ``T`` (4, 4),
    lifting the vessel."""
    return [Grasp(T @ g.pose, g.width, _LIFT) for g in (grasps() if isinstance(grasps, Deferred) else grasps)]


def _arch_grasps(d: float, R: float, h: float, r: float) -> list[Grasp]:
    """Grasps from above on the top bar of :func:`arch_top_handle`, around its middle."""
    return [top_grasp(k * (d - R), 0.0, h + R, 2 * r + 0.02, "y") for k in (-0.5, 0.0, 0.5)]


def _handle(name, prims, grip=("grip",), clear: float | None = None) -> Part:
    """A handle part; ``clear`` is its highest point within 15 mm of the wall."""
    part = Part("handle", name, prims, regions={"grasp": Region(grip), "lift": Region(grip)},
                actionable="line_fixed_handle")
    if clear is not None:
        part.anchors["clear"] = (0.0, 0.0, clear)
    return part


def _bracket(p, r, rise):
    """Riveted plate on the wall under a long handle's root; returns it and the
    handle's highest point within 15 mm of the wall."""
    t = p.uniform("bracket_thickness", 0.003, 0.005)
    h = 2 * r + p.uniform("bracket_rise", 0.01, 0.02)
    prim = cuboid(t, 2 * r + p.uniform("bracket_margin", 0.006, 0.014), h, translation(t / 2 - _EMBED, 0, 0),
                  role="bracket")
    return prim, max(h / 2, r / math.cos(rise) + 0.015 * math.tan(rise))


def stick_handle(p, radius: float) -> Part:
    """Straight round handle rising gently from a bracket (saucepans)."""
    r = p.uniform("radius", 0.007, 0.011)
    L = p.uniform("length", 0.14, 0.22)
    a = p.uniform("rise", 0.05, 0.3)
    bracket, clear = _bracket(p, r, a)
    part = _handle("stick_handle", [bracket] + tube(r, [line(L)], a, translation(-_EMBED, 0, 0), role="grip"),
                   clear=clear)
    part.grasps = Deferred(_side_grasps, a, (0.45 * L, 0.75 * L), 2 * r + 0.02)
    return part


def grip_handle(p, radius: float) -> Part:
    """Thin metal neck, a thick grip and a hanging ring at the end (frying pans)."""
    rn = p.uniform("neck_radius", 0.005, 0.007)
    ln = p.uniform("neck_length", 0.03, 0.05)
    rg = p.uniform("grip_radius", 0.01, 0.014)
    lg = p.uniform("grip_length", 0.1, 0.15)
    a = p.uniform("rise", 0.05, 0.3)
    T = translation(-_EMBED, 0, 0) @ rot_y(-a)  # local x along the handle
    rr = p.uniform("ring_radius", 0.008, 0.012)
    bracket, clear = _bracket(p, rn, a)
    prims = [bracket, cylinder(rn, ln + 0.002, T @ translation((ln + 0.002) / 2, 0, 0) @ _ALONG_X,
                                       role="neck"),
             cylinder(rg, lg, T @ translation(ln + lg / 2, 0, 0) @ _ALONG_X, role="grip"),
             torus(rr, 0.002, pose=T @ translation(ln + lg + rr - 0.001, 0, 0), role="grip")]
    part = _handle("grip_handle", prims, clear=clear)
    part.grasps = Deferred(_side_grasps, a, (ln + 0.3 * lg, ln + 0.7 * lg), 2 * rg + 0.02)
    return part


def flat_handle(p, radius: float) -> Part:
    """Flat riveted bar with a hanging eye (stainless pots)."""
    w = p.uniform("width", 0.016, 0.026)
    t = p.uniform("thickness", 0.004, 0.007)
    L = p.uniform("length", 0.13, 0.2)
    eye = p.uniform("eye", 0.02, 0.03)
    a = p.uniform("rise", 0.05, 0.3)
    T = translation(-_EMBED, 0, 0) @ rot_y(-a)
    bracket, clear = _bracket(p, t, a)
    prims = [bracket, cuboid(L, w, t, T @ translation(L / 2, 0, 0), role="grip"),
             rect_ring(eye + w * 0.4, w, t, eye, w * 0.5, T @ translation(L + eye / 2 - 0.002, 0, 0), role="grip")]
    part = _handle("flat_handle", prims, clear=clear)
    part.grasps = Deferred(_side_grasps, a, (0.45 * L, 0.75 * L), t + 0.02)
    return part


LONG_HANDLES = {stick_handle: 2.0, grip_handle: 1.5, flat_handle: 1.5}


def _sag(radius, half):
    return radius - math.sqrt(max(radius * radius - half * half, 0.0))


def loop_lug(p, radius: float) -> Part:
    """Horizontal wire loop (stockpots)."""
    r = p.uniform("wire_radius", 0.003, 0.005)
    R = p.uniform("loop_radius", 0.012, 0.025)
    a = p.uniform("reach", 0.012, 0.03) + _sag(radius, R) + _EMBED
    T = _XZ_TO_XY @ translation(-_sag(radius, R) - _EMBED, 0, -R)
    part = _handle("loop_lug", tube(r, [line(a), arc(R, math.pi), line(a)], 0.0, T, role="grip"), clear=r)
    part.grasps = Deferred.one(_radial_grasp, a - _sag(radius, R) - _EMBED + R, 2 * r + 0.02)
    return part


def tab_lug(p, radius: float) -> Part:
    """Flat ear with a finger hole (casseroles, roasters)."""
    w = p.uniform("width", 0.04, 0.07)
    d = p.uniform("reach", 0.025, 0.04)
    t = p.uniform("thickness", 0.004, 0.008)
    rim = p.uniform("rim", 0.008, 0.012)
    s = _sag(radius, w / 2) + _EMBED
    part = _handle("tab_lug", [rect_ring(d + s, w, t, d + s - 2 * rim, w - 2 * rim,
                                         translation((d + s) / 2 - s, 0, 0), role="grip")], clear=t / 2)
    part.grasps = Deferred.one(_radial_grasp, d - rim / 2, t + 0.02)
    return part


def arch_lug(p, radius: float) -> Part:
    """Bent-wire D handle lying sideways (a front-handle template turned 90 deg)."""
    L = p.uniform("span", 0.04, 0.065)
    part = arch_handle(p, length=L)
    T = _SIDEWAYS.at(-_sag(radius, L / 2) - _EMBED, 0, 0)
    part.primitives = [pr.placed(T) for pr in part.primitives]
    part.grasps = Deferred(_lifted, T, part.grasp_source())
    part.template = "arch_lug"
    part.anchors["clear"] = (0.0, 0.0, span(part.primitives, 2)[1])
    return part


SIDE_HANDLES = {loop_lug: 2.0, tab_lug: 1.5, arch_lug: 1.5}


def loop_lid(p, radius: float, sides: int | None = None) -> Part:
    """Flat lid with a wire loop handle standing on its centre."""
    lid = flat_lid(p, radius, sides)
    t = float(lid.anchors["top"][2])
    r = p.uniform("wire_radius", 0.003, 0.005)
    R = p.uniform("loop_radius", 0.015, 0.03)
    h = p.uniform("loop_height", 0.008, 0.02)
    prims = tube(r, [line(h + 0.001), arc(R, -math.pi), line(h + 0.001)], math.pi / 2,
                 translation(-R, 0, t - 0.001), role="grip")
    lid.primitives += prims
    lid.template = "loop_lid"
    lid.anchors["top"] = (0.0, 0.0, t + h + R + r)
    lid.regions = {"lift": Region(("grip",)), "grasp": Region(("grip",))}
    lid.grasps = Deferred.one(top_grasp, 0.0, 0.0, t + h + R, 2 * r + 0.02, "y")
    return lid


def _c_path(r_top, z_top, r_bot, z_bot, s, rb):
    """Tube path of a C handle from the wall at z_top out by ``s``, down and back in."""
    x1 = r_top + s - rb
    return [line(x1 - r_top + _EMBED), arc(rb, -math.pi / 2), line(z_top - z_bot - 2 * rb), arc(rb, -math.pi / 2),
            line(x1 - r_bot + _EMBED)], translation(r_top - _EMBED, 0, z_top), x1 + rb


def c_handle(p, r_top: float, z_top: float, r_bot: float, z_bot: float) -> Part:
    """Round C handle on the side (kettles, jugs)."""
    r = p.uniform("radius", 0.008, 0.012)
    rb = min(p.uniform("bend", 0.015, 0.03), (z_top - z_bot) / 2 - 0.004)
    segs, T, x = _c_path(r_top, z_top, r_bot, z_bot, max(p.uniform("reach", 0.035, 0.05), rb + r_bot - r_top), rb)
    part = _handle("c_handle", tube(r, segs, 0.0, T, role="grip"))
    part.grasps = Deferred.one(_grasp, x, 0.0, (z_top + z_bot) / 2, (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), 2 * r + 0.02)
    part.anchors.update(top=((r_top + x - rb) / 2, 0.0, z_top + r), tube=(r, 0.0, 0.0))
    return part


def sleeved_c_handle(p, r_top: float, z_top: float, r_bot: float, z_bot: float) -> Part:
    """Thin metal C frame with a thick grip sleeve on its upright (pour-over kettles)."""
    r = p.uniform("radius", 0.005, 0.007)
    rb = min(p.uniform("bend", 0.012, 0.022), (z_top - z_bot) / 2 - 0.006)
    segs, T, x = _c_path(r_top, z_top, r_bot, z_bot, max(p.uniform("reach", 0.035, 0.05), rb + r_bot - r_top), rb)
    rs = p.uniform("sleeve_radius", 0.011, 0.015)
    ls = z_top - z_bot - 2 * rb
    prims = tube(r, segs, 0.0, T, role="frame")
    prims.append(cylinder(rs, ls, translation(x, 0, (z_top + z_bot) / 2), role="grip"))
    part = _handle("sleeved_c_handle", prims)
    part.grasps = Deferred.one(_grasp, x, 0.0, (z_top + z_bot) / 2, (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), 2 * rs + 0.02)
    part.anchors.update(top=((r_top + x - rb) / 2, 0.0, z_top + r), tube=(r, 0.0, 0.0))
    return part


def block_c_handle(p, r_top: float, z_top: float, r_bot: float, z_bot: float) -> Part:
    """Moulded D handle of three flat bars (electric kettles)."""
    w = p.uniform("width", 0.018, 0.028)
    t = p.uniform("thickness", 0.012, 0.018)
    x = max(r_top, r_bot) + p.uniform("reach", 0.035, 0.05)
    prims = [cuboid_between((r_top - _EMBED, -w / 2, z_top - t / 2), (x + t / 2, w / 2, z_top + t / 2), role="grip"),
             cuboid_between((x - t / 2, -w / 2, z_bot - t / 2), (x + t / 2, w / 2, z_top + t / 2), role="grip"),
             cuboid_between((r_bot - _EMBED, -w / 2, z_bot - t / 2), (x + t / 2, w / 2, z_bot + t / 2), role="grip")]
    part = _handle("block_c_handle", prims)
    part.grasps = Deferred.one(_grasp, x, 0.0, (z_top + z_bot) / 2, (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), w + 0.02)
    part.anchors.update(top=((r_top + x) / 2, 0.0, z_top + t / 2), tube=(t / 2, 0.0, 0.0))
    return part


KETTLE_HANDLES = {c_handle: 2.0, block_c_handle: 1.5, sleeved_c_handle: 1.0}


def arch_top_handle(p, d: float, clearance: float) -> Part:
    """Fixed arch across the top from a front to a back post; its underside stands
    ``clearance`` above the post feet on the axis."""
    r = p.uniform("radius", 0.007, 0.011)
    R = min(p.uniform("bend", 0.015, 0.03), d * 0.8)
    h = clearance + r - R
    segs = [line(h + _EMBED), arc(R, -math.pi / 2), line(2 * (d - R)), arc(R, -math.pi / 2), line(h + _EMBED)]
    part = _handle("arch_top_handle", tube(r, segs, math.pi / 2, translation(-d, 0, -_EMBED), role="grip"))
    part.anchors["under"] = (0.0, 0.0, h + R - r)
    part.grasps = Deferred(_arch_grasps, d, R, h, r)
    return part
