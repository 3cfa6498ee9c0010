"""Bucket-specific properties: the bail's rest pose and swing, bail clearance, lids."""

from __future__ import annotations

import math

import numpy as np
import pytest

import artipg
from artipg.geometry.transforms import rot_y
from artipg.rules import ParamRecorder
from artipg.templates import levers, lids


def _surface(part, n_per=400, seed=0):
    rng = np.random.default_rng(seed)
    out = []
    for prim in part.primitives:
        P = np.repeat(np.asarray([prim.params], dtype=float), n_per, axis=0)
        pts, _ = prim.geom.sample(P, rng)
        out.append(pts @ prim.pose[:3, :3].T + prim.pose[:3, 3])
    return np.concatenate(out)


@pytest.mark.parametrize("seed", range(0, 40, 3))
def test_bail_rests_folded_back_and_swings_over_the_top_to_the_front(seed):
    obj = artipg.generate("bucket", seed)
    k, j = next((k, j) for k, j in enumerate(obj.movable_joints) if j.child.startswith("handle"))
    lo, hi = j.limits
    assert j.type == "revolute" and lo == 0.0 and math.pi <= hi <= math.pi + 0.6
    part = obj.links[obj.link_index[j.child]].parts[0]
    apex = np.append(part.anchor("apex"), 1.0)
    pivot = obj.link_poses()[obj.link_index[j.child], :3, 3]

    def apex_at(q):
        qq = np.zeros(obj.dof)
        qq[k] = q
        T = obj.link_poses(qq)[obj.link_index[j.child]] @ part.pose
        return (T @ apex)[:3] - pivot

    rest, up, front = apex_at(0.0), apex_at(hi / 2), apex_at(hi)
    assert rest[0] > 0 and rest[2] <= 1e-9  # folded down to the back
    assert abs(up[0]) < 1e-9 and up[2] > 0  # upright half way
    assert front[0] == pytest.approx(-rest[0]) and front[2] == pytest.approx(rest[2])  # mirror image


@pytest.mark.parametrize("template", list(levers.BAILS))
def test_bail_swings_clear_of_the_obstacle_it_was_sized_for(template):
    for seed in range(6):
        rng = np.random.default_rng(seed)
        R, dz = rng.uniform(0.1, 0.2), rng.uniform(0.02, 0.09)
        span = R + rng.uniform(0.012, 0.025)
        bail = template(ParamRecorder(rng), span, clear=(R, dz))
        pts = _surface(bail)
        for a in np.linspace(-math.pi / 2, math.pi / 2, 19):
            q = pts @ rot_y(a)[:3, :3].T
            inside = (np.hypot(q[:, 0], q[:, 1]) < R) & (q[:, 2] > 0) & (q[:, 2] < dz)
            assert not inside.any()


@pytest.mark.parametrize("template", list(lids.LIDS))
@pytest.mark.parametrize("sides", [None, 6])
def test_lids_rest_on_the_rim_plane_and_flip_up_about_their_hinge(template, sides):
    for seed in range(4):
        lid = template(ParamRecorder(np.random.default_rng(seed)), 0.15, sides=sides)
        pts = _surface(lid)
        h = lid.anchor("hinge")
        assert pts[:, 0].max() <= h[0] + 1e-9 and pts[:, 2].min() >= h[2] - 1e-9
        assert lid.bounds()[1, 2] == pytest.approx(lid.anchor("top")[2], abs=1e-9)
        for a in np.linspace(0.0, math.pi / 2, 7):  # rotation about +y at the hinge lifts the front
            q = (pts - h) @ rot_y(a)[:3, :3].T
            assert q[:, 2].min() >= -1e-9
