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
ALL = ("urdf", "mjcf", "usd", "glb")
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


def _compare(obj, links, joints, where: str, tol: float = 1e-6):
    """Assert read-back links and joints equal the model's (inertials to 1e-6 relative;
    ``tol`` (m, rad) for origins, axes and limits: USD stores joint frames in float32)."""
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
        assert np.abs(np.asarray(gT) - T).max() <= tol, (where, name, gT, T)
        if t != "fixed":
            assert np.abs(np.asarray(gax) - ax).max() <= tol, (where, name)
        if t in ("revolute", "prismatic"):
            assert np.abs(np.asarray(glim) - lim).max() <= tol, (where, name, glim, lim)


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


def _usd_matrix(m) -> np.ndarray:
    return np.array(m, dtype=float).T


def _frame(pos, rot) -> np.ndarray:
    from pxr import Gf

    T = np.eye(4)
    T[:3, :3] = np.array(Gf.Matrix3d(Gf.Quatd(rot.GetReal(), Gf.Vec3d(rot.GetImaginary()))), dtype=float).T
    T[:3, 3] = np.array(pos, dtype=float)
    return T


def read_usd(path: Path):
    from pxr import Gf, Usd, UsdPhysics

    stage = Usd.Stage.Open(str(path))
    links, joints = {}, {}
    for prim in stage.Traverse():
        if prim.HasAPI(UsdPhysics.RigidBodyAPI):
            mass = UsdPhysics.MassAPI(prim)
            q = mass.GetPrincipalAxesAttr().Get()
            R = np.array(Gf.Matrix3d(Gf.Quatd(q.GetReal(), Gf.Vec3d(q.GetImaginary()))), dtype=float).T
            I = R @ np.diag(np.array(mass.GetDiagonalInertiaAttr().Get(), dtype=float)) @ R.T
            links[prim.GetName()] = (mass.GetMassAttr().Get(), np.array(mass.GetCenterOfMassAttr().Get()), I)
    for prim in stage.Traverse():
        j = UsdPhysics.Joint(prim)
        if not j or not j.GetBody0Rel().GetTargets():
            continue
        parent, child = (r.GetTargets()[0].name for r in (j.GetBody0Rel(), j.GetBody1Rel()))
        T0 = _frame(j.GetLocalPos0Attr().Get(), j.GetLocalRot0Attr().Get())
        T1 = _frame(j.GetLocalPos1Attr().Get(), j.GetLocalRot1Attr().Get())
        origin = T0 @ np.linalg.inv(T1)
        kind, axis, lim = "fixed", None, None
        for cls, name, unit in ((UsdPhysics.RevoluteJoint, "revolute", np.pi / 180), (UsdPhysics.PrismaticJoint,
                                                                                     "prismatic", 1.0)):
            if prim.IsA(cls):
                jj = cls(prim)
                axis = T1[:3, :3] @ np.eye(3)["XYZ".index(jj.GetAxisAttr().Get())]
                lo, hi = jj.GetLowerLimitAttr().Get(), jj.GetUpperLimitAttr().Get()
                limited = jj.GetLowerLimitAttr().HasAuthoredValue()
                kind = name if limited or name == "prismatic" else "continuous"
                lim = (lo * unit, hi * unit) if limited else None
        joints[prim.GetName()] = (kind, parent, child, origin, axis, lim)
    return links, joints


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
    from artipg.export.annotation import category_fixed_base

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


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("category", CATEGORIES)
def test_usd_round_trips_the_model(out, category, seed):
    """Inertials to 1e-6 relative; joint frames, axes and limits within 1e-6 m / rad
    (float32 attributes: about 1e-7 relative)."""
    _compare(model(category, seed), *read_usd(folder(out, category, seed) / "mobility.usd"), "usd")


