"""Drying-rack parts: tube ladders (a frame of two side tubes and end bars with rails
between them) and swept U-shaped leg frames.

Frames (metres): a ladder's bars and rails run along local x, centred on x = 0; its
side tubes run along local +y from the first bar (y = ``start``) to the last
(y = ``length``); the hinge of a folding ladder is the local x axis. A leg frame is an
inverted U in the local x-z plane: its top bar on the local x axis (the hinge), its
legs running down to z = -``length``. Every size comes from the caller.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cylinder
from artipg.geometry.sweep import sweep
from artipg.geometry.transforms import rot_x, rot_y, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Part

_ALONG_X = rot_y(math.pi / 2)  # local z -> x
_ALONG_Y = rot_x(-math.pi / 2)  # local z -> y


def frame_pose(origin, u, v) -> np.ndarray:
    """Pose mapping local x to ``u`` and local y to ``v`` (unit, orthogonal), local z to u x v."""
    T = np.eye(4)
    T[:3, 0], T[:3, 1], T[:3, 2], T[:3, 3] = u, v, np.cross(u, v), origin
    return T


def _bar(r: float, length: float, y: float, role: str):
    return cylinder(r, length, translation(0.0, y, 0.0) @ _ALONG_X, role=role)


def ladder(width: float, length: float, rails, r_frame: float, r_rail: float, start: float = 0.0,
           end_bar: bool = True, first_bar: bool = True, rail_label: str = "rail") -> tuple[Part, Part]:
    """A rack frame: end bars along x (``width`` long) at y = ``start`` and y = ``length``,
    two side tubes along y at x = ±(width/2 - r_frame), and rails (radius ``r_rail``)
    along x at the distances ``rails`` (y) between the side tubes.

    Returns
    -------
    (Part, Part)
        The frame (label ``frame``: tubes and end bars) and the rails (label
        ``rail_label``: ``frame`` for the cross bars of a side frame).
    """
    xs = width / 2 - r_frame
    run = length - start
    tubes = [cylinder(r_frame, run, translation(s * xs, start + run / 2, 0.0) @ _ALONG_Y, role="tube")
             for s in (-1.0, 1.0)]
    if first_bar:
        tubes.append(_bar(r_frame, width, start, "tube"))
    if end_bar:
        tubes.append(_bar(r_frame, width, length, "tube"))
    rail_prims = [_bar(r_rail, 2 * xs, float(y), "rail") for y in rails]
    return (Part("frame", "tube_ladder", tubes, anchors={"end": (0.0, length, 0.0)}),
            Part(rail_label, "rails", rail_prims))


def leg_frame(width: float, length: float, r: float, bend: float) -> Part:
    """Inverted-U leg frame swept as one tube: the top bar (``width`` between the leg
    axes) on the local x axis, the legs down to z = -``length``, corners bent with
    radius ``bend``."""
    path = [line(length - bend), arc(bend, -math.pi / 2), line(width - 2 * bend), arc(bend, -math.pi / 2),
            line(length - bend)]
    # sweep paths lie in the local x-z plane: start at the left foot heading up (+z)
    T = translation(-width / 2, 0.0, -length)
    return Part("leg", "u_leg", [sweep(r, path, heading=math.pi / 2, pose=T, role="leg")],
                anchors={"foot": (width / 2, 0.0, -length)})


def evenly(n: int, a: float, b: float) -> np.ndarray:
    """``n`` positions evenly inside (a, b), ends excluded."""
    return a + (b - a) * np.arange(1, n + 1) / (n + 1)
