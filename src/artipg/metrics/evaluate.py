"""Evaluating object sets: the computations behind ``artipg eval`` and ``artipg stats``.

The distance between two objects is Chamfer-L1 (:mod:`artipg.metrics.chamfer`) between
their point clouds after the chosen normalisation; MMD / COV / 1-NNA / NND come from one
pairwise matrix over the union of both sets (:mod:`artipg.metrics.sets`).
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from artipg.metrics.chamfer import chamfer_matrix
from artipg.metrics.fid import fid
from artipg.metrics.normalize import normalize
from artipg.metrics.sets import nearest_neighbor_distance, set_metrics
from artipg.metrics.structure import summarize_structure


def compare_sets(gen_points: np.ndarray, ref_points: np.ndarray, normalization: str = "bbox", kind: str = "l1",
                 workers: int | None = None, encoder=None,
                 progress: Callable[[int], None] | None = None) -> dict:
    """Set metrics of a generated set against a reference set.

    Parameters
    ----------
    gen_points : (G, N, 3) float array
        Generated clouds (rest pose, any units).
    ref_points : (R, N', 3) float array
        Reference clouds.
    normalization : {"bbox", "none"}
        Applied to every cloud before distances (see :func:`artipg.metrics.normalize`).
    kind : {"l1", "l2"}
        Chamfer variant.
    workers : int, optional
        Threads for the distance matrix.
    encoder : PointNetEncoder, optional
        When given (and both sets have >= 2 objects), FID of its features is added.
    progress : callable, optional
        Called with 1 per KD-tree (G + R calls in all).

    Returns
    -------
    dict
        The keys of :func:`artipg.metrics.sets.set_metrics` plus ``fid`` (None without
        an encoder) and ``n_generated``, ``n_reference``.
    """
    G = normalize(gen_points, normalization)
    R = normalize(ref_points, normalization)
    ng = len(G)
    D = chamfer_matrix(list(G) + list(R), kind=kind, workers=workers, progress=progress)
    out = {"n_generated": ng, "n_reference": len(R)}
    out.update(set_metrics(D[:ng, :ng], D[ng:, ng:], D[:ng, ng:]))
    out["fid"] = None
    if encoder is not None and ng >= 2 and len(R) >= 2:
        out["fid"] = fid(encoder.features(gen_points), encoder.features(ref_points))
    return out


def set_statistics(points: np.ndarray, structures, normalization: str = "bbox", kind: str = "l1",
                   workers: int | None = None, with_nnd: bool = True,
                   progress: Callable[[int], None] | None = None) -> dict:
    """Statistics of one set: NND diversity (paper eq. 1) and structure.

    Parameters
    ----------
    points : (M, N, 3) float array
    structures : sequence of ObjectStructure
    normalization, kind, workers, progress
        As in :func:`compare_sets` (M progress calls).
    with_nnd : bool
        Skip the distance matrix when False.

    Returns
    -------
    dict
        ``nnd`` (None when skipped or M < 2) and ``structure``
        (:func:`artipg.metrics.structure.summarize_structure`).
    """
    nnd = None
    if with_nnd and len(points) >= 2:
        D = chamfer_matrix(list(normalize(points, normalization)), kind=kind, workers=workers, progress=progress)
        nnd = nearest_neighbor_distance(D)
    return {"nnd": nnd, "structure": summarize_structure(structures)}
