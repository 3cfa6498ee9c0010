"""Grasps built on first use (:class:`artipg.model.part.Deferred`): the same values as
built eagerly by the templates, and never built by generation and point sampling."""

import copy
import dataclasses
import pathlib
import pickle
import re

import numpy as np
import pytest

import artipg
from artipg.geometry import cuboid
from artipg.model import part as part_module
from artipg.model.part import Deferred, Grasp, Part

TEMPLATES = pathlib.Path(part_module.__file__).parents[1] / "templates"
SEEDS = 15  # enough for every grasp builder to show up in some category


def _grasp(x):
    return Grasp(np.eye(4) * x, x)


def test_deferred_calls_once_and_keeps_the_value():
    calls = []

    def build(a, b):
        calls.append((a, b))
        return [_grasp(a + b)]

    d = Deferred(build, 1.0, 2.0)
    assert calls == []
    first = d()
    assert d() is first and calls == [(1.0, 2.0)] and d.args is None
    one = Deferred.one(_grasp, 0.5)()
    assert len(one) == 1 and one[0].width == 0.5


def test_part_builds_deferred_grasps_on_first_read_and_copies_share_them():
    calls = []

    def build():
        calls.append(1)
        return [_grasp(2.0)]

    prim = [cuboid(1.0, 1.0, 1.0)]
    a = Part("handle", "bar", prim, grasps=build)  # any zero-argument callable
    assert isinstance(a.grasp_source(), Deferred) and calls == []
    b = copy.copy(a)
    c = Part(a.semantic, a.template, a.primitives, grasps=a.grasp_source())
    d = dataclasses.replace(a)  # reads the field: builds
    assert calls == [1] and d.grasps is a.grasps is b.grasps is c.grasps and a.grasps[0].width == 2.0
    assert a.grasp_source() is a.grasps  # the list is kept on the part
    e = pickle.loads(pickle.dumps(Part("handle", "bar", prim, grasps=Deferred.one(Grasp, np.eye(4), 0.1))))
    assert e.grasps[0].width == 0.1
    # lists as before; assignment takes a list or a callable
    g = [_grasp(1.0)]
    f = Part("handle", "bar", prim, grasps=g)
    assert f.grasps is g and f.grasp_source() is g and Part("handle", "bar", prim).grasps == []
    f.grasps = Deferred(lambda: [_grasp(3.0)])
    assert f.grasps[0].width == 3.0
    f.grasps = g
    assert f.grasps is g
    assert [x.name for x in dataclasses.fields(Part)].count("grasps") == 1 and "grasps=[" in repr(f)


def _builders_in_templates() -> set:
    """(module, function) of every grasp builder the templates pass to Deferred."""
    out = set()
    for path in TEMPLATES.glob("*.py"):
        for name in re.findall(r"Deferred(?:\.one)?\((\w+)", path.read_text()):
            fn = getattr(__import__(f"artipg.templates.{path.stem}", fromlist=[name]), name)
            out.add((fn.__module__, fn.__name__))
    return out


def _grasp_bits(obj):
    return [[(g.pose.tobytes(), float(g.width), np.asarray(g.open_dir, dtype=float).tobytes()) for g in p.grasps]
            for p in obj.parts]


def test_deferred_grasps_are_the_eager_ones(monkeypatch):
    """Every template grasp, built when first read after generation, has the bits it
    has when built where the template defines it (nothing it reads changes later)."""
    categories = artipg.categories()
    lazy = {(c, s): _grasp_bits(artipg.generate(c, s)) for c in categories for s in range(SEEDS)}
    seen = set()
    init = Deferred.__init__

    def eager(self, fn, *args):  # build at once, as the templates did
        init(self, fn, *args)
        f = args[0] if fn is part_module._one else fn
        seen.add((f.__module__, f.__name__))
        self()

    monkeypatch.setattr(Deferred, "__init__", eager)
    n = 0
    for c in categories:
        for s in range(SEEDS):
            want = _grasp_bits(artipg.generate(c, s))
            assert lazy[(c, s)] == want, (c, s)
            n += sum(map(len, want))
    assert n > 1000
    missing = _builders_in_templates() - seen
    assert not missing, f"grasp builders not exercised: {missing}"


@pytest.mark.parametrize("category", ["storage_furniture", "dishwasher", "oven", "kettle", "faucet", "safe"])
def test_generation_and_point_sampling_build_no_grasps(category, monkeypatch):
    made = []
    init = Deferred.__init__

    def tracked(self, fn, *args):
        init(self, fn, *args)
        made.append(self)

    monkeypatch.setattr(Deferred, "__init__", tracked)
    for seed in range(4):
        obj = artipg.generate(category, seed)
        obj.sample_points(256, seed=seed)
        assert made and all(d.fn is not None for d in made), f"{category} {seed}: grasps built by (b)"
        _grasp_bits(obj)  # reading them builds those of the object's parts
        assert any(d.fn is None for d in made)
        made.clear()
