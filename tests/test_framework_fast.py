"""The framework's fast paths give the bits of the plain computations they replace:
Part.bounds' stacked corners, and the compiled (numba) twins of the templates' patches
and local boxes that PrimitiveTable uses (artipg.geometry.kernels)."""

from __future__ import annotations

import copy

import numpy as np
import pytest

import artipg
from artipg.annotate.points import PrimitiveTable
from artipg.geometry import cuboid
from artipg.geometry.box import Cuboid
from artipg.geometry.patches import FAMILIES
from artipg.geometry.transforms import rot_x, rot_z, translation
from artipg.model import ObjectBuilder, Part
from test_points_fast import GEOMS, _object_groups, _param_cases, _random_params, same


CATS = artipg.categories()


@pytest.mark.parametrize("category", CATS)
def test_part_bounds_is_the_union_of_the_primitive_bounds(category):
    for seed in range(3):
        for part in artipg.generate(category, seed).parts:
            b = np.array([p.bounds() for p in part.primitives])
            plain = np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])
            assert same(part.bounds(), plain), part.name


# ---------------------------------------------------------------- compiled patch families and boxes

def _table(geoms_params: list, rng) -> PrimitiveTable:
    """A table whose groups are ``(geom, P)`` pairs, rows dealt to shuffled global indices."""
    N = sum(len(P) for _, P in geoms_params)
    order = rng.permutation(N)
    start, foff, flat = [0], [0], []
    for _, P in geoms_params:
        start.append(start[-1] + len(P))
        foff.append(foff[-1] + P.size)
        flat.append(P.ravel())
    T = np.tile(np.eye(4), (N, 1, 1))
    T[:, :3, 3] = rng.random((N, 3))
    return PrimitiveTable([g for g, _ in geoms_params], np.concatenate(flat), start, foff, order, T,
                          np.zeros(N, dtype=np.int64), np.zeros(N, dtype=np.int64), np.zeros(1, dtype=np.int64))


def _plain_cell_rows(fams) -> tuple:
    """Family code (K,) and zero-padded parameter rows (K, 15) of every cell, family by family."""
    code = np.concatenate([np.full(f.stop - f.start, list(FAMILIES).index(f.name)) for f in fams])
    Q = np.zeros((len(code), max(FAMILIES.values())))
    for f in fams:
        Q[f.start:f.stop, :len(f.params)] = f.params.T
    return code, Q


def _same_families(table) -> bool:
    got, want = table.families, table._plain_families()
    code, Q = table.cell_rows
    want_code, want_Q = _plain_cell_rows(want)
    area = np.concatenate([w.area for w in want])
    return len(got) == len(want) and all(
        (g.name, g.start, g.stop) == (w.name, w.start, w.stop) and same(g.params, w.params)
        and same(g.prim, w.prim) and same(g.area, w.area) for g, w in zip(got, want)) \
        and same(table.cell_areas, area) and same(table.cell_prim, np.concatenate([w.prim for w in want])) \
        and same(code, want_code) and same(Q, want_Q) and same(table.cell_cdf, np.cumsum(area)) \
        and same(table.cell_p, area / area.sum())


def _same_centre_half(table) -> bool:
    """The compiled centres and half extents of the local boxes, against transform_boxes' formula."""
    b = table._plain_local_boxes()
    c, h = table._local_centre_half
    return same(c, (b[:, 0] + b[:, 1]) * 0.5) and same(h, (b[:, 1] - b[:, 0]) * 0.5)


@pytest.mark.parametrize("name", sorted(GEOMS))
def test_compiled_families_and_local_boxes_match_the_templates(name):
    """Every template's compiled twin, on the edge cases of test_points_fast (cones, open
    caps, partial and full arcs, tapers, cut spheres, mixed prism side counts...)."""
    rng = np.random.default_rng(11)
    cases = [P for n, P in _param_cases() if n == name] + [P for n, P in _object_groups(1) if n == name]
    for P in cases:
        table = _table([(GEOMS[name], np.ascontiguousarray(P, dtype=float))], rng)
        assert table._packed is not None and table._compiled_boxes()
        assert _same_families(table), name
        assert same(table.local_boxes, table._plain_local_boxes()), name
        assert _same_centre_half(table), name


def test_compiled_families_and_local_boxes_match_on_mixed_tables():
    """Several templates in one table, in every order, rows scattered over the indices."""
    rng = np.random.default_rng(12)
    names = sorted(GEOMS)
    for _ in range(40):
        picked = rng.permutation(names)[:int(rng.integers(1, len(names) + 1))]
        table = _table([(GEOMS[n], _random_params(n, int(rng.integers(1, 9)), rng)) for n in picked], rng)
        assert _same_families(table)
        assert same(table.local_boxes, table._plain_local_boxes()) and _same_centre_half(table)


