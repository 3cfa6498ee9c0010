"""Category-specific facts of clocks, fans and lamps: the joints each real object has,
clearances the generator promises, and duplicated parts' counts."""

import math

import numpy as np

import artipg

SEEDS = range(10)


def _joints(obj, name):
    return [j for j in obj.movable_joints if j.child.startswith(name)]


def _by_sub(category, sub, n=3, start=0, limit=300):
    out = []
    for seed in range(start, start + limit):
        obj = artipg.generate(category, seed)
        if obj.subcategory == sub:
            out.append(obj)
            if len(out) == n:
                break
    assert out, f"no {sub} among {limit} seeds"
    return out


def test_clock_hands_turn_about_the_dial_axis_in_separate_planes():
    for seed in SEEDS:
        obj = artipg.generate("clock", seed)
        hands = _joints(obj, "hour_hand") + _joints(obj, "minute_hand") + _joints(obj, "second_hand")
        assert 2 <= len(hands) <= 3 and all(j.type == "continuous" for j in hands)
        # every hand turns about the same axis (object x), through the same point
        origins = np.array([j.origin[:3, 3] for j in hands])
        axes = np.array([j.origin[:3, :3] @ j.axis for j in hands])
        assert np.allclose(np.abs(axes[:, 0]), 1.0)
        assert np.allclose(origins[:, 1:], origins[0, 1:], atol=1e-9)
        # stacked along -x with gaps: each hand's slab lies clear of the next one's
        slabs = []
        for j in hands:
            link = next(lk for lk in obj.links if lk.name == j.child)
            b = np.array([p.bounds() for p in link.parts])
            slabs.append((j.origin[0, 3] + b[:, 0, 0].min(), j.origin[0, 3] + b[:, 1, 0].max()))
        slabs.sort()
        for (lo0, hi0), (lo1, hi1) in zip(slabs, slabs[1:]):
            assert lo1 - hi0 >= 0.001


def test_clock_subcategories_have_their_joints():
    for obj in _by_sub("clock", "mantel_clock"):
        door = _joints(obj, "door")
        assert len(door) == 1 and door[0].type == "revolute" and math.radians(80) < door[0].limits[1] < 2.0
        for j in _joints(obj, "pendulum"):
            assert j.type == "revolute" and -0.2 < j.limits[0] < 0 < j.limits[1] < 0.2
    for obj in _by_sub("clock", "alarm_clock"):
        buttons, knobs = _joints(obj, "button"), _joints(obj, "knob")
        assert 1 <= len(buttons) <= 2 and all(j.type == "prismatic" and j.limits[1] <= 0.006 for j in buttons)
        assert 1 <= len(knobs) <= 3 and all(j.type == "continuous" for j in knobs)
    for obj in _by_sub("clock", "wall_clock"):
        assert {j.child.split("_")[0] for j in obj.movable_joints} <= {"hour", "minute", "second"}
        ext = np.ptp(np.asarray(obj.bounds()), axis=0)
        assert 0.2 <= ext[1] <= 0.45 and 0.04 <= ext[0] <= 0.12  # 0.22-0.42 across, a shallow case (or cradle)


def _axis(j):
    return j.origin[:3, :3] @ j.axis


def test_fans_spin_3_to_6_blades_inside_the_guard():
    for seed in SEEDS:
        obj = artipg.generate("fan", seed)
        rotor = _joints(obj, "rotor")
        assert len(rotor) == 1 and rotor[0].type == "continuous"
        link = next(lk for lk in obj.links if lk.name == rotor[0].child)
        blades = [p for p in link.parts if p.semantic == "blade"]
        assert len(blades) == 1 and 3 <= len(blades[0].primitives) <= 6
        # the blades' tips stay inside the guard (or the box frame's opening)
        tip = max(float(np.abs(p.bounds()[:, 1:]).max()) for p in link.parts)  # along y or z: the blade radius
        ring = [p for p in obj.parts if p.semantic == "guard"]
        assert ring and tip < max(np.ptp(p.bounds()[:, 2]) for p in ring) / 2 - 0.005


def test_fan_heads_oscillate_tilt_and_pedestal_poles_telescope():
    for sub in ("desk_fan", "pedestal_fan"):
        for obj in _by_sub("fan", sub):
            neck, head = _joints(obj, "neck"), _joints(obj, "head")
            assert len(neck) == 1 and neck[0].type == "revolute" and np.allclose(np.abs(_axis(neck[0])), (0, 0, 1))
            assert len(head) == 1 and head[0].type == "revolute" and np.allclose(np.abs(_axis(head[0])), (0, 1, 0))
            assert head[0].limits[0] < 0 < head[0].limits[1]
            pole = _joints(obj, "pole")
            if sub == "pedestal_fan":
                assert len(pole) == 1 and pole[0].type == "prismatic" and 0.15 <= pole[0].limits[1] <= 0.35
                assert 1.0 <= np.ptp(np.asarray(obj.bounds())[:, 2]) <= 1.6
            else:
                assert not pole and 0.35 <= np.ptp(np.asarray(obj.bounds())[:, 2]) <= 0.7
    for obj in _by_sub("fan", "box_fan"):
        knobs = _joints(obj, "knob")
        assert 1 <= len(knobs) <= 2 and all(j.type == "revolute" for j in knobs)


def test_desk_lamps_have_a_swivel_two_arms_and_a_head():
    for obj in _by_sub("lamp", "desk_lamp"):
        t, lo, up, hd = (_joints(obj, n) for n in ("turret", "lower_arm", "upper_arm", "head"))
        assert len(t) == 1 and np.allclose(np.abs(_axis(t[0])), (0, 0, 1))
        for j in (*lo, *up, *hd):
            assert j.type == "revolute" and np.isclose(abs(_axis(j)[1]), 1.0)
        assert len(lo) == len(up) == len(hd) == 1
        assert len(_joints(obj, "button")) == 1


def test_table_and_floor_lamps_have_one_switch():
    for sub in ("table_lamp", "floor_lamp"):
        for obj in _by_sub("lamp", sub, n=6):
            sw = _joints(obj, "chain") + _joints(obj, "knob") + _joints(obj, "button")
            assert len(sw) == 1
            j = sw[0]
            assert (j.type == "prismatic" and j.limits[1] <= 0.012) or (j.type == "revolute" and j.limits[1] <= 4.8)
            h = np.ptp(np.asarray(obj.bounds())[:, 2])
            assert (0.3 <= h <= 0.8) if sub == "table_lamp" else (1.2 <= h <= 1.9)
