"""The vectorised machinery of the geometric checks equals its plain definitions.

The checks (:mod:`artipg.validate.checks`) cull pairs by sweep and prune (or all
pairs at once), build every joint's poses in one batch, evaluate prepared signed
distances, work box-box pairs in one frame (world-aligned boxes by a shortcut), cull
samples by the radial extent of solids of revolution and compute only the samples
of the pieces asked for; each shortcut is compared here with the straightforward
computation it replaces, on random inputs and on real objects of every registered
category, most of them bit for bit. Broken objects (a part moved away, a hinge
flipped) are caught with the right names.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg
from artipg.geometry import cuboid, frustum, prism, ring, sphere, torus, tri_prism
from artipg.geometry.transforms import rotation, translation
from artipg.validate import check_object
from artipg.validate.checks import run_checks
from artipg.validate.contacts import (box_box, close_pairs, evaluate, overlapping, pair_distance,
                                      refine_distance, world_boxes)
from artipg.validate.kinematics import Kinematics, motion, rotations
from artipg.validate.shapes import Pieces
from conftest import CATEGORIES

SEEDS = (0, 1, 2)


def _pieces(obj):
    return Kinematics.of(obj), Pieces.of(obj, np.random.default_rng(0x5A3B1E))


# ---------------------------------------------------------------- building blocks

def _overlap_reference(ca, ha, cb, hb, pad):
    """Boolean (A, B): boxes closer than ``pad`` on every axis, one pair at a time."""
    return np.array([[all(abs(ca[i, k] - cb[j, k]) - (ha[i, k] + hb[j, k]) < pad for k in range(3))
                      for j in range(len(cb))] for i in range(len(ca))], dtype=bool).reshape(len(ca), len(cb))


@pytest.mark.parametrize("pad", [2e-3, 0.0, -1e-4])
def test_close_pairs_equal_the_all_pairs_test(pad):
    """Both the all-pairs pass (small sets) and sweep and prune (large ones), with
    and without labels, against the plain per-pair test."""
    import artipg.validate.contacts as contacts

    rng = np.random.default_rng(3)
    for trial in range(40):
        M = int(rng.integers(0, 50)) if trial < 30 else int(rng.integers(contacts._DENSE - 5, contacts._DENSE + 60))
        c, h = rng.normal(size=(M, 3)) * 0.3, rng.uniform(0.0, 0.2, (M, 3))
        if trial % 2:  # touching faces and equal coordinates
            c, h = np.round(c, 1), np.round(h, 1)
        label = rng.integers(0, 4, M)
        a, b = np.triu_indices(M, 1)
        ov = (_overlap_reference(c, h, c, h, pad) if M < 60 else overlapping(c, h, c, h, pad))[a, b]
        x, y = close_pairs(c, h, pad)
        assert np.array_equal(x, a[ov]) and np.array_equal(y, b[ov])
        ov &= label[a] != label[b]
        x, y = close_pairs(c, h, pad, label)
        assert np.array_equal(x, a[ov]) and np.array_equal(y, b[ov])
    A, B = rng.normal(size=(30, 3)) * 0.3, rng.normal(size=(20, 3)) * 0.3
    hA, hB = rng.uniform(0.0, 0.2, (30, 3)), rng.uniform(0.0, 0.2, (20, 3))
    assert np.array_equal(overlapping(A, hA, B, hB, pad), _overlap_reference(A, hA, B, hB, pad))


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


def test_box_box_of_world_aligned_boxes_is_the_separating_axis_test():
    """Boxes turned by quarter turns (axes permuted and flipped) take the world-aligned
    shortcut, which must give the general test's values, overlapping, touching
    and apart (within the margin: exact distances; beyond: the axis gap)."""
    from artipg.validate.contacts import _sat_box_box

    rng = np.random.default_rng(8)
    K = 600
    quarter = [rotation(ax, k * np.pi / 2) for ax in np.eye(3) for k in range(4)]
    for W in quarter:  # exact permutations: cos/sin of quarter turns rounded to 0, +-1
        W[:3, :3] = np.round(W[:3, :3])
    ha, hb = np.round(rng.uniform(0.01, 0.1, (K, 3)), 3), np.round(rng.uniform(0.01, 0.1, (K, 3)), 3)
    Wa = np.array([quarter[i] for i in rng.integers(0, len(quarter), K)])
    Wb = np.array([quarter[i] for i in rng.integers(0, len(quarter), K)])
    Wa[:, :3, 3] = np.round(rng.normal(size=(K, 3)) * 0.08, 3)  # many touching faces
    Wb[:, :3, 3] = np.round(rng.normal(size=(K, 3)) * 0.08, 3)
    ea = np.abs(Wa[:, :3, :3]) @ ha[:, :, None]
    eb = np.abs(Wb[:, :3, :3]) @ hb[:, :, None]
    Wb[:60, :3, 3] = Wa[:60, :3, 3]  # face to face along x: touching
    Wb[:60, 0, 3] += (ea + eb)[:60, 0, 0]
    margin = np.where(rng.uniform(size=K) < 0.5, 2e-3, np.where(rng.uniform(size=K) < 0.5, 0.0, np.inf))
    got, want = box_box(ha, hb, Wa, Wb, margin), _sat_box_box(ha, hb, Wa, Wb, margin)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    assert (got < -1e-9).sum() > K // 5 and (np.abs(got) < 1e-9).sum() > 30 and (got > 1e-9).sum() > K // 5
    mixed = Wa.copy()
    mixed[::3] = rotation(rng.normal(size=3), 0.4)  # some general pairs in the same call
    mixed[::3, :3, 3] = Wa[::3, :3, 3]
    np.testing.assert_allclose(box_box(ha, hb, mixed, Wb, margin), _sat_box_box(ha, hb, mixed, Wb, margin),
                               rtol=0, atol=1e-12)


@pytest.mark.parametrize("category", CATEGORIES)
def test_piece_sdfs_are_each_templates_sdf(category):
    """Mixed rows, grouped by distinct solid, give each piece's template SDF."""
    rng = np.random.default_rng(11)
    for seed in SEEDS:
        _, pieces = _pieces(artipg.generate(category, seed))
        rows = rng.integers(0, pieces.n, 500)
        x = pieces.center[rows] + rng.normal(size=(500, 3)) * pieces.half[rows]
        want = np.empty(len(rows))
        for i, r in enumerate(rows.tolist()):
            g = pieces.geom[r]
            want[i] = g.sdf(tuple(pieces.params[r, :len(g.params)]), x[[i]])[0]
        np.testing.assert_allclose(pieces.sdf(rows, x), want, rtol=0, atol=1e-12)
        np.testing.assert_allclose(pieces.prepare(rows)(x), want, rtol=0, atol=1e-12)


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
    rng = np.random.default_rng(4)
    a = rng.normal(size=(500, 3))
    a /= np.linalg.norm(a, axis=1, keepdims=True)
    a[:60] = np.eye(3)[rng.integers(0, 3, 60)]
    q = rng.uniform(-7.0, 7.0, 500)
    q[::7] = 0.0
    assert np.array_equal(rotations(a, q), motion("revolute", a, q)[:, :3, :3])  # same arithmetic


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


