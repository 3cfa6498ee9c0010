"""Procedural geometric detail shared by the templates: rounded panel edges (boxes),
rounded vessel lips, and discs with rounded or chamfered rims (board tops, knobs,
lids, bar ends).

Every size here is drawn through the recorder's ``detail_*`` methods
(:mod:`artipg.rules.detail`): with detail off they return the sharp values (radius 0,
no lip) without drawing, and the structure's parameters are the same either way.
Rounded shapes stay inside the sharp ones they replace (a rounded box inside its box,
a rounded lip inside the wall's top), so clearances, contacts and anchors computed
from the sharp sizes still hold.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, frustum, ring
from artipg.geometry.lathe import lathe
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import translation

#: Edge radius range (metres) of furniture panels and appliance bodies.
EDGE_RADIUS = (0.001, 0.006)
#: Largest edge radius as a share of the panel's thinnest dimension (a rounding of
#: half the thickness would leave no flat edge band).
EDGE_SHARE = 0.3


def edge_radius(p, thin: float, name: str = "edge_radius", lo: float = EDGE_RADIUS[0],
                hi: float = EDGE_RADIUS[1], share: float = EDGE_SHARE) -> float:
    """The edge radius (metres) of a part whose thinnest dimension is ``thin``.

    Drawn in ``[min(lo, s), s]`` with ``s = min(hi, share * thin)``, so it scales with
    the part's thickness and never exceeds ``share`` (< 1/2) of it; 0 with detail off.
    """
    top = min(hi, share * thin)
    return p.detail_uniform(name, min(lo, top), top)


def rbox(sx: float, sy: float, sz: float, r: float, pose: np.ndarray, role: str = ""):
    """A box of extents (sx, sy, sz) at ``pose`` with edges rounded by ``r`` (a plain
    :func:`~artipg.geometry.cuboid` when r is 0); r is clipped to below half the
    thinnest extent."""
    if r <= 0.0:
        return cuboid(sx, sy, sz, pose, role)
    return rounded_box(sx, sy, sz, min(r, 0.49 * min(sx, sy, sz)), pose, role)


def rbox_between(lo, hi, r: float, role: str = ""):
    """:func:`~artipg.geometry.cuboid_between` with edges rounded by ``r`` (see :func:`rbox`)."""
    if r <= 0.0:
        return cuboid_between(lo, hi, role)
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    return rbox(x1 - x0, y1 - y0, z1 - z0, r, translation((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), role)


#: Lip styles of vessel walls: a half-round (bullnose) top, or a flat top with its
#: outer corner rounded (an eased rim).
LIPS = {"round": 2.0, "eased": 1.0}

_QUARTER = math.tan(math.pi / 8)  # bulge of a quarter-circle arc


def lip_style(p) -> str:
    """The lip style of a vessel's rim (:data:`LIPS`); ``"flat"`` with detail off."""
    return p.detail_choice("lip", LIPS, "flat")


def lipped_wall(r_out: float, r_in: float, height: float, zc: float, lip: str, taper: float = 0.0,
                role: str = "wall", max_lip: float = math.inf) -> list:
    """Primitives of a vessel wall ``height`` tall centred at height ``zc`` (radii
    ``r_out`` > ``r_in`` at the bottom, both growing by ``taper`` to the top) whose top
    is a lip of style ``lip``.

    ``"flat"`` is the plain :func:`~artipg.geometry.ring`. Otherwise the ring stops
    ``e`` below the top (its top face, now inside, left out of the sampled surface)
    and one lathe primitive of the same role sits on it: the upper half of a disc of
    the wall's thickness t (``"round"``, e = t / 2), or a flat top e = 0.6 t high with
    its outer corner a quarter circle of radius e (``"eased"``). The lip has the
    ring's radii where it starts and rises straight, so it lies inside the sharp ring
    (to within taper x e on a flaring wall) and its top is the sharp top. A wall
    thicker than ``2 max_lip`` gets the eased lip with e at most ``max_lip``.
    """
    t = r_out - r_in
    if lip == "flat" or t <= 0.0:
        return [ring(r_out, r_in, height, pose=translation(0, 0, zc), role=role, taper=taper)]
    z0 = zc - 0.5 * height
    if 0.5 * t > max_lip:
        lip = "eased"
    e = min(0.5 * t if lip == "round" else 0.6 * t, 0.45 * height, max_lip)
    hb = height - e
    k = taper / height
    wall = ring(r_out, r_in, hb, pose=translation(0, 0, z0 + hb / 2), role=role, taper=k * hb)
    P = wall.params
    wall = wall._replace(params=P[:11] + (0.0,) + P[12:])  # the top face (segment 2) is inside the lip
    ro, ri = r_out + k * hb, r_in + k * hb  # radii where the lip starts
    if lip == "round":
        # chord (ri, 0) -> (ro, 0) left out of the sampled surface, then a half turn over the top
        c, r = 0.5 * (ro + ri), 0.5 * (ro - ri)
        loop = [(c - r, 0.0, 0.0), (c + r, 0.0, 1.0)]
        on = (0.0, 1.0)
    else:
        loop = [(ri, 0.0, 0.0), (ro, 0.0, _QUARTER), (ro - e, e, 0.0), (ri, e, 0.0)]
        on = (0.0, 1.0, 1.0, 1.0)
    return [wall, lathe(loop, on=on, pose=translation(0, 0, z0 + hb), role=role)]


#: Edge profiles of round boards and discs: both edges rounded, or the top edge
#: bevelled (a 45-degree chamfer) and the bottom one eased.
EDGE_PROFILES = {"round": 2.0, "bevel": 1.0}


def edge_profile(p, t: float) -> tuple:
    """``(top, bottom, bevel)``: the edge sizes (metres) of a round board ``t`` thick
    (:func:`edge_radius` each) and whether the top edge is a chamfer; zeros with
    detail off."""
    style = p.detail_choice("edge_profile", EDGE_PROFILES, "round")
    top = edge_radius(p, t, "edge_radius")
    bottom = edge_radius(p, t, "bottom_radius", hi=0.004) if top > 0.0 else 0.0
    return top, bottom, style == "bevel" and top > 0.0


def rounded_disc(R: float, t: float, top: float, bottom: float, bevel: bool, pose: np.ndarray, role: str = "",
                 R_top: float | None = None):
    """A disc of radius ``R`` (``R_top`` at its top: a frustum) and thickness ``t``
    centred at ``pose`` (axis z) whose top and bottom rims are rounded by ``top`` /
    ``bottom`` (metres; a 45-degree chamfer of that size on top when ``bevel``); the
    plain :func:`~artipg.geometry.frustum` when both are 0."""
    Rt = R if R_top is None else R_top
    if top <= 0.0 and bottom <= 0.0:
        return frustum(R, Rt, t, pose, role)
    h = 0.5 * t
    k = (Rt - R) / t  # radius change per metre of height along the side
    loop = [(0.0, -h, 0.0)]
    if bottom > 0.0:
        loop += [(R - bottom, -h, _QUARTER), (R + k * bottom, -h + bottom, 0.0)]
    else:
        loop += [(R, -h, 0.0)]
    if top > 0.0:
        loop += [(Rt - k * top, h - top, 0.0 if bevel else _QUARTER), (Rt - top, h, 0.0)]
    else:
        loop += [(Rt, h, 0.0)]
    loop += [(0.0, h, 0.0)]
    return lathe(loop, pose=pose, role=role)
