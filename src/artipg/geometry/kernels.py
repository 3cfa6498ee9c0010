"""Compiled twins of the geometry templates' ``patches`` and ``bounds_batch``.

:class:`artipg.annotate.points.PrimitiveTable` builds an object's patch families (and
its primitives' local boxes) here in one call instead of a few dozen numpy calls per
template. The templates' numpy methods stay the definition: every formula below repeats
theirs operation for operation (the same IEEE operations in the same order, no
fastmath), so the results are the same bits, which tests/test_framework_fast.py checks
template by template. Three things make that hold:

- the transcendental values (cosines and sines of arcs and of polygon angles) are
  computed by numpy and passed in, because numpy's SIMD ``cos`` need not round like
  the C library's (``hypot``, which both take from the C library, is called here);
- the affine patch tables (:func:`artipg.geometry.patches.linear`) have at most two
  non-zero coefficients per row, each ±1/2 or ±1, so the matrix product numpy hands to
  BLAS is one correctly rounded sum of exact products whatever order BLAS adds in;
  :func:`_affine_rows` adds them from +0.0 like the BLAS kernels do, and spreads a NaN
  or infinite parameter to the whole row as BLAS's zero products do (:func:`_poison`);
- only cells with a positive area are kept, as ``PrimitiveTable.families`` does, so a
  template may skip a block that numpy builds full of zero areas.

The matrix products of poses (4 x 4 and 3 x 3, BLAS) stay with numpy: BLAS kernels
differ between machines (fused multiply-adds, summation order), so nothing here may
replace one. Import this module lazily: numba itself takes half a second to import, and
loading these kernels from numba's cache another tenth of a second.
"""

from __future__ import annotations

import math
import sys

import numba
import numpy as np

from artipg.geometry.base import TWO_PI
from artipg.geometry.box import _BOX_TABLE, _RING_SIDES, _RING_TABLE, Cuboid, RectRing
from artipg.geometry.patches import FAMILIES
from artipg.geometry.prism import MAX_SIDES, Prism, TriPrism
from artipg.geometry.revolve import _FRUSTUM_CAPS, _QUARTERS, _RING_CAPS, Frustum, Ring, Sphere, Torus
from artipg.kernel_cache import drop_stale_caches

# the kernels compile in constants of these modules
drop_stale_caches(__file__, [sys.modules[f"artipg.geometry.{m}"].__file__ for m in ("base", "box", "patches", "prism",
                                                                                     "revolve")])

#: Template -> code used by the kernels; a template not listed takes the numpy path.
CODES = {Cuboid: 0, RectRing: 1, Frustum: 2, Ring: 3, Sphere: 4, Torus: 5, Prism: 6, TriPrism: 7}
#: Codes of the templates whose local boxes :func:`local_boxes` computes: all (a prism's
#: only for an integer side count 3..MAX_SIDES, from numpy's cosines in :data:`_PRISM_BOX`).
BOX_CODES = (0, 1, 2, 3, 4, 5, 6, 7)
#: Column of the arc parameter of the templates that have one (ring, torus), by code.
ARC_COLUMN = {3: 3, 5: 2}
_RING_ARC, _TORUS_ARC = ARC_COLUMN[3], ARC_COLUMN[5]

_RECT, _TRI, _SECTOR, _BAND, _ZONE, _TORUS = range(6)
_NPARAM = np.array(list(FAMILIES.values()), dtype=np.int64)
#: Upper bound of the cells of each family per row of each template (code).
_CELLS = np.zeros((8, 6), dtype=np.int64)
_CELLS[0, _RECT] = 6
_CELLS[1, _RECT] = 16
_CELLS[2, _BAND], _CELLS[2, _SECTOR] = 1, 2
_CELLS[3, _BAND], _CELLS[3, _SECTOR], _CELLS[3, _RECT] = 2, 2, 2
_CELLS[4, _ZONE], _CELLS[4, _SECTOR] = 1, 2
_CELLS[5, _TORUS], _CELLS[5, _SECTOR] = 1, 2
_CELLS[6, _RECT], _CELLS[6, _TRI] = MAX_SIDES, 2 * MAX_SIDES
_CELLS[7, _RECT], _CELLS[7, _TRI] = 3, 2

_FULL_TURN = TWO_PI - 1e-9  # _is_full: arc >= this
_ANGLES = np.concatenate([[0.0], _QUARTERS, [TWO_PI]])
_FACE_I, _FACE_J = (1, 0, 0), (2, 2, 1)  # Cuboid.component_areas


