"""RGB views with materials (Mitsuba 3 on the CPU): deterministic per seed and aligned
with the label images of the partial views."""

from __future__ import annotations

import numpy as np
import pytest

import artipg

pytest.importorskip("mitsuba")


@pytest.mark.parametrize("category", ["storage_furniture", "window", "kettle"])
def test_rgb_view_lines_up_with_the_label_image(category):
    from artipg.annotate.views import fit_camera, render_view
    from artipg.appearance.rgb import build_scene, render_rgb

    obj = artipg.generate(category, 3)
    cam = fit_camera(obj, None, width=640, height=480)  # the size: silhouettes are a smaller share
    rgb, cov = render_rgb(build_scene(obj), cam, spp=4, seed=1)
    labels = render_view(obj, cam).instance
    obj_px, hit = labels >= 0, cov > 0.5
    assert obj_px.mean() > 0.05
    # the same pixels are object in both images (silhouette pixels may differ by a hair)
    assert (hit == obj_px)[obj_px | hit].mean() > 0.99
    # the object is drawn, not left in the background colour
    assert np.abs(rgb[obj_px].astype(int) - rgb[~obj_px & ~hit].mean(axis=0)).sum(axis=1).mean() > 10


def test_rgb_view_is_deterministic_per_seed():
    from artipg.annotate.views import fit_camera
    from artipg.appearance.rgb import build_scene, random_lighting, render_rgb

    obj = artipg.generate("microwave", 2)
    cam = fit_camera(obj, None, width=96, height=72)
    light = random_lighting(np.random.default_rng(5))
    scene = build_scene(obj, sun=light["sun"], sky=light["sky"])
    a = render_rgb(scene, cam, spp=2, seed=3, background=light["background"])[0]
    b = render_rgb(build_scene(obj, sun=light["sun"], sky=light["sky"]), cam, spp=2, seed=3,
                   background=light["background"])[0]
    assert a.tobytes() == b.tobytes()
    assert random_lighting(np.random.default_rng(5)) == light != random_lighting(np.random.default_rng(6))


def test_rgb_of_the_partial_views_uses_their_cameras():
    from artipg.annotate.arrays import view_arrays
    from artipg.appearance.rgb import rgb_view_arrays

    obj = artipg.generate("storage_furniture", 1)
    views = view_arrays(obj, 2, 256, seed=obj.seed, width=160, height=120)
    out = rgb_view_arrays(obj, views, spp=2, seed=obj.seed, randomize=True)
    assert out["rgb"].shape == (2, 120, 160, 3) and out["rgb"].dtype == np.uint8
    obj_px, hit = views["instance_image"] >= 0, out["rgb_coverage"] > 0.5
    assert (hit == obj_px)[obj_px | hit].mean() > 0.98  # silhouettes weigh more at 160 x 120
    # randomised backgrounds differ between the views
    bg = [out["rgb"][i][~obj_px[i] & ~hit[i]].mean(axis=0) for i in range(2)]
    assert np.abs(bg[0] - bg[1]).sum() > 5


def test_generate_writes_colour_views_aligned_with_the_label_views(tmp_path):
    """``artipg generate --views 1 --rgb random`` adds views_rgb.npz, one colour image per
    view of views.npz, the same size, and lists it in annotation.json."""
    import json
    import subprocess
    import sys

    r = subprocess.run([sys.executable, "-m", "artipg.cli", "generate", "box", "-n", "1", "--views", "1", "--rgb",
                        "random", "--out", str(tmp_path), "-q", "--no-validate"], capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stderr
    folder = tmp_path / "box" / "0"
    with np.load(folder / "views_rgb.npz") as c, np.load(folder / "views.npz") as v:
        assert c["rgb"].shape[:3] == v["depth"].shape and c["rgb"].dtype == np.uint8
        assert c["rgb"].std() > 0
    listed = {f["path"] for f in json.loads((folder / "annotation.json").read_text())["files"]}
    assert "views_rgb.npz" in listed
