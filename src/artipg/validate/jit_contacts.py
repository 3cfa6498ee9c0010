"""Compiled kernels of :mod:`artipg.validate.contacts`: the batched pair distance.

:func:`pair_distance` gives the same signed separations as
:func:`artipg.validate.contacts.pair_distance`, bit for bit: box-box pairs by the same
separating-axis test and exact box distance, ball-ball pairs by their centres, other
pairs by the same culled minimum over surface samples of the exact SDFs
(:mod:`artipg.validate.rowsdf`), each written out one row (one point) at a time with
the numpy code's operations in the numpy code's order. :func:`refine_distance` is
:func:`artipg.validate.contacts.refine_distance` the same way. The frames between
pieces (a matrix product: BLAS) stay numpy here (:mod:`artipg.validate.jit_scenes`
forms them in its kernel where :func:`artipg.validate.jit_base.kernels_match`
holds); the SDFs' ``hypot`` and the tables' sines need that probe too.

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math
import sys

import numba
import numpy as np

from artipg.geometry.box import Cuboid
from artipg.geometry.prism import MAX_SIDES, Prism, TriPrism
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.kernel_cache import drop_stale_caches
from artipg.validate.jit_base import apply, apply_t, box_near, clip01, kernels_match, vmax, vmin
from artipg.validate.kinematics import rigid_inverse
from artipg.validate import jit_base

drop_stale_caches(__file__, [jit_base.__file__, sys.modules[Prism.__module__].__file__])

#: SDF codes of the templates the kernels evaluate (0: none of them: a mesh piece).
SDF_CODES = {Cuboid: 1, Frustum: 2, Ring: 3, Sphere: 4, Torus: 5, Prism: 6, TriPrism: 7}
_V = MAX_SIDES  # polygon vertices in the table
#: Columns of :func:`piece_table`: the polygon (vertex count, x, y) of prisms and
#: of the (ρ, z) profiles of frusta and rings, then a wedge's -sin(arc), cos(arc).
_NS, _CS = 1 + 2 * _V, 2 + 2 * _V
_RADIAL_CULL = 200


def piece_table(pieces) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The SDF code (M,) int64, parameter table (M, 3 + 2 MAX_SIDES) float64 and radial
    extent (M, 2) (:attr:`artipg.validate.shapes.Pieces.radial`) of the pieces: every
    value the row-wise SDFs of :mod:`artipg.validate.rowsdf` compute from the
    parameters alone, by the same expressions (the sines and cosines by numpy)."""
    kinds = pieces._kinds
    code = np.array([SDF_CODES.get(g, 0) for g in kinds] + [0], dtype=np.int64)[pieces._kind]
    P = pieces.params
    if kernels_match():  # the sines and cosines by the kernel: numpy's
        aux, radial = _table_trig(code, P)
        return code, aux, radial
    sn = cs = _NO_FLOAT
    if Ring in kinds or Torus in kinds:  # rowsdf.prepare_wedge
        arc = np.where(code == 3, P[:, min(3, P.shape[1] - 1)], P[:, 2])
        sn, cs = np.sin(arc), np.cos(arc)
    rows, px, py = _NO_INT, _NO_POLY, _NO_POLY
    if Prism in kinds:  # rowsdf.prepare_prism
        rows = (code == 6).nonzero()[0]
        r, n = P[rows, 0], P[rows, 2]
        k = np.minimum(np.arange(MAX_SIDES)[:, None], n[None, :] - 1)
        a = np.pi / n + 2 * np.pi * k / n
        px, py = np.ascontiguousarray((r * np.cos(a)).T), np.ascontiguousarray((r * np.sin(a)).T)
    aux, radial = _table(code, P, sn, cs, rows, px, py)
    return code, aux, radial


_NO_FLOAT = np.zeros(0)
_NO_POLY = np.zeros((0, MAX_SIDES))


