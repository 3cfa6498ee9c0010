"""Structural shortcuts in the chair, door, window and kettle rules and their templates:
each gives exactly what the plain computation it replaces gives (the same bits)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from artipg.categories.kettle import TURN, _at
from artipg.geometry import cuboid, cuboid_between, cylinder
from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.rules import ParamRecorder
from artipg.templates import seating
from artipg.templates.turn_handles import (DOOR_KNOBS, DOOR_LEVERS, SIDELESS, casement_handle, matching, replay,
                                           thumb_turn)


def _bits(a) -> bytes:
    return np.ascontiguousarray(np.asarray(a, dtype=float)).tobytes()


def _same_part(a, b) -> None:
    assert (a.semantic, a.template, a.actionable) == (b.semantic, b.template, b.actionable)
    assert len(a.primitives) == len(b.primitives)
    for pa, pb in zip(a.primitives, b.primitives):
        assert (pa.geom, pa.params, pa.role) == (pb.geom, pb.params, pb.role)
        assert _bits(pa.pose) == _bits(pb.pose)
    assert {k: _bits(v) for k, v in a.anchors.items()} == {k: _bits(v) for k, v in b.anchors.items()}
    assert a.regions.keys() == b.regions.keys()
    for k in a.regions:
        ra, rb = a.regions[k], b.regions[k]
        assert ra.roles == rb.roles and (ra.box is None) == (rb.box is None)
        assert ra.box is None or _bits(ra.box) == _bits(rb.box)
    assert [(_bits(g.pose), g.width, _bits(g.open_dir)) for g in a.grasps] == \
        [(_bits(g.pose), g.width, _bits(g.open_dir)) for g in b.grasps]


def _poses(rng, k):
    """Random rigid poses, some pure translations, some turned about x or y."""
    out = []
    for i in range(k):
        T = translation(*rng.uniform(-0.5, 0.5, 3))
        if i % 3 == 1:
            T = T @ rot_y(math.pi / 2)
        elif i % 3 == 2:
            T = T @ rot_y(rng.uniform(-3, 3))
        out.append(T)
    return out


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7])
def test_turns_stacked_products_are_the_products_one_by_one(n):
    rng = np.random.default_rng(n)
    R = seating.turns(n)
    assert not R.flags.writeable
    for T in _poses(rng, 30):
        stacked, chained = R @ T, (R @ T) @ seating._X_AXIS
        for i in range(n):
            assert _bits(rot_z(2 * math.pi * i / n)) == _bits(R[i])
            assert _bits(rot_z(2 * math.pi * i / n) @ T) == _bits(stacked[i])
            assert _bits(rot_z(2 * math.pi * i / n) @ T @ seating._X_AXIS) == _bits(chained[i])


def test_leaned_back_is_each_primitive_placed():
    rng = np.random.default_rng(1)
    for _ in range(50):
        prims = [cuboid_between(tuple(rng.uniform(-0.3, 0.0, 3)), tuple(rng.uniform(0.0, 0.3, 3)), role="post"),
                 cuboid(*rng.uniform(0.01, 0.3, 3), _poses(rng, 3)[2], role="board"),
                 cylinder(0.02, 0.3, _poses(rng, 2)[1], role="board")]
        lean = float(rng.uniform(0.05, 0.2))
        part = seating._back("panel_back", prims, lean, 0.5)
        R = rot_y(lean)
        for got, pr in zip(part.primitives, prims):
            want = pr.placed(R)
            assert (got.geom, got.params, got.role) == (want.geom, want.params, want.role)
            assert _bits(got.pose) == _bits(want.pose)


def test_kettle_at_is_the_product():
    zs = list(np.random.default_rng(2).uniform(-1.0, 1.0, 2000)) + [0.0, -0.0, 5e-324, -5e-324, 1e-3, 0.3]
    for z in zs:
        assert _bits(TURN @ translation(0, 0, z)) == _bits(_at(z))


@pytest.mark.parametrize("template", [*DOOR_LEVERS, *DOOR_KNOBS, thumb_turn], ids=lambda t: t.__name__)
@pytest.mark.parametrize("sides", [[1.0, -1.0], [-1.0, 1.0], [1.0, -1.0, -1.0, 1.0]])
def test_matching_copies_are_the_rebuilt_handles(template, sides):
    for seed in range(20):
        got = matching(template, ParamRecorder(np.random.default_rng(seed)).scope("handle"), sides)
        p = ParamRecorder(np.random.default_rng(seed)).scope("handle")
        want = [template(p if i == 0 else replay(p), side=s) for i, s in enumerate(sides)]
        assert len({id(h) for h in got}) == len(sides)
        for a, b in zip(got, want):
            _same_part(a, b)


def test_sideless_templates_ignore_side():
    for template in SIDELESS:
        for seed in range(20):
            p = ParamRecorder(np.random.default_rng(seed))
            _same_part(template(p, side=1.0), template(replay(p), side=-1.0))


def test_casement_handle_replayed_is_the_same():
    for seed in range(20):
        p = ParamRecorder(np.random.default_rng(seed)).scope("handle")
        for a, b in zip(casement_handle(p), casement_handle(replay(p))):
            _same_part(a, b)


