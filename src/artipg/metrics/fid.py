"""Fréchet distance between feature distributions (FID, Heusel et al. 2017)."""

from __future__ import annotations

import numpy as np


def feature_statistics(features: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Mean (F,) and covariance (F, F) (unbiased, ddof = 1) of features (M, F), M >= 2."""
    f = np.asarray(features, dtype=np.float64)
    if f.ndim != 2 or len(f) < 2:
        raise ValueError(f"need at least 2 feature vectors of shape (M, F), got {f.shape}")
    return f.mean(axis=0), np.cov(f, rowvar=False)


def _psd_sqrt(S: np.ndarray) -> np.ndarray:
    w, V = np.linalg.eigh((S + S.T) / 2)
    return (V * np.sqrt(np.clip(w, 0.0, None))) @ V.T


def frechet_distance(mu1: np.ndarray, sigma1: np.ndarray, mu2: np.ndarray, sigma2: np.ndarray) -> float:
    """Fréchet (2-Wasserstein) distance between two Gaussians.

    ``d^2 = ||mu1 - mu2||^2 + Tr(S1 + S2 - 2 (S1 S2)^(1/2))``

    ``Tr((S1 S2)^(1/2))`` is computed as the sum of the square roots of the eigenvalues
    of the symmetric PSD matrix ``S1^(1/2) S2 S1^(1/2)`` (same spectrum as ``S1 S2``),
    which stays real and stable for the rank-deficient covariances of small sets
    (fewer objects than feature dimensions), unlike a general ``sqrtm``.

    Returns
    -------
    float
        >= 0 (clipped at 0 against round-off); squared feature units.
    """
    mu1, mu2 = np.asarray(mu1, dtype=np.float64), np.asarray(mu2, dtype=np.float64)
    r = _psd_sqrt(np.asarray(sigma1, dtype=np.float64))
    M = r @ np.asarray(sigma2, dtype=np.float64) @ r
    tr_sqrt = float(np.sqrt(np.clip(np.linalg.eigvalsh((M + M.T) / 2), 0.0, None)).sum())
    diff = mu1 - mu2
    d = float(diff @ diff + np.trace(sigma1) + np.trace(sigma2) - 2.0 * tr_sqrt)
    return max(0.0, d)


def fid(features_a: np.ndarray, features_b: np.ndarray) -> float:
    """FID between two sets of feature vectors (M_a, F) and (M_b, F), each M >= 2.

    Same value as ``frechet_distance(*feature_statistics(a), *feature_statistics(b))``.
    When the sets are smaller than the feature dimension (the usual case: 100 objects,
    256 features), ``Tr((S_a S_b)^(1/2))`` is computed exactly in sample space: with
    centred, scaled features ``A = (a - mean) / sqrt(M_a - 1)`` (so ``S_a = A^T A``) and
    likewise ``B``, the non-zero eigenvalues of ``S_a S_b`` are the squared singular
    values of ``A B^T`` (M_a, M_b), so the trace is that matrix's nuclear norm.

    With the point-cloud encoder of :mod:`artipg.metrics.encoder`:
    ``fid(enc.features(clouds_g), enc.features(clouds_r))``.
    """
    a = np.asarray(features_a, dtype=np.float64)
    b = np.asarray(features_b, dtype=np.float64)
    if a.ndim != 2 or b.ndim != 2 or len(a) < 2 or len(b) < 2 or a.shape[1] != b.shape[1]:
        raise ValueError(f"need two (M >= 2, F) feature arrays with equal F, got {a.shape} and {b.shape}")
    if len(a) * len(b) >= a.shape[1] ** 2:
        return frechet_distance(*feature_statistics(a), *feature_statistics(b))
    mu_a, mu_b = a.mean(axis=0), b.mean(axis=0)
    A = (a - mu_a) / np.sqrt(len(a) - 1)
    B = (b - mu_b) / np.sqrt(len(b) - 1)
    tr_sqrt = float(np.linalg.svd(A @ B.T, compute_uv=False).sum())
    diff = mu_a - mu_b
    return max(0.0, float(diff @ diff + np.sum(A * A) + np.sum(B * B) - 2.0 * tr_sqrt))
