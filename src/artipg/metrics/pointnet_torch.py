"""The torch twin of :class:`artipg.metrics.encoder.PointNetEncoder`, for training only.

Needs the optional ``learn`` extra (``pip install torch==2.13.0``); nothing at
inference time imports this module.
"""

from __future__ import annotations

import numpy as np

CONV_WIDTHS = (64, 64, 128, 256)
FC_WIDTHS = (128,)


def build_model(n_classes: int, conv_widths=CONV_WIDTHS, fc_widths=FC_WIDTHS, dropout: float = 0.3):
    """A PointNet classifier taking clouds (B, N, 3) (already bbox-normalised) to logits (B, K).

    ``model.features(x)`` returns the max-pooled global features (B, conv_widths[-1]).
    """
    import torch
    from torch import nn

    class PointNet(nn.Module):
        def __init__(self):
            super().__init__()
            dims = (3,) + tuple(conv_widths)
            # kernel-1 convolutions over the (B, C, N) layout = one shared linear map per point
            self.conv = nn.ModuleList(nn.Conv1d(a, b, 1) for a, b in zip(dims[:-1], dims[1:]))
            self.conv_bn = nn.ModuleList(nn.BatchNorm1d(b) for b in dims[1:])
            fdims = (dims[-1],) + tuple(fc_widths)
            self.fc = nn.ModuleList(nn.Linear(a, b) for a, b in zip(fdims[:-1], fdims[1:]))
            self.fc_bn = nn.ModuleList(nn.BatchNorm1d(b) for b in fdims[1:])
            self.drop = nn.Dropout(dropout)
            self.head = nn.Linear(fdims[-1], n_classes)

        def features(self, x):
            h = x.transpose(1, 2)
            for conv, bn in zip(self.conv, self.conv_bn):
                h = torch.relu(bn(conv(h)))
            return h.max(dim=2).values

        def forward(self, x):
            h = self.features(x)
            for lin, bn in zip(self.fc, self.fc_bn):
                h = self.drop(torch.relu(bn(lin(h))))
            return self.head(h)

    return PointNet()


def _fold(lin, bn) -> tuple[np.ndarray, np.ndarray]:
    """Linear (or kernel-1 Conv1d) followed by eval-mode batch-norm as one (in, out)
    weight and (out,) bias."""
    W = lin.weight.detach().double().numpy().reshape(lin.weight.shape[0], -1)   # (out, in)
    b = lin.bias.detach().double().numpy()
    g = bn.weight.detach().double().numpy() / np.sqrt(bn.running_var.detach().double().numpy() + bn.eps)
    mean = bn.running_mean.detach().double().numpy()
    beta = bn.bias.detach().double().numpy()
    return (W * g[:, None]).T.astype(np.float32), ((b - mean) * g + beta).astype(np.float32)


def export_encoder(model, classes, meta: dict | None = None):
    """The numpy :class:`~artipg.metrics.encoder.PointNetEncoder` equal to ``model`` in eval mode."""
    from artipg.metrics.encoder import PointNetEncoder

    conv = [_fold(lin, bn) for lin, bn in zip(model.conv, model.conv_bn)]
    fc = [_fold(lin, bn) for lin, bn in zip(model.fc, model.fc_bn)]
    fc.append((model.head.weight.detach().numpy().T.astype(np.float32), model.head.bias.detach().numpy().astype(np.float32)))
    return PointNetEncoder(conv, fc, classes, meta)
