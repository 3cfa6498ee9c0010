"""Earth mover's distance between point clouds (exact assignment, or subsampled)."""

from __future__ import annotations

import numpy as np
from scipy.optimize import linear_sum_assignment
from scipy.spatial.distance import cdist


def earth_movers_distance(a: np.ndarray, b: np.ndarray, max_points: int = 1024, seed: int = 0) -> float:
    """EMD: mean Euclidean distance of the optimal one-to-one matching of two clouds.

    ``EMD(A, B) = min over bijections phi: A -> B of 1/n * sum_{x in A} ||x - phi(x)||_2``,
    solved exactly with :func:`scipy.optimize.linear_sum_assignment` on the (n, n)
    Euclidean cost matrix.

    Approximation for large or unequal clouds: when ``len(a) != len(b)`` or either
    exceeds ``max_points``, both clouds are replaced by uniform random subsets (without
    replacement, from ``numpy.random.default_rng(seed)``) of
    ``n = min(len(a), len(b), max_points)`` points and the exact EMD of the subsets is
    returned. For i.i.d. surface samples this is a consistent estimate that is biased
    upward for small ``n`` (matching fewer points leaves larger gaps), so compare EMDs
    only at equal ``n``. The exact solve costs O(n^3): about 1 s at n = 1024 and 9 s at
    n = 2048 per pair (one core of a busy 2-core machine).

    Parameters
    ----------
    a : (n_a, 3) float array
    b : (n_b, 3) float array
    max_points : int
        Largest matching solved exactly.
    seed : int
        Seed of the subsampling stream.

    Returns
    -------
    float
        In the units of the points; 0 for identical clouds (when not subsampled).
    """
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    n = min(len(a), len(b), int(max_points))
    if n < 1:
        raise ValueError("empty point cloud")
    rng = np.random.default_rng(seed)
    if len(a) > n:
        a = a[rng.choice(len(a), size=n, replace=False)]
    if len(b) > n:
        b = b[rng.choice(len(b), size=n, replace=False)]
    cost = cdist(a, b)
    rows, cols = linear_sum_assignment(cost)
    return float(cost[rows, cols].mean())
