"""PointNet point-cloud encoder for FID, inference in numpy (no torch needed).

Architecture (Qi et al. 2017, without the input/feature transforms; the paper's
footnote: four shared point-wise layers, max-pooling, then an MLP):

    cloud (N, 3), normalised to its bounding box (centre 0, diagonal 1)
    -> shared MLP 3 -> 64 -> 64 -> 128 -> 256 (linear + batch-norm + ReLU per point)
    -> max-pool over points                       = the 256-d *feature* used for FID
    -> MLP 256 -> 128 (linear + batch-norm + ReLU) -> n_classes logits

Batch-norm layers are folded into the linear layers at export (eval mode), so the
forward pass is only matrix products, biases, ReLUs and a max. The weights ship as
``artipg/data/fid_pointnet.npz`` (trained by ``scripts/train_fid_encoder.py`` on
artipg's own categories); the file holds ``conv{i}_w`` (in, out), ``conv{i}_b``,
``fc{i}_w``, ``fc{i}_b`` (float32), ``classes`` (the category of each logit) and
``meta`` (a JSON string: training set, points, accuracy).

Inputs are always bounding-box normalised here (whatever ``--normalize`` says), so the
features, and FID, describe shape, not absolute size.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from artipg.metrics.normalize import normalize_bbox

DEFAULT_ENCODER_PATH = Path(__file__).resolve().parent.parent / "data" / "fid_pointnet.npz"


class PointNetEncoder:
    """A trained PointNet classifier evaluated in numpy.

    Parameters
    ----------
    conv : list of ((in, out) array, (out,) array)
        Shared point-wise layers (batch-norm folded), each followed by a ReLU.
    fc : list of ((in, out) array, (out,) array)
        Classifier layers; ReLU after all but the last.
    classes : sequence of str
        Class name of each logit.
    meta : dict, optional
        Free-form training information.
    """

    def __init__(self, conv, fc, classes, meta: dict | None = None):
        self.conv = [(np.asarray(w, dtype=np.float32), np.asarray(b, dtype=np.float32)) for w, b in conv]
        self.fc = [(np.asarray(w, dtype=np.float32), np.asarray(b, dtype=np.float32)) for w, b in fc]
        self.classes = tuple(str(c) for c in classes)
        self.meta = dict(meta or {})
        if self.conv[0][0].shape[0] != 3 or self.fc[-1][0].shape[1] != len(self.classes):
            raise ValueError("weights do not match a 3-D input and the class list")

    @property
    def feature_dim(self) -> int:
        """Length of the global feature vector."""
        return int(self.conv[-1][0].shape[1])

    # ------------------------------------------------------------------ io
    @classmethod
    def from_arrays(cls, arrays) -> "PointNetEncoder":
        """Build from a mapping with the keys of the ``.npz`` format (module docstring)."""
        def layers(prefix):
            out, i = [], 0
            while f"{prefix}{i}_w" in arrays:
                out.append((arrays[f"{prefix}{i}_w"], arrays[f"{prefix}{i}_b"]))
                i += 1
            return out

        meta = arrays["meta"] if "meta" in arrays else "{}"
        meta = json.loads(str(np.asarray(meta)))
        return cls(layers("conv"), layers("fc"), [str(c) for c in arrays["classes"]], meta)

    def to_arrays(self) -> dict:
        """The ``.npz`` arrays of this encoder (inverse of :meth:`from_arrays`)."""
        out = {"classes": np.array(self.classes), "meta": np.array(json.dumps(self.meta, sort_keys=True))}
        for prefix, layers in (("conv", self.conv), ("fc", self.fc)):
            for i, (w, b) in enumerate(layers):
                out[f"{prefix}{i}_w"], out[f"{prefix}{i}_b"] = w, b
        return out

    @classmethod
    def load(cls, path: str | Path | None = None) -> "PointNetEncoder":
        """Load weights from ``path`` (default: the file shipped in ``artipg/data``).

        Raises
        ------
        FileNotFoundError
        """
        path = Path(path) if path is not None else DEFAULT_ENCODER_PATH
        if not path.is_file():
            raise FileNotFoundError(f"no encoder weights at {path}; train them with scripts/train_fid_encoder.py")
        with np.load(path, allow_pickle=False) as d:
            return cls.from_arrays({k: d[k] for k in d.files})

    # ------------------------------------------------------------- forward
    def _pooled(self, clouds: np.ndarray) -> np.ndarray:
        B, N, _ = clouds.shape
        h = normalize_bbox(clouds).astype(np.float32).reshape(B * N, 3)   # one GEMM per layer
        for w, b in self.conv:
            h = h @ w
            h += b
            np.maximum(h, 0.0, out=h)
        return h.reshape(B, N, -1).max(axis=1)

    def features(self, clouds, batch: int = 16) -> np.ndarray:
        """Global features (M, F) float64 of clouds (M, N, 3) (or one cloud (N, 3) -> (1, F)).

        Each cloud is bounding-box normalised first; any N works (max-pooling), though
        features are most comparable at equal N.
        """
        x = np.asarray(clouds, dtype=np.float64)
        if x.ndim == 2:
            x = x[None]
        out = np.empty((len(x), self.feature_dim))
        for s in range(0, len(x), batch):
            out[s:s + batch] = self._pooled(x[s:s + batch])
        return out

    def logits_from_features(self, features: np.ndarray) -> np.ndarray:
        """Class logits (M, K) of global features (M, F)."""
        h = np.asarray(features, dtype=np.float32)
        for i, (w, b) in enumerate(self.fc):
            h = h @ w + b
            if i < len(self.fc) - 1:
                h = np.maximum(h, 0.0)
        return h.astype(np.float64)

    def logits(self, clouds, batch: int = 16) -> np.ndarray:
        """Class logits (M, K) of clouds (M, N, 3)."""
        return self.logits_from_features(self.features(clouds, batch))

    def predict(self, clouds, batch: int = 16) -> list[str]:
        """Most likely class name of each cloud."""
        return [self.classes[i] for i in self.logits(clouds, batch).argmax(axis=1)]


def load_default_encoder() -> PointNetEncoder | None:
    """The shipped encoder, or None when its weights file is absent."""
    try:
        return PointNetEncoder.load()
    except FileNotFoundError:
        return None
