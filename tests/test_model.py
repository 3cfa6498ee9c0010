"""Core model: forward kinematics, the builder, the parameter recorder and the rules."""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg
from artipg.geometry import cuboid
from artipg.geometry.transforms import translation
from artipg.model import ObjectBuilder, Part
from artipg.rules import Category, ParamRecorder, Slot


def _two_link(joint_type, axis=(0, 0, 1), limits=(0.0, 1.0)):
    b = ObjectBuilder()
    root = b.create_link("base")
    root.add(Part("body", "box", [cuboid(0.4, 0.4, 0.4, translation(0, 0, 0.2))]))
    child = b.create_link("door", root)
    child.set_joint(joint_type, translation(-0.2, 0.2, 0.2), axis=axis, limits=limits)
    child.add(Part("door", "slab", [cuboid(0.02, 0.4, 0.4, translation(-0.01, -0.2, 0.0))]))
    return b.build("test", "test", 0)


@pytest.mark.parametrize("jtype", ["revolute", "prismatic", "continuous"])
def test_fk_moves_child_and_only_child(jtype):
    obj = _two_link(jtype)
    rest = obj.link_poses()
    moved = obj.link_poses({obj.joints[0].name: 0.5})
    assert np.allclose(rest[0], moved[0])
    assert not np.allclose(rest[1], moved[1])
    # the joint origin stays on the axis for rotations
    if jtype != "prismatic":
        assert np.allclose(rest[1][:3, 3], moved[1][:3, 3])
        R = rest[1][:3, :3].T @ moved[1][:3, :3]
        assert math.isclose(np.arccos((np.trace(R) - 1) / 2), 0.5, abs_tol=1e-9)
    else:
        assert np.linalg.norm(moved[1][:3, 3] - rest[1][:3, 3]) == pytest.approx(0.5)


def test_qpos_forms_agree():
    obj = _two_link("revolute")
    assert np.allclose(obj.link_poses([0.3]), obj.link_poses({obj.joints[0].name: 0.3}))
    with pytest.raises(ValueError):
        obj.link_poses([0.1, 0.2])


def test_builder_normalises_to_floor_and_axis():
    obj = _two_link("revolute")
    b = obj.bounds()
    assert b[0, 2] == pytest.approx(0.0, abs=1e-12)
    assert np.allclose((b[0, :2] + b[1, :2]) / 2, 0.0, atol=1e-12)


def test_builder_rejects_bad_joints():
    b = ObjectBuilder()
    root = b.create_link("base")
    with pytest.raises(ValueError):
        root.set_joint("revolute", np.eye(4))
    child = b.create_link("x", root)
    with pytest.raises(ValueError):
        child.set_joint("revolute", np.eye(4), limits=(1.0, 0.5))
    with pytest.raises(ValueError):
        child.set_joint("ball", np.eye(4))


def test_recorder_records_ranges_and_clamps_overrides():
    rec = ParamRecorder(np.random.default_rng(0))
    v = rec.uniform("w", 0.2, 0.4)
    assert 0.2 <= v <= 0.4 and rec.record["w"].lo == 0.2 and rec.record["w"].hi == 0.4
    rec2 = ParamRecorder(np.random.default_rng(0), overrides={"w": 9.0, "n": -3, "c": "b"})
    assert rec2.uniform("w", 0.2, 0.4) == 0.4
    assert rec2.integers("n", 1, 5) == 1
    assert rec2.choice("c", ["a", "b"]) == "b"
    assert rec2.record["w"].kind == "uniform"


def test_override_does_not_shift_other_streams():
    rec_a = ParamRecorder(np.random.default_rng(3))
    rec_b = ParamRecorder(np.random.default_rng(3), overrides={"a": 0.1})
    rec_a.uniform("a", 0, 1)
    rec_b.uniform("a", 0, 1)
    assert rec_a.uniform("b", 0, 1) == rec_b.uniform("b", 0, 1)


def test_choice_weights_are_respected():
    rec = ParamRecorder(np.random.default_rng(0))
    picks = [rec.scope(str(i)).choice("c", {"a": 3.0, "b": 1.0}) for i in range(4000)]
    assert picks.count("a") / 4000 == pytest.approx(0.75, abs=0.03)


def test_slots_run_in_topological_order_and_optional_slots_keep_other_streams():
    seen = []

    def mk(name, draw=True):
        def build(ctx):
            seen.append(name)
            return ctx.p.uniform("x", 0, 1) if draw else None
        return build

    cat = Category("t", {"s": 1.0}, (Slot("c", mk("c"), after=("a", "b")), Slot("a", mk("a")), Slot("b", mk("b"), after=("a",))))
    assert [s.name for s in cat.order] == ["a", "b", "c"]
    with pytest.raises(ValueError):
        Category("t", {"s": 1.0}, (Slot("a", mk("a"), after=("zz",)),))


def test_generate_rejects_bad_input():
    with pytest.raises(KeyError, match="valid"):
        artipg.generate("no_such_category", 0)
    with pytest.raises(ValueError):
        artipg.generate(artipg.categories()[0], -1)


def test_overrides_regenerate_with_clamped_value():
    cat = artipg.categories()[0]
    obj = artipg.generate(cat, 4)
    name, p = next((k, v) for k, v in obj.params.items() if v.kind == "uniform")
    obj2 = artipg.generate(cat, 4, overrides={name: p.hi + 1.0})
    assert obj2.params[name].value == pytest.approx(obj2.params[name].hi)
