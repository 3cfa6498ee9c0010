"""Applying the detail bridge: a labelled structure cloud in, a detailed cloud out.

1. The structure cloud (N, 3) (metres, object frame) is normalised like the training
   pairs: centred on its bounding-box centre, divided by its diagonal ``d``.
2. It is split, in a seeded random order, into chunks of the training density
   (``points`` of the model's config; the last chunk is filled up with other points of
   the cloud, whose outputs are dropped), each an area-uniform sample of the same
   surface, and the model samples every point's offset (Euler integration of the flow
   from seeded Gaussian noise: the same seed gives the same cloud).
3. **Drift bound.** An offset longer than ``bound * d`` is pulled back along its
   direction to that length. The default ``bound`` (the model's, 0.006 unless trained
   otherwise) is relative to the object's size: 0.006 of the diagonal is the paper's
   5 mm at its average object diameter of 0.86 m, 3 mm on a 0.5 m microwave, 12 mm on a
   2 m wardrobe. Every detailed point is then within ``bound * d`` of the structure
   point it came from, so within that distance of the structure's surface.
4. **Labels.** Every detailed point takes every per-point annotation (semantic,
   instance, link, primitive, actionable, affordance, normals, NPCS) of its *nearest*
   structure point, which is within the bound.

Drift is reported per point: ``drift`` is the distance of a detailed point from the
structure cloud (the paper's definition, A.1: distance to the nearest structure point),
``displacement`` the length of its offset after the pull-back, ``raw`` before it.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: Per-point arrays of ``points.npz`` carried over from the nearest structure point.
PER_POINT = ("normals", "semantic", "instance", "link", "primitive", "actionable", "affordance", "npcs",
             "object_npcs")

_CACHE: dict = {}


class DetailModelError(ValueError):
    """A detail model that cannot be used (missing file, not a model, torch missing)."""


@dataclass
class DetailModel:
    """A trained bridge and what its file records (``extra``: training history)."""

    net: object
    extra: dict
    path: str

    @property
    def config(self):
        return self.net.config


def load_detail_model(path) -> DetailModel:
    """Load (once per process and path) a model written by ``artipg detail train``.

    Raises
    ------
    DetailModelError
        One line: no such file, not a detail model, or torch not installed.
    """
    key = str(Path(path).resolve())
    if key in _CACHE:
        return _CACHE[key]
    try:
        from artipg.detail.model import load_model
    except ImportError as e:
        raise DetailModelError(f"the learned detail bridge needs torch: pip install 'artipg[learn]' ({e})") from e
    try:
        net, extra = load_model(path)
    except (FileNotFoundError, ValueError) as e:
        raise DetailModelError(str(e)) from e
    _CACHE[key] = DetailModel(net, extra, key)
    return _CACHE[key]


@dataclass
class Detailed:
    """A detailed cloud (module docstring).

    Attributes
    ----------
    points : (N, 3) float64
        Detailed points, metres, object frame.
    nearest : (N,) int64
        Index of every detailed point's nearest structure point (its labels' source).
    drift : (N,) float64
        Distance of every detailed point from the structure cloud, metres.
    displacement, raw : (N,) float64
        Offset length after / before the pull-back, metres.
    bound : float
        The drift bound, metres.
    """

    points: np.ndarray
    nearest: np.ndarray
    drift: np.ndarray
    displacement: np.ndarray
    raw: np.ndarray
    bound: float

    def summary(self) -> dict:
        """Drift statistics in metres: max and 95th percentile of ``drift`` and of the
        offsets before the pull-back, the bound, and the share of points pulled back."""
        def q(x, p):
            return float(np.percentile(x, p)) if len(x) else 0.0
        return {"drift_max": q(self.drift, 100), "drift_p95": q(self.drift, 95),
                "raw_max": q(self.raw, 100), "raw_p95": q(self.raw, 95), "bound": self.bound,
                "pulled_back": float(np.mean(self.raw > self.bound)) if len(self.raw) else 0.0}


def _chunks(n: int, size: int, rng: np.random.Generator) -> np.ndarray:
    """(C, size) indices covering 0..n-1 in random order, the last chunk filled up with
    other indices (repeats only when n < size)."""
    order = rng.permutation(n)
    c = max(1, -(-n // size))
    fill = c * size - n
    if fill:
        order = np.concatenate([order, rng.choice(n, size=fill, replace=fill > n)])
    return order.reshape(c, size)


def detail_points(model: DetailModel, points: np.ndarray, seed: int = 0, bound: float | None = None,
                  steps: int | None = None) -> Detailed:
    """Detail a structure cloud (module docstring).

    Parameters
    ----------
    model : DetailModel
    points : (N, 3) float array
        The structure cloud, metres, object frame.
    seed : int
        Seeds the chunking and the flow's noise.
    bound : float, optional
        Drift bound as a fraction of the cloud's bounding-box diagonal (default: the
        model's ``bound``).
    steps : int, optional
        Euler steps (default: the model's).

    Returns
    -------
    Detailed
    """
    import torch
    from scipy.spatial import cKDTree

    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 3 or not len(pts):
        raise ValueError(f"expected a non-empty (N, 3) cloud, got shape {pts.shape}")
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    diag = float(np.linalg.norm(hi - lo)) or 1.0
    unit = (pts - (lo + hi) / 2) / diag
    cfg = model.config
    rng = np.random.default_rng(seed)
    idx = _chunks(len(pts), cfg.points, rng)
    noise = rng.standard_normal((*idx.shape, 3)).astype(np.float32)
    P = torch.from_numpy(unit[idx].astype(np.float32))
    D = torch.full((len(idx),), float(np.log(diag)))
    off = model.net.sample(P, D, torch.from_numpy(noise), steps).numpy().astype(np.float64) * diag
    offsets = np.empty_like(pts)
    first = np.unique(idx.ravel(), return_index=True)[1]  # each point's first occurrence
    offsets[idx.ravel()[first]] = off.reshape(-1, 3)[first]
    raw = np.linalg.norm(offsets, axis=1)
    b = (cfg.bound if bound is None else float(bound)) * diag
    shrink = np.where(raw > b, b / np.maximum(raw, 1e-300), 1.0)
    offsets *= shrink[:, None]
    out = pts + offsets
    drift, nearest = cKDTree(pts).query(out)
    return Detailed(out, nearest.astype(np.int64), drift, raw * shrink, raw, b)


def detail_arrays(model: DetailModel, arrays: dict, seed: int = 0, bound: float | None = None) -> tuple[dict, dict]:
    """``points.npz`` arrays with the detailed cloud: ``points`` replaced, every
    per-point array (:data:`PER_POINT`) taken from the nearest structure point, and
    ``structure_points`` (N, 3) and ``detail_drift`` (N,) (metres) added.

    Returns
    -------
    (new arrays, :meth:`Detailed.summary`)
    """
    d = detail_points(model, arrays["points"], seed=seed, bound=bound)
    out = dict(arrays)
    for k in PER_POINT:
        if k in out:
            out[k] = np.asarray(out[k])[d.nearest]
    out["structure_points"] = np.asarray(arrays["points"], dtype=np.float32)
    out["points"] = d.points.astype(np.float32)
    out["detail_drift"] = d.drift.astype(np.float32)
    return out, d.summary()


def generation_model(path) -> DetailModel:
    """:func:`load_detail_model` for ``artipg generate``'s worker processes: torch on one
    thread (the engine runs one object per process)."""
    import torch

    torch.set_num_threads(1)
    return load_detail_model(path)
