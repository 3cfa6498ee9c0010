"""The command line: listing, generation layout, resume after a kill, bad input."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

import artipg

CAT = "storage_furniture"


def run(*args, timeout=300):
    return subprocess.run([sys.executable, "-m", "artipg.cli", *args], capture_output=True, text=True,
                          timeout=timeout)


def test_categories_lists_every_category():
    r = run("categories")
    assert r.returncode == 0
    listed = [line.split(":")[0] for line in r.stdout.splitlines()]
    assert listed == artipg.categories()


def test_generate_layout_and_byte_identical_rerun(tmp_path):
    r = run("generate", CAT, "-n", "3", "--seed", "5", "--out", str(tmp_path / "a"), "-q")
    assert r.returncode == 0, r.stderr
    folders = sorted(p.name for p in (tmp_path / "a" / CAT).iterdir())
    assert folders == ["5", "6", "7"]
    for s in folders:
        names = {p.name for p in (tmp_path / "a" / CAT / s).iterdir()}
        assert {"mobility.urdf", "meshes", "semantics.txt", "annotation.json", "points.npz"} <= names
    # one seed alone, with workers, reproduces the folder byte for byte
    r = run("generate", CAT, "-n", "1", "--seed", "6", "--out", str(tmp_path / "b"), "-q", "--workers", "2")
    assert r.returncode == 0, r.stderr
    a, b = tmp_path / "a" / CAT / "6", tmp_path / "b" / CAT / "6"
    for f in a.rglob("*"):
        if f.is_file():
            assert f.read_bytes() == (b / f.relative_to(a)).read_bytes(), f


@pytest.mark.parametrize("args, message", [
    (("generate", "no_such_thing"), "unknown category"),
    (("generate", CAT, "-n", "0"), "-n must be at least 1"),
    (("generate", CAT, "-n", "-4"), "-n must be at least 1"),
    (("generate", CAT, "--seed", "-1"), "--seed must be >= 0"),
    (("generate", CAT, "--workers", "0"), "--workers"),
    (("generate", CAT, "--points", "-5"), "--points"),
    (("generate", CAT, "-n", "abc"), "Invalid value for '-n'"),
    (("generate",), "Missing argument"),
])
def test_bad_input_gives_one_line_error(args, message, tmp_path):
    r = run(*args, "--out", str(tmp_path / "o"))
    assert r.returncode != 0
    assert "Traceback" not in r.stderr + r.stdout
    assert message in r.stderr
    if "unknown category" in message:
        assert all(c in r.stderr for c in artipg.categories())


def test_unwritable_output_folder(tmp_path):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    target = ro / "sub"
    if os.access(ro, os.W_OK):  # running as root: use a path under a file instead
        blocker = tmp_path / "file"
        blocker.write_text("x")
        target = blocker / "sub"
    r = run("generate", CAT, "-n", "1", "--out", str(target))
    assert r.returncode != 0 and "Traceback" not in r.stderr
    assert "cannot write" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_killed_run_resumes_without_rewriting(tmp_path):
    out = tmp_path / "o"
    n = 60
    proc = subprocess.Popen([sys.executable, "-m", "artipg.cli", "generate", CAT, "-n", str(n), "--out", str(out),
                             "-q"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    folder = out / CAT
    deadline = time.time() + 120
    while time.time() < deadline:
        done = [p for p in folder.iterdir() if not p.name.startswith(".")] if folder.exists() else []
        if len(done) >= 3:
            break
        time.sleep(0.05)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    finished = {p.name: p.stat().st_mtime_ns for p in folder.iterdir() if not p.name.startswith(".")}
    assert 3 <= len(finished) < n
    for name in finished:  # a folder that exists is complete
        assert (folder / name / "points.npz").is_file() and (folder / name / "mobility.urdf").is_file()
    r = run("generate", CAT, "-n", str(n), "--out", str(out), "-q")
    assert r.returncode == 0, r.stderr
    assert f"{len(finished)} already present" in r.stdout
    after = {p.name: p.stat().st_mtime_ns for p in folder.iterdir()}
    assert sorted(after, key=int) == [str(s) for s in range(n)]  # no temporary leftovers
    assert all(after[k] == v for k, v in finished.items())


def test_validate_mounts_fixtures_unless_told_otherwise(tmp_path):
    """A door's annotation marks it a fixture: `artipg validate` simulates it mounted by
    default and dropped on the floor with --free-base."""
    import json

    from artipg.export import export_object

    folder = export_object(artipg.generate("door", 0), tmp_path / "door" / "0")
    assert json.loads((folder / "annotation.json").read_text())["fixed_base"] is True
    for flag, expected in (([], True), (["--free-base"], False)):
        out = tmp_path / f"report{len(flag)}.json"
        r = run("validate", str(folder), "--json", str(out), *flag)
        report = json.loads(out.read_text())["objects"][0]
        assert report["fixed_base"] is expected, (r.stdout, r.stderr)
        assert report["checks"]["simulator"]["info"]["fixed_base"] is expected