def _prism_trig() -> np.ndarray:
    """(MAX_SIDES + 1, 6, MAX_SIDES): for each side count n, the cosines and sines of the
    vertex angles a, of a + 2π/n and of the side normals' angles a + π/n, computed by
    the expressions of :meth:`Prism.patches`."""
    out = np.zeros((MAX_SIDES + 1, 6, MAX_SIDES))
    for n in np.arange(3, MAX_SIDES + 1):
        a = (np.pi / n + TWO_PI * np.arange(n) / n)[:, None]
        a1 = a + TWO_PI / n
        mid = a + np.pi / n
        for k, v in enumerate((np.cos(a), np.sin(a), np.cos(a1), np.sin(a1), np.cos(mid), np.sin(mid))):
            out[n, k, :n] = v[:, 0]
    return out


def _sparse(table: np.ndarray) -> np.ndarray:
    """A :func:`artipg.geometry.patches.compile_linear` table (c, p, q + 1) as rows (c p, 5)
    ``i0, i1, a0, a1, b``: each output is ``a0 P[i0] + a1 P[i1] + b``, the row's at most
    two non-zero coefficients (a missing one is 0 on column 0)."""
    flat = table.reshape(-1, table.shape[-1])
    out = np.zeros((len(flat), 5))
    for r, row in enumerate(flat):
        nz = np.flatnonzero(row[:-1])
        if len(nz) > 2 or not np.isin(np.abs(row[nz]), (0.5, 1.0)).all():
            raise ValueError("compiled patch tables need at most two coefficients of ±1/2 or ±1 per row")
        out[r, :len(nz)] = nz
        out[r, 2:2 + len(nz)] = row[nz]
        out[r, 4] = row[-1]
    return out


# the constant tables of the kernels (compiled in)
_BOX_T = _sparse(_BOX_TABLE)
_RING_T = _sparse(_RING_TABLE)
_SIDES_T = _sparse(np.concatenate([_RING_SIDES.T, np.zeros((32, 1))], 1))
_FCAPS_T = _sparse(_FRUSTUM_CAPS)
_RCAPS_T = _sparse(_RING_CAPS)
_PRISM_TRIG = _prism_trig()
#: Prism.bounds_batch of a unit radius and height for each side count n (rows 3..MAX_SIDES):
#: the x and y extremes [n, lo/hi, x/y] are numpy's cosines and sines times 1.0 (exact),
#: so r times them is bounds_batch's ``r * cos(...)``.
_PRISM_BOX = np.zeros((MAX_SIDES + 1, 2, 2))
_PRISM_BOX[3:] = Prism.bounds_batch(np.column_stack([np.ones(MAX_SIDES - 2), np.zeros(MAX_SIDES - 2),
                                                     np.arange(3.0, MAX_SIDES + 1)]))[:, :, :2]
#: Upper bound of the cells of one row of each template (code): buffer sizes of :func:`cells`.
ROW_CELLS = tuple(int(k) for k in _CELLS.sum(axis=1))
#: Parameters per cell row (:attr:`artipg.annotate.points.PrimitiveTable.cell_rows`).
Q_WIDTH = int(_NPARAM.max())
#: numpy's cos (row 0) and sin (row 1) of 0, the quarter turns that
#: :func:`artipg.geometry.revolve._arc_bounds_batch` tests, and 2π.
TRIG = np.ascontiguousarray(np.stack([np.cos(_ANGLES), np.sin(_ANGLES)]))


# ---------------------------------------------------------------- cell buffers

@numba.njit(cache=True)
def _affine_rows(T, P, out):
    """``out[r, m]``: row r of sparse table ``T`` (:func:`_sparse`) applied to parameter
    row ``P[m]``, the value of ``A @ P.T + b`` in :func:`artipg.geometry.patches.linear`
    (and of ``P @ sides``, with b = 0). The sum starts from +0.0 like BLAS's, and
    leaving out the zero terms changes nothing: adding ±0 to it keeps it."""
    nan = _poison(P)
    for r in range(T.shape[0]):
        i0, i1, a0, a1, b = int(T[r, 0]), int(T[r, 1]), T[r, 2], T[r, 3], T[r, 4]
        for m in range(P.shape[0]):
            acc = 0.0
            acc += a0 * P[m, i0]
            acc += a1 * P[m, i1]
            acc += nan[m]
            out[r, m] = acc + b


