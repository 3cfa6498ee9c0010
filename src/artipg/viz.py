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

from artipg.annotate.views import fit_camera, object_sphere, render_view
from artipg.vocabulary import ACTIONABLE_ID, AFFORDANCES, SEMANTIC_LABELS, label_id

COLOR_BY = ("semantic", "instance", "link", "actionable")
#: Share of a glass pane's own colour in pictures; the rest is what lies behind it.
GLASS_TINT = 0.35
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
    cam = fit_camera(obj, qpos, azimuth, elevation, width, height, fov_deg)
    view = render_view(obj, cam, qpos)
    labels, _ = _label_image(obj, view, color_by)
    # head light, a little above and to the left of the camera
    light = -cam.pose[:3, 2] - 0.35 * cam.pose[:3, 1] - 0.25 * cam.pose[:3, 0]
    light /= np.linalg.norm(light)
    img = shade(labels, view.normal, light)
    glass = view.semantic == label_id("glass")
    if glass.any():  # panes tint what lies behind them (a clock's hands, an oven's racks)
        behind = render_view(obj, cam, qpos, exclude=("glass",))
        back = shade(_label_image(obj, behind, color_by)[0], behind.normal, light)
        img[glass] = np.rint(GLASS_TINT * img[glass] + (1.0 - GLASS_TINT) * back[glass]).astype(np.uint8)
    return img


def _items(objs_with_qpos):
    for it in objs_with_qpos:
        if isinstance(it, tuple):
            yield it[0], (it[1] if len(it) > 1 else None)
        else:
            yield it, None


#: Height in pixels of one row of a picture's colour key.
LEGEND_ROW = 16


def semantic_legend(objs) -> list[tuple[str, np.ndarray]]:
    """(label, RGB colour in [0, 1]) of every semantic label the parts of ``objs`` carry,
    in vocabulary order: the key of the semantic colours of :func:`render_image`."""
    ids = sorted({label_id(p.semantic) for o in objs for p in o.parts})
    colors = palette(ids[-1] + 1) if ids else np.zeros((0, 3))
    return [(SEMANTIC_LABELS[i], colors[i]) for i in ids]


