"""Pictures: label colours carry a key that names exactly the labels shown."""

from __future__ import annotations

import numpy as np
from PIL import Image

import artipg
from artipg.viz import LEGEND_ROW, palette, save_grid, semantic_legend
from artipg.vocabulary import label_id


def test_semantic_legend_names_the_labels_of_the_objects_with_their_colours():
    objs = [artipg.generate("microwave", 1), artipg.generate("faucet", 2)]
    legend = semantic_legend(objs)
    names = [n for n, _ in legend]
    assert set(names) == {p.semantic for o in objs for p in o.parts}
    assert names == sorted(names, key=label_id)  # vocabulary order
    for name, c in legend:
        assert np.allclose(c, palette(label_id(name) + 1)[label_id(name)])


def test_grid_has_a_key_below_semantic_pictures_only(tmp_path):
    obj = artipg.generate("microwave", 1)
    a = Image.open(save_grid([obj], tmp_path / "a.png", width=200, height=150))
    b = Image.open(save_grid([obj], tmp_path / "b.png", width=200, height=150, color_by="instance"))
    assert b.size == (200, 150)
    assert a.size[0] == 200 and a.size[1] > 150 and (a.size[1] - 150) % LEGEND_ROW == 0
    key = np.asarray(a)[150:]
    # every legend colour appears in the key strip
    for _, c in semantic_legend([obj]):
        rgb = np.array([int(255 * v) for v in c])
        assert (np.abs(key.astype(int) - rgb).sum(axis=2) == 0).any()
