"""Label alignment for point clouds near, but not exactly on, an object's surface.

Geometry that has been changed after generation (detail synthesis, noise, remeshing)
no longer lies on the primitives. Each point takes the labels of the primitive whose
surface is nearest (exact primitive SDFs, paper A.1) when that surface is within the
drift threshold; farther points stay unlabelled (-1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from artipg.annotate.sdf import object_sdf

#: Default drift threshold in metres (paper A.1).
DRIFT = 0.005


@dataclass
class Alignment:
    """Labels transferred to N free-floating points.

    Attributes
    ----------
    primitive, semantic, instance, link : (N,) int64
        Labels of the nearest primitive surface (see
        :class:`artipg.annotate.points.PointCloud`), -1 for unlabelled points.
    distance : (N,) float64
        Distance to that surface in metres (+inf beyond the threshold).
    labelled : (N,) bool
        Whether the point was within the drift threshold.
    """

    primitive: np.ndarray
    semantic: np.ndarray
    instance: np.ndarray
    link: np.ndarray
    distance: np.ndarray
    labelled: np.ndarray

    @property
    def unlabelled_share(self) -> float:
        """Share of points left unlabelled, in [0, 1]."""
        return float(1.0 - self.labelled.mean()) if len(self.labelled) else 0.0


def align_labels(obj, points: np.ndarray, qpos=None, drift: float = DRIFT) -> Alignment:
    """Give each point the labels of the nearest part surface within ``drift``.

    Parameters
    ----------
    obj : ArticulatedObject
    points : (N, 3) array
        Points in the object frame (metres), e.g. samples of a detailed mesh.
    qpos : None, dict or sequence
        Joint state of the object the points belong to.
    drift : float
        Largest distance (metres) from the surface at which a point is labelled.

    Returns
    -------
    Alignment
        Use :attr:`Alignment.unlabelled_share` for the share left unlabelled, and
        :func:`artipg.annotate.labels.point_labels` with ``primitive`` (on the
        labelled points) for affordances and NPCS.
    """
    x = np.asarray(points, dtype=float).reshape(-1, 3)
    d, prim = object_sdf(obj, x, qpos, max_dist=drift, unsigned=True)
    ok = (prim >= 0) & (d <= drift)
    table = obj.primitive_table
    p = np.where(ok, prim, 0)
    part = table.prim_part[p]
    out = Alignment(
        primitive=np.where(ok, prim, -1),
        semantic=np.where(ok, table.part_semantic[part], -1),
        instance=np.where(ok, part, -1),
        link=np.where(ok, table.prim_link[p], -1),
        distance=np.where(ok, d, np.inf),
        labelled=ok,
    )
    return out