@numba.njit(cache=True)
def _table_trig(code, P):
    """:func:`_table` with the sines and cosines computed here (see
    :func:`artipg.validate.jit_base.kernels_match`)."""
    M = len(code)
    sn = np.zeros(M)
    cs = np.zeros(M)
    n_prism = 0
    for m in range(M):
        if code[m] == 3 or code[m] == 5:
            arc = P[m, 3] if code[m] == 3 else P[m, 2]
            sn[m], cs[m] = math.sin(arc), math.cos(arc)
        n_prism += code[m] == 6
    rows = np.empty(n_prism, dtype=np.int64)
    px = np.empty((n_prism, _V))
    py = np.empty((n_prism, _V))
    i = 0
    for m in range(M):
        if code[m] == 6:  # rowsdf.prepare_prism
            r, n = P[m, 0], P[m, 2]
            rows[i] = m
            for v in range(_V):
                k = vmin(float(v), n - 1)
                a = np.pi / n + 2 * np.pi * k / n
                px[i, v], py[i, v] = r * math.cos(a), r * math.sin(a)
            i += 1
    return _table(code, P, sn, cs, rows, px, py)


@numba.njit(cache=True)
def _table(code, P, sn, cs, prism_rows, px, py):
    """The rows of :func:`piece_table` (``sn``, ``cs``: sine and cosine of each
    piece's arc where rings or tori exist; ``px``, ``py``: the prisms' polygons)."""
    M = len(code)
    aux = np.zeros((M, 3 + 2 * _V))
    radial = np.empty((M, 2))
    for m in range(M):
        c = code[m]
        radial[m, 0], radial[m, 1] = -np.inf, np.inf
        if c == 2 or c == 3:  # rowsdf._prepare_profile
            if c == 2:
                r0, r1, h = P[m, 0], P[m, 1], P[m, 2]
                x0, x1, x2, x3 = -r0, r0, r1, -r1
                radial[m, 0], radial[m, 1] = 0.0, vmax(r0, r1)
            else:
                ro, ri, h, tp = P[m, 0], P[m, 1], P[m, 2], P[m, 4]
                x0, x1, x2, x3 = ri, ro, ro + tp, ri + tp
                radial[m, 0], radial[m, 1] = vmin(ri, ri + tp), vmax(ro, ro + tp)
            zb, zt = -h / 2, h / 2
            aux[m, 0] = 4
            aux[m, 1], aux[m, 2], aux[m, 3], aux[m, 4] = x0, x1, x2, x3
            aux[m, 1 + _V], aux[m, 2 + _V], aux[m, 3 + _V], aux[m, 4 + _V] = zb, zb, zt, zt
        elif c == 4:
            radial[m, 0], radial[m, 1] = 0.0, P[m, 0]
        elif c == 5:
            radial[m, 0], radial[m, 1] = P[m, 0] - P[m, 1], P[m, 0] + P[m, 1]
        elif c == 7:  # rowsdf.prepare_tri_prism
            w, t, a = P[m, 0], P[m, 1], P[m, 2]
            aux[m, 0] = 3
            aux[m, 1], aux[m, 2], aux[m, 3] = -w / 2, w / 2, a
            aux[m, 3 + _V] = t
        if c == 3 or c == 5:  # rowsdf.prepare_wedge
            aux[m, _NS], aux[m, _CS] = -sn[m], cs[m]
    for k in range(len(prism_rows)):
        m = prism_rows[k]
        aux[m, 0] = _V
        for v in range(_V):
            aux[m, 1 + v], aux[m, 1 + _V + v] = px[k, v], py[k, v]
    return aux, radial


def pair_distance(pieces, a, b, Wa, Wb, margin: np.ndarray) -> np.ndarray:
    """:func:`artipg.validate.contacts.pair_distance` (``margin`` (K,)), compiled; the
    pieces must all have SDF codes (see :attr:`artipg.validate.shapes.Pieces.jit_table`)."""
    code, aux, radial = pieces.jit_table
    box = pieces.is_box[a] & pieces.is_box[b]
    ball = pieces.is_ball[a] & pieces.is_ball[b]
    i = (~box & ~ball).nonzero()[0]
    if len(i):
        rel = np.concatenate([rigid_inverse(Wb[i]) @ Wa[i], rigid_inverse(Wa[i]) @ Wb[i]])
        src, tgt = np.concatenate([a[i], b[i]]), np.concatenate([b[i], a[i]])
        m = margin[i]
        keep = _cull(src, tgt, rel, pieces.center, pieces.half, m)
        pieces.require(src[keep])
        pts = pieces.points_t
    else:
        rel, src, tgt, keep, pts = _NO_REL, _NO_INT, _NO_INT, _NO_BOOL, _NO_PTS
    return _pair_distance(a, b, Wa, Wb, margin, box, ball, i, src, tgt, rel, keep, pieces.params, code, aux,
                          pieces.center, pieces.half, radial, pts, pieces.start, pieces.count)


