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
  samples inside the target's bounding box (plus ``margin``) are evaluated exactly
  (for solids of revolution, also inside its radial extent plus ``margin``), so a
  result above ``margin`` only says that the pair is farther apart than that.

Box-box pairs whose rotations only permute and flip the world axes (most boxes of
furniture at rest and along prismatic joints) take a shortcut with the same
arithmetic: the overlap of their world-aligned boxes.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.box import _box_rows_sdf
from artipg.validate.kinematics import rigid_inverse
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
    ca, ha, cb, hb = (np.ascontiguousarray(x.T) for x in (ca, ha, cb, hb))  # one axis at a time: 2-D passes
    ok = np.abs(ca[0][:, None] - cb[0]) - (ha[0][:, None] + hb[0]) < pad
    ok &= np.abs(ca[1][:, None] - cb[1]) - (ha[1][:, None] + hb[1]) < pad
    ok &= np.abs(ca[2][:, None] - cb[2]) - (ha[2][:, None] + hb[2]) < pad
    return ok


#: Largest number of boxes for which :func:`close_pairs` tests all pairs directly.
_DENSE = 256


def close_pairs(c: np.ndarray, h: np.ndarray, pad: float, label: np.ndarray | None = None
                ) -> tuple[np.ndarray, np.ndarray]:
    """All pairs ``a < b`` of boxes (centres ``c``, half extents ``h``: (M, 3)) closer
    than ``pad`` on every axis (see :func:`overlapping`), in ``np.triu_indices`` order;
    with ``label`` (M,), only pairs of different labels.

    Up to ``_DENSE`` boxes, every pair is tested at once by :func:`overlapping` (three
    (M, M) passes are cheaper than sorting); beyond, sweep and prune: boxes sorted by
    their lower x bound, each is paired only with those that start before it ends, and
    the same test is applied to these candidates.
    """
    M = len(c)
    if M <= _DENSE:
        ok = overlapping(c, h, c, h, pad)
        if label is not None:
            ok &= label[:, None] != label
        a, b = ok.nonzero()
        upper = a < b
        return a[upper], b[upper]
    lo = c[:, 0] - h[:, 0]
    order = np.argsort(lo, kind="stable")
    end = np.searchsorted(lo[order], (c[:, 0] + h[:, 0])[order] + (pad + 1e-9), side="right")
    n = np.maximum(end - np.arange(1, M + 1), 0)
    total = int(n.sum())
    if not total:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    i = np.arange(M).repeat(n)
    j = np.arange(total) - (n.cumsum() - n - 1).repeat(n) + i
    u, v = order[i], order[j]
    a, b = np.minimum(u, v), np.maximum(u, v)
    ok = (np.abs(c[a] - c[b]) - (h[a] + h[b]) < pad).all(axis=1)
    if label is not None:
        ok &= label[a] != label[b]
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
    margin = _per_row(margin, K)
    box = pieces.is_box[a] & pieces.is_box[b]
    i = box.nonzero()[0]
    if len(i):
        out[i] = box_box(pieces.params[a[i], :3] / 2, pieces.params[b[i], :3] / 2, Wa[i], Wb[i], margin[i])
    ball = pieces.is_ball[a] & pieces.is_ball[b]
    i = ball.nonzero()[0]
    if len(i):  # exact: centre distance minus the radii
        gap = Wa[i, :3, 3] - Wb[i, :3, 3]
        out[i] = np.sqrt((gap * gap).sum(axis=1)) - pieces.params[a[i], 0] - pieces.params[b[i], 0]
    i = (~box & ~ball).nonzero()[0]
    if len(i):
        rel_ab = rigid_inverse(Wb[i]) @ Wa[i]
        rel_ba = rigid_inverse(Wa[i]) @ Wb[i]
        d = evaluate(pieces, np.concatenate([a[i], b[i]]), np.concatenate([b[i], a[i]]),
                     np.concatenate([rel_ab, rel_ba]), np.concatenate([margin[i], margin[i]]))
        out[i] = np.minimum(d[:len(i)], d[len(i):])
    return out


