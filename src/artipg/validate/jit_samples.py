"""Surface samples of one geometry template's pieces in one compiled pass.

:func:`draw_group` is :func:`artipg.validate.shapes._sample_group` compiled: the same
draws from the same stream and the same arithmetic in the same order, so its points
are bit for bit those of ``_sample_group`` (``tests/test_validate_compiled.py``).

- cuboids, frusta, rings, spheres and tori (:data:`TEMPLATE_CODES`): one kernel
  computes everything, the templates' component areas and patch parameters
  included (their own expressions, written out one piece at a time: the tests
  compare both with the templates' ``component_areas`` and ``patches``);
- other templates (prisms): their numpy ``component_areas`` and ``patches``, then
  one kernel for the counts, the patch pick, the family samplers and the points.

:func:`require` does :meth:`artipg.validate.shapes.Pieces.require`'s bookkeeping in
the kernels as well.

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math
import sys

import numba
import numpy as np

from artipg.geometry.box import _BOX_TABLE, Cuboid
from artipg.geometry.revolve import _FRUSTUM_CAPS, _RING_CAPS, Frustum, Ring, Sphere, Torus
from artipg.kernel_cache import drop_stale_caches
from artipg.validate.jit_base import fma, kernels_match, vmax
from artipg.validate.shapes import _BOX_FEATURES, DENSITY, MAX_PER_COMPONENT, MIN_PER_COMPONENT, _layout
from artipg.validate.streams import _CAP, _buffer
from artipg.validate import jit_base

drop_stale_caches(__file__, [jit_base.__file__, sys.modules[Cuboid.__module__].__file__,
                              sys.modules[Frustum.__module__].__file__, sys.modules[_layout.__module__].__file__])

_TWO_PI = 2.0 * np.pi
_TORUS = 5  # family code (shapes._FAMILY_CODES)
_EMPTY = np.zeros(0)


def draw_group(geom, P: np.ndarray, seed: int, key: int, want: np.ndarray | None = None):
    """``_sample_group(geom, P, UniformStream(seed, key), want)`` (see
    :func:`artipg.validate.shapes._sample_group`), compiled.

    Parameters
    ----------
    geom : GeometryTemplate
    P : (M, p) float64
        Parameters of the template's pieces.
    seed, key : int
        The sample stream (:class:`artipg.validate.streams.UniformStream`).
    want : (M,) bool, optional
        Pieces whose samples are computed (the stream is consumed as for all).

    Returns
    -------
    tuple or None
        Points as coordinate rows (3, N), piece frames, and the count per piece (M,)
        (zero for the pieces not wanted); None when the draws would run past the
        cached part of the stream (the caller falls back to ``_sample_group``).
    """
    if geom in TEMPLATE_CODES and kernels_match():
        return draw_template(geom, P, seed, key, want)
    comp_area = geom.component_areas(P)
    positive = comp_area > 0.0
    on = positive.any(axis=1)  # pieces with samples
    blocks = geom.patches(P if on.all() else P[on])
    lay = _layout(blocks, comp_area.shape[1])
    if lay.one_per_comp:
        direct = lay.complete or bool((lay.patch[positive.any(axis=0)] >= 0).all())
    else:
        direct = False
    q = blocks[0].params.ravel() if len(blocks) == 1 else np.concatenate([b.params.ravel() for b in blocks])
    area = _EMPTY if direct else np.concatenate([np.ravel(b.area) for b in blocks])
    want = np.ones(len(P), dtype=np.bool_) if want is None else want
    return _on_stream(seed, key, lambda buf: _draw(comp_area, P, want, lay.meta, q, area, buf, direct,
                                                   geom is Cuboid, DENSITY, MIN_PER_COMPONENT, MAX_PER_COMPONENT,
                                                   _BOX_FEATURES))


def _on_stream(seed: int, key: int, kernel):
    """``kernel(buf)`` on the cached uniforms ``buf`` of sample stream (seed, key),
    lengthened until the kernel's draws fit: ``(points, counts)``, or None past the
    cache's cap. ``kernel`` returns ``(points, counts, short)`` with ``short`` 0 or
    the stream length it needs."""
    size = 4096
    while True:
        buf = _buffer(seed, key, size)
        out, per, short = kernel(buf)
        if not short:
            return out, per
        size = max(short, 2 * len(buf))
        if size > _CAP:
            return None


@numba.njit(cache=True)
def _draw(comp_area, P, want, meta, q, area, buf, direct, box, density, lo, hi, feat):
    """The kernel of :func:`draw_group`: ``(points (3, N), counts (M,), short)``, where
    ``short`` is 0, or the stream length needed when ``buf`` is too short."""
    M, C = comp_area.shape
    NP, NB = meta[1], meta[2]
    patch = meta[5:5 + C]
    pcomp = meta[5 + C:5 + C + NP]
    pblock = meta[5 + C + NP:5 + C + 2 * NP]
    family = meta[5 + C + 2 * NP:5 + C + 2 * NP + NB]
    bp = meta[5 + C + 2 * NP + NB:5 + C + 2 * NP + 2 * NB]  # parameters per patch of each block
    bc = meta[5 + C + 2 * NP + 2 * NB:5 + C + 2 * NP + 3 * NB]  # patches of each block
    # samples per piece and component: clip(ceil(area * density), lo, hi) where area > 0
    n = np.zeros((M, C), dtype=np.int64)
    per = np.zeros(M, dtype=np.int64)
    used = np.full(M, -1, dtype=np.int64)  # index among the pieces with samples
    U = 0
    N = 0
    for r in range(M):
        for c in range(C):
            a = comp_area[r, c]
            if a > 0.0:
                n[r, c] = _sample_count(a, density, lo, hi)
                per[r] += n[r, c]
        if per[r]:
            used[r] = U
            U += 1
            N += per[r]
    F = len(feat) if box else 0
    off = np.zeros(M, dtype=np.int64)  # output column of each wanted piece's first sample
    total = 0
    for r in range(M):
        if want[r]:
            off[r] = total
            total += per[r] + F
    out = np.empty((3, total))
    bstart = np.zeros(NB, dtype=np.int64)  # first patch of each block
    qoff = np.zeros(NB, dtype=np.int64)  # its parameters in q: (patches, p, U) blocks, flat
    for b in range(1, NB):
        bstart[b] = bstart[b - 1] + bc[b - 1]
        qoff[b] = qoff[b - 1] + bc[b - 1] * bp[b - 1] * U
    if N > len(buf):
        return out, per, 3 * N
    if direct and not (family == _TORUS).any():
        # each component's samples all fall on its one patch: every block's draws
        # follow from the counts, and only the wanted samples are computed
        ksum = np.zeros(NB, dtype=np.int64)  # samples per block
        for r in range(M):
            for c in range(C):
                if n[r, c]:
                    ksum[pblock[patch[c]]] += n[r, c]
        bpos = np.empty(NB, dtype=np.int64)  # first draw of each block
        pos = N
        for b in range(NB):
            bpos[b] = pos
            pos += 2 * ksum[b]
        if pos > len(buf):
            return out, per, pos
        seen = np.zeros(NB, dtype=np.int64)  # samples of each block in earlier cells
        for r in range(M):
            o = off[r]
            for c in range(C):
                k = n[r, c]
                if k == 0:
                    continue
                p = patch[c]
                b = pblock[p]
                if want[r]:
                    base = qoff[b] + (p - bstart[b]) * bp[b] * U + used[r]
                    u0 = bpos[b] + seen[b]
                    for j in range(k):
                        x, y, z = _point(family[b], q, base, U, buf[u0 + j], buf[u0 + ksum[b] + j])
                        out[0, o], out[1, o], out[2, o] = x, y, z
                        o += 1
                else:
                    o += k
                seen[b] += k
        return _box_points(out, per, want, off, F, feat, P, np.arange(M)), per, 0
    # the piece, component and rank in its piece of every sample, in cell order
    srow = np.empty(N, dtype=np.int64)
    scomp = np.empty(N, dtype=np.int64)
    sidx = np.empty(N, dtype=np.int64)
    i = 0
    for r in range(M):
        j = 0
        for c in range(C):
            for _ in range(n[r, c]):
                srow[i] = r
                scomp[i] = c
                sidx[i] = j
                i += 1
                j += 1
    # the pick (one draw per sample): the component's patch, or one by area
    which = np.empty(N, dtype=np.int64)
    if direct:
        for i in range(N):
            which[i] = patch[scomp[i]]
    else:
        cum = np.empty(NP)
        for i in range(N):
            u_row = used[srow[i]]
            c = scomp[i]
            acc = 0.0
            for p in range(NP):
                a = area[p * U + u_row] if pcomp[p] == c else 0.0
                acc = a if p == 0 else acc + a
                cum[p] = acc
            u = buf[i] * cum[NP - 1]
            k = 0
            for p in range(NP - 1):
                if u >= cum[p]:
                    k += 1
            which[i] = k
    pos = N
    for b in range(NB):
        k = 0
        for i in range(N):
            if pblock[which[i]] == b:
                k += 1
        if k == 0:
            continue  # no draw
        sel = np.empty(k, dtype=np.int64)
        k = 0
        for i in range(N):
            if pblock[which[i]] == b:
                sel[k] = i
                k += 1
        fam = family[b]
        stride = bp[b] * U
        if fam != _TORUS:  # random((2, k)): u then v
            if pos + 2 * k > len(buf):
                return out, per, pos + 2 * k + 3 * N
            for j in range(k):
                i = sel[j]
                r = srow[i]
                if want[r]:
                    base = qoff[b] + (which[i] - bstart[b]) * stride + used[r]
                    x, y, z = _point(fam, q, base, U, buf[pos + j], buf[pos + k + j])
                    o = off[r] + sidx[i]
                    out[0, o] = x
                    out[1, o] = y
                    out[2, o] = z
            pos += 2 * k
        else:
            # artipg.geometry.patches.torus_tube_angles: rejection rounds over the
            # samples still to place, then one angle per sample along the arc
            v = np.empty(k)
            Rs = np.empty(k)
            rs = np.empty(k)
            for jj in range(k):
                i = sel[jj]
                base = qoff[b] + (which[i] - bstart[b]) * stride + used[srow[i]]
                Rs[jj] = q[base]
                rs[jj] = q[base + U]
            pos = _tube_angles(Rs, rs, buf, pos, v)
            if pos < 0:
                return out, per, -pos + 4 * N
            if pos + k > len(buf):
                return out, per, pos + k + 4 * N
            for j in range(k):
                i = sel[j]
                r = srow[i]
                if want[r]:
                    base = qoff[b] + (which[i] - bstart[b]) * stride + used[r]
                    R = q[base]
                    rr = q[base + U]
                    th = buf[pos + j] * q[base + 2 * U]
                    cv = math.cos(v[j])
                    rho = R + rr * cv
                    o = off[r] + sidx[i]
                    out[0, o] = rho * math.cos(th)
                    out[1, o] = rho * math.sin(th)
                    out[2, o] = rr * math.sin(v[j])
            pos += k
    return _box_points(out, per, want, off, F, feat, P, np.arange(M)), per, 0


@numba.njit(cache=True)
def _sample_count(a, density, lo, hi):
    """Samples of a surface component of area ``a``: ``ceil(a * density)`` clipped to
    [lo, hi], as :func:`artipg.validate.shapes._sample_group` counts them."""
    x = np.ceil(a * density)
    x = x if x >= lo else float(lo)
    x = x if x <= hi else float(hi)
    return int(x)


@numba.njit(cache=True)
def _tube_angles(Rs, rs, buf, pos, out):
    """:func:`artipg.geometry.patches.torus_tube_angles` on the uniforms ``buf[pos:]``:
    rejection rounds over the samples still to place (centre-line radii ``Rs``, tube
    radii ``rs`` (k,)), writing their tube angles into ``out`` (k,). Returns the stream
    position after the rounds, or minus the length they need when ``buf`` is too short."""
    k = len(Rs)
    todo = np.arange(k)
    nt = k
    while nt:
        if pos + 2 * nt > len(buf):
            return -(pos + 2 * nt)
        m = 0
        for t in range(nt):
            i = todo[t]
            cand = buf[pos + t] * _TWO_PI
            if buf[pos + nt + t] * (Rs[i] + rs[i]) <= Rs[i] + rs[i] * math.cos(cand):
                out[i] = cand
            else:
                todo[m] = i
                m += 1
        pos += 2 * nt
        nt = m
    return pos


@numba.njit(cache=True)
def _box_points(out, per, want, off, F, feat, P, rows):
    """A box's corners and edge points after its samples (``F`` of them, or none), in
    ``out``; ``per`` becomes the count per piece (0 for the pieces not wanted)."""
    for r in range(len(per)):
        if want[r]:
            o = off[r] + per[r]
            for f in range(F):
                out[0, o + f] = feat[f, 0] * P[rows[r], 0]
                out[1, o + f] = feat[f, 1] * P[rows[r], 1]
                out[2, o + f] = feat[f, 2] * P[rows[r], 2]
            per[r] += F
        else:
            per[r] = 0
    return out


@numba.njit(cache=True)
def _affine(q, base, U, u, v):
    """``o + u a + v b`` from the rows o a b of a patch's parameters."""
    return (q[base] + u * q[base + 3 * U] + v * q[base + 6 * U], q[base + U] + u * q[base + 4 * U] + v * q[base + 7 * U],
            q[base + 2 * U] + u * q[base + 5 * U] + v * q[base + 8 * U])


