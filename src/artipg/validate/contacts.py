"""Signed distances between posed pieces: exact for box pairs, sampled otherwise.

``pair_distance(pieces, a, b, Wa, Wb, margin)`` gives, for every pair of pieces posed
in the world, a signed separation in metres: negative values are penetration depths
(minus), positive values gaps. Two paths, both vectorised over all pairs at once:

- box-box pairs: the separating-axis test over the 15 axes of two oriented boxes;
  its smallest overlap is the exact penetration depth (the minimum translation
  that separates them). Separated pairs within ``margin`` get their exact distance
  from vertex-box signed distances and edge-edge segment distances.
- ball-ball pairs (whole spheres): centre distance minus the radii, exact.
- other pairs: the surface samples of each piece are moved into the other's frame
  and its exact SDF is evaluated (both directions); the minimum is the result. Only
  samples inside the target's bounding box (plus ``margin``) are evaluated exactly,
  so a result above ``margin`` only says that the pair is farther apart than that.
"""

from __future__ import annotations

import numpy as np

from artipg.validate.kinematics import rigid_inverse
from artipg.validate.rowsdf import cuboid_rows
from artipg.validate.shapes import Pieces

_CORNERS = np.array([[a, b, c] for a in (-0.5, 0.5) for b in (-0.5, 0.5) for c in (-0.5, 0.5)])
# the 12 edges of the unit box as (start corner, end corner) indices into _CORNERS
_EDGES = np.array([(i, j) for i in range(8) for j in range(i + 1, 8)
                   if np.count_nonzero(_CORNERS[i] != _CORNERS[j]) == 1])


def world_boxes(pieces: Pieces, W: np.ndarray, rows: np.ndarray | None = None):
    """World bounding boxes of pieces posed by ``W`` (K, 4, 4).

    ``rows`` (K,) gives the piece of each pose (default: all pieces in order).
    Returns centres and half extents, both (K, 3).
    """
    rows = np.arange(pieces.n) if rows is None else rows
    return transform_boxes(W, pieces.center[rows], pieces.half[rows])


def transform_boxes(W: np.ndarray, c: np.ndarray, h: np.ndarray):
    """Axis-aligned boxes (centres, half extents: (K, 3)) of the local boxes ``c``, ``h``
    (K, 3) posed by ``W`` (K, 4, 4)."""
    R = W[:, :3, :3]
    A = np.abs(R)
    out = R[:, :, 0] * c[:, 0, None] + R[:, :, 1] * c[:, 1, None] + R[:, :, 2] * c[:, 2, None] + W[:, :3, 3]
    return out, A[:, :, 0] * h[:, 0, None] + A[:, :, 1] * h[:, 1, None] + A[:, :, 2] * h[:, 2, None]


def overlapping(ca, ha, cb, hb, pad: float) -> np.ndarray:
    """Boolean (A, B): boxes a and b are closer than ``pad`` on every axis (``pad`` > 0
    accepts boxes up to ``pad`` apart; ``pad`` < 0 demands an overlap of ``-pad``)."""
    d = np.abs(ca[:, None, :] - cb[None, :, :]) - (ha[:, None, :] + hb[None, :, :])
    return (d < pad).all(axis=2)


def close_pairs(c: np.ndarray, h: np.ndarray, pad: float) -> tuple[np.ndarray, np.ndarray]:
    """All pairs ``a < b`` of boxes (centres ``c``, half extents ``h``: (M, 3)) closer
    than ``pad`` on every axis (see :func:`overlapping`), in ``np.triu_indices`` order.

    Sweep and prune: boxes sorted by their lower x bound, each is paired only with
    those that start before it ends; the exact test of :func:`overlapping` is then
    applied to these candidates.
    """
    M = len(c)
    lo = c[:, 0] - h[:, 0]
    order = np.argsort(lo, kind="stable")
    end = np.searchsorted(lo[order], (c[:, 0] + h[:, 0])[order] + (pad + 1e-9), side="right")
    n = np.maximum(end - np.arange(1, M + 1), 0)
    total = int(n.sum())
    if not total:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    i = np.repeat(np.arange(M), n)
    j = np.arange(total) - np.repeat(np.cumsum(n) - n - 1, n) + i
    u, v = order[i], order[j]
    a, b = np.minimum(u, v), np.maximum(u, v)
    ok = (np.abs(c[a] - c[b]) - (h[a] + h[b]) < pad).all(axis=1)
    a, b = a[ok], b[ok]
    key = np.argsort(a * M + b)
    return a[key], b[key]