def _per_row(value, K: int) -> np.ndarray:
    """``value`` (a number or (K,)) as a float array (K,)."""
    value = np.asarray(value, dtype=float)
    return value if value.ndim else np.full(K, float(value))


def box_box(ha: np.ndarray, hb: np.ndarray, Wa: np.ndarray, Wb: np.ndarray, margin: np.ndarray) -> np.ndarray:
    """Signed separation of oriented boxes with half extents ``ha``, ``hb`` (K, 3) at
    poses ``Wa``, ``Wb`` (K, 4, 4): minus the exact penetration depth when they
    overlap; when apart by at most ``margin`` (K,), the exact distance or, if it
    is already known to be within ``margin``, an upper bound that is; otherwise the
    separating-axis gap (a lower bound of the distance)."""
    A = Wa[:, :3, :3]
    B = Wb[:, :3, :3]
    # boxes whose axes are world axes (rotations that only permute and flip them):
    # the separating axes are the world axes and the overlap along each is that of
    # the world-aligned boxes, which is the same arithmetic as the general test gives
    # for them (every product with a 0 or 1 is exact)
    aligned = ((A == 0.0) | (np.abs(A) == 1.0)).all(axis=(1, 2)) & ((B == 0.0) | (np.abs(B) == 1.0)).all(axis=(1, 2))
    if aligned.all():
        return _aligned_box_box(ha, hb, Wa, Wb, margin)
    if not aligned.any():
        return _sat_box_box(ha, hb, Wa, Wb, margin)
    out = np.empty(len(ha))
    i, g = aligned.nonzero()[0], (~aligned).nonzero()[0]
    out[i] = _aligned_box_box(ha[i], hb[i], Wa[i], Wb[i], margin[i])
    out[g] = _sat_box_box(ha[g], hb[g], Wa[g], Wb[g], margin[g])
    return out


def _sat_box_box(ha, hb, Wa, Wb, margin) -> np.ndarray:
    """:func:`box_box` by the separating-axis test over the 15 axes of two oriented boxes."""
    A = Wa[:, :3, :3]  # columns: box axes in the world
    B = Wb[:, :3, :3]
    t = Wb[:, :3, 3] - Wa[:, :3, 3]
    # everything in a's frame: R = A^T B (columns: b's axes), T = A^T t
    R = A[:, 0, :, None] * B[:, 0, None, :] + A[:, 1, :, None] * B[:, 1, None, :] + A[:, 2, :, None] * B[:, 2, None, :]
    T = A[:, 0] * t[:, 0, None] + A[:, 1] * t[:, 1, None] + A[:, 2] * t[:, 2, None]
    over = _sat_overlaps(ha, hb, R, T)
    depth = over.min(axis=1)
    out = -depth
    sep = depth < 0
    near = (sep & (-depth <= margin)).nonzero()[0]
    if len(near):
        m = margin[near]
        out[near] = box_distance(ha[near], hb[near], Wa[near], Wb[near], np.where(np.isfinite(m), m, -1.0))
    return out


def _sat_overlaps(ha, hb, R, T) -> np.ndarray:
    """Overlap (K, 15) of boxes ``ha``, ``hb`` (K, 3) along the 15 candidate separating
    axes (a's, b's, a_i x b_j; unnormalised, in a's frame, one coordinate per (K, 15)
    array), ``R``: b's axes as columns, ``T``: b's centre, both in a's frame; inf for
    degenerate axes."""
    K = len(ha)
    ax, ay, az = np.zeros((3, K, 15))
    ax[:, 0] = ay[:, 1] = az[:, 2] = 1.0
    ax[:, 3:6], ay[:, 3:6], az[:, 3:6] = R[:, 0], R[:, 1], R[:, 2]
    ay[:, 6:9], az[:, 6:9] = -R[:, 2], R[:, 1]      # a_0 x b_j
    ax[:, 9:12], az[:, 9:12] = R[:, 2], -R[:, 0]    # a_1 x b_j
    ax[:, 12:15], ay[:, 12:15] = -R[:, 1], R[:, 0]  # a_2 x b_j
    n = np.sqrt(ax * ax + ay * ay + az * az)
    ok = n > 1e-9
    ra = np.abs(ax) * ha[:, 0, None] + np.abs(ay) * ha[:, 1, None] + np.abs(az) * ha[:, 2, None]
    rb = [np.abs(ax * R[:, 0, c, None] + ay * R[:, 1, c, None] + az * R[:, 2, c, None]) * hb[:, c, None]
          for c in range(3)]
    dist = np.abs(ax * T[:, 0, None] + ay * T[:, 1, None] + az * T[:, 2, None])
    over = (ra + (rb[0] + rb[1] + rb[2]) - dist) / np.where(ok, n, 1.0)
    return np.where(ok, over, np.inf)


