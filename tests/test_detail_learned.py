"""The learned detail bridge (needs torch): pairs, a tiny training run, application with
labels and the drift bound, and the CLI (bad model path, generate --detail learned).

Pairs are made here from artipg objects: the structure is the object, the "detailed"
object the same surface under a fixed smooth perturbation (no real data)."""

import subprocess
import sys

import numpy as np
import pytest

torch = pytest.importorskip("torch")

import artipg  # noqa: E402
from artipg.detail.application import DetailModel, detail_arrays, detail_points, load_detail_model  # noqa: E402
from artipg.detail.model import DetailNet, ModelConfig, save_model  # noqa: E402
from artipg.detail.pairs import Pair, build_pair, load_pairs, twin_clouds  # noqa: E402
from artipg.detail.training import TrainConfig, train  # noqa: E402

TINY = dict(k=8, local=16, width=32, t_dim=8)


def perturb(p: np.ndarray) -> np.ndarray:
    """A fixed smooth perturbation (diagonal units): shrink by 4 % and a ripple of 1 %."""
    return 0.96 * p + 0.01 * np.sin(10.0 * p[..., [1, 2, 0]])


def make_pair(category: str, seed: int, n: int = 256) -> dict:
    obj = artipg.generate(category, seed, validate=False)
    s, sem, diag = twin_clouds(obj, n, seed=0)
    return build_pair(s, sem, perturb(s[:, ::-1]), diag, category, f"{category}_{seed}", dense=perturb(s))


@pytest.fixture(scope="module")
def pairs(tmp_path_factory):
    d = tmp_path_factory.mktemp("pairs")
    for c, s in (("laptop", 0), ("box", 1), ("bucket", 2)):
        np.savez_compressed(d / f"{c}_{s}.npz", **make_pair(c, s))
    return d


@pytest.fixture(scope="module")
def trained(pairs):
    torch.set_num_threads(1)
    net, hist = train(load_pairs(pairs), ModelConfig(**TINY), TrainConfig(steps=120, batch=4, points=128, lr=1e-2))
    return net, hist


def test_pairs_are_matched_and_projected(pairs):
    ps = load_pairs(pairs)
    assert len(ps) == 3 and all(isinstance(p, Pair) for p in ps)
    for p in ps:
        assert p.structure.shape == p.detailed.shape == p.projected.shape == (3, 256, 3)
        assert p.semantic.shape == (256,) and p.diagonal > 0
        # the matching is a permutation of the perturbed cloud: the same points, reordered
        raw = make_pair(p.category, int(p.name.rsplit("_", 1)[1]))
        assert np.allclose(np.sort(p.detailed[0], axis=0), np.sort(raw["detailed"][0], axis=0))
        # projections land on the perturbed surface, near their structure point
        assert np.percentile(np.linalg.norm(p.offsets("projected"), axis=-1), 95) < 0.05
        # the matching beats the identity order of the reversed cloud it was given
        assert np.linalg.norm(p.offsets("matched"), axis=-1).mean() < 0.05


def test_load_pairs_bad_folder(tmp_path):
    with pytest.raises(FileNotFoundError):
        load_pairs(tmp_path / "missing")
    with pytest.raises(FileNotFoundError):
        load_pairs(tmp_path)
    np.savez(tmp_path / "x.npz", a=np.zeros(3))
    with pytest.raises(ValueError):
        load_pairs(tmp_path)


def test_tiny_training_loss_falls_and_is_deterministic(pairs, trained):
    net, hist = trained
    assert hist["final_loss"] < 0.8 * hist["initial_loss"]
    assert hist["losses"][-1] < hist["losses"][0]
    net2, hist2 = train(load_pairs(pairs), ModelConfig(**TINY), TrainConfig(steps=10, batch=4, points=128))
    net3, hist3 = train(load_pairs(pairs), ModelConfig(**TINY), TrainConfig(steps=10, batch=4, points=128))
    assert hist2["final_loss"] == hist3["final_loss"]
    for a, b in zip(net2.state_dict().values(), net3.state_dict().values()):
        assert torch.equal(a, b)


def _model(net, bound=None) -> DetailModel:
    if bound is not None:
        net.config.bound = bound
    return DetailModel(net, {}, "memory")


def test_labels_survive_and_drift_is_bounded(trained):
    net, _ = trained
    model = _model(net)
    obj = artipg.generate("microwave", 3, validate=False)
    from artipg.export.folder import point_arrays

    arr = point_arrays(obj, 512)
    out, summary = detail_arrays(model, arr, seed=5)
    pts, src = arr["points"].astype(np.float64), out["points"].astype(np.float64)
    from scipy.spatial import cKDTree

    near = cKDTree(pts).query(src)[1]
    for k in ("semantic", "instance", "link", "actionable", "npcs"):
        assert np.array_equal(out[k], arr[k][near]), k
    assert set(np.unique(out["semantic"])) <= set(np.unique(arr["semantic"]))
    # most points keep their own label: the bound is below the point spacing
    assert np.mean(out["semantic"] == arr["semantic"]) > 0.9
    diag = float(np.linalg.norm(np.ptp(pts, axis=0)))
    assert summary["bound"] == pytest.approx(net.config.bound * diag)
    assert out["detail_drift"].max() <= summary["bound"] * (1 + 1e-5)
    assert np.allclose(out["structure_points"], arr["points"])
    assert not np.allclose(out["points"], arr["points"])  # it did move points
    # the same seed gives the same cloud, another seed another one
    again, _ = detail_arrays(model, arr, seed=5)
    other, _ = detail_arrays(model, arr, seed=6)
    assert np.array_equal(again["points"], out["points"]) and not np.array_equal(other["points"], out["points"])