@numba.njit(cache=True)
def _point(fam, q, base, U, u, v):
    """One point of family ``fam`` from draws ``u``, ``v``; the patch's parameters are
    ``q[base + j U]`` (the samplers of :mod:`artipg.geometry.patches`, one point)."""
    if fam == 0:  # rect
        return _affine(q, base, U, u, v)
    if fam == 1:  # tri: the far half of the unit square reflected
        if u + v > 1.0:
            return _affine(q, base, U, 1.0 - u, 1.0 - v)
        return _affine(q, base, U, u, v)
    if fam == 2:  # sector
        r0, r1, arc = q[base + 12 * U], q[base + 13 * U], q[base + 14 * U]
        rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
        phi = v * arc
        return _affine(q, base, U, math.cos(phi) * rho, math.sin(phi) * rho)
    if fam == 3:  # band
        r0, r1, z0, z1, arc = q[base], q[base + U], q[base + 2 * U], q[base + 3 * U], q[base + 4 * U]
        rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
        s = u * (r0 + r1) / (rho + r0 + 1e-300)
        th = v * arc
        return rho * math.cos(th), rho * math.sin(th), z0 + s * (z1 - z0)
    # zone
    R, z0, z1 = q[base], q[base + U], q[base + 2 * U]
    z = u * (z1 - z0)
    z += z0
    m = R * R - z * z
    rho = math.sqrt(m if m >= 0.0 else 0.0)
    th = v * _TWO_PI
    return math.cos(th) * rho, math.sin(th) * rho, z


