"""Category-specific properties of camera, mouse, phone and cart that the shared
per-category tests do not see: joint kinds and axes per sub-category, travel of
buttons, lenses pointing forward, zoom tubes extending, counts of duplicated parts."""

from __future__ import annotations

import numpy as np
import pytest

import artipg

SEEDS = range(0, 48, 3)


def _world_axis(obj, joint) -> np.ndarray:
    """Joint axis in the object frame at rest."""
    i = obj.link_index[joint.child]
    return obj.link_poses()[i][:3, :3] @ joint.axis


def _by_child(obj) -> dict:
    out: dict = {}
    for j in obj.movable_joints:
        out.setdefault(j.child.rsplit("_", 1)[0], []).append(j)
    return out


def _xmin(obj, qpos=None) -> float:
    return float(obj.bounds(qpos)[0, 0])


@pytest.mark.parametrize("seed", SEEDS)
def test_camera_joints_per_subcategory(seed):
    obj = artipg.generate("camera", seed)
    k = _by_child(obj)
    for j in k["button"]:  # shutter and top buttons: short presses into the body
        assert j.type == "prismatic" and 0.0005 < j.limits[1] <= 0.002
    if obj.subcategory == "dslr":
        (zoom,) = k["zoom_ring"]
        assert zoom.type == "revolute" and 1.0 < zoom.limits[1] < 1.7
        assert abs(_world_axis(obj, zoom) @ (-1.0, 0.0, 0.0)) == pytest.approx(1.0)  # the optical axis
        assert k["mode_dial"][0].type in ("revolute", "continuous")
        lens = [i for i, p in enumerate(obj.parts) if p.semantic in ("lens", "glass")]
        front = obj.sample_points(2000, seed=1, parts=lens).points[:, 0].min()
        assert front == pytest.approx(_xmin(obj), abs=2e-3)  # the lens is the front of the camera
    elif obj.subcategory == "compact":
        tubes = k["zoom_tube"]
        assert len(tubes) in (2, 3) and all(j.type == "prismatic" for j in tubes)
        assert all(_world_axis(obj, j) @ (-1.0, 0.0, 0.0) == pytest.approx(1.0) for j in tubes)
        hi = obj.limits()[:, 1]
        assert _xmin(obj, hi) < _xmin(obj) - 0.01  # the zoom comes out of the front
    else:
        (door,) = k["film_door"]
        assert door.type == "revolute" and door.limits[1] > 1.5
    if obj.subcategory != "instant":
        assert k["battery_door"][0].type == "revolute"


@pytest.mark.parametrize("seed", SEEDS)
def test_mouse_buttons_wheel_and_side_buttons(seed):
    obj = artipg.generate("mouse", seed)
    k = _by_child(obj)
    main = k["button"]
    assert len(main) == 2
    for j in main:
        axis = _world_axis(obj, j)
        if j.type == "revolute":  # about a rear hinge along y: the front drops 0.8-1.5 mm
            assert abs(axis[1]) == pytest.approx(1.0) and 0.005 < j.limits[1] < 0.03
        else:
            assert j.type == "prismatic" and axis[2] == pytest.approx(-1.0) and j.limits[1] <= 0.0015
    (wheel,) = k["scroll_wheel"]
    assert wheel.type == "continuous" and abs(_world_axis(obj, wheel)[1]) == pytest.approx(1.0)
    wheel_top = obj.sample_points(1500, seed=1, parts=[i for i, p in enumerate(obj.parts)
                                                       if p.semantic == "wheel"]).points[:, 2].max()
    caps_top = obj.sample_points(1500, seed=1, parts=[i for i, p in enumerate(obj.parts)
                                                      if p.semantic == "button"]).points[:, 2].max()
    assert wheel_top > caps_top - 0.005  # the wheel stands proud of the buttons next to it
    side = k.get("side_button", [])
    lo, hi = {"office": (0, 2), "gaming": (2, 5), "travel": (0, 0)}[obj.subcategory]
    assert lo <= len(side) <= hi
    assert all(j.type == "prismatic" and _world_axis(obj, j)[1] == pytest.approx(1.0) for j in side)


@pytest.mark.parametrize("seed", SEEDS)
def test_phone_joints_per_subcategory(seed):
    obj = artipg.generate("phone", seed)
    k = _by_child(obj)
    for j in k.get("key", []) + k["side_key"]:
        assert j.type == "prismatic" and 0.0003 < j.limits[1] <= 0.001
    assert all(abs(_world_axis(obj, j)[1]) == pytest.approx(1.0) for j in k["side_key"])  # into the sides
    if obj.subcategory == "flip":
        (lid,) = k["lid"]
        assert lid.type == "revolute" and 2.5 < lid.limits[1] < 3.0
        assert abs(_world_axis(obj, lid)[1]) == pytest.approx(1.0)
        hi = {lid.name: lid.limits[1] * 0.5}
        assert obj.bounds(hi)[1, 2] > obj.bounds()[1, 2] + 0.03  # half open, the lid stands up
    elif obj.subcategory == "slider":
        (lid,) = k["lid"]
        assert lid.type == "prismatic" and _world_axis(obj, lid)[0] == pytest.approx(1.0)
        assert len([j for j in k["key"] if j.parent != lid.child]) == 12  # the keypad under the lid
    if obj.subcategory in ("bar", "flip"):
        assert len(k["key"]) == 15  # a navigation row of 3 and a 3 x 4 keypad
    if obj.subcategory == "smartphone":
        assert "key" not in k and "lid" not in k and len(k["side_key"]) >= 2


@pytest.mark.parametrize("seed", SEEDS)
def test_cart_wheels_casters_and_folding_parts(seed):
    obj = artipg.generate("cart", seed)
    k = _by_child(obj)
    wheels = k["wheel"]
    assert all(j.type == "continuous" and abs(_world_axis(obj, j)[1]) == pytest.approx(1.0) for j in wheels)
    swivels = k.get("caster", [])
    assert all(j.type == "continuous" and _world_axis(obj, j)[2] == pytest.approx(1.0) for j in swivels)
    if obj.subcategory == "hand_truck":
        assert len(wheels) == 2 and not swivels
        (plate,) = k["nose_plate"]
        assert plate.type == "revolute" and plate.limits[1] == pytest.approx(np.pi / 2)
        up = obj.bounds({plate.name: np.pi / 2})
        assert up[0, 0] > obj.bounds()[0, 0] + 0.1  # folded up, the plate no longer reaches forward
    else:
        assert len(wheels) == 4 and len(swivels) in (2, 4)
        name = "seat_flap" if obj.subcategory == "shopping" else "handle"
        (j,) = k[name]
        assert j.type == "revolute" and j.limits[1] == pytest.approx(np.pi / 2)
    # every wheel touches the floor at rest (its lowest point is its tyre's)
    for i in [i for i, p in enumerate(obj.parts) if p.semantic == "wheel"]:
        assert obj.part_poses()[i][2, 3] == pytest.approx(obj.parts[i].bounds()[1, 2], abs=1e-3)