@numba.njit(cache=True)
def _push(fam, params, area, prim, buf, cnt):
    """Append the cells of a block (``params`` (c, p, M), ``area`` (c, M)) with a positive
    area to family ``fam``'s rows of the cell arrays ``buf`` (:func:`cells`), patch by
    patch and, within one, row by row."""
    Q, ab, ib, base = buf
    k = base[fam] + cnt[fam]
    c, p, M = params.shape
    for i in range(c):
        for m in range(M):
            a = area[i, m]
            if a > 0.0:
                for j in range(p):
                    Q[k, j] = params[i, j, m]
                ab[k] = a
                ib[k] = prim[m]
                k += 1
    cnt[fam] = k - base[fam]


@numba.njit(cache=True)
def _poison(P):
    """Per row of ``P``, the sum of 0 times each parameter: ±0 (adding it changes nothing:
    the sums it is added to are never -0) or NaN when a parameter is NaN or infinite,
    which the zero coefficients that BLAS multiplies spread to every output."""
    out = np.empty(P.shape[0])
    for m in range(P.shape[0]):
        z = 0.0
        for k in range(P.shape[1]):
            z += 0.0 * P[m, k]
        out[m] = z
    return out


@numba.njit(cache=True)
def _push_affine(fam, T, area, P, prim, buf, cnt):
    """:func:`_push` of a block whose parameters are the rows of sparse table ``T``
    (:func:`_sparse`, c p rows) applied to ``P`` (M, q), computed only for the kept cells."""
    Q, ab, ib, base = buf
    k = base[fam] + cnt[fam]
    c, M = area.shape
    p = T.shape[0] // c
    nan = _poison(P)
    for i in range(c):
        for m in range(M):
            a = area[i, m]
            if a > 0.0:
                for j in range(p):
                    r = i * p + j
                    acc = 0.0
                    acc += T[r, 2] * P[m, int(T[r, 0])]
                    acc += T[r, 3] * P[m, int(T[r, 1])]
                    acc += nan[m]
                    Q[k, j] = acc + T[r, 4]
                ab[k] = a
                ib[k] = prim[m]
                k += 1
    cnt[fam] = k - base[fam]


@numba.njit(cache=True)
def _min(a, b):
    """``np.minimum`` of two floats (NaN if either is)."""
    return a if a <= b or a != a else b


@numba.njit(cache=True)
def _max(a, b):
    """``np.maximum`` of two floats (NaN if either is)."""
    return a if a >= b or a != a else b


@numba.njit(cache=True)
def _np_min(a, b):
    """``np.minimum(a, b)`` to the sign of a zero: NaN if either is, else ``b`` unless
    ``a < b`` (so ``np.minimum(0.0, -0.0)`` is -0.0)."""
    return a if a < b or a != a else b


@numba.njit(cache=True)
def _np_max(a, b):
    """``np.maximum(a, b)`` to the sign of a zero (see :func:`_np_min`)."""
    return a if a > b or a != a else b


@numba.njit(cache=True)
def _cross_norm(ax, ay, az, bx, by, bz):
    """:func:`artipg.geometry.patches.cross_norm` of one pair (same operations)."""
    u = ay * bz - az * by
    v = az * bx - ax * bz
    w = ax * by - ay * bx
    return math.sqrt(u * u + v * v + w * w)


# ---------------------------------------------------------------- templates' patches

@numba.njit(cache=True)
def _cuboid(P, prim, box_t, buf, cnt):
    M = P.shape[0]
    area = np.empty((6, M))
    for m in range(M):
        for i in range(3):
            a = P[m, _FACE_I[i]] * P[m, _FACE_J[i]]
            area[2 * i, m] = a
            area[2 * i + 1, m] = a
    _push_affine(_RECT, box_t, area, P, prim, buf, cnt)


@numba.njit(cache=True)
def _rect_ring(P, prim, ring_t, sides_t, buf, cnt):
    M = P.shape[0]
    sides = np.empty((32, M))
    _affine_rows(sides_t, P, sides)
    area = np.empty((16, M))
    for r in range(16):
        for m in range(M):
            area[r, m] = sides[r, m] * sides[16 + r, m]
    _push_affine(_RECT, ring_t, area, P, prim, buf, cnt)


