"""Scissor parts: blades (pointed, round-tipped, pinking), handles (round loops,
finger loop, bent metal loops) and the pivot screw.

Frame of a half: the pivot on the z axis, the blade along +x, the handle towards -x
and to the side ``hand`` (+1: +y, -1: -y); its metal layer lies in
``z0 <= z <= z0 + t``. The blade's cutting edge faces the side of its own handle, so
that a half turning about +z with its handle on -y opens its blade towards +y, across
the other blade. Handles of both halves span the object's full height (``0 <= z <=
height``), side by side when closed. Metres.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cylinder, ring
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region

HOLE_CLEAR = 0.0009  # radial clearance of the screw in the moving half's boss


def _tip(Lb: float, wb: float, edge: float, kind: str, teeth: int) -> list:
    """Outline points (x, y, bulge) of a blade with its edge on +y, from the spine at
    the pivot round the tip and back along the edge (counter-clockwise)."""
    pts = [(0.0, -wb / 2, 0.0), (0.6 * Lb, -0.42 * wb, 0.0)]
    if kind == "round":
        # a half-circle tip as a polygon (caps of outlines with arcs are sampled by rejection)
        rt = 0.28 * wb
        a = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 7)
        pts += [(Lb - rt + rt * math.cos(v), edge + rt * math.sin(v), 0.0) for v in a]
    else:
        pts += [(Lb, edge, 0.0)]
    if kind == "pinking":
        # zigzag teeth along the edge from the tip back to the pivot
        x = np.linspace(0.92 * Lb, 0.12 * Lb, 2 * teeth + 1)[1:]
        y = edge + (wb / 2 - edge) * (1 - x / Lb) + np.where(np.arange(len(x)) % 2 == 0, 0.0, -0.1 * wb)
        pts += [(float(a), float(b), 0.0) for a, b in zip(x, y)]
    pts += [(0.0, wb / 2, 0.0)]
    return pts


def blade_half(p, hand: float, kind: str, Lb: float, wb: float, t: float, z0: float, hole: float, loop) -> Part:
    """The metal of one half: blade, boss round the pivot and tang to the handle.

    ``hole`` is the boss's hole radius (0: solid, the screw's own half); ``loop``
    = (x, y) of the handle's centre, where the tang ends.
    """
    edge = 0.08 * wb
    pts = np.array(_tip(Lb, wb, edge, kind, p.integers("teeth", 9, 16) if kind == "pinking" else 0))
    x0 = hole + 0.0004 if hole > 0 else 0.0
    pts[:, 0] = np.maximum(pts[:, 0], x0)
    pts[:, 1] *= hand  # the edge faces the own handle's side
    zc = z0 + t / 2
    T = translation(0.0, 0.0, zc)
    rb = wb / 2
    tb = t - 0.0002  # a hair thinner than the blade: no coplanar overlapping faces
    boss = ring(rb, hole, tb, pose=T, role="boss") if hole > 0 else cylinder(rb, tb, pose=T, role="boss")
    ws = 0.7 * wb
    xl, yl = loop
    tang = profile.polygon([[-x0, -ws / 2], [-x0, ws / 2], [xl, yl + ws / 2], [xl, yl - ws / 2]])
    prims = [extrusion([pts], t, pose=T, role="blade"), boss, extrusion([tang], t, pose=T, role="tang")]
    return Part("blade", f"{kind}_blade", prims, regions={"push": Region(("blade",))})


def _loop(w: float, h: float, wall: float, height: float, centre, role: str):
    """A flat loop ``w`` (x) by ``h`` (y) with a ``wall`` thick rim, on z = [0, height]."""
    cx, cy = centre
    T = translation(cx, cy, height / 2)
    if abs(w - h) < 1e-9:
        return ring(w / 2, w / 2 - wall, height, pose=T, role=role)
    r = 0.49 * min(w, h)
    outer = profile.rectangle(w, h, r)
    inner = profile.rectangle(w - 2 * wall, h - 2 * wall, r - wall)
    return extrusion([outer, inner], height, pose=T, role=role)


def _sleeve(start: float, loop, ws: float, height: float, role: str = "grip"):
    """Plastic grip from ``start`` (fraction of the way out from the pivot) to the loop."""
    xl, yl = loop
    xa, ya = start * xl, start * yl
    quad = profile.polygon([[xa, ya - ws / 2], [xl, yl - ws / 2], [xl, yl + ws / 2], [xa, ya + ws / 2]])
    # 0.2 mm inside the loop's faces: no coplanar overlapping faces
    return extrusion([quad], height - 0.0004, pose=translation(0.0, 0.0, height / 2), role=role)


def handle_size(kind: str, p, finger: bool):
    """(length along x, width along y, wall) of a handle loop of template ``kind``."""
    if kind == "metal_loops":
        d = p.uniform("loop", 0.018, 0.024)
        return d, d, p.uniform("wall", 0.003, 0.004)
    if kind == "finger_loop" and finger:
        return p.uniform("loop_length", 0.032, 0.048), p.uniform("loop_width", 0.018, 0.024), p.uniform("wall", 0.003, 0.0045)
    d = p.uniform("loop", 0.02, 0.028)
    return d, d, p.uniform("wall", 0.003, 0.0045)


def handle(kind: str, loop, size, height: float, sleeve: float, actionable: str) -> Part:
    """A handle: the loop at ``loop`` (x, y) and, on plastic handles, a grip sleeve."""
    w, h, wall = size
    prims = [_loop(w, h, wall, height, loop, "grip")]
    if kind != "metal_loops":
        prims.append(_sleeve(sleeve, (loop[0] + w / 2 - wall / 2, loop[1]), 0.9 * wall + 0.004, height))
    return Part("handle", kind, prims, regions={"grasp": Region(("grip",))}, actionable=actionable)


def screw(rs: float, top: float, rh: float, hh: float) -> Part:
    """Pivot screw: a shaft from z = 0 to ``top`` and a head ``rh`` by ``hh`` above it."""
    prims = [cylinder(rs, top, pose=translation(0.0, 0.0, top / 2), role="shaft"),
             cylinder(rh, hh, pose=translation(0.0, 0.0, top + hh / 2), role="head")]
    return Part("hinge", "pivot_screw", prims)


HANDLES = {"round_loops": 2.0, "finger_loop": 2.0, "metal_loops": 1.0}
