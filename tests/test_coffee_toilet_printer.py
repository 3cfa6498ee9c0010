"""Category-specific facts of toilets, coffee machines and printers: the joints each
real object has, their directions and ranges, counts and clearances."""

import math

import numpy as np

import artipg
from artipg.templates.toilets import swing_limit

SEEDS = range(10)


def _joints(obj, name):
    return [j for j in obj.movable_joints if j.child.rsplit("_", 1)[0] == name]


def test_swing_limit_stops_before_an_obstacle_and_is_free_without_one():
    rect = [((-0.45, -0.01), (-0.02, 0.0))]  # a 0.44 m slab lying along -x from the axis
    assert swing_limit(rect, [], 1.9) == 1.9
    # a wall 0.1 m behind the axis: the slab stands up and leans back until 4 mm off it
    lim = swing_limit(rect, [(0.1, -0.5, 1.0)], 1.9, margin=0.004)
    assert math.pi / 2 < lim < 1.9
    c, s = math.cos(lim), math.sin(lim)
    assert max(c * u + s * w for u in (-0.45, -0.01) for w in (-0.02, 0.0)) < 0.1 - 0.004


def test_toilets_hinge_seat_and_lid_about_one_rear_axis():
    subs = set()
    for seed in SEEDS:
        obj = artipg.generate("toilet", seed)
        subs.add(obj.subcategory)
        seat, lid = _joints(obj, "seat"), _joints(obj, "seat_lid")
        assert len(seat) == 1 and seat[0].type == "revolute" and np.allclose(seat[0].axis, (0, 1, 0))
        assert 1.4 < seat[0].limits[1] < 1.93  # 80-110 degrees: up against the lid, tank or wall
        for lj in lid:  # same axis, the lid stays ahead of the seat so the seat never meets it
            assert lj.type == "revolute" and np.allclose(lj.origin, seat[0].origin)
            assert seat[0].limits[1] < lj.limits[1] <= 1.92
        tank_lid = _joints(obj, "tank_lid")
        assert len(tank_lid) == (0 if obj.subcategory == "wall_hung" else 1)
        assert all(j.type == "prismatic" and np.allclose(j.axis, (0, 0, 1)) for j in tank_lid)
        buttons, lever = _joints(obj, "button"), _joints(obj, "lever")
        assert 1 <= len(buttons) + len(lever) <= 2
        assert all(j.type == "prismatic" and j.limits[1] <= 0.007 for j in buttons)
        assert all(j.type == "revolute" and np.allclose(j.axis, (1, 0, 0)) for j in lever)
        if obj.subcategory == "one_piece":
            assert buttons and not lever
    assert subs == {"two_piece", "one_piece", "wall_hung"}
    assert artipg.get_category("toilet").fixed_base


def test_toilet_rim_height_and_footprint_are_real():
    for seed in SEEDS:
        obj = artipg.generate("toilet", seed)
        seat = _joints(obj, "seat")[0]
        rim = seat.origin[2, 3]
        assert 0.39 < rim < 0.48  # the seat's top (hinge axis) above the floor
        lo, hi = obj.bounds()
        size = hi - lo
        assert 0.33 <= size[1] <= 0.66 and 0.5 <= size[0] <= 0.9, size
        assert size[2] <= (1.26 if obj.subcategory == "wall_hung" else 0.85), size


def test_toilet_bodies_wear_sanitary_white():
    from artipg.appearance import materials_of
    for seed in SEEDS:
        obj = artipg.generate("toilet", seed)
        mats = materials_of(obj)
        body = [mats[p.name] for p in obj.parts if p.semantic == "body"]
        assert all(m.family == "sanitary_ceramic" and min(m.color) > 0.8 for m in body)


def _link_points(obj, name, q=None):
    pc = obj.sample_points(4000, seed=0, qpos=q)
    names = np.array(pc.link_names)[pc.link]
    return pc.points[np.char.startswith(names.astype(str), name)]