def pair_distance(pieces: Pieces, a: np.ndarray, b: np.ndarray, Wa: np.ndarray, Wb: np.ndarray,
                  margin) -> np.ndarray:
    """Signed separation (K,) of pieces ``a`` and ``b`` posed at ``Wa``, ``Wb`` (K, 4, 4).

    Parameters
    ----------
    pieces : Pieces
    a, b : (K,) int64
        Piece indices.
    Wa, Wb : (K, 4, 4) float64
        Piece frames in the world (object) frame.
    margin : float or (K,) float64
        Gaps up to ``margin`` are exact; a larger result only says that the pair is
        farther apart than ``margin`` (a lower bound, or inf) (metres).

    Returns
    -------
    (K,) float64
        Negative: minus the penetration depth; positive: the gap (metres).
    """
    K = len(a)
    out = np.empty(K)
    if K == 0:
        return out
    margin = np.broadcast_to(np.asarray(margin, dtype=float), (K,))
    box = pieces.is_box[a] & pieces.is_box[b]
    i = np.flatnonzero(box)
    if len(i):
        out[i] = box_box(pieces.params[a[i], :3] / 2, pieces.params[b[i], :3] / 2, Wa[i], Wb[i], margin[i])
    ball = pieces.is_ball[a] & pieces.is_ball[b]
    i = np.flatnonzero(ball)
    if len(i):  # exact: centre distance minus the radii
        gap = Wa[i, :3, 3] - Wb[i, :3, 3]
        out[i] = np.sqrt((gap * gap).sum(axis=1)) - pieces.params[a[i], 0] - pieces.params[b[i], 0]
    i = np.flatnonzero(~box & ~ball)
    if len(i):
        rel_ab = rigid_inverse(Wb[i]) @ Wa[i]
        rel_ba = rigid_inverse(Wa[i]) @ Wb[i]
        d = evaluate(pieces, np.concatenate([a[i], b[i]]), np.concatenate([b[i], a[i]]),
                     np.concatenate([rel_ab, rel_ba]), np.concatenate([margin[i], margin[i]]))
        out[i] = np.minimum(d[:len(i)], d[len(i):])
    return out


def box_box(ha: np.ndarray, hb: np.ndarray, Wa: np.ndarray, Wb: np.ndarray, margin: np.ndarray) -> np.ndarray:
    """Signed separation of oriented boxes with half extents ``ha``, ``hb`` (K, 3) at
    poses ``Wa``, ``Wb`` (K, 4, 4): minus the exact penetration depth when they
    overlap; when apart by at most ``margin`` (K,), the exact distance or, if it
    is already known to be within ``margin``, an upper bound that is; otherwise the
    separating-axis gap (a lower bound of the distance)."""
    K = len(ha)
    A = Wa[:, :3, :3]  # columns: box axes in the world
    B = Wb[:, :3, :3]
    t = Wb[:, :3, 3] - Wa[:, :3, 3]
    # everything in a's frame: R = A^T B (columns: b's axes), T = A^T t
    R = A[:, 0, :, None] * B[:, 0, None, :] + A[:, 1, :, None] * B[:, 1, None, :] + A[:, 2, :, None] * B[:, 2, None, :]
    T = A[:, 0] * t[:, 0, None] + A[:, 1] * t[:, 1, None] + A[:, 2] * t[:, 2, None]
    # the 15 candidate axes (a's, b's, a_i x b_j), unnormalised, in a's frame
    axes = np.zeros((K, 15, 3))
    axes[:, 0, 0] = axes[:, 1, 1] = axes[:, 2, 2] = 1.0
    axes[:, 3:6] = R.transpose(0, 2, 1)
    vx, vy, vz = R[:, 0], R[:, 1], R[:, 2]  # (K, 3): components of b_j
    axes[:, 6:9, 1], axes[:, 6:9, 2] = -vz, vy     # a_0 x b_j
    axes[:, 9:12, 0], axes[:, 9:12, 2] = vz, -vx   # a_1 x b_j
    axes[:, 12:15, 0], axes[:, 12:15, 1] = -vy, vx  # a_2 x b_j
    n = np.sqrt((axes * axes).sum(axis=2))
    ok = n > 1e-9
    ra = (np.abs(axes) * ha[:, None, :]).sum(axis=2)
    P = axes[..., 0, None] * R[:, None, 0] + axes[..., 1, None] * R[:, None, 1] + axes[..., 2, None] * R[:, None, 2]
    rb = (np.abs(P) * hb[:, None, :]).sum(axis=2)
    dist = np.abs((axes * T[:, None, :]).sum(axis=2))
    over = (ra + rb - dist) / np.where(ok, n, 1.0)  # overlap along each axis (negative: separated)
    over = np.where(ok, over, np.inf)
    depth = over.min(axis=1)
    out = -depth
    sep = depth < 0
    near = np.flatnonzero(sep & (-depth <= margin))
    if len(near):
        m = margin[near]
        out[near] = box_distance(ha[near], hb[near], Wa[near], Wb[near], np.where(np.isfinite(m), m, -1.0))
    return out


