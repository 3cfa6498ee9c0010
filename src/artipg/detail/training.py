"""Training the detail bridge on pairs (:mod:`artipg.detail.pairs`).

Every (pair, joint state) is one training cloud. A batch draws clouds at random and
augments each, structure and offsets alike, with a rigid and scale transform:

- a rotation about +Z (up) of at most ``rotate_deg`` and, with probability 1/2, the
  mirror y -> -y (objects are near-symmetric left-right; front stays -X, up stays +Z);
- an anisotropic scale, each axis by a factor in ``[1 - scale, 1 + scale]`` (other
  proportions of the same structure);
- the metric size (the ``log_diag`` condition) jittered by ``exp(U(-size_jitter,
  size_jitter))`` (other sizes of the same shape).

Pairs whose twin fits the object poorly (``max_fit_chamfer``) are left out, and so are,
from the loss, points whose offset is longer than ``max_offset``: both are differences of
structure (a missing or misplaced part), which the fit, not the detail bridge, answers.

The loss is flow matching's (:meth:`artipg.detail.model.DetailNet.loss`); Adam with a
cosine learning-rate decay over the run (over the steps, or over ``minutes`` of wall
time when that runs out first: then the run is not deterministic in its length).
``initial_loss`` and ``final_loss`` are measured on one fixed, unaugmented batch with
fixed noise, so they compare like with like.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass
from typing import Callable

import numpy as np
import torch

from artipg.detail.model import DetailNet, ModelConfig


@dataclass
class TrainConfig:
    """Training settings (module docstring).

    Attributes
    ----------
    steps : int
        Optimiser steps (fewer when ``minutes`` runs out first).
    batch : int
        Clouds per step.
    points : int
        Points per training cloud: a random subset of each pair's (the model is then
        applied to chunks of this many points, the density it was trained at).
    lr : float
        Peak learning rate.
    seed : int
        Seeds initialisation, batches, augmentation and noise.
    minutes : float, optional
        Wall-time limit of the loop.
    target : {"projected", "matched"}
        Offsets to the projection on the real surface, or to the matched points.
    rotate_deg, scale, size_jitter : float
        Augmentation (module docstring).
    max_fit_chamfer : float
        Pairs whose fit (whole-object Chamfer-L1 at the closed state, diagonals) is worse
        are left out: their twin differs from the object in structure, not in detail.
    max_offset : float
        Points whose target offset is longer (diagonals) are left out of the loss: a
        part the twin lacks or misplaces, not detail.
    threads : int, optional
        torch intra-op threads (default: torch's).
    """

    steps: int = 2000
    batch: int = 8
    points: int = 512
    lr: float = 2e-3
    seed: int = 0
    minutes: float | None = None
    target: str = "projected"
    rotate_deg: float = 15.0
    scale: float = 0.15
    size_jitter: float = 0.3
    max_fit_chamfer: float = 0.05
    max_offset: float = 0.05
    threads: int | None = None


def pair_arrays(pairs, target: str = "projected", max_offset: float = np.inf):
    """Training clouds of pairs: structure (M, N, 3), offsets (M, N, 3) (diagonals),
    log metric diagonal (M,) and point weights (M, N) (0 where the offset is longer than
    ``max_offset``), one row per (pair, state)."""
    if target not in ("projected", "matched"):
        raise ValueError(f"target must be 'projected' or 'matched', got {target!r}")
    sizes = {p.structure.shape[1] for p in pairs}
    if len(sizes) != 1:
        raise ValueError(f"pairs with different point counts {sorted(sizes)}")
    P = np.concatenate([p.structure for p in pairs]).astype(np.float32)
    O = np.concatenate([p.offsets(target) for p in pairs]).astype(np.float32)
    D = np.concatenate([np.full(len(p.structure), np.log(p.diagonal)) for p in pairs]).astype(np.float32)
    W = (np.linalg.norm(O, axis=-1) <= max_offset).astype(np.float32)
    return P, O, D, W


def augment(rng: np.random.Generator, P: np.ndarray, O: np.ndarray, D: np.ndarray, cfg: TrainConfig):
    """Rigid and scale augmentation of clouds P, offsets O (B, N, 3) and log-diagonals D (B,)."""
    B = len(P)
    a = np.deg2rad(cfg.rotate_deg) * rng.uniform(-1, 1, B)
    c, s = np.cos(a), np.sin(a)
    R = np.zeros((B, 3, 3))
    R[:, 0, 0], R[:, 0, 1], R[:, 1, 0], R[:, 1, 1], R[:, 2, 2] = c, -s, s, c, 1.0
    R[:, 1] *= np.where(rng.random(B) < 0.5, -1.0, 1.0)[:, None]
    A = R * rng.uniform(1 - cfg.scale, 1 + cfg.scale, (B, 3, 1))  # scale rows: after the rotation
    P2 = np.einsum("bij,bnj->bni", A, P)
    O2 = np.einsum("bij,bnj->bni", A, O)
    D2 = D + rng.uniform(-cfg.size_jitter, cfg.size_jitter, B)
    return P2.astype(np.float32), O2.astype(np.float32), D2.astype(np.float32)


def _subsets(rng: np.random.Generator, b: int, n: int, k: int) -> np.ndarray:
    """(b, k) random subsets of range(n), one per row."""
    return rng.random((b, n)).argsort(axis=1)[:, :k]


def _rows(X: np.ndarray, sub: np.ndarray) -> np.ndarray:
    """X[b, sub[b]] for every row b of X (B, N, ...)."""
    return X[np.arange(len(X))[:, None], sub]


def _progress(cfg: TrainConfig, step: int, seconds: float) -> float:
    """Fraction of the run done: of the steps, or of the wall time when that is nearer its end."""
    frac = step / max(cfg.steps, 1)
    if cfg.minutes is not None:
        frac = max(frac, seconds / (60.0 * cfg.minutes))
    return frac


def _cosine(cfg: TrainConfig, step: int, seconds: float) -> float:
    """Learning rate: cosine decay from ``lr`` to 5 % of it over the run (steps or time)."""
    f = min(_progress(cfg, step, seconds), 1.0)
    return cfg.lr * (0.05 + 0.95 * 0.5 * (1.0 + np.cos(np.pi * f)))


def _fixed_loss(net: DetailNet, P, O, D, W, seed: int) -> float:
    gen = torch.Generator().manual_seed(seed + 7919)
    with torch.no_grad():
        return float(net.loss(torch.from_numpy(P), torch.from_numpy(D), torch.from_numpy(O), gen,
                              torch.from_numpy(W)))


def train(pairs, model_config: ModelConfig | None = None, cfg: TrainConfig | None = None,
          progress: Callable[[int, float], None] | None = None) -> tuple[DetailNet, dict]:
    """Train a :class:`DetailNet` on ``pairs``.

    Parameters
    ----------
    pairs : list of :class:`artipg.detail.pairs.Pair`
    model_config : ModelConfig, optional
        ``points`` and ``offset_scale`` are set from the pairs.
    cfg : TrainConfig, optional
    progress : callable, optional
        Called with (step, running loss) every 25 steps.

    Returns
    -------
    (trained network in eval mode, history dict: losses every 25 steps,
    ``initial_loss`` / ``final_loss`` on a fixed batch, steps, seconds, pairs, configs)
    """
    cfg = cfg or TrainConfig()
    used = [p for p in pairs if p.fit_chamfer is None or not np.isfinite(p.fit_chamfer[0])
            or p.fit_chamfer[0] <= cfg.max_fit_chamfer]
    if not used:
        raise ValueError(f"no pair fits within max_fit_chamfer={cfg.max_fit_chamfer}")
    P, O, D, W = pair_arrays(used, cfg.target, cfg.max_offset)
    mc = model_config or ModelConfig()
    n = min(int(cfg.points), P.shape[1])
    mc.points = n
    mc.offset_scale = float(np.sqrt(np.mean(O[W > 0].astype(np.float64) ** 2)) if W.any() else 1.0) or 1.0
    if cfg.threads:
        torch.set_num_threads(int(cfg.threads))
    torch.manual_seed(cfg.seed)
    net = DetailNet(mc)
    rng = np.random.default_rng(cfg.seed)
    gen = torch.Generator().manual_seed(cfg.seed)
    fixed = np.sort(rng.choice(len(P), size=min(len(P), cfg.batch), replace=False))
    sub = _subsets(rng, len(fixed), P.shape[1], n)
    fP, fO, fD, fW = _rows(P[fixed], sub), _rows(O[fixed], sub), D[fixed], _rows(W[fixed], sub)
    initial = _fixed_loss(net, fP, fO, fD, fW, cfg.seed)
    opt = torch.optim.Adam(net.parameters(), lr=cfg.lr)
    start = time.perf_counter()
    losses, running, step = [], [], 0
    net.train()
    for step in range(1, cfg.steps + 1):
        idx = rng.choice(len(P), size=cfg.batch, replace=len(P) < cfg.batch)
        sub = _subsets(rng, cfg.batch, P.shape[1], n)
        Pb, Ob, Db = augment(rng, _rows(P[idx], sub), _rows(O[idx], sub), D[idx], cfg)
        loss = net.loss(torch.from_numpy(Pb), torch.from_numpy(Db), torch.from_numpy(Ob), gen,
                        torch.from_numpy(_rows(W[idx], sub)))
        opt.zero_grad()
        loss.backward()
        opt.step()
        for group in opt.param_groups:
            group["lr"] = _cosine(cfg, step, time.perf_counter() - start)
        running.append(float(loss.detach()))
        if step % 25 == 0:
            losses.append(float(np.mean(running)))
            running = []
            if progress is not None:
                progress(step, losses[-1])
        if _progress(cfg, step, time.perf_counter() - start) >= 1.0:
            break
    seconds = time.perf_counter() - start
    net.eval()
    history = {"losses": losses, "initial_loss": initial,
               "final_loss": _fixed_loss(net, fP, fO, fD, fW, cfg.seed),
               "steps": step, "seconds": seconds, "pairs": [p.name for p in used],
               "pairs_left_out": sorted({p.name for p in pairs} - {p.name for p in used}),
               "points_in_loss": float(W.mean()),
               "train_config": asdict(cfg), "threads": torch.get_num_threads()}
    return net, history