def usd_errors(path: Path) -> list[str]:
    """Messages of USD's own validators (UsdPhysics, UsdGeom, stage metadata) on a file."""
    from pxr import Usd, UsdValidation

    ctx = UsdValidation.ValidationContext(UsdValidation.ValidationRegistry().GetOrLoadAllValidators())
    return [e.GetMessage() for e in ctx.Validate(Usd.Stage.Open(str(path)))]


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("category", CATEGORIES)
def test_usd_opens_and_its_physics_schema_is_valid(out, category, seed, capfd):
    from pxr import Usd, UsdGeom, UsdPhysics

    path = folder(out, category, seed) / "mobility.usd"
    stage = Usd.Stage.Open(str(path))
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0 and UsdGeom.GetStageUpAxis(stage) == "Z"
    root = stage.GetDefaultPrim()
    assert root.HasAPI(UsdPhysics.ArticulationRootAPI)
    assert usd_errors(path) == []
    obj = model(category, seed)
    fixed = [p for p in stage.Traverse() if p.IsA(UsdPhysics.FixedJoint) and p.GetName() == "fixed_to_world"]
    from artipg.export.annotation import category_fixed_base

    assert len(fixed) == int(category_fixed_base(category))
    n_col = 0
    for prim in stage.Traverse():
        if prim.IsA(UsdPhysics.RevoluteJoint):
            assert prim.HasAPI(UsdPhysics.DriveAPI, "angular") and not prim.HasAPI(UsdPhysics.DriveAPI, "linear")
        if prim.IsA(UsdPhysics.PrismaticJoint):
            assert prim.HasAPI(UsdPhysics.DriveAPI, "linear") and not prim.HasAPI(UsdPhysics.DriveAPI, "angular")
        if prim.HasAPI(UsdPhysics.CollisionAPI):
            n_col += 1
            assert "collisions" in str(prim.GetPath()) and UsdGeom.Imageable(prim).ComputePurpose() == "guide"
            if prim.IsA(UsdGeom.Mesh):
                assert UsdPhysics.MeshCollisionAPI(prim).GetApproximationAttr().Get() == "convexHull"
        if prim.IsA(UsdGeom.Mesh) and "visuals" in str(prim.GetPath()):
            assert not prim.HasAPI(UsdPhysics.CollisionAPI)
    from artipg.export.meshes import link_collision_pieces

    assert n_col == sum(len(link_collision_pieces(lk)) for lk in obj.links)
    captured = capfd.readouterr()
    assert "Warning" not in captured.err and "Error" not in captured.err


def test_usd_validators_catch_a_broken_joint(out, tmp_path):
    """Planted fault: a joint whose child body is missing is reported."""
    from pxr import Sdf, Usd, UsdPhysics

    stage = Usd.Stage.Open(str(folder(out, "microwave", 0) / "mobility.usd"))
    joint = next(p for p in stage.Traverse() if p.IsA(UsdPhysics.RevoluteJoint))
    UsdPhysics.Joint(joint).GetBody1Rel().SetTargets([Sdf.Path("/nowhere")])
    bad = tmp_path / "bad.usda"
    stage.GetRootLayer().Export(str(bad))
    assert usd_errors(bad)


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("category", CATEGORIES)
def test_glb_loads_as_one_node_per_link(out, category, seed):
    import trimesh

    obj = model(category, seed)
    scene = trimesh.load(folder(out, category, seed) / "mobility.glb")
    assert isinstance(scene, trimesh.Scene)
    nodes = set(scene.graph.nodes) - {scene.graph.base_frame}
    links = {lk.name for lk in obj.links}
    assert links <= nodes
    edges = scene.graph.transforms.edge_data
    parents = scene.graph.transforms.parents
    for n in nodes - links:  # a link's further materials: child nodes at its frame
        assert parents[n] in links and n.startswith(parents[n] + "_visual")
        assert np.abs(edges[(parents[n], n)].get("matrix", np.eye(4)) - np.eye(4)).max() < 1e-12
    for j in obj.joints:
        assert parents[j.child] == j.parent
        data = edges[(j.parent, j.child)]
        assert np.abs(data["matrix"] - j.origin).max() < 1e-6
        extras = data["metadata"]["joint"]
        assert (extras["type"], extras["parent"], extras["child"]) == (j.type, j.parent, j.child)
        assert np.abs(np.array(extras["axis"]) - j.axis).max() < 1e-9
    # the rest pose: node world transforms are the model's link poses
    poses = obj.link_poses()
    for i, lk in enumerate(obj.links):
        assert np.abs(scene.graph.get(lk.name)[0] - poses[i]).max() < 1e-6
    # PBR materials with texture coordinates (tests/test_material_formats.py checks their values)
    for name, geom in scene.geometry.items():
        assert geom.visual.kind == "texture"


