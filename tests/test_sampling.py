"""Labelled point sampling by property: determinism, points on the surface with unit
outward normals, counts per primitive proportional to area, labels covering the parts,
and the torus's tube law through the one family sampler."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

import artipg
from artipg.annotate.points import sample_points
from artipg.geometry.patches import TWO_PI, sample_family

CATEGORIES = artipg.categories()


def _prims(obj):
    return [pr for part in obj.parts for pr in part.primitives]


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_same_bytes_and_seeds_differ(category):
    a, b = artipg.generate(category, 3), artipg.generate(category, 3)
    pa, pb = sample_points(a, 512, seed=1), sample_points(b, 512, seed=1)
    for name in ("points", "normals", "semantic", "instance", "link", "primitive"):
        assert getattr(pa, name).tobytes() == getattr(pb, name).tobytes(), name
    assert list(a.params.items()) == list(b.params.items())
    assert not np.array_equal(sample_points(a, 512, seed=2).points, pa.points)


@pytest.mark.parametrize("category", CATEGORIES)
def test_points_lie_on_their_primitive_with_unit_normals(category):
    obj = artipg.generate(category, 5)
    pc = sample_points(obj, 1024, seed=0)
    W = obj.primitive_table.world_all(obj.link_poses())
    prims = _prims(obj)
    assert np.allclose(np.linalg.norm(pc.normals, axis=1), 1.0, atol=1e-9)
    for k in np.unique(pc.primitive):
        sel = pc.primitive == k
        R, t = W[k, :, :3], W[k, :, 3]
        local = (pc.points[sel] - t) @ R  # rigid poses: R^T (x - t)
        d = prims[k].geom.sdf(prims[k].params, local)
        assert np.abs(d).max() < 1e-6, (k, prims[k].geom.__name__)
        # outward: a small step along the normal leaves the solid
        out = local + 1e-5 * (pc.normals[sel] @ R)
        assert (prims[k].geom.sdf(prims[k].params, out) > 0).mean() > 0.99


@pytest.mark.parametrize("category", ["storage_furniture", "kettle", "eyeglasses", "faucet"])
def test_counts_per_primitive_follow_area_and_labels_cover_parts(category):
    obj = artipg.generate(category, 2)
    n = 40_000
    pc = sample_points(obj, n, seed=4)
    area = np.array([pr.area() for pr in _prims(obj)])
    counts = np.bincount(pc.primitive, minlength=len(area))
    keep = area > 0
    assert counts[~keep].sum() == 0
    p = area[keep] / area[keep].sum()
    big = p * n >= 5  # chi-square over cells with enough expected points, the rest pooled
    obs = np.append(counts[keep][big], counts[keep][~big].sum())
    exp = np.append(p[big], p[~big].sum()) * n
    obs, exp = obs[exp > 0], exp[exp > 0]
    assert stats.chisquare(obs, exp).pvalue > 1e-4
    # every part with a visible share of the surface is labelled, with its own ids
    table = obj.primitive_table
    part_area = np.bincount(table.prim_part, weights=area, minlength=len(obj.parts))
    assert set(np.flatnonzero(part_area / part_area.sum() > 1e-3)) <= set(pc.instance.tolist())
    assert np.array_equal(pc.semantic, table.part_semantic[pc.instance])
    assert np.array_equal(pc.link, table.prim_link[pc.primitive])


def test_parts_restrict_the_surface():
    obj = artipg.generate("storage_furniture", 1)
    pc = sample_points(obj, 500, seed=0, parts=[1])
    assert set(pc.instance.tolist()) == {1}


def test_sample_points_refuses_an_object_without_surface():
    from artipg.geometry import cuboid_between
    from artipg.model.builder import ObjectBuilder
    from artipg.model.part import Part

    b = ObjectBuilder()
    b.create_link("base").add(Part("body", "box", [cuboid_between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))]))
    with pytest.raises(ValueError, match="no surface"):
        sample_points(b.build("test", "a", 0, normalize=False), 10)


@pytest.mark.parametrize("e", [0.05, 0.3, 0.67, 0.95])
def test_torus_points_follow_the_area_law(e):
    """Tube angles of torus points from :func:`sample_family` against the exact law
    (v + e sin v) / (2π), and the arc angle uniform."""
    n = 100_000
    R, r, arc = 1.0, e, 4.0
    q = np.tile(np.array([[R], [r], [arc]]), (1, n))
    pts = sample_family("torus", q, np.random.default_rng(int(e * 1000)))
    x, y, z = pts[:3]
    v = np.arctan2(z, np.hypot(x, y) - R) % TWO_PI
    assert stats.kstest(v, lambda t: (t + e * np.sin(t)) / TWO_PI).pvalue > 1e-3
    th = np.arctan2(y, x) % TWO_PI
    assert stats.kstest(th / arc, "uniform").pvalue > 1e-3
    centre = np.stack([R * np.cos(th), R * np.sin(th), np.zeros(n)])
    np.testing.assert_allclose(pts[3:], (pts[:3] - centre) / r, atol=1e-9)


def test_unknown_family_is_refused():
    with pytest.raises(ValueError, match="unknown patch family"):
        sample_family("blob", np.zeros((3, 2)), np.random.default_rng(0))


@pytest.mark.parametrize("category", CATEGORIES)
def test_table_boxes_enclose_the_sampled_points(category):
    obj = artipg.generate(category, 7)
    # every movable joint half way (continuous joints at a quarter turn)
    q = {j.name: (0.5 * (j.limits[0] + j.limits[1]) if np.isfinite(j.limits).all() else 1.5)
         for j in obj.joints if j.movable}
    table = obj.primitive_table
    poses = obj.link_poses(q)
    pc = sample_points(obj, 2048, seed=3, qpos=q)
    boxes = table.world_boxes(poses)[pc.primitive]
    tol = 1e-9
    assert ((pc.points >= boxes[:, 0] - tol) & (pc.points <= boxes[:, 1] + tol)).all()
    lo, hi = table.bounds(poses)
    assert (pc.points >= lo - tol).all() and (pc.points <= hi + tol).all()


def test_family_instances_are_one_per_shape_key_and_survive_pickling():
    import pickle

    from artipg.geometry import GEOMETRY_FAMILIES, Extrusion, Lathe, Sweep

    assert Lathe(4) is Lathe(4) and Lathe(4) is not Lathe(2)
    assert Extrusion((4, 4)) is Extrusion([4, 4]) and Sweep("LA").name == "sweepLA"
    for fam in (Lathe(4), Extrusion((3,)), GEOMETRY_FAMILIES["rounded_box"](()), Sweep("L")):
        assert pickle.loads(pickle.dumps(fam)) is fam


def test_faces_sampled_by_rejection_get_their_share_of_points():
    """An extruded outline with arcs has flat caps that the families sample by rejection:
    labelled clouds cover them in proportion to their area."""
    from artipg.geometry.extrusion import extrusion
    from artipg.geometry.outlines import ruler
    from artipg.model.builder import ObjectBuilder
    from artipg.model.part import Part

    b = ObjectBuilder()
    root = b.create_link("base")
    length, width, height = 0.3, 0.03, 0.004
    prim = extrusion(ruler(length, width, corner=0.008, hole=0.004), height)
    root.add(Part("body", "rounded_ruler", [prim]))
    obj = b.build("test", "test", 0)
    table = obj.primitive_table
    assert table.regions, "the rounded outline's caps are sampled by rejection"
    pc = obj.sample_points(20000, seed=3)
    z = pc.points[:, 2] - pc.points[:, 2].min()
    on_caps = (np.abs(z) < 1e-9) | (np.abs(z - height) < 1e-9)
    cap_area = sum(r[3] for r in table.regions)
    share = cap_area / table.cell_areas.sum()
    assert abs(on_caps.mean() - share) < 4 * np.sqrt(share * (1 - share) / len(z))
    np.testing.assert_allclose(np.abs(pc.normals[on_caps, 2]), 1.0, atol=1e-9)
