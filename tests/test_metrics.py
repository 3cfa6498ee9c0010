"""Evaluation toolkit: distances, set metrics, FID, structure statistics, readers, CLI."""

from __future__ import annotations

import itertools
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import cKDTree
from scipy.spatial.distance import cdist

import artipg
from artipg.export.folder import export_object
from artipg.io import find_object_folders, load_set, read_object, sample_surface
from artipg.metrics import (PointNetEncoder, chamfer_distance, chamfer_matrix, compare_sets, coverage,
                            earth_movers_distance, fid, frechet_distance, joint_histogram, load_default_encoder,
                            minimum_matching_distance, nearest_neighbor_distance, normalize_bbox, one_nn_accuracy,
                            set_metrics, summarize_structure)

CATEGORIES = artipg.categories()
RNG_SEED = 1234
N_EXPORTED = 3  # exported objects per category for the reader / CLI tests


def clouds_of(category: str, seeds, n: int = 512) -> np.ndarray:
    """(len(seeds), n, 3) rest-pose point clouds of generated objects."""
    return np.stack([artipg.generate(category, s).sample_points(n, seed=0).points for s in seeds])


def brute_chamfer(a, b, kind="l1"):
    d = cdist(a, b)
    p = 1 if kind == "l1" else 2
    return 0.5 * (np.mean(d.min(axis=1) ** p) + np.mean(d.min(axis=0) ** p))


# ---------------------------------------------------------------- Chamfer, EMD
@pytest.mark.parametrize("kind", ["l1", "l2"])
def test_chamfer_identical_clouds_is_zero(kind):
    a = np.random.default_rng(RNG_SEED).random((300, 3))
    assert chamfer_distance(a, a, kind) == 0.0
    assert chamfer_distance(a, a[::-1].copy(), kind) == 0.0  # order does not matter


def test_chamfer_of_two_single_points_is_their_distance():
    p, q = np.array([[0.1, -0.2, 0.3]]), np.array([[1.1, 0.8, -0.7]])
    d = np.linalg.norm(p - q)
    assert chamfer_distance(p, q, "l1") == pytest.approx(d, rel=1e-12)
    assert chamfer_distance(p, q, "l2") == pytest.approx(d ** 2, rel=1e-12)


@pytest.mark.parametrize("kind", ["l1", "l2"])
def test_chamfer_matches_brute_force_and_is_symmetric(kind):
    rng = np.random.default_rng(RNG_SEED)
    for n, m in ((1, 7), (50, 80), (200, 33)):
        a, b = rng.normal(size=(n, 3)), rng.normal(size=(m, 3)) + 0.3
        assert chamfer_distance(a, b, kind) == pytest.approx(brute_chamfer(a, b, kind), rel=1e-12)
        assert chamfer_distance(a, b, kind) == pytest.approx(chamfer_distance(b, a, kind), rel=1e-12)


@pytest.mark.parametrize("kind", ["l1", "l2"])
def test_chamfer_matrix_equals_pairwise_distances(kind):
    rng = np.random.default_rng(RNG_SEED)
    A = [rng.normal(size=(n, 3)) * rng.uniform(0.5, 2) for n in (40, 64, 17, 64)]
    B = [rng.normal(size=(n, 3)) + 1 for n in (30, 64, 5)]
    D = chamfer_matrix(A, B, kind=kind, workers=2)
    expect = np.array([[brute_chamfer(a, b, kind) for b in B] for a in A])
    np.testing.assert_allclose(D, expect, rtol=1e-10)
    S = chamfer_matrix(A, kind=kind, workers=1)
    np.testing.assert_allclose(S, [[brute_chamfer(a, b, kind) for b in A] for a in A], rtol=1e-10, atol=1e-15)
    assert np.all(np.diag(S) == 0) and np.array_equal(S, S.T)
    calls = []
    chamfer_matrix(A, B, kind=kind, progress=calls.append)
    assert sum(calls) == len(A) + len(B)