_NO_REL = np.zeros((0, 4, 4))
_NO_INT = np.zeros(0, dtype=np.int64)
_NO_BOOL = np.zeros(0, dtype=np.bool_)
_NO_PTS = np.zeros((3, 0))


@numba.njit(cache=True)
def _cull(src, tgt, rel, center, half, m):
    """Jobs of :func:`artipg.validate.contacts.evaluate` whose source box, posed in the
    target frame, comes within the margin of the target box on every axis."""
    n = len(src)
    k = len(m)
    keep = np.empty(n, dtype=np.bool_)
    for j in range(n):
        s, t = src[j], tgt[j]
        keep[j] = box_near(rel[j], center[s], half[s], center[t], half[t], m[j % k])
    return keep


@numba.njit(cache=True)
def _pair_distance(a, b, Wa, Wb, margin, box, ball, other, src, tgt, rel, keep, params, code, aux, center, half,
                   radial, pts, start, count):
    K = len(a)
    out = np.empty(K)
    for r in range(K):
        if box[r]:
            out[r] = _box_box(params[a[r], 0] / 2, params[a[r], 1] / 2, params[a[r], 2] / 2, params[b[r], 0] / 2,
                              params[b[r], 1] / 2, params[b[r], 2] / 2, Wa[r], Wb[r], margin[r])
        elif ball[r]:
            g0 = Wa[r, 0, 3] - Wb[r, 0, 3]
            g1 = Wa[r, 1, 3] - Wb[r, 1, 3]
            g2 = Wa[r, 2, 3] - Wb[r, 2, 3]
            out[r] = math.sqrt(0.0 + g0 * g0 + g1 * g1 + g2 * g2) - params[a[r], 0] - params[b[r], 0]
    n = len(other)
    if n == 0:
        return out
    # evaluate(): the samples of each kept job near the target's box, then (with many
    # of them) near its radial extent
    near = 0
    for j in range(2 * n):  # (only whether there are more than _RADIAL_CULL)
        if keep[j] and near <= _RADIAL_CULL:
            s, t = src[j], tgt[j]
            mj = margin[other[j % n]]
            for p in range(start[s], start[s] + count[s]):
                if _near_box(rel[j], pts[0, p], pts[1, p], pts[2, p], center[t], half[t], mj):
                    near += 1
                    if near > _RADIAL_CULL:
                        break
    radial_cull = near > _RADIAL_CULL
    d = np.full(2 * n, np.inf)
    for j in range(2 * n):
        if not keep[j]:
            continue
        s, t = src[j], tgt[j]
        mj = margin[other[j % n]]
        R = rel[j]
        best = np.inf
        for p in range(start[s], start[s] + count[s]):
            x, y, z = pts[0, p], pts[1, p], pts[2, p]
            if not _near_box(R, x, y, z, center[t], half[t], mj):
                continue
            y0 = R[0, 0] * x + R[0, 1] * y + R[0, 2] * z + R[0, 3]
            y1 = R[1, 0] * x + R[1, 1] * y + R[1, 2] * z + R[1, 3]
            y2 = R[2, 0] * x + R[2, 1] * y + R[2, 2] * z + R[2, 3]
            if radial_cull:
                mn = mj + 1e-9
                rho = math.hypot(y0, y1)
                if not (rho <= radial[t, 1] + mn and rho >= radial[t, 0] - mn):
                    continue
            v = sdf(code[t], params[t], aux[t], y0, y1, y2)
            if v < best:
                best = v
        d[j] = best
    for j in range(n):
        out[other[j]] = vmin(d[j], d[n + j])
    return out


