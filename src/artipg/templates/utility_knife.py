"""Utility-knife parts: a channel handle and the blade carrier that slides in it.

Frame: the handle along +x from its back end (x = 0) to its nose (x = ``L``), the
channel's floor on z = 0 (the grip reaches below it), centred on y = 0. The channel (``wi`` wide, from z = ``zb`` to
``zt``) runs the whole length and is open at the nose; the top cover over it is cut
by a slot from x = ``slot[0]`` to ``slot[1]`` through which the carrier's thumb slider
rises. The carrier slides along +x (the blade comes out of the nose). Metres.
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between, profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import rot_x, translation
from artipg.model.part import Part, Region

_XZ = rot_x(0.5 * math.pi)  # extrusion outline (x, z), extruded along y


def channel_handle(L: float, H: float, wi: float, ts: float, zb: float, zt: float, slot, nose: float,
                   drop: float) -> Part:
    """Side plates (``ts`` thick, their front top corner cut back by ``nose``, the grip
    behind 0.55 ``L`` ``drop`` deeper, z < 0), the bottom bar under the channel (down
    to the grip's underside), a back cap and the top cover on both sides of the slot."""
    bottom = [(0.0, -drop), (0.55 * L, -drop), (0.75 * L, 0.0)]
    side = profile.polygon([*bottom, (L, 0.0), (L, zt + 0.25 * (H - zt)), (L - nose, H), (0.0, H)])
    prims = [extrusion([side], ts, pose=translation(0.0, s * (wi + ts) / 2, 0.0) @ _XZ, role="grip")
             for s in (1.0, -1.0)]
    y = wi / 2
    floor = profile.polygon([*bottom, (L, 0.0), (L, zb), (0.0, zb)])
    prims += [extrusion([floor], wi, pose=_XZ, role="grip"),
              cuboid_between((0.0, -y, zb), (0.004, y, zt), role="grip"),
              cuboid_between((0.0, -y, zt), (slot[0], y, H), role="grip"),
              cuboid_between((slot[1], -y, zt), (L - nose, y, H), role="grip")]
    return Part("handle", "channel_handle", prims, regions={"grasp": Region(("grip",))})


def carrier(x0: float, x1: float, wi: float, zb: float, zt: float, gap: float, neck, button) -> Part:
    """The blade carrier in the channel (``gap`` off its walls) from x0 to x1, a neck
    ``neck`` = (x, length) rising through the slot and a thumb button ``button`` =
    (length, width, height, H) riding 1.5 mm above the cover, whose top is z = H."""
    xn, nl = neck
    bl, bw, bh, H = button
    y = wi / 2 - gap
    prims = [cuboid_between((x0, -y, zb + gap), (x1, y, zt - gap), role="carrier"),
             cuboid_between((xn, -0.3 * wi, zt - gap - 0.001), (xn + nl, 0.3 * wi, H + 0.0015 + 0.001), role="neck"),
             rounded_box(bl, bw, bh, 0.3 * bh, translation(xn + nl / 2, 0.0, H + 0.0015 + bh / 2), role="thumb")]
    return Part("button", "thumb_slider", prims, regions={"press": Region(("thumb",)), "push": Region(("thumb",))},
                actionable="slider_button")


def trapezoid_blade(x0: float, length: float, z0: float, z1: float, t: float) -> Part:
    """A trapezoid blade from x0 (inside the carrier) to its tip at x0 + ``length``:
    the cutting edge along z = z0, the back along z = z1, both ends slanted."""
    k = 0.4 * (z1 - z0)
    outline = profile.polygon([(x0, z0), (x0 + length, z0), (x0 + length - k, z1), (x0 + k, z1)])
    return Part("blade", "trapezoid_blade", [extrusion([outline], t, pose=_XZ, role="blade")],
                regions={"grasp": Region(("blade",))})
