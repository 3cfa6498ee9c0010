"""Mobile-phone parts: slab bodies and halves, display windows, hinge knuckles, slide
rails and flush side keys.

Frames: slabs lie flat, ``length`` along x (the earpiece end at +x), ``width`` along
y; a slab's origin is the centre of its bottom face. A display window's origin is the
centre of the face it lies on, the window rising along local +z (turn the frame for
a face looking down). Knuckles are cylinders along y about the origin. A side key
follows the control convention of :mod:`artipg.templates.controls`: mounted on the
plane x = 0 whose outward normal is -x, protruding along -x, pressed along +x.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import rot_x, rot_y, translation
from artipg.model.part import Part, Region

_AXLE_Y = rot_x(math.pi / 2)  # a lathe's z along y


def slab(p, semantic: str, length: float, width: float, thickness: float, radius: float,
         actionable: str = "none") -> Part:
    """A phone body or half: a box with edges rounded by ``radius`` (metres), its
    bottom face centred on the origin. Movable halves (``actionable`` set) get push /
    pull / lift regions over their whole shell."""
    prim = rounded_box(length, width, thickness, radius, translation(0, 0, thickness / 2), role="shell")
    shell = Region(("shell",))
    regions = {"grasp": shell, "lift": shell} if actionable == "none" else \
        {"push": shell, "pull": shell, "lift": shell, "grasp": shell}
    return Part(semantic, "phone_slab", [prim], anchors={"top": (0.0, 0.0, thickness)}, regions=regions,
                actionable=actionable)


def display(p, length: float, width: float, thickness: float = 0.001) -> Part:
    """A display (or camera, speaker) window ``length`` x ``width`` on a face, rising
    ``thickness`` along local +z from the origin."""
    return Part("screen", "display_window", [cuboid(length, width, thickness, translation(0, 0, thickness / 2),
                                                    role="display")])


def knuckles(p, semantic: str, radius: float, spans) -> Part:
    """Hinge knuckles: cylinders of ``radius`` along y over each (y0, y1) of ``spans``,
    their axis through the origin."""
    prims = []
    for y0, y1 in spans:
        T = _AXLE_Y.copy()
        T[1, 3] = (y0 + y1) / 2
        prims.append(cylinder(radius, y1 - y0, T, role="knuckle"))
    return Part(semantic, "hinge_knuckles", prims)


def rails(p, length: float, y_inner: float, y_outer: float, height: float) -> Part:
    """Two slide rails ``length`` long (centred on x), over |y| in [``y_inner``,
    ``y_outer``], from z = 0 up to ``height``."""
    prims = [cuboid_between((-length / 2, s * y_inner if s > 0 else -y_outer, 0.0),
                            (length / 2, y_outer if s > 0 else -y_inner, height), role="rail") for s in (-1, 1)]
    return Part("body", "slide_rails", prims)


def _key_part(template, prim, stand, d, travel, length, height) -> Part:
    box = np.array([[-d - 1e-4, -length / 2, -height / 2], [-d + 1e-4, length / 2, height / 2]])
    cap = Region(("cap",), box)
    return Part("button", template, [prim],
                anchors={"front": (-d, 0.0, 0.0), "back": (-stand, 0.0, 0.0), "stop": (-stand + travel, 0.0, 0.0)},
                regions={"press": cap, "push": cap}, actionable="slider_button")


def side_key(p, length: float, height: float, travel: float) -> Part:
    """Flat key (side volume and power keys, keypad keys): a cap ``length`` (local y) x
    ``height`` (local z) standing ``travel`` + 0.3 mm off the surface (so it needs no
    collar to touch the body), 0.6-1.2 mm proud of it. Anchors as controls' buttons:
    ``front``, ``back``, ``stop``."""
    stand = travel + 0.0003
    d = p.uniform("proud", 0.0006, 0.0012) + stand
    prim = cuboid(d - stand, length, height, translation(-(stand + d) / 2, 0, 0), role="cap")
    return _key_part("side_key", prim, stand, d, travel, length, height)


def round_key(p, length: float, height: float, travel: float) -> Part:
    """A round flat key of diameter min(``length``, ``height``), otherwise as
    :func:`side_key`."""
    stand = travel + 0.0003
    d = p.uniform("proud", 0.0006, 0.0012) + stand
    r = min(length, height) / 2
    prim = cylinder(r, d - stand, translation(-(stand + d) / 2, 0, 0) @ rot_y(math.pi / 2), role="cap")
    return _key_part("round_key", prim, stand, d, travel, 2 * r, 2 * r)


KEYS = {side_key: 2.0, round_key: 1.0}
