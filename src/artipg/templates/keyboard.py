"""Computer-keyboard parts: ANSI key layouts, the case, keycaps and fold-out feet.

Layouts are lists of cells in key units (u, 19.05 mm on real boards): ``(x, y, w, h,
kind)`` with x across the board from the left as a typist sees it (object +y to -y),
y from the back row (+x) to the front, ``kind`` "k" (a key) or "r" (a rib: a gap
between key clusters, filled by the case). Keys and ribs tile the key field, so every cap has a neighbour, a rib or the
case's rim within the key gap (< 2 mm).

Frames: the case lies on z = 0 (on four pads), the key field centred on the z axis.
A keycap's origin is the centre of its bottom face; it moves down (-z). A foot's
origin is on its hinge axis (along y); folded, it lies under the case along -x.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry import cuboid_between
from artipg.model.part import Part, Region

GAP = 0.0008  # clearance of a folded foot under the case

MODS = {"standard": (1.25, 1.25, 1.25, 6.25, 1.25, 1.25, 1.25, 1.25), "tsangan": (1.5, 1.0, 1.5, 7.0, 1.5, 1.0, 1.5)}


def _row(y: float, cells, x: float = 0.0, h: float = 1.0) -> list:
    """Cells of one row from ``x``: positive widths are keys, negative ones ribs."""
    out = []
    for w in cells:
        out.append((x, y, abs(w), h, "k" if w > 0 else "r"))
        x += abs(w)
    return out


def ansi_layout(function_row: bool, nav: bool, numpad: bool, bottom: str = "standard") -> tuple[list, float, float]:
    """Cells of an ANSI board (see the module docstring) and the field's size (w, h) in u.

    ``function_row``: Esc and F1-F12 above a half-unit rib; ``nav``: the 3-unit
    navigation cluster (print/scroll/pause, insert..page down, arrows) after a
    quarter-unit rib; ``numpad``: the 4-unit numeric pad after another.
    """
    y0 = 1.5 if function_row else 0.0
    cells = _row(y0, [1] * 13 + [2]) + _row(y0 + 1, [1.5] + [1] * 12 + [1.5]) + \
        _row(y0 + 2, [1.75] + [1] * 11 + [2.25]) + _row(y0 + 3, [2.25] + [1] * 10 + [2.75]) + \
        _row(y0 + 4, MODS[bottom])
    if function_row:
        cells += _row(0, [1, -1, 1, 1, 1, 1, -0.5, 1, 1, 1, 1, -0.5, 1, 1, 1, 1]) + _row(1, [-15], h=0.5)
    x, rows = 15.0, y0 + 5
    for present, width in ((nav, 3.0), (numpad, 4.0)):
        if not present:
            continue
        cells.append((x, 0.0, 0.25, rows, "r"))
        x += 0.25
        if function_row:
            cells += _row(1, [-width], x, h=0.5)
        if width == 3.0:
            cells += (_row(0, [1, 1, 1], x) if function_row else []) + _row(y0, [1, 1, 1], x) + \
                _row(y0 + 1, [1, 1, 1], x) + _row(y0 + 2, [-3], x) + _row(y0 + 3, [-1, 1, -1], x) + \
                _row(y0 + 4, [1, 1, 1], x)
        else:
            cells += (_row(0, [-4], x) if function_row else []) + _row(y0, [1, 1, 1, 1], x) + \
                _row(y0 + 1, [1, 1, 1], x) + _row(y0 + 2, [1, 1, 1], x) + _row(y0 + 3, [1, 1, 1], x) + \
                _row(y0 + 4, [2, 1], x) + [(x + 3, y0 + 1, 1, 2, "k"), (x + 3, y0 + 3, 1, 2, "k")]
        x += width
    return cells, x, rows


def cell_boxes(cells, unit: float, gap: float, size) -> tuple[np.ndarray, np.ndarray]:
    """Keys' and ribs' (x, y, size x, size y) in metres in the object frame, the
    field of ``size`` (w, h) u centred: keys ``gap`` smaller than their cells, ribs
    ``gap / 2`` (each side of a gap gets half). Returns (keys (K, 4), ribs (R, 4))."""
    a = np.array([c[:4] for c in cells], dtype=float)
    is_key = np.array([c[4] == "k" for c in cells])
    W, H = size
    # across the board (u x, left to right for the typist at -x) runs to -y; rows (u y, from the back) to -x
    box = np.column_stack([(H / 2 - a[:, 1] - a[:, 3] / 2) * unit, (W / 2 - a[:, 0] - a[:, 2] / 2) * unit,
                           a[:, 3] * unit, a[:, 2] * unit])
    box[is_key, 2:] -= gap
    box[~is_key, 2:] -= gap / 2
    return box[is_key], box[~is_key]


def keyboard_case(p, field: tuple[float, float], gap: float, ribs: np.ndarray, levels: tuple[float, float],
                  pad: float) -> Part:
    """Case: a base slab, a rim around the key field (``field`` = (x, y) extents,
    metres) and the ``ribs`` between clusters, on four pads ``pad`` tall.

    ``levels`` = (slab top, rim and rib top) z in metres. Anchors: ``size``
    (the case's outer x, y extents).
    """
    border = p.uniform("border", 0.006, 0.02)
    back = border + p.uniform("back_extra", 0.0, 0.02)  # a wider rim behind the keys (logo, lights)
    fx, fy = field
    X, Y = fx + border + back, fy + 2 * border
    cx = (back - border) / 2  # the case's centre in x (the field stays centred)
    z0, z1 = levels
    prims = [cuboid_between((cx - X / 2, -Y / 2, pad), (cx + X / 2, Y / 2, z0), role="shell")]
    prims += _rim(X, Y, fx, fy, gap, cx, z0, z1)
    prims += [cuboid_between((x - sx / 2, y - sy / 2, z0), (x + sx / 2, y + sy / 2, z1), role="rib")
              for x, y, sx, sy in ribs]
    pw = p.uniform("pad_size", 0.008, 0.015)
    for sx in (-1, 1):
        for sy in (-1, 1):
            x, y = cx + sx * (X / 2 - pw), sy * (Y / 2 - pw)
            prims.append(cuboid_between((x - pw / 2, y - pw / 2, 0.0), (x + pw / 2, y + pw / 2, pad), role="pad"))
    return Part("body", "keyboard_case", prims, anchors={"size": (X, Y, cx)},
                regions={"grasp": Region(("shell", "rim")), "lift": Region(("shell", "rim"))})


def _rim(X, Y, fx, fy, gap, cx, z0, z1) -> list:
    """The rim: four bars around the key field (``gap`` / 2 off its edge)."""
    x0, x1, y0, y1 = cx - X / 2, cx + X / 2, -(fy + gap) / 2, (fy + gap) / 2
    xf, xb = -(fx + gap) / 2, (fx + gap) / 2
    return [cuboid_between((x0, -Y / 2, z0), (xf, Y / 2, z1), role="rim"),
            cuboid_between((xb, -Y / 2, z0), (x1, Y / 2, z1), role="rim"),
            cuboid_between((xf, -Y / 2, z0), (xb, y0, z1), role="rim"),
            cuboid_between((xf, y1, z0), (xb, Y / 2, z1), role="rim")]


def keycap(size_x: float, size_y: float, height: float) -> Part:
    """A keycap ``size_x`` x ``size_y`` x ``height`` metres standing on its origin."""
    prim = cuboid_between((-size_x / 2, -size_y / 2, 0.0), (size_x / 2, size_y / 2, height), role="cap")
    top = np.array([[-size_x / 2, -size_y / 2, height - 1e-4], [size_x / 2, size_y / 2, height + 1e-4]])
    return Part("button", "keycap", [prim], regions={"press": Region(("cap",), top), "push": Region(("cap",), top)},
                actionable="slider_button")


def fold_foot(p, length: float, width: float, thickness: float) -> Part:
    """Fold-out foot: a plate from its hinge (origin) along -x, ``thickness`` centred on
    the hinge axis."""
    prims = [cuboid_between((-length, -width / 2, -thickness / 2), (0.0, width / 2, thickness / 2), role="foot")]
    end = np.array([[-length - 1e-4, -width / 2, -thickness / 2], [-length + 0.004, width / 2, thickness / 2]])
    return Part("leg", "fold_foot", prims, regions={"pull": Region(("foot",), end), "rotate": Region(("foot",))})