def _legend_rows(legend, width: int) -> list[list[tuple[int, str, np.ndarray]]]:
    """Lay ``legend`` entries out left to right in rows of ``width`` pixels: (x, name, colour)."""
    rows, row, x = [], [], 6
    for name, c in legend:
        w = 20 + 6 * len(name)
        if row and x + w > width:
            rows.append(row)
            row, x = [], 6
        row.append((x, name, c))
        x += w + 8
    return rows + ([row] if row else [])


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
        Semantic colours (the default) get a colour key of the labels shown below the grid.

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
    legend = semantic_legend([o for o, _ in items]) if render_kw.get("color_by", "semantic") == "semantic" else []
    rows = _legend_rows(legend, ncols * width)
    grid = Image.new("RGB", (ncols * width, nrows * height + LEGEND_ROW * len(rows)),
                     tuple(int(x) for x in BACKGROUND))
    draw = ImageDraw.Draw(grid)
    for i, (obj, q) in enumerate(items):
        img = render_image(obj, q, width=width, height=height, **render_kw)
        x, y = (i % ncols) * width, (i // ncols) * height
        grid.paste(Image.fromarray(img), (x, y))
        title = titles[i] if titles is not None else f"{obj.category} {obj.seed}"
        draw.text((x + 4, y + 3), title, fill=(0, 0, 0))
    for r, row in enumerate(rows):  # colour key of the semantic labels shown
        y = nrows * height + r * LEGEND_ROW + 3
        for x, name, c in row:
            draw.rectangle((x, y + 1, x + 9, y + 10), fill=tuple(int(255 * v) for v in c))
            draw.text((x + 13, y), name, fill=(0, 0, 0))
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    grid.save(path, optimize=True)
    return path


# ---------------------------------------------------------------- point clouds and grasps

#: Colours of the affordances (grasp, pull, push, lift, rotate, press) in pictures.
AFFORDANCE_COLORS = np.array([[0.95, 0.75, 0.05], [0.9, 0.2, 0.15], [0.2, 0.45, 0.95], [0.6, 0.25, 0.85],
                              [0.1, 0.75, 0.45], [0.95, 0.45, 0.7]])
_NEUTRAL = np.array([0.78, 0.78, 0.78])


def splat_points(cam, points: np.ndarray, colors: np.ndarray, normals: np.ndarray | None = None,
                 radius: int = 1, ambient: float = 0.45) -> tuple[np.ndarray, np.ndarray]:
    """Draw points as small discs with a z-buffer.

    Parameters
    ----------
    cam : artipg.annotate.views.Camera
    points : (N, 3) array
        Object frame, metres.
    colors : (N, 3) array
        RGB in [0, 1].
    normals : (N, 3) array, optional
        Unit normals for head-light shading (sign ignored).
    radius : int
        Disc radius in pixels.

    Returns
    -------
    rgb : (H, W, 3) float
        Colours (undefined where nothing is drawn).
    depth : (H, W) float
        Depth along the optical axis, +inf where nothing is drawn.
    """
    H, W = cam.height, cam.width
    Ti = np.linalg.inv(cam.pose)
    pc = points @ Ti[:3, :3].T + Ti[:3, 3]
    front = pc[:, 2] > 1e-6
    pc, col = pc[front], np.asarray(colors, dtype=float)[front]
    if normals is not None:
        nc = np.asarray(normals, dtype=float)[front] @ Ti[:3, :3].T
        col = col * (ambient + (1 - ambient) * np.abs(nc[:, 2]))[:, None]
    u = pc[:, 0] / pc[:, 2] * cam.K[0, 0] + cam.K[0, 2]
    v = pc[:, 1] / pc[:, 2] * cam.K[1, 1] + cam.K[1, 2]
    off = np.array([(dy, dx) for dy in range(-radius, radius + 1) for dx in range(-radius, radius + 1)
                    if dx * dx + dy * dy <= radius * radius + radius])
    rows = (np.floor(v)[:, None] + off[None, :, 0]).astype(np.int64)
    cols = (np.floor(u)[:, None] + off[None, :, 1]).astype(np.int64)
    ok = (rows >= 0) & (rows < H) & (cols >= 0) & (cols < W)
    pix = (rows * W + cols)[ok]
    z = np.broadcast_to(pc[:, 2:3], rows.shape)[ok]
    idx = np.broadcast_to(np.arange(len(pc))[:, None], rows.shape)[ok]
    order = np.lexsort((z, pix))
    pix, z, idx = pix[order], z[order], idx[order]
    first = np.ones(len(pix), dtype=bool)
    first[1:] = pix[1:] != pix[:-1]
    rgb = np.zeros((H * W, 3))
    depth = np.full(H * W, np.inf)
    rgb[pix[first]] = col[idx[first]]
    depth[pix[first]] = z[first]
    return rgb.reshape(H, W, 3), depth.reshape(H, W)


def _mesh_layer(cam, mesh, face_colors: np.ndarray, ambient: float = 0.35) -> tuple[np.ndarray, np.ndarray]:
    """Ray-cast ``mesh`` (object frame): shaded colours (H, W, 3) and depth (H, W)."""
    from artipg.annotate.views import _face_normals, camera_rays, cast_rays

    H, W = cam.height, cam.width
    o, d, cosang = camera_rays(cam)
    t, face = cast_rays(mesh, np.ascontiguousarray(o), d)
    hit = face >= 0
    depth = np.where(hit, t * cosang, np.inf)
    rgb = np.zeros((H * W, 3))
    n = _face_normals(mesh, face[hit])
    lam = np.abs(np.einsum("ij,ij->i", n, d[hit]))
    rgb[hit] = face_colors[face[hit]] * (ambient + (1 - ambient) * lam)[:, None]
    return rgb.reshape(H, W, 3), depth.reshape(H, W)


def _compose(layers) -> np.ndarray:
    """Nearest-first composition of (rgb, depth) layers on white; (H, W, 3) uint8."""
    rgb = np.stack([l[0] for l in layers])
    depth = np.stack([l[1] for l in layers])
    k = np.argmin(depth, axis=0)
    out = np.take_along_axis(rgb, k[None, ..., None], axis=0)[0]
    bg = ~np.isfinite(np.min(depth, axis=0))
    out[bg] = 1.0
    return np.clip(out * 255 + 0.5, 0, 255).astype(np.uint8)


def _grasp_layer(cam, grasps, length: float):
    """Gripper boxes (green: collision-free, red: colliding) and opening arrows."""
    import trimesh

    from artipg.annotate.grasps import DEFAULT_GRIPPER, mesh_gripper

    if not len(grasps):
        return []
    meshes, cols = [], []
    for k in range(len(grasps)):
        m = mesh_gripper(grasps.pose[k], float(grasps.width[k]), DEFAULT_GRIPPER)
        meshes.append(m)
        c = (0.1, 0.8, 0.2) if grasps.collision_free[k] else (0.9, 0.15, 0.1)
        cols.append(np.tile(c, (len(m.faces), 1)))
    layers = [_mesh_layer(cam, trimesh.util.concatenate(meshes), np.concatenate(cols))]
    # opening direction: a dotted blue segment from each grasp point
    s = np.linspace(0.0, length, 24)
    pts = (grasps.pose[:, None, :3, 3] + s[None, :, None] * grasps.open_dir[:, None]).reshape(-1, 3)
    has = np.repeat(np.any(grasps.open_dir != 0, axis=1), len(s))
    if has.any():
        layers.append(splat_points(cam, pts[has], np.tile([0.1, 0.3, 1.0], (int(has.sum()), 1)), radius=1))
    return layers


def render_annotations(obj, qpos=None, width: int = 400, height: int = 300, azimuth: float = 35.0,
                       elevation: float = 25.0, n_points: int = 16384, seed: int = 0) -> np.ndarray:
    """A 2 x 2 picture of an object's annotations at ``qpos``.

    Panels: labelled points coloured by semantic label with the grasp poses (gripper
    boxes green when collision-free, red otherwise, blue dots along the opening
    direction); affordance regions; part NPCS (RGB = npcs + 0.5, actionable parts
    only); a partial view from an upper-hemisphere camera (instance labels, the rest
    of the complete cloud in light grey).

    Returns
    -------
    (2 * height, 2 * width, 3) uint8 ndarray
    """
    from PIL import Image, ImageDraw

    from artipg.annotate.grasps import world_grasps
    from artipg.annotate.labels import point_labels
    from artipg.annotate.views import partial_views

    c, r = object_sphere(obj, qpos)
    cam = fit_camera(obj, qpos, azimuth, elevation, width, height, 40.0, fill=0.85)
    pc = obj.sample_points(n_points, seed=seed, qpos=qpos)
    lab = point_labels(obj, pc.points, pc.primitive, qpos)
    sem_col = palette(int(pc.semantic.max()) + 1)[pc.semantic]
    g = world_grasps(obj, qpos)
    panels = []
    layers = [splat_points(cam, pc.points, sem_col, pc.normals)] + _grasp_layer(cam, g, 0.06 * r / 0.5)
    panels.append(("semantic labels + grasps", _compose(layers)))
    aff = lab.affordance
    col = np.tile(_NEUTRAL, (len(aff), 1))
    for k in range(aff.shape[1] - 1, -1, -1):  # earlier affordances drawn on top
        col[aff[:, k]] = AFFORDANCE_COLORS[k]
    panels.append(("affordances:", _compose([splat_points(cam, pc.points, col, pc.normals)])))
    legend = [(n, AFFORDANCE_COLORS[k]) for k, n in enumerate(AFFORDANCES) if aff[:, k].any()]
    col = np.where((lab.actionable > 0)[:, None], lab.npcs + 0.5, _NEUTRAL)
    panels.append(("part NPCS (actionable parts)", _compose([splat_points(cam, pc.points, col, pc.normals)])))
    view = partial_views(obj, 1, 4096, qpos, seed=seed + 1, width=320, height=240, azimuth_range=(10.0, 80.0))[0]
    icol = palette(len(obj.parts) + 1)[view.instance]
    panels.append((f"partial view (az {view.camera.azimuth:.0f}, el {view.camera.elevation:.0f})",
                   _compose([splat_points(cam, view.points, icol, radius=1),
                             splat_points(cam, pc.points, np.tile([0.9, 0.9, 0.9], (len(pc.points), 1)), radius=1)])))
    grid = Image.new("RGB", (2 * width, 2 * height), (255, 255, 255))
    draw = ImageDraw.Draw(grid)
    for i, (title, img) in enumerate(panels):
        x, y = (i % 2) * width, (i // 2) * height
        grid.paste(Image.fromarray(img), (x, y))
        draw.text((x + 4, y + 3), title, fill=(0, 0, 0))
    for r, row in enumerate(_legend_rows(semantic_legend([obj]), width)):  # colour key of the semantic panel
        for x, name, c in row:
            y = 17 + r * LEGEND_ROW
            draw.rectangle((x, y + 1, x + 9, y + 10), fill=tuple(int(255 * v) for v in c))
            draw.text((x + 13, y), name, fill=(0, 0, 0))
    x = width + 78
    for name, c in legend:  # colour key of the affordance panel
        draw.rectangle((x, 4, x + 8, 12), fill=tuple(int(255 * v) for v in c))
        draw.text((x + 11, 3), name, fill=(0, 0, 0))
        x += 16 + 7 * len(name)
    draw.text((4, 2 * height - 14), f"{obj.category} / {obj.subcategory}  seed {obj.seed}", fill=(0, 0, 0))
    return np.asarray(grid)