def box_distance(ha, hb, Wa, Wb, edge_margin=None) -> np.ndarray:
    """Exact distance (K,) between disjoint oriented boxes (vertex-face and edge-edge).

    With ``edge_margin`` (K,), pairs whose vertex-face distance is already within it
    skip the edge-edge part: their result is that upper bound (still <= the margin).
    """
    Ra, Rb = Wa[:, :3, :3], Wb[:, :3, :3]
    d = Wa[:, :3, 3] - Wb[:, :3, 3]
    # a's frame in b's: R = Rb^T Ra, t = Rb^T (ta - tb); b's frame in a's: R^T, -R^T t
    R = (Rb[:, 0, :, None] * Ra[:, 0, None, :] + Rb[:, 1, :, None] * Ra[:, 1, None, :]
         + Rb[:, 2, :, None] * Ra[:, 2, None, :])
    t = Rb[:, 0] * d[:, 0, None] + Rb[:, 1] * d[:, 1, None] + Rb[:, 2] * d[:, 2, None]
    u = -(R[:, 0] * t[:, 0, None] + R[:, 1] * t[:, 1, None] + R[:, 2] * t[:, 2, None])
    va = _CORNERS[None] * 2 * ha[:, None]  # (K, 8, 3) corners of a in a's frame
    vb = _CORNERS[None] * 2 * hb[:, None]
    va_b = (R[:, None, :, 0] * va[..., 0, None] + R[:, None, :, 1] * va[..., 1, None]
            + R[:, None, :, 2] * va[..., 2, None] + t[:, None, :])
    vb_a = (R[:, None, 0, :] * vb[..., 0, None] + R[:, None, 1, :] * vb[..., 1, None]
            + R[:, None, 2, :] * vb[..., 2, None] + u[:, None, :])
    K = len(ha)
    d1 = cuboid_rows(np.repeat(2 * hb, 8, axis=0), va_b.reshape(-1, 3)).reshape(K, 8).min(axis=1)
    d2 = cuboid_rows(np.repeat(2 * ha, 8, axis=0), vb_a.reshape(-1, 3)).reshape(K, 8).min(axis=1)
    out = np.minimum(d1, d2)
    if edge_margin is not None:  # edges matter only where the vertex bound is not yet enough
        need = np.flatnonzero(out > edge_margin)
    else:
        need = np.arange(K)
    if len(need):
        # edges of both boxes in b's frame
        p0, p1 = va_b[need][:, _EDGES[:, 0]], va_b[need][:, _EDGES[:, 1]]  # (k, 12, 3)
        q0, q1 = vb[need][:, _EDGES[:, 0]], vb[need][:, _EDGES[:, 1]]
        d3 = segment_distance(p0[:, :, None], p1[:, :, None], q0[:, None], q1[:, None]).reshape(len(need), -1)
        out[need] = np.minimum(out[need], d3.min(axis=1))
    return out


def segment_distance(p0, p1, q0, q1) -> np.ndarray:
    """Distance between segments [p0, p1] and [q0, q1] (broadcast arrays (..., 3))."""
    d1, d2, r = p1 - p0, q1 - q0, p0 - q0
    a = (d1 * d1).sum(-1)
    e = (d2 * d2).sum(-1)
    b = (d1 * d2).sum(-1)
    c = (d1 * r).sum(-1)
    f = (d2 * r).sum(-1)
    den = a * e - b * b
    s = np.where(den > 1e-18, np.clip((b * f - c * e) / np.where(den > 1e-18, den, 1.0), 0.0, 1.0), 0.0)
    t = (b * s + f) / np.maximum(e, 1e-18)
    s = np.where(t < 0, np.clip(-c / np.maximum(a, 1e-18), 0, 1), np.where(t > 1, np.clip((b - c) / np.maximum(a, 1e-18), 0, 1), s))
    t = np.clip(t, 0.0, 1.0)
    diff = p0 + s[..., None] * d1 - q0 - t[..., None] * d2
    return np.sqrt((diff * diff).sum(-1))


