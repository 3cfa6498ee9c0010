"""``artipg eval --generate``: generated sets on the fly against a reference folder."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

import artipg
from artipg.export.folder import export_object
from artipg.io.generated import generated_set, partnet_qpos


def test_generated_set_is_the_objects_own_sample():
    s = generated_set("bucket", [3, 4], n_points=256, sampling_seed=7)
    assert s.points.shape == (2, 256, 3) and s.folders == ["bucket/3", "bucket/4"]
    for i, seed in enumerate((3, 4)):
        pc = artipg.generate("bucket", seed).sample_points(256, seed=7)
        np.testing.assert_array_equal(s.points[i], pc.points)
        np.testing.assert_array_equal(s.link[i], pc.link)


def test_partnet_pose_opens_laptops_only():
    lap = artipg.generate("laptop", 0)
    q = partnet_qpos(lap, "laptop")
    assert q and all(v > 1.0 for v in q.values())
    rest, opened = generated_set("laptop", [0], 512), generated_set("laptop", [0], 512, pose="partnet")
    assert opened.structures[0].extents[2] > 2 * rest.structures[0].extents[2]  # the screen stands up
    assert partnet_qpos(artipg.generate("bucket", 0), "bucket") == {}


def _run(*args):
    return subprocess.run([sys.executable, "-m", "artipg.cli", "eval", *args], capture_output=True, text=True,
                          timeout=600)


def test_eval_generate_against_a_reference_folder(tmp_path):
    ref = tmp_path / "ref"
    for seed in (100, 101, 102):
        export_object(artipg.generate("bucket", seed), ref / "Bucket" / str(seed), n_points=0)
    out = tmp_path / "e.json"
    r = _run("--reference", str(ref), "--generate", "match", "--draws", "2", "--no-fid", "-q", "-j", "1",
             "--json", str(out))
    assert r.returncode == 0, r.stderr
    res = json.loads(out.read_text())["categories"]["bucket"]
    assert res["n_reference"] == 3 and res["n_generated"] == 3 and len(res["cov_draws"]) == 2
    assert 0.0 <= res["cov"] <= 1.0 and 0.0 <= res["one_nna"] <= 1.0
    assert res["structure"]["reference"]["proportions"]["height_width"]["median"] > 0


@pytest.mark.parametrize("args, message", [
    (("--generate", "1"), "at least 2"),
    (("--generate", "3", "--category", "no_such"), "unknown category"),
    (("--generate", "3", "--pose", "upside_down"), "--pose must be one of"),
    ((), "give either --generated DIR or --generate N"),
])
def test_eval_generate_bad_input(tmp_path, args, message):
    ref = tmp_path / "ref"
    export_object(artipg.generate("bucket", 0), ref / "bucket" / "0", n_points=0)
    r = _run("--reference", str(ref), "--no-fid", "-q", *args)
    assert r.returncode != 0 and message in r.stderr and "Traceback" not in r.stderr
