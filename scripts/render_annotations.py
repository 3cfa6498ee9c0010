"""Render one annotation picture per registered category into docs/images/annotations/.

Each picture (see :func:`artipg.viz.render_annotations`) shows the labelled point
cloud with the grasp poses, the affordance regions, the part NPCS and a partial view,
with every movable joint at ``--open`` of its range.

Usage: python scripts/render_annotations.py [--categories a b] [--seed 0] [--open 0.6]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from PIL import Image

import artipg
from artipg.viz import render_annotations

OUT = Path(__file__).resolve().parents[1] / "docs" / "images" / "annotations"


def open_state(obj, frac: float) -> np.ndarray:
    """Each movable joint at ``frac`` of the way from rest to its far limit."""
    lim = obj.limits()
    lo = np.where(np.isfinite(lim[:, 0]), lim[:, 0], -np.pi)
    hi = np.where(np.isfinite(lim[:, 1]), lim[:, 1], np.pi)
    return frac * np.where(hi >= -lo, hi, lo)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--open", type=float, default=0.6, dest="frac")
    ap.add_argument("--out", type=Path, default=OUT)
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    for c in args.categories or artipg.categories():
        obj = artipg.generate(c, args.seed)
        img = render_annotations(obj, open_state(obj, args.frac))
        path = args.out / f"{c}.png"
        Image.fromarray(img).save(path, optimize=True)
        print(f"{path} ({path.stat().st_size // 1024} KB)")


if __name__ == "__main__":
    main()