# ------------------------------------------------------------------ templates written out

#: Templates whose component areas and patch parameters :func:`_draw_template` computes
#: itself (the templates' own expressions, in the same order), and their codes.
TEMPLATE_CODES = {Cuboid: 1, Frustum: 2, Ring: 3, Sphere: 4, Torus: 5}
_C = (0, 6, 3, 6, 3, 3)  # components per template code
#: Block (patch list position) and family of each component, per template code.
_BLOCK = np.array([[0] * 6, [0] * 6, [0, 1, 1, 0, 0, 0], [0, 0, 1, 1, 2, 2], [0, 1, 1, 0, 0, 0], [0, 1, 1, 0, 0, 0]])
_FAM = np.array([[0] * 6, [0] * 6, [3, 2, 2, 0, 0, 0], [3, 3, 2, 2, 0, 0], [4, 2, 2, 0, 0, 0], [5, 2, 2, 0, 0, 0]])


def draw_template(geom, P: np.ndarray, seed: int, key: int, want: np.ndarray | None = None):
    """:func:`draw_group` for the templates of :data:`TEMPLATE_CODES` without calling
    their numpy ``component_areas`` and ``patches``: the kernel computes both (bit
    for bit; needs :func:`artipg.validate.jit_base.kernels_match`)."""
    want = np.ones(len(P), dtype=np.bool_) if want is None else want
    code, rows = TEMPLATE_CODES[geom], np.arange(len(P))
    return _on_stream(seed, key, lambda buf: _draw_template(code, P, rows, want, buf, DENSITY, MIN_PER_COMPONENT,
                                                            MAX_PER_COMPONENT, _BOX_FEATURES, _BOX_TABLE,
                                                            _FRUSTUM_CAPS, _RING_CAPS, _BLOCK, _FAM))


