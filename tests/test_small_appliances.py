"""Category-specific facts of toasters, remotes, keyboards and suitcases: the joints
each real object has, and the key layouts' counts."""

import numpy as np
import pytest

import artipg
from artipg.templates.keyboard import ansi_layout, cell_boxes

SEEDS = range(12)


def _joints(obj, name):
    return [j for j in obj.movable_joints if j.child.startswith(name)]


@pytest.mark.parametrize("layout, keys", [((True, True, True), 104), ((True, True, False), 87),
                                          ((False, False, False), 61)])
def test_ansi_layouts_count_their_keys_and_tile_the_field(layout, keys):
    cells, w, h = ansi_layout(*layout)
    assert sum(c[4] == "k" for c in cells) == keys
    assert sum(c[2] * c[3] for c in cells) == pytest.approx(w * h)  # keys and ribs leave no hole
    k, r = cell_boxes(cells, 0.019, 0.0015, (w, h))
    assert len(k) == keys and np.all(k[:, 2:] > 0.0) and np.all(r[:, 2:] > 0.0)


def test_keyboard_escape_is_at_the_typists_back_left():
    cells, w, h = ansi_layout(True, True, True)
    keys, _ = cell_boxes(cells, 0.019, 0.0015, (w, h))
    esc = keys[[c[:2] for c in cells if c[4] == "k"].index((0, 0))]
    assert esc[0] > 0 and esc[1] > 0  # back (+x) and the typist's left (+y: the typist faces +x from -x)


def test_keyboards_press_every_key_down():
    for seed in SEEDS:
        obj = artipg.generate("keyboard", seed)
        keys = _joints(obj, "key")
        assert len(keys) >= 60 and all(j.type == "prismatic" for j in keys)
        assert all(np.allclose(j.axis, (0, 0, -1)) and 0.001 <= j.limits[1] <= 0.0045 for j in keys)
        assert len(_joints(obj, "foot")) == 2


def test_toasters_have_levers_knobs_and_a_crumb_tray():
    for seed in SEEDS:
        obj = artipg.generate("toaster", seed)
        levers, knobs, tray = _joints(obj, "lever"), _joints(obj, "knob"), _joints(obj, "tray")
        assert len(levers) == (2 if obj.subcategory == "four_slot" else 1)
        assert all(j.type == "prismatic" and np.allclose(j.axis, (0, 0, -1)) and j.limits[1] >= 0.03 for j in levers)
        assert len(knobs) >= 1 and all(j.type == "revolute" for j in knobs)
        assert len(tray) == 1 and np.allclose(tray[0].axis, (-1, 0, 0))


def test_remotes_have_buttons_and_a_sliding_battery_cover():
    for seed in SEEDS:
        obj = artipg.generate("remote", seed)
        buttons = _joints(obj, "button")
        assert len(buttons) >= 6 and all(j.type == "prismatic" and j.limits[1] <= 0.0025 for j in buttons)
        cover = _joints(obj, "cover")
        assert len(cover) == 1 and cover[0].type == "prismatic"


def test_suitcases_roll_and_extend_their_handle():
    for seed in SEEDS:
        obj = artipg.generate("suitcase", seed)
        wheels = _joints(obj, "wheel")
        assert len(wheels) == (2 if obj.subcategory == "two_wheel" else 4)
        assert all(j.type == "continuous" for j in wheels)
        (tele,) = _joints(obj, "telescopic")
        assert tele.type == "prismatic" and np.allclose(tele.axis, (0, 0, 1)) and tele.limits[1] >= 0.15
        assert len(_joints(obj, "lid")) == 1