def test_coffee_machines_move_like_the_real_ones():
    subs = set()
    for seed in range(14):
        obj = artipg.generate("coffee_machine", seed)
        subs.add(obj.subcategory)
        tray, buttons = _joints(obj, "tray"), _joints(obj, "button")
        assert all(j.type == "prismatic" and j.limits[1] <= 0.007 for j in buttons)
        if obj.subcategory == "drip":
            lid, drawer, jug = _joints(obj, "lid"), _joints(obj, "drawer"), _joints(obj, "carafe")
            assert len(lid) == 1 and np.allclose(lid[0].axis, (0, 1, 0)) and 1.2 <= lid[0].limits[1] <= 1.75
            assert len(drawer) == 1  # a filter drawer, or a basket swinging out about a vertical edge
            assert np.allclose(drawer[0].axis, (-1, 0, 0)) or np.allclose(np.abs(drawer[0].axis), (0, 0, 1))
            assert len(jug) == 1 and jug[0].type == "prismatic" and not tray
            assert 1 <= len(buttons) <= 3
            # the carafe stands under the head: its top is below the filter drawer
            assert _link_points(obj, "carafe")[:, 2].max() < _link_points(obj, "drawer")[:, 2].min()
        elif obj.subcategory == "espresso":
            pf, wand, knobs = _joints(obj, "portafilter"), _joints(obj, "wand"), _joints(obj, "knob")
            assert len(pf) == 1 and np.allclose(pf[0].axis, (0, 0, 1)) and 0.5 < pf[0].limits[1] < 0.8
            assert len(wand) == 1 and np.allclose(wand[0].axis, (1, 0, 0))
            assert 1 <= len(knobs) <= 2 and len(tray) == 1 and np.allclose(tray[0].axis, (-1, 0, 0))
        else:
            lever, tank = _joints(obj, "lever"), _joints(obj, "tank")
            assert len(lever) == 1 and np.allclose(lever[0].axis, (0, 1, 0)) and lever[0].limits[1] <= math.pi / 2
            assert len(tank) == 1 and np.allclose(tank[0].axis, (0, 0, 1)) and len(tray) == 1
            assert 1 <= len(buttons) <= 3
    assert subs == {"drip", "espresso", "capsule"}


def test_open_capsule_lever_and_tank_lift_clear_of_the_body():
    for seed in range(14):
        obj = artipg.generate("coffee_machine", seed)
        if obj.subcategory != "capsule":
            continue
        lo, hi = obj.bounds()
        q = {j.name: j.limits[1] for j in obj.movable_joints if j.child.startswith(("lever", "tank"))}
        lo2, hi2 = obj.bounds(q)
        assert hi2[2] > hi[2] + 0.05  # both rise well above the closed machine


def test_printers_open_their_paper_paths():
    subs = set()
    for seed in range(12):
        obj = artipg.generate("printer", seed)
        subs.add(obj.subcategory)
        buttons = _joints(obj, "button")
        assert buttons and all(j.type == "prismatic" and j.limits[1] <= 0.007 for j in buttons)
        slides = _joints(obj, "tray") + _joints(obj, "drawer")
        assert slides and all(j.type == "prismatic" and np.allclose(j.axis, (-1, 0, 0)) for j in slides)
        lids = _joints(obj, "lid") + _joints(obj, "flap") + _joints(obj, "adf")
        lids += [j for j in _joints(obj, "support") if j.type == "revolute"]
        assert all(np.allclose(j.axis, (0, 0, 1)) for j in _joints(obj, "support") if j.type == "prismatic")
        assert all(j.type == "revolute" and np.allclose(j.axis, (0, 1, 0)) and 0.9 <= j.limits[1] <= 1.75
                   for j in lids)
        if obj.subcategory == "inkjet":
            assert [len(_joints(obj, n)) for n in ("tray", "support", "lid")] == [1, 1, 1]
        elif obj.subcategory == "laser":
            door = _joints(obj, "door")
            assert len(door) == 1 and door[0].type == "revolute" and len(_joints(obj, "drawer")) == 1
            assert len(_joints(obj, "flap")) == 1
        else:  # scanner lid, cassette, output tray and a tilting control panel with its buttons
            assert len(_joints(obj, "lid")) == 1 and len(_joints(obj, "drawer")) == 1 and len(_joints(obj, "tray")) == 1
            panel = _joints(obj, "panel")
            assert len(panel) == 1 and panel[0].type == "revolute"
            assert all(j.parent == panel[0].child for j in buttons)
    assert subs == {"inkjet", "laser", "all_in_one"}


def test_printer_sizes_are_real():
    for seed in range(12):
        obj = artipg.generate("printer", seed)
        lo, hi = obj.bounds()
        d, w, h = hi - lo
        assert 0.33 <= w <= 0.5 and 0.24 <= d <= 0.5 and 0.11 <= h <= 0.37, (obj.subcategory, d, w, h)