@numba.njit(cache=True)
def _near_box(R, x, y, z, ct, ht, m):
    """The point (x, y, z), moved by ``R`` (4, 4), lies within ``m`` of the box
    ``ct``, ``ht`` on every axis (:func:`artipg.validate.contacts.evaluate`)."""
    for i in range(3):
        v = R[i, 0] * x + R[i, 1] * y + R[i, 2] * z + R[i, 3]
        if not (abs(v - ct[i]) - ht[i] <= m):
            return False
    return True


# ------------------------------------------------------------------ signed distances

@numba.njit(cache=True)
def sdf(code, p, aux, x, y, z):
    """Signed distance of the point (x, y, z), piece frame, to a piece of SDF ``code``
    with parameters ``p`` and table row ``aux`` (:func:`piece_table`): the row-wise
    SDFs of :mod:`artipg.validate.rowsdf`, one point."""
    if code == 1:
        return _cuboid(p[0] * 0.5, p[1] * 0.5, p[2] * 0.5, x, y, z)
    if code == 2 or code == 3:
        d = _polygon(math.hypot(x, y), z, aux)
        if code == 3:
            d = vmax(d, _wedge(x, y, p[3], aux))
        return d
    if code == 4:
        return vmax(vmax(math.sqrt(x * x + y * y + z * z) - p[0], p[1] - z), z - p[2])
    if code == 5:
        return vmax(math.hypot(math.hypot(x, y) - p[0], z) - p[1], _wedge(x, y, p[2], aux))
    if code == 6:
        return vmax(_polygon(x, y, aux), abs(z) - p[1] / 2)
    return vmax(_polygon(x, y, aux), abs(z) - p[3] / 2)  # tri prism


@numba.njit(cache=True)
def _cuboid(sx, sy, sz, x, y, z):
    qx, qy, qz = abs(x) - sx, abs(y) - sy, abs(z) - sz
    ox, oy, oz = vmax(qx, 0.0), vmax(qy, 0.0), vmax(qz, 0.0)
    return math.sqrt(ox * ox + oy * oy + oz * oz) + vmin(vmax(vmax(qx, qy), qz), 0.0)


@numba.njit(cache=True)
def _polygon(qx, qy, aux):
    """:func:`artipg.validate.rowsdf.prepare_polygon` at one point: the polygon of
    ``aux[0]`` vertices ``aux[1:]`` (x) and ``aux[1 + MAX_SIDES:]`` (y)."""
    V = int(aux[0])
    best = np.inf
    crossings = 0
    for i in range(V):
        nx = i + 1 if i + 1 < V else 0
        px, py = aux[1 + i], aux[1 + _V + i]
        bx, by = aux[1 + nx], aux[1 + _V + nx]
        ex, ey = bx - px, by - py
        ee = vmax(ex * ex + ey * ey, 1e-30)
        ey_safe = ey if abs(ey) > 1e-30 else 1e-30
        wx, wy = qx - px, qy - py
        t = vmin(vmax((wx * ex + wy * ey) / ee, 0.0), 1.0)
        dx, dy = wx - t * ex, wy - t * ey
        d2 = dx * dx + dy * dy
        if d2 < best:
            best = d2
        if (py > qy) != (by > qy) and qx < px + (qy - py) * ex / ey_safe:
            crossings += 1
    dist = math.sqrt(best)
    return -dist if crossings % 2 == 1 else dist


@numba.njit(cache=True)
def _wedge(x, y, arc, aux):
    """:func:`artipg.validate.rowsdf.prepare_wedge` at one point."""
    if arc >= 2.0 * np.pi - 1e-9:
        return -np.inf
    d0 = -y
    d1 = aux[_NS] * x + aux[_CS] * y
    return vmax(d0, d1) if arc <= np.pi else vmin(d0, d1)


# ------------------------------------------------------------------ boxes

