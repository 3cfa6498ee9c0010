"""Category-specific properties of clip, ruler and lighter that the shared per-category
tests do not see: joint kinds and limits per sub-category, counts, clearances."""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg

SEEDS = range(0, 40, 3)


def _by_sub(category: str, sub: str, n: int = 3) -> list:
    """The first ``n`` objects of ``sub`` among seeds 0, 1, 2 ..."""
    out, s = [], 0
    while len(out) < n:
        o = artipg.generate(category, s)
        if o.subcategory == sub:
            out.append(o)
        s += 1
    return out


def _child_part(obj, joint, semantic: str | None = None) -> str:
    """Name of the (first) part of ``joint``'s child link (with label ``semantic``)."""
    parts = obj.links[obj.link_index[joint.child]].parts
    return next(p.name for p in parts if semantic is None or p.semantic == semantic)


def _points(obj, name: str, qpos=None) -> np.ndarray:
    i = next(k for k, p in enumerate(obj.parts) if p.name == name)
    return obj.sample_points(2000, seed=1, qpos=qpos, parts=[i]).points


@pytest.mark.parametrize("seed", SEEDS)
def test_clip_joints_per_subcategory(seed):
    obj = artipg.generate("clip", seed)
    moving = obj.movable_joints
    assert all(j.type == "revolute" and j.limits[0] == 0.0 for j in moving)
    if obj.subcategory == "binder_clip":
        assert len(moving) == 2 and {p.semantic for p in obj.parts} == {"body", "lever"}
        assert all(1.5 < j.limits[1] < math.pi for j in moving)  # folded back -> upright
    else:
        assert len(moving) == 1 and 0.08 < moving[0].limits[1] < 0.3
        assert {"hinge"} < {p.semantic for p in obj.parts} <= {"hinge", "leg", "jaw"}


def test_binder_levers_stand_upright_and_fold_against_the_body():
    for obj in _by_sub("clip", "binder_clip"):
        body = next(p.name for p in obj.parts if p.semantic == "body")
        top = _points(obj, body)[:, 2].max()
        for j in obj.movable_joints:
            lever = _child_part(obj, j, "lever")
            up = _points(obj, lever, {j.name: j.limits[1]})
            assert up[:, 2].max() > top + 0.5 * np.ptp(_points(obj, body)[:, 1])  # stands above the mouth
            rest = _points(obj, lever)
            assert rest[:, 2].max() < top + 0.003  # folded down beside the body


def test_spring_clip_jaws_open_and_handles_close():
    for sub in ("clothes_peg", "bag_clip"):
        for obj in _by_sub("clip", sub):
            j = obj.movable_joints[0]
            jaw = _child_part(obj, j)
            rest, opened = _points(obj, jaw), _points(obj, jaw, {j.name: j.limits[1]})
            front = rest[:, 0] < np.quantile(rest[:, 0], 0.05)
            assert opened[front, 1].min() > rest[front, 1].min() + 0.002  # the jaw tip lifts off


@pytest.mark.parametrize("seed", SEEDS)
def test_ruler_joints_per_subcategory(seed):
    obj = artipg.generate("ruler", seed)
    moving = obj.movable_joints
    if obj.subcategory == "tape_measure":
        kinds = sorted((j.type, tuple(np.round(j.axis, 6))) for j in moving)
        assert kinds == [("prismatic", (-1.0, 0.0, 0.0)), ("prismatic", (0.0, 0.0, -1.0))]
        blade = next(j for j in moving if j.axis[0] < 0)
        assert 0.03 < blade.limits[1] < 0.1
    else:
        n = len(moving) + 1
        assert (n == 2) if obj.subcategory == "hinged_rule" else (4 <= n <= 10)
        assert all(j.type == "revolute" and j.limits == (0.0, math.pi) for j in moving)


def test_folding_rule_counts_vary_and_it_unfolds_straight():
    counts = set()
    for obj in _by_sub("ruler", "folding_rule", 8):
        counts.add(len(obj.movable_joints) + 1)
        pc_rest = obj.sample_points(3000, seed=2).points
        pc_open = obj.sample_points(3000, seed=2, qpos=obj.limits()[:, 1]).points
        pitch = obj.params["ruler.segment_length"].value - obj.params["ruler.width"].value
        # folded: one segment long; straight: n pitches plus the end caps
        assert np.ptp(pc_rest[:, 0]) < pitch + obj.params["ruler.width"].value + 1e-6
        assert np.ptp(pc_open[:, 0]) > (len(obj.movable_joints) + 1) * pitch * 0.99
    assert len(counts) >= 3


def test_tape_blade_slides_out_of_the_mouth():
    for obj in _by_sub("ruler", "tape_measure"):
        blade = next(j for j in obj.movable_joints if j.axis[0] < 0)
        name = _child_part(obj, blade)
        case = next(p.name for p in obj.parts if p.semantic == "body")
        front = _points(obj, case)[:, 0].min()
        out = _points(obj, name, {blade.name: blade.limits[1]})
        assert out[:, 0].min() < front - 0.9 * blade.limits[1]


@pytest.mark.parametrize("seed", SEEDS)
def test_lighter_joints_per_subcategory(seed):
    obj = artipg.generate("lighter", seed)
    kinds = sorted(j.type for j in obj.movable_joints)
    expected = {"flip_top": ["continuous", "revolute"], "disposable": ["continuous", "prismatic"],
                "utility": ["prismatic", "prismatic"]}[obj.subcategory]
    assert kinds == expected
    for j in obj.movable_joints:
        if j.type == "revolute":  # the flip-top lid flips over beside the case
            assert 2.6 < j.limits[1] < math.pi
        elif j.type == "prismatic":
            assert 0.0015 < j.limits[1] < 0.008


def test_flip_lid_clears_the_chimney_and_lands_beside_the_case():
    for obj in _by_sub("lighter", "flip_top"):
        lid = next(j for j in obj.movable_joints if j.type == "revolute")
        name = _child_part(obj, lid, "lid")
        case = _points(obj, next(p.name for p in obj.parts if p.semantic == "body"))
        side = case[:, 1].min() + obj.params["lighter.width"].value  # the case's +y side (its knuckle aside)
        opened = _points(obj, name, {lid.name: lid.limits[1]})
        assert np.quantile(opened[:, 1], 0.02) > side  # on the hinge side, beside the case
        rest = _points(obj, name)
        assert abs(rest[:, 1].min() - case[:, 1].min()) < 1e-3  # closed: over the case


def test_utility_lighter_trigger_stays_in_its_opening():
    for obj in _by_sub("lighter", "utility"):
        trig = next(j for j in obj.movable_joints if tuple(j.axis) == (1.0, 0.0, 0.0) and
                    _child_part(obj, j).startswith("button"))
        pts = _points(obj, _child_part(obj, trig), {trig.name: trig.limits[1]})
        handle = _points(obj, next(p.name for p in obj.parts if p.semantic == "body"))
        assert pts[:, 2].min() > handle[:, 2].min() and pts[:, 0].max() < handle[:, 0].max()
