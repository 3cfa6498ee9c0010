"""Train the PointNet encoder used for FID and export it for numpy inference.

Data comes from artipg itself: every registered category (at the time of training),
``--per-category`` objects from seeds 0.. for training and ``--test-per-category``
objects from seeds 1,000,000.. for testing, each sampled at the rest pose with 2048
area-uniform points. Training clouds are random ``--points``-point subsets (re-drawn
every epoch) with a random anisotropic scale and jitter; all clouds are bounding-box
normalised, as the numpy encoder does at inference. Test accuracy is measured with
the exported numpy encoder on the full 2048-point clouds (the inference path of
``artipg eval``).

Needs torch (``pip install 'artipg[learn]'``, i.e. ``torch==2.13.0``, CPU).

Usage:
    python scripts/train_fid_encoder.py [--per-category 300] [--epochs 30] [--time-budget 420]
        [--threads 2] [--out src/artipg/data/fid_pointnet.npz]
"""

from __future__ import annotations

import argparse
import json
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

import artipg
from artipg.export.npz import npz_bytes
from artipg.metrics.normalize import normalize_bbox

DEFAULT_OUT = Path(__file__).resolve().parent.parent / "src" / "artipg" / "data" / "fid_pointnet.npz"
TEST_SEED0 = 1_000_000
CLOUD_POINTS = 2048


def _clouds(task: tuple[str, int, int]) -> np.ndarray:
    """(count, 2048, 3) float32 rest-pose clouds of seeds first..first+count-1."""
    category, first, count = task
    return np.stack([artipg.generate(category, s).sample_points(CLOUD_POINTS, seed=0).points
                     for s in range(first, first + count)]).astype(np.float32)


def make_split(categories, per_category: int, first_seed: int, workers: int) -> tuple[np.ndarray, np.ndarray]:
    """Clouds (M, 2048, 3) and labels (M,) for every category, generated in parallel."""
    chunk = 25
    tasks = [(c, first_seed + s, min(chunk, per_category - s)) for c in categories for s in range(0, per_category, chunk)]
    labels = np.concatenate([np.full(t[2], categories.index(t[0])) for t in tasks])
    with ProcessPoolExecutor(max_workers=workers) as ex:
        clouds = np.concatenate(list(ex.map(_clouds, tasks)))
    return clouds, labels.astype(np.int64)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--per-category", type=int, default=300, help="training objects per category")
    ap.add_argument("--test-per-category", type=int, default=50, help="test objects per category")
    ap.add_argument("--points", type=int, default=256, help="points per training cloud")
    ap.add_argument("--epochs", type=int, default=30, help="most epochs")
    ap.add_argument("--time-budget", type=float, default=420.0, help="seconds of training (epochs are cut to fit)")
    ap.add_argument("--batch", type=int, default=32)
    ap.add_argument("--lr", type=float, default=2e-3)
    ap.add_argument("--threads", type=int, default=2, help="processes generating data, and torch threads")
    ap.add_argument("--torch-threads", type=int, default=0, help="torch threads if not --threads (1 is faster "
                                                                  "than 2 on a busy machine)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    args = ap.parse_args()

    import torch

    from artipg.metrics.pointnet_torch import build_model, export_encoder

    torch.set_num_threads(args.torch_threads or args.threads)
    torch.manual_seed(args.seed)
    rng = np.random.default_rng(args.seed)
    categories = artipg.categories()
    t0 = time.perf_counter()
    X, y = make_split(categories, args.per_category, 0, args.threads)
    Xt, yt = make_split(categories, args.test_per_category, TEST_SEED0, args.threads)
    t_data = time.perf_counter() - t0
    print(f"{len(categories)} categories, {len(X)} training / {len(Xt)} test clouds, generated in {t_data:.0f} s")

    model = build_model(len(categories))
    opt = torch.optim.AdamW(model.parameters(), lr=args.lr, weight_decay=1e-4)
    loss_fn = torch.nn.CrossEntropyLoss(label_smoothing=0.1)
    t1 = time.perf_counter()
    epochs, epoch = args.epochs, 0
    while epoch < epochs:
        model.train()
        lr = args.lr * 0.5 * (1 + np.cos(np.pi * epoch / epochs))
        for g in opt.param_groups:
            g["lr"] = lr
        order = rng.permutation(len(X))
        total, correct, seen = 0.0, 0, 0
        for s in range(0, len(order) - args.batch + 1, args.batch):
            idx = order[s:s + args.batch]
            pick = rng.random((len(idx), CLOUD_POINTS)).argsort(axis=1)[:, :args.points]
            pts = np.take_along_axis(X[idx], pick[:, :, None], axis=1).astype(np.float64)
            pts = pts * rng.uniform(0.85, 1.15, size=(len(idx), 1, 3)) + rng.normal(0, 0.002, size=pts.shape)
            xb = torch.from_numpy(normalize_bbox(pts).astype(np.float32))
            yb = torch.from_numpy(y[idx])
            logits = model(xb)
            loss = loss_fn(logits, yb)
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += float(loss.detach()) * len(idx)
            correct += int((logits.argmax(1) == yb).sum())
            seen += len(idx)
        epoch += 1
        elapsed = time.perf_counter() - t1
        # fit the schedule into the time budget (re-estimated every epoch: the machine may be shared)
        epochs = min(epochs, epoch + int(max(0.0, args.time_budget - elapsed) // (elapsed / epoch)))
        print(f"epoch {epoch}/{epochs}: loss {total / seen:.3f}, train acc {correct / seen:.3f}, lr {lr:.2e}, "
              f"{elapsed:.0f} s")
    t_train = time.perf_counter() - t1

    model.eval()
    enc = export_encoder(model, categories)
    pred = enc.logits(Xt).argmax(axis=1)
    acc = float(np.mean(pred == yt))
    per_class = {c: float(np.mean(pred[yt == i] == i)) for i, c in enumerate(categories)}
    train_pred = enc.logits(X[:: max(1, len(X) // 1000)]).argmax(axis=1)
    train_acc = float(np.mean(train_pred == y[:: max(1, len(X) // 1000)]))
    enc.meta = {"artipg_version": artipg.__version__, "categories": categories, "train_per_category": args.per_category,
                "test_per_category": args.test_per_category, "train_points": args.points,
                "test_points": CLOUD_POINTS, "epochs": epochs, "train_seconds": round(t_train),
                "torch_threads": torch.get_num_threads(), "test_accuracy": round(acc, 4), "train_accuracy": round(train_acc, 4),
                "test_accuracy_per_category": {k: round(v, 4) for k, v in per_class.items()},
                "train_seeds": [0, args.per_category - 1], "test_seeds": [TEST_SEED0, TEST_SEED0 + args.test_per_category - 1]}
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_bytes(npz_bytes(enc.to_arrays()))
    print(f"trained {epochs} epochs in {t_train:.0f} s on {torch.get_num_threads()} torch threads; test accuracy (numpy encoder, "
          f"{CLOUD_POINTS} points) {acc:.3f}, train {train_acc:.3f}")
    print(json.dumps(per_class, indent=1))
    print(f"wrote {args.out} ({args.out.stat().st_size / 1024:.0f} KiB)")


if __name__ == "__main__":
    main()