@numba.njit(cache=True)
def _box_box(ha0, ha1, ha2, hb0, hb1, hb2, Wa, Wb, margin):
    """:func:`artipg.validate.contacts.box_box` of one pair."""
    aligned = True
    for i in range(3):
        for j in range(3):
            va, vb = Wa[i, j], Wb[i, j]
            if not ((va == 0.0 or abs(va) == 1.0) and (vb == 0.0 or abs(vb) == 1.0)):
                aligned = False
    edge = margin if math.isfinite(margin) else -1.0
    if aligned:  # contacts._aligned_box_box
        out = -np.inf
        for i in range(3):
            ea = abs(Wa[i, 0]) * ha0 + abs(Wa[i, 1]) * ha1 + abs(Wa[i, 2]) * ha2
            eb = abs(Wb[i, 0]) * hb0 + abs(Wb[i, 1]) * hb1 + abs(Wb[i, 2]) * hb2
            v = abs(Wa[i, 3] - Wb[i, 3]) - (ea + eb)
            if v > out:
                out = v
        if out > 0 and out <= margin:
            out = _box_distance(ha0, ha1, ha2, hb0, hb1, hb2, Wa, Wb, edge)
        return out
    # contacts._sat_box_box: everything in a's frame, R = A^T B, T = A^T t
    R = np.empty((3, 3))
    T = np.empty(3)
    t0, t1, t2 = Wb[0, 3] - Wa[0, 3], Wb[1, 3] - Wa[1, 3], Wb[2, 3] - Wa[2, 3]
    for i in range(3):
        for j in range(3):
            R[i, j] = Wa[0, i] * Wb[0, j] + Wa[1, i] * Wb[1, j] + Wa[2, i] * Wb[2, j]
        T[i] = Wa[0, i] * t0 + Wa[1, i] * t1 + Wa[2, i] * t2
    depth = np.inf
    for k in range(15):
        # the axis (unnormalised, a's frame): a's axes, b's, a_i x b_j
        if k < 3:
            ax, ay, az = (1.0 if k == 0 else 0.0), (1.0 if k == 1 else 0.0), (1.0 if k == 2 else 0.0)
        elif k < 6:
            ax, ay, az = R[0, k - 3], R[1, k - 3], R[2, k - 3]
        elif k < 9:
            ax, ay, az = 0.0, -R[2, k - 6], R[1, k - 6]
        elif k < 12:
            ax, ay, az = R[2, k - 9], 0.0, -R[0, k - 9]
        else:
            ax, ay, az = -R[1, k - 12], R[0, k - 12], 0.0
        n = math.sqrt(ax * ax + ay * ay + az * az)
        if not n > 1e-9:
            continue  # inf
        ra = abs(ax) * ha0 + abs(ay) * ha1 + abs(az) * ha2
        rb = (abs(ax * R[0, 0] + ay * R[1, 0] + az * R[2, 0]) * hb0
              + abs(ax * R[0, 1] + ay * R[1, 1] + az * R[2, 1]) * hb1
              + abs(ax * R[0, 2] + ay * R[1, 2] + az * R[2, 2]) * hb2)
        dist = abs(ax * T[0] + ay * T[1] + az * T[2])
        over = (ra + rb - dist) / n
        if over < depth:
            depth = over
    out = -depth
    if depth < 0 and -depth <= margin:
        out = _box_distance(ha0, ha1, ha2, hb0, hb1, hb2, Wa, Wb, edge)
    return out


#: Corners of the unit box (as contacts._CORNERS) and its 12 edges.
_CORNERS = np.array([[a, b, c] for a in (-0.5, 0.5) for b in (-0.5, 0.5) for c in (-0.5, 0.5)])
_EDGES = np.array([(i, j) for i in range(8) for j in range(i + 1, 8)
                   if np.count_nonzero(_CORNERS[i] != _CORNERS[j]) == 1], dtype=np.int64)


