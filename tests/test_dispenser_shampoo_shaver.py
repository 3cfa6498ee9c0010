"""Category-specific facts of dispensers, shampoo bottles and shavers: the joints each
real object has (kinds, axes, ranges) per sub-category, and real sizes."""

import numpy as np

import artipg

SEEDS = range(16)


def _joints(obj, name):
    return [j for j in obj.movable_joints if j.child.startswith(name)]


def _extents(obj):
    b = obj.bounds()
    return b[1] - b[0]


def test_dispensers_pump_spray_or_push_like_real_ones():
    seen = set()
    for seed in SEEDS:
        obj = artipg.generate("dispenser", seed)
        seen.add(obj.subcategory)
        D, W, H = _extents(obj)
        if obj.subcategory == "wall_dispenser":
            (plate,), (lid,) = _joints(obj, "plate"), _joints(obj, "lid")
            assert plate.type in ("prismatic", "revolute") and plate.limits[1] > 0
            if plate.type == "prismatic":
                assert np.allclose(plate.axis, (1, 0, 0)) and 0.005 <= plate.limits[1] <= 0.013
            assert lid.type == "revolute" and 1.1 <= lid.limits[1] <= 1.75
            assert 0.15 <= H <= 0.3 and 0.07 <= D <= 0.13
            continue
        (collar,) = _joints(obj, "collar")
        assert collar.type == "continuous" and np.allclose(collar.axis, (0, 0, 1))
        if obj.subcategory == "pump_dispenser":
            (pump,) = _joints(obj, "pump")
            assert pump.type == "prismatic" and np.allclose(pump.axis, (0, 0, -1)) and 0.007 <= pump.limits[1] <= 0.016
            for lock in _joints(obj, "head"):  # locking heads turn about the stem
                assert lock.type == "revolute" and np.allclose(lock.axis, (0, 0, 1))
            assert 0.12 <= H <= 0.3
        else:
            (trigger,), (nozzle,) = _joints(obj, "trigger"), _joints(obj, "nozzle")
            assert trigger.type == "revolute" and np.allclose(trigger.axis, (0, -1, 0))
            assert 0.3 <= trigger.limits[1] <= 0.6
            assert nozzle.type == "revolute" and np.allclose(nozzle.axis, (-1, 0, 0))
            assert 0.2 <= H <= 0.33
    assert seen == {"pump_dispenser", "trigger_sprayer", "wall_dispenser"}


def test_pressed_pump_and_pulled_trigger_move_the_right_way():
    for seed in SEEDS:
        obj = artipg.generate("dispenser", seed)
        for name, axis, sign in (("pump", 2, -1), ("trigger", 0, 1)):
            for j in _joints(obj, name):
                child = obj.link_index[j.child]
                rest = obj.link_poses()[child][:3, 3]
                moved = obj.link_poses({j.name: j.limits[1]})[child]
                # the pump head goes down; the trigger's lower end swings back towards the bottle
                probe = moved @ np.array([0.0, 0.0, -0.03, 1.0]) if name == "trigger" else moved[:, 3]
                ref = obj.link_poses()[child] @ np.array([0.0, 0.0, -0.03, 1.0]) if name == "trigger" else rest
                assert sign * (probe[axis] - ref[axis]) > 0.003


def test_dispensers_are_deterministic():
    a, b = artipg.generate("dispenser", 5), artipg.generate("dispenser", 5)
    assert a.params.keys() == b.params.keys()
    assert all(a.params[k].value == b.params[k].value for k in a.params)
    np.testing.assert_array_equal(a.bounds(), b.bounds())
