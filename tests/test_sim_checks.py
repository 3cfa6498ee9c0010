"""Simulator checks (issue 3): pybullet and MuJoCo.

- every registered category passes them (the benchmark sweeps seeds 0..199);
- fixtures (``Category.fixed_base``) are simulated mounted, everything else is dropped
  on a floor, and the policy travels with the object (report, folders);
- each engine setting of :mod:`artipg.validate.sim` is needed: a minimal object shows
  the simulator artefact it removes (the setting turned off, the check fails on a
  sound object), and the check passes with it;
- joints blocked only while another joint is closed (a rack behind its door) are not
  reported; joints blocked either way are.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import artipg
from artipg.export.folder import export_object
from artipg.export.meshes import obj_text
from artipg.export.urdf import build_urdf, urdf_text
from artipg.geometry import cuboid, cuboid_between, cylinder, frustum, rect_ring
from artipg.geometry.transforms import rot_x, rot_y, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.validate import check_object, generate_valid, sim, sim_common, sim_mujoco, sim_pybullet
from artipg.validate.folder import validate_folder
from conftest import CATEGORIES

SIM_SEEDS = (0, 1)
_Y = rot_x(math.pi / 2)  # local z -> y


def _rule(name, build):
    obj = Category(name, {"plain": 1.0}, (Slot("main", build),)).generate(0)
    assert check_object(obj).ok  # geometrically sound: any simulator failure is an artefact
    return obj


def _write(obj, folder):
    robot, meshes = build_urdf(obj, visuals=False)
    for rel, text in meshes.items():
        (folder / rel).parent.mkdir(parents=True, exist_ok=True)
        (folder / rel).write_text(text)
    (folder / "mobility.urdf").write_text(urdf_text(robot))
    return folder / "mobility.urdf"


# ---------------------------------------------------------------- every category

@pytest.mark.parametrize("category", CATEGORIES)
def test_every_category_passes_the_simulator_checks(category):
    fixed = artipg.get_category(category).fixed_base
    for seed in SIM_SEEDS:
        obj = generate_valid(category, seed)
        assert obj.report["fixed_base"] is fixed
        r = sim.simulate_object(obj)
        assert r.ok, f"{category}/{seed}: {[i.to_json() for i in r.issues]}"
        assert r.info["fixed_base"] is fixed
        for engine in ("pybullet", "mujoco"):
            info = r.info[engine]
            assert info["rest_penetration"] <= 1e-3
            if fixed:
                assert info["drop"] == "fixed base" and "drift" not in info
            else:
                assert 0.0 <= info["drift"] < 1e-3


def test_fixtures_are_mounted_and_everything_else_stands_on_the_floor():
    fixtures = {c for c in CATEGORIES if artipg.get_category(c).fixed_base}
    assert fixtures == {"door", "door_handle", "faucet", "switch", "window", "toilet"}
    assert Category("test_free", {"plain": 1.0}, ()).fixed_base is False


def test_office_chairs_stand_on_their_casters():
    """Casters, column and seat are jointed: held rigidly, the chair must not creep."""
    seeds = [s for s in range(40) if artipg.generate("chair", s).subcategory == "office"][:3]
    assert len(seeds) == 3
    for seed in seeds:
        r = sim.simulate_object(generate_valid("chair", seed))
        assert r.ok, [i.to_json() for i in r.issues]
        assert max(r.info["pybullet"]["drift"], r.info["mujoco"]["drift"]) < 1e-3


def test_folding_chairs_stand_on_all_four_feet():
    """Front tubes and rear legs both reach the floor (a chair on two feet rocks)."""
    seeds = [s for s in range(60) if artipg.generate("chair", s).subcategory == "folding"][:6]
    assert len(seeds) == 6
    for seed in seeds:
        obj = artipg.generate("chair", seed)
        lows = {}
        for link, T in zip(obj.links, obj.link_poses()):
            if link.name in ("base_0", "leg_0"):
                lows[link.name] = min(prim.placed(T @ part.pose).bounds()[0][2]
                                      for part in link.parts for prim in part.primitives)
        assert lows["base_0"] == pytest.approx(0.0, abs=1e-5) and lows["leg_0"] == pytest.approx(0.0, abs=1e-5)


def test_folders_keep_the_mounting_policy(tmp_path):
    faucet = generate_valid("faucet", 0)
    dest = export_object(faucet, tmp_path / "faucet", n_points=0)
    report, meta = validate_folder(dest)
    assert meta["fixed_base"] is True and report.ok
    assert report.checks["simulator"].info["mujoco"]["drop"] == "fixed base"
    # the same URDF without its annotation is dropped on the floor (and a faucet tips)
    bare = tmp_path / "bare"
    bare.mkdir()
    (bare / "mobility.urdf").write_text((dest / "mobility.urdf").read_text())
    (bare / "meshes").symlink_to(dest / "meshes")
    report, meta = validate_folder(bare)
    assert meta["fixed_base"] is False and "drift" in report.checks["simulator"].info["mujoco"]


# ---------------------------------------------------------------- pybullet margins

def test_eroded_hulls_move_every_face_in_by_the_margin():
    box = np.array([[x, y, z] for x in (0, 0.02) for y in (0, 0.01) for z in (0, 0.005)])
    V, F, e = sim_pybullet.eroded_hull(box, 1e-3)
    assert e == 1e-3 and F.shape[1] == 3
    assert np.allclose(V.min(axis=0), [0.001] * 3) and np.allclose(V.max(axis=0), [0.019, 0.009, 0.004])
    plate = box * [1.0, 1.0, 0.3]  # 1.5 mm thick: eroded to a sliver, not to nothing
    V, F, e = sim_pybullet.eroded_hull(plate, 1e-3)
    assert e == pytest.approx(0.0007) and np.ptp(V[:, 2]) == pytest.approx(1e-4)


def test_pybullet_sees_touching_meshes_touch(tmp_path):
    """pybullet pads each convex mesh by 1 mm: two touching mesh boxes read 2 mm deep,
    unless the meshes are eroded by that margin first (:func:`pybullet_urdf`)."""
    box = np.array([[x, y, z] for x in (-0.02, 0.02) for y in (-0.02, 0.02) for z in (0, 0.02)], dtype=float)
    hull_faces = sim_pybullet.eroded_hull(box, 0.0)[1]
    (tmp_path / "box.obj").write_text(obj_text(box, hull_faces))
    robot = ET.Element("robot", name="touch")
    for name in ("a", "b"):
        link = ET.SubElement(robot, "link", name=name)
        inertial = ET.SubElement(link, "inertial")
        ET.SubElement(inertial, "mass", value="0.1")
        ET.SubElement(inertial, "inertia", ixx="1e-4", iyy="1e-4", izz="1e-4", ixy="0", ixz="0", iyz="0")
        col = ET.SubElement(link, "collision")
        ET.SubElement(ET.SubElement(col, "geometry"), "mesh", filename="box.obj")
    joint = ET.SubElement(robot, "joint", name="slide", type="prismatic")
    ET.SubElement(joint, "origin", xyz="0 0 0.02", rpy="0 0 0")
    ET.SubElement(joint, "parent", link="a")
    ET.SubElement(joint, "child", link="b")
    ET.SubElement(joint, "axis", xyz="0 0 1")
    ET.SubElement(joint, "limit", lower="0", upper="0.1", effort="10", velocity="1")
    ET.ElementTree(robot).write(tmp_path / "touch.urdf")

    pb = sim_pybullet._import_pybullet()

    def distance(urdf):
        cid = pb.connect(pb.DIRECT)
        try:
            _, flags = sim_pybullet.pybullet_configure(pb, cid)
            body = pb.loadURDF(str(urdf), useFixedBase=True, flags=flags, physicsClientId=cid)
            cps = pb.getClosestPoints(body, body, 0.005, linkIndexA=-1, linkIndexB=0, physicsClientId=cid)
            return min(c[8] for c in cps)
        finally:
            pb.disconnect(cid)

    assert distance(tmp_path / "touch.urdf") == pytest.approx(-2 * sim_pybullet.PYBULLET_MESH_MARGIN, abs=2e-4)
    eroded, inflation = sim_pybullet.pybullet_urdf(tmp_path / "touch.urdf", str(tmp_path / "eroded"))
    assert abs(distance(eroded)) < 1e-4 and inflation == {"a": 0.0, "b": 0.0}


# ---------------------------------------------------------------- engine artefacts

def _laptop_lid(ctx):
    """A lid whose back edge turns round a hinge barrel, touching it all the way."""
    root = ctx.builder.create_link("base")
    D, W, h, rb = 0.25, 0.34, 0.018, 0.007
    ax, az = D / 2 + 0.8 * rb, h - rb
    root.add(Part("base", "test_base", [cuboid_between((-D / 2, -W / 2, 0), (D / 2, W / 2, h)),
                                        cylinder(rb, W - 0.04, translation(ax, 0, az) @ _Y)]))
    lid = ctx.builder.create_link("lid", root)
    lid.set_joint("revolute", translation(ax, 0, az), axis=(0.0, 1.0, 0.0), limits=(0.0, 2.0))
    depth, rim, t = ax + D / 2, 0.002, 0.006
    lid.add(Part("screen", "test_lid", [cuboid_between((-depth, -W / 2, rb + rim), (0.0, W / 2, rb + rim + t)),
                                         rect_ring(depth, W, rim, depth - 0.012, W - 0.012,
                                                   translation(-depth / 2, 0, rb + rim / 2))]))


def test_a_lid_sliding_round_its_hinge_barrel_is_not_jammed_by_stale_contacts(monkeypatch):
    obj = _rule("test_lid", _laptop_lid)
    only_pb = sim.SimOptions(engines=("pybullet",))
    assert sim.simulate_object(obj, only_pb).ok
    monkeypatch.setattr(sim_pybullet, "CONTACT_BREAKING", 0.02)  # pybullet's default
    r = sim.simulate_object(obj, only_pb)
    assert not r.ok and {i.joint for i in r.issues} == {"joint_lid_0"}


def _knob(ctx):
    """A tapered knob whose back face sits (1 um deep: round-off) on its panel."""
    root = ctx.builder.create_link("base")
    root.add(Part("body", "test_panel", [cuboid(0.02, 0.3, 0.3, translation(0.01, 0, 0.15))]))
    link = ctx.builder.create_link("knob", root)
    link.set_joint("continuous", translation(0, 0, 0.15), axis=(1.0, 0.0, 0.0))
    d = 0.006
    link.add(Part("knob", "test_knob", [frustum(0.04, 0.036, d, translation(-d / 2 + 1e-6, 0, 0) @ rot_y(-math.pi / 2)),
                                        cuboid(0.01, 0.008, 0.06, translation(-d - 0.005, 0, 0))]))


def test_a_knob_pressed_on_its_panel_along_its_axis_turns_in_mujoco(monkeypatch):
    obj = _rule("test_knob", _knob)
    only_mj = sim.SimOptions(engines=("mujoco",))
    assert sim.simulate_object(obj, only_mj).ok
    monkeypatch.setattr(sim_mujoco, "INVWEIGHT_FLOOR", 0.0)  # MuJoCo's own estimate: 0 for a knob
    r = sim.simulate_object(obj, only_mj)
    assert not r.ok and all(i.kind == "joint_blocked" and i.amount > 1.0 for i in r.issues)


def _stapler(ctx):
    """A magazine on an axle whose ends touch the cheeks, carrying an arm on the same axis."""
    root = ctx.builder.create_link("base")
    w, r, span = 0.024, 0.0075, 0.0151
    root.add(Part("base", "test_base", [cuboid(0.4, 0.06, 0.004, translation(-0.2, 0, -0.02)),
                                        cuboid(0.01, 0.003, 0.02, translation(0, span + 0.0015, 0.0)),
                                        cuboid(0.01, 0.003, 0.02, translation(0, -span - 0.0015, 0.0))]))
    mag = ctx.builder.create_link("magazine", root)
    mag.set_joint("revolute", translation(), axis=(0.0, 1.0, 0.0), limits=(0.0, 0.7))
    mag.add(Part("magazine", "test_mag", [cylinder(r, w, _Y), cylinder(0.0015, 2 * span, _Y),
                                          cuboid(0.4, w, 0.002, translation(-0.2 - r / 2, 0, -r + 0.001))]))
    arm = ctx.builder.create_link("arm", mag)
    arm.set_joint("revolute", translation(), axis=(0.0, 1.0, 0.0), limits=(0.0, 1.2))
    arm.add(Part("arm", "test_arm", [cuboid(0.4, 0.028, 0.002, translation(-0.2, 0, r + 0.001))]))


def test_an_arm_riding_on_a_driven_hinge_follows_it_in_pybullet(tmp_path):
    """The axle's ends press on the cheeks along the hinge axis: a contact no joint can
    move, whose zero effective mass pybullet divides by unless regularised (globalCFM)."""
    urdf = _write(_rule("test_stapler", _stapler), tmp_path)
    path, _ = sim_pybullet.pybullet_urdf(urdf, str(tmp_path))
    pb = sim_pybullet._import_pybullet()

    def drive(cfm):
        cid = pb.connect(pb.DIRECT)
        try:
            _, flags = sim_pybullet.pybullet_configure(pb, cid)
            if cfm is not None:
                pb.setPhysicsEngineParameter(globalCFM=cfm, physicsClientId=cid)
            pb.setGravity(0, 0, 0, physicsClientId=cid)
            body = pb.loadURDF(str(path), useFixedBase=True, flags=flags, physicsClientId=cid)
            for i in range(-1, 2):
                pb.changeDynamics(body, i, lateralFriction=0.0, physicsClientId=cid)
            # the magazine driven up alone, the arm held at rest on it (as the check does)
            pb.setJointMotorControlArray(body, [0, 1], pb.POSITION_CONTROL, targetPositions=[0.7, 0.0],
                                         forces=[200.0, 200.0], physicsClientId=cid)
            arm = []
            for _ in range(120):
                pb.stepSimulation(physicsClientId=cid)
                arm.append(abs(pb.getJointState(body, 1, physicsClientId=cid)[0]))
            return pb.getJointState(body, 0, physicsClientId=cid)[0], max(arm)
        finally:
            pb.disconnect(cid)

    q, lag = drive(None)
    assert q == pytest.approx(0.7, abs=0.02) and lag < 0.01
    assert drive(0.0)[1] > 0.03  # without the regularisation the arm stays behind, deep in the magazine


# ---------------------------------------------------------------- blocked joints

def test_a_joint_is_blocked_only_if_it_misses_with_the_others_at_rest_and_open():
    J = sim_common.Joint
    door, rack, stuck = J("door", "revolute", 0.0, 1.5), J("rack", "prismatic", 0.0, 0.3), J("stuck", "revolute",
                                                                                             0.0, 1.0)
    calls = []

    def run(sel, others_open):
        calls.append(([j.name for j in sel], others_open))
        out = []
        for j in sel:
            for t in j.targets()[::-1]:  # to the upper, then back to the lower target
                q = t
                if j is rack and t > 0 and not others_open:
                    q = 0.01  # against the closed door
                if j is stuck and t > 0:
                    q = 0.2
                out.append((j, t, q))
        return out

    opts = sim.SimOptions()
    blocked = sim_common.blocked(run, [door, rack, stuck], opts)
    assert [(j.name, t, q) for j, t, q in blocked] == [("stuck", 1.0, 0.2)]
    assert calls == [(["door", "rack", "stuck"], False), (["rack"], False), (["rack"], True), (["stuck"], False),
                     (["stuck"], True)]
    assert sim_common.blocked(run, [rack], opts)  # nothing to open: the rack alone is blocked