@pytest.mark.parametrize("kind", ["l1", "l2"])
def test_chamfer_matrix_matches_per_pair_distance_on_generated_clouds(kind):
    """The pykdtree matrices equal per-pair cKDTree ``chamfer_distance`` on real clouds of every category."""
    A = [clouds_of(c, [0], 256)[0] for c in CATEGORIES]
    B = [clouds_of(c, [7], 256)[0] for c in CATEGORIES[::-1]]
    D = chamfer_matrix(A, B, kind=kind, workers=2)
    np.testing.assert_allclose(D, [[chamfer_distance(a, b, kind) for b in B] for a in A], rtol=1e-12, atol=0)
    S = chamfer_matrix(A, kind=kind, workers=2)
    np.testing.assert_allclose(S, [[chamfer_distance(a, b, kind) for b in A] for a in A], rtol=1e-12, atol=0)
    assert np.all(np.diag(S) == 0) and np.array_equal(S, S.T) and np.all(S + np.eye(len(A)) > 0)
    # every entry is computed by one thread: the thread count does not change a single bit
    assert np.array_equal(chamfer_matrix(A, kind=kind, workers=1), S)


_THREAD_PROBE = """
import ctypes, json, os, sys
from pykdtree import kdtree
import artipg
from artipg.metrics import chamfer_matrix
clouds = [artipg.generate(c, 0).sample_points(512, seed=0).points for c in artipg.categories()]
tasks = lambda: len(os.listdir("/proc/self/task"))
base, seen = tasks(), []
chamfer_matrix(clouds, workers=int(sys.argv[1]), progress=lambda k: seen.append(tasks()))
print(json.dumps({"extra_threads": max(seen) - base,
                  "caller_omp_threads": ctypes.CDLL(kdtree.__file__).omp_get_max_threads()}))
"""


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="counts threads in /proc/self/task (Linux)")
@pytest.mark.parametrize("workers", [1, 2])
def test_chamfer_matrix_runs_exactly_workers_threads(workers):
    """``workers`` threads in all, even where OpenMP would start 4 per query (OMP_NUM_THREADS=4).

    OpenMP keeps the threads of a team alive after a parallel region, so any extra
    OpenMP thread started by a query would still be counted at the next progress call
    (without the per-thread limit this counts 4 threads per worker). One fresh process
    per run: a joined thread can linger in /proc for a moment.
    """
    env = dict(os.environ, OMP_NUM_THREADS="4")
    run = subprocess.run([sys.executable, "-c", _THREAD_PROBE, str(workers)], env=env, capture_output=True,
                         text=True, check=True)
    out = json.loads(run.stdout.strip().splitlines()[-1])
    assert out["extra_threads"] == workers
    assert out["caller_omp_threads"] == 4  # the caller's own OpenMP setting is left alone


def test_emd_exact_cases():
    rng = np.random.default_rng(RNG_SEED)
    a = rng.random((64, 3))
    assert earth_movers_distance(a, a) == 0.0
    assert earth_movers_distance(a, rng.permutation(a)) == 0.0
    t = np.array([0.3, -0.4, 1.2])
    # a pure translation: the identity matching is optimal (triangle inequality), EMD = |t|
    assert earth_movers_distance(a, a + t) == pytest.approx(np.linalg.norm(t), rel=1e-9)
    # small clouds: equal to the best of all permutations
    x, y = rng.random((6, 3)), rng.random((6, 3))
    best = min(np.linalg.norm(x - y[list(p)], axis=1).mean() for p in itertools.permutations(range(6)))
    assert earth_movers_distance(x, y) == pytest.approx(best, rel=1e-12)
    # large / unequal clouds: subsampled (documented approximation), deterministic
    big, other = rng.random((3000, 3)), rng.random((2500, 3))
    e1 = earth_movers_distance(big, other, max_points=256)
    assert e1 == earth_movers_distance(big, other, max_points=256) and 0 < e1 < 1
    assert earth_movers_distance(big, other, max_points=256) >= chamfer_distance(big, other) - 1e-12


# ---------------------------------------------------------------- set metrics
def _random_set(rng, n_objects, n=128, spread=1.0):
    return [rng.normal(size=(n, 3)) * rng.uniform(0.2, 1.0, size=3) * spread for _ in range(n_objects)]


def test_copy_of_reference_gives_full_coverage_and_zero_1nna():
    R = _random_set(np.random.default_rng(RNG_SEED), 25)
    G = [r.copy() for r in R]
    D = chamfer_matrix(G + R)
    m = set_metrics(D[:25, :25], D[25:, 25:], D[:25, 25:])
    assert m["cov"] == 1.0
    assert m["one_nna"] == 0.0 and m["one_nna_generated"] == 0.0 and m["one_nna_reference"] == 0.0
    assert m["mmd"] == 0.0
    assert m["nnd_generated"] == pytest.approx(m["nnd_reference"]) and m["nnd_generated"] > 0