@pytest.mark.parametrize("category", CATEGORIES)
def test_radial_cull_changes_nothing_at_or_below_the_margin(category, monkeypatch):
    """Culling samples outside the radial extent of solids of revolution (done when
    many samples are near) keeps every result at or below the margin."""
    import artipg.validate.contacts as contacts

    for seed in SEEDS:
        kin, pieces = _pieces(artipg.generate(category, seed))
        W = kin.poses()[pieces.link] @ pieces.T
        c, h = world_boxes(pieces, W)
        a, b = close_pairs(c, h, 0.01)
        if not len(a):
            continue
        rel = np.linalg.inv(W[b]) @ W[a]
        for margin in (0.0, 2e-3):
            monkeypatch.setattr(contacts, "_RADIAL_CULL", 0)
            culled = evaluate(pieces, a, b, rel, margin)
            monkeypatch.setattr(contacts, "_RADIAL_CULL", 1 << 60)
            full = evaluate(pieces, a, b, rel, margin)
            low = full <= margin
            assert np.array_equal(culled[low], full[low]) and (culled[~low] > margin).all(), (category, seed)


def test_samples_are_the_templates_own_draws_whichever_pieces_are_asked_for():
    """The samples of every piece are those of the geometry template's own
    ``sample_components`` over all pieces of the template (one stream each), drawn
    all at once or a few pieces at a time in any order (only the wanted pieces'
    samples are computed; the stream is consumed as for all of them)."""
    from artipg.validate.shapes import DENSITY, MAX_PER_COMPONENT, MIN_PER_COMPONENT, _BOX_FEATURES
    from artipg.geometry.box import Cuboid

    rng = np.random.default_rng(9)
    for category in CATEGORIES:
        for seed in SEEDS[:2]:
            _, pieces = _pieces(artipg.generate(category, seed))
            want = {}
            for k, g in enumerate(pieces._kinds):
                rows = np.flatnonzero(pieces._kind == k)
                P = pieces.params[rows, :len(g.params)]
                area = g.component_areas(P)
                n = np.where(area > 0, np.clip(np.ceil(area * DENSITY), MIN_PER_COMPONENT, MAX_PER_COMPONENT), 0)
                cells = np.repeat(np.arange(n.size), n.astype(np.int64).ravel())
                r = cells // area.shape[1]
                p, _ = g.sample_components(P[r], cells - r * area.shape[1], pieces._stream(k))
                for i, row in enumerate(rows):
                    want[row] = p[r == i]
                    if g is Cuboid:
                        want[row] = np.concatenate([want[row], _BOX_FEATURES * P[i]])
            order = rng.permutation(pieces.n)
            for chunk in np.array_split(order, 3):
                pieces.require(chunk)
            for row in range(pieces.n):
                assert np.array_equal(pieces.samples(row), want[row]), (category, seed, row)


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


