"""One coordinate of a part's bounding box, for rules that need only that.

:meth:`artipg.model.part.Part.bounds` transforms the eight corners of every
primitive's local box with numpy, tens of microseconds a part. A rule that needs one
side of it (how high an arm rises, how far a lever reaches) calls :func:`bound`
instead. Where a primitive's pose keeps the asked axis (that row of its rotation is
the unit vector), its extent along it is its pose's offset plus its local box's, the
very sums the corner transform makes, so the result is the same float; other
primitives use their bounds.
"""

from __future__ import annotations

from artipg.geometry import Cuboid


def bound(prims, axis: int, upper: bool) -> float:
    """Lowest (``upper`` False) or highest coordinate along ``axis`` (0, 1, 2 for x, y, z)
    of primitives ``prims`` in their part's frame, metres: for a part's primitives,
    ``part.bounds()[int(upper), axis]``."""
    out = None
    for prim in prims:
        row = prim.pose[axis].tolist()
        if row[axis] == 1.0 and row[axis - 1] == 0.0 and row[axis - 2] == 0.0:
            if prim.geom is Cuboid:
                hi = prim.params[axis] / 2
                lo = -hi
            else:
                lo, hi = prim.geom.bounds(prim.params)[:, axis].tolist()
            # corners at lo and lo + (hi - lo), as Primitive.bounds places them
            v = row[3] + (lo + (hi - lo)) if upper else row[3] + lo
        else:
            v = float(prim.bounds()[int(upper), axis])
        if out is None or (v > out if upper else v < out):
            out = v
    return out