def test_far_apart_sets_give_100_percent_1nna():
    rng = np.random.default_rng(RNG_SEED)
    R = _random_set(rng, 20)
    G = [c + np.array([50.0, 0, 0]) for c in _random_set(rng, 15)]
    res = compare_sets(np.stack(G), np.stack(R), normalization="none")
    assert res["one_nna"] == 1.0
    assert res["mmd"] > 40


def test_set_metrics_hand_computed():
    # 2 generated, 3 reference, on a line: g = {0, 10}, r = {1, 2, 20}; D = |x - y|
    g, r = np.array([0.0, 10.0]), np.array([1.0, 2.0, 20.0])
    D_gr, D_gg, D_rr = np.abs(g[:, None] - r), np.abs(g[:, None] - g), np.abs(r[:, None] - r)
    assert minimum_matching_distance(D_gr) == pytest.approx((1 + 2 + 10) / 3)
    assert coverage(D_gr) == pytest.approx(2 / 3)  # g = 0 picks r = 1, g = 10 picks r = 2 (8 < 9 < 10)
    acc = one_nn_accuracy(D_gg, D_rr, D_gr)
    # g0: same 10 vs other 1 -> wrong; g10: same 10 vs other 8 -> wrong;
    # r1: same 1 vs other 1 -> tie -> wrong; r2: same 1 vs 2 -> right; r20: same 18 vs 10 -> wrong
    assert acc["accuracy"] == pytest.approx(1 / 5)
    assert acc["accuracy_generated"] == 0.0 and acc["accuracy_reference"] == pytest.approx(1 / 3)
    assert nearest_neighbor_distance(D_rr) == pytest.approx((1 + 1 + 18) / 3)


def test_1nna_near_half_for_independent_samples_of_one_category():
    # a statistical property of the metric, checked on one category (the first registered)
    category = CATEGORIES[0]
    G = clouds_of(category, range(0, 40))
    R = clouds_of(category, range(10_000, 10_040))
    res = compare_sets(G, R, normalization="bbox")
    assert 0.30 <= res["one_nna"] <= 0.70, res
    assert res["cov"] > 0.3
    # a copy of the reference set, through the same pipeline
    cp = compare_sets(R[:12].copy(), R[:12], normalization="bbox")
    assert cp["cov"] == 1.0 and cp["one_nna"] == 0.0


def test_nnd_matches_brute_force_loop():
    rng = np.random.default_rng(RNG_SEED)
    S = _random_set(rng, 12, n=60)
    S.append(S[3].copy())  # a duplicate counts with distance 0
    D = chamfer_matrix(S)
    brute = np.mean([min(chamfer_distance(x, y) for j, y in enumerate(S) if j != i) for i, x in enumerate(S)])
    assert nearest_neighbor_distance(D) == pytest.approx(brute, rel=1e-12)


def test_bbox_normalization_makes_scale_and_position_irrelevant():
    rng = np.random.default_rng(RNG_SEED)
    a = rng.random((500, 3)) * [0.4, 1.2, 2.0]
    n = normalize_bbox(a)
    lo, hi = n.min(axis=0), n.max(axis=0)
    np.testing.assert_allclose((lo + hi) / 2, 0, atol=1e-12)
    assert np.linalg.norm(hi - lo) == pytest.approx(1.0)
    # a metre-scale object and a unit-less copy (scaled, shifted) compare as identical
    b = a * 37.5 + np.array([3.0, -2.0, 10.0])
    assert chamfer_distance(normalize_bbox(a), normalize_bbox(b)) == pytest.approx(0.0, abs=1e-12)
    batch = normalize_bbox(np.stack([a, b]))
    np.testing.assert_allclose(batch[0], batch[1], atol=1e-12)


