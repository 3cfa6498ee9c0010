"""Faucet-specific properties: spouts reach forward, handles open outwards, the
pull-out head slides out along the spout's outlet, lever ranges are realistic."""

from __future__ import annotations

import numpy as np

import artipg

SEEDS = range(0, 60, 2)


def _objects(sub=None):
    objs = [artipg.generate("faucet", s) for s in SEEDS]
    return [o for o in objs if sub is None or o.subcategory == sub]


def _link_centroid(obj, name, qpos):
    pc = obj.sample_points(3000, seed=2, qpos=qpos)
    return pc.points[pc.link == obj.link_index[name]].mean(axis=0)


def test_spout_outlet_is_in_front_of_the_body():
    for obj in _objects():
        spout = next(p for p in obj.parts if p.semantic == "spout")
        T = obj.part_poses()[obj.parts.index(spout)]
        outlet = T[:3, :3] @ spout.anchor("outlet") + T[:3, 3]
        assert outlet[0] < -0.04, obj.seed  # reaches over the basin (front is -x)
        assert outlet[2] > 0.04, obj.seed


def test_two_handles_mirror_each_other_and_open_outwards():
    objs = _objects("two_handle")
    assert objs
    for obj in objs:
        handles = [(k, j) for k, j in enumerate(obj.movable_joints) if j.child.startswith("lever")]
        assert len(handles) == 2
        (k0, j0), (k1, j1) = handles
        assert j0.limits == j1.limits and j0.limits[0] == 0.0 and 1.0 <= j0.limits[1] <= 1.7
        for k, j in handles:  # the front of the handle (-x at rest) turns away from the spout
            i = obj.link_index[j.child]
            part = obj.links[i].parts[0]
            front = np.array([-part.anchor("reach")[0], 0.0, 0.0, 1.0])
            q = np.zeros(obj.dof)
            q[k] = j.limits[1]
            y0 = (obj.link_poses()[i] @ part.pose @ front)[1]
            y1 = (obj.link_poses(q)[i] @ part.pose @ front)[1]
            side = np.sign(obj.link_poses()[i, 1, 3])
            assert side * (y1 - y0) > 0.5 * part.anchor("reach")[0], obj.seed


def test_pull_out_head_slides_along_the_outlet_direction():
    objs = _objects("pull_out")
    assert objs
    for obj in objs:
        k, j = next((k, j) for k, j in enumerate(obj.movable_joints) if j.child.startswith("nozzle"))
        assert j.type == "prismatic" and 0.05 <= j.limits[1] <= 0.25
        spout = next(p for p in obj.parts if p.semantic == "spout")
        T = obj.part_poses()[obj.parts.index(spout)]
        d = T[:3, :3] @ spout.anchor("outlet_dir")
        q = np.zeros(obj.dof)
        q[k] = j.limits[1]
        i = obj.link_index[j.child]
        move = obj.link_poses(q)[i, :3, 3] - obj.link_poses()[i, :3, 3]
        assert np.allclose(move, j.limits[1] * d, atol=1e-9)
        assert d[2] < 0  # pulls out downwards / forwards into the basin


def test_lever_ranges_are_realistic():
    for obj in _objects():
        for j in obj.movable_joints:
            if j.child.startswith("lever"):
                assert j.type == "revolute" and j.limits[0] == 0.0 and 0.25 <= j.limits[1] <= 1.7
            elif j.child.startswith("spout") and j.type == "revolute":
                assert j.limits[0] == -j.limits[1] and 0.5 <= j.limits[1] <= 1.7
