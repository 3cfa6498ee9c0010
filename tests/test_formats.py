"""MJCF, USD and GLB beside the URDF: each loads in its consumer, round-trips the one
kinematic model, and behaves in MuJoCo (see docs/formats.md).

Every category on 2 seeds here; ``benchmarks/bench_formats.py`` runs 20.
"""

from __future__ import annotations

import subprocess
import sys
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

import artipg
from artipg.export.folder import export_object
from artipg.export.meshes import link_inertial

CATEGORIES = artipg.categories()
SEEDS = (0, 1)
ALL = ("urdf", "mjcf")
#: Categories whose MuJoCo behaviour is simulated here (free-standing and fixtures,
#: hinges and slides); the benchmark reports every category.
SIM_CATEGORIES = ("storage_furniture", "microwave", "faucet", "dishwasher", "laptop", "door")

mujoco = pytest.importorskip("mujoco")


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    return tmp_path_factory.mktemp("formats")


_made: dict = {}


def folder(out: Path, category: str, seed: int) -> Path:
    """The object folder of (category, seed) with all four formats and servos."""
    key = (category, seed)
    if key not in _made:
        _made[key] = export_object(artipg.generate(category, seed), out / category / str(seed), n_points=0,
                                   formats=ALL, actuators=True)
    return _made[key]


@lru_cache(maxsize=None)
def model(category: str, seed: int):
    return artipg.generate(category, seed)


def _rel(a, b) -> float:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return float(np.abs(a - b).max() / max(np.abs(b).max(), 1e-12))


def _expected(obj):
    """{link: (mass, com, inertia)} and {joint: (type, parent, child, origin, axis, limits)} of the model."""
    links = {lk.name: link_inertial(lk, 24, obj.materials) for lk in obj.links}
    joints = {j.name: (j.type, j.parent, j.child, j.origin, j.axis, j.limits) for j in obj.joints}
    return links, joints


def _compare(obj, links, joints, where: str):
    """Assert read-back links and joints equal the model's (inertials to 1e-6 relative)."""
    want_links, want_joints = _expected(obj)
    assert set(links) == set(want_links), where
    assert set(joints) == set(want_joints), where
    for name, (m, c, I) in want_links.items():
        gm, gc, gI = links[name]
        assert abs(gm - m) <= 1e-6 * m, (where, name, gm, m)
        assert np.abs(np.asarray(gc) - c).max() <= 1e-6 * max(1.0, np.abs(c).max()), (where, name)
        assert _rel(gI, I) <= 1e-6, (where, name, gI, I)
    for name, (t, p, ch, T, ax, lim) in want_joints.items():
        gt, gp, gch, gT, gax, glim = joints[name]
        assert (gt, gp, gch) == (t, p, ch), (where, name)
        assert np.abs(np.asarray(gT) - T).max() <= 1e-6, (where, name, gT, T)
        if t != "fixed":
            assert np.abs(np.asarray(gax) - ax).max() <= 1e-6, (where, name)
        if t in ("revolute", "prismatic"):
            assert np.abs(np.asarray(glim) - lim).max() <= 1e-6, (where, name, glim, lim)


# ------------------------------------------------------------------ readers

def read_urdf(path: Path):
    from artipg.export.asset import asset_from_urdf, load_robot

    a = asset_from_urdf(load_robot(path))
    links = {lk.name: (lk.mass, lk.com, lk.inertia) for lk in a.links}
    joints = {j.name: (j.type, j.parent, j.child, j.origin, j.axis, j.limits) for j in a.joints}
    return links, joints


def _quat_mat(q) -> np.ndarray:
    m = np.zeros(9)
    mujoco.mju_quat2Mat(m, np.asarray(q, dtype=float))
    return m.reshape(3, 3)


def read_mjcf(path: Path):
    m = mujoco.MjModel.from_xml_path(str(path))
    name = lambda t, i: mujoco.mj_id2name(m, t, i)  # noqa: E731
    links, joints = {}, {}
    jtype = {int(mujoco.mjtJoint.mjJNT_HINGE): "revolute", int(mujoco.mjtJoint.mjJNT_SLIDE): "prismatic"}
    for b in range(1, m.nbody):
        R = _quat_mat(m.body_iquat[b])
        links[name(mujoco.mjtObj.mjOBJ_BODY, b)] = (m.body_mass[b], m.body_ipos[b],
                                                    R @ np.diag(m.body_inertia[b]) @ R.T)
        p = m.body_parentid[b]
        if p == 0:
            continue
        T = np.eye(4)
        T[:3, :3] = _quat_mat(m.body_quat[b])
        T[:3, 3] = m.body_pos[b]
        n = m.body_jntnum[b]
        assert n <= 1
        if n:
            j = m.body_jntadr[b]
            t = jtype[int(m.jnt_type[j])]
            if t == "revolute" and not m.jnt_limited[j]:
                t = "continuous"
            joints[name(mujoco.mjtObj.mjOBJ_JOINT, j)] = (t, name(mujoco.mjtObj.mjOBJ_BODY, p),
                                                          name(mujoco.mjtObj.mjOBJ_BODY, b), T, m.jnt_axis[j],
                                                          tuple(m.jnt_range[j]))
        else:  # a welded child: the URDF's fixed joint, named in the file
            joints[_fixed_name(path, name(mujoco.mjtObj.mjOBJ_BODY, b))] = (
                "fixed", name(mujoco.mjtObj.mjOBJ_BODY, p), name(mujoco.mjtObj.mjOBJ_BODY, b), T, None, None)
    return links, joints


