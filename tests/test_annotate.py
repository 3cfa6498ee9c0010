"""Annotations of every registered category at several seeds and joint states: NPCS,
part poses, affordance regions, grasp poses, rendered views and label alignment."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

import artipg
from artipg.annotate.align import align_labels
from artipg.annotate.grasps import DEFAULT_GRIPPER, collision_margin, gripper_clearance, world_grasps
from artipg.annotate.labels import REQUIRED_AFFORDANCES, part_frames, point_labels
from artipg.annotate.points import sample_points
from artipg.annotate.sdf import object_sdf
from artipg.annotate.views import ELEVATION_RANGE, partial_views, render_view
from artipg.vocabulary import ACTIONABLE_CLASSES, AFFORDANCES
from conftest import CATEGORIES, open_qpos

SEEDS = (0, 1, 2)


def _states(obj, seed):
    """Rest, a random state inside the limits and fully open."""
    rng = np.random.default_rng(1000 + seed)
    lim = obj.limits()
    return [None, lim[:, 0] + rng.random(len(lim)) * (lim[:, 1] - lim[:, 0]), open_qpos(obj, 1.0)]


@pytest.mark.parametrize("category", CATEGORIES)
def test_npcs_in_unit_cube_and_maps_back(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        rest = None
        for q in _states(obj, seed):
            pc = obj.sample_points(2048, seed=7, qpos=q)
            lab = point_labels(obj, pc.points, pc.primitive, q)
            assert np.all(np.abs(lab.npcs) <= 0.5 + 1e-9)
            assert np.all(np.abs(lab.object_npcs) <= 0.5 + 1e-9)
            F = part_frames(obj, q)
            i = pc.instance
            back = np.einsum("nij,nj->ni", F.pose[i, :3, :3], lab.npcs * F.scale[i, None]) + F.pose[i, :3, 3]
            np.testing.assert_allclose(back, pc.points, atol=1e-9)
            # rotations are proper and the box is tight: each part's points span
            # its box (within sampling) and the size matches the part's extents
            assert np.allclose(np.linalg.det(F.pose[:, :3, :3]), 1.0)
            # object NPCS is articulation-aware: the same surface samples map to the
            # same rest-state coordinates whatever the joint state
            if rest is None:
                rest = lab.object_npcs
            else:
                np.testing.assert_allclose(lab.object_npcs, rest, atol=1e-9)
        # the actionable class per point is its part's class
        assert set(np.unique(lab.actionable)) <= set(range(len(ACTIONABLE_CLASSES)))
        acts = np.array([ACTIONABLE_CLASSES.index(p.actionable) for p in obj.parts])
        np.testing.assert_array_equal(lab.actionable, acts[pc.instance])


@pytest.mark.parametrize("category", CATEGORIES)
def test_part_pose_size_match_geometry(category):
    obj = artipg.generate(category, 0)
    q = open_qpos(obj, 0.5)
    F = part_frames(obj, q)
    for i, part in enumerate(obj.parts):
        pc = sample_points(obj, 400, seed=i, qpos=q, parts=[i])
        local = (pc.points - F.pose[i, :3, 3]) @ F.pose[i, :3, :3]
        # every point inside the (conservative) canonical box, and the box not loose
        # along any axis by more than the curvature of round primitives allows
        assert np.all(np.abs(local) <= F.size[i] / 2 + 1e-9)
        span = local.max(axis=0) - local.min(axis=0)
        # (a partial ring or torus turned off its axes has a box loose beyond that: its
        # arc's box, itself turned, is the bound)
        partial = any(pr.geom.name in ("ring", "torus") and pr.params[2 + (pr.geom.name == "ring")] < 2 * np.pi - 1e-9
                      for pr in part.primitives)
        if not partial:
            assert np.all(span >= 0.5 * F.size[i] - 1e-6), (part.name, span, F.size[i])
        np.testing.assert_allclose(F.size[i], part.canonical_size(), rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("category", CATEGORIES)
def test_affordance_regions_exactly_on_their_parts(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        q = _states(obj, seed)[1]
        for i, part in enumerate(obj.parts):
            for anyof in REQUIRED_AFFORDANCES[part.actionable]:
                assert set(anyof) & set(part.regions), f"{part.template} ({part.actionable}) lacks a {anyof} region"
            pc = sample_points(obj, 3000, seed=seed, qpos=q, parts=[i])
            aff = point_labels(obj, pc.points, pc.primitive, q, npcs=False).affordance
            for k, a in enumerate(AFFORDANCES):
                if a in part.regions:
                    assert aff[:, k].any(), f"{category} {seed}: empty {a!r} region on {part.name} ({part.template})"
                else:
                    assert not aff[:, k].any(), f"{a!r} points on {part.name}, which has no such region"
        # on a whole-object cloud, affordance points only occur on parts with that region
        pc = obj.sample_points(4096, seed=3, qpos=q)
        aff = point_labels(obj, pc.points, pc.primitive, q, npcs=False).affordance
        has = np.array([[a in p.regions for a in AFFORDANCES] for p in obj.parts])
        assert not np.any(aff & ~has[pc.instance])


def _far_state(obj, only=None) -> dict:
    """Movable joints (or just ``only``) at the limit farther from 0; continuous at 0."""
    q = {}
    for j in obj.movable_joints:
        lo, hi = j.limits
        if (only is None or j.name == only) and np.isfinite(hi):
            q[j.name] = hi if hi >= -lo else lo
    return q


def _grasp_point_on_part(obj, q, g, k):
    """The grasped part fills some of the space between the open jaws of grasp k: a
    grid point inside the part, or (for plates and walls thinner than the grid
    spacing) a point of a dense surface sample."""
    lo, hi = DEFAULT_GRIPPER.closing_box(g.width[k])
    t = np.linspace(0.0, 1.0, 9)
    grid = lo + np.stack(np.meshgrid(t, t, t, indexing="ij"), axis=-1).reshape(-1, 3) * (hi - lo)
    T = g.pose[k]
    d, _ = object_sdf(obj, grid @ T[:3, :3].T + T[:3, 3], q, parts=[int(g.part[k])])
    if np.any(d <= 0.0):
        return True
    pc = obj.sample_points(20000, seed=k, qpos=q, parts=[int(g.part[k])])
    local = (pc.points - T[:3, 3]) @ T[:3, :3]
    return np.any(np.all((local >= lo) & (local <= hi), axis=1))


@pytest.mark.parametrize("category", CATEGORIES)
def test_grasps_sit_on_part_collision_free_and_open(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        for q in _states(obj, seed):
            g = world_grasps(obj, q)
            if not len(g):
                continue
            for k in range(len(g)):
                assert _grasp_point_on_part(obj, q, g, k), f"grasp {k} on {obj.parts[g.part[k]].name} misses it"
                R = g.pose[k, :3, :3]
                np.testing.assert_allclose(R.T @ R, np.eye(3), atol=1e-9)
                assert abs(np.linalg.det(R) - 1) < 1e-9
            # collision-free grasps: no dense object sample lies inside a gripper box
            pc = obj.sample_points(30000, seed=5, qpos=q)
            for k in np.flatnonzero(g.collision_free):
                local = (pc.points - g.pose[k, :3, 3]) @ g.pose[k, :3, :3]
                for lo, hi in DEFAULT_GRIPPER.boxes(g.width[k]):
                    assert not np.any(np.all((local > lo) & (local < hi), axis=1))
            # the checker sees a collision when the gripper is pushed into the part
            pushed = g.pose.copy()
            pushed[:, :3, 3] += 0.04 * g.approach
            assert np.all(gripper_clearance(obj, pushed, g.width, q) <= collision_margin(0.004))
            # moving the joint by a small step in the opening direction moves the grasp
            # point along open_dir (grasp order does not depend on the joint state)
            qd = obj.qpos_dict(q)
            for j in np.unique(g.joint[g.joint >= 0]):
                joint = obj.joints[j]
                lo, hi = joint.limits
                opening = 1.0 if not np.isfinite(hi) or hi >= -lo else -1.0
                v = qd.get(joint.name, 0.0)
                step = 1e-4 * opening
                if np.isfinite(hi) and not lo <= v + step <= hi:
                    step = -step
                g2 = world_grasps(obj, {**qd, joint.name: v + step}, check=False)
                for k in np.flatnonzero((g.joint == j) & np.any(g.open_dir != 0, axis=1)):
                    d = g2.pose[k, :3, 3] - g.pose[k, :3, 3]
                    if np.linalg.norm(d) < 1e-9:  # on the axis (a knob's centre)
                        continue
                    motion = d / np.linalg.norm(d) * np.sign(step) * opening
                    assert motion @ g.open_dir[k] > 0.99, (obj.parts[g.part[k]].name, motion, g.open_dir[k])
        # every moving part with grasps can be grasped somewhere when it is opened alone
        # (as a robot would) or, for parts inside others (a microwave's turntable), when
        # everything is open (continuous joints stay at 0: they do not open anything)
        g0 = world_grasps(obj, None, check=False)
        g_all = world_grasps(obj, _far_state(obj))
        for j in sorted(set(g0.joint[g0.joint >= 0].tolist()))[:4]:
            g = world_grasps(obj, _far_state(obj, only=obj.joints[j].name))
            ok = g.collision_free[g.joint == j].any() or g_all.collision_free[g_all.joint == j].any()
            assert ok, f"{category} {seed}: no free grasp on {obj.joints[j].child}, opened alone or with all others"


@pytest.mark.parametrize("category", CATEGORIES)
def test_view_labels_agree_with_complete_cloud(category):
    for seed in SEEDS[:2]:
        obj = artipg.generate(category, seed)
        for q in _states(obj, seed)[1 + seed:2 + seed]:  # seed 0: a random state, seed 1: open
            views = partial_views(obj, 2, 2048, q, seed=seed, width=200, height=150)
            pts = np.concatenate([v.points for v in views])
            lab = {k: np.concatenate([getattr(v, k) for v in views]) for k in ("semantic", "instance", "link")}
            for v in views:
                assert ELEVATION_RANGE[0] <= v.camera.elevation <= ELEVATION_RANGE[1]
                # the camera looks at the object's centre from above
                assert v.camera.pose[2, 2] < 0
            # exact: every view point lies on the part it is labelled with (up to the
            # tessellation of curved primitives in the ray-cast mesh)
            for i in np.unique(lab["instance"]):
                m = lab["instance"] == i
                d, _ = object_sdf(obj, pts[m], q, parts=[i], unsigned=True, max_dist=0.01)
                assert np.all(d < 2e-3), (obj.parts[i].name, d.max())
            # and the nearest point of a dense complete cloud mostly agrees; the cloud is
            # dense enough (>= 2.5 points per cm^2, 131k to 300k points) that the neighbour is
            # rarely on another part just because samples are sparse (with 16384 points
            # a large wardrobe has ~4 cm between samples)
            area = obj.primitive_table.cell_areas.sum()
            n = int(min(300_000, max(131_072, area / 4e-5)))
            pc = obj.sample_points(n, seed=1, qpos=q)
            _, nn = cKDTree(pc.points).query(pts)
            for key in ("semantic", "instance", "link"):
                agree = np.mean(getattr(pc, key)[nn] == lab[key])
                assert agree >= 0.99, (category, seed, key, agree)


@pytest.mark.parametrize("category", CATEGORIES)
def test_depth_backprojects_to_hit_points(category):
    obj = artipg.generate(category, 0)
    q = open_qpos(obj, 0.3)
    v = partial_views(obj, 1, 500, q, seed=0, width=160, height=120)[0]
    view = render_view(obj, v.camera, q)
    m = view.mask
    assert m.any() and not m.all()
    cam = v.camera
    Ti = np.linalg.inv(cam.pose)
    p = view.points[m].astype(float)
    pc = p @ Ti[:3, :3].T + Ti[:3, 3]
    np.testing.assert_allclose(pc[:, 2], view.depth[m], rtol=1e-4, atol=1e-5)
    uv = pc[:, :2] / pc[:, 2:] * np.diag(cam.K)[:2] + cam.K[:2, 2]
    rows, cols = np.nonzero(m)
    np.testing.assert_allclose(uv, np.stack([cols + 0.5, rows + 0.5], axis=1), atol=1e-2)


@pytest.mark.parametrize("category", CATEGORIES)
def test_label_alignment_within_drift(category):
    obj = artipg.generate(category, 1)
    q = open_qpos(obj, 0.5)
    pc = obj.sample_points(4000, seed=2, qpos=q)
    rng = np.random.default_rng(0)
    # outward along the normal by less than the threshold: every point is labelled and
    # its distance never exceeds the displacement
    delta = rng.uniform(0.0, 0.0045, len(pc.points))
    a = align_labels(obj, pc.points + pc.normals * delta[:, None], q)
    assert a.unlabelled_share == 0.0
    assert np.all(a.distance <= delta + 1e-9)
    # distances agree with an exhaustive (unculled) evaluation of all primitives
    d_all, _ = object_sdf(obj, pc.points + pc.normals * delta[:, None], q, unsigned=True)
    np.testing.assert_allclose(a.distance, d_all, atol=1e-12)
    # far away: nothing is labelled
    far = obj.bounds(q)[1] + 0.05 + rng.random((100, 3))
    b = align_labels(obj, far, q)
    assert b.unlabelled_share == 1.0 and np.all(b.instance == -1)
    # exactly on the surface, the label is the sampled one except where parts touch
    c = align_labels(obj, pc.points, q)
    assert np.mean(c.instance == pc.instance) > 0.9


def test_cli_views_and_render_and_documented_arrays(tmp_path):
    from pathlib import Path

    from typer.testing import CliRunner

    from artipg.cli import app

    cat = CATEGORIES[0]
    runner = CliRunner()
    r = runner.invoke(app, ["generate", cat, "-n", "1", "--views", "2", "--points", "512", "-o", str(tmp_path), "-q"])
    assert r.exit_code == 0, r.output
    folder = tmp_path / cat / "0"
    pts = np.load(folder / "points.npz")
    views = np.load(folder / "views.npz")
    assert pts["points"].shape == (512, 3) and pts["affordance"].shape == (512, len(AFFORDANCES))
    assert views["partial_points"].shape == (2, 2048, 3) and views["depth"].shape == (2, 240, 320)
    # partial points are labelled like the instance image they come from
    v, (rows, cols) = 0, views["partial_pixels"][0].T
    np.testing.assert_array_equal(views["instance_image"][v][rows, cols], views["partial_instance"][v])
    # every stored array is documented
    doc = (Path(__file__).resolve().parents[1] / "docs" / "annotations.md").read_text()
    for key in list(pts.files) + list(views.files):
        assert f"`{key}`" in doc, f"{key} is not documented in docs/annotations.md"
    out = tmp_path / "pic.png"
    r = runner.invoke(app, ["render", cat, "--width", "160", "--height", "120", "-o", str(out)])
    assert r.exit_code == 0, r.output
    from PIL import Image

    img = np.asarray(Image.open(out))
    assert img.shape == (240, 320, 3) and (img < 250).any()
    r = runner.invoke(app, ["render", cat, "--open", "3"])
    assert r.exit_code == 2
