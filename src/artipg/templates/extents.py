"""One coordinate of a part's bounding box, for rules that need only that.

:meth:`artipg.model.part.Part.bounds` transforms the eight corners of every
primitive's box with numpy, tens of microseconds a part. A rule that needs one side of
it (how high an arm rises, how far a lever reaches) calls :func:`bound` instead: a
cuboid whose pose keeps the asked axis (that row of its rotation is the unit vector)
spans its pose's offset plus or minus half its size along it, the very sum the corner
transform makes, so the result is the same float; other primitives use their bounds.
"""

from __future__ import annotations

from artipg.geometry import Cuboid


def bound(prims, axis: int, upper: bool) -> float:
    """Lowest (``upper`` False) or highest coordinate along ``axis`` (0, 1, 2 for x, y, z)
    of primitives ``prims`` in their part's frame, metres: for a part's primitives,
    ``part.bounds()[int(upper), axis]``."""
    out = None
    for prim in prims:
        T = prim.pose
        row = T[axis]
        if prim.geom is Cuboid and row[axis] == 1.0 and row[axis - 1] == 0.0 and row[axis - 2] == 0.0:
            h = prim.params[axis] / 2
            v = float(row[3] + h if upper else row[3] - h)
        else:
            v = float(prim.bounds()[int(upper), axis])
        if out is None or (v > out if upper else v < out):
            out = v
    return out
