"""A run that tells the truth: file lists, resume that rebuilds damaged folders, the
index of an output folder, Ctrl-C, and the validated Python API."""

from __future__ import annotations

import json
import re
import signal
import subprocess
import sys
import time

import pytest

import artipg
from artipg.data.index import INDEX_NAME, index_row, read_index
from artipg.export.folder import export_object
from artipg.io.manifest import check_folder

CAT = "storage_furniture"


def run(*args, timeout=300):
    return subprocess.run([sys.executable, "-m", "artipg.cli", *args], capture_output=True, text=True,
                          timeout=timeout)


def folder_bytes(folder):
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def objects_on_disk(out):
    return sorted(f"{c.name}/{o.name}" for c in out.iterdir() if c.is_dir() for o in c.iterdir())


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return export_object(artipg.generate(CAT, 2), tmp_path_factory.mktemp("one") / CAT / "2")


def test_annotation_lists_every_other_file(folder):
    listed = json.loads((folder / "annotation.json").read_text())["files"]
    on_disk = {k: len(v) for k, v in folder_bytes(folder).items() if k != "annotation.json"}
    assert {r["path"]: r["size"] for r in listed} == on_disk
    assert all(re.fullmatch(r"[0-9a-f]{64}", r["sha256"]) for r in listed)
    assert check_folder(folder).ok


@pytest.mark.parametrize("fault, status", [
    (lambda f: (f / "points.npz").unlink(), "damaged"),
    (lambda f: (f / "mobility.urdf").write_text("garbage"), "damaged"),
    (lambda f: (f / "extra.txt").write_text("x"), "damaged"),
    (lambda f: (f / "annotation.json").write_text("{"), "damaged"),
    (lambda f: (f / "annotation.json").unlink(), "incomplete"),
])
def test_check_folder_catches_planted_faults(folder, tmp_path, fault, status):
    import shutil

    copy = shutil.copytree(folder, tmp_path / "copy")
    fault(copy)
    assert check_folder(copy).status == status


def test_same_size_corruption_needs_hashes(folder, tmp_path):
    import shutil

    copy = shutil.copytree(folder, tmp_path / "copy")
    data = bytearray((copy / "mobility.urdf").read_bytes())
    data[100] ^= 1
    (copy / "mobility.urdf").write_bytes(bytes(data))
    assert check_folder(copy, hashes=False).ok
    assert check_folder(copy).status == "damaged"


def test_resume_rebuilds_damaged_and_incomplete_folders(tmp_path):
    out = tmp_path / "o"
    r = run("generate", CAT, "-n", "5", "--out", str(out), "-q")
    assert r.returncode == 0, r.stderr
    objs = out / CAT
    before = {s: folder_bytes(objs / s) for s in map(str, range(5))}
    kept_mtime = (objs / "0" / "mobility.urdf").stat().st_mtime_ns
    (objs / "1" / "mobility.urdf").write_text("<robot> garbage")
    (objs / "2" / "points.npz").unlink()
    (objs / "3" / "annotation.json").unlink()
    r = run("generate", CAT, "-n", "6", "--out", str(out), "-q")
    assert r.returncode == 0, r.stderr
    assert "4 written (1 new; 3 rebuilt: 2 damaged, 1 incomplete), 2 already present" in r.stdout
    for s, files in before.items():
        assert folder_bytes(objs / s) == files, s
    assert (objs / "0" / "mobility.urdf").stat().st_mtime_ns == kept_mtime
    assert [r["path"] for r in read_index(out)] == [f"{CAT}/{s}" for s in range(6)]


def test_index_lists_exactly_what_is_on_disk(tmp_path):
    out = tmp_path / "o"
    assert run("generate", CAT, "-n", "3", "--out", str(out), "-q", "--no-validate").returncode == 0
    assert run("generate", "bucket", "-n", "2", "--seed", "7", "--out", str(out), "-q").returncode == 0
    # a re-run of the first category keeps the second's rows, without duplicates
    assert run("generate", CAT, "-n", "3", "--out", str(out), "-q", "--no-validate").returncode == 0
    written = (out / INDEX_NAME).read_text()
    rows = read_index(out)
    assert [r["path"] for r in rows] == objects_on_disk(out)
    for row in rows:
        annotation = json.loads((out / row["path"] / "annotation.json").read_text())
        assert row == index_row(annotation, row["path"])
        assert row["valid"] is (None if row["category"] == CAT else True)
    # rebuilt from disk: the same file; a removed folder drops out
    r = run("index", str(out))
    assert r.returncode == 0 and "indexed 5 objects" in r.stdout, r.stderr
    assert (out / INDEX_NAME).read_text() == written
    import shutil

    shutil.rmtree(out / "bucket" / "8")
    (out / CAT / "1" / "points.npz").unlink()
    r = run("index", str(out))
    assert "indexed 3 objects" in r.stdout and "1 incomplete or damaged" in r.stderr
    assert [r["path"] for r in read_index(out)] == ["bucket/7", f"{CAT}/0", f"{CAT}/2"]


