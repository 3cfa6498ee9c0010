"""Every registered category, seeds 0..49: the exported URDF loads in yourdfpy, pybullet
and MuJoCo and agrees with our kinematics; joints move their children; objects stand on
the floor; labels cover the parts in proportion to their area; output is deterministic."""

from __future__ import annotations

import filecmp
import os

import numpy as np
import pytest

import artipg
from artipg.export.folder import export_object
from artipg.vocabulary import SEMANTIC_LABELS
from conftest import CATEGORIES, SEEDS, open_qpos


@pytest.fixture(scope="module")
def bullet():
    import pybullet as pb

    cid = pb.connect(pb.DIRECT)
    yield pb, cid
    pb.disconnect(cid)


def _check_yourdfpy(obj, urdf_path):
    import yourdfpy

    u = yourdfpy.URDF.load(urdf_path)
    for link in u.robot.links:  # yourdfpy does not insist that meshes exist: we do
        for g in [*link.visuals, *link.collisions]:
            if g.geometry.mesh is not None:
                assert os.path.isfile(os.path.join(os.path.dirname(urdf_path), g.geometry.mesh.filename))
    mv = obj.movable_joints
    assert sorted(u.actuated_joint_names) == sorted(j.name for j in mv)
    # forward kinematics of the URDF equals ours, at rest and in a random state
    rng = np.random.default_rng(obj.seed)
    lim = obj.limits()
    q = lim[:, 0] + rng.random(len(mv)) * (lim[:, 1] - lim[:, 0])
    for qpos in (np.zeros(len(mv)), q):
        u.update_cfg({j.name: v for j, v in zip(mv, qpos)})
        ours = obj.link_poses(qpos)
        for i, link in enumerate(obj.links):
            T = u.get_transform(link.name, obj.links[0].name)
            assert np.allclose(T, ours[i], atol=1e-6), f"{link.name} pose differs from the URDF's"


def _check_pybullet(pb, cid, obj, urdf_path):
    body = pb.loadURDF(urdf_path, useFixedBase=True, physicsClientId=cid,
                       flags=pb.URDF_USE_SELF_COLLISION | pb.URDF_USE_SELF_COLLISION_INCLUDE_PARENT)
    try:
        assert pb.getNumJoints(body, physicsClientId=cid) == len(obj.joints)
        types = {pb.JOINT_REVOLUTE: ("revolute", "continuous"), pb.JOINT_PRISMATIC: ("prismatic",),
                 pb.JOINT_FIXED: ("fixed",)}
        for i in range(pb.getNumJoints(body, physicsClientId=cid)):
            info = pb.getJointInfo(body, i, physicsClientId=cid)
            j = obj.joint(info[1].decode())
            assert j.type in types[info[2]]
            if j.type in ("revolute", "prismatic"):
                assert info[8] == pytest.approx(j.limits[0], abs=1e-6) and info[9] == pytest.approx(j.limits[1], abs=1e-6)
    finally:
        pb.removeBody(body, physicsClientId=cid)


def _check_mujoco(obj, urdf_path):
    import mujoco

    m = mujoco.MjModel.from_xml_path(urdf_path)
    assert m.njnt == obj.dof
    assert m.nbody == len(obj.links) + 1  # + world
    for j in obj.movable_joints:
        jid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, j.name)
        assert jid >= 0
        if j.type in ("revolute", "prismatic"):
            assert np.allclose(m.jnt_range[jid], j.limits, atol=1e-6)


@pytest.mark.parametrize("category", CATEGORIES)
def test_urdf_loads_and_matches_kinematics(category, tmp_path, bullet):
    pb, cid = bullet
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        dest = export_object(obj, tmp_path / str(seed), n_points=0)
        urdf = str(dest / "mobility.urdf")
        _check_yourdfpy(obj, urdf)
        _check_pybullet(pb, cid, obj, urdf)
        _check_mujoco(obj, urdf)


@pytest.mark.parametrize("category", CATEGORIES)
def test_every_joint_moves_its_child(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        assert obj.dof >= 1, f"{category}/{seed} has no movable joint"
        rest = obj.link_poses()
        idx = obj.link_index
        for j, (lo, hi) in zip(obj.movable_joints, obj.limits()):
            for v in (lo, hi):
                if v == 0.0:
                    continue
                moved = obj.link_poses({j.name: v})
                assert not np.allclose(moved[idx[j.child]], rest[idx[j.child]]), f"{j.name} does not move"
                assert np.allclose(moved[idx[j.parent]], rest[idx[j.parent]])


@pytest.mark.parametrize("category", CATEGORIES)
def test_objects_stand_on_the_floor_centred(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        b = obj.bounds()
        assert b[0, 2] == pytest.approx(0.0, abs=1e-9)
        assert np.allclose((b[0, :2] + b[1, :2]) / 2, 0.0, atol=1e-9)
        assert 0.01 < np.ptp(b, axis=0).max() < 3.5, "not a real-world size"
        for j in obj.movable_joints:
            if j.type in ("revolute", "prismatic"):
                assert j.limits[0] < j.limits[1]
                assert j.limits[0] <= 0.0 <= j.limits[1], "joint value 0 must be the rest pose"


@pytest.mark.parametrize("category", CATEGORIES)
def test_points_cover_links_in_proportion_to_area(category):
    for seed in range(5):
        obj = artipg.generate(category, seed)
        n = 20000
        pc = obj.sample_points(n, seed=seed, qpos=open_qpos(obj, 0.5))
        assert pc.points.shape == (n, 3) and pc.normals.shape == (n, 3)
        assert pc.semantic_names == SEMANTIC_LABELS
        table = obj.primitive_table
        area = np.zeros(len(obj.links))
        for g in table.groups:
            np.add.at(area, g.link, g.area)
        expected = n * area / area.sum()
        observed = np.bincount(pc.link, minlength=len(obj.links))
        sigma = np.sqrt(expected * (1 - area / area.sum()))
        assert (np.abs(observed - expected) <= 5 * sigma + 2).all()
        assert (observed[expected >= 20] > 0).all()
        # labels agree with the parts the points came from
        parts = obj.parts
        assert all(SEMANTIC_LABELS[pc.semantic[i]] == parts[pc.instance[i]].semantic for i in range(0, n, 97))
        assert (obj.part_link[pc.instance] == pc.link).all()


@pytest.mark.parametrize("category", CATEGORIES)
def test_same_seed_gives_identical_folders(category, tmp_path):
    for seed in (0, 7):
        a = export_object(artipg.generate(category, seed), tmp_path / "a" / str(seed))
        b = export_object(artipg.generate(category, seed), tmp_path / "b" / str(seed))
        cmp = filecmp.dircmp(a, b)
        files = [p.relative_to(a) for p in a.rglob("*") if p.is_file()]
        assert files and not cmp.left_only and not cmp.right_only
        for f in files:
            assert (a / f).read_bytes() == (b / f).read_bytes(), f"{f} differs"
    other = artipg.generate(category, 8).sample_points(256).points
    assert not np.allclose(other, artipg.generate(category, 0).sample_points(256).points)