def _hand_pieces(prims, links, seed=0x5A3B1E):
    """Pieces of primitives ``prims`` (one part each, on links ``links``), piece frames
    equal to their link frames."""
    params = np.zeros((len(prims), max(len(p.params) for p in prims)))
    for i, p in enumerate(prims):
        params[i, :len(p.params)] = p.params
    b = np.stack([p.geom.bounds_batch(np.array([p.params], dtype=float))[0] for p in prims])
    return Pieces(links, np.arange(len(prims)), np.tile(np.eye(4), (len(prims), 1, 1)), (b[:, 0] + b[:, 1]) / 2,
                  (b[:, 1] - b[:, 0]) / 2, [p.geom for p in prims], params, [f"p{i}" for i in range(len(prims))],
                  links, np.random.default_rng(seed))


def test_overlapping_round_parts_penetrate_whatever_was_computed_before():
    """Two knob balls 4 mm into each other, and a knob post 3 mm into a ball: the
    depths are the same alone, repeated, after the full checks ran on the same pieces
    and after other pieces were sampled first (the sample stream once leaked between
    calls, and a 5 mm knob overlap passed)."""
    prims = [sphere(0.017), sphere(0.019), frustum(0.008, 0.008, 0.03), cuboid(0.3, 0.3, 0.01)]
    L = len(prims)
    kin = Kinematics([f"l{i}" for i in range(L)], np.array([-1] + [0] * (L - 1)), [""] + ["j"] * (L - 1),
                     ["fixed"] * L, np.tile(np.eye(4), (L, 1, 1)), np.zeros((L, 3)), np.zeros((L, 2)))
    kin.origin[1] = translation(0.032, 0.0, 0.0)  # ball 1: 0.017 + 0.019 - 0.004 from ball 0
    kin.origin[2] = translation(0.0, 0.0, -0.017 - 0.015 + 0.003)  # post: its top 3 mm into ball 0
    kin.origin[3] = translation(0.0, 0.3, 0.0)  # a plate far away
    W = kin.poses()
    a, b = np.array([0, 0, 2, 3]), np.array([1, 2, 3, 1])

    def depths(pieces):
        return pair_distance(pieces, a, b, W[a], W[b], 2e-3)

    fresh = depths(_hand_pieces(prims, np.arange(L)))
    assert fresh[0] == pytest.approx(-0.004, abs=1e-12)  # balls: exact
    assert fresh[1] < -1e-3  # the post's end face, sampled
    pieces = _hand_pieces(prims, np.arange(L))
    first = depths(pieces)
    assert np.array_equal(first, fresh) and np.array_equal(depths(pieces), fresh)
    r = run_checks(kin, pieces)
    assert np.array_equal(depths(pieces), fresh)
    pen = r["penetration"]
    assert not pen.ok
    assert {tuple(sorted(i.parts)) for i in pen.issues} == {("p0", "p1"), ("p0", "p2")}
    assert max(i.amount for i in pen.issues) == pytest.approx(0.004, abs=1e-12)
    other = _hand_pieces(prims, np.arange(L))
    other.require(np.array([3, 1]))  # other pieces first
    assert np.array_equal(depths(other), fresh)
    for i in range(L):
        assert np.array_equal(other.samples(i), pieces.samples(i))