def evaluate(pieces: Pieces, src: np.ndarray, tgt: np.ndarray, rel: np.ndarray, margin) -> np.ndarray:
    """Minimum over the samples of ``src`` of the signed distance to ``tgt``, per job.

    Parameters
    ----------
    pieces : Pieces
    src, tgt : (K,) int64
        Source and target piece of each job.
    rel : (K, 4, 4) float64
        Source frame -> target frame.
    margin : float or (K,) float64
        Only samples within ``margin`` of the target's bounding box are evaluated
        (exactly); a result above ``margin`` is only known to be above it: a lower
        bound of the sampled minimum, or ``inf`` when no sample comes that close
        (metres).

    Returns
    -------
    (K,) float64
    """
    K = len(src)
    out = np.full(K, np.inf)
    if K == 0:
        return out
    pieces.require(src)  # every source, so that the sample stream does not depend on culling
    m = np.broadcast_to(np.asarray(margin, dtype=float), (K,))
    # jobs whose source box, posed in the target frame, stays farther than the margin
    # from the target box on some axis have no sample within the margin
    c, e = transform_boxes(rel, pieces.center[src], pieces.half[src])
    ct, ht = pieces.center[tgt], pieces.half[tgt]
    keep = np.flatnonzero((np.abs(c - ct) - e - ht <= m[:, None]).all(axis=1))
    if not len(keep):
        return out
    counts = pieces.count[src[keep]]
    k = len(keep)
    first = np.cumsum(counts) - counts
    total = int(counts.sum())
    idx = np.arange(total) + np.repeat(pieces.start[src[keep]] - first, counts)
    X = pieces.points[idx]
    Rf = np.repeat(rel[keep, :3, :].reshape(k, 12), counts, axis=0)  # rows of the 3x4 transforms
    x, y, z = X[:, 0], X[:, 1], X[:, 2]
    Y = np.empty_like(X)
    Y[:, 0] = Rf[:, 0] * x + Rf[:, 1] * y + Rf[:, 2] * z + Rf[:, 3]
    Y[:, 1] = Rf[:, 4] * x + Rf[:, 5] * y + Rf[:, 6] * z + Rf[:, 7]
    Y[:, 2] = Rf[:, 8] * x + Rf[:, 9] * y + Rf[:, 10] * z + Rf[:, 11]
    # samples farther than the margin from the target box on some axis are farther
    # than the margin from the target (the SDF is at least the box distance)
    q = np.abs(Y - np.repeat(ct[keep], counts, axis=0)) - np.repeat(ht[keep], counts, axis=0)
    near = np.flatnonzero((q <= np.repeat(m[keep], counts)[:, None]).all(axis=1))
    if not len(near):
        return out
    job = np.repeat(np.arange(k), counts)[near]
    d = pieces.sdf(tgt[keep][job], Y[near])
    cut = np.concatenate([[0], (job[1:] != job[:-1]).nonzero()[0] + 1])
    out[keep[job[cut]]] = np.minimum.reduceat(d, cut)
    return out


