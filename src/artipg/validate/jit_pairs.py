"""Compiled kernels of the pair building in :mod:`artipg.validate.checks`.

- :func:`close_pairs`: :func:`artipg.validate.contacts.close_pairs` (up to its
  all-pairs size);
- :func:`sweep_pairs`: the rows of :func:`artipg.validate.checks._sweep_pairs`
  (the moving pieces' boxes at every pose of their joint, their swept boxes, the
  candidates and the per-pose box test, the moved frames).

The same tests and the same arithmetic in the same order as the numpy code, one
row at a time, so the pairs and frames are bit for bit the same
(``tests/test_validate_fast.py``). The joint values' sines and cosines come from
numpy.

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import numba
import numpy as np

from artipg.kernel_cache import drop_stale_caches
from artipg.validate.kinematics import _SKEW, _SKEW_SIGN
from artipg.validate import kinematics
from artipg.validate.jit_base import copy4

drop_stale_caches(__file__, [kinematics.__file__])


@numba.njit(cache=True)
def close_pairs(c, h, pad, label):
    """All pairs ``a < b`` of boxes (centres ``c``, half extents ``h``: (M, 3)) closer
    than ``pad`` on every axis, in ``np.triu_indices`` order; with ``label`` (M,)
    (empty: none), only pairs of different labels."""
    M = len(c)
    use_label = len(label) == M
    n = 0
    a = np.empty(16, dtype=np.int64)
    b = np.empty(16, dtype=np.int64)
    for i in range(M):
        for j in range(i + 1, M):
            if use_label and label[i] == label[j]:
                continue
            if (abs(c[i, 0] - c[j, 0]) - (h[i, 0] + h[j, 0]) < pad and abs(c[i, 1] - c[j, 1]) - (h[i, 1] + h[j, 1]) < pad
                    and abs(c[i, 2] - c[j, 2]) - (h[i, 2] + h[j, 2]) < pad):
                if n == len(a):
                    a = grow(a)
                    b = grow(b)
                a[n] = i
                b[n] = j
                n += 1
    return a[:n].copy(), b[:n].copy()


@numba.njit(cache=True)
def grow(x):
    """An int64 array twice as long as ``x`` starting with ``x``."""
    y = np.empty(2 * len(x), dtype=np.int64)
    for i in range(len(x)):
        y[i] = x[i]
    return y


@numba.njit(cache=True)
def turns_in_place(axis, point, slides, symmetric, W0):
    """:func:`artipg.validate.checks._turns_in_place`: boolean (J, M), piece m is a
    solid of revolution about joint j's (revolute or continuous) axis line (unit
    directions ``axis`` and points ``point``: (J, 3))."""
    J, M = len(axis), len(W0)
    out = np.zeros((J, M), dtype=np.bool_)
    for j in range(J):
        if slides[j]:
            continue
        ax, ay, az = axis[j, 0], axis[j, 1], axis[j, 2]
        for m in range(M):
            if not symmetric[m]:
                continue
            zx, zy, zz = W0[m, 0, 2], W0[m, 1, 2], W0[m, 2, 2]
            cross = max(max(abs(zy * az - zz * ay), abs(zz * ax - zx * az)), abs(zx * ay - zy * ax))
            d0, d1, d2 = W0[m, 0, 3] - point[j, 0], W0[m, 1, 3] - point[j, 1], W0[m, 2, 3] - point[j, 2]
            da = 0.0 + d0 * ax + d1 * ay + d2 * az  # (.sum(): from zero)
            r0, r1, r2 = d0 - da * ax, d1 - da * ay, d2 - da * az
            out[j, m] = cross < 1e-9 and np.sqrt(0.0 + r0 * r0 + r1 * r1 + r2 * r2) < 1e-9
    return out


@numba.njit(cache=True)
def sweep_pairs(moving, subtree, scene_joint, scene_q, cos_q, sin_q, slides, axis, point, W0, c0, h0, half, pad):
    """The rows of :func:`artipg.validate.checks._sweep_pairs`: ``(a, b, Wa, Wb, scene)``.

    Parameters
    ----------
    moving, subtree : (J, M) bool
        Pieces each joint moves (less those turning in place), and its whole subtree.
    scene_joint, scene_q : (S,)
        :meth:`artipg.validate.kinematics.Kinematics.sweep_table`.
    cos_q, sin_q : (S,)
        Cosine and sine of each scene's turn (0 for slides).
    slides : (J,) bool
    axis, point : (J, 3)
        The joints' world axis lines at rest.
    W0 : (M, 4, 4)
        Piece frames at rest; ``c0``, ``h0`` their world boxes, ``half`` the local ones.
    pad : float
        The box test's pad (minus the demanded overlap).
    """
    J, M = moving.shape
    S = len(scene_joint)
    GR, Gt = world_motions(scene_joint, scene_q, cos_q, sin_q, slides, axis, point)
    n_pose = np.zeros(J, dtype=np.int64)
    for s in range(S):
        n_pose[scene_joint[s]] += 1
    first = np.zeros(J, dtype=np.int64)
    for j in range(1, J):
        first[j] = first[j - 1] + n_pose[j - 1]
    # (joint, moving piece) pairs and every pose of each: frames and boxes
    U = 0
    for j in range(J):
        for m in range(M):
            if moving[j, m]:
                U += 1
    uj = np.empty(U, dtype=np.int64)
    up = np.empty(U, dtype=np.int64)
    ustart = np.empty(U, dtype=np.int64)
    u = 0
    n_rows = 0
    for j in range(J):
        for m in range(M):
            if moving[j, m]:
                uj[u], up[u], ustart[u] = j, m, n_rows
                n_rows += n_pose[j]
                u += 1
    s_idx = np.empty(n_rows, dtype=np.int64)
    p_idx = np.empty(n_rows, dtype=np.int64)
    for u in range(U):
        for k in range(n_pose[uj[u]]):
            s_idx[ustart[u] + k], p_idx[ustart[u] + k] = first[uj[u]] + k, up[u]
    Rm, cm, hm = moved_boxes(GR, Gt, W0, c0, half, s_idx, p_idx)
    sw_c = np.empty((U, 3))
    sw_h = np.empty((U, 3))
    for u in range(U):
        for i in range(3):
            lo, hi = np.inf, -np.inf
            for k in range(n_pose[uj[u]]):
                r = ustart[u] + k
                lo = min(lo, cm[r, i] - hm[r, i])
                hi = max(hi, cm[r, i] + hm[r, i])
            sw_c[u, i] = 0.5 * (lo + hi)
            sw_h[u, i] = 0.5 * (hi - lo)
    # candidates by swept box, then per-pose boxes; rows by (joint, moving piece),
    # static piece, pose
    n = 0
    for u in range(U):
        for b in range(M):
            if subtree[uj[u], b] or not _overlap(sw_c[u], sw_h[u], c0[b], h0[b], pad):
                continue
            for k in range(n_pose[uj[u]]):
                r = ustart[u] + k
                if _overlap(cm[r], hm[r], c0[b], h0[b], pad):
                    n += 1
    a_out = np.empty(n, dtype=np.int64)
    b_out = np.empty(n, dtype=np.int64)
    s_out = np.empty(n, dtype=np.int64)
    Wa = np.zeros((n, 4, 4))
    Wb = np.empty((n, 4, 4))
    n = 0
    for u in range(U):
        j, p = uj[u], up[u]
        for b in range(M):
            if subtree[j, b] or not _overlap(sw_c[u], sw_h[u], c0[b], h0[b], pad):
                continue
            for k in range(n_pose[j]):
                r = ustart[u] + k
                if not _overlap(cm[r], hm[r], c0[b], h0[b], pad):
                    continue
                s = first[j] + k
                a_out[n], b_out[n], s_out[n] = p, b, s
                for i in range(3):
                    for l in range(3):
                        Wa[n, i, l] = Rm[r, i, l]
                    Wa[n, i, 3] = (GR[s, i, 0] * W0[p, 0, 3] + GR[s, i, 1] * W0[p, 1, 3] + GR[s, i, 2] * W0[p, 2, 3]
                                   + Gt[s, i])
                Wa[n, 3, 3] = 1.0
                copy4(W0[b], Wb[n])
                n += 1
    return a_out, b_out, Wa, Wb, s_out


@numba.njit(cache=True)
def world_motions(scene_joint, scene_q, cos_q, sin_q, slides, axis, point):
    """:func:`artipg.validate.checks._world_motions`: the rotation (S, 3, 3) and
    translation (S, 3) of every scene, from the cosine and sine of its turn."""
    S = len(scene_joint)
    GR = np.empty((S, 3, 3))
    Gt = np.empty((S, 3))
    for s in range(S):
        j = scene_joint[s]
        c, sn = cos_q[s], sin_q[s]
        a4 = (axis[j, 0], axis[j, 1], axis[j, 2], 0.0)
        for i in range(3):  # kinematics.rotations
            for k in range(3):
                GR[s, i, k] = (axis[j, i] * axis[j, k]) * (1.0 - c) + a4[_SKEW[i, k]] * _SKEW_SIGN[i, k] * sn
            GR[s, i, i] += c
        q = scene_q[s]
        for i in range(3):
            if slides[j]:
                Gt[s, i] = q * axis[j, i]
            else:
                Gt[s, i] = point[j, i] - (GR[s, i, 0] * point[j, 0] + GR[s, i, 1] * point[j, 1]
                                          + GR[s, i, 2] * point[j, 2])
    return GR, Gt


@numba.njit(cache=True)
def moved_boxes(GR, Gt, W0, c0, half, s_idx, p_idx):
    """:func:`artipg.validate.checks._moved_boxes` of pieces ``p_idx`` moved by the
    motions ``s_idx`` (rows of ``GR``, ``Gt``)."""
    n = len(s_idx)
    Rm = np.empty((n, 3, 3))
    cm = np.empty((n, 3))
    hm = np.empty((n, 3))
    for r in range(n):
        s, p = s_idx[r], p_idx[r]
        for i in range(3):
            for l in range(3):
                Rm[r, i, l] = GR[s, i, 0] * W0[p, 0, l] + GR[s, i, 1] * W0[p, 1, l] + GR[s, i, 2] * W0[p, 2, l]
            cm[r, i] = GR[s, i, 0] * c0[p, 0] + GR[s, i, 1] * c0[p, 1] + GR[s, i, 2] * c0[p, 2] + Gt[s, i]
        for i in range(3):
            hm[r, i] = abs(Rm[r, i, 0]) * half[p, 0] + abs(Rm[r, i, 1]) * half[p, 1] + abs(Rm[r, i, 2]) * half[p, 2]
    return Rm, cm, hm


@numba.njit(cache=True)
def _overlap(ca, ha, cb, hb, pad):
    """Boxes closer than ``pad`` on every axis (contacts.overlapping)."""
    for i in range(3):
        if not (abs(ca[i] - cb[i]) - (ha[i] + hb[i]) < pad):
            return False
    return True
