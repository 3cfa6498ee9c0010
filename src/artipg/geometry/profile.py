"""2-D outlines made of line segments and circular arcs: the cross-sections of the
lathe and extrusion families.

A *loop* is a closed chain of ``n`` segments stored as an (n, 3) array of rows
``(x, y, b)``: segment i runs from vertex i to vertex i + 1 (the last back to the
first) and ``b`` is its *bulge* ``tan(δ / 4)``, δ the signed angle the segment turns
through: ``b = 0`` is a straight segment, ``b > 0`` a counter-clockwise arc (it bulges
to the right of its chord), ``b = ±1`` a half circle (the DXF polyline convention). An
*outline* is a list of loops: the first is the outer boundary, counter-clockwise; the
others are holes, clockwise (:func:`oriented` makes a loop either way). The region is
the even-odd interior, and every formula here is exact: area, signed distance, inside
test, arc-length parametrisation; only :func:`polygonise` (for meshes) approximates.

Segment functions take arrays of any matching shape, so a family evaluates the
segments of all its primitives (M rows) in one call.
"""

from __future__ import annotations

import math

import numpy as np

TWO_PI = 2.0 * math.pi


# ---------------------------------------------------------------- one segment, vectorised

def segments(loop: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Start points (..., n, 2), end points (..., n, 2) and bulges (..., n) of the
    segments of loops (..., n, 3)."""
    loop = np.asarray(loop, dtype=float)
    return loop[..., :2], np.roll(loop[..., :2], -1, axis=-2), loop[..., 2]


def arc_geometry(p0, p1, b):
    """Centre (..., 2), radius, start angle and signed sweep δ (...) of arcs from ``p0``
    to ``p1`` (..., 2) with bulges ``b`` (...). Straight segments (b = 0) give an infinite
    radius and δ = 0 (their centre is meaningless)."""
    c = p1 - p0
    L = np.hypot(c[..., 0], c[..., 1])
    bb = np.where(b == 0.0, 1.0, b)
    d = L * (1.0 - bb * bb) / (4.0 * bb)  # signed offset of the centre along the chord's left normal
    Ls = np.where(L > 0, L, 1.0)
    left = np.stack([-c[..., 1], c[..., 0]], axis=-1) / Ls[..., None]
    centre = 0.5 * (p0 + p1) + d[..., None] * left
    radius = np.where(b == 0.0, np.inf, L * (1.0 + bb * bb) / (4.0 * np.abs(bb)))
    a0 = np.arctan2(p0[..., 1] - centre[..., 1], p0[..., 0] - centre[..., 0])
    sweep = 4.0 * np.arctan(b)
    return centre, radius, a0, sweep


def seg_length(p0, p1, b) -> np.ndarray:
    """Length (...) of segments: the chord, or radius x |δ| for arcs."""
    L = np.hypot(p1[..., 0] - p0[..., 0], p1[..., 1] - p0[..., 1])
    d = 4.0 * np.arctan(b)
    # arc length = L (δ / 2) / sin(δ / 2), which tends to L for straight segments
    half = 0.5 * d
    ratio = np.where(np.abs(half) > 1e-12, half / np.where(half == 0, 1.0, np.sin(half)), 1.0)
    return L * np.abs(ratio)


def point_at(p0, p1, b, t):
    """Points (..., 2) and unit tangents (..., 2) at fractions ``t`` (...) of the arc
    length of segments (``t`` broadcasts against the segments)."""
    c, rad, a0, d = arc_geometry(p0, p1, b)
    straight = (b == 0.0)[..., None]
    a = a0 + t * d
    ca, sa = np.cos(a), np.sin(a)
    rr = np.where(np.isfinite(rad), rad, 0.0)
    on_arc = c + rr[..., None] * np.stack([ca, sa], axis=-1)
    sg = np.sign(np.where(d == 0, 1.0, d))[..., None]
    tan_arc = sg * np.stack([-sa, ca], axis=-1)
    chord = p1 - p0
    Lc = np.hypot(chord[..., 0], chord[..., 1])[..., None]
    line = p0 + np.asarray(t)[..., None] * chord
    return np.where(straight, line, on_arc), np.where(straight, chord / np.where(Lc > 0, Lc, 1.0), tan_arc)


def chord_side(p0, p1, q) -> np.ndarray:
    """Cross product of the chord p0 -> p1 with q - p0 (> 0: q left of the chord)."""
    c = p1 - p0
    w = q - p0
    return c[..., 0] * w[..., 1] - c[..., 1] * w[..., 0]


# ---------------------------------------------------------------- loops

def loop_area(loop: np.ndarray) -> np.ndarray:
    """Signed area (...) of loops (..., n, 3): positive counter-clockwise, m^2.

    The chord polygon's shoelace area plus each arc's circular segment
    ``R² (δ - sin δ) / 2`` (signed with δ)."""
    p0, p1, b = segments(loop)
    shoelace = 0.5 * (p0[..., 0] * p1[..., 1] - p1[..., 0] * p0[..., 1]).sum(axis=-1)
    _, rad, _, d = arc_geometry(p0, p1, b)
    rr = np.where(np.isfinite(rad), rad, 0.0)
    return shoelace + (0.5 * rr * rr * (d - np.sin(d))).sum(axis=-1)


def oriented(loop, ccw: bool = True) -> np.ndarray:
    """The loop (n, 3) traversed counter-clockwise (``ccw``) or clockwise: reversing a
    loop reverses its vertices and negates each bulge, kept with its segment."""
    loop = np.array(loop, dtype=float)
    if (loop_area(loop) > 0) == ccw:
        return loop
    out = loop[::-1].copy()
    # reversed segment k runs from vertex n-1-k to n-2-k: the old segment n-2-k
    out[:, 2] = -np.roll(loop[::-1, 2], -1)
    return out


def outline_area(loops) -> float:
    """Area of an outline (outer loop counter-clockwise, holes clockwise), m^2."""
    return float(sum(loop_area(l) for l in loops))


def perimeter(loop) -> np.ndarray:
    """Cumulative arc length (n + 1,) at the vertices of a loop (n, 3), from 0."""
    p0, p1, b = segments(loop)
    return np.concatenate([[0.0], np.cumsum(seg_length(p0, p1, b))])


def at_length(loop, s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points (k, 2) and unit tangents (k, 2) at arc lengths ``s`` (k,) along a loop
    (wrapped to its perimeter)."""
    cum = perimeter(loop)
    s = np.mod(s, cum[-1])
    i = np.clip(np.searchsorted(cum, s, side="right") - 1, 0, len(loop) - 1)
    p0, p1, b = segments(loop)
    L = cum[i + 1] - cum[i]
    return point_at(p0[i], p1[i], b[i], (s - cum[i]) / np.where(L > 0, L, 1.0))


def _closest(loop, q: np.ndarray, skip=None) -> tuple[np.ndarray, np.ndarray]:
    """Distance (N,) from points q (N, 2) to a loop's curve and the arc length (N,) of
    the closest curve point: (n, N) rows, one per segment; segments flagged in ``skip``
    (n,) are left out (a lathe profile's segments on the axis are no surface)."""
    p0, p1, b = segments(loop)
    c, rad, a0, d = arc_geometry(p0, p1, b)
    P0, P1, B = p0[:, None], p1[:, None], b[:, None]
    Q = q[None]
    # straight segments: clamped projection
    e = P1 - P0
    ee = np.maximum((e * e).sum(-1), 1e-300)
    t_line = np.clip(((Q - P0) * e).sum(-1) / ee, 0.0, 1.0)
    # arcs: the angle of q about the centre, if it falls inside the sweep, else the nearer end
    w = Q - c[:, None]
    ang = np.arctan2(w[..., 1], w[..., 0])
    D = d[:, None]
    rel = np.mod((ang - a0[:, None]) * np.sign(np.where(D == 0, 1.0, D)), TWO_PI)
    inside = rel <= np.abs(D)
    t_end = np.where(np.linalg.norm(Q - P0, axis=-1) <= np.linalg.norm(Q - P1, axis=-1), 0.0, 1.0)
    t_arc = np.where(inside, rel / np.where(D == 0, 1.0, np.abs(D)), t_end)
    t = np.where(B == 0.0, t_line, t_arc)
    pt, _ = point_at(P0, P1, B, t)
    dist = np.linalg.norm(Q - pt, axis=-1)
    if skip is not None:
        dist[np.asarray(skip, dtype=bool)] = np.inf
    k = dist.argmin(axis=0)
    cols = np.arange(len(q))
    cum = perimeter(loop)
    return dist[k, cols], cum[k] + t[k, cols] * (cum[k + 1] - cum[k])


def loop_distance(loop, q: np.ndarray, skip=None) -> np.ndarray:
    """Unsigned distance (N,) from points ``q`` (N, 2) to a loop's curve (without the
    segments flagged in ``skip`` (n,))."""
    return _closest(np.asarray(loop, dtype=float), np.asarray(q, dtype=float), skip)[0]


def loop_length_at(loop, q: np.ndarray, skip=None) -> np.ndarray:
    """Arc length (N,) of the loop point closest to each of ``q`` (N, 2)."""
    return _closest(np.asarray(loop, dtype=float), np.asarray(q, dtype=float), skip)[1]


def loop_parity(loop, q: np.ndarray) -> np.ndarray:
    """Boolean (N,): ``q`` (N, 2) inside the loop by the even-odd rule.

    The region is the chord polygon XOR the circular segments between each arc and its
    chord (the chords cancel), so the crossing test of the chords is corrected by the
    disc-and-side test of each arc."""
    p0, p1, b = segments(loop)
    qx, qy = q[:, 0][None], q[:, 1][None]
    ax, ay, bx, by = p0[:, 0:1], p0[:, 1:2], p1[:, 0:1], p1[:, 1:2]
    cond = (ay > qy) != (by > qy)
    ey = by - ay
    xint = ax + (qy - ay) * (bx - ax) / np.where(ey != 0, ey, 1.0)
    par = (cond & (qx < xint)).sum(axis=0) % 2 == 1
    c, rad, _, d = arc_geometry(p0, p1, b)
    arcs = np.flatnonzero(b != 0.0)
    if len(arcs):
        cc = c[arcs][:, None]
        in_disc = ((q[None] - cc) ** 2).sum(-1) < (rad[arcs] ** 2)[:, None]
        side = chord_side(p0[arcs][:, None], p1[arcs][:, None], q[None])
        # a counter-clockwise arc (b > 0) bulges to the right of its chord
        arc_side = np.where(b[arcs][:, None] > 0, side < 0, side > 0)
        # points on a chord's line count for one of a pair of opposite chords (the two
        # half circles of a circle): those whose chord points along +x (or +y)
        ch = p1[arcs] - p0[arcs]
        first = (ch[:, 0] > 0) | ((ch[:, 0] == 0) & (ch[:, 1] > 0))
        arc_side |= (side == 0) & first[:, None]
        par ^= ((in_disc & arc_side).sum(axis=0) % 2) == 1
    return par


def inside(loops, q) -> np.ndarray:
    """Boolean (N,): points ``q`` (N, 2) inside an outline (even-odd over all loops)."""
    q = np.asarray(q, dtype=float)
    out = np.zeros(len(q), dtype=bool)
    for loop in loops:
        out ^= loop_parity(np.asarray(loop, dtype=float), q)
    return out


def sdf(loops, q, skips=None) -> np.ndarray:
    """Exact signed distance (N,) of points ``q`` (N, 2) to an outline: negative inside.
    ``skips`` (one (n,) mask per loop, optional) leaves segments out of the distance."""
    q = np.asarray(q, dtype=float)
    skips = [None] * len(loops) if skips is None else skips
    d = np.min([loop_distance(l, q, s) for l, s in zip(loops, skips)], axis=0)
    return np.where(inside(loops, q), -d, d)


def polygonise(loop, sections: int = 32) -> np.ndarray:
    """Vertices (k, 2) of a polygon through the loop's vertices, arcs cut into
    ``ceil(sections |δ| / 2π)`` chords (at least 2 for a half turn or more)."""
    loop = np.asarray(loop, dtype=float)
    p0, p1, b = segments(loop)
    out = []
    for i in range(len(loop)):  # a loop has a few segments: the points are vectorised
        if b[i] == 0.0:
            out.append(p0[i][None])
            continue
        d = 4.0 * math.atan(b[i])
        m = max(2 if abs(d) >= math.pi else 1, int(math.ceil(sections * abs(d) / TWO_PI)))
        t = np.arange(m) / m
        out.append(point_at(np.broadcast_to(p0[i], (m, 2)), np.broadcast_to(p1[i], (m, 2)), np.full(m, b[i]), t)[0])
    return np.concatenate(out)


def bounds(loop) -> np.ndarray:
    """Exact bounding box (2, 2) of a loop: vertices plus the axis extremes of arcs that
    their sweep passes."""
    loop = np.asarray(loop, dtype=float)
    p0, p1, b = segments(loop)
    pts = [p0]
    c, rad, a0, d = arc_geometry(p0, p1, b)
    for k in range(4):  # angles 0, π/2, π, 3π/2
        ang = k * 0.5 * math.pi
        rel = np.mod((ang - a0) * np.sign(np.where(d == 0, 1.0, d)), TWO_PI)
        hit = (b != 0.0) & (rel <= np.abs(d))
        if hit.any():
            pts.append(c[hit] + rad[hit, None] * np.array([math.cos(ang), math.sin(ang)]))
    P = np.concatenate(pts)
    return np.stack([P.min(axis=0), P.max(axis=0)])


def has_arcs(loops) -> bool:
    """Whether any segment of the outline is an arc."""
    return any(bool(np.any(np.asarray(l)[:, 2] != 0.0)) for l in loops)


# ---------------------------------------------------------------- builders

def polygon(points) -> np.ndarray:
    """A loop (n, 3) of straight segments through ``points`` (n, 2)."""
    p = np.asarray(points, dtype=float)
    return np.column_stack([p, np.zeros(len(p))])


def rectangle(w: float, h: float, r: float = 0.0, centre=(0.0, 0.0)) -> np.ndarray:
    """Counter-clockwise ``w`` x ``h`` rectangle centred at ``centre``, corners rounded
    with radius ``r`` (quarter arcs, bulge tan(π/8))."""
    cx, cy = centre
    x, y = w / 2, h / 2
    if r <= 0.0:
        return polygon([[cx + x, cy - y], [cx + x, cy + y], [cx - x, cy + y], [cx - x, cy - y]])
    q = math.tan(math.pi / 8)
    pts = [(x, -y + r, 0), (x, y - r, q), (x - r, y, 0), (-x + r, y, q),
           (-x, y - r, 0), (-x, -y + r, q), (-x + r, -y, 0), (x - r, -y, q)]
    return np.array([(cx + a, cy + c, bb) for a, c, bb in pts], dtype=float)


def circle(r: float, centre=(0.0, 0.0)) -> np.ndarray:
    """Counter-clockwise circle: two half-circle arcs (bulge 1)."""
    cx, cy = centre
    return np.array([[cx + r, cy, 1.0], [cx - r, cy, 1.0]])


def regular_polygon(r: float, n: int, phase: float | None = None) -> np.ndarray:
    """Counter-clockwise regular ``n``-gon of circumradius ``r``; the first vertex at
    angle ``phase`` (default π/n, as :class:`artipg.geometry.prism.Prism`)."""
    a = (math.pi / n if phase is None else phase) + TWO_PI * np.arange(n) / n
    return polygon(np.stack([r * np.cos(a), r * np.sin(a)], axis=1))
