"""Point-cloud normalisation."""

from __future__ import annotations

import numpy as np

NORMALIZATIONS = ("bbox", "none")


def normalize_bbox(points: np.ndarray) -> np.ndarray:
    """Centre each cloud at its bounding-box centre and scale it to unit box diagonal.

    After this, metric-scale objects (artipg, PartNet-Mobility: metres) compare with
    unit-less ones: distances are in units of the object's own box diagonal.

    Parameters
    ----------
    points : (N, 3) or (M, N, 3) float array
        One cloud or a batch of clouds (each normalised on its own).

    Returns
    -------
    ndarray, same shape, float64
        Clouds with axis-aligned box centred at the origin and diagonal 1 (a
        degenerate cloud of one repeated point is only centred).
    """
    p = np.asarray(points, dtype=np.float64)
    lo = p.min(axis=-2, keepdims=True)
    hi = p.max(axis=-2, keepdims=True)
    diag = np.linalg.norm(hi - lo, axis=-1, keepdims=True)
    return (p - (lo + hi) / 2) / np.where(diag > 0, diag, 1.0)


def normalize(points: np.ndarray, how: str = "bbox") -> np.ndarray:
    """Apply the normalisation named ``how`` (``"bbox"``: :func:`normalize_bbox`,
    ``"none"``: unchanged, as float64) to one cloud (N, 3) or a batch (M, N, 3)."""
    if how == "bbox":
        return normalize_bbox(points)
    if how == "none":
        return np.asarray(points, dtype=np.float64)
    raise ValueError(f"normalisation must be one of {NORMALIZATIONS}, got {how!r}")