def refine_distance(pieces: Pieces, a: np.ndarray, b: np.ndarray, Wa: np.ndarray, Wb: np.ndarray,
                    starts: int = 3, iters: int = 10, stop_below: float = 0.0) -> np.ndarray:
    """Upper bounds (K,) of the distance between pieces ``a`` and ``b`` posed at ``Wa``,
    ``Wb`` (K, 4, 4), for pairs whose surface samples miss the closest points (a ball
    on a plane touches it in one point).

    From the ``starts`` samples of each piece nearest the other, alternately projects
    onto the other piece's surface and back (Newton steps along the exact SDF's
    gradient); every point reached on one surface bounds the distance by its signed
    distance to the other. A step can land off the surface (past an edge of a prism,
    a cap's rim): a point counts only when it lies on the source surface, within
    ``_ON_SURFACE`` of it by the source's SDF, and then bounds the distance by its
    signed distance to the target plus that offset; otherwise the bound it would give
    is dropped (a point on the target but off the source says nothing). Converges to
    the distance for convex pieces. Vectorised
    over all pairs and both directions; stops early once every pair is within
    ``stop_below`` or no bound improves by more than 1 µm.
    """
    K = len(a)
    if K == 0:
        return np.zeros(0)
    src = np.concatenate([a, b])
    tgt = np.concatenate([b, a])
    Ws = np.concatenate([Wa, Wb])
    Wt = np.concatenate([Wb, Wa])
    pieces.require(src)
    counts = pieces.count[src]
    job = np.repeat(np.arange(2 * K), counts)
    first = np.cumsum(counts) - counts
    idx = np.arange(int(counts.sum())) - first[job] + pieces.start[src][job]
    X = _to_world(pieces.points[idx], Ws[job])
    d = _sdf_world(pieces, tgt[job], Wt[job], X)
    order = np.lexsort((d, job))  # by job, nearest first
    rank = np.arange(len(order)) - first[job[order]]
    pick = order[rank < starts]
    p, j = X[pick], job[pick]
    best = np.full(2 * K, np.inf)
    np.minimum.at(best, j, d[pick])
    # each iteration: project onto the target, back onto the source, and bound by the
    # signed distance of that point to the target. The 7-point stencil of a point on
    # the target (its SDF and the gradient's) serves both the bound of one iteration
    # and the projection of the next, and the per-row SDF set-up is done once.
    n = len(j)
    sdf_t = pieces.prepare(np.concatenate([tgt[j], np.repeat(tgt[j], 6)]))
    sdf_s = pieces.prepare(np.concatenate([src[j], np.repeat(src[j], 6)]))
    on_s = pieces.prepare(src[j])
    Rt, tt = Wt[j][:, :3, :3], Wt[j][:, :3, 3]
    Rs, ts = Ws[j][:, :3, :3], Ws[j][:, :3, 3]
    Lt, dt = _stencil(sdf_t, Rt, tt, p, n)
    for _ in range(iters):
        q = _step(Lt, dt, Rt, tt, n)
        Ls, ds = _stencil(sdf_s, Rs, ts, q, n)
        p = _step(Ls, ds, Rs, ts, n)
        Lt, dt = _stencil(sdf_t, Rt, tt, p, n)
        off = np.abs(on_s(np.einsum("nji,nj->ni", Rs, p - ts)))  # p's offset from the source surface
        on = np.flatnonzero(off <= _ON_SURFACE)
        before = np.minimum(best[:K], best[K:])
        np.minimum.at(best, j[on], dt[on] + off[on])
        now = np.minimum(best[:K], best[K:])
        if (now <= stop_below).all() or (before - now).max() < 1e-6:
            break
    return np.minimum(best[:K], best[K:])


_H = 1e-6  # central-difference step of the SDF gradients (metres)
#: Largest |SDF| of the source piece (metres) at which a projected point of
#: :func:`refine_distance` counts as lying on the source surface.
_ON_SURFACE = 1e-5
_OFFS = np.concatenate([np.eye(3), -np.eye(3)]) * _H


def _stencil(sdf, R, t, X, n):
    """World points ``X`` (n, 3) in their pieces' frames (``R``, ``t``: (n, 3, 3), (n, 3))
    and the SDF at them and at their six central-difference neighbours, (7n,)."""
    L = np.einsum("nji,nj->ni", R, X - t)
    Y = np.concatenate([L, (L[:, None, :] + _OFFS[None]).reshape(-1, 3)])
    return L, sdf(Y)


def _step(L, d, R, t, n):
    """One Newton step onto the surface from the stencil of :func:`_stencil`, world frame."""
    d0, dd = d[:n], d[n:].reshape(n, 6)
    g = (dd[:, :3] - dd[:, 3:]) / (2 * _H)
    g /= np.maximum(np.linalg.norm(g, axis=1, keepdims=True), 1e-12)
    return np.einsum("nij,nj->ni", R, L - d0[:, None] * g) + t


def _to_world(X, W):
    return np.einsum("nij,nj->ni", W[:, :3, :3], X) + W[:, :3, 3]


def _sdf_world(pieces, rows, W, X):
    """Signed distance of world points ``X`` (n, 3) to pieces ``rows`` posed at ``W`` (n, 4, 4)."""
    R = W[:, :3, :3]
    L = np.einsum("nji,nj->ni", R, X - W[:, :3, 3])
    return pieces.sdf(rows, L)


def deepest_point(pieces: Pieces, a: int, b: int, Wa: np.ndarray, Wb: np.ndarray) -> np.ndarray:
    """World point (3,) of the samples of ``a`` and ``b`` lying deepest in the other piece."""
    best, where = np.inf, 0.5 * (Wa[:3, 3] + Wb[:3, 3])
    for s, t, Ws, Wt in ((a, b, Wa, Wb), (b, a, Wb, Wa)):
        X = pieces.samples(s)
        rel = rigid_inverse(Wt) @ Ws
        d = pieces.sdf(np.full(len(X), t), X @ rel[:3, :3].T + rel[:3, 3])
        i = int(np.argmin(d))
        if d[i] < best:
            best, where = d[i], X[i] @ Ws[:3, :3].T + Ws[:3, 3]
    return where
