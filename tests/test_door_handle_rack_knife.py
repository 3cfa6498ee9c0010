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
