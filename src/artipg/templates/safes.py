"""Safe parts: the stepped door and the keypad housing.

``safe_door`` follows the front-panel convention of :mod:`artipg.templates.panels`
(origin at the centre of the front plate's back face, plate in x in [-plate, 0]) and
adds a plug behind the plate (x > 0) that fills the body's opening; hinge it with
:func:`artipg.templates.mounting.mount_hinged` on the front plane of the body. The
plug keeps ``clearance`` from the walls, more on the free side, whose back corner
swings on a radius a little longer than the door is wide.

``keypad_housing`` follows the control convention of :mod:`artipg.templates.controls`
(mounted on a surface facing -x, origin on the surface at the centre of the key
field): a raised frame around a field of keys, with a display window above it.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part, Region

_RING_TO_X = Placer(rot_y(np.pi / 2))


def safe_door(p, width: float, height: float, wall: float, hinge: float, knuckles: bool | None = None) -> Part:
    """Thick stepped door covering a safe's whole front; ``wall`` is the body's wall
    thickness, ``hinge`` +1 for a hinge on the +y edge, -1 on -y. Anchor ``plug``
    (depth, 0, 0) is how far the plug reaches into the body."""
    tf, tp = p.uniform("plate", 0.015, 0.035), p.uniform("plug", 0.02, 0.06)
    c = p.uniform("clearance", 0.002, 0.003)
    cf = (tf + tp) ** 2 / (2 * (width - wall)) + c  # free side: the swing radius exceeds the span
    yh, yf = hinge * (width / 2 - wall - c), -hinge * (width / 2 - wall - cf)
    z = height / 2 - wall - c
    prims = [cuboid_between((-tf, -width / 2, -height / 2), (0.0, width / 2, height / 2), role="plate"),
             cuboid_between((0.0, min(yh, yf), -z), (tp, max(yh, yf), z), role="plug")]
    if p.flag("knuckles", 0.6, fixed=knuckles):  # barrel hinges on the hinge edge, coaxial with the axis
        rk, lk = p.uniform("knuckle_radius", 0.5, 0.9) * tf, p.uniform("knuckle_length", 0.05, 0.1) * height
        prims += [cylinder(rk, lk, translation(-tf, hinge * width / 2, s * (height / 2 - 0.06 * height - lk / 2)),
                           role="hinge") for s in (-1.0, 1.0)]
    face = np.array([[-tf - 1e-4, -width / 2, -height / 2], [-tf + 1e-4, width / 2, height / 2]])
    return Part("door", "safe_door", prims, anchors={"front": (-tf, 0.0, 0.0), "plug": (tp, 0.0, 0.0)},
                regions={"push": Region(("plate",), face)}, actionable="hinge_door")


def keypad_housing(p, field_w: float, field_h: float, depth: float, gap: float):
    """Raised frame, ``depth`` proud of the surface, around a ``field_w`` x ``field_h``
    key field (``gap`` wider on every side), and a display window above.

    Returns
    -------
    (Part, Part)
        The frame (``panel``, anchor ``corner``: its front top corner on +y) and the
        display (``screen``, anchor ``top``), both in the mount frame.
    """
    band = p.uniform("band", 0.006, 0.012)
    d = depth
    iw, ih = field_w + 2 * gap, field_h + 2 * gap
    frame = Part("panel", "keypad_housing", [rect_ring(ih + 2 * band, iw + 2 * band, d, ih, iw,
                                                       _RING_TO_X.at(-d / 2, 0, 0), role="frame")],
                 anchors={"corner": (-d, iw / 2 + band, ih / 2 + band)})
    dh = p.uniform("display_height", 0.015, 0.03)
    dd = p.uniform("display_depth", 0.004, 0.01)
    z0 = ih / 2 + band
    screen = Part("screen", "keypad_display", [cuboid(dd, iw + 2 * band, dh, translation(-dd / 2, 0, z0 + dh / 2),
                                                      role="display")], anchors={"top": (-dd, 0.0, z0 + dh)})
    return frame, screen