@numba.njit(cache=True)
def _frustum(P, prim, caps_t, buf, cnt):
    M = P.shape[0]
    band = np.empty((1, 7, M))
    area = np.empty((1, M))
    for m in range(M):
        r0, r1, h = P[m, 0], P[m, 1], P[m, 2]
        z1 = h / 2
        z0 = -z1
        d0 = r1 - r0
        d1 = z1 - z0
        slant = math.sqrt(d0 * d0 + d1 * d1)
        s = 1.0 / (slant if slant > 0 else 1.0)
        q = band[0, :, m]
        q[0], q[1], q[2], q[3], q[4] = r0, r1, z0, z1, TWO_PI
        q[5] = s * d1
        q[6] = -s * d0
        area[0, m] = ((TWO_PI * 0.5) * (r0 + r1)) * slant
    _push(_BAND, band, area, prim, buf, cnt)
    cap_area = np.empty((2, M))
    for k in range(2):
        for m in range(M):
            r = P[m, k]
            cap_area[k, m] = ((np.pi * P[m, 3 + k]) * r) * r
    _push_affine(_SECTOR, caps_t, cap_area, P, prim, buf, cnt)


@numba.njit(cache=True)
def _ring(P, prim, C, S, trig, caps_t, buf, cnt):
    M = P.shape[0]
    walls = np.empty((2, 7, M))
    wall_area = np.empty((2, M))
    annulus_area = np.empty((2, M))
    ends = np.zeros((2, 12, M))
    end_area = np.zeros((2, M))
    for m in range(M):
        ro, ri, h, arc, tp = P[m, 0], P[m, 1], P[m, 2], P[m, 3], P[m, 4]
        z = h / 2
        dz = z - -z
        for w in range(2):  # outer wall (normals outward), inner wall (inward)
            a0 = ro if w == 0 else ri
            a1 = a0 + tp
            dr = a1 - a0
            slant = math.sqrt(dr * dr + dz * dz)
            s = (1.0 if w == 0 else -1.0) / (slant if slant > 0 else 1.0)
            q = walls[w, :, m]
            q[0], q[1], q[2], q[3], q[4] = a0, a1, -z, z, arc
            q[5] = s * dz
            q[6] = -s * dr
            wall_area[w, m] = ((arc * 0.5) * (a0 + a1)) * slant
        ro1, ri1 = ro + tp, ri + tp
        annulus_area[0, m] = (arc / 2) * (ro * ro - ri * ri)
        annulus_area[1, m] = (arc / 2) * (ro1 * ro1 - ri1 * ri1)
        if not arc >= _FULL_TURN:  # the flat ends of a partial ring
            for k in range(2):  # at 0 and at arc
                ce, se = (trig[0, 0], trig[1, 0]) if k == 0 else (C[m, 3], S[m, 3])
                sg = -1.0 if k == 0 else 1.0
                ax, ay = (ro - ri) * ce, (ro - ri) * se
                bx, by = tp * ce, tp * se
                e = ends[k, :, m]
                e[0], e[1], e[2] = ri * ce, ri * se, -z
                e[3], e[4] = ax, ay
                e[6], e[7], e[8] = bx, by, h
                e[9], e[10] = -se * sg, ce * sg
                end_area[k, m] = _cross_norm(ax, ay, 0.0, bx, by, h)
    _push(_BAND, walls, wall_area, prim, buf, cnt)
    _push_affine(_SECTOR, caps_t, annulus_area, P, prim, buf, cnt)
    _push(_RECT, ends, end_area, prim, buf, cnt)


@numba.njit(cache=True)
def _sphere(P, prim, buf, cnt):
    M = P.shape[0]
    zone = np.empty((1, 3, M))
    zone_area = np.empty((1, M))
    caps = np.zeros((2, 15, M))
    cap_area = np.empty((2, M))
    for m in range(M):
        R, lo, hi = P[m, 0], P[m, 1], P[m, 2]
        zone[0, 0, m], zone[0, 1, m], zone[0, 2, m] = R, lo, hi
        zone_area[0, m] = (TWO_PI * R) * (hi - lo)
        for k in range(2):
            z = lo if k == 0 else hi
            v = R * R - z * z
            r1 = math.sqrt(_max(v, 0.0))
            q = caps[k, :, m]
            q[2], q[3], q[7] = z, 1.0, 1.0
            q[11] = -1.0 if k == 0 else 1.0
            q[13], q[14] = r1, TWO_PI
            cap_area[k, m] = (0.5 * TWO_PI) * (r1 * r1)
    _push(_ZONE, zone, zone_area, prim, buf, cnt)
    _push(_SECTOR, caps, cap_area, prim, buf, cnt)


