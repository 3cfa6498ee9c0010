"""Signed distances between posed pieces: exact for box pairs, sampled otherwise.

``pair_distance(pieces, a, b, Wa, Wb, margin)`` gives, for every pair of pieces posed
in the world, a signed separation in metres: negative values are penetration depths
(minus), positive values gaps. Two paths, both vectorised over all pairs at once:

- box-box pairs: the separating-axis test over the 15 axes of two oriented boxes;
  its smallest overlap is the exact penetration depth (the minimum translation
  that separates them). Separated pairs within ``margin`` get their exact distance
  from vertex-box signed distances and edge-edge segment distances.
- other pairs: the surface samples of each piece are moved into the other's frame
  and its exact SDF is evaluated (both directions); the minimum is the result. Only
  samples inside the target's bounding box (plus ``margin``) are evaluated exactly,
  so results above ``margin`` are lower bounds.
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
    R = W[:, :3, :3]
    c = np.einsum("kij,kj->ki", R, pieces.center[rows]) + W[:, :3, 3]
    h = np.einsum("kij,kj->ki", np.abs(R), pieces.half[rows])
    return c, h


def overlapping(ca, ha, cb, hb, pad: float) -> np.ndarray:
    """Boolean (A, B): boxes a and b are closer than ``pad`` on every axis (``pad`` > 0
    accepts boxes up to ``pad`` apart; ``pad`` < 0 demands an overlap of ``-pad``)."""
    d = np.abs(ca[:, None, :] - cb[None, :, :]) - (ha[:, None, :] + hb[None, :, :])
    return (d < pad).all(axis=2)


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
        Gaps up to ``margin`` are exact; larger results may be lower bounds (metres).

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
    i = np.flatnonzero(~box)
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
    A = Wa[:, :3, :3]  # columns: box axes in the world
    B = Wb[:, :3, :3]
    t = Wb[:, :3, 3] - Wa[:, :3, 3]
    Ac, Bc = A.transpose(0, 2, 1), B.transpose(0, 2, 1)  # rows: box axes
    cross = np.cross(Ac[:, :, None, :], Bc[:, None, :, :]).reshape(-1, 9, 3)
    axes = np.concatenate([Ac, Bc, cross], axis=1)  # (K, 15, 3)
    n = np.linalg.norm(axes, axis=2)
    ok = n > 1e-9
    axes = axes / np.where(ok, n, 1.0)[..., None]
    ra = np.abs(np.einsum("kmj,kji->kmi", axes, A)) @ ha[..., None]  # (K, 15, 1)
    rb = np.abs(np.einsum("kmj,kji->kmi", axes, B)) @ hb[..., None]
    dist = np.abs(np.einsum("kmj,kj->km", axes, t))
    over = ra[..., 0] + rb[..., 0] - dist  # overlap along each axis (negative: separated)
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
    rel_ab = rigid_inverse(Wb) @ Wa
    rel_ba = rigid_inverse(Wa) @ Wb
    va = _CORNERS[None] * 2 * ha[:, None]  # (K, 8, 3) corners of a in a's frame
    vb = _CORNERS[None] * 2 * hb[:, None]
    va_b = np.einsum("kij,kvj->kvi", rel_ab[:, :3, :3], va) + rel_ab[:, None, :3, 3]
    vb_a = np.einsum("kij,kvj->kvi", rel_ba[:, :3, :3], vb) + rel_ba[:, None, :3, 3]
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
        Exact signed distances are computed only for samples within ``margin`` of the
        target's bounding box; a result above ``margin`` is a lower bound (metres).

    Returns
    -------
    (K,) float64
    """
    K = len(src)
    if K == 0:
        return np.zeros(0)
    pieces.require(src)
    counts = pieces.count[src]
    total = int(counts.sum())
    job = np.repeat(np.arange(K), counts)
    first = np.cumsum(counts) - counts
    idx = np.arange(total) - first[job] + pieces.start[src][job]
    X = pieces.points[idx]
    Rf = rel[:, :3, :].reshape(K, 12)[job]  # (n, 12) rows of the 3x4 transform
    x, y, z = X[:, 0], X[:, 1], X[:, 2]
    Y = np.empty_like(X)
    Y[:, 0] = Rf[:, 0] * x + Rf[:, 1] * y + Rf[:, 2] * z + Rf[:, 3]
    Y[:, 1] = Rf[:, 4] * x + Rf[:, 5] * y + Rf[:, 6] * z + Rf[:, 7]
    Y[:, 2] = Rf[:, 8] * x + Rf[:, 9] * y + Rf[:, 10] * z + Rf[:, 11]
    trow = tgt[job]
    q = np.abs(Y - pieces.center[trow]) - pieces.half[trow]
    d = np.sqrt((np.maximum(q, 0.0) ** 2).sum(axis=1))  # distance to the box: a lower bound
    m = np.asarray(margin, dtype=float)
    near = np.flatnonzero(d <= (m[job] if m.ndim else m))
    if len(near):
        d[near] = pieces.sdf(trow[near], Y[near])
    return np.minimum.reduceat(d, first)


def refine_distance(pieces: Pieces, a: np.ndarray, b: np.ndarray, Wa: np.ndarray, Wb: np.ndarray,
                    starts: int = 3, iters: int = 10, stop_below: float = 0.0) -> np.ndarray:
    """Upper bounds (K,) of the distance between pieces ``a`` and ``b`` posed at ``Wa``,
    ``Wb`` (K, 4, 4), for pairs whose surface samples miss the closest points (a ball
    on a plane touches it in one point).

    From the ``starts`` samples of each piece nearest the other, alternately projects
    onto the other piece's surface and back (Newton steps along the exact SDF's
    gradient); every point reached on one surface bounds the distance by its signed
    distance to the other. Converges to the distance for convex pieces. Vectorised
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
    for _ in range(iters):
        q = _project(pieces, tgt[j], Wt[j], p)
        p = _project(pieces, src[j], Ws[j], q)
        before = np.minimum(best[:K], best[K:])
        np.minimum.at(best, j, _sdf_world(pieces, tgt[j], Wt[j], p))
        now = np.minimum(best[:K], best[K:])
        if (now <= stop_below).all() or (before - now).max() < 1e-6:
            break
    return np.minimum(best[:K], best[K:])


def _to_world(X, W):
    return np.einsum("nij,nj->ni", W[:, :3, :3], X) + W[:, :3, 3]


def _sdf_world(pieces, rows, W, X):
    """Signed distance of world points ``X`` (n, 3) to pieces ``rows`` posed at ``W`` (n, 4, 4)."""
    R = W[:, :3, :3]
    L = np.einsum("nji,nj->ni", R, X - W[:, :3, 3])
    return pieces.sdf(rows, L)


def _project(pieces, rows, W, X, h: float = 1e-6):
    """World points ``X`` (n, 3) moved onto the surfaces of pieces ``rows`` (one Newton
    step along the central-difference gradient of the exact SDF)."""
    R = W[:, :3, :3]
    L = np.einsum("nji,nj->ni", R, X - W[:, :3, 3])
    n = len(L)
    offs = np.concatenate([np.eye(3), -np.eye(3)]) * h
    Y = np.concatenate([L, (L[:, None, :] + offs[None]).reshape(-1, 3)])
    d = pieces.sdf(np.concatenate([rows, np.repeat(rows, 6)]), Y)
    d0, dd = d[:n], d[n:].reshape(n, 6)
    g = (dd[:, :3] - dd[:, 3:]) / (2 * h)
    g /= np.maximum(np.linalg.norm(g, axis=1, keepdims=True), 1e-12)
    return _to_world(L - d0[:, None] * g, W)


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