def test_pull_back_catches_planted_long_offsets():
    torch.manual_seed(0)
    net = DetailNet(ModelConfig(**TINY, points=128, offset_scale=0.5, bound=0.004))  # untrained: offsets ~0.5
    pts = artipg.generate("box", 0, validate=False).sample_points(300).points
    d = detail_points(_model(net), pts, seed=0)
    s = d.summary()
    assert s["raw_max"] > 10 * s["bound"] and s["pulled_back"] > 0.9
    assert d.displacement.max() <= s["bound"] * (1 + 1e-9)
    assert d.drift.max() <= d.displacement.max() + 1e-12
    assert s["drift_max"] <= s["bound"] * (1 + 1e-9)
    # a looser bound lets the same offsets further
    assert detail_points(_model(net), pts, seed=0, bound=0.04).drift.max() > 2 * s["drift_max"]


def test_model_file_round_trip_and_bad_files(tmp_path, trained):
    net, hist = trained
    save_model(net, tmp_path / "m.pt", extra={"history": {"steps": hist["steps"]}})
    m = load_detail_model(tmp_path / "m.pt")
    pts = artipg.generate("laptop", 1, validate=False).sample_points(200).points
    assert np.array_equal(detail_points(m, pts, seed=1).points, detail_points(_model(net), pts, seed=1).points)
    from artipg.detail.application import DetailModelError

    (tmp_path / "junk.pt").write_bytes(b"not a model")
    for bad in (tmp_path / "missing.pt", tmp_path / "junk.pt"):
        with pytest.raises(DetailModelError):
            load_detail_model(bad)


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "artipg.cli", *map(str, args)], capture_output=True, text=True,
                          timeout=600, cwd=cwd)


def _one_line_error(r):
    assert r.returncode != 0 and "Traceback" not in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1, r.stderr


def test_cli_bad_model_path_and_bad_input(tmp_path, pairs):
    _one_line_error(cli("generate", "laptop", "-n", "1", "--out", tmp_path / "o", "--detail", "learned",
                        "--detail-model", tmp_path / "nope.pt"))
    (tmp_path / "junk.pt").write_bytes(b"junk")
    _one_line_error(cli("generate", "laptop", "-n", "1", "--out", tmp_path / "o", "--detail", "learned",
                        "--detail-model", tmp_path / "junk.pt"))
    _one_line_error(cli("generate", "laptop", "-n", "1", "--out", tmp_path / "o", "--detail", "learned"))
    _one_line_error(cli("generate", "laptop", "-n", "1", "--out", tmp_path / "o", "--detail", "fancy"))
    _one_line_error(cli("detail", "train", "--pairs", tmp_path / "none", "--out", tmp_path / "m.pt"))
    _one_line_error(cli("detail", "pairs", "--reference", tmp_path / "none", "--out", tmp_path / "p"))


def test_cli_train_then_generate_learned(tmp_path, pairs):
    r = cli("detail", "train", "--pairs", pairs, "--out", tmp_path / "m.pt", "--steps", "3", "--batch", "2",
            "--points", "128", "--threads", "1")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "m.pt").is_file()
    out = tmp_path / "gen"
    r = cli("generate", "bucket", "-n", "1", "--seed", "4", "--out", out, "--no-validate", "--formats", "urdf",
            "--points", "300", "--detail", "learned", "--detail-model", tmp_path / "m.pt", "-q")
    assert r.returncode == 0, r.stderr
    z = np.load(out / "bucket" / "4" / "points.npz")
    assert z["points"].shape == z["structure_points"].shape == (300, 3)
    diag = np.linalg.norm(np.ptp(z["structure_points"], axis=0))
    assert z["detail_drift"].max() <= 0.006 * diag * (1 + 1e-5)
    plain = artipg.generate("bucket", 4, validate=False, detail="off").sample_points(300)  # the sharp structure
    assert np.allclose(z["structure_points"], plain.points, atol=1e-6)
    # the folder stays complete: re-running keeps it
    r = cli("generate", "bucket", "-n", "1", "--seed", "4", "--out", out, "--no-validate", "--formats", "urdf",
            "--points", "300", "--detail", "learned", "--detail-model", tmp_path / "m.pt", "-q")
    assert r.returncode == 0 and "1 already present" in r.stdout, r.stdout


def test_cli_pairs_from_artipg_folders(tmp_path):
    from artipg.export import export_object

    export_object(artipg.generate("box", 2, validate=False), tmp_path / "ref" / "box" / "2", n_points=0)
    r = cli("detail", "pairs", "--reference", tmp_path / "ref", "--out", tmp_path / "p", "--restarts", "1",
            "--refine", "1", "--iterations", "0")
    assert r.returncode == 0, r.stderr
    (p,) = load_pairs(tmp_path / "p")
    assert p.category == "box" and p.structure.shape == (3, 1024, 3)
    # the twin of an artipg box is close to it: short projections
    assert np.median(np.linalg.norm(p.offsets(), axis=-1)) < 0.05