@numba.njit(cache=True)
def _linear(table, patch, j, P, r):
    """Parameter j of patch ``patch`` of row r by a :func:`artipg.geometry.patches.linear`
    table (c, p, q + 1): ``A @ P.T + b`` as numpy (BLAS) computes it."""
    q = table.shape[2] - 1
    s = 0.0
    for k in range(q):
        s = fma(table[patch, j, k], P[r, k], s)
    return s + table[patch, j, q]


@numba.njit(cache=True)
def _areas(code, P, r, out):
    """``geom.component_areas(P)[r]`` of template ``code`` into ``out``."""
    if code == 1:
        sx, sy, sz = P[r, 0], P[r, 1], P[r, 2]
        out[0] = out[1] = sy * sz
        out[2] = out[3] = sx * sz
        out[4] = out[5] = sx * sy
    elif code == 2:
        r0, r1, h = P[r, 0], P[r, 1], P[r, 2]
        out[0] = (np.pi * (r0 + r1)) * math.hypot(h, r1 - r0)
        out[1] = np.pi * P[r, 3] * r0 * r0
        out[2] = np.pi * P[r, 4] * r1 * r1
    elif code == 3:
        ro, ri, h, arc, tp = P[r, 0], P[r, 1], P[r, 2], P[r, 3], P[r, 4]
        slant = math.hypot(h, tp)
        out[0] = arc * (ro + tp / 2) * slant
        out[1] = arc * (ri + tp / 2) * slant
        ro1, ri1 = ro + tp, ri + tp
        out[2] = arc / 2 * (ro * ro - ri * ri)
        out[3] = arc / 2 * (ro1 * ro1 - ri1 * ri1)
        out[4] = out[5] = 0.0 if arc >= _TWO_PI - 1e-9 else (ro - ri) * h
    elif code == 4:
        R, lo, hi = P[r, 0], P[r, 1], P[r, 2]
        out[0] = _TWO_PI * R * (hi - lo)
        out[1] = np.pi * vmax(R * R - lo * lo, 0.0)
        out[2] = np.pi * vmax(R * R - hi * hi, 0.0)
    else:
        R, rr, arc = P[r, 0], P[r, 1], P[r, 2]
        part = 0.0 if arc >= _TWO_PI - 1e-9 else 1.0
        out[0] = _TWO_PI * rr * R * arc
        out[1] = np.pi * rr * rr * P[r, 3] * part
        out[2] = np.pi * rr * rr * P[r, 4] * part