def _aligned_box_box(ha, hb, Wa, Wb, margin) -> np.ndarray:
    """:func:`box_box` of boxes whose rotations only permute and flip the world axes."""
    A, B = np.abs(Wa[:, :3, :3]), np.abs(Wb[:, :3, :3])
    ea = A[:, :, 0] * ha[:, 0, None] + A[:, :, 1] * ha[:, 1, None] + A[:, :, 2] * ha[:, 2, None]
    eb = B[:, :, 0] * hb[:, 0, None] + B[:, :, 1] * hb[:, 1, None] + B[:, :, 2] * hb[:, 2, None]
    out = (np.abs(Wa[:, :3, 3] - Wb[:, :3, 3]) - (ea + eb)).max(axis=1)  # minus the smallest overlap
    near = ((out > 0) & (out <= margin)).nonzero()[0]
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
    d1 = _box_sdf(2 * hb, va_b)
    d2 = _box_sdf(2 * ha, vb_a)
    out = np.minimum(d1, d2)
    if edge_margin is not None:  # edges matter only where the vertex bound is not yet enough
        need = (out > edge_margin).nonzero()[0]
    else:
        need = np.arange(K)
    if len(need):
        # edges of both boxes in b's frame
        p0, p1 = va_b[need][:, _EDGES[:, 0]], va_b[need][:, _EDGES[:, 1]]  # (k, 12, 3)
        q0, q1 = vb[need][:, _EDGES[:, 0]], vb[need][:, _EDGES[:, 1]]
        d3 = segment_distance(p0[:, :, None], p1[:, :, None], q0[:, None], q1[:, None]).reshape(len(need), -1)
        out[need] = np.minimum(out[need], d3.min(axis=1))
    return out


