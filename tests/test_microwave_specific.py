"""Microwave-specific properties and the panel-control frame convention."""

from __future__ import annotations

import numpy as np
import pytest

import artipg
from artipg.rules import ParamRecorder
from artipg.templates import controls

SEEDS = range(0, 40, 3)


def _moving_points(obj, link, qpos, n=4000):
    pc = obj.sample_points(n, seed=1, qpos=qpos)
    return pc.points[pc.link == obj.link_index[link]]


@pytest.mark.parametrize("seed", SEEDS)
def test_door_hinges_on_the_left_and_swings_out_in_front(seed):
    obj = artipg.generate("microwave", seed)
    door = next(j for j in obj.movable_joints if j.child.startswith("door"))
    lo, hi = door.limits
    assert lo == 0.0 and np.radians(85) <= hi <= np.radians(115)
    front = obj.bounds()[0, 0]  # the closed door's front face is the object's front
    body = [p for p in obj.links[0].parts if p.template == "appliance_housing"][0]
    body_front = body.pose[0, 3] + body.anchor("front")[0]
    i = obj.movable_joints.index(door)
    for frac in (0.25, 0.5, 1.0):
        q = np.zeros(obj.dof)
        q[i] = frac * hi
        pts = _moving_points(obj, door.child, q)
        assert pts[:, 0].max() <= body_front + 1e-6  # never enters the body
    q = np.zeros(obj.dof)
    q[i] = hi
    pts = _moving_points(obj, door.child, q)
    assert pts[:, 0].min() < front - 0.1  # really swung out
    assert pts[:, 1].mean() > 0.0  # towards the hinge side (+y, viewer's left)


@pytest.mark.parametrize("seed", SEEDS)
def test_buttons_press_inwards_a_few_millimetres_and_knobs_turn_about_x(seed):
    obj = artipg.generate("microwave", seed)
    L0 = obj.link_poses()
    for k, j in enumerate(obj.movable_joints):
        if j.child.startswith("button"):
            assert j.type == "prismatic" and 0.003 <= j.limits[1] <= 0.006
            q = np.zeros(obj.dof)
            q[k] = j.limits[1]
            d = obj.link_poses(q)[obj.link_index[j.child], :3, 3] - L0[obj.link_index[j.child], :3, 3]
            assert d[0] == pytest.approx(j.limits[1]) and abs(d[1]) < 1e-9 and abs(d[2]) < 1e-9
        if j.child.startswith("knob"):
            axis = L0[obj.link_index[j.child], :3, :3] @ j.axis
            assert abs(axis[0]) == pytest.approx(1.0)


@pytest.mark.parametrize("template", list(controls.KNOBS) + list(controls.BUTTONS) + [controls.rocker_switch])
def test_controls_protrude_along_minus_x_from_the_mount_plane(template):
    for s in range(5):
        part = template(ParamRecorder(np.random.default_rng(s)))
        b = part.bounds()
        assert b[1, 0] <= 1e-9 and b[0, 0] < -0.003
        if part.semantic == "button":  # fully pressed, the cap still stays off the surface
            travel = part.anchors["stop"][0] - part.anchors["back"][0]
            assert 0.003 <= travel <= 0.006 and b[1, 0] + travel < 0.0


@pytest.mark.parametrize("template", list(controls.BUTTONS))
def test_bezel_holds_its_button_within_two_millimetres_and_lets_it_press(template):
    for seed in range(5):
        p = ParamRecorder(np.random.default_rng(seed))
        cap = template(p)
        bezel = controls.button_bezel(p.scope("bezel"), cap)
        prim = cap.primitives[0]
        P = np.repeat(np.asarray([prim.params], dtype=float), 500, axis=0)
        local, _ = prim.geom.sample(P, np.random.default_rng(seed))
        pts = local @ prim.pose[:3, :3].T + prim.pose[:3, 3]
        travel = cap.anchors["stop"][0] - cap.anchors["back"][0]
        ring = bezel.primitives[0]
        assert ring.sdf(pts).min() <= 0.002  # touches at rest
        for q in np.linspace(0.0, travel, 5):
            assert ring.sdf(pts + [q, 0.0, 0.0]).min() >= -1e-9  # slides in without penetrating
        assert bezel.bounds()[1, 0] == pytest.approx(0.0, abs=1e-9)  # stands on the surface