@numba.njit(cache=True)
def _patch(code, comp, P, r, box_t, frustum_t, ring_t, q):
    """Parameters (``q[:15]``, as the family's rows) of the patch of component ``comp``
    of row r, as ``geom.patches(P)`` makes them."""
    q[:] = 0.0
    if code == 1:  # one rect per face, a linear table
        for j in range(12):
            q[j] = _linear(box_t, comp, j, P, r)
    elif code == 2:
        if comp == 0:  # the band, written out in Frustum.patches
            z = P[r, 2] / 2
            q[0], q[1], q[2], q[3], q[4] = P[r, 0], P[r, 1], -z, z, _TWO_PI
        else:
            for j in range(15):
                q[j] = _linear(frustum_t, comp - 1, j, P, r)
    elif code == 3:
        ro, ri, h, arc, tp = P[r, 0], P[r, 1], P[r, 2], P[r, 3], P[r, 4]
        z = h / 2
        if comp < 2:  # outer and inner walls
            rb = ro if comp == 0 else ri
            q[0], q[1], q[2], q[3], q[4] = rb, rb + tp, -z, z, arc
        elif comp < 4:  # bottom and top annuli, a linear table
            for j in range(15):
                q[j] = _linear(ring_t, comp - 2, j, P, r)
        else:  # the ends of a partial ring
            e = 0.0 if comp == 4 else arc
            ce, se = math.cos(e), math.sin(e)
            q[0], q[1], q[2] = ri * ce, ri * se, -z
            q[3], q[4], q[5] = (ro - ri) * ce, (ro - ri) * se, 0.0
            q[6], q[7], q[8] = tp * ce, tp * se, h
    elif code == 4:
        if comp == 0:  # the zone
            q[0], q[1], q[2] = P[r, 0], P[r, 1], P[r, 2]
        else:  # the cut discs
            R, zc = P[r, 0], P[r, comp]
            q[2], q[3], q[7] = zc, 1.0, 1.0
            q[13] = math.sqrt(vmax(R * R - zc * zc, 0.0))
            q[14] = _TWO_PI
    else:
        if comp == 0:  # the tube
            q[0], q[1], q[2] = P[r, 0], P[r, 1], P[r, 2]
        else:  # the end discs of a partial torus
            e = 0.0 if comp == 1 else P[r, 2]
            ce, se = math.cos(e), math.sin(e)
            q[0], q[1], q[2] = P[r, 0] * ce, P[r, 0] * se, 0.0
            q[3], q[4], q[5] = ce, se, 0.0
            q[6], q[7], q[8] = 0.0, 0.0, 1.0
            q[12], q[13], q[14] = 0.0, P[r, 1], _TWO_PI


