"""Detail pictures: per category, the same seeds without geometric detail (top rows)
and with procedural detail (bottom rows), written to docs/images/detail/<category>.png.

Each seed gets a whole view at rest and a close-up of its upper front corner with its
joints 60 % open (a sphere of a tenth of the object's size, at least 2.5 cm), where
rounded edges, lips and raised panels show.

Usage: python scripts/render_detail.py [--categories a b] [--seeds 4] [--out docs/images/detail]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import artipg
from artipg.annotate.views import orbit_camera, render_view
from artipg.viz import BACKGROUND, _label_image, render_image, shade

AZIMUTH, ELEVATION = 35.0, 28.0


def opened(obj, frac: float = 0.6) -> np.ndarray:
    """Joint vector with every movable joint at ``frac`` of its range (lids and doors
    open, so rims and door edges show)."""
    lim = obj.limits()
    return lim[:, 0] + frac * (lim[:, 1] - lim[:, 0])


def close_up(obj, width: int, height: int) -> np.ndarray:
    """A shaded picture of the upper front corner of ``obj`` with its joints 60 % open
    (the corner of its rest bounding box at -x, -y, +z, pulled 8 % of the way to the
    centre)."""
    b = obj.bounds()
    c = 0.5 * (b[0] + b[1])
    corner = np.array([b[0, 0], b[0, 1], b[1, 2]])
    size = float(np.linalg.norm(b[1] - b[0]))
    target = corner + 0.08 * (c - corner)
    target[2] = b[1, 2] - 0.02 * (b[1, 2] - b[0, 2])
    cam = orbit_camera(target, max(0.1 * size, 0.025), AZIMUTH, ELEVATION, width, height, 40.0)
    view = render_view(obj, cam, opened(obj))
    labels, _ = _label_image(obj, view, "semantic")
    light = -cam.pose[:3, 2] - 0.35 * cam.pose[:3, 1] - 0.25 * cam.pose[:3, 0]
    return shade(labels, view.normal, light / np.linalg.norm(light))


def detail_sheet(category: str, out: Path, seeds=range(4), width: int = 300, height: int = 260) -> Path:
    """Write ``out/<category>.png``: one column pair (whole, close-up) per seed; row 1
    detail off, row 2 procedural."""
    from PIL import Image, ImageDraw

    cols = 2 * len(seeds)
    grid = Image.new("RGB", (cols * width, 2 * height), tuple(int(x) for x in BACKGROUND))
    draw = ImageDraw.Draw(grid)
    for row, level in enumerate(("off", "procedural")):
        for i, s in enumerate(seeds):
            obj = artipg.generate(category, s, detail=level)
            for k, img in enumerate((render_image(obj, width=width, height=height, azimuth=AZIMUTH,
                                                  elevation=ELEVATION), close_up(obj, width, height))):
                x, y = (2 * i + k) * width, row * height
                grid.paste(Image.fromarray(img), (x, y))
                draw.text((x + 4, y + 3), f"#{s} detail {level}" + (" (close-up)" if k else ""), fill=(0, 0, 0))
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"{category}.png"
    grid.save(path, optimize=True)
    return path


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=4)
    ap.add_argument("--out", type=Path, default=Path("docs/images/detail"))
    args = ap.parse_args()
    for c in args.categories or artipg.categories():
        print(detail_sheet(c, args.out, range(args.seeds)))


if __name__ == "__main__":
    main()