def test_formats_are_deterministic(tmp_path):
    obj = artipg.generate("microwave", 3)
    a = export_object(obj, tmp_path / "a", n_points=0, formats=ALL)
    b = export_object(artipg.generate("microwave", 3), tmp_path / "b", n_points=0, formats=ALL)
    for name in ("mobility.xml", "mobility.usd", "mobility.glb"):
        assert (a / name).read_bytes() == (b / name).read_bytes(), name


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
    text = (src / "mobility.xml").read_text().replace('meshdir="."', f'meshdir="{src}" texturedir="{src}"')
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


# ------------------------------------------------------------------ convert

def _cli(*args):
    return subprocess.run([sys.executable, "-m", "artipg.cli", *map(str, args)], capture_output=True, text=True)


def test_convert_of_an_artipg_folder_writes_what_generate_writes(out, tmp_path):
    """The URDF is the one source: converting a URDF-only folder gives the MJCF that
    generate writes, and a USD with the same physics (its colours are per link then,
    not per part)."""
    obj = artipg.generate("storage_furniture", 1)
    src = folder(out, "storage_furniture", 1)
    dst = export_object(obj, tmp_path / "o", n_points=0, formats=("urdf",))
    r = _cli("convert", dst, "--to", "mjcf,usd,glb", "--actuators")
    assert r.returncode == 0, r.stderr
    assert (dst / "mobility.xml").read_bytes() == (src / "mobility.xml").read_bytes()
    _compare(obj, *read_usd(dst / "mobility.usd"), "converted usd")
    assert not (dst / "collision").exists()  # the exported pieces are convex already


def test_convert_decomposes_non_convex_meshes_and_caches_them(tmp_path):
    """A third-party folder: one link with a non-convex (L-shaped, open-topped box)
    mesh and no inertial, one hinged lid; CoACD pieces are written once and reused."""
    pytest.importorskip("coacd")
    import trimesh

    from artipg.export.meshes import obj_text

    f = tmp_path / "thing"
    (f / "m").mkdir(parents=True)
    walls = [trimesh.creation.box(extents=e, transform=trimesh.transformations.translation_matrix(t))
             for e, t in (((0.3, 0.3, 0.02), (0, 0, 0.01)), ((0.02, 0.3, 0.2), (-0.14, 0, 0.1)),
                          ((0.02, 0.3, 0.2), (0.14, 0, 0.1)), ((0.3, 0.02, 0.2), (0, -0.14, 0.1)),
                          ((0.3, 0.02, 0.2), (0, 0.14, 0.1)))]
    body = trimesh.boolean.union(walls) if trimesh.boolean.engines_available else trimesh.util.concatenate(walls)
    (f / "m" / "body.obj").write_text(obj_text(body.vertices, body.faces))
    lid = trimesh.creation.box(extents=(0.3, 0.3, 0.02))
    (f / "m" / "lid.obj").write_text(obj_text(lid.vertices, lid.faces))
    (f / "mobility.urdf").write_text("""<?xml version="1.0"?>
<robot name="thing">
 <link name="base"><visual><geometry><mesh filename="m/body.obj"/></geometry></visual>
  <collision><geometry><mesh filename="m/body.obj"/></geometry></collision></link>
 <link name="lid"><visual><geometry><mesh filename="m/lid.obj"/></geometry></visual>
  <collision><geometry><mesh filename="m/lid.obj"/></geometry></collision></link>
 <joint name="hinge" type="revolute"><parent link="base"/><child link="lid"/>
  <origin xyz="0.15 0 0.21"/><axis xyz="0 1 0"/><limit lower="0" upper="1.5" effort="1" velocity="1"/></joint>
</robot>
""")
    r = _cli("convert", f, "--to", "mjcf,usd", "--actuators", "--check")
    assert r.returncode == 0, r.stderr
    pieces = sorted((f / "collision").glob("base_c*.obj"))
    assert len(pieces) >= 2 and not list((f / "collision").glob("lid_c*"))
    stamp = [p.stat().st_mtime_ns for p in pieces]
    r2 = _cli("convert", f, "--to", "mjcf")
    assert r2.returncode == 0
    assert [p.stat().st_mtime_ns for p in pieces] == stamp  # cached
    m = mujoco.MjModel.from_xml_path(str(f / "mobility.xml"))
    assert m.body_mass[1] > 0.1 and m.ngeom >= 4
    assert "1/1 joints reach both limits" in r.stdout


