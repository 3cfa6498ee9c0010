"""The vectorised machinery of the geometric checks equals its plain definitions.

The checks (:mod:`artipg.validate.checks`) cull pairs by sweep and prune, build every
joint's poses in one batch, evaluate prepared signed distances and work box-box pairs
in one frame; each shortcut is compared here with the straightforward computation it
replaces, on random inputs and on real objects of every registered category. Broken
objects (a part moved away, a hinge flipped) are caught with the right names.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg
from artipg.geometry import cuboid, sphere
from artipg.geometry.transforms import rotation, translation
from artipg.validate import check_object
from artipg.validate.contacts import box_box, close_pairs, evaluate, overlapping, refine_distance, world_boxes
from artipg.validate.kinematics import Kinematics
from artipg.validate.rowsdf import PREPARE, ROW_SDF
from artipg.validate.shapes import Pieces
from conftest import CATEGORIES

SEEDS = (0, 1, 2)


def _pieces(obj):
    return Kinematics.of(obj), Pieces.of(obj, np.random.default_rng(0x5A3B1E))


# ---------------------------------------------------------------- building blocks

@pytest.mark.parametrize("pad", [2e-3, 0.0, -1e-4])
def test_close_pairs_equal_the_all_pairs_test(pad):
    rng = np.random.default_rng(3)
    for trial in range(60):
        M = int(rng.integers(0, 50))
        c, h = rng.normal(size=(M, 3)) * 0.3, rng.uniform(0.0, 0.2, (M, 3))
        if trial % 2:  # touching faces and equal coordinates
            c, h = np.round(c, 1), np.round(h, 1)
        a, b = np.triu_indices(M, 1)
        ov = overlapping(c, h, c, h, pad)[a, b]
        x, y = close_pairs(c, h, pad)
        assert np.array_equal(x, a[ov]) and np.array_equal(y, b[ov])


def _sat_reference(ha, hb, Wa, Wb):
    """Separating-axis overlap of two oriented boxes, one pair, world frame, 15 axes."""
    A, B = Wa[:3, :3], Wb[:3, :3]
    t = Wb[:3, 3] - Wa[:3, 3]
    axes = [A[:, i] for i in range(3)] + [B[:, j] for j in range(3)]
    axes += [np.cross(A[:, i], B[:, j]) for i in range(3) for j in range(3)]
    best = math.inf
    for ax in axes:
        n = np.linalg.norm(ax)
        if n <= 1e-9:
            continue
        ax = ax / n
        over = np.abs(ax @ A) @ ha + np.abs(ax @ B) @ hb - abs(ax @ t)
        best = min(best, over)
    return -best


def test_box_box_equals_a_per_pair_separating_axis_test():
    rng = np.random.default_rng(5)
    K = 300
    ha, hb = rng.uniform(0.01, 0.1, (K, 3)), rng.uniform(0.01, 0.1, (K, 3))
    Wa = np.array([rotation(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(K)])
    Wb = np.array([rotation(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(K)])
    Wa[: K // 3] = np.eye(4)  # axis-aligned pairs: parallel edges
    Wb[: K // 4] = np.eye(4)
    Wa[:, :3, 3] = rng.normal(size=(K, 3)) * 0.05
    Wb[:, :3, 3] = rng.normal(size=(K, 3)) * 0.05
    d = box_box(ha, hb, Wa, Wb, np.zeros(K))  # margin 0: the SAT value everywhere
    ref = np.array([_sat_reference(ha[k], hb[k], Wa[k], Wb[k]) for k in range(K)])
    assert (d < 0).sum() > K // 4 and (d > 0).sum() > K // 4
    np.testing.assert_allclose(d, ref, atol=1e-12)


@pytest.mark.parametrize("geom", list(ROW_SDF), ids=lambda g: g.name)
def test_prepared_sdfs_equal_the_row_sdfs(geom):
    rng = np.random.default_rng(7)
    K = 2000
    P = rng.uniform(0.01, 0.1, (K, len(geom.params)))
    names = list(geom.params)
    if "n" in names:  # prism sides
        P[:, names.index("n")] = rng.integers(3, 17, K)
    if "arc" in names:  # partial and full turns
        P[:, names.index("arc")] = np.where(rng.uniform(size=K) < 0.3, 2 * np.pi, rng.uniform(0.3, 6.0, K))
    if "z_lo" in names:
        P[:, names.index("z_lo")] *= -1.0
    x = rng.normal(size=(K, 3)) * 0.1
    assert np.array_equal(PREPARE[geom](P)(x), ROW_SDF[geom](P, x))


@pytest.mark.parametrize("category", CATEGORIES)
def test_piece_sdfs_equal_the_row_sdfs_of_each_template(category):
    """Mixed rows (frusta and rings share one polygon pass) give each template's values."""
    rng = np.random.default_rng(11)
    for seed in SEEDS:
        _, pieces = _pieces(artipg.generate(category, seed))
        rows = rng.integers(0, pieces.n, 500)
        x = pieces.center[rows] + rng.normal(size=(500, 3)) * pieces.half[rows]
        want = np.empty(len(rows))
        for i, r in enumerate(rows.tolist()):
            g = pieces.geom[r]
            want[i] = ROW_SDF[g](pieces.params[[r], :len(g.params)], x[[i]])[0]
        assert np.array_equal(pieces.sdf(rows, x), want)
        assert np.array_equal(pieces.prepare(rows)(x), want)