# ---------------------------------------------------------------- FID
def test_frechet_distance_matches_sqrtm_formula():
    from scipy.linalg import sqrtm

    rng = np.random.default_rng(RNG_SEED)
    X, Y = rng.normal(size=(200, 6)), rng.normal(size=(150, 6)) @ rng.normal(size=(6, 6)) + 0.5
    m1, m2 = X.mean(0), Y.mean(0)
    s1, s2 = np.cov(X, rowvar=False), np.cov(Y, rowvar=False)
    ref = np.sum((m1 - m2) ** 2) + np.trace(s1 + s2 - 2 * np.real(sqrtm(s1 @ s2)))
    assert frechet_distance(m1, s1, m2, s2) == pytest.approx(ref, rel=1e-8)
    assert fid(X, Y) == pytest.approx(ref, rel=1e-8)
    # rank-deficient covariances (fewer samples than features) stay real and ~0 on themselves
    Z = rng.normal(size=(10, 64))
    assert fid(Z, Z) == pytest.approx(0.0, abs=1e-8)
    # sets smaller than the feature dimension: the sample-space formula equals the covariance one
    P, Q = rng.normal(size=(12, 40)), rng.normal(size=(9, 40)) * 1.5 + 0.2
    expect = frechet_distance(P.mean(0), np.cov(P, rowvar=False), Q.mean(0), np.cov(Q, rowvar=False))
    assert fid(P, Q) == pytest.approx(expect, rel=1e-7)


def _random_torch_pointnet(n_classes=3):
    torch = pytest.importorskip("torch")
    from artipg.metrics.pointnet_torch import build_model

    torch.manual_seed(0)
    model = build_model(n_classes)
    # non-trivial batch-norm statistics and affine parameters
    with torch.no_grad():
        for bn in list(model.conv_bn) + list(model.fc_bn):
            bn.running_mean.uniform_(-0.5, 0.5)
            bn.running_var.uniform_(0.5, 2.0)
            bn.weight.uniform_(0.5, 1.5)
            bn.bias.uniform_(-0.2, 0.2)
    return torch, model.eval()


def test_numpy_encoder_matches_torch():
    torch, model = _random_torch_pointnet()
    from artipg.metrics.pointnet_torch import export_encoder

    enc = export_encoder(model, ["a", "b", "c"], {"note": "random"})
    enc = PointNetEncoder.from_arrays(enc.to_arrays())  # through the file format
    clouds = clouds_of(CATEGORIES[0], range(4), n=300)
    x = torch.from_numpy(normalize_bbox(clouds).astype(np.float32))
    with torch.no_grad():
        f_t, l_t = model.features(x).numpy(), model(x).numpy()
    np.testing.assert_allclose(enc.features(clouds), f_t, rtol=1e-4, atol=1e-4)
    np.testing.assert_allclose(enc.logits(clouds), l_t, rtol=1e-4, atol=1e-4)


@pytest.fixture(scope="module")
def encoder():
    enc = load_default_encoder()
    assert enc is not None, "the shipped FID encoder artipg/data/fid_pointnet.npz is missing"
    return enc


def test_shipped_encoder_fid_self_zero_and_grows_across_categories(encoder):
    cats = [c for c in encoder.classes if c in CATEGORIES]
    assert len(cats) >= 2
    feats = {c: encoder.features(clouds_of(c, range(0, 25))) for c in cats}
    again = {c: encoder.features(clouds_of(c, range(5000, 5025))) for c in cats}
    for c in cats:
        scale = np.trace(np.cov(feats[c], rowvar=False))
        assert fid(feats[c], feats[c]) < 1e-6 * scale
        same = fid(feats[c], again[c])  # two independent samples of one category
        cross = np.array([fid(feats[c], feats[d]) for d in cats if d != c])
        # every other category is farther than a second sample of this one, most of them far more
        assert cross.min() > 1.2 * same, (c, same, cross.min())
        assert np.median(cross) > 5 * same, (c, same, np.median(cross))


def test_shipped_encoder_classifies_its_categories(encoder):
    known = [c for c in encoder.classes if c in CATEGORIES]
    assert len(known) >= 2
    for c in known:
        # 40 objects: with 10, one category's accuracy swings by 20 points between seed blocks
        pred = encoder.predict(clouds_of(c, range(20_000, 20_040)))
        assert np.mean([p == c for p in pred]) >= 0.7, (c, pred)


