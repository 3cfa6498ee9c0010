"""Plier parts: the halves of a lap joint (jaw, handle and the half-thickness plate
round the pivot), handle grips and the rivet.

Frame of a half: the pivot on the z axis, the jaw along +x on the side ``hand``
(+1: +y, its gripping face on y = 0), the handle along -x on the other side. Jaws
and handles span the full thickness ``0 <= z <= T`` and stay outside the radius
``R0`` round the pivot, where each half is a plate of half the thickness (the lower
half at the bottom, the upper one at the top), so the halves cross without touching.
Metres.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cylinder, ring
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Part, Region

FACE_GAP = 0.0004  # each jaw's gripping face off y = 0 (closed jaws nearly touch)
PIN_CLEAR = 0.0009  # radial clearance of the rivet in the moving half's plate


def _mirror(pts, hand: float) -> np.ndarray:
    pts = np.asarray(pts, dtype=float)
    return profile.polygon(np.column_stack([pts[:, 0], hand * pts[:, 1]]))


def jaw(kind: str, hand: float, R0: float, L: float, w0: float, w1: float, T: float) -> Part:
    """A jaw from x = ``R0`` to ``R0 + L``, ``w0`` wide at its root and ``w1`` at its
    tip; ``kind`` "pipe_grip" has a hollow in its gripping face, "cutter" a bevelled
    cutting edge, "smooth" a flat face."""
    x1 = R0 + L
    face = [(x1, FACE_GAP), (R0, FACE_GAP)]
    if kind == "pipe_grip":  # a hollow behind the flat tip, for round stock
        d = 0.35 * w0
        face = [(x1, FACE_GAP), (R0 + 0.6 * L, FACE_GAP), (R0 + 0.45 * L, FACE_GAP + d), (R0 + 0.2 * L, FACE_GAP + d),
                (R0 + 0.08 * L, FACE_GAP), (R0, FACE_GAP)]
    outer = [(R0, w0), (R0 + 0.6 * L, 0.5 * (w0 + w1) + 0.15 * w0), (x1, w1)]
    pts = [*face, *outer] if kind != "cutter" else [(x1, FACE_GAP), (R0, FACE_GAP), (R0, w0), (x1 - 0.5 * w1, w1)]
    prim = extrusion([_mirror(pts, hand)], T, pose=translation(0.0, 0.0, T / 2), role="jaw")
    return Part("blade", f"{kind}_jaw", [prim], regions={"grasp": Region(("jaw",))})


def handle_outline(R0: float, L: float, g0: float, g1: float, w0: float, w1: float, hand: float, start: float = 0.0,
                   grow: float = 0.0, bulge: float = 0.0, bow: float = 0.0) -> np.ndarray:
    """Outline of a handle on side ``-hand`` from x = -R0 - start to -R0 - L: its inner
    edge ``g0`` -> ``g1`` off y = 0, ``w0`` -> ``w1`` wide, grown by ``grow`` all round
    and ``bulge`` more at its middle (cushion grips), bowed out by ``bow`` at its middle."""
    u = np.array([start / L, 0.3, 0.6, 1.0])
    u = u[u >= u[0]]
    x = -R0 - u * L
    gin = g0 + (g1 - g0) * u - grow + bow * np.sin(np.pi * u)
    wid = w0 + (w1 - w0) * u + 2 * grow + bulge * np.sin(np.pi * u)
    xe = -R0 - L - grow
    pts = [*zip(x, gin), (xe, gin[-1] + 0.2 * wid[-1]), (xe, gin[-1] + 0.8 * wid[-1]), *zip(x[::-1], (gin + wid)[::-1])]
    return _mirror(pts, -hand)


def handle(p, kind: str, dims, hand: float, T: float, actionable: str) -> Part:
    """A handle (metal) with grip ``kind``: "bare", "dipped" (a plastic coat over the
    outer part) or "cushion" (a thicker grip, swelling in the middle)."""
    R0, L, g0, g1, w0, w1, bow = dims
    prims = [extrusion([handle_outline(R0, L, g0, g1, w0, w1, hand, bow=bow)], T, pose=translation(0.0, 0.0, T / 2),
                       role="shank" if kind != "bare" else "grip")]
    if kind != "bare":
        e = p.uniform("grip_thickness", 0.0008, 0.0015)
        bulge = p.uniform("cushion", 0.002, 0.005) if kind == "cushion" else 0.0
        start = p.uniform("grip_start", 0.25, 0.4) * L
        outline = handle_outline(R0, L, g0, g1, w0, w1, hand, start, e, bulge, bow)
        prims.append(extrusion([outline], T + e, pose=translation(0.0, 0.0, (T + e) / 2), role="grip"))
    return Part("handle", f"{kind}_handle", prims, regions={"grasp": Region(("grip",))}, actionable=actionable)


def pivot_plate(hand: float, R0: float, T: float, hole: float, lower: bool, neck: tuple) -> Part:
    """The half-thickness plate round the pivot (a disc, with a hole for the rivet on
    the moving half) and the necks joining it to the jaw root (``wj`` wide) and the
    handle root (inner edge ``g0``, ``wh`` wide)."""
    wj, g0, wh = neck
    th = T / 2 - 0.0003
    z = th / 2 if lower else T - th / 2
    T_ = translation(0.0, 0.0, z)
    disc = ring(R0, hole, th, pose=T_, role="plate") if hole > 0 else cylinder(R0, th, pose=T_, role="plate")
    d = 0.0015  # the necks reach into the jaw and the handle, and stay off the rivet's hole
    x0 = max(0.6 * R0, hole + 0.0005)
    necks = [extrusion([_mirror(q, hand)], th, pose=T_, role="plate") for q in
             ([(x0, FACE_GAP), (R0 + d, FACE_GAP), (R0 + d, wj), (x0, wj)],
              [(-R0 - d, -g0 - wh), (-x0, -g0 - wh), (-x0, -g0), (-R0 - d, -g0)])]
    return Part("hinge", "lap_plate", [disc, *necks])


def rivet(r: float, T: float, rh: float, hh: float) -> Part:
    """The pivot rivet: a pin through both plates and a domed-flat head on top."""
    top = T + 0.0006  # the head clears the moving plate
    prims = [cylinder(r, top, pose=translation(0.0, 0.0, top / 2), role="pin"),
             cylinder(rh, hh, pose=translation(0.0, 0.0, top + hh / 2), role="head")]
    return Part("hinge", "rivet", prims)


def adjust_screw(x: float, y: float, r: float, L: float, T: float) -> Part:
    """Locking pliers' adjusting screw knob at the end of the fixed handle, along -x."""
    pose = translation(x - L / 2, y, T / 2) @ rot_y(np.pi / 2)
    return Part("knob", "adjust_screw", [cylinder(r, L, pose=pose, role="knob")], regions={"rotate": Region(("knob",))})


GRIPS = {"bare": 1.0, "dipped": 2.0, "cushion": 1.5}
