"""Surface samples of one geometry template's pieces in one compiled pass.

:func:`draw_group` is :func:`artipg.validate.shapes._sample_group` with everything
that depends on the samples (the counts, the patch pick, the family samplers, a box's
corners and edge points) done by one numba kernel: the same draws from the same
stream and the same arithmetic in the same order, so its points are bit for bit
those of ``_sample_group`` (``tests/test_validate_fast.py`` checks it on every
category). The templates' own component areas and patch blocks are still computed
by their numpy code.

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from artipg.geometry.box import Cuboid
from artipg.validate.shapes import _BOX_FEATURES, DENSITY, MAX_PER_COMPONENT, MIN_PER_COMPONENT, _layout
from artipg.validate.streams import _CAP, _buffer

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
    size = 4096
    while True:
        buf = _buffer(seed, key, size)
        out, per, short = _draw(comp_area, P, want, lay.meta, q, area, buf, direct, geom is Cuboid, DENSITY,
                                MIN_PER_COMPONENT, MAX_PER_COMPONENT, _BOX_FEATURES)
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
                x = np.ceil(a * density)
                x = x if x >= lo else float(lo)
                x = x if x <= hi else float(hi)
                n[r, c] = int(x)
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
        return _box_points(out, per, want, off, F, feat, P), per, 0
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
            todo = np.arange(k)
            nt = k
            while nt:
                if pos + 2 * nt > len(buf):
                    return out, per, pos + 2 * nt + 4 * N
                m = 0
                for t in range(nt):
                    jj = todo[t]
                    i = sel[jj]
                    base = qoff[b] + (which[i] - bstart[b]) * stride + used[srow[i]]
                    R = q[base]
                    rr = q[base + U]
                    cand = buf[pos + t] * _TWO_PI
                    if buf[pos + nt + t] * (R + rr) <= R + rr * math.cos(cand):
                        v[jj] = cand
                    else:
                        todo[m] = jj
                        m += 1
                pos += 2 * nt
                nt = m
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
    return _box_points(out, per, want, off, F, feat, P), per, 0


@numba.njit(cache=True)
def _box_points(out, per, want, off, F, feat, P):
    """A box's corners and edge points after its samples (``F`` of them, or none), in
    ``out``; ``per`` becomes the count per piece (0 for the pieces not wanted)."""
    for r in range(len(per)):
        if want[r]:
            o = off[r] + per[r]
            for f in range(F):
                out[0, o + f] = feat[f, 0] * P[r, 0]
                out[1, o + f] = feat[f, 1] * P[r, 1]
                out[2, o + f] = feat[f, 2] * P[r, 2]
            per[r] += F
        else:
            per[r] = 0
    return out


@numba.njit(cache=True, inline="always")
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