# ---------------------------------------------------------------- structure
def test_joint_histogram_bins():
    h = joint_histogram([0, 1, 1, 9, 10, 25])
    assert h.shape == (11,) and h.sum() == pytest.approx(1)
    np.testing.assert_allclose(h * 6, [1, 2, 0, 0, 0, 0, 0, 0, 0, 1, 2])


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """A few exported objects of every category, in artipg's DIR/<category>/<seed> layout."""
    root = tmp_path_factory.mktemp("eval_set")
    for c in CATEGORIES:
        for s in range(N_EXPORTED):
            export_object(artipg.generate(c, s), root / c / str(s), n_points=1024)
    return root


def _own_link_distance(sample, dense_pc) -> np.ndarray:
    """Distance (N,) from each point of ``sample`` to the dense analytic points of its own link."""
    d = np.empty(len(sample.points))
    for i in np.unique(sample.link):
        own = dense_pc.points[dense_pc.link == dense_pc.link_names.index(sample.link_names[i])]
        d[sample.link == i] = cKDTree(own).query(sample.points[sample.link == i])[0]
    return d


@pytest.mark.parametrize("category", CATEGORIES)
def test_reader_on_artipg_folders(exported, category):
    for s in range(N_EXPORTED):
        folder = exported / category / str(s)
        obj = artipg.generate(category, s)
        mesh = read_object(folder, 1024, source="mesh")
        npz = read_object(folder, 1024, source="npz")
        assert mesh.source == "mesh" and npz.source == "npz"
        assert mesh.points.shape == npz.points.shape == (1024, 3)
        # the URDF's meshes through its kinematics are the analytic surfaces: mesh samples are as
        # close to a dense analytic sample as exact analytic samples are (plus tessellation error)
        dense = obj.sample_points(40_000, seed=7).points  # exact samples of the analytic surfaces
        diag = np.linalg.norm(mesh.structure.extents)
        d_mesh = np.median(cKDTree(dense).query(mesh.points)[0])
        d_npz = np.median(cKDTree(dense).query(npz.points)[0])
        assert d_mesh < 2 * d_npz + 1e-3 * diag, (d_mesh, d_npz)
        np.testing.assert_allclose(mesh.structure.extents, np.ptp(dense, axis=0), atol=1e-2 * diag)
        assert mesh.structure.n_joints == obj.dof
        assert mesh.structure.n_links == sum(1 for lk in obj.links if lk.parts)
        # per-point link labels: every point lies on the surface of the link it is labelled with,
        # as closely as the analytic npz points do (distance to a dense analytic sample of that link)
        dense_pc = obj.sample_points(40_000, seed=7)
        for sample in (mesh, npz):
            assert {sample.link_names[i] for i in np.unique(sample.link)} <= {lk.name for lk in obj.links if lk.parts}
        dm, dn = _own_link_distance(mesh, dense_pc), _own_link_distance(npz, dense_pc)
        assert np.median(dm) < 2 * np.median(dn) + 1e-3 * diag
        assert np.quantile(dm, 0.99) < 2 * np.quantile(dn, 0.99) + 1e-2 * diag


def test_reader_auto_prefers_npz_and_same_folder_same_cloud(exported):
    folder = exported / CATEGORIES[0] / "0"
    assert read_object(folder, 1024).source == "npz"
    assert read_object(folder, 2048).source == "mesh"  # points.npz has only 1024
    a, b = read_object(folder, 500, seed=3), read_object(folder, 500, seed=3)
    np.testing.assert_array_equal(a.points, b.points)
    with pytest.raises(FileNotFoundError):
        read_object(folder, 2048, source="npz")


# ------------------------------------------------ a PartNet-Mobility-style folder
_PM_URDF = """<?xml version="1.0"?>
<robot name="partnet_fixture">
  <link name="base"/>
  <link name="link_0">
    <visual name="body">
      <origin xyz="0 0 0.5" rpy="1.5707963267948966 0 0"/>
      <geometry><mesh filename="textured_objs/body.obj"/></geometry>
    </visual>
  </link>
  <link name="link_1">
    <visual name="door">
      <origin xyz="0 0.2 0" rpy="1.5707963267948966 0 0"/>
      <geometry><mesh filename="textured_objs/door.obj" scale="1 1 1"/></geometry>
    </visual>
  </link>
  <joint name="joint_0" type="revolute">
    <origin xyz="-0.3 -0.2 0.5" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <parent link="link_0"/>
    <child link="link_1"/>
    <limit lower="0" upper="1.57" effort="1" velocity="1"/>
  </joint>
  <joint name="joint_1" type="fixed">
    <origin xyz="0 0 0" rpy="0 0 0"/>
    <parent link="base"/>
    <child link="link_0"/>
  </joint>
</robot>
"""