@pytest.mark.parametrize("category", CATEGORIES)
def test_sweep_table_and_batched_poses_equal_the_scalar_versions(category):
    for seed in SEEDS:
        kin = Kinematics.of(artipg.generate(category, seed))
        joint, q = kin.sweep_table(16)
        values = [kin.sweep_values(i, 16) for i in kin.movable()]
        assert np.array_equal(q, np.concatenate(values) if values else np.zeros(0))
        assert np.array_equal(joint, np.repeat(np.arange(len(values)), [len(v) for v in values]))
        mv = kin.movable()
        Q = np.zeros((3, kin.n_links))
        if len(mv):
            Q[1, mv] = 0.3
            Q[2, mv[0]] = -0.2
        P = kin.poses_batch(Q)
        for r in range(3):
            np.testing.assert_allclose(P[r], kin.poses({kin.joint_names[i]: Q[r, i] for i in mv}), atol=1e-12)


@pytest.mark.parametrize("category", CATEGORIES)
def test_evaluate_equals_the_minimum_over_all_samples(category):
    """Culled jobs and samples change nothing at or below the margin."""
    for seed in SEEDS:
        kin, pieces = _pieces(artipg.generate(category, seed))
        W = kin.poses()[pieces.link] @ pieces.T
        c, h = world_boxes(pieces, W)
        a, b = close_pairs(c, h, 0.01)
        keep = ~pieces.is_box[a] & (pieces.part[a] != pieces.part[b])
        a, b = a[keep], b[keep]
        if not len(a):
            continue
        rel = np.linalg.inv(W[b]) @ W[a]
        for margin in (0.0, 2e-3):
            got = evaluate(pieces, a, b, rel, margin)
            for k in range(len(a)):
                X = pieces.samples(a[k]) @ rel[k, :3, :3].T + rel[k, :3, 3]
                want = pieces.sdf(np.full(len(X), b[k]), X).min()
                if want <= margin:
                    assert got[k] == pytest.approx(want, abs=1e-12), (category, seed, k)
                else:
                    assert got[k] > margin


def test_refine_bounds_the_distance_of_a_ball_over_a_box_better_than_the_samples():
    box, ball = cuboid(0.2, 0.2, 0.02), sphere(0.03)
    from artipg.validate.shapes import Pieces as P

    geoms = [box.geom, ball.geom]
    params = np.zeros((2, 5))
    params[0, :3] = box.params
    params[1, :len(ball.params)] = ball.params
    b0 = box.geom.bounds_batch(np.array([box.params]))[0]
    b1 = ball.geom.bounds_batch(np.array([ball.params]))[0]
    center = np.array([(b0[0] + b0[1]) / 2, (b1[0] + b1[1]) / 2])
    half = np.array([(b0[1] - b0[0]) / 2, (b1[1] - b1[0]) / 2])
    pieces = P([0, 1], [0, 1], np.tile(np.eye(4), (2, 1, 1)), center, half, geoms, params, ["box", "ball"],
               [0, 1], np.random.default_rng(0))
    for gap in (0.0, 0.0015, 0.004, 0.02):
        Wb = translation(0.013, -0.021, 0.01 + 0.03 + gap)  # ball above the box's top face
        d = refine_distance(pieces, np.array([0]), np.array([1]), np.eye(4)[None], Wb[None])[0]
        X = pieces.samples(1) @ Wb[:3, :3].T + Wb[:3, 3]
        sampled = min(pieces.sdf(np.zeros(len(X), dtype=np.int64), X).min(),
                      pieces.sdf(np.ones(len(pieces.samples(0)), dtype=np.int64),
                                 (pieces.samples(0) - Wb[:3, 3]) @ Wb[:3, :3]).min())
        # an upper bound of the true distance (the gap), tighter than the samples'
        assert gap - 1e-9 <= d <= sampled
        if sampled > gap + 1e-6:  # the samples miss the closest points: refining gets closer
            assert d < sampled - 1e-7


# ---------------------------------------------------------------- broken objects

@pytest.mark.parametrize("category", CATEGORIES)
def test_a_part_moved_away_is_floating_and_named(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        li = max(range(len(obj.links)), key=lambda i: (len(obj.links[i].parts) > 0, i))
        link = obj.links[li]
        part = link.parts[-1]
        part.pose = translation(0.0, 0.0, 3.0) @ part.pose  # 3 m above everything
        obj.__dict__.pop("primitive_table", None)
        r = check_object(obj)
        assert "floating" in r.failed(), (category, seed)
        issues = r.checks["floating"].issues
        if len(link.parts) > 1:
            assert any(i.kind == "floating_part" and i.parts == [part.name] and i.links == [link.name] for i in issues)
        else:
            assert any(i.kind == "floating_link" and link.name in i.links for i in issues)
        assert min(i.amount for i in issues) > 1.0  # metres: far, not grazing


@pytest.mark.parametrize("category", CATEGORIES)
def test_validation_is_deterministic_and_independent_of_earlier_checks(category):
    """The check of an object does not depend on what was checked before it."""
    objs = [artipg.generate(category, s) for s in SEEDS]
    first = [check_object(o).to_json() for o in objs]
    again = [check_object(o).to_json() for o in reversed(objs)][::-1]
    assert first == again
