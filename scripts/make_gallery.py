"""Gallery images: per category, 8 seeds rendered at rest (top row) and with every
joint opened to 80 % of its range (bottom row), written to docs/images/gallery/.

Usage: python scripts/make_gallery.py [--categories a b] [--out docs/images/gallery]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import artipg
from artipg.viz import save_grid


def opened(obj, frac: float = 0.8) -> np.ndarray:
    """Joint vector with every movable joint at ``frac`` of its range (continuous: frac * pi/2)."""
    lim = obj.limits()
    q = lim[:, 0] + frac * (lim[:, 1] - lim[:, 0])
    cont = np.array([j.type == "continuous" for j in obj.movable_joints], dtype=bool)
    q[cont] = frac * np.pi / 2
    return q


def gallery(category: str, out: Path, seeds=range(8)) -> Path:
    objs = [artipg.generate(category, s) for s in seeds]
    items = [*objs, *[(o, opened(o)) for o in objs]]
    titles = [f"{o.subcategory} #{o.seed}" for o in objs] + [f"opened #{o.seed}" for o in objs]
    return save_grid(items, out / f"{category}.png", ncols=len(objs), width=220, height=200, titles=titles)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--out", type=Path, default=Path("docs/images/gallery"))
    args = ap.parse_args()
    for c in args.categories or artipg.categories():
        print(gallery(c, args.out))


if __name__ == "__main__":
    main()