def _write_box_obj(path: Path, size) -> None:
    import trimesh

    m = trimesh.creation.box(extents=size)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in m.vertices)
                    + "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in m.faces))


@pytest.fixture
def partnet_folder(tmp_path):
    """Meshes modelled Y-up (height along mesh +y); the URDF's visual origins rotate them +Z up."""
    d = tmp_path / "pm" / "101"
    _write_box_obj(d / "textured_objs" / "body.obj", (0.6, 1.0, 0.4))   # x 0.6, y (up) 1.0, z 0.4
    _write_box_obj(d / "textured_objs" / "door.obj", (0.02, 0.9, 0.4))  # thin along x
    (d / "mobility.urdf").write_text(_PM_URDF)
    (d / "meta.json").write_text(json.dumps({"model_cat": "StorageFurniture"}))
    return d


def test_reader_partnet_style_folder_is_z_up_with_link_labels(partnet_folder):
    o = read_object(partnet_folder, 4000, seed=1)
    assert o.source == "mesh" and o.category == "storage_furniture"
    lo, hi = o.points.min(axis=0), o.points.max(axis=0)
    # body: mesh y (1.0) became z, mesh z (0.4) became -y; door is 0.9 tall, 0.4 wide, at x = -0.3 +- 0.01
    np.testing.assert_allclose([lo[2], hi[2]], [0.0, 1.0], atol=1e-9)
    np.testing.assert_allclose([lo[1], hi[1]], [-0.2, 0.2], atol=1e-9)
    np.testing.assert_allclose([lo[0], hi[0]], [-0.31, 0.3], atol=1e-9)
    assert o.link_names == ("base", "link_0", "link_1")
    door = o.points[o.link == 2]
    np.testing.assert_allclose([door[:, 0].min(), door[:, 0].max()], [-0.31, -0.29], atol=1e-9)
    np.testing.assert_allclose([door[:, 2].min(), door[:, 2].max()], [0.05, 0.95], atol=5e-3)
    assert not np.any(o.link == 0)  # the empty base link has no points
    # area-uniform: each link gets points in proportion to its surface area
    a_body = 2 * (0.6 * 1.0 + 0.6 * 0.4 + 1.0 * 0.4)
    a_door = 2 * (0.02 * 0.9 + 0.02 * 0.4 + 0.9 * 0.4)
    frac = np.mean(o.link == 2)
    expect = a_door / (a_body + a_door)
    assert abs(frac - expect) < 4 * math.sqrt(expect * (1 - expect) / 4000)
    s = o.structure
    assert s.n_joints == 1 and s.n_links == 2 and s.joint_types == ("revolute", "fixed")
    np.testing.assert_allclose(s.extents, [0.61, 0.4, 1.0], atol=1e-9)


def test_sample_surface_is_area_uniform():
    # two unit squares, one 3x larger in area: points split 1:3, uniform inside
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                  [0, 0, 1], [3, 0, 1], [3, 1, 1], [0, 1, 1]], dtype=float)
    f = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]])
    pts, lab = sample_surface(v, f, 40_000, np.random.default_rng(0), face_labels=[0, 0, 1, 1])
    assert abs(np.mean(lab == 1) - 0.75) < 0.01
    top = pts[lab == 1]
    np.testing.assert_allclose(top[:, 2], 1.0)
    # uniform in x over [0, 3]: each third holds a third of the points
    np.testing.assert_allclose(np.histogram(top[:, 0], bins=3, range=(0, 3))[0] / len(top), 1 / 3, atol=0.015)


def test_find_object_folders_layouts(exported, partnet_folder, tmp_path):
    nested = find_object_folders(exported)
    assert sorted(nested) == sorted(CATEGORIES)
    assert [p.name for p in nested[CATEGORIES[0]]] == [str(s) for s in range(N_EXPORTED)]
    (exported / CATEGORIES[0] / ".tmp-9-x").mkdir()
    assert len(find_object_folders(exported)[CATEGORIES[0]]) == N_EXPORTED
    flat = find_object_folders(exported / CATEGORIES[0])  # a flat folder of artipg objects
    assert list(flat) == [CATEGORIES[0]] and len(flat[CATEGORIES[0]]) == N_EXPORTED
    assert find_object_folders(partnet_folder.parent) == {"storage_furniture": [partnet_folder]}
    with pytest.raises(FileNotFoundError):
        find_object_folders(tmp_path / "missing")


