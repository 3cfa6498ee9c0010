"""Laptop parts: the base (a shell on feet with the hinge barrel), keyboards,
touchpads and the screen lid.

Frames: ``laptop_base`` has its origin at the centre of the footprint on the floor,
+z up, front towards -x; its anchor ``deck`` is the centre of the top face and
``hinge`` the hinge axis (along y) behind the back edge. The base is a shell whose top
skin leaves openings (``holes``) for the deck inserts: keyboards and touchpads have
their origin at the centre of their opening on the deck plane and fill it with a plate
``skin`` thick (anchor ``skin`` of the base), so no other surface lies just under
them. ``screen_lid`` has its origin on the hinge axis and, closed, lies on the deck
towards -x, face down; its rim stands on the deck and keeps the display clear of the
keys.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, rect_ring
from artipg.geometry.transforms import Placer, rot_x, translation
from artipg.model.part import Part, Region

_Y = Placer(rot_x(math.pi / 2))  # local z -> y


def _skin(D: float, W: float, holes, z0: float, z1: float) -> list:
    """Boxes of a skin over x in [-D, D], y in [-W, W] around ``holes`` (x0, x1, y0, y1)
    that do not overlap in x: full-width strips between them, side strips beside them."""
    prims, x = [], -D
    for x0, x1, y0, y1 in sorted(holes) + [(D, D, 0.0, 0.0)]:
        if x0 > x:
            prims.append(cuboid_between((x, -W, z0), (x0, W, z1), role="body"))
        if x1 > x0:
            prims += [cuboid_between((x0, -W, z0), (x1, y0, z1), role="body"),
                      cuboid_between((x0, y1, z0), (x1, W, z1), role="body")]
        x = x1
    return prims


def laptop_base(p, width: float, depth: float, thickness: float, holes=()) -> Part:
    """Base shell on round feet or rubber strips, with one full-width hinge barrel or
    two short ones along the back edge; ``holes`` (x0, x1, y0, y1) are openings in the
    top skin for the deck inserts."""
    feet = p.uniform("foot_height", 0.001, 0.003)
    rb = p.uniform("barrel_radius", 0.35, 0.5) * thickness
    sk, wt = p.uniform("skin", 0.0015, 0.003), p.uniform("shell", 0.0015, 0.003)
    D, W = depth / 2, width / 2
    h = feet + thickness
    prims = [cuboid_between((-D, -W, feet), (D, W, feet + wt), role="body"),
             cuboid_between((-D, -W, feet + wt), (-D + wt, W, h - sk), role="body"),
             cuboid_between((D - wt, -W, feet + wt), (D, W, h - sk), role="body"),
             cuboid_between((-D + wt, -W, feet + wt), (D - wt, -W + wt, h - sk), role="body"),
             cuboid_between((-D + wt, W - wt, feet + wt), (D - wt, W, h - sk), role="body"),
             *_skin(D, W, holes, h - sk, h)]
    if p.flag("strip_feet", 0.4):
        prims += [cuboid_between((x - 0.006, -W + 0.03, 0), (x + 0.006, W - 0.03, feet + 1e-4), role="foot")
                  for x in (-D + 0.025, D - 0.025)]
    else:
        fr = p.uniform("foot_radius", 0.004, 0.008)
        prims += [cylinder(fr, feet + 1e-4, translation(sx * (D - 0.025), sy * (W - 0.03), feet / 2), role="foot")
                  for sx in (-1, 1) for sy in (-1, 1)]
    ax, az = D + 0.8 * rb, h - rb  # hinge axis, barrel flush with the deck
    hinge_len = p.uniform("hinge_length", 0.15, 0.35) if p.flag("two_hinges", 0.5) else 0.0
    if hinge_len:  # two short barrels near the corners
        L = hinge_len * W
        prims += [cylinder(rb, L, _Y.at(ax, s * (W - 0.02 - L / 2), az), role="hinge") for s in (-1, 1)]
    else:
        prims.append(cylinder(rb, width - 0.04, _Y.at(ax, 0, az), role="hinge"))
    return Part("base", "laptop_base", prims, anchors={"deck": (0.0, 0.0, h), "hinge": (ax, 0.0, az),
                                                       "barrel": (rb, 0.0, 0.0), "skin": (sk, 0.0, 0.0)},
                regions={"lift": Region(("body",))})


def _keyboard(template, prims, w, d, h, plate, key_top=None) -> Part:
    """The keyboard part; ``press`` covers the key tops at ``key_top`` (default ``h``)."""
    kt = h if key_top is None else key_top
    top = np.array([[-d / 2, -w / 2, kt - 1e-4], [d / 2, w / 2, kt + 1e-4]])
    prims.append(cuboid(d, w, plate, translation(0, 0, -plate / 2), role="plate"))
    return Part("keyboard", template, prims, anchors={"top": (0.0, 0.0, h)}, regions={"press": Region(("key",), top)})


def row_keyboard(p, width: float, depth: float, height: float, plate: float) -> Part:
    """Keys as five or six raised rows (a row of keycaps as one strip), with a space bar."""
    n = p.integers("rows", 5, 6)
    pitch = depth / n
    gap = p.uniform("row_gap", 0.12, 0.25) * pitch
    prims = [cuboid(pitch - gap, width * (0.45 if i == 0 else 1.0), height,
                    translation(-depth / 2 + (i + 0.5) * pitch, 0, height / 2), role="key") for i in range(n)]
    return _keyboard("row_keyboard", prims, width, depth, height, plate)


def block_keyboard(p, width: float, depth: float, height: float, plate: float) -> Part:
    """Chiclet keyboard in blocks: each row split into groups of keys, a separate
    arrow cluster and optionally a numeric keypad on the right."""
    n = p.integers("rows", 5, 6)
    pitch = depth / n
    gap = p.uniform("key_gap", 0.12, 0.2) * pitch
    numpad = width > 0.3 and p.flag("numpad", 0.5)
    wm = width * (0.78 if numpad else 1.0)
    prims = []
    for i in range(n):
        x = -depth / 2 + (i + 0.5) * pitch
        groups = (0.12, 0.5, 0.12) if i == 0 else (0.3, 0.4, 0.3) if i == n - 1 else (0.5, 0.5)
        y = -width / 2
        for g in groups:
            w = g * wm - gap
            prims.append(cuboid(pitch - gap, w, height, translation(x, y + gap / 2 + w / 2, height / 2), role="key"))
            y += g * wm
    if numpad:
        prims.append(cuboid(depth - gap, width - wm - gap, height, translation(0, width / 2 - (width - wm) / 2,
                                                                               height / 2), role="key"))
    return _keyboard("block_keyboard", prims, width, depth, height, plate)


def well_keyboard(p, width: float, depth: float, height: float, plate: float) -> Part:
    """Keyboard seen as a key field inside a raised surround (a keyboard bezel)."""
    band = p.uniform("surround", 0.003, 0.006)
    prims = [rect_ring(depth, width, height, depth - 2 * band, width - 2 * band, translation(0, 0, height / 2),
                       role="surround"),
             cuboid(depth - 2 * band, width - 2 * band, 0.7 * height, translation(0, 0, 0.35 * height), role="key")]
    return _keyboard("well_keyboard", prims, width, depth, height, plate, key_top=0.7 * height)


KEYBOARDS = {block_keyboard: 2.0, row_keyboard: 1.5, well_keyboard: 1.0}


def touchpad(p, width: float, depth: float, plate: float) -> Part:
    """Touchpad: a plate filling its opening in the palm rest, a hair proud of it."""
    t = p.uniform("proud", 0.0002, 0.0006)
    top = np.array([[-depth / 2, -width / 2, t - 1e-4], [depth / 2, width / 2, t + 1e-4]])
    return Part("touchpad", "touchpad", [cuboid(depth, width, t + plate, translation(0, 0, (t - plate) / 2),
                                                role="pad")],
                regions={"press": Region((), top), "push": Region((), top)})


def screen_lid(p, width: float, depth: float, thickness: float, rim: float, barrel: float) -> Part:
    """Screen lid, closed: a shell over a rim of height ``rim`` (standing on the deck)
    with the display set in its underside; the origin is the hinge axis, which lies
    ``barrel`` below the deck at the lid's back edge."""
    band = p.uniform("rim_band", 0.004, 0.008)
    bezel = p.uniform("bezel", 0.005, 0.02)
    z0 = barrel  # the deck
    prims = [cuboid_between((-depth, -width / 2, z0 + rim), (0.0, width / 2, z0 + rim + thickness), role="shell"),
             rect_ring(depth, width, rim, depth - 2 * band, width - 2 * band, translation(-depth / 2, 0, z0 + rim / 2),
                       role="rim"),
             cuboid_between((-depth + bezel + band, -width / 2 + bezel, z0 + rim - 5e-4),
                            (-bezel - band, width / 2 - bezel, z0 + rim), role="display")]
    grip = np.array([[-depth - 1e-3, -width / 4, z0], [-depth + 0.01, width / 4, z0 + rim + thickness]])
    return Part("screen", "screen_lid", prims, anchors={"front": (-depth, 0.0, z0 + rim + thickness / 2)},
                regions={"lift": Region(("shell",), grip), "grasp": Region(("shell",), grip)},
                actionable="hinge_lid")