@numba.njit(cache=True)
def _box_distance(ha0, ha1, ha2, hb0, hb1, hb2, Wa, Wb, edge_margin):
    """:func:`artipg.validate.contacts.box_distance` of one pair (vertex-face, then
    edge-edge where the vertex bound exceeds ``edge_margin``)."""
    d0, d1, d2 = Wa[0, 3] - Wb[0, 3], Wa[1, 3] - Wb[1, 3], Wa[2, 3] - Wb[2, 3]
    R = np.empty((3, 3))  # a's frame in b's: R = Rb^T Ra, t = Rb^T (ta - tb)
    t = np.empty(3)
    u = np.empty(3)
    for i in range(3):
        for j in range(3):
            R[i, j] = Wb[0, i] * Wa[0, j] + Wb[1, i] * Wa[1, j] + Wb[2, i] * Wa[2, j]
        t[i] = Wb[0, i] * d0 + Wb[1, i] * d1 + Wb[2, i] * d2
    for i in range(3):
        u[i] = -(R[0, i] * t[0] + R[1, i] * t[1] + R[2, i] * t[2])
    va_b = np.empty((8, 3))  # a's corners in b's frame
    vb = np.empty((8, 3))  # b's corners in b's frame
    best = np.inf
    sa0, sa1, sa2 = (2 * ha0) * 0.5, (2 * ha1) * 0.5, (2 * ha2) * 0.5
    sb0, sb1, sb2 = (2 * hb0) * 0.5, (2 * hb1) * 0.5, (2 * hb2) * 0.5
    for v in range(8):
        a0, a1, a2 = _CORNERS[v, 0] * 2 * ha0, _CORNERS[v, 1] * 2 * ha1, _CORNERS[v, 2] * 2 * ha2
        b0, b1, b2 = _CORNERS[v, 0] * 2 * hb0, _CORNERS[v, 1] * 2 * hb1, _CORNERS[v, 2] * 2 * hb2
        vb[v, 0], vb[v, 1], vb[v, 2] = b0, b1, b2
        for i in range(3):
            va_b[v, i] = R[i, 0] * a0 + R[i, 1] * a1 + R[i, 2] * a2 + t[i]
        x = _cuboid(sb0, sb1, sb2, va_b[v, 0], va_b[v, 1], va_b[v, 2])
        if x < best:
            best = x
        w0 = R[0, 0] * b0 + R[1, 0] * b1 + R[2, 0] * b2 + u[0]
        w1 = R[0, 1] * b0 + R[1, 1] * b1 + R[2, 1] * b2 + u[1]
        w2 = R[0, 2] * b0 + R[1, 2] * b1 + R[2, 2] * b2 + u[2]
        x = _cuboid(sa0, sa1, sa2, w0, w1, w2)
        if x < best:
            best = x
    if not best > edge_margin:
        return best
    for e in range(12):
        for f in range(12):
            x = _segment_distance(va_b[_EDGES[e, 0]], va_b[_EDGES[e, 1]], vb[_EDGES[f, 0]], vb[_EDGES[f, 1]])
            if x < best:
                best = x
    return best


@numba.njit(cache=True)
def _segment_distance(p0, p1, q0, q1):
    """:func:`artipg.validate.contacts.segment_distance` of one pair of segments."""
    a = b = c = e = f = 0.0
    for k in range(3):
        d1, d2, r = p1[k] - p0[k], q1[k] - q0[k], p0[k] - q0[k]
        a += d1 * d1
        e += d2 * d2
        b += d1 * d2
        c += d1 * r
        f += d2 * r
    den = a * e - b * b
    s = clip01((b * f - c * e) / den) if den > 1e-18 else 0.0
    t = (b * s + f) / vmax(e, 1e-18)
    if t < 0:
        s = clip01(-c / vmax(a, 1e-18))
    elif t > 1:
        s = clip01((b - c) / vmax(a, 1e-18))
    t = clip01(t)
    out = 0.0
    for k in range(3):
        v = p0[k] + s * (p1[k] - p0[k]) - q0[k] - t * (q1[k] - q0[k])
        out += v * v
    return math.sqrt(out)


# ------------------------------------------------------------------ refinement

