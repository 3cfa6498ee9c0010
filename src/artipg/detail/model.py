"""The detail bridge network: conditional flow matching over per-point offsets.

Given a structure cloud ``P`` (B, N, 3) (normalised: bounding-box centre at the origin,
unit diagonal; see :mod:`artipg.detail.pairs`), the model describes the distribution of
each point's offset ``x`` (3,) to the detailed surface, in units of ``offset_scale``
(diagonals), through a velocity field ``v(x_t, t | P, i)`` of the linear path
``x_t = (1 - t) x_0 + t x_1`` from Gaussian noise ``x_0 ~ N(0, I)`` to the offset ``x_1``
(rectified flow / flow matching). Sampling integrates ``dx/dt = v`` from ``t = 0`` to 1
with Euler steps.

The condition of point i (computed once per cloud by :meth:`DetailNet.encode`):

- local: an EdgeConv layer over its ``k`` nearest structure neighbours (their relative
  positions, scaled by :data:`EDGE_SCALE`, and its own position), max-pooled;
- point: an MLP of its position and local feature;
- global: the max-pool of the point features over the cloud (the object's shape);
- size: the log of the object's diagonal in metres (real detail has a metric scale:
  a bevel is millimetres on a phone and on a wardrobe).

Every operation is per point or a symmetric pooling, so the model takes any number of
points; it was trained at one density (``points`` in its config), so
:mod:`artipg.detail.application` feeds it clouds of that size.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import torch
from torch import nn

#: Relative neighbour positions are multiplied by this (they are ~0.01-0.05 diagonals).
EDGE_SCALE = 20.0


@dataclass
class ModelConfig:
    """Sizes of :class:`DetailNet` and what it was trained on.

    Attributes
    ----------
    k : int
        Neighbours of the local feature.
    local, width : int
        Widths of the local feature and of the point / condition / head layers.
    t_dim : int
        Sinusoidal features of the flow time.
    points : int
        Points per cloud at training (the density the local feature saw).
    offset_scale : float
        Offsets are predicted in units of this many diagonals.
    bound : float
        Default drift bound, as a fraction of the object's bounding-box diagonal.
    steps : int
        Default Euler steps of sampling.
    """

    k: int = 16
    local: int = 64
    width: int = 128
    t_dim: int = 16
    points: int = 1024
    offset_scale: float = 0.02
    bound: float = 0.006
    steps: int = 8


def mlp(sizes: list[int], last_act: bool = False) -> nn.Sequential:
    """Linear layers with SiLU between them (and after the last when ``last_act``)."""
    layers: list[nn.Module] = []
    for i, (a, b) in enumerate(zip(sizes[:-1], sizes[1:])):
        layers.append(nn.Linear(a, b))
        if i < len(sizes) - 2 or last_act:
            layers.append(nn.SiLU())
    return nn.Sequential(*layers)


def knn(points: torch.Tensor, k: int) -> torch.Tensor:
    """Indices (B, N, k) of the k nearest other points of every point of (B, N, 3)."""
    d = torch.cdist(points, points)
    k = min(k + 1, points.shape[1])
    return d.topk(k, dim=-1, largest=False).indices[..., 1:]


def time_features(t: torch.Tensor, dim: int) -> torch.Tensor:
    """Sinusoidal features (..., dim) of flow times ``t`` (...,) in [0, 1]."""
    half = dim // 2
    freq = torch.exp(torch.arange(half, dtype=t.dtype, device=t.device) * (-math.log(100.0) / max(half - 1, 1)))
    a = t[..., None] * freq * 2 * math.pi
    return torch.cat([a.sin(), a.cos()], dim=-1)


class DetailNet(nn.Module):
    """Velocity field of the offsets given the structure (module docstring)."""

    def __init__(self, config: ModelConfig):
        super().__init__()
        c = config
        self.config = c
        self.edge = mlp([6, 32, c.local], last_act=True)
        self.point = mlp([3 + c.local, c.width, c.width], last_act=True)
        self.cond = mlp([c.local + 2 * c.width + 1, c.width, c.width], last_act=True)
        self.head = mlp([3 + c.t_dim + c.width, c.width, c.width, 3])

    def encode(self, points: torch.Tensor, log_diag: torch.Tensor) -> torch.Tensor:
        """Per-point condition (B, N, width) of structure clouds (B, N, 3) (normalised)
        of objects whose diagonals are ``exp(log_diag)`` (B,) metres."""
        B, N, _ = points.shape
        idx = knn(points, self.config.k)
        nb = points[torch.arange(B)[:, None, None], idx]
        rel = (nb - points[:, :, None]) * EDGE_SCALE
        e = self.edge(torch.cat([rel, points[:, :, None].expand_as(rel)], dim=-1)).amax(dim=2)
        h = self.point(torch.cat([points, e], dim=-1))
        g = h.amax(dim=1, keepdim=True).expand_as(h)
        s = log_diag[:, None, None].expand(B, N, 1)
        return self.cond(torch.cat([e, h, g, s], dim=-1))

    def velocity(self, x: torch.Tensor, t: torch.Tensor, cond: torch.Tensor) -> torch.Tensor:
        """Velocity (B, N, 3) at offsets ``x`` (B, N, 3) and times ``t`` (B, N)."""
        return self.head(torch.cat([x, time_features(t, self.config.t_dim), cond], dim=-1))

    def loss(self, points: torch.Tensor, log_diag: torch.Tensor, offsets: torch.Tensor,
             gen: torch.Generator, weight: torch.Tensor | None = None) -> torch.Tensor:
        """Flow-matching loss of a batch: structure (B, N, 3), offsets (B, N, 3) in
        diagonals, optional per-point weights (B, N); one flow time per point."""
        x1 = offsets / self.config.offset_scale
        x0 = torch.randn(x1.shape, generator=gen, dtype=x1.dtype)
        t = torch.rand(x1.shape[:2], generator=gen, dtype=x1.dtype)
        xt = (1 - t[..., None]) * x0 + t[..., None] * x1
        v = self.velocity(xt, t, self.encode(points, log_diag))
        err = ((v - (x1 - x0)) ** 2).mean(dim=-1)
        if weight is None:
            return err.mean()
        return (err * weight).sum() / weight.sum().clamp_min(1.0)

    @torch.no_grad()
    def sample(self, points: torch.Tensor, log_diag: torch.Tensor, noise: torch.Tensor,
               steps: int | None = None) -> torch.Tensor:
        """Offsets (B, N, 3) in diagonals, integrated from ``noise`` (B, N, 3) ~ N(0, I)."""
        steps = int(steps or self.config.steps)
        cond = self.encode(points, log_diag)
        x = noise
        for i in range(steps):
            t = torch.full(x.shape[:2], i / steps, dtype=x.dtype)
            x = x + self.velocity(x, t, cond) / steps
        return x * self.config.offset_scale


def save_model(net: DetailNet, path, extra: dict | None = None) -> None:
    """Write the weights and config (``torch.save``; a dict of tensors and plain values)."""
    torch.save({"format": "artipg-detail-1", "config": asdict(net.config), "state_dict": net.state_dict(),
                "extra": extra or {}}, path)


def load_model(path) -> tuple[DetailNet, dict]:
    """(network in eval mode, ``extra`` dict) from a file written by :func:`save_model`.

    Raises
    ------
    FileNotFoundError
        No such file.
    ValueError
        A file that is not a detail model.
    """
    from pathlib import Path

    p = Path(path)
    if not p.is_file():
        raise FileNotFoundError(f"no detail model at {p}")
    try:
        blob = torch.load(p, map_location="cpu", weights_only=True)
        if not isinstance(blob, dict) or blob.get("format") != "artipg-detail-1":
            raise ValueError("not an artipg detail model")
        net = DetailNet(ModelConfig(**blob["config"]))
        net.load_state_dict(blob["state_dict"])
    except ValueError as e:
        raise ValueError(f"{p}: {e}") from e
    except Exception as e:  # torch raises many types on a foreign or damaged file
        raise ValueError(f"{p}: not an artipg detail model ({type(e).__name__})") from e
    net.eval()
    return net, blob.get("extra", {})
