"""Evaluation metrics: point-cloud distances, set metrics, FID and structure statistics.

- :mod:`~artipg.metrics.chamfer`   Chamfer-L1 / -L2 and batched, threaded pairwise matrices;
- :mod:`~artipg.metrics.emd`       earth mover's distance (exact assignment / subsampled);
- :mod:`~artipg.metrics.sets`      MMD, COV, 1-NNA (generated vs reference) and NND (one set);
- :mod:`~artipg.metrics.fid`       Fréchet distance of features;
- :mod:`~artipg.metrics.encoder`   numpy PointNet encoder giving those features;
- :mod:`~artipg.metrics.structure` joints / joint types / links / sizes statistics;
- :mod:`~artipg.metrics.normalize` bounding-box normalisation;
- :mod:`~artipg.metrics.evaluate`  the whole evaluation of object sets (used by the CLI);
- :mod:`~artipg.metrics.plots`     PNG plots.
"""

from artipg.metrics.chamfer import chamfer_distance, chamfer_matrix, nn_distances
from artipg.metrics.emd import earth_movers_distance
from artipg.metrics.encoder import PointNetEncoder, load_default_encoder
from artipg.metrics.evaluate import compare_sets, set_statistics
from artipg.metrics.fid import fid, frechet_distance
from artipg.metrics.normalize import normalize, normalize_bbox
from artipg.metrics.sets import (coverage, minimum_matching_distance, nearest_neighbor_distance, one_nn_accuracy,
                                 set_metrics)
from artipg.metrics.structure import ObjectStructure, joint_histogram, summarize_structure

__all__ = [
    "ObjectStructure", "PointNetEncoder", "chamfer_distance", "chamfer_matrix", "compare_sets", "coverage",
    "earth_movers_distance", "fid", "frechet_distance", "joint_histogram", "load_default_encoder",
    "minimum_matching_distance", "nearest_neighbor_distance", "nn_distances", "normalize", "normalize_bbox",
    "one_nn_accuracy", "set_metrics", "set_statistics", "summarize_structure",
]
