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
            assert 0.11 <= H <= 0.33  # round-flask sprayers are the short ones
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


def test_shampoo_caps_flip_tilt_or_pump():
    seen = set()
    for seed in SEEDS:
        obj = artipg.generate("shampoo", seed)
        seen.add(obj.subcategory)
        D, W, H = _extents(obj)
        assert 0.13 <= H <= 0.28 and 0.03 <= D <= 0.095 and 0.045 <= W <= 0.095
        body = next(p for p in obj.parts if p.semantic == "body")
        if body.template != "round_squeeze_body":  # oval sections: the wide face looks front (-x)
            bx, by, _ = body.bounds()[1] - body.bounds()[0]
            assert by > bx
        if obj.subcategory == "flip_cap":
            (lid,) = obj.movable_joints
            assert lid.type == "revolute" and np.allclose(lid.axis, (0, 1, 0)) and 1.8 <= lid.limits[1] <= 2.8
        elif obj.subcategory == "disc_top":
            (disc,) = obj.movable_joints
            assert disc.type == "revolute" and np.allclose(disc.axis, (0, 1, 0)) and 0.05 <= disc.limits[1] <= 0.31
        else:
            (collar,), (pump,) = _joints(obj, "collar"), _joints(obj, "pump")
            assert collar.type == "continuous" and pump.type == "prismatic" and 0.005 <= pump.limits[1] <= 0.01
    assert seen == {"flip_cap", "disc_top", "pump_lotion"}


def test_shampoo_disc_tilts_its_back_down_and_front_up():
    for seed in SEEDS:
        obj = artipg.generate("shampoo", seed)
        for j in _joints(obj, "disc"):
            child = obj.link_index[j.child]
            back, front = np.array([0.01, 0.0, 0.0, 1.0]), np.array([-0.01, 0.0, 0.0, 1.0])
            rest, tilted = obj.link_poses()[child], obj.link_poses({j.name: j.limits[1]})[child]
            assert (tilted @ back)[2] < (rest @ back)[2] and (tilted @ front)[2] > (rest @ front)[2]


def test_shavers_pivot_flip_and_spin_like_real_ones():
    seen = set()
    for seed in range(24):
        obj = artipg.generate("shaver", seed)
        seen.add(obj.subcategory)
        D, W, H = _extents(obj)
        if obj.subcategory == "safety_razor":
            (cart,) = obj.movable_joints
            assert cart.type == "revolute" and np.allclose(cart.axis, (0, 1, 0)) and 0.4 <= cart.limits[1] <= 0.8
            assert 0.09 <= D <= 0.15 and H <= 0.02  # lying on its handle
            blades = [p for p in obj.parts if p.semantic == "head"][0].primitives[1:]
            assert 2 <= len(blades) <= 5
            continue
        (button,) = _joints(obj, "button")
        assert button.type == "prismatic" and np.allclose(button.axis, (1, 0, 0))  # into the front face
        assert 0.12 <= H <= 0.2 and 0.03 <= D <= 0.085
        if obj.subcategory == "foil_shaver":
            (head,), (cover,) = _joints(obj, "head"), _joints(obj, "cover")
            assert head.type == "revolute" and head.limits[0] < 0 < head.limits[1]  # rocks both ways
            assert cover.type == "prismatic" and np.allclose(cover.axis, (0, 0, 1))
            for trimmer in _joints(obj, "trimmer"):
                assert trimmer.type == "prismatic" and np.allclose(trimmer.axis, (0, 0, 1))
                assert trimmer.limits[1] > 0.004
        else:
            (holder,) = _joints(obj, "holder")
            cutters = _joints(obj, "cutter")
            assert holder.type == "revolute" and 1.3 <= holder.limits[1] <= 1.9
            assert len(cutters) in (2, 3) and all(j.type == "continuous" for j in cutters)
    assert seen == {"foil_shaver", "rotary_shaver", "safety_razor"}


def test_shaver_cover_lifts_clear_of_the_foils():
    for seed in range(24):
        obj = artipg.generate("shaver", seed)
        for j in _joints(obj, "cover"):
            cover = next(i for i, p in enumerate(obj.parts) if p.template == "foil_cover")
            foils = next(i for i, p in enumerate(obj.parts) if p.template == "foils")
            lo = obj.sample_points(400, seed=0, qpos={j.name: j.limits[1]}, parts=[cover]).points[:, 2].min()
            hi = obj.sample_points(400, seed=0, parts=[foils]).points[:, 2].max()
            assert lo > hi + 0.004