def test_convert_bad_input_is_one_line_and_writes_nothing(out, tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    r = _cli("convert", empty)
    assert r.returncode != 0 and len(r.stderr.strip().splitlines()) == 1 and "no URDF" in r.stderr
    broken = export_object(artipg.generate("faucet", 0), tmp_path / "broken", n_points=0, formats=("urdf",))
    good = export_object(artipg.generate("faucet", 1), tmp_path / "good", n_points=0, formats=("urdf",))
    next((broken / "meshes").glob("*.obj")).unlink()
    before = {p.name for p in tmp_path.rglob("*")}
    r = _cli("convert", good, broken, "--to", "mjcf,usd")
    assert r.returncode != 0 and len(r.stderr.strip().splitlines()) == 1 and "missing" in r.stderr
    assert {p.name for p in tmp_path.rglob("*")} == before  # not even the good folder
    r = _cli("convert", good, "--to", "mjcf,step")
    assert r.returncode != 0 and len(r.stderr.strip().splitlines()) == 1 and "step" in r.stderr
    assert {p.name for p in tmp_path.rglob("*")} == before


@pytest.mark.parametrize("category", SIM_CATEGORIES)
def test_mjx_accepts_the_model(out, category):
    """MJX takes the model: every pair of collision geom types has an MJX collision
    function (cylinders are prisms). Skipped where jax is not installed. MJX's
    performance warning on hull faces of more than 20 vertices is allowed: revolved
    primitives' hulls have 24 sections."""
    pytest.importorskip("jax")
    mjx = pytest.importorskip("mujoco.mjx")
    import warnings

    m = mujoco.MjModel.from_xml_path(str(folder(out, category, 0) / "mobility.xml"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", message=".*coplanar face with more than 20 vertices")
        mx = mjx.put_model(m)
    assert mx.nbody == m.nbody


@pytest.mark.parametrize("category", CATEGORIES)
def test_urdf_loads_in_sapien_on_cpu(out, category, tmp_path):
    """SAPIEN (where it installs; physics only, no rendering device needed) builds the
    articulation with the model's links, degrees of freedom and masses."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its import warns when the system has no Vulkan
        sapien = pytest.importorskip("sapien")
    import shutil
    import xml.etree.ElementTree as ET

    obj = model(category, 0)
    # SAPIEN turns every <material> into a render material, which needs a rendering
    # device: load a copy without them (physics only)
    tree = ET.parse(folder(out, category, 0) / "mobility.urdf")
    for parent in tree.getroot().iter():
        for m in parent.findall("material"):
            parent.remove(m)
    copy = shutil.copytree(folder(out, category, 0), tmp_path / "obj")
    urdf = copy / "mobility_physics_only.urdf"
    tree.write(urdf)
    scene = sapien.Scene([sapien.physx.PhysxCpuSystem()])
    builder = scene.create_urdf_loader().load_file_as_articulation_builder(str(urdf))
    for lb in builder.link_builders:
        lb.visual_records = []  # rendering needs a GPU
    art = builder.build()
    assert art.dof == obj.dof
    mass = {lk.name: lk.mass for lk in art.get_links()}
    assert set(mass) == {lk.name for lk in obj.links}
    for lk in obj.links:
        m = link_inertial(lk, 24, obj.materials)[0]
        assert abs(mass[lk.name] - m) <= 1e-5 * m  # float32 in PhysX
