"""The scenes of :func:`artipg.validate.checks.run_checks` in one compiled pass.

:func:`build` poses the object at rest, every movable joint's sweep and the
all-open poses, finds the pairs of pieces of each scene (rest: within the floating
tolerance; sweep and open: overlapping boxes) and, for the pairs that need surface
samples, the frames between the pieces and which sources come near their targets;
:func:`scenes` then draws the samples needed and measures every pair
(:mod:`artipg.validate.jit_contacts`). The scenes are the numpy code's, bit for bit:
the same poses (:mod:`artipg.validate.kinematics`), boxes, tests and pair order.

Runs only where :func:`artipg.validate.jit_base.kernels_match` holds (the kernels'
matrix products and sines are numpy's) and up to
:data:`artipg.validate.contacts._DENSE` pieces (beyond, numpy's pair search is a
sweep and prune).

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from artipg.kernel_cache import drop_stale_caches
from artipg.validate.jit_base import box_near, copy4, matmul4, rigid_inverse, set_identity
from artipg.validate.jit_pairs import _overlap, close_pairs, grow, sweep_pairs, turns_in_place
from artipg.validate.kinematics import _SKEW, _SKEW_SIGN
from artipg.validate import jit_base, jit_pairs, kinematics

drop_stale_caches(__file__, [jit_base.__file__, jit_pairs.__file__, kinematics.__file__])


def scenes(kin, pieces, tol, overlap: float):
    """The rest, sweep and open scenes of :func:`artipg.validate.checks.run_checks`
    with their distances ``"d"``: ``(W0, c0, h0, [rest, sweep, open...])``."""
    return measure(kin, pieces, tol, overlap)[:4]


def measure(kin, pieces, tol, overlap: float):
    """:func:`scenes` and ``(a, b, d, sizes, amb, undrawn)``: every scene's pairs and
    distances concatenated (the scenes' arrays are views of them), the rows per scene,
    and the rest rows ``run_checks`` refines with whether one of their pieces has no
    samples yet (:func:`artipg.validate.jit_verdicts.ambiguous`); ``amb`` is None where
    the pieces have no compiled SDFs."""
    fracs = np.asarray(tol.open_fractions, dtype=float) if len(kin.movable()) >= 2 else np.zeros(0)
    (W0, c0, h0, a, b, Wa, Wb, margin, sizes, sw_scene, sw_joint, sw_q, box, ball, other, src, tgt, rel,
     keep) = build(kin.parent, kin.origin, kin.type_codes, kin.axis, kin.limits, kin.movable(), pieces.link,
                   pieces.part, pieces.T, pieces.center, pieces.half, pieces.symmetric, pieces.is_box, pieces.is_ball,
                   float(tol.floating), int(tol.sweep_poses), fracs, float(overlap))
    amb = undrawn = None
    if pieces.jit_table is not None:
        from artipg.validate.jit_verdicts import distances

        code, aux, radial = pieces.jit_table
        if len(other):
            pieces.require(src[keep])
        d, amb, undrawn = distances(a, b, Wa, Wb, margin, box, ball, other, src, tgt, rel, keep, pieces.params, code,
                                    aux, pieces.center, pieces.half, radial, pieces.points_t, pieces.start,
                                    pieces.count, sizes[0], c0, h0, pieces.is_box, pieces._drawn, float(tol.floating))
    else:
        from artipg.validate.contacts import pair_distance

        d = pair_distance(pieces, a, b, Wa, Wb, margin)
    out = []
    k = 0
    for i, n in enumerate(sizes.tolist()):
        s = {"a": a[k:k + n], "b": b[k:k + n], "Wa": Wa[k:k + n], "Wb": Wb[k:k + n], "d": d[k:k + n],
             "margin": tol.floating if i == 0 else 0.0}
        if i == 1:
            s.update(scene=sw_scene, joint=sw_joint, q=sw_q, movable=kin.movable())
        elif i > 1:
            s["frac"] = tol.open_fractions[i - 2]
        out.append(s)
        k += n
    return W0, c0, h0, out, (a, b, d, sizes, amb, undrawn)


@numba.njit(cache=True)
def _poses(parent, origin, jtype, axis, q):
    """:meth:`artipg.validate.kinematics.Kinematics.poses` with joint values ``q`` (L,)
    (0: rest)."""
    L = len(parent)
    T = np.empty((L, 4, 4))
    set_identity(T[0])
    motion = np.empty((4, 4))
    tmp = np.empty((4, 4))
    for i in range(1, L):
        matmul4(T[parent[i]], origin[i], T[i])
        v = q[i]
        if v != 0.0 and jtype[i] != 0:
            set_identity(motion)
            x, y, z = axis[i, 0], axis[i, 1], axis[i, 2]
            if jtype[i] == 2:
                motion[0, 3], motion[1, 3], motion[2, 3] = v * x, v * y, v * z
            else:  # kinematics._motion1
                c, s = math.cos(v), math.sin(v)
                C = 1.0 - c
                motion[0, 0], motion[0, 1], motion[0, 2] = c + x * x * C, x * y * C - z * s, x * z * C + y * s
                motion[1, 0], motion[1, 1], motion[1, 2] = y * x * C + z * s, c + y * y * C, y * z * C - x * s
                motion[2, 0], motion[2, 1], motion[2, 2] = z * x * C - y * s, z * y * C + x * s, c + z * z * C
            copy4(T[i], tmp)
            matmul4(tmp, motion, T[i])
    return T


@numba.njit(cache=True)
def _posed(P, link, T, center, half):
    """Piece frames ``P[link] @ T`` and their world boxes (contacts.world_boxes)."""
    M = len(link)
    W = np.empty((M, 4, 4))
    c = np.empty((M, 3))
    h = np.empty((M, 3))
    for m in range(M):
        matmul4(P[link[m]], T[m], W[m])
        for i in range(3):
            c[m, i] = W[m, i, 0] * center[m, 0] + W[m, i, 1] * center[m, 1] + W[m, i, 2] * center[m, 2] + W[m, i, 3]
            h[m, i] = abs(W[m, i, 0]) * half[m, 0] + abs(W[m, i, 1]) * half[m, 1] + abs(W[m, i, 2]) * half[m, 2]
    return W, c, h


@numba.njit(cache=True)
def descendants(parent):
    """:attr:`artipg.validate.kinematics.Kinematics.descendants` (L, L) bool."""
    L = len(parent)
    desc = np.zeros((L, L), dtype=np.bool_)
    for k in range(L):
        a = k
        while a >= 0:
            desc[a, k] = True
            a = parent[a]
    return desc


@numba.njit(cache=True)
def build(parent, origin, jtype, axis, limits, movable, link, part, T, center, half, symmetric, is_box, is_ball,
          floating, n_poses, fracs, overlap):
    """Every scene's pairs, concatenated (rest, sweep, open per fraction), with what
    :func:`artipg.validate.jit_contacts._pair_distance` needs."""
    L, M, J = len(parent), len(link), len(movable)
    desc = descendants(parent)
    rest = _poses(parent, origin, jtype, axis, np.zeros(L))
    W0, c0, h0 = _posed(rest, link, T, center, half)
    ra, rb = close_pairs(c0, h0, floating, part)
    # sweeps: kinematics.sweep_table, world_axes; checks._sweep_pairs
    slides = np.empty(J, dtype=np.bool_)
    cont = np.empty(J, dtype=np.bool_)
    ax = np.empty((J, 3))
    pt = np.empty((J, 3))
    for j in range(J):
        i = movable[j]
        slides[j], cont[j] = jtype[i] == 2, jtype[i] == 3
        for r in range(3):
            ax[j, r] = rest[i, r, 0] * axis[i, 0] + rest[i, r, 1] * axis[i, 1] + rest[i, r, 2] * axis[i, 2]
            pt[j, r] = rest[i, r, 3]
    S = 0
    V = np.empty((J, n_poses + 1))
    keep_q = np.zeros((J, n_poses + 1), dtype=np.bool_)
    if J and M:
        for j in range(J):
            lo = 0.0 if cont[j] else limits[movable[j], 0]
            hi = 0.0 if cont[j] else limits[movable[j], 1]
            step = (hi - lo) / n_poses
            for k in range(n_poses + 1):
                V[j, k] = k * step + lo
            V[j, n_poses] = hi
            for k in range(n_poses + 1):
                if cont[j]:
                    if k < n_poses:
                        V[j, k] = 2.0 * np.pi * (k + 1) / (n_poses + 1)
                    keep_q[j, k] = k < n_poses
                else:
                    keep_q[j, k] = abs(V[j, k]) > 1e-12
                S += keep_q[j, k]
    sw_joint = np.empty(S, dtype=np.int64)
    sw_q = np.empty(S)
    s = 0
    for j in range(J):
        for k in range(n_poses + 1):
            if keep_q[j, k]:
                sw_joint[s], sw_q[s] = j, V[j, k]
                s += 1
    if J and M:
        subtree = np.empty((J, M), dtype=np.bool_)
        for j in range(J):
            for m in range(M):
                subtree[j, m] = desc[movable[j], link[m]]
        turns = turns_in_place(ax, pt, slides, symmetric, W0)
        moving = np.empty((J, M), dtype=np.bool_)
        for j in range(J):
            for m in range(M):
                moving[j, m] = subtree[j, m] and not turns[j, m]
        cq = np.empty(S)
        sq = np.empty(S)
        for s in range(S):
            v = 0.0 if slides[sw_joint[s]] else sw_q[s]
            cq[s], sq[s] = math.cos(v), math.sin(v)
        sa, sb, sWa, sWb, sw_scene = sweep_pairs(moving, subtree, sw_joint, sw_q, cq, sq, slides, ax, pt, W0, c0, h0,
                                                 half, -overlap)
    else:
        sa = np.zeros(0, dtype=np.int64)
        sb = np.zeros(0, dtype=np.int64)
        sWa = np.zeros((0, 4, 4))
        sWb = np.zeros((0, 4, 4))
        sw_scene = np.zeros(0, dtype=np.int64)
    # all joints open: checks._open_pairs (each fraction's pairs appended to o*)
    F = len(fracs) if J >= 2 else 0
    n_open = np.zeros(F, dtype=np.int64)
    oA = np.empty(16, dtype=np.int64)
    oB = np.empty(16, dtype=np.int64)
    oWa = np.empty((16, 4, 4))
    oWb = np.empty((16, 4, 4))
    no = 0
    inv = np.empty((L, 4, 4))
    for i in range(L):
        rigid_inverse(rest[i], inv[i])
    G = np.empty((L, 4, 4))
    for f in range(F):
        q = np.zeros(L)
        for j in range(J):
            i = movable[j]
            q[i] = fracs[f] * np.pi if cont[j] else limits[i, 0] + fracs[f] * (limits[i, 1] - limits[i, 0])
        P = _poses(parent, origin, jtype, axis, q)
        W, c, h = _posed(P, link, T, center, half)
        # links moved by the same rigid motion keep their relative pose (checked at rest)
        for i in range(L):
            matmul4(P[i], inv[i], G[i])
        label = np.arange(L)
        for i in range(L):
            first = i
            for k in range(L):
                same = True
                for r in range(3):
                    for cc in range(4):
                        if not abs(G[i, r, cc] - G[k, r, cc]) < 1e-9:
                            same = False
                if same:
                    first = k
                    break
            if first < i:
                label[i] = label[first]
        piece_label = np.empty(M, dtype=np.int64)
        for m in range(M):
            piece_label[m] = label[link[m]]
        a, b = close_pairs(c, h, -overlap, piece_label)
        n_open[f] = len(a)
        while no + len(a) > len(oA):
            oA, oB, oWa, oWb = grow(oA), grow(oB), _grow_frames(oWa), _grow_frames(oWb)
        for r in range(len(a)):
            oA[no], oB[no] = a[r], b[r]
            copy4(W[a[r]], oWa[no])
            copy4(W[b[r]], oWb[no])
            no += 1
    # concatenated, with each row's margin
    sizes = np.empty(2 + F, dtype=np.int64)
    sizes[0], sizes[1] = len(ra), len(sa)
    for f in range(F):
        sizes[2 + f] = n_open[f]
    K = len(ra) + len(sa) + no
    A = np.empty(K, dtype=np.int64)
    B = np.empty(K, dtype=np.int64)
    WA = np.empty((K, 4, 4))
    WB = np.empty((K, 4, 4))
    margin = np.zeros(K)
    k = 0
    for r in range(len(ra)):
        A[k], B[k], margin[k] = ra[r], rb[r], floating
        copy4(W0[ra[r]], WA[k])
        copy4(W0[rb[r]], WB[k])
        k += 1
    for r in range(len(sa)):
        A[k], B[k] = sa[r], sb[r]
        copy4(sWa[r], WA[k])
        copy4(sWb[r], WB[k])
        k += 1
    for r in range(no):
        A[k], B[k] = oA[r], oB[r]
        copy4(oWa[r], WA[k])
        copy4(oWb[r], WB[k])
        k += 1
    # pairs measured by samples: frames between the pieces, and the jobs that come near
    box = np.empty(K, dtype=np.bool_)
    ball = np.empty(K, dtype=np.bool_)
    n_other = 0
    for r in range(K):
        box[r] = is_box[A[r]] and is_box[B[r]]
        ball[r] = is_ball[A[r]] and is_ball[B[r]]
        n_other += not box[r] and not ball[r]
    other = np.empty(n_other, dtype=np.int64)
    k = 0
    for r in range(K):
        if not box[r] and not ball[r]:
            other[k] = r
            k += 1
    src = np.empty(2 * n_other, dtype=np.int64)
    tgt = np.empty(2 * n_other, dtype=np.int64)
    rel = np.empty((2 * n_other, 4, 4))
    keep = np.empty(2 * n_other, dtype=np.bool_)
    tmp = np.empty((4, 4))
    for k in range(n_other):
        r = other[k]
        src[k], tgt[k], src[n_other + k], tgt[n_other + k] = A[r], B[r], B[r], A[r]
        rigid_inverse(WB[r], tmp)
        matmul4(tmp, WA[r], rel[k])
        rigid_inverse(WA[r], tmp)
        matmul4(tmp, WB[r], rel[n_other + k])
    for j in range(2 * n_other):
        s, t = src[j], tgt[j]
        keep[j] = box_near(rel[j], center[s], half[s], center[t], half[t], margin[other[j % n_other]])
    return (W0, c0, h0, A, B, WA, WB, margin, sizes, sw_scene, sw_joint, sw_q, box, ball, other, src, tgt, rel,
            keep)


@numba.njit(cache=True)
def contact_graphs(L, P, link, part, part_link, a, b, D, floating):
    """The contact graphs of :func:`artipg.validate.checks._floating` from the rest
    pairs ``a``, ``b`` (distances ``D``): the component label (the smallest member) of
    every link (L,) over pairs of different links, and of every part (P,) over pairs
    within a link; which links and parts have pieces; per link the smallest and
    largest component of its parts (``P`` and -1 without parts); and whether the
    links with pieces fall into more than one component."""
    lp = np.arange(L)
    pp = np.arange(P)
    for r in range(len(a)):
        if not D[r] <= floating:
            continue
        la, lb = link[a[r]], link[b[r]]
        if la != lb:
            _union(lp, la, lb)
        else:
            _union(pp, part[a[r]], part[b[r]])
    comp = np.empty(L, dtype=np.int64)
    for i in range(L):
        comp[i] = _root(lp, i)
    pcomp = np.empty(P, dtype=np.int64)
    for i in range(P):
        pcomp[i] = _root(pp, i)
    has_geom = np.zeros(L, dtype=np.bool_)
    for m in range(len(link)):
        has_geom[link[m]] = True
    has_piece = np.zeros(P, dtype=np.bool_)
    for m in range(len(part)):
        has_piece[part[m]] = True
    lo = np.full(L, P, dtype=np.int64)
    hi = np.full(L, -1, dtype=np.int64)
    for p in range(P):
        if has_piece[p]:
            lo[part_link[p]] = min(lo[part_link[p]], pcomp[p])
            hi[part_link[p]] = max(hi[part_link[p]], pcomp[p])
    main = -1
    several = False
    for i in range(L):
        if has_geom[i]:
            if main < 0:
                main = comp[i]
            elif comp[i] != main:
                several = True
    return comp, pcomp, has_geom, has_piece, lo, hi, several


@numba.njit(cache=True)
def _root(parent, x):
    while parent[x] != x:
        parent[x] = parent[parent[x]]
        x = parent[x]
    return x


@numba.njit(cache=True)
def _union(parent, i, j):
    """Join the components of i and j under the smaller root (roots stay minima)."""
    ri, rj = _root(parent, i), _root(parent, j)
    if ri != rj:
        parent[max(ri, rj)] = min(ri, rj)


@numba.njit(cache=True)
def _rotation(axis, q, slide, out):
    """``out[:] =`` :func:`artipg.validate.kinematics.motion` of one joint value."""
    v = 0.0 if slide else q
    c, sn = math.cos(v), math.sin(v)
    a4 = (axis[0], axis[1], axis[2], 0.0)
    for i in range(3):
        for k in range(3):
            out[i, k] = (axis[i] * axis[k]) * (1.0 - c) + a4[_SKEW[i, k]] * _SKEW_SIGN[i, k] * sn
        out[i, i] += c
        out[i, 3] = (q if slide else 0.0) * axis[i]
        out[3, i] = 0.0
    out[3, 3] = 1.0


@numba.njit(cache=True)
def poses_batch(parent, origin, jtype, axis, Q):
    """:meth:`artipg.validate.kinematics.Kinematics.poses_batch`: link poses (S, L, 4, 4)
    for joint values ``Q`` (S, L)."""
    S, L = Q.shape
    T = np.empty((S, L, 4, 4))
    M = np.empty((4, 4))
    tmp = np.empty((4, 4))
    for s in range(S):
        set_identity(T[s, 0])
    for i in range(1, L):
        moves = False
        if jtype[i] != 0:
            for s in range(S):
                if Q[s, i] != 0.0:
                    moves = True
        for s in range(S):
            matmul4(T[s, parent[i]], origin[i], T[s, i])
            if moves:
                _rotation(axis[i], Q[s, i], jtype[i] == 2, M)
                copy4(T[s, i], tmp)
                matmul4(tmp, M, T[s, i])
    return T


@numba.njit(cache=True)
def blocked_rows(parent, origin, jtype, axis, Q, desc, link, T, center, half, pj, pk, pS, pad):
    """The pairs of :func:`artipg.validate.checks._needs_open`: for each (moving joint
    ``pj``, blocking joint ``pk``) link pair and its ``pS`` rows of ``Q``, the pieces
    only the first moves against those only the second moves, where their boxes
    overlap; ``(a, b, Wa, Wb, owner)`` in the numpy code's order. The rows of a pair
    differ in the moving joint's value only, and it does not ride on the blocking
    joint (nor this on it), as in ``_needs_open``."""
    P = poses_batch(parent, origin, jtype, axis, Q)
    M = len(link)
    n = 0
    A = np.empty(16, dtype=np.int64)
    B = np.empty(16, dtype=np.int64)
    own = np.empty(16, dtype=np.int64)
    WA = np.empty((16, 4, 4))
    WB = np.empty((16, 4, 4))
    rows = 0
    for p in range(len(pj)):
        S = pS[p]
        na = 0
        nb = 0
        for m in range(M):
            sj, sk = desc[pj[p], link[m]], desc[pk[p], link[m]]
            na += sj and not sk
            nb += sk and not sj
        both = np.empty(na + nb, dtype=np.int64)
        ia = 0
        ib = na
        for m in range(M):
            sj, sk = desc[pj[p], link[m]], desc[pk[p], link[m]]
            if sj and not sk:
                both[ia] = m
                ia += 1
            elif sk and not sj:
                both[ib] = m
                ib += 1
        W = np.empty((S, na + nb, 4, 4))
        c = np.empty((S, na + nb, 3))
        h = np.empty((S, na + nb, 3))
        for s in range(S):
            # the pieces only k moves sit at the same pose in every row of the pair
            # (its joint value is the same in all, the moving joint is not above them):
            # the same products give the same bits, computed once
            for x in range(na + nb if s == 0 else na):
                m = both[x]
                matmul4(P[rows + s, link[m]], T[m], W[s, x])
                for i in range(3):
                    c[s, x, i] = (W[s, x, i, 0] * center[m, 0] + W[s, x, i, 1] * center[m, 1]
                                  + W[s, x, i, 2] * center[m, 2] + W[s, x, i, 3])
                    h[s, x, i] = (abs(W[s, x, i, 0]) * half[m, 0] + abs(W[s, x, i, 1]) * half[m, 1]
                                  + abs(W[s, x, i, 2]) * half[m, 2])
        for s in range(S):
            for x in range(na):
                for y in range(na, na + nb):
                    if not _overlap(c[s, x], h[s, x], c[0, y], h[0, y], pad):
                        continue
                    if n == len(A):
                        A, B, own = grow(A), grow(B), grow(own)
                        WA, WB = _grow_frames(WA), _grow_frames(WB)
                    A[n], B[n], own[n] = both[x], both[y], p
                    copy4(W[s, x], WA[n])
                    copy4(W[0, y], WB[n])
                    n += 1
        rows += S
    return A[:n].copy(), B[:n].copy(), WA[:n].copy(), WB[:n].copy(), own[:n].copy()


@numba.njit(cache=True)
def blocked_table(bad, sw_scene, sw_joint, sw_q, sw_b, movable, link, parent, not_fixed, jtype, limits, desc):
    """:func:`artipg.validate.checks._blockers` and the joint values of
    :func:`artipg.validate.checks._needs_open` for the colliding sweep rows ``bad``.

    Returns ``(row_pair, pj, pk, Q, pS)``: the index of each bad row's (moving joint,
    blocking joint) pair, -1 when it has no blocker; the pairs' link indices in order
    of first occurrence; their joint values (S, L) (the moving joint's sweep values,
    ``sw_q`` of its scenes, the blocking joint at the upper end of its range, as
    :meth:`artipg.validate.kinematics.Kinematics.open_values` at 1.0) and the rows
    of each pair."""
    L = len(parent)
    n = len(bad)
    blocker = np.full((L, L), -2, dtype=np.int64)  # (moving joint, link): not yet known
    pair_of = np.full((L, L), -1, dtype=np.int64)
    row_pair = np.full(n, -1, dtype=np.int64)
    pj = np.empty(n, dtype=np.int64)
    pk = np.empty(n, dtype=np.int64)
    P = 0
    for r in range(n):
        s = bad[r]
        j = movable[sw_joint[sw_scene[s]]]
        lb = link[sw_b[s]]
        k = blocker[j, lb]
        if k == -2:  # checks._blocker: the movable joint closest to the root j does not ride on
            k = -1
            x = lb
            while x > 0:
                if not_fixed[x] and not desc[x, j]:
                    k = x
                x = parent[x]
            blocker[j, lb] = k
        if k > 0:
            if pair_of[j, k] < 0:
                pair_of[j, k] = P
                pj[P], pk[P] = j, k
                P += 1
            row_pair[r] = pair_of[j, k]
    # the scenes of each movable joint are consecutive in the sweep table
    first = np.zeros(L, dtype=np.int64)
    count = np.zeros(L, dtype=np.int64)
    for s in range(len(sw_joint) - 1, -1, -1):
        i = movable[sw_joint[s]]
        first[i] = s
        count[i] += 1
    pS = np.empty(P, dtype=np.int64)
    for p in range(P):
        pS[p] = count[pj[p]]
    Q = np.zeros((pS.sum(), L))
    row = 0
    for p in range(P):
        j, k = pj[p], pk[p]
        up = 1.0 * np.pi if jtype[k] == 3 else limits[k, 0] + 1.0 * (limits[k, 1] - limits[k, 0])
        for s in range(pS[p]):
            Q[row + s, j] = sw_q[first[j] + s]
            Q[row + s, k] = up
        row += pS[p]
    return row_pair, pj[:P].copy(), pk[:P].copy(), Q, pS


@numba.njit(cache=True)
def needs_open_rows(bad, sw_scene, sw_joint, sw_q, sw_b, movable, parent, not_fixed, jtype, limits, origin, axis,
                    desc, link, T, center, half, pad):
    """:func:`blocked_table` and :func:`blocked_rows` in one call: ``(row_pair, pj,
    pk, a, b, Wa, Wb, owner)``."""
    row_pair, pj, pk, Q, pS = blocked_table(bad, sw_scene, sw_joint, sw_q, sw_b, movable, link, parent, not_fixed,
                                            jtype, limits, desc)
    A, B, WA, WB, owner = blocked_rows(parent, origin, jtype, axis, Q, desc, link, T, center, half, pj, pk, pS, pad)
    return row_pair, pj, pk, A, B, WA, WB, owner


@numba.njit(cache=True)
def _grow_frames(x):
    y = np.empty((2 * len(x), 4, 4))
    for i in range(len(x)):
        copy4(x[i], y[i])
    return y
