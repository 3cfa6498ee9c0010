"""A part's extent along one axis, for rules that need only that.

:meth:`artipg.model.part.Part.bounds` transforms the eight corners of every
primitive's local box with numpy, tens of microseconds a part. A rule that needs the
extent along one axis (how high an arm rises, how far a lever reaches) calls
:func:`span` instead. Where that row of a primitive's rotation has a single non-zero
entry (the pose maps one local axis onto the asked one, scaled or not: every axis
permutation, and the axis of a rotation about it), the corner transform reduces to
one product and one sum per corner, made here in the same order, so the result is
the same float; other primitives use their bounds. The local box's entry along that
axis is written out for the templates whose entry is a plain expression of their
parameters (a ring's box, say, takes a dozen numpy calls for its x-y extent, which a
span along its axis does not need).
"""

from __future__ import annotations

from artipg.geometry import BOX, Lathe

_LATHE4 = Lathe(4)


def _local(geom, params, k: int):
    """(lo, hi) of ``geom.bounds(params)[:, k]`` (the local box along local axis ``k``),
    the same floats, made in Python where the entry is a plain expression of the
    parameters (the curved families' boxes are numpy arrays, an arc's made from
    candidate points); None elsewhere."""
    if geom is BOX:
        b1 = params[k] / 2
        return -b1, b1
    if geom is _LATHE4 and k == 2 and params[1] == params[5] <= params[9] == params[13] and not (
            params[2] or params[6] or params[10] or params[14]):  # frusta and rings: z of the straight profile's ends
        return params[1], params[9]
    return None


def span(prims, axis: int) -> tuple[float, float]:
    """Lowest and highest coordinate along ``axis`` (0, 1, 2 for x, y, z) of primitives
    ``prims`` in their part's frame, metres: for a part's primitives, the column
    ``part.bounds()[:, axis]``."""
    lo = hi = None
    for prim in prims:
        r0, r1, r2, t = prim.pose[axis].tolist()
        # the one local axis the pose maps onto this one, if there is a single one
        if r0 != 0.0:
            k = 0 if r1 == 0.0 and r2 == 0.0 else -1
        elif r1 != 0.0:
            k = 1 if r2 == 0.0 else -1
        else:
            k = 2 if r2 != 0.0 else -1
        if k >= 0:
            b = _local(prim.geom, prim.params, k)
            b0, b1 = b if b is not None else prim.geom.bounds(prim.params)[:, k].tolist()
            r = (r0, r1, r2)[k]
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
