"""Quick pictures of objects: shaded, label-coloured ray-cast images and grids.

>>> import artipg
>>> from artipg.viz import render_image, save_grid
>>> obj = artipg.generate("storage_furniture", 3)
>>> img = render_image(obj, qpos=obj.limits()[:, 1] * 0.7)       # (360, 480, 3) uint8
>>> save_grid([obj, (obj, obj.limits()[:, 1])], "grid.png")    # rest and open

CPU only (Embree ray casting through trimesh); needs Pillow only for :func:`save_grid`.
"""

from __future__ import annotations

import colorsys
from pathlib import Path

import numpy as np

from artipg.annotate.views import object_sphere, orbit_camera, render_view
from artipg.vocabulary import ACTIONABLE_ID

COLOR_BY = ("semantic", "instance", "link", "actionable")
BACKGROUND = np.array([255, 255, 255], dtype=np.uint8)


def palette(n: int) -> np.ndarray:
    """``n`` distinct RGB colours (n, 3) float in [0, 1]; colour i is the same for any n."""
    i = np.arange(n)
    h = (i * 0.618033988749895 + 0.05) % 1.0
    s = 0.55 + 0.35 * ((i // 3) % 2)
    v = 0.95 - 0.25 * ((i // 6) % 2)
    return np.array([colorsys.hsv_to_rgb(*x) for x in zip(h, s, v)]).reshape(n, 3)


def _label_image(obj, view, color_by: str) -> tuple[np.ndarray, int]:
    if color_by == "semantic":
        return view.semantic, 0
    if color_by == "instance":
        return view.instance, 0
    if color_by == "link":
        return view.link, 0
    if color_by == "actionable":
        act = np.array([ACTIONABLE_ID[p.actionable] for p in obj.parts] + [-1])
        return act[view.instance], 0
    raise ValueError(f"color_by must be one of {COLOR_BY}, got {color_by!r}")


def shade(labels: np.ndarray, normal: np.ndarray, light_dir: np.ndarray, colors: np.ndarray | None = None,
          ambient: float = 0.35) -> np.ndarray:
    """Lambert-shaded RGB image (H, W, 3) uint8 from a label image.

    Parameters
    ----------
    labels : (H, W) int
        Label per pixel, negative for background (drawn white).
    normal : (H, W, 3) float
        Unit normals (any frame, the same as ``light_dir``).
    light_dir : (3,) float
        Unit direction towards the light.
    colors : (K, 3) float in [0, 1], optional
        Colour per label; :func:`palette` by default.
    ambient : float
        Share of light that does not depend on the normal.
    """
    fg = labels >= 0
    k = int(labels.max()) + 1 if fg.any() else 1
    colors = palette(k) if colors is None else np.asarray(colors, dtype=float)
    lam = np.clip(normal @ np.asarray(light_dir, dtype=float), 0.0, 1.0)
    col = colors[np.clip(labels, 0, len(colors) - 1)] * (ambient + (1.0 - ambient) * lam)[..., None]
    img = np.where(fg[..., None], np.clip(col * 255.0 + 0.5, 0, 255), BACKGROUND).astype(np.uint8)
    return img


def render_image(obj, qpos=None, width: int = 480, height: int = 360, azimuth: float = 35.0,
                 elevation: float = 25.0, color_by: str = "semantic", fov_deg: float = 40.0) -> np.ndarray:
    """A shaded ray-cast picture of ``obj`` at joint state ``qpos``.

    Parameters
    ----------
    obj : ArticulatedObject
    qpos : None, dict or sequence
        Joint state (None: rest pose).
    width, height : int
        Image size in pixels.
    azimuth, elevation : float
        Viewing angles in degrees; azimuth 0 looks at the front (from -x), 90 from -y
        (see :mod:`artipg.annotate.views`).
    color_by : {"semantic", "instance", "link", "actionable"}
        Which label picks the colour (semantic colours are the same in every image).
    fov_deg : float
        Vertical field of view in degrees.

    Returns
    -------
    (height, width, 3) uint8 ndarray
    """
    c, r = object_sphere(obj, qpos)
    cam = orbit_camera(c, r, azimuth, elevation, width, height, fov_deg, margin=1.02)
    view = render_view(obj, cam, qpos)
    labels, _ = _label_image(obj, view, color_by)
    # head light, a little above and to the left of the camera
    light = -cam.pose[:3, 2] - 0.35 * cam.pose[:3, 1] - 0.25 * cam.pose[:3, 0]
    return shade(labels, view.normal, light / np.linalg.norm(light))


def _items(objs_with_qpos):
    for it in objs_with_qpos:
        if isinstance(it, tuple):
            yield it[0], (it[1] if len(it) > 1 else None)
        else:
            yield it, None


def save_grid(objs_with_qpos, path, ncols: int = 4, width: int = 320, height: int = 240, titles=None,
              **render_kw) -> Path:
    """Render several objects into one grid PNG.

    Parameters
    ----------
    objs_with_qpos : iterable
        Objects, or ``(obj, qpos)`` tuples.
    path : str or Path
        Output PNG file (parent folders are created).
    ncols : int
        Images per row.
    width, height : int
        Size of each cell in pixels.
    titles : list of str, optional
        One caption per cell; default ``"<category> <seed>"``.
    **render_kw
        Passed to :func:`render_image` (``azimuth``, ``elevation``, ``color_by`` ...).

    Returns
    -------
    Path
        The written file.
    """
    from PIL import Image, ImageDraw

    items = list(_items(objs_with_qpos))
    if not items:
        raise ValueError("save_grid needs at least one object")
    ncols = max(1, min(ncols, len(items)))
    nrows = (len(items) + ncols - 1) // ncols
    grid = Image.new("RGB", (ncols * width, nrows * height), tuple(int(x) for x in BACKGROUND))
    draw = ImageDraw.Draw(grid)
    for i, (obj, q) in enumerate(items):
        img = render_image(obj, q, width=width, height=height, **render_kw)
        x, y = (i % ncols) * width, (i // ncols) * height
        grid.paste(Image.fromarray(img), (x, y))
        title = titles[i] if titles is not None else f"{obj.category} {obj.seed}"
        draw.text((x + 4, y + 3), title, fill=(0, 0, 0))
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    grid.save(path, optimize=True)
    return path
