"""Distance queries between pieces: bounding-box culling and batched SDF jobs.

A *job* ``(src, tgt, rel)`` asks for the minimum, over the surface samples of piece
``src``, of the signed distance to piece ``tgt``, where ``rel`` (4, 4) maps ``src``'s
frame into ``tgt``'s frame. Negative minima are penetrations (depth = -minimum),
small positive ones are gaps. All jobs of a validation run are evaluated in one
vectorised pass, whatever scene (joint state) they come from.
"""

from __future__ import annotations

import numpy as np

from artipg.validate.kinematics import rigid_inverse
from artipg.validate.shapes import Pieces


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
    """Boolean (A, B): boxes a and b overlap by more than ``-pad`` on every axis
    (``pad`` > 0 also accepts boxes up to ``pad`` apart; < 0 demands real overlap)."""
    d = np.abs(ca[:, None, :] - cb[None, :, :]) - (ha[:, None, :] + hb[None, :, :])
    return (d < pad).all(axis=2)


def evaluate(pieces: Pieces, src: np.ndarray, tgt: np.ndarray, rel: np.ndarray, margin) -> np.ndarray:
    """Minimum signed distance (K,) of each job (see module docstring).

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
    counts = pieces.counts[src]
    total = int(counts.sum())
    job = np.repeat(np.arange(K), counts)
    first = np.cumsum(counts) - counts
    idx = np.arange(total) - first[job] + pieces.offsets[src][job]
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


def deepest_point(pieces: Pieces, src: int, tgt: int, rel: np.ndarray, src_world: np.ndarray):
    """The sample of ``src`` with the lowest signed distance to ``tgt``: (point (3,) in
    the world frame given by ``src_world`` (4, 4), signed distance)."""
    X = pieces.points[pieces.offsets[src]:pieces.offsets[src + 1]]
    Y = X @ rel[:3, :3].T + rel[:3, 3]
    d = pieces.sdf(np.full(len(X), tgt), Y)
    i = int(np.argmin(d))
    return X[i] @ src_world[:3, :3].T + src_world[:3, 3], float(d[i])


def pair_jobs(Wa: np.ndarray, Wb: np.ndarray):
    """Relative transforms of both directions for piece pairs posed at ``Wa``, ``Wb``
    (K, 4, 4): a -> b and b -> a."""
    return rigid_inverse(Wb) @ Wa, rigid_inverse(Wa) @ Wb