def _obb_gap(pieces, a, b, Wa, Wb):
    """Signed separation (K,) of the posed local bounding boxes of pieces ``a`` and
    ``b`` (exact distance when apart): a lower bound of the distance of the pieces."""
    Ta, Tb = Wa.copy(), Wb.copy()
    Ta[:, :3, 3] += np.einsum("kij,kj->ki", Wa[:, :3, :3], pieces.center[a])
    Tb[:, :3, 3] += np.einsum("kij,kj->ki", Wb[:, :3, :3], pieces.center[b])
    return box_box(pieces.half[a], pieces.half[b], Ta, Tb, np.full(len(a), np.inf))


def test_refinement_never_brings_distant_pieces_into_contact():
    """Pieces whose bounding boxes are centimetres apart stay centimetres apart after
    refinement: a projection step that lands off the source surface (a prism's edge,
    a dome's rim) once gave ~0 for a prism 3 cm from a dome."""
    rng = np.random.default_rng(17)
    shapes = [tri_prism(0.13, 0.065, 0.0, 0.014), sphere(0.22, 0.185, 0.22), prism(0.03, 0.05, 6),
              ring(0.05, 0.04, 0.02, 4.0), torus(0.04, 0.008, 3.0), frustum(0.02, 0.035, 0.04), sphere(0.03, -0.01)]
    K = 400
    ia, ib = rng.integers(0, len(shapes), K), rng.integers(0, len(shapes), K)
    prims = [shapes[i] for i in ia] + [shapes[i] for i in ib]
    pieces = _hand_pieces(prims, np.arange(2 * K))
    a, b = np.arange(K), np.arange(K, 2 * K)
    Wa = np.array([rotation(rng.normal(size=3), rng.uniform(0, np.pi)) for _ in range(K)])
    Wb = np.array([rotation(rng.normal(size=3), rng.uniform(0, np.pi)) for _ in range(K)])
    # b slid away from a along a random direction until their boxes are 5-30 mm apart
    # (bisection: the gap is a convex function of the offset)
    u = rng.normal(size=(K, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    target = rng.uniform(0.005, 0.03, K)
    lo, hi = np.zeros(K), np.ones(K)
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        Wb[:, :3, 3] = mid[:, None] * u
        far = _obb_gap(pieces, a, b, Wa, Wb) > target
        hi, lo = np.where(far, mid, hi), np.where(far, lo, mid)
    Wb[:, :3, 3] = hi[:, None] * u
    gap = _obb_gap(pieces, a, b, Wa, Wb)
    assert (gap >= 0.005 - 1e-9).all()
    sampled = pair_distance(pieces, a, b, Wa, Wb, np.inf)
    d = refine_distance(pieces, a, b, Wa, Wb)
    # an upper bound no worse than the samples; never "touching" (within the 2 mm of
    # the floating check) for pieces at least 5 mm apart
    assert (d <= sampled + 1e-12).all()
    assert (d > 2e-3).all(), np.sort(d)[:5]
    d3 = refine_distance(pieces, a, b, Wa, Wb, iters=3, stop_below=2e-3)  # as the checks call it
    assert (d3 > 2e-3).all()


def _close_round_pairs(category, seed, pad):
    """Pieces, rest poses and the pairs (a, b) of pieces of different parts whose boxes
    are within ``pad`` and which are not both boxes (the pairs refinement handles)."""
    kin, pieces = _pieces(artipg.generate(category, seed))
    W = kin.poses()[pieces.link] @ pieces.T
    c, h = world_boxes(pieces, W)
    a, b = close_pairs(c, h, pad)
    keep = ~(pieces.is_box[a] & pieces.is_box[b]) & (pieces.part[a] != pieces.part[b])
    return pieces, W, a[keep], b[keep]


@pytest.mark.parametrize("category", CATEGORIES)
def test_refined_rest_distances_respect_the_bounding_boxes(category):
    """On real objects, pieces whose oriented bounding boxes are 5 mm or more apart
    are never within the floating tolerance (2 mm) after refinement."""
    for seed in SEEDS:
        pieces, W, a, b = _close_round_pairs(category, seed, 0.02)
        if not len(a):
            continue
        far = _obb_gap(pieces, a, b, W[a], W[b]) >= 0.005
        d = refine_distance(pieces, a, b, W[a], W[b], iters=3, stop_below=2e-3)
        assert (d[far] > 2e-3).all(), (category, seed)


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


@pytest.mark.parametrize("category", CATEGORIES)
def test_piece_traits_hold_for_their_solids(category):
    """Every piece's box holds its samples; its radial extent holds the radius of
    every sample; symmetric pieces keep their SDF under a turn about their z axis;
    whole balls have the SDF of a ball; boxes are exactly the Cuboid pieces."""
    from artipg.geometry.box import Cuboid

    rng = np.random.default_rng(13)
    for seed in SEEDS:
        _, pc = _pieces(artipg.generate(category, seed))
        pc.require(np.arange(pc.n))
        assert np.array_equal(pc.is_box, np.array([g is Cuboid for g in pc.geom]))
        for i in range(pc.n):
            X = pc.samples(i)
            assert (np.abs(X - pc.center[i]) <= pc.half[i] + 1e-9).all(), (category, seed, i)
            rho = np.hypot(X[:, 0], X[:, 1])
            assert ((rho >= pc.radial[i, 0] - 1e-9) & (rho <= pc.radial[i, 1] + 1e-9)).all(), (category, seed, i)
            x = pc.center[i] + rng.normal(size=(200, 3)) * (pc.half[i] + 0.01)
            d = pc.sdf(np.full(len(x), i), x)
            if pc.symmetric[i]:
                turned = x @ rotation(np.array([0.0, 0.0, 1.0]), rng.uniform(0, 2 * np.pi))[:3, :3].T
                np.testing.assert_allclose(pc.sdf(np.full(len(x), i), turned), d, rtol=0, atol=1e-9)
            if pc.is_ball[i]:
                np.testing.assert_allclose(d, np.linalg.norm(x, axis=1) - pc.params[i, 0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("category", CATEGORIES)
def test_descendants_follow_the_parent_chains(category):
    for seed in SEEDS:
        kin = Kinematics.of(artipg.generate(category, seed))
        for k in range(kin.n_links):
            chain, i = set(), k
            while i >= 0:
                chain.add(i)
                i = int(kin.parent[i])
            assert [bool(kin.descendants[i, k]) for i in range(kin.n_links)] == \
                [i in chain for i in range(kin.n_links)], (category, seed, k)