def test_load_set_parallel_equals_serial_and_reports_errors(exported, tmp_path):
    folders = [exported / c / str(s) for c in CATEGORIES for s in range(N_EXPORTED)]
    bad = tmp_path / "broken"
    bad.mkdir()
    (bad / "mobility.urdf").write_text("<robot name='x'><link name='a'><visual><geometry><mesh filename='no.obj'/>"
                                       "</geometry></visual></link></robot>")
    a = load_set(folders + [bad], 256, workers=1)
    b = load_set(folders + [bad], 256, workers=2)
    np.testing.assert_array_equal(a.points, b.points)
    assert len(a) == len(folders) and [e[0] for e in a.errors] == [bad]
    st = summarize_structure(a.structures)
    assert st["n_objects"] == len(folders)
    assert st["joints"]["mean"] == pytest.approx(np.mean([artipg.generate(c, s).dof for c in CATEGORIES
                                                          for s in range(N_EXPORTED)]))


# ---------------------------------------------------------------- CLI
def _cli(*args):
    from typer.testing import CliRunner

    from artipg.cli import app

    return CliRunner().invoke(app, list(args), catch_exceptions=False)


def test_cli_eval_copy_and_stats(exported, tmp_path):
    out = tmp_path / "r.json"
    r = _cli("eval", "--generated", str(exported), "--reference", str(exported), "--points", "256",
             "--json", str(out), "-q", "-j", "2")
    assert r.exit_code == 0, r.output
    data = json.loads(out.read_text())
    assert sorted(data["categories"]) == sorted(CATEGORIES)
    for c, m in data["categories"].items():
        assert m["cov"] == 1.0 and m["one_nna"] == 0.0 and m["mmd"] == 0.0
        assert m["fid"] == pytest.approx(0.0, abs=1e-6)
        assert m["structure"]["generated"] == m["structure"]["reference"]
        assert c in r.output
    assert "COV" in r.output and "1-NNA" in r.output and "NND" in r.output and "FID" in r.output
    # plots (one category keeps the test fast)
    c = CATEGORIES[-1]
    r = _cli("eval", "-g", str(exported), "-r", str(exported), "-c", c, "--points", "128", "--no-fid", "-q",
             "--plots", str(tmp_path / "plots"))
    assert r.exit_code == 0, r.output
    assert (tmp_path / "plots" / f"{c}_joints.png").stat().st_size > 1000
    assert (tmp_path / "plots" / f"{c}_sizes.png").stat().st_size > 1000

    r = _cli("stats", str(exported), "--points", "256", "--json", str(out), "-q")
    assert r.exit_code == 0, r.output
    data = json.loads(out.read_text())
    for c in CATEGORIES:
        m = data["categories"][c]
        assert m["n_objects"] == N_EXPORTED and m["nnd"] > 0
        assert m["structure"]["joints"]["mean"] == pytest.approx(np.mean([artipg.generate(c, s).dof
                                                                          for s in range(N_EXPORTED)]))


def test_cli_eval_partnet_reference_and_bad_input(exported, partnet_folder, tmp_path):
    out = tmp_path / "r.json"
    r = _cli("eval", "-g", str(exported / CATEGORIES[0]), "-r", str(partnet_folder.parent), "--points", "128",
             "--json", str(out), "-q", "--no-fid", "--normalize", "none")
    assert r.exit_code == 0, r.output
    (label, m), = json.loads(out.read_text())["categories"].items()
    assert m["n_reference"] == 1 and m["n_generated"] == N_EXPORTED and m["fid"] is None
    assert m["nnd_reference"] is None  # one object: no nearest other object
    r = _cli("eval", "-g", str(tmp_path / "nope"), "-r", str(exported))
    assert r.exit_code == 2 and "not a directory" in r.output
    r = _cli("eval", "-g", str(exported), "-r", str(exported), "--normalize", "unit")
    assert r.exit_code == 2 and "--normalize" in r.output