@pytest.mark.parametrize("category", CATS)
def test_compiled_table_matches_the_numpy_table_on_objects(category):
    for seed in range(3):
        obj = artipg.generate(category, seed)
        table = obj.primitive_table
        assert table._packed is not None and _same_families(table) and table._compiled_boxes()
        assert same(table.local_boxes, table._plain_local_boxes()) and _same_centre_half(table)
        plain = copy.copy(table)  # the same arrays, without the cached compiled results
        for k in ("local_boxes", "_local_centre_half", "families", "_cells", "cell_p"):
            plain.__dict__.pop(k, None)
        plain._packed = None  # the numpy path throughout
        for qpos in (None, obj.limits()[:, 1], 0.3 * obj.limits()[:, 0] + 0.7 * obj.limits()[:, 1]):
            L = obj.link_poses(qpos)
            assert same(table.bounds(L), plain.bounds(L))
        assert same(table.world_boxes(L), plain.world_boxes(L))
        # the plain path's cells, from the plain families
        assert _same_families(plain)
        assert all(same(a, b) for a, b in zip(plain.cell_rows, table.cell_rows))
        assert same(plain.cell_cdf, table.cell_cdf) and same(plain.cell_p, table.cell_p)


def test_compiled_prism_boxes_match_bounds_batch_on_edge_rows():
    """Prism and TriPrism local boxes: signed zeros and NaNs as np.minimum / np.maximum
    give them, and prisms whose side count is off the kernel's table (non-integer, out of
    range) left to bounds_batch."""
    from artipg.geometry.prism import Prism, TriPrism

    rng = np.random.default_rng(13)
    nan = np.nan
    tri = np.array([[0.0, 0.0, 0.0, 0.0], [-0.0, -0.0, -0.0, -0.0], [0.0, -0.0, 0.0, 1.0], [-0.0, 0.0, -0.0, 1.0],
                    [0.4, -0.0, -0.2, 0.1], [0.4, 0.3, 0.2, -0.0], [nan, 0.3, 0.1, 0.2], [0.4, nan, nan, 0.2],
                    [0.4, 0.3, -0.2, 0.1]])
    prism = np.array([[0.0, 0.0, 3.0], [-0.0, -0.0, 16.0], [0.3, 0.2, 7.0], [nan, 0.2, 5.0], [0.3, nan, 4.0]])
    def same_bits(a, b):  # signed zeros included; a NaN's sign is the arithmetic's choice
        a, b = np.where(np.isnan(a), nan, a), np.where(np.isnan(b), nan, b)
        return same(a, b)

    for geoms_params in ([(TriPrism, tri)], [(Prism, prism)], [(Prism, prism), (TriPrism, tri)]):
        table = _table(geoms_params, rng)
        boxes = table._plain_local_boxes()
        assert same_bits(table.local_boxes, boxes)
        c, h = table._local_centre_half
        assert same_bits(c, (boxes[:, 0] + boxes[:, 1]) * 0.5) and same_bits(h, (boxes[:, 1] - boxes[:, 0]) * 0.5)
    for n in (2.0, 17.0, 4.5, nan):
        bad = np.vstack([prism[:3], [[0.3, 0.2, n]]])
        table = _table([(Cuboid, np.ones((2, 3))), (Prism, bad), (TriPrism, tri[:6])], rng)
        assert same(table.local_boxes, table._plain_local_boxes()) and _same_centre_half(table), n


def test_compiled_tables_take_only_exact_affine_rows():
    """The compiled affine rows rely on at most two coefficients of ±1/2 or ±1 per row."""
    from artipg.geometry.kernels import _sparse

    _sparse(np.array([[[0.5, -1.0, 0.0, 2.0]]]))
    for bad in ([[[0.5, 0.5, 0.5, 0.0]]], [[[0.25, 0.0, 0.0, 0.0]]]):
        with pytest.raises(ValueError):
            _sparse(np.array(bad))


# ---------------------------------------------------------------- link poses and the normalisation