def _box_sdf(size: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Smallest signed distance (K,) of points ``x`` (K, V, 3) to centred boxes of
    extents ``size`` (K, 3): :meth:`artipg.geometry.Cuboid.sdf`'s formula with one box
    per row (its (3, 1, n) broadcast form)."""
    K, V = x.shape[:2]
    ax = np.abs(x.reshape(-1, 3).T)[:, None, :]  # (3, 1, K V)
    return _box_rows_sdf(ax, size.repeat(V, axis=0).T)[0].reshape(K, V).min(axis=1)


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
    m = _per_row(margin, K)
    # jobs whose source box, posed in the target frame, stays farther than the margin
    # from the target box on some axis have no sample within the margin
    c, e = transform_boxes(rel, pieces.center[src], pieces.half[src])
    ct, ht = pieces.center[tgt], pieces.half[tgt]
    keep = (np.abs(c - ct) - e - ht <= m[:, None]).all(axis=1).nonzero()[0]
    if not len(keep):
        return out
    # only the sources still in play: a template's samples are drawn all at once from
    # its own stream, so they do not depend on which of its pieces asked first
    s = src[keep]
    pieces.require(s)
    counts = pieces.count[s]
    job = np.arange(len(keep)).repeat(counts)  # index into keep of every sample
    first = counts.cumsum() - counts
    x, y, z = pieces.points_t.take(np.arange(len(job)) + (pieces.start[s] - first)[job], axis=1)
    # per sample, as contiguous rows: the 3 x 4 transform to the target frame, the
    # target's box (centre, half extents) and the margin
    G = np.concatenate([rel[keep, :3, :].reshape(len(keep), 12), ct[keep], ht[keep], m[keep, None]], axis=1)
    G = np.ascontiguousarray(G.T).take(job, axis=1)
    Y = np.empty((3, len(job)))
    near = np.ones(len(job), dtype=bool)
    for i in range(3):
        Y[i] = G[4 * i] * x + G[4 * i + 1] * y + G[4 * i + 2] * z + G[4 * i + 3]
        # samples farther than the margin from the target box on some axis are farther
        # than the margin from the target (the SDF is at least the box distance)
        near &= np.abs(Y[i] - G[12 + i]) - G[15 + i] <= G[18]
    near = near.nonzero()[0]
    if len(near) > _RADIAL_CULL:
        # solids of revolution: samples farther than the margin from the target's
        # radial extent are farther than the margin from it (see Pieces.radial)
        rad = pieces.radial[tgt[keep][job[near]]]
        mn = G[18].take(near) + 1e-9
        rho = np.hypot(Y[0].take(near), Y[1].take(near))
        near = near[(rho <= rad[:, 1] + mn) & (rho >= rad[:, 0] - mn)]
    if not len(near):
        return out
    job = job[near]
    d = pieces.sdf(tgt[keep][job], Y.take(near, axis=1).T)
    cut = np.concatenate([[0], (job[1:] != job[:-1]).nonzero()[0] + 1])
    out[keep[job[cut]]] = np.minimum.reduceat(d, cut)
    return out


#: Near samples above which :func:`evaluate` also culls by the radial extent of
#: solids of revolution before evaluating SDFs (below, the test costs more than it saves).
_RADIAL_CULL = 200


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
    job = np.arange(2 * K).repeat(counts)
    first = counts.cumsum() - counts
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
    # signed distance of that point to the target. At a point p on the source the
    # target's 7-point stencil (SDF and the gradient's) bounds the distance and projects
    # p on, and the source's SDF at p says how far off the source surface it lies; at
    # the point q reached on the target the source's stencil projects it back. Only
    # these values are evaluated (row-wise, so the same as in a full evaluation of both
    # stencils at every point); the per-row SDF set-up is done once.
    n = len(j)
    rt, rs = tgt[j], src[j]
    at_p = pieces.prepare(np.concatenate([rt, rt.repeat(6), rs]))
    at_q = pieces.prepare(np.concatenate([rs, rs.repeat(6)]))
    Rt, tt = Wt[j][:, :3, :3], Wt[j][:, :3, 3]
    Rs, ts = Ws[j][:, :3, :3], Ws[j][:, :3, 3]
    Lt, dt, _ = _target_stencil(at_p, Rt, tt, Rs, ts, p, n)
    for _ in range(iters):
        q = _step(Lt, dt, Rt, tt, n)
        Ls, ds = _stencil(at_q, Rs, ts, q)
        p = _step(Ls, ds, Rs, ts, n)
        Lt, dt, off = _target_stencil(at_p, Rt, tt, Rs, ts, p, n)
        off = np.abs(off)  # p's offset from the source surface
        on = (off <= _ON_SURFACE).nonzero()[0]
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


def _stencil(sdf, R, t, X):
    """World points ``X`` (n, 3) in the frames of their pieces (``R``, ``t``: (n, 3, 3),
    (n, 3)), and the SDF (7n,) of the pieces at them and at their six central-difference
    neighbours (``sdf``: prepared for the rows, then the rows six times each)."""
    L = np.einsum("nji,nj->ni", R, X - t)
    return L, sdf(np.concatenate([L, (L[:, None, :] + _OFFS[None]).reshape(-1, 3)]))


def _target_stencil(sdf, Rt, tt, Rs, ts, X, n):
    """:func:`_stencil` of the target pieces at world points ``X`` (n, 3) and the source
    pieces' SDF (n,) at them (``sdf``: prepared for the target rows seven times, then
    the source rows once): ``(Lt, dt, ds)``."""
    Lt = np.einsum("nji,nj->ni", Rt, X - tt)
    Ls = np.einsum("nji,nj->ni", Rs, X - ts)
    d = sdf(np.concatenate([Lt, (Lt[:, None, :] + _OFFS[None]).reshape(-1, 3), Ls]))
    return Lt, d[:7 * n], d[7 * n:]


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