@numba.njit(cache=True)
def _torus(P, prim, C, S, trig, buf, cnt):
    M = P.shape[0]
    tube = np.empty((1, 3, M))
    tube_area = np.empty((1, M))
    caps = np.zeros((2, 15, M))
    cap_area = np.zeros((2, M))
    for m in range(M):
        R, r, arc = P[m, 0], P[m, 1], P[m, 2]
        tube[0, 0, m], tube[0, 1, m], tube[0, 2, m] = R, r, arc
        tube_area[0, m] = ((TWO_PI * r) * R) * arc
        if not arc >= _FULL_TURN:  # end discs of a partial torus, when capped
            for k in range(2):  # at 0 and at arc
                ce, se = (trig[0, 0], trig[1, 0]) if k == 0 else (C[m, 2], S[m, 2])
                sg = -1.0 if k == 0 else 1.0
                q = caps[k, :, m]
                q[0], q[1], q[3], q[4] = R * ce, R * se, ce, se
                q[8] = 1.0
                q[9], q[10] = -se * sg, ce * sg
                q[13], q[14] = r, TWO_PI
                cap_area[k, m] = ((0.5 * TWO_PI) * (r * r - 0.0 * 0.0)) * (1.0 * P[m, 3 + k])
    _push(_TORUS, tube, tube_area, prim, buf, cnt)
    _push(_SECTOR, caps, cap_area, prim, buf, cnt)


@numba.njit(cache=True)
def _prism(P, prim, trig, buf, cnt):
    M = P.shape[0]
    ns = np.unique(P[:, 2])
    for n_ in ns:
        n = int(n_)
        on = np.empty(M)
        for m in range(M):
            on[m] = 1.0 if P[m, 2] == n else 0.0
        side = np.zeros((n, 12, M))
        side_area = np.empty((n, M))
        fan = np.zeros((2 * n, 12, M))
        fan_area = np.empty((2 * n, M))
        for i in range(n):
            ca, sa, ca1, sa1, cm, sm = trig[n, 0, i], trig[n, 1, i], trig[n, 2, i], trig[n, 3, i], \
                trig[n, 4, i], trig[n, 5, i]
            for m in range(M):
                r, h = P[m, 0], P[m, 1]
                x0, y0, x1, y1 = r * ca, r * sa, r * ca1, r * sa1
                dx, dy = x1 - x0, y1 - y0
                q = side[i, :, m]
                q[0], q[1], q[2], q[3], q[4], q[8], q[9], q[10] = x0, y0, -h / 2, dx, dy, h, cm, sm
                side_area[i, m] = _cross_norm(dx, dy, 0.0, 0.0, 0.0, h) * on[m]
                a = (0.5 * _cross_norm(x0, y0, 0.0, x1, y1, 0.0)) * on[m]
                for k in range(2):
                    f = fan[k * n + i, :, m]
                    f[2] = -h / 2 if k == 0 else h / 2
                    f[3], f[4], f[6], f[7] = x0, y0, x1, y1
                    f[11] = -1.0 if k == 0 else 1.0
                    fan_area[k * n + i, m] = a
        _push(_RECT, side, side_area, prim, buf, cnt)
        _push(_TRI, fan, fan_area, prim, buf, cnt)


