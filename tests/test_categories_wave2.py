"""Category-specific properties of display, globe, mug, pen, glue_stick and usb that the
shared per-category tests do not see: joint kinds per sub-category, the globe's axial
tilt, the portrait pivot's clearance, how a pen lies, the stein lid's lever stop."""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg

SEEDS = range(0, 60, 3)


def _kinds(obj) -> dict:
    return {j.child.rsplit("_", 1)[0]: (j.type, j.limits) for j in obj.movable_joints}


def _zmin(obj, name: str, qpos=None) -> float:
    i = next(k for k, p in enumerate(obj.parts) if p.name == name)
    return float(obj.sample_points(3000, seed=1, qpos=qpos, parts=[i]).points[:, 2].min())


def _zmax(obj, name: str, qpos=None) -> float:
    i = next(k for k, p in enumerate(obj.parts) if p.name == name)
    return float(obj.sample_points(3000, seed=1, qpos=qpos, parts=[i]).points[:, 2].max())


@pytest.mark.parametrize("seed", SEEDS)
def test_display_joints_and_portrait_clearance(seed):
    obj = artipg.generate("display", seed)
    k = _kinds(obj)
    if obj.subcategory == "ergonomic_monitor":
        kind, (lo, hi) = k["carriage"]
        assert kind == "prismatic" and hi == 0.0 and -0.18 <= lo <= -0.1  # rest = highest position
    if "screen" in k:  # portrait pivot: the screen's corners clear the base at every angle
        assert k["screen"][0] == "revolute" and k["screen"][1] == (0.0, math.pi / 2)
        screen = next(p.name for p in obj.parts if p.semantic == "screen")
        top = _zmax(obj, next(p.name for p in obj.parts if p.semantic == "base"))
        for a in np.linspace(0.0, math.pi / 2, 7):
            assert _zmin(obj, screen, {obj.joint("joint_screen_0").name: a}) > top + 0.005
    if "hinge" in k:
        lo, hi = k["hinge"][1]
        assert -0.1 < lo < 0.0 < hi <= 0.4  # tilts forward a little, back more


@pytest.mark.parametrize("seed", SEEDS)
def test_globe_spins_about_a_tilted_axis(seed):
    obj = artipg.generate("globe", seed)
    j = next(j for j in obj.joints if j.child.startswith("sphere"))
    assert j.type == "continuous"
    link = next(i for i, lk in enumerate(obj.links) if lk.name == j.child)
    axis = obj.link_poses()[link][:3, :3] @ j.axis
    assert math.degrees(math.acos(abs(axis[2]))) == pytest.approx(23.4, abs=0.3)
    k = _kinds(obj)
    assert ("meridian" in k) == (obj.subcategory != "desk_globe")


@pytest.mark.parametrize("seed", SEEDS)
def test_pen_lies_on_its_clip(seed):
    obj = artipg.generate("pen", seed)
    clip = next(p.name for p in obj.parts if p.semantic == "clip")
    assert _zmin(obj, clip) < 0.0005  # the clip's ball or bar touches the floor
    k = _kinds(obj)
    moving = {"click_pen": "button", "capped_pen": "cap", "twist_pen": "knob"}[obj.subcategory]
    assert moving in k and k[moving][1][0] == 0.0


@pytest.mark.parametrize("seed", SEEDS)
def test_glue_stick_has_twist_glue_and_cap(seed):
    obj = artipg.generate("glue_stick", seed)
    k = _kinds(obj)
    assert k["knob"][0] == "continuous" and k["glue"][0] == "prismatic" and k["cap"][0] == "prismatic"
    assert 0.003 < k["glue"][1][1] < 0.013  # the glue rises no further than the cap's headroom


@pytest.mark.parametrize("seed", SEEDS)
def test_usb_moving_part_per_subcategory(seed):
    obj = artipg.generate("usb", seed)
    kind, (lo, hi) = _kinds(obj)[{"capped": "cap", "swivel": "cover", "retractable": "carriage"}[obj.subcategory]]
    if obj.subcategory == "swivel":
        assert kind == "revolute" and (lo, hi) == (0.0, math.pi)
    else:
        assert kind == "prismatic" and 0.006 < hi < 0.03


@pytest.mark.parametrize("seed", SEEDS)
def test_mug_lid_opens_clear_of_the_handle(seed):
    obj = artipg.generate("mug", seed)
    j = obj.movable_joints[0]
    lo, hi = j.limits
    assert lo == 0.0 and hi > 0.0
    if obj.subcategory == "beer_stein":
        assert 0.5 <= hi <= 1.9 and j.axis.tolist() == [0.0, 1.0, 0.0]
