"""Outline builders for the small categories' flat parts, as loops of
:mod:`artipg.geometry.profile` for :func:`artipg.geometry.extrusion.extrusion`
(metres; every outer loop counter-clockwise, every hole clockwise)."""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import profile


def _bulge(turn: float) -> float:
    """Bulge of an arc turning ``turn`` radians (> 0 counter-clockwise)."""
    return math.tan(turn / 4.0)


def blade(length: float, width: float, tip: float = 0.3, belly: float = 0.6) -> list[np.ndarray]:
    """A knife blade along +x from the bolster at x = 0: straight spine at y = width,
    edge at y = 0 curving up to the tip (length, width) over the last ``tip`` fraction
    of the length, an arc turning ``belly`` radians."""
    x_t = length * (1.0 - tip)
    return [np.array([[0.0, 0.0, 0.0], [x_t, 0.0, _bulge(belly)], [length, width, 0.0], [0.0, width, 0.0]])]


def ruler(length: float, width: float, corner: float = 0.0, hole: float = 0.0) -> list[np.ndarray]:
    """A ruler: a rectangle with rounded corners, optionally with a hanging hole of
    diameter ``hole`` near its +x end."""
    loops = [profile.rectangle(length, width, corner)]
    if hole > 0:
        loops.append(profile.oriented(profile.circle(hole / 2, (length / 2 - width / 2, 0.0)), ccw=False))
    return loops


def clip(length: float, width: float, slot: float, slot_length: float) -> list[np.ndarray]:
    """A C-shaped clip seen from the side: a slot ``rectangle`` with round ends
    (stadium, ``width`` across) with a ``slot`` wide cut from +x of ``slot_length``."""
    r = width / 2
    s = slot / 2
    x0, x1 = -length / 2 + r, length / 2 - r
    xs = length / 2 - slot_length
    # stadium outline, then the slot cut in from its +x round end
    c = math.sqrt(max(r * r - s * s, 0.0))
    a_out = math.atan2(s, c)  # angle of the slot's edge on the round end
    return [np.array([
        [x0, -r, 0.0], [x1, -r, _bulge(0.5 * math.pi - a_out)],
        [x1 + c, -s, 0.0], [xs, -s, 0.0], [xs, s, 0.0], [x1 + c, s, _bulge(0.5 * math.pi - a_out)],
        [x1, r, 0.0], [x0, r, _bulge(math.pi)],
    ])]


def plier_half(length: float, jaw: float, width: float, pivot: float) -> list[np.ndarray]:
    """Half of a pair of pliers along +x: a handle from x = -length (``0.6 width``
    across, round end) to the pivot block (``width`` across, |x| <= width / 2), a jaw
    to x = ``jaw`` tapering to ``0.3 width`` (round tip), and a pivot hole of diameter
    ``pivot`` at the origin."""
    w = width / 2
    outer = np.array([
        [-length, -0.3 * w * 2, 0.0], [-w, -w, 0.0], [w, -w, 0.0], [jaw, -0.3 * w, _bulge(math.pi)],
        [jaw, 0.3 * w, 0.0], [w, w, 0.0], [-w, w, 0.0], [-length, 0.6 * w, _bulge(math.pi)],
    ])
    return [profile.oriented(outer, True), profile.oriented(profile.circle(pivot / 2), False)]
