"""Textured gallery: per category, a row of seeds rendered in colour with their visual
materials (Mitsuba 3, the ``render`` extra), at rest and half opened, written to
docs/images/appearance/<category>.png, and one picture per category side by side in
docs/images/appearance_gallery.png.

Usage: python scripts/render_appearance.py [--categories a b] [--seeds 6] [--spp 32]
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw

import artipg
from artipg.annotate.views import fit_camera
from artipg.appearance.rgb import build_scene, render_rgb


def opened(obj, frac: float) -> np.ndarray:
    """Joint vector with every movable joint at ``frac`` of its range (continuous: frac * pi/2)."""
    lim = obj.limits()
    q = lim[:, 0] + frac * (lim[:, 1] - lim[:, 0])
    q[[j.type == "continuous" for j in obj.movable_joints]] = frac * np.pi / 2
    return q


def tile(obj, qpos, size: int, spp: int, title: str) -> Image.Image:
    """One colour render of ``obj`` at ``qpos``, ``size`` pixels square, titled."""
    cam = fit_camera(obj, qpos, azimuth=35.0, elevation=22.0, width=size, height=size, fill=0.85)
    rgb, _ = render_rgb(build_scene(obj, qpos), cam, spp=spp, seed=obj.seed, background=(0.93, 0.93, 0.93))
    im = Image.fromarray(rgb)
    ImageDraw.Draw(im).text((4, 2), title, fill=(40, 40, 40))
    return im


def category_strip(category: str, seeds, size: int, spp: int) -> Image.Image:
    """Top row: the seeds at rest; bottom row: half opened."""
    objs = [artipg.generate(category, s) for s in seeds]
    top = [tile(o, None, size, spp, f"{o.subcategory} #{o.seed}") for o in objs]
    bottom = [tile(o, opened(o, 0.5), size, spp, f"opened #{o.seed}") for o in objs]
    out = Image.new("RGB", (size * len(objs), 2 * size), "white")
    for i, (a, b) in enumerate(zip(top, bottom)):
        out.paste(a, (i * size, 0))
        out.paste(b, (i * size, size))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--categories", nargs="*", default=None)
    ap.add_argument("--seeds", type=int, default=6)
    ap.add_argument("--size", type=int, default=220)
    ap.add_argument("--spp", type=int, default=32)
    ap.add_argument("--out", type=Path, default=Path("docs/images"))
    args = ap.parse_args()
    cats = args.categories or artipg.categories()
    (args.out / "appearance").mkdir(parents=True, exist_ok=True)
    firsts = []
    for c in cats:
        strip = category_strip(c, range(args.seeds), args.size, args.spp)
        strip.save(args.out / "appearance" / f"{c}.png", optimize=True)
        firsts.append((c, strip.crop((0, 0, args.size, args.size))))
        print(args.out / "appearance" / f"{c}.png")
    if args.categories is None:  # the overview needs every category
        cols, s = 9, args.size // 2
        rows = (len(firsts) + cols - 1) // cols
        grid = Image.new("RGB", (cols * s, rows * s), "white")
        for k, (c, im) in enumerate(firsts):
            im = im.resize((s, s), Image.LANCZOS)
            ImageDraw.Draw(im).rectangle((0, 0, s, 12), fill=(255, 255, 255))
            ImageDraw.Draw(im).text((3, 0), c, fill=(0, 0, 0))
            grid.paste(im, ((k % cols) * s, (k // cols) * s))
        grid.save(args.out / "appearance_gallery.png", optimize=True)


if __name__ == "__main__":
    main()
