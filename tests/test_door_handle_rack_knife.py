"""Category-specific properties of door_handle, folding_rack and knife that the shared
per-category tests do not see: joint kinds per sub-category, real sizes, clearances
between turning or folding parts and what they turn on, duplicated rails."""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg

SEEDS = range(0, 48, 4)


def _joints(obj) -> dict:
    """{child link base name: [joint, ...]}."""
    out: dict = {}
    for j in obj.movable_joints:
        out.setdefault(j.child.rsplit("_", 1)[0], []).append(j)
    return out


def _points(obj, pred, qpos=None, n=3000) -> np.ndarray:
    idx = [i for i, p in enumerate(obj.parts) if pred(p)]
    return obj.sample_points(n, seed=1, qpos=qpos, parts=idx).points


@pytest.mark.parametrize("seed", SEEDS)
def test_door_handle_joints_sizes_and_clearance(seed):
    obj = artipg.generate("door_handle", seed)
    J = _joints(obj)
    (h,) = J["handle"]
    axis = h.origin[:3, :3] @ h.axis
    assert h.type == "revolute" and abs(abs(axis[0]) - 1.0) < 1e-9  # about the spindle (x)
    lo, hi = h.limits
    if obj.subcategory.startswith("lever"):
        assert lo == 0.0 and math.radians(40) <= hi <= math.radians(50)
        grip = _points(obj, lambda p: p.semantic == "handle")
        reach = np.abs(grip[:, 1] - h.origin[1, 3]).max()
        assert 0.1 <= reach <= 0.16
        down = _points(obj, lambda p: p.semantic == "handle", qpos={h.name: hi})
        assert down[:, 2].min() < grip[:, 2].min() - 0.05  # the lever turns tip down
    else:
        assert lo == -hi and 1.2 <= hi <= math.pi / 2
    turns = J.get("thumb_turn", [])
    assert not turns or (obj.subcategory.endswith("plate") and turns[0].limits == (0.0, math.pi / 2))
    moving = _points(obj, lambda p: p.semantic in ("handle", "knob"))
    plate = _points(obj, lambda p: p.semantic == "base")
    front = plate[:, 0].min()
    assert moving[:, 0].max() < front - 0.001  # turning parts clear their rose or plate
    height = np.ptp(plate[:, 2])
    assert (0.15 <= height <= 0.25) if obj.subcategory.endswith("plate") else (0.05 <= height <= 0.064)


@pytest.mark.parametrize("seed", SEEDS)
def test_folding_rack_joints_rails_and_sizes(seed):
    obj = artipg.generate("folding_rack", seed)
    J = _joints(obj)
    assert all(j.type == "revolute" and j.limits[0] == 0.0 for j in obj.movable_joints)
    lo, hi = obj.bounds()
    size = hi - lo
    rails = [p for p in obj.parts if p.semantic == "rail"]
    assert rails and sum(len(p.primitives) for p in rails) >= 6  # duplicated rails
    if obj.subcategory == "gullwing":
        assert len(J["wing"]) == 2 and len(J["leg"]) == 2
        assert all(math.pi / 2 <= j.limits[1] <= math.pi / 2 + 0.3 for j in J["wing"])
        assert 0.84 <= size[2] <= 1.02 and 0.5 <= size[0] <= 0.62
        opened = obj.bounds({j.name: j.limits[1] for j in J["wing"]})
        assert 1.4 <= np.ptp(opened[:, 1]) <= 2.0  # wings out: 1.4-1.95 m long
    elif obj.subcategory == "a_frame":
        (f,) = J["frame"]
        assert 0.05 < f.limits[1] < 0.7 and 1.0 <= size[2] <= 1.46
    else:
        n = len(J["wing"])
        assert n % 2 == 0 and 4 <= n <= 8 and all(j.limits[1] == math.pi / 2 for j in J["wing"])
        assert 1.1 <= size[2] <= 1.72
    # at rest the rack stands on the floor: its legs or frames reach the lowest point
    feet = _points(obj, lambda p: p.semantic in ("leg", "frame"))
    assert feet[:, 2].min() < lo[2] + 0.003
    # wings hang clear of the floor at rest
    if "wing" in J:
        wings = _points(obj, lambda p: obj.part_link[obj.parts.index(p)] in
                        [obj.link_index[j.child] for j in J["wing"]])
        assert wings[:, 2].min() > lo[2] + 0.05


@pytest.mark.parametrize("seed", SEEDS)
def test_knife_utility_slides_and_multitool_pivots(seed):
    obj = artipg.generate("knife", seed)
    kinds = sorted({j.type for j in obj.movable_joints})
    if obj.subcategory == "utility":
        (j,) = obj.movable_joints
        assert j.type == "prismatic" and 0.018 <= j.limits[1] <= 0.038
        blade = _points(obj, lambda p: p.semantic == "blade")
        handle = _points(obj, lambda p: p.semantic == "handle")
        assert blade[:, 0].max() < handle[:, 0].max()  # retracted at rest
        out = _points(obj, lambda p: p.semantic == "blade", qpos={j.name: j.limits[1]})
        assert out[:, 0].max() - handle[:, 0].max() >= 0.012  # the blade comes out of the nose
        return
    assert kinds == ["revolute"] and all(j.limits == (0.0, math.pi) for j in obj.movable_joints)
    pivots = {tuple(np.round(j.origin[:3, 3], 6)) for j in obj.movable_joints}
    n = len(obj.movable_joints)
    if obj.subcategory == "multitool":
        assert len(pivots) == 2 and 3 <= n <= 6
    else:
        assert len(pivots) == 1 and n <= {"folder": 1, "pocket": 3, "penknife": 2}[obj.subcategory]