@pytest.mark.parametrize("workers", [1, 2])
def test_ctrl_c_stops_cleanly_with_its_line(tmp_path, workers):
    out = tmp_path / "o"
    proc = subprocess.Popen([sys.executable, "-m", "artipg.cli", "generate", CAT, "-n", "200", "--out", str(out),
                             "--workers", str(workers), "-q"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    objs = out / CAT
    deadline = time.time() + 120
    while time.time() < deadline:
        if objs.exists() and sum(1 for p in objs.iterdir() if not p.name.startswith(".")) >= 3:
            break
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 130, stderr
    m = re.search(r"^interrupted: (\d+) written, re-run to resume$", stderr, re.M)
    assert m, stderr
    assert "Traceback" not in stderr
    names = [p.name for p in objs.iterdir()]
    assert not [n for n in names if n.startswith(".")]  # no temporary folder left
    assert 3 <= len(names) == int(m.group(1)) < 200
    assert all(check_folder(objs / n).ok for n in names)
    assert [r["path"] for r in read_index(out)] == objects_on_disk(out)


@pytest.mark.parametrize("category, seed", [("door", 1), (CAT, 4)])
def test_validated_api_object_is_what_the_cli_writes(tmp_path, category, seed):
    r = run("generate", category, "-n", "1", "--seed", str(seed), "--out", str(tmp_path / "cli"), "-q")
    assert r.returncode == 0, r.stderr
    obj = artipg.generate(category, seed, validate=True)
    assert obj.report["ok"] is True and "repair" in obj.report
    api = export_object(obj, tmp_path / "api" / category / str(seed))
    assert folder_bytes(api) == folder_bytes(tmp_path / "cli" / category / str(seed))
    assert artipg.generate(category, seed).report == {}  # the plain call stays unvalidated


def test_shards_follow_the_index_and_are_reproducible(tmp_path):
    from artipg.data.shards import SHARD_DIR, iter_shard

    outs = [tmp_path / "a", tmp_path / "b"]
    for out in outs:
        r = run("generate", CAT, "bucket", "-n", "3", "--out", str(out), "-q", "--no-validate", "--shards", "2")
        assert r.returncode == 0 and "3 shards of up to 2 objects" in r.stdout, r.stderr
    shards = sorted((outs[0] / SHARD_DIR).glob("*.tar"))
    keys = [key for s in shards for key, _ in iter_shard(s)]
    assert keys == [row["path"] for row in read_index(outs[0])]
    for key, members in iter_shard(shards[0]):
        assert set(members) == {"annotation.json", "points.npz"}
        assert members["points.npz"] == (outs[0] / key / "points.npz").read_bytes()
    assert [s.read_bytes() for s in shards] == [s.read_bytes() for s in sorted((outs[1] / SHARD_DIR).glob("*.tar"))]
    # an unchanged shard is not rewritten; one whose objects changed is
    mtimes = [s.stat().st_mtime_ns for s in shards]
    import shutil

    shutil.rmtree(outs[0] / CAT / "2")
    r = run("index", str(outs[0]), "--shards", "2")
    assert r.returncode == 0 and "3 shards" in r.stdout, r.stderr
    assert [s.stat().st_mtime_ns for s in shards[:2]] == mtimes[:2]
    assert [key for s in shards for key, _ in iter_shard(s)] == [row["path"] for row in read_index(outs[0])]


def test_datasets_split_seeds_and_match_written_folders(tmp_path):
    pytest.importorskip("torch")
    import numpy as np
    from torch.utils.data import DataLoader

    from artipg.data import FolderDataset, ProceduralDataset

    out = tmp_path / "o"
    assert run("generate", CAT, "bucket", "-n", "3", "--out", str(out), "-q", "--shards", "2").returncode == 0

    def items(ds, workers=0):
        loader = DataLoader(ds, batch_size=None, num_workers=workers)
        return {(x["category"], int(x["seed"])): {k: np.asarray(v) for k, v in x.items() if k not in ("category",
                                                                                                  "seed")}
                for x in loader}

    procedural = ProceduralDataset([CAT, "bucket"], range(3), n_points=2048)
    every = items(procedural)
    assert sorted(every) == sorted((c, s) for c in (CAT, "bucket") for s in range(3))
    # two ranks with two loader workers each read every object once, the same arrays
    parts = [items(ProceduralDataset([CAT, "bucket"], range(3), rank=r, world_size=2), workers=2) for r in (0, 1)]
    assert not set(parts[0]) & set(parts[1]) and set(parts[0]) | set(parts[1]) == set(every)
    for part in parts:
        for key, arrays in part.items():
            assert all(np.array_equal(arrays[k], every[key][k]) for k in arrays)
    # at rest and epoch 0 the generated clouds are the written ones, from folders or shards
    for shards in (False, True):
        written = items(FolderDataset(out, shards=shards), workers=2)
        assert sorted(written) == sorted(every)
        for key, arrays in written.items():
            assert all(np.array_equal(arrays[k], every[key][k]) for k in arrays)
    moved = items(ProceduralDataset(CAT, [0], qpos="open"))[(CAT, 0)]
    assert not np.array_equal(moved["points"], every[(CAT, 0)]["points"])


@pytest.mark.parametrize("args, message", [
    (("generate", CAT, "--shards", "-1"), "--shards must be >= 0"),
    (("index", "no/such/folder"), "is not a folder"),
])
def test_bad_input_of_new_options_gives_one_line_error(tmp_path, args, message):
    r = run(*args, *(("--out", str(tmp_path / "o")) if args[0] == "generate" else ()))
    assert r.returncode != 0 and "Traceback" not in r.stderr + r.stdout
    assert message in r.stderr and len(r.stderr.strip().splitlines()) == 1
