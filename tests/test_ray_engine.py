"""``artipg generate --engine ray``: the same bytes as the local pool for the same
seeds, resume, and one-line errors. Skipped without Ray (``pip install 'artipg[ray]'``)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

pytest.importorskip("ray")

CATS = ("storage_furniture", "usb")
N = 3


def run(*args, timeout=300):
    return subprocess.run([sys.executable, "-m", "artipg.cli", "generate", *args, "-q"], capture_output=True,
                          text=True, timeout=timeout)


def tree_bytes(out):
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*"))
            if p.is_file() and p.name != "index.jsonl"}


def index_rows(out):
    return sorted((json.loads(line) for line in (out / "index.jsonl").read_text().splitlines()),
                  key=lambda r: r["path"])


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    base = tmp_path_factory.mktemp("engines")
    local, ray = base / "local", base / "ray"
    r = run(*CATS, "-n", str(N), "--workers", "2", "--out", str(local))
    assert r.returncode == 0, r.stderr
    r = run(*CATS, "-n", str(N), "--workers", "2", "--engine", "ray", "--out", str(ray))
    assert r.returncode == 0, r.stderr
    return local, ray


def test_ray_writes_the_bytes_of_the_local_pool(outputs):
    local, ray = outputs
    a, b = tree_bytes(local), tree_bytes(ray)
    assert len({k.split("/")[1] for k in b if k.count("/") >= 2}) == N
    assert sorted(a) == sorted(b)
    assert [k for k in a if a[k] != b[k]] == []
    assert index_rows(local) == index_rows(ray)
    assert len(index_rows(ray)) == len(CATS) * N


def test_ray_resume_keeps_complete_and_rebuilds_damaged(outputs):
    _, ray = outputs
    before = tree_bytes(ray)
    (ray / CATS[0] / "1" / "points.npz").unlink()
    (ray / CATS[1] / "0" / "mobility.urdf").write_text("garbage")
    r = run(*CATS, "-n", str(N), "--workers", "2", "--engine", "ray", "--out", str(ray))
    assert r.returncode == 0, r.stderr
    assert "2 written (2 rebuilt: 2 damaged)" in r.stdout
    assert f"{len(CATS) * N - 2} already present" in r.stdout
    assert tree_bytes(ray) == before
    assert len(index_rows(ray)) == len(CATS) * N


@pytest.mark.parametrize("args, message", [
    (["--engine", "ray", "--address", "127.0.0.1:1"], "cannot connect to the Ray cluster"),
    (["--address", "127.0.0.1:6380"], "--address needs --engine ray"),
    (["--engine", "spark"], "unknown engine 'spark'"),
])
def test_engine_errors_are_one_line(tmp_path, args, message):
    r = run("usb", "-n", "1", "--out", str(tmp_path / "out"), *args, timeout=60)
    assert r.returncode != 0
    assert message in r.stderr
    assert "Traceback" not in r.stderr