@numba.njit(cache=True)
def _draw_template(code, P, rows, want, buf, density, lo, hi, feat, box_t, frustum_t, ring_t, block, fam):
    """The kernel of :func:`draw_template` for the pieces ``P[rows]``: ``(points (3, N),
    counts (M,), short)``."""
    M = len(rows)
    C = _C_OF[code]
    area = np.empty(6)
    n = np.zeros((M, C), dtype=np.int64)
    per = np.zeros(M, dtype=np.int64)
    N = 0
    for r in range(M):
        _areas(code, P, rows[r], area)
        for c in range(C):
            a = area[c]
            if a > 0.0:
                n[r, c] = _sample_count(a, density, lo, hi)
                per[r] += n[r, c]
        N += per[r]
    F = len(feat) if code == 1 else 0
    off = np.zeros(M, dtype=np.int64)
    total = 0
    for r in range(M):
        if want[r]:
            off[r] = total
            total += per[r] + F
    out = np.empty((3, total))
    NB = 3
    ksum = np.zeros(NB, dtype=np.int64)
    for r in range(M):
        for c in range(C):
            ksum[block[code, c]] += n[r, c]
    q = np.empty(15)
    # the pick takes one draw per sample; then each block with samples draws in turn
    pos = N
    bpos = np.zeros(NB, dtype=np.int64)
    tube = np.empty(0)
    for b in range(NB):
        bpos[b] = pos
        if ksum[b] == 0:
            continue
        if code == 5 and b == 0:
            # the tube: artipg.geometry.patches.torus_tube_angles over all its samples
            k = ksum[0]
            tube = np.empty(k)
            Rs = np.empty(k)
            rs = np.empty(k)
            t = 0
            for r in range(M):
                for _ in range(n[r, 0]):
                    Rs[t], rs[t] = P[rows[r], 0], P[rows[r], 1]
                    t += 1
            pos = _tube_angles(Rs, rs, buf, pos, tube)
            if pos < 0:
                return out, per, -pos + 4 * N
            bpos[b] = pos  # then one angle per sample along the arc
            pos += k
        else:
            pos += 2 * ksum[b]
    if pos > len(buf):
        return out, per, pos + N
    seen = np.zeros(NB, dtype=np.int64)
    for r in range(M):
        o = off[r]
        for c in range(C):
            k = n[r, c]
            if k == 0:
                continue
            b = block[code, c]
            if want[r]:
                _patch(code, c, P, rows[r], box_t, frustum_t, ring_t, q)
                u0 = bpos[b] + seen[b]
                for j in range(k):
                    if code == 5 and c == 0:
                        v = tube[seen[b] + j]
                        th = buf[u0 + j] * q[2]
                        rho = q[0] + q[1] * math.cos(v)
                        out[0, o], out[1, o], out[2, o] = rho * math.cos(th), rho * math.sin(th), q[1] * math.sin(v)
                    else:
                        x, y, z = _point(fam[code, c], q, 0, 1, buf[u0 + j], buf[u0 + ksum[b] + j])
                        out[0, o], out[1, o], out[2, o] = x, y, z
                    o += 1
            else:
                o += k
            seen[b] += k
    return _box_points(out, per, want, off, F, feat, P, rows), per, 0


