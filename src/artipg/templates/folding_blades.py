"""Folding-knife parts: a handle of two scales with a back spacer, folding blades in
layers between them and the pivot pin.

Frame: the pivot on the z axis at x = 0, the handle along -x, its back (the spacer)
on +y; a closed blade lies in the handle pointing -x and opens by turning about +z
through -y to point +x. Layer k of a blade spans ``z0 <= z <= z0 + t``. Metres.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cylinder, ring
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import translation
from artipg.model.part import Part, Region

PIN_CLEAR = 0.0009


def scales(L: float, w: float, ts: float, inner: float, back: float, round_back: bool = False) -> Part:
    """Bottom and top scales (``ts`` thick, the inner faces ``inner`` apart) from the
    pivot's round front end (radius w / 2) to x = -L, and the back spacer ``back``
    wide along +y between them. ``round_back``: the back end is round too, about a
    second pivot at x = -L (multi-tools), and the spacer stops short of it."""
    r = w / 2
    # the round ends as polygons: caps of outlines with arcs are sampled by rejection
    a = np.linspace(-0.5 * np.pi, 0.5 * np.pi, 9)
    front = list(zip(r * np.cos(a), r * np.sin(a)))
    if round_back:
        outline = profile.polygon([*front, *zip(-L - r * np.cos(a), -r * np.sin(a))])
    else:
        outline = profile.polygon([(-L, -r), *front, (-L, r)])
    prims = [extrusion([outline], ts, pose=translation(0.0, 0.0, z), role="scale")
             for z in (ts / 2, ts + inner + ts / 2)]
    x0 = -L + 1.3 * r if round_back else -L
    spacer = profile.polygon([[x0, r - back], [-1.3 * r, r - back], [-1.3 * r, r], [x0, r]])
    prims.append(extrusion([spacer], inner, pose=translation(0.0, 0.0, ts + inner / 2), role="spacer"))
    return Part("handle", "scaled_handle", prims, regions={"grasp": Region(("scale",))})


def blade(kind: str, L: float, wb: float, spine: float, t: float, z0: float, hole: float, rb: float) -> Part:
    """A folding blade along -x (closed), ``wb`` wide, its spine on y = ``spine`` and
    its edge below, with a round tang of radius ``rb`` holed for the pin; ``kind`` "drop_point", "sheepsfoot" or "spey"."""
    x0 = hole + 0.0004
    top, bot = spine, spine - wb
    if kind == "sheepsfoot":
        pts = [(-x0, bot), (-x0, top), (-L, top), (-L + 0.2 * wb, bot)]
    elif kind == "spey":
        pts = [(-x0, bot), (-x0, top), (-0.75 * L, top), (-L, 0.5 * (top + bot)), (-0.8 * L, bot)]
    else:  # drop point: the spine drops to the tip
        pts = [(-x0, bot), (-x0, top), (-0.7 * L, top), (-L, bot + 0.25 * wb), (-0.85 * L, bot)]
    T = translation(0.0, 0.0, z0 + t / 2)
    prims = [extrusion([profile.polygon(pts)], t, pose=T, role="blade"),
             ring(rb, hole, t - 0.0002, pose=T, role="tang")]
    return Part("blade", f"{kind}_blade", prims, regions={"pull": Region(("blade",)), "grasp": Region(("blade",))},
                actionable="hinge_handle")


def pin(r: float, top: float, rh: float, hh: float) -> Part:
    """The pivot pin from z = 0 to ``top`` with flat heads on both scales' outer faces."""
    prims = [cylinder(r, top, pose=translation(0.0, 0.0, top / 2), role="pin"),
             cylinder(rh, hh, pose=translation(0.0, 0.0, top + hh / 2), role="head")]
    return Part("hinge", "pivot_pin", prims)


BLADES = {"drop_point": 3.0, "sheepsfoot": 1.0, "spey": 1.0}


def tool(kind: str, L: float, wb: float, spine: float, t: float, z0: float, hole: float, rb: float) -> Part:
    """A multi-tool's folding tool in the frame of :func:`blade` (closed along -x,
    spine on y = ``spine``): "saw" (a blade with a toothed edge), "screwdriver" (a
    narrow shank ending in a flat tip) or "opener" (a cap lifter: a broad tool with a
    hooked notch in its edge)."""
    x0 = hole + 0.0004
    top, bot = spine, spine - wb
    if kind == "saw":
        n = max(6, int(0.7 * L / 0.004))  # teeth about 4 mm apart along the edge
        xs = np.linspace(-x0 - 0.2 * L, -0.9 * L, 2 * n + 1)
        teeth = [(x, bot + (0.0 if i % 2 == 0 else 0.18 * wb)) for i, x in enumerate(xs)]
        pts = [(-x0, bot + 0.18 * wb), (-x0, top), (-L, top), (-L, bot + 0.35 * wb), *teeth[::-1]]
    elif kind == "screwdriver":
        w = 0.45 * wb
        pts = [(-x0, bot), (-x0, top), (-L, top), (-L, top - w), (-0.3 * L, top - w), (-0.2 * L, bot)]
    else:  # opener: a hook cut into the edge behind a flat screwdriver tip
        pts = [(-x0, bot), (-x0, top), (-L, top), (-L, top - 0.55 * wb), (-0.7 * L, top - 0.55 * wb),
               (-0.62 * L, bot + 0.1 * wb), (-0.45 * L, top - 0.5 * wb), (-0.35 * L, bot)]
    T = translation(0.0, 0.0, z0 + t / 2)
    prims = [extrusion([profile.polygon(pts)], t, pose=T, role="blade"),
             ring(rb, hole, t - 0.0002, pose=T, role="tang")]
    return Part("blade", f"{kind}_tool", prims, regions={"pull": Region(("blade",)), "grasp": Region(("blade",))},
                actionable="hinge_handle")


TOOLS = {"saw": 1.0, "screwdriver": 1.5, "opener": 1.0}