def _fixed_name(mjcf: Path, child: str) -> str:
    """Name of the fixed URDF joint of ``child`` (MJCF welds have no joint element)."""
    from artipg.export.asset import load_robot

    robot = load_robot(mjcf.with_name("mobility.urdf"))
    return next(j.name for j in robot.joints if j.child == child)


# ------------------------------------------------------------------ tests

@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("category", CATEGORIES)
def test_mjcf_loads_in_mujoco_without_warning(out, category, seed, capfd, tmp_path, monkeypatch):
    f = folder(out, category, seed)
    monkeypatch.chdir(tmp_path)  # MuJoCo writes warnings to MUJOCO_LOG.TXT here
    m = mujoco.MjModel.from_xml_path(str(f / "mobility.xml"))
    captured = capfd.readouterr()
    assert "WARNING" not in captured.out + captured.err
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()
    obj = model(category, seed)
    assert m.nbody == len(obj.links) + 1
    assert m.nu == obj.dof
    free = m.njnt and m.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    from artipg.validate.sim import category_fixed_base

    assert bool(free) != category_fixed_base(category)
    # visuals never collide, collision geoms do
    vis = m.geom_group == 2
    assert vis.any() and not (m.geom_contype[vis] | m.geom_conaffinity[vis]).any()
    assert (m.geom_contype[~vis] == 1).all()


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("category", CATEGORIES)
def test_urdf_and_mjcf_round_trip_the_model(out, category, seed):
    f = folder(out, category, seed)
    obj = model(category, seed)
    _compare(obj, *read_urdf(f / "mobility.urdf"), "urdf")
    _compare(obj, *read_mjcf(f / "mobility.xml"), "mjcf")


@pytest.mark.parametrize("category", SIM_CATEGORIES)
def test_mujoco_rest_and_drive(out, category):
    from artipg.export.mjcf_sim import drive_limits, drive_tolerance, rest_drift

    f = folder(out, category, 0) / "mobility.xml"
    assert rest_drift(f) < 2e-3
    tol = drive_tolerance(f)
    reached = drive_limits(f)
    assert set(reached) == set(tol) and reached
    missed = {k: v for k, v in reached.items() if max(v) > tol[k]}
    assert not missed


def test_mujoco_checks_catch_a_blocked_joint_and_a_tipping_object(out, tmp_path):
    """Planted faults: a wall just in front of a cabinet (its doors and drawers cannot
    open), and the cabinet dropped tilted on one edge."""
    import re

    from artipg.export.mjcf_sim import drive_limits, drive_tolerance, rest_drift

    src = folder(out, "storage_furniture", 0)
    front = float(model("storage_furniture", 0).bounds()[0, 0])
    text = (src / "mobility.xml").read_text().replace('meshdir="."', f'meshdir="{src}"')
    blocked = tmp_path / "blocked.xml"
    blocked.write_text(text.replace("<worldbody>", f'<worldbody><geom type="box" size="0.01 3 3" '
                                                   f'pos="{front - 0.012} 0 0"/>', 1))
    tol = drive_tolerance(blocked)
    assert tol and all(max(v) > tol[k] for k, v in drive_limits(blocked).items())
    tilted = tmp_path / "tilted.xml"
    tilted.write_text(re.sub(r'<body name="([^"]+)">', r'<body name="\1" euler="0.5 0 0" pos="0 0 0.3">', text, count=1))
    assert rest_drift(tilted) > 2e-3


def test_generate_cli_formats_and_bad_format(tmp_path):
    cmd = [sys.executable, "-m", "artipg.cli", "generate", "faucet", "-n", "1", "--points", "0", "--no-validate",
           "-q", "-o", str(tmp_path), "--formats", "urdf,mjcf,usd,glb"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    names = {p.name for p in (tmp_path / "faucet" / "0").iterdir()}
    assert {"mobility.urdf", "mobility.xml", "mobility.usd", "mobility.glb"} <= names
    r = subprocess.run(cmd[:-1] + ["urdf,sdf"], capture_output=True, text=True)
    assert r.returncode != 0 and len(r.stderr.strip().splitlines()) == 1 and "sdf" in r.stderr