def refine_distance(pieces, a, b, Wa, Wb, starts: int, iters: int, stop_below: float) -> np.ndarray:
    """:func:`artipg.validate.contacts.refine_distance`, compiled (the pieces must all
    have SDF codes, and :func:`artipg.validate.jit_base.kernels_match`)."""
    code, aux, _ = pieces.jit_table
    pieces.require(np.concatenate([a, b]))
    return _refine(a, b, np.ascontiguousarray(Wa), np.ascontiguousarray(Wb), starts, iters, float(stop_below),
                   pieces.params, code, aux, pieces.points_t, pieces.start, pieces.count, _H, _ON_SURFACE, _OFFS)


# the constants of artipg.validate.contacts' refinement (the same expressions)
_H = 1e-6
_ON_SURFACE = 1e-5
_OFFS = np.concatenate([np.eye(3), -np.eye(3)]) * _H


@numba.njit(cache=True)
def _refine(a, b, Wa, Wb, starts, iters, stop_below, params, code, aux, pts, start, count, H, on_surface, offs):
    K = len(a)
    J = 2 * K
    # the samples of each job's source nearest its target (by their SDF; ties: first)
    first = np.zeros(J + 1, dtype=np.int64)
    for j in range(J):
        s = a[j] if j < K else b[j - K]
        first[j + 1] = first[j] + min(starts, count[s])
    n = first[J]
    P = np.empty((n, 3))  # the rows' points, world frame
    job = np.empty(n, dtype=np.int64)
    best = np.full(J, np.inf)
    for j in range(J):
        s, t = (a[j], b[j]) if j < K else (b[j - K], a[j - K])
        Ws, Wt = (Wa[j], Wb[j]) if j < K else (Wb[j - K], Wa[j - K])
        c = count[s]
        X = np.empty((c, 3))
        d = np.empty(c)
        for k in range(c):
            x0, x1, x2 = pts[0, start[s] + k], pts[1, start[s] + k], pts[2, start[s] + k]
            for i in range(3):
                X[k, i] = apply(Ws, x0, x1, x2, i) + Ws[i, 3]
            y0, y1, y2 = X[k, 0] - Wt[0, 3], X[k, 1] - Wt[1, 3], X[k, 2] - Wt[2, 3]
            d[k] = sdf(code[t], params[t], aux[t], apply_t(Wt, y0, y1, y2, 0), apply_t(Wt, y0, y1, y2, 1),
                       apply_t(Wt, y0, y1, y2, 2))
        taken = np.zeros(c, dtype=np.bool_)
        for r in range(first[j + 1] - first[j]):
            k = _next_nearest(d, taken)
            P[first[j] + r, 0], P[first[j] + r, 1], P[first[j] + r, 2] = X[k, 0], X[k, 1], X[k, 2]
            job[first[j] + r] = j
            if d[k] < best[j]:
                best[j] = d[k]
    # alternate projections; every point reached on the source bounds the distance
    Lt = np.empty((n, 3))
    dt = np.empty((n, 7))
    off = np.empty(n)
    Q = np.empty((n, 3))
    Ls = np.empty((n, 3))
    ds = np.empty((n, 7))
    _target_stencil(P, job, K, a, b, Wa, Wb, params, code, aux, offs, Lt, dt, off)
    for _ in range(iters):
        _step(Lt, dt, job, K, Wb, Wa, H, Q)  # onto the target
        _source_stencil(Q, job, K, a, b, Wa, Wb, params, code, aux, offs, Ls, ds)
        _step(Ls, ds, job, K, Wa, Wb, H, P)  # back onto the source
        _target_stencil(P, job, K, a, b, Wa, Wb, params, code, aux, offs, Lt, dt, off)
        before = np.empty(K)
        for k in range(K):
            before[k] = vmin(best[k], best[K + k])
        for r in range(n):
            o = abs(off[r])
            if o <= on_surface:
                v = dt[r, 0] + o
                if v < best[job[r]]:
                    best[job[r]] = v
        done = True
        gain = -np.inf
        nan = False
        for k in range(K):
            now = vmin(best[k], best[K + k])
            if not now <= stop_below:
                done = False
            g = before[k] - now
            if g != g:
                nan = True
            elif g > gain:
                gain = g
        if done or (not nan and gain < 1e-6):
            break
    out = np.empty(K)
    for k in range(K):
        out[k] = vmin(best[k], best[K + k])
    return out