@numba.njit(cache=True)
def _tri_prism(P, prim, buf, cnt):
    M = P.shape[0]
    side = np.zeros((3, 12, M))
    side_area = np.empty((3, M))
    end = np.zeros((2, 12, M))
    end_area = np.empty((2, M))
    V = np.empty((3, 2))
    E = np.empty((3, 2))
    for m in range(M):
        w, t, a, d = P[m, 0], P[m, 1], P[m, 2], P[m, 3]
        V[0, 0], V[0, 1] = -w / 2, 0.0
        V[1, 0], V[1, 1] = w / 2, 0.0
        V[2, 0], V[2, 1] = a, t
        for i in range(3):  # the edges v1 - v0, v2 - v1, v0 - v2
            j = (i + 1) % 3
            E[i, 0] = V[j, 0] - V[i, 0]
            E[i, 1] = V[j, 1] - V[i, 1]
        for i in range(3):
            L = math.hypot(E[i, 0], E[i, 1])
            q = side[i, :, m]
            q[0], q[1], q[2], q[3], q[4], q[8] = V[i, 0], V[i, 1], -d / 2, E[i, 0], E[i, 1], d
            q[9] = E[i, 1] / L
            q[10] = -E[i, 0] / L
            side_area[i, m] = _cross_norm(E[i, 0], E[i, 1], 0.0, 0.0, 0.0, d)
        ea = 0.5 * _cross_norm(E[0, 0], E[0, 1], 0.0, -E[2, 0], -E[2, 1], 0.0)
        for k in range(2):
            q = end[k, :, m]
            q[0], q[1] = V[0, 0], V[0, 1]
            q[2] = -d / 2 if k == 0 else d / 2
            q[3], q[4], q[6], q[7] = E[0, 0], E[0, 1], -E[2, 0], -E[2, 1]
            q[11] = -1.0 if k == 0 else 1.0
            end_area[k, m] = ea
    _push(_RECT, side, side_area, prim, buf, cnt)
    _push(_TRI, end, end_area, prim, buf, cnt)