def test_primitive_table_of_groups_like_a_per_primitive_loop():
    """The table PrimitiveTable.of builds (link order, groups by first appearance, packed
    parameters), against a per-primitive loop."""
    for category in CATS:
        obj = artipg.generate(category, 1)
        table = PrimitiveTable.of(obj)
        rows, geoms = [], []
        for link in obj.links:
            for part in link.parts:
                for prim in part.primitives:
                    rows.append((prim.geom, prim.params))
                    if prim.geom not in geoms:
                        geoms.append(prim.geom)
        assert [g.geom for g in table.groups] == geoms
        for g in table.groups:
            idx = [i for i, (geom, _) in enumerate(rows) if geom is g.geom]
            assert same(g.prim, np.array(idx, dtype=np.int64))
            assert same(g.P, np.array([rows[i][1] for i in idx], dtype=float))
        assert table._n_root == sum(len(p.primitives) for p in obj.links[0].parts)


def _plain_link_poses(obj, qpos=None):
    """One link at a time, as the definition reads."""
    q = obj.qpos_dict(qpos)
    idx = obj.link_index
    T = np.empty((len(obj.links), 4, 4))
    T[0] = np.eye(4)
    for i in range(1, len(obj.links)):
        j = obj.links[i].joint
        v = q.get(j.name, 0.0)
        T[i] = (T[idx[j.parent]] @ j.origin) @ j.motion(v) if v else T[idx[j.parent]] @ j.origin
    return T


def _tree(normalize: bool):
    """Links out of depth order (root, a, b under a, c, d under b, e under c), parts on all."""
    rng = np.random.default_rng(5)
    b = ObjectBuilder()
    made = {"root": b.create_link("root")}
    for name, parent in (("a", "root"), ("b", "a"), ("c", "root"), ("d", "b"), ("e", "c")):
        lb = made[name] = b.create_link(name, made[parent])
        lb.set_joint("revolute", rot_z(rng.random()) @ translation(*rng.random(3)), axis=rng.random(3) - 0.5,
                     limits=(-1.0, 1.0))
    for name, lb in made.items():
        for k in range(2):
            prim = cuboid(*(rng.random(3) + 0.1), rot_x(rng.random()) @ translation(*rng.random(3)))
            lb.add(Part("body", "box", [prim]), rot_x(rng.random()) @ translation(*(rng.random(3) - 0.5)))
    return b.build("test", "test", 0, normalize=normalize)


def test_link_poses_a_level_at_a_time_match_one_link_at_a_time():
    objs = [_tree(True)] + [artipg.generate(c, s) for c in CATS for s in range(2)]
    for obj in objs:
        lim = obj.limits()
        for qpos in (None, lim[:, 1], 0.3 * lim[:, 0] + 0.7 * lim[:, 1]):
            assert same(obj.link_poses(qpos), _plain_link_poses(obj, qpos))


def test_normalisation_shifts_poses_and_frames_like_the_plain_loop():
    obj, raw = _tree(True), _tree(False)
    b = raw.bounds()
    c = (b[0] + b[1]) / 2.0
    S = translation(-c[0], -c[1], -b[0, 2])
    root = raw.links[0]
    for part in root.parts:
        part.pose = S @ part.pose
    for j in raw.joints:
        if j.parent == root.name:
            j.origin = S @ j.origin
    table = raw.primitive_table
    m = table.prim_link == 0
    table.prim_T[m] = S @ table.prim_T[m]
    assert all(same(p.pose, q.pose) for p, q in zip(obj.parts, raw.parts))
    assert all(same(j.origin, k.origin) for j, k in zip(obj.joints, raw.joints))
    assert same(obj.primitive_table.prim_T, table.prim_T)


def test_compiled_paths_propagate_nan_like_numpy():
    """A NaN parameter spoils the same cells and boxes on both paths (values compared
    NaN-aware: NaN payloads are not part of the contract)."""
    rng = np.random.default_rng(13)
    for name in sorted(GEOMS):
        for col in range(len(GEOMS[name].params)):
            if name == "Prism" and col == 2:
                continue  # a NaN side count makes numpy's patches raise
            P = _random_params(name, 4, rng)
            P[1, col] = np.nan
            table = _table([(GEOMS[name], P)], rng)
            got, want = table.families, table._plain_families()
            assert [(f.name, f.start, f.stop) for f in got] == [(f.name, f.start, f.stop) for f in want]
            for g, w in zip(got, want):
                np.testing.assert_array_equal(g.params, w.params)
                np.testing.assert_array_equal(g.area, w.area)
            np.testing.assert_array_equal(table.local_boxes, table._plain_local_boxes())
            plain = copy.copy(table)
            plain.__dict__.pop("_local_centre_half", None)
            plain._packed = None
            L = np.eye(4)[None]
            np.testing.assert_array_equal(table.bounds(L), plain.bounds(L))
