"""The build's short cuts give what the plain computations give: the primitive table's
offset arrays, the stacked box products of PrimitiveTable.bounds, and the values cached
by the first bounds (table, packed arrays, local boxes, link levels) against the
cached properties read first."""

from __future__ import annotations

import copy

import numpy as np
import pytest

import artipg
from artipg.annotate.points import PrimitiveTable, transform_boxes
from test_framework_fast import _table
from test_points_fast import GEOMS, _random_params, same

CATS = artipg.categories()


@pytest.mark.parametrize("category", CATS)
def test_table_offsets_and_packed_arrays_are_the_group_lists(category):
    for seed in range(2):
        table = PrimitiveTable.of(artipg.generate(category, seed))
        foff, start = table._offsets
        assert same(foff, np.array(table._foff)) and same(start, np.array(table._start))
        plain = copy.copy(table)
        plain.__dict__.pop("_packed", None)
        plain._offsets = None  # _pack makes them from the lists
        assert all(same(a, b) for a, b in zip(table._packed, plain._packed))


def _axis_turns(rng, n):
    """(n, 3, 3) signed permutations with signed zeros off the axes."""
    R = np.zeros((n, 3, 3))
    for i in range(n):
        R[i, np.arange(3), rng.permutation(3)] = rng.choice([-1.0, 1.0], 3)
    R[R == 0] = rng.choice([0.0, -0.0], int((R == 0).sum()))
    return R


def test_stacked_box_products_match_transform_boxes():
    """R c and |R| h taken as one stacked product give transform_boxes' two products:
    signed-zero turns, centred and off-centre boxes, tiny and huge scales, a NaN."""
    rng = np.random.default_rng(21)
    names = sorted(GEOMS)
    for trial in range(60):
        picked = rng.permutation(names)[:int(rng.integers(1, 4))]
        table = _table([(GEOMS[n], _random_params(n, int(rng.integers(1, 7)), rng)) for n in picked], rng)
        N = table.n_prims
        T = table.prim_T
        T[:, :3, :3] = _axis_turns(rng, N)
        turned = rng.random(N) < 0.5  # others: general rotations (QR of a random matrix)
        T[turned, :3, :3] = np.linalg.qr(rng.standard_normal((int(turned.sum()), 3, 3)))[0]
        T[:, :3, 3] = rng.standard_normal((N, 3)) * rng.choice([1e-9, 1.0, 1e6], (N, 1))
        T[:, :3, 3][rng.random((N, 3)) < 0.2] = -0.0
        if trial % 10 == 9:
            T[int(rng.integers(N)), 1, 1] = np.nan
        L = np.eye(4)[None]
        L[0, :3, :3] = _axis_turns(rng, 1)[0] if trial % 2 else np.eye(3)
        assert table._compiled_boxes()
        got = table.bounds(L)
        b = transform_boxes(table._plain_local_boxes(), table.world_all(L))
        want = np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])
        if np.isnan(want).any() or np.isnan(got).any():
            np.testing.assert_array_equal(got, want)  # NaN-aware: payloads are not the contract
        else:
            assert same(got, want), trial


@pytest.mark.parametrize("category", CATS)
def test_first_bounds_caches_what_the_properties_give(category):
    """obj.bounds() first (the build's order) caches the table, its packed arrays, local
    boxes and centres and the link levels; reading the cached properties first gives the
    same values."""
    import artipg.geometry.kernels  # noqa: F401  (numba loaded: the compiled path)

    for seed in range(2):
        obj = artipg.generate(category, seed)
        fresh = copy.copy(obj)
        fresh.__dict__ = {k: v for k, v in obj.__dict__.items() if k not in ("primitive_table", "_levels")}
        b = fresh.bounds()
        t = fresh.__dict__["primitive_table"]
        assert {"_packed", "local_boxes", "_local_centre_half"} <= set(t.__dict__)
        assert "_levels" in fresh.__dict__ or len(obj.links) == 1
        other = PrimitiveTable.of(obj)  # through the properties
        assert same(other.local_boxes, t.local_boxes)
        assert all(same(x, y) for x, y in zip(other._local_centre_half, t._local_centre_half))
        assert all(same(x, y) for x, y in zip(other._packed, t._packed))
        assert same(other.bounds(obj.link_poses()), b)
        assert same(fresh.link_poses(), obj.link_poses())
        assert _by_depth(fresh._levels) == _plain_depths(obj)


def _by_depth(levels) -> list:
    """The link indices of each level of ``ArticulatedObject._levels``."""
    return [list(members) for _, _, _, members in levels]


def _plain_depths(obj) -> list:
    """The non-root links grouped by depth, in link order, from each link's chain of parents."""
    idx = obj.link_index
    depth = {}
    for i, link in enumerate(obj.links[1:], 1):
        d, name = 0, link.name
        while name != obj.links[0].name:
            name = obj.links[idx[name]].joint.parent
            d += 1
        depth[i] = d
    return [[i for i in depth if depth[i] == d] for d in range(1, max(depth.values(), default=0) + 1)]


def test_levels_of_trees_out_of_depth_order():
    from test_framework_fast import _tree

    for normalize in (True, False):
        obj = _tree(normalize)
        assert _by_depth(obj._plan_levels()) == _plain_depths(obj) == [[1, 3], [2, 5], [4]]