_C_OF = np.array(_C, dtype=np.int64)


def require(pieces, idx: np.ndarray) -> list:
    """Draw the samples of the pieces ``idx`` of ``pieces`` that have none yet, for the
    templates of :data:`TEMPLATE_CODES` (:meth:`artipg.validate.shapes.Pieces.require`,
    with the bookkeeping in the kernel). Returns the template indices left to draw
    (other templates, meshes) and the mask of the pieces needed, or None when none are."""
    need, kinds = _needed(np.asarray(idx, dtype=np.int64), pieces._drawn, pieces._kind, len(pieces._kinds))
    if not len(kinds):
        return None
    rest = []
    for k in kinds.tolist():
        code = TEMPLATE_CODES.get(pieces._kinds[k], 0)
        out = None
        size = 4096
        while code:
            buf = _buffer(pieces._seed, k, size)
            out, short = _require_kind(code, k, need, pieces._kind, pieces.params, buf, pieces.start, pieces.count,
                                       pieces._drawn, pieces._size, DENSITY, MIN_PER_COMPONENT, MAX_PER_COMPONENT,
                                       _BOX_FEATURES, _BOX_TABLE, _FRUSTUM_CAPS, _RING_CAPS, _BLOCK, _FAM)
            if not short:
                break
            out = None
            size = max(short, 2 * len(buf))
            if size > _CAP:
                break
        if out is None:
            rest.append(k)
        else:
            pieces._chunks.append(out)
            pieces._size += out.shape[1]
    return rest, need


@numba.njit(cache=True)
def _needed(idx, drawn, kind, K):
    """The pieces of ``idx`` without samples (mask) and their templates (ascending)."""
    need = np.zeros(len(drawn), dtype=np.bool_)
    has = np.zeros(K, dtype=np.bool_)
    for i in idx:
        if not drawn[i]:
            need[i] = True
            has[kind[i]] = True
    return need, np.nonzero(has)[0]


@numba.njit(cache=True)
def _require_kind(code, k, need, kind, params, buf, start, count, drawn, size, density, lo, hi, feat, box_t,
                  frustum_t, ring_t, block, fam):
    """Draw template ``k`` (code ``code``) for the needed pieces, record where their
    samples start (after ``size`` samples drawn before) and how many: ``(points,
    short)``."""
    n = 0
    for m in range(len(kind)):
        n += kind[m] == k
    rows = np.empty(n, dtype=np.int64)
    want = np.empty(n, dtype=np.bool_)
    n = 0
    for m in range(len(kind)):
        if kind[m] == k:
            rows[n], want[n] = m, need[m]
            n += 1
    out, per, short = _draw_template(code, params, rows, want, buf, density, lo, hi, feat, box_t, frustum_t, ring_t,
                                     block, fam)
    if short:
        return out, short
    at = size
    for i in range(n):
        if want[i]:
            m = rows[i]
            start[m], count[m], drawn[m] = at, per[i], True
            at += per[i]
    return out, 0


def template_areas(geom, P: np.ndarray) -> np.ndarray:
    """``geom.component_areas(P)`` as the kernel of :func:`draw_template` computes it."""
    return _template_areas(TEMPLATE_CODES[geom], np.ascontiguousarray(P, dtype=float))


def template_patch(geom, P: np.ndarray, comp: int) -> np.ndarray:
    """The parameters (M, 15) of component ``comp``'s patch of every row of ``P`` (the
    family's rows, zero-padded), as the kernel of :func:`draw_template` computes them."""
    return _template_patch(TEMPLATE_CODES[geom], np.ascontiguousarray(P, dtype=float), comp, _BOX_TABLE,
                           _FRUSTUM_CAPS, _RING_CAPS)


@numba.njit(cache=True)
def _template_areas(code, P):
    out = np.zeros((len(P), _C_OF[code]))
    area = np.empty(6)
    for r in range(len(P)):
        _areas(code, P, r, area)
        out[r] = area[:_C_OF[code]]
    return out


@numba.njit(cache=True)
def _template_patch(code, P, comp, box_t, frustum_t, ring_t):
    out = np.empty((len(P), 15))
    for r in range(len(P)):
        _patch(code, comp, P, r, box_t, frustum_t, ring_t, out[r])
    return out