@numba.njit(cache=True)
def _rows(flat, foff, start, g):
    """Parameters (M, p) of group g: a view of the packed parameters."""
    M = start[g + 1] - start[g]
    return flat[foff[g]:foff[g + 1]].reshape(M, (foff[g + 1] - foff[g]) // M)


@numba.njit(cache=True)
def cells(flat, foff, start, prim, code, cos_f, sin_f, Q, area, cell_prim, cell_code, cdf, counts):
    """Patch cells of an object's primitives, as ``PrimitiveTable`` builds them from its
    patch families: the kept cells (area > 0) family by family, in :data:`FAMILIES`
    order, and within a family in the order of the templates' ``patches``.

    Parameters
    ----------
    flat : (F,) ndarray
        Parameters of every primitive, groups one after the other, row-major in a group.
    foff, start : (G + 1,) int64
        Group g is ``flat[foff[g]:foff[g + 1]]`` and rows ``start[g]:start[g + 1]``.
    prim : (N,) int64
        Global primitive index of each row.
    code : (G,) int64
        :data:`CODES` of each group's template.
    cos_f, sin_f : (F,) ndarray
        numpy's cos and sin of ``flat``, read for the arcs of rings and tori only (and
        only those below 2π: the arcs numpy takes the cosines of); other entries may
        hold anything.
    Q : (R, Q_WIDTH) ndarray, zeros
        Out: each cell's family parameters (zero-padded).
    area, cdf : (R,) ndarray
        Out: cell areas (m^2) and their running sum (``np.cumsum``).
    cell_prim, cell_code : (R,) int64
        Out: global primitive index and family code of each cell.
    counts : (6,) int64
        Out: number of cells of each family.

    The outputs have R >= the sum over rows of :data:`ROW_CELLS` rows; the first K hold
    the cells.

    Returns
    -------
    K : int
    """
    G = len(code)
    base = np.zeros(6, dtype=np.int64)  # each family fills its own rows, then they close up
    for g in range(G):
        M = start[g + 1] - start[g]
        for f in range(5):
            base[f + 1] += _CELLS[code[g], f] * M
    for f in range(5):
        base[f + 1] += base[f]
    rows = base[5]
    for g in range(G):
        rows += _CELLS[code[g], 5] * (start[g + 1] - start[g])
    if rows > len(area):
        raise ValueError("cell arrays too short")
    buf = (Q, area, cell_prim, base)
    counts[:] = 0
    for g in range(G):
        s, e = start[g], start[g + 1]
        P, pr, c = _rows(flat, foff, start, g), prim[s:e], code[g]
        if c == 0:
            _cuboid(P, pr, _BOX_T, buf, counts)
        elif c == 1:
            _rect_ring(P, pr, _RING_T, _SIDES_T, buf, counts)
        elif c == 2:
            _frustum(P, pr, _FCAPS_T, buf, counts)
        elif c == 3:
            _ring(P, pr, _rows(cos_f, foff, start, g), _rows(sin_f, foff, start, g), TRIG, _RCAPS_T, buf, counts)
        elif c == 4:
            _sphere(P, pr, buf, counts)
        elif c == 5:
            _torus(P, pr, _rows(cos_f, foff, start, g), _rows(sin_f, foff, start, g), TRIG, buf, counts)
        elif c == 6:
            _prism(P, pr, _PRISM_TRIG, buf, counts)
        else:
            _tri_prism(P, pr, buf, counts)
    o = 0
    width = Q.shape[1]
    for f in range(6):
        b, k = base[f], counts[f]
        if b != o:  # to earlier rows only: whole rows move, with their zero padding
            for r in range(k):
                for j in range(width):
                    Q[o + r, j] = Q[b + r, j]
                area[o + r] = area[b + r]
                cell_prim[o + r] = cell_prim[b + r]
        for r in range(o, o + k):
            cell_code[r] = f
        o += k
    if o:
        acc = area[0]
        cdf[0] = acc
        for r in range(1, o):
            acc = acc + area[r]
            cdf[r] = acc
    return o


@numba.njit(cache=True)
def cell_arrays(flat, foff, start, prim, code, cos_f, sin_f):
    """:func:`cells` into arrays made here, cut to the K cells: (family code (K,),
    parameter rows (K, Q_WIDTH), areas (K,), primitives (K,), running area sums (K,),
    cells per family (6,)); the arguments are :func:`cells`'s first seven."""
    R = 0
    for g in range(len(code)):
        R += _CELLS[code[g]].sum() * (start[g + 1] - start[g])
    Q = np.zeros((R, Q_WIDTH))
    area, cdf = np.empty(R), np.empty(R)
    ints = np.empty((2, R), dtype=np.int64)
    counts = np.empty(6, dtype=np.int64)
    K = cells(flat, foff, start, prim, code, cos_f, sin_f, Q, area, ints[0], ints[1], cdf, counts)
    return ints[1, :K], Q[:K], area[:K], ints[0, :K], cdf[:K], counts


# ---------------------------------------------------------------- local boxes

@numba.njit(cache=True)
def _turn_box(out, r, z0, z1):
    out[1, 0] = r
    out[1, 1] = r
    out[0, 0] = -r
    out[0, 1] = -r
    out[0, 2] = z0
    out[1, 2] = z1


@numba.njit(cache=True)
def _arc_box(out, r_lo, r_hi, arc, ca, sa, trig, z0, z1):
    """:func:`artipg.geometry.revolve._arc_bounds_batch` of one row: ``ca``, ``sa`` are
    numpy's cos and sin of min(arc, 2π), ``trig`` is :data:`TRIG`."""
    out[0, 2] = z0
    out[1, 2] = z1
    a = _min(arc, TWO_PI)
    for ax in range(2):
        lo, hi = np.inf, -np.inf
        for j in range(5):  # the angles 0, arc and the quarter turns inside the arc
            if j == 0:
                t = trig[ax, 0]
            elif j == 1:
                t = ca if ax == 0 else sa
            else:
                if not _QUARTERS[j - 2] < a:
                    continue
                t = trig[ax, j - 1]
            for r in (r_lo, r_hi):
                v = t * r
                lo = _min(lo, v)
                hi = _max(hi, v)
        out[0, ax] = lo
        out[1, ax] = hi


@numba.njit(cache=True)
def _arc_trig(C, S, trig, m, col, arc):
    """numpy's cos and sin of min(arc, 2π) for row m: the packed ones below 2π."""
    if not arc >= TWO_PI:
        return C[m, col], S[m, col]
    return trig[0, 4], trig[1, 4]


@numba.njit(cache=True)
def local_boxes(flat, foff, start, prim, code, cos_f, sin_f, out, ch):
    """Write the local box (2, 3) of every primitive to ``out[prim]`` (N, 2, 3), the
    values of its template's ``bounds_batch``, and its centre and half extents to
    ``ch[0, prim]``, ``ch[1, prim]`` ((2, N, 3), as :func:`centre_half`). Arguments as
    for :func:`cells`.

    Returns False when a prism has a side count outside the integers 3..MAX_SIDES (its
    group's rows are then left for ``bounds_batch``), else True.
    """
    done = True
    for g in range(len(code)):
        s, e, c = start[g], start[g + 1], code[g]
        P = _rows(flat, foff, start, g)
        if c == 6:  # Prism: numpy's extremes for its side count, times r
            for m in range(e - s):
                r, h, n = P[m, 0], P[m, 1], P[m, 2]
                if not (n >= 3 and n <= MAX_SIDES and n == int(n)):
                    done = False
                    break
            if not done:
                continue
        if c >= 6:
            for m in range(e - s):
                i = prim[s + m]
                p, b = P[m], out[i]
                if c == 6:
                    r, t = p[0], _PRISM_BOX[int(p[2])]
                    b[0, 0], b[0, 1], b[1, 0], b[1, 1] = r * t[0, 0], r * t[0, 1], r * t[1, 0], r * t[1, 1]
                    b[0, 2], b[1, 2] = -p[1] / 2, p[1] / 2
                else:  # TriPrism
                    w, t, a, d = p[0], p[1], p[2], p[3]
                    b[0, 0], b[0, 1], b[0, 2] = _np_min(-w / 2, a), _np_min(0.0, t), -d / 2
                    b[1, 0], b[1, 1], b[1, 2] = _np_max(w / 2, a), _np_max(0.0, t), d / 2
                for k in range(3):
                    ch[0, i, k] = (b[0, k] + b[1, k]) * 0.5
                    ch[1, i, k] = (b[1, k] - b[0, k]) * 0.5
            continue
        C = _rows(cos_f, foff, start, g)
        S = _rows(sin_f, foff, start, g)
        full = True  # every row a full turn (rings and tori)
        if c == 3 or c == 5:
            col = _RING_ARC if c == 3 else _TORUS_ARC
            for m in range(e - s):
                full = full and P[m, col] >= _FULL_TURN
        for m in range(e - s):
            i = prim[s + m]
            p, b = P[m], out[i]
            if c == 0 or c == 1:
                for k in range(3):
                    b[1, k] = p[k] * 0.5
                    b[0, k] = -b[1, k]
            elif c == 2:
                r = _max(p[0], p[1])
                b[1, 0], b[1, 1], b[1, 2] = r, r, p[2] * 0.5
                for k in range(3):
                    b[0, k] = -b[1, k]
            elif c == 3:
                ro, ri, h, arc, tp = p[0], p[1], p[2], p[3], p[4]
                r_hi = _max(ro, ro + tp)
                if full:
                    _turn_box(b, r_hi, -h / 2, h / 2)
                else:
                    r_lo = _min(ri, ri + tp)
                    ca, sa = _arc_trig(C, S, TRIG, m, 3, arc)
                    _arc_box(b, r_lo, r_hi, arc, ca, sa, TRIG, -h / 2, h / 2)
            elif c == 4:
                R, lo, hi = p[0], p[1], p[2]
                if lo <= 0 and hi >= 0:
                    r = R
                else:
                    r = math.sqrt(_max(R * R - _min(lo * lo, hi * hi), 0.0))
                b[1, 0], b[1, 1], b[0, 0], b[0, 1] = r, r, -r, -r
                b[0, 2], b[1, 2] = lo, hi
            elif c == 5:
                R, r, arc = p[0], p[1], p[2]
                if full:
                    _turn_box(b, R + r, -r, r)
                else:
                    ca, sa = _arc_trig(C, S, TRIG, m, 2, arc)
                    _arc_box(b, R - r, R + r, arc, ca, sa, TRIG, -r, r)
            for k in range(3):
                ch[0, i, k] = (b[0, k] + b[1, k]) * 0.5
                ch[1, i, k] = (b[1, k] - b[0, k]) * 0.5
    return done


@numba.njit(cache=True)
def centre_half(boxes, out):
    """Centres ``out[0]`` and half extents ``out[1]`` (N, 3) of ``boxes`` (N, 2, 3), as
    :func:`artipg.annotate.points.transform_boxes` computes them."""
    for i in range(boxes.shape[0]):
        for k in range(3):
            out[0, i, k] = (boxes[i, 0, k] + boxes[i, 1, k]) * 0.5
            out[1, i, k] = (boxes[i, 1, k] - boxes[i, 0, k]) * 0.5


@numba.njit(cache=True)
def box_union(Rc, Rh, W, out):
    """Bounding box ``out`` (2, 3) of the boxes with centres ``Rc + W[:, :3, 3]`` and half
    extents ``Rh`` (``Rc``, ``Rh`` (N, 3, 1): the rotated centres and the half extents
    through |R|): the union :func:`artipg.annotate.points.transform_boxes` gives."""
    for k in range(3):
        lo, hi = np.inf, -np.inf
        for i in range(Rc.shape[0]):
            wc = Rc[i, k, 0] + W[i, k, 3]
            lo = _min(lo, wc - Rh[i, k, 0])
            hi = _max(hi, wc + Rh[i, k, 0])
        out[0, k] = lo
        out[1, k] = hi