@numba.njit(cache=True)
def _next_nearest(d, taken):
    """The smallest ``d`` not yet taken (ties: the first; NaN last), marked taken: one
    step of a stable sort (``np.lexsort``) of a few."""
    best = -1
    for k in range(len(d)):
        if taken[k]:
            continue
        if best < 0 or d[k] < d[best] or (d[best] != d[best] and d[k] == d[k]):
            best = k
    taken[best] = True
    return best


@numba.njit(cache=True)
def _target_stencil(X, job, K, a, b, Wa, Wb, params, code, aux, offs, L, d, off):
    """contacts._target_stencil: the targets' SDF at world points ``X`` and their six
    neighbours (``d`` (n, 7), local points ``L``), the sources' SDF (``off``)."""
    for r in range(len(X)):
        j = job[r]
        s, t = (a[j], b[j]) if j < K else (b[j - K], a[j - K])
        Ws, Wt = (Wa[j], Wb[j]) if j < K else (Wb[j - K], Wa[j - K])
        y0, y1, y2 = X[r, 0] - Wt[0, 3], X[r, 1] - Wt[1, 3], X[r, 2] - Wt[2, 3]
        for i in range(3):
            L[r, i] = apply_t(Wt, y0, y1, y2, i)
        _stencil_row(code[t], params[t], aux[t], L[r], offs, d[r])
        y0, y1, y2 = X[r, 0] - Ws[0, 3], X[r, 1] - Ws[1, 3], X[r, 2] - Ws[2, 3]
        off[r] = sdf(code[s], params[s], aux[s], apply_t(Ws, y0, y1, y2, 0), apply_t(Ws, y0, y1, y2, 1),
                     apply_t(Ws, y0, y1, y2, 2))


@numba.njit(cache=True)
def _source_stencil(X, job, K, a, b, Wa, Wb, params, code, aux, offs, L, d):
    """contacts._stencil of the sources at world points ``X``."""
    for r in range(len(X)):
        j = job[r]
        s = a[j] if j < K else b[j - K]
        Ws = Wa[j] if j < K else Wb[j - K]
        y0, y1, y2 = X[r, 0] - Ws[0, 3], X[r, 1] - Ws[1, 3], X[r, 2] - Ws[2, 3]
        for i in range(3):
            L[r, i] = apply_t(Ws, y0, y1, y2, i)
        _stencil_row(code[s], params[s], aux[s], L[r], offs, d[r])


@numba.njit(cache=True)
def _stencil_row(code, p, aux, L, offs, d):
    d[0] = sdf(code, p, aux, L[0], L[1], L[2])
    for o in range(6):
        d[1 + o] = sdf(code, p, aux, L[0] + offs[o, 0], L[1] + offs[o, 1], L[2] + offs[o, 2])


@numba.njit(cache=True)
def _step(L, d, job, K, W_first, W_second, H, out):
    """contacts._step: one Newton step from each row's stencil onto its piece's
    surface, world frame (the piece of job j is posed by ``W_first[j]`` for j < K,
    else by ``W_second[j - K]``)."""
    for r in range(len(L)):
        j = job[r]
        W = W_first[j] if j < K else W_second[j - K]
        g0 = (d[r, 1] - d[r, 4]) / (2 * H)
        g1 = (d[r, 2] - d[r, 5]) / (2 * H)
        g2 = (d[r, 3] - d[r, 6]) / (2 * H)
        norm = vmax(math.sqrt(g0 * g0 + g1 * g1 + g2 * g2), 1e-12)
        g0, g1, g2 = g0 / norm, g1 / norm, g2 / norm
        d0 = d[r, 0]
        v0, v1, v2 = L[r, 0] - d0 * g0, L[r, 1] - d0 * g1, L[r, 2] - d0 * g2
        for i in range(3):
            out[r, i] = apply(W, v0, v1, v2, i) + W[i, 3]
