"""Set metrics from pairwise distance matrices: MMD, COV, 1-NNA (PointFlow) and NND.

Notation: ``S_g`` is the generated (evaluated) set, ``S_r`` the reference set (e.g.
real objects), ``D`` a distance between two objects (here Chamfer-L1, the paper's
"Instantiation Distance"). Matrices are laid out with the generated set on the rows:
``D_gr[i, j] = D(g_i, r_j)``, shape (|S_g|, |S_r|).
"""

from __future__ import annotations

import numpy as np


def _check(D: np.ndarray, square: bool = False) -> np.ndarray:
    D = np.asarray(D, dtype=np.float64)
    if D.ndim != 2 or (square and D.shape[0] != D.shape[1]):
        raise ValueError(f"expected a {'square ' if square else ''}2-D distance matrix, got shape {D.shape}")
    return D


def minimum_matching_distance(D_gr: np.ndarray) -> float:
    """MMD: for each *reference* object, the distance to its closest generated object,
    averaged over the reference set (lower is better: reference shapes are matched
    closely; measures fidelity).

    ``MMD(S_g, S_r) = 1/|S_r| * sum_{Y in S_r} min_{X in S_g} D(X, Y)``

    Parameters
    ----------
    D_gr : (|S_g|, |S_r|) float array
        Rows generated, columns reference.
    """
    D = _check(D_gr)
    return float(D.min(axis=0).mean())


def coverage(D_gr: np.ndarray) -> float:
    """COV: fraction of *reference* objects that are the nearest reference neighbour
    of at least one generated object (higher is better; measures diversity / mode
    coverage). Ties take the first reference index.

    ``COV(S_g, S_r) = |{ argmin_{Y in S_r} D(X, Y) : X in S_g }| / |S_r|``

    Parameters
    ----------
    D_gr : (|S_g|, |S_r|) float array
        Rows generated, columns reference.

    Returns
    -------
    float in [0, 1]
    """
    D = _check(D_gr)
    return float(len(np.unique(D.argmin(axis=1))) / D.shape[1])


def one_nn_accuracy(D_gg: np.ndarray, D_rr: np.ndarray, D_gr: np.ndarray) -> dict:
    """1-NNA: leave-one-out accuracy of the 1-nearest-neighbour classifier that labels
    each object of ``S_g ∪ S_r`` with the set of its nearest *other* object.

    ``1-NNA = ( sum_{X in S_g} [N_X in S_g] + sum_{Y in S_r} [N_Y in S_r] ) / (|S_g| + |S_r|)``

    where ``N_X`` is X's nearest neighbour in ``S_g ∪ S_r - {X}``. 50% is ideal (the
    sets are indistinguishable); 100% means fully separated sets; values below 50%
    mean generated objects sit closer to reference objects than to each other (e.g.
    copies). The metric is symmetric in the two sets.

    Ties: an object is classified correctly only when its nearest same-set distance
    is *strictly* smaller than its nearest other-set distance; a tie counts as a
    miss. So an exact copy of a reference object (distance 0) always has its copy as
    nearest neighbour, and a generated set that copies the reference gives 0%.
    Self-distances on the diagonals of ``D_gg`` and ``D_rr`` are excluded by index
    (never by value); a set of one object has no same-set neighbour (always a miss).

    Parameters
    ----------
    D_gg : (|S_g|, |S_g|) float array
    D_rr : (|S_r|, |S_r|) float array
    D_gr : (|S_g|, |S_r|) float array
        Rows generated, columns reference.

    Returns
    -------
    dict
        ``accuracy`` (the 1-NNA, in [0, 1]), ``accuracy_generated`` and
        ``accuracy_reference`` (the classifier's accuracy on each set alone).
    """
    D_gg, D_rr, D_gr = _check(D_gg, True), _check(D_rr, True), _check(D_gr)
    ng, nr = D_gr.shape
    if D_gg.shape[0] != ng or D_rr.shape[0] != nr:
        raise ValueError(f"inconsistent shapes {D_gg.shape}, {D_rr.shape}, {D_gr.shape}")
    same_g = _min_off_diagonal(D_gg)
    same_r = _min_off_diagonal(D_rr)
    correct_g = same_g < D_gr.min(axis=1)
    correct_r = same_r < D_gr.min(axis=0)
    return {
        "accuracy": float((correct_g.sum() + correct_r.sum()) / (ng + nr)),
        "accuracy_generated": float(correct_g.mean()),
        "accuracy_reference": float(correct_r.mean()),
    }


def _min_off_diagonal(D: np.ndarray) -> np.ndarray:
    """Row minima of a square matrix ignoring the diagonal (inf for a 1x1 matrix)."""
    M = D.copy()
    np.fill_diagonal(M, np.inf)
    return M.min(axis=1)


def nearest_neighbor_distance(D_ss: np.ndarray) -> float:
    """NND diversity of one set (paper eq. 1): the distance from each object to its
    nearest *other* object of the same set, averaged over the set (higher = more
    diverse, at equal set size).

    ``NND(S) = 1/|S| * sum_{X in S} min { D(X, Y) | Y in S - {X} }``

    "Other" is by index: duplicated objects count with distance 0.

    Parameters
    ----------
    D_ss : (|S|, |S|) float array, |S| >= 2

    Returns
    -------
    float
    """
    D = _check(D_ss, True)
    if D.shape[0] < 2:
        raise ValueError("NND needs at least 2 objects")
    return float(_min_off_diagonal(D).mean())


def set_metrics(D_gg: np.ndarray, D_rr: np.ndarray, D_gr: np.ndarray) -> dict:
    """All set metrics of generated set ``S_g`` against reference ``S_r``.

    Returns
    -------
    dict
        ``cov`` and ``one_nna`` (fractions in [0, 1]), ``one_nna_generated`` /
        ``one_nna_reference`` (per-set accuracies), ``mmd`` (distance units),
        ``nnd_generated`` and ``nnd_reference`` (NaN for sets of one object).
    """
    nna = one_nn_accuracy(D_gg, D_rr, D_gr)
    nan = float("nan")
    return {
        "cov": coverage(D_gr),
        "mmd": minimum_matching_distance(D_gr),
        "one_nna": nna["accuracy"],
        "one_nna_generated": nna["accuracy_generated"],
        "one_nna_reference": nna["accuracy_reference"],
        "nnd_generated": nearest_neighbor_distance(D_gg) if len(D_gg) > 1 else nan,
        "nnd_reference": nearest_neighbor_distance(D_rr) if len(D_rr) > 1 else nan,
    }
