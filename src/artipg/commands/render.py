"""``artipg render``: a picture of an object's annotations (or a shaded view)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from artipg.commands import fail


def register(app: typer.Typer) -> None:
    @app.command()
    def render(
        category: str = typer.Argument(..., help="Category name (see 'artipg categories')."),
        seed: int = typer.Option(0, "--seed", "-s", help="Object seed."),
        open_frac: float = typer.Option(0.6, "--open", help="Every movable joint at this fraction of its range "
                                                            "(0 = rest, 1 = fully open)."),
        out: Optional[Path] = typer.Option(None, "--out", "-o", help="PNG file (default <category>_<seed>.png)."),
        kind: str = typer.Option("annotations", "--kind", help="'annotations' (labelled points, grasps, "
                                                               "affordances, NPCS, a partial view) or "
                                                               "'semantic' / 'instance' / 'link' / 'actionable' "
                                                               "(a shaded view coloured by that label)."),
        width: int = typer.Option(400, "--width", help="Width of one panel in pixels."),
        height: int = typer.Option(300, "--height", help="Height of one panel in pixels."),
        azimuth: float = typer.Option(35.0, "--azimuth", help="Degrees; 0 looks at the front (from -x)."),
        elevation: float = typer.Option(25.0, "--elevation", help="Degrees above the horizon."),
    ) -> None:
        """Render one object to a PNG so a person can check its annotations."""
        import numpy as np
        from PIL import Image

        import artipg
        from artipg.viz import COLOR_BY, render_annotations, render_image

        if category not in artipg.categories():
            fail(f"unknown category {category!r}; valid categories: {', '.join(artipg.categories())}")
        if seed < 0:
            fail(f"--seed must be >= 0, got {seed}")
        if not 0.0 <= open_frac <= 1.0:
            fail(f"--open must be in [0, 1], got {open_frac}")
        if kind != "annotations" and kind not in COLOR_BY:
            fail(f"--kind must be 'annotations' or one of {', '.join(COLOR_BY)}, got {kind!r}")
        if width < 16 or height < 16:
            fail(f"--width and --height must be at least 16, got {width}x{height}")
        obj = artipg.generate(category, seed)
        lim = obj.limits()
        lo = np.where(np.isfinite(lim[:, 0]), lim[:, 0], -np.pi)
        hi = np.where(np.isfinite(lim[:, 1]), lim[:, 1], np.pi)
        # open towards the side of 0 with the larger range (0 = rest)
        far = np.where(hi >= -lo, hi, lo)
        q = open_frac * far
        if kind == "annotations":
            img = render_annotations(obj, q, width=width, height=height, azimuth=azimuth, elevation=elevation)
        else:
            img = render_image(obj, q, width=width, height=height, azimuth=azimuth, elevation=elevation,
                               color_by=kind)
        path = out or Path(f"{category}_{seed}.png")
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            Image.fromarray(img).save(path, optimize=True)
        except OSError as e:
            fail(f"cannot write {str(path)!r}: {e.strerror or e}")
        typer.echo(f"wrote {path}")
