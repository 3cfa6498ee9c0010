"""A part's extent along one axis, for rules that need only that.

:meth:`artipg.model.part.Part.bounds` transforms the eight corners of every
primitive's local box with numpy, tens of microseconds a part. A rule that needs the
extent along one axis (how high an arm rises, how far a lever reaches) calls
:func:`span` instead. Where that row of a primitive's rotation has a single non-zero
entry (the pose maps one local axis onto the asked one, scaled or not: every axis
permutation, and the axis of a rotation about it), the corner transform reduces to
one product and one sum per corner, made here in the same order, so the result is
the same float; other primitives use their bounds.
"""

from __future__ import annotations

from artipg.geometry import Cuboid


def span(prims, axis: int) -> tuple[float, float]:
    """Lowest and highest coordinate along ``axis`` (0, 1, 2 for x, y, z) of primitives
    ``prims`` in their part's frame, metres: for a part's primitives, the column
    ``part.bounds()[:, axis]``."""
    lo = hi = None
    for prim in prims:
        row = prim.pose[axis].tolist()
        nonzero = [k for k in range(3) if row[k] != 0.0]
        if len(nonzero) == 1:
            k = nonzero[0]
            if prim.geom is Cuboid:
                b1 = prim.params[k] / 2
                b0 = -b1
            else:
                b0, b1 = prim.geom.bounds(prim.params)[:, k].tolist()
            r, t = row[k], row[3]
            # the local box's corners lie at b0 and b0 + (b1 - b0), as Primitive.bounds puts them
            v0, v1 = t + b0 * r, t + (b0 + (b1 - b0)) * r
            if r < 0.0:
                v0, v1 = v1, v0
        else:
            v0, v1 = prim.bounds()[:, axis].tolist()
        if lo is None or v0 < lo:
            lo = v0
        if hi is None or v1 > hi:
            hi = v1
    return lo, hi
