"""USD writer: ``mobility.usd``, a UsdPhysics articulation (Isaac Sim, Isaac Lab).

Layout (``metersPerUnit`` 1, Z up, the object's prim the default prim)::

    /<object>                 Xform, PhysicsArticulationRootAPI
      /<link>                 Xform at the link's rest pose, RigidBodyAPI, MassAPI
        /visuals/mesh         Mesh, vertex colours per semantic part, no collision
        /collisions/c<k>      Cube / Cylinder / Sphere, or Mesh with MeshCollisionAPI
                              convexHull: one per convex piece, purpose "guide"
      /joints/<joint>         RevoluteJoint / PrismaticJoint / FixedJoint
      /joints/fixed_to_world  FixedJoint to the world (fixtures only)

Joint frames: ``localPos0``/``localRot0`` place the joint in the parent link (the
URDF origin turned so that the joint's X axis is the motion axis) and
``localPos1``/``localRot1`` in the child link, so any axis direction works with
``physics:axis = "X"``. Limits are degrees for revolute and metres for prismatic
joints; revolute joints get an angular drive, prismatic ones a linear drive, damped
by the joint's damping (per degree for angular drives) and, with ``actuators``,
stiff as the MJCF's position servos. Masses carry mass, centre of mass and the
inertia's principal moments and axes (``diagonalInertia``, ``principalAxes``).
"""

from __future__ import annotations

import math
import os
import tempfile

import numpy as np

from artipg.export.asset import Asset, geom_arrays

_DEG = 180.0 / math.pi


def _mat(T: np.ndarray):
    from pxr import Gf

    return Gf.Matrix4d(np.asarray(T, dtype=float).T.tolist())  # USD multiplies row vectors


def _quat(R: np.ndarray):
    from pxr import Gf

    from artipg.export.mjcf import mat_to_quat

    w, x, y, z = mat_to_quat(R).tolist()
    return Gf.Quatf(w, Gf.Vec3f(x, y, z))


def axis_frame(axis) -> np.ndarray:
    """A rotation (3, 3) whose first column is the unit ``axis`` (3,)."""
    x = np.asarray(axis, dtype=float)
    x = x / np.linalg.norm(x)
    helper = np.eye(3)[int(np.argmin(np.abs(x)))]
    y = np.cross(x, helper)
    y /= np.linalg.norm(y)
    return np.column_stack([x, y, np.cross(x, y)])


def principal_inertia(I: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Principal moments (3,) and axes (3, 3), a rotation with ``I = R diag R^T``."""
    w, R = np.linalg.eigh((np.asarray(I, dtype=float) + np.asarray(I, dtype=float).T) / 2)
    if np.linalg.det(R) < 0:
        R[:, 2] = -R[:, 2]
    return w, R


def _colors(asset: Asset, link, n: int) -> np.ndarray:
    """Per-vertex RGB (n, 3) of a link's visual mesh from its semantic labels."""
    from artipg.export.glb import label_color

    runs = asset.vertex_labels.get(link.name)
    if runs and sum(c for _, c in runs) == n:
        return np.concatenate([np.tile(label_color(lab), (c, 1)) for lab, c in runs])
    return np.tile(label_color(link.label), (n, 1))


def build_stage(asset: Asset, actuators: bool = False):
    """A ``pxr.Usd.Stage`` (in memory) holding ``asset`` as a UsdPhysics articulation."""
    from pxr import Usd, UsdGeom, UsdPhysics, Vt

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    root = UsdGeom.Xform.Define(stage, "/" + _name(asset.name)).GetPrim()
    stage.SetDefaultPrim(root)
    UsdPhysics.ArticulationRootAPI.Apply(root)
    base = root.GetPath()
    poses = asset.link_poses()
    paths = {}
    for lk in asset.links:
        path = paths[lk.name] = base.AppendChild(_name(lk.name))
        x = UsdGeom.Xform.Define(stage, path)
        x.AddTransformOp().Set(_mat(poses[lk.name]))
        prim = x.GetPrim()
        UsdPhysics.RigidBodyAPI.Apply(prim)
        mass = UsdPhysics.MassAPI.Apply(prim)
        mass.CreateMassAttr(float(lk.mass))
        mass.CreateCenterOfMassAttr().Set(tuple(float(c) for c in lk.com))
        moments, R = principal_inertia(lk.inertia)
        mass.CreateDiagonalInertiaAttr().Set(tuple(float(v) for v in moments))
        mass.CreatePrincipalAxesAttr().Set(_quat(R))
        vm = asset.visual_mesh(lk)
        if vm is not None:
            UsdGeom.Xform.Define(stage, path.AppendChild("visuals"))
            mesh = _mesh(stage, path.AppendChild("visuals").AppendChild("mesh"), *vm)
            col = UsdGeom.Gprim(mesh.GetPrim()).CreateDisplayColorPrimvar(UsdGeom.Tokens.vertex)
            col.Set(Vt.Vec3fArray.FromNumpy(_colors(asset, lk, len(vm[0])).astype(np.float32)))
        if lk.collisions:
            cpath = path.AppendChild("collisions")
            UsdGeom.Imageable(UsdGeom.Xform.Define(stage, cpath)).CreatePurposeAttr(UsdGeom.Tokens.guide)
            for k, g in enumerate(lk.collisions):
                _collider(stage, asset, cpath.AppendChild(f"c{k}"), g)
    UsdGeom.Scope.Define(stage, base.AppendChild("joints"))
    jbase = base.AppendChild("joints")
    for j in asset.joints:
        _joint(stage, jbase.AppendChild(_name(j.name)), j, paths, actuators)
    for a, b in asset.excludes:  # PhysX already skips parent-child pairs of an articulation
        UsdPhysics.FilteredPairsAPI.Apply(stage.GetPrimAtPath(paths[a])).CreateFilteredPairsRel().AddTarget(paths[b])
    if asset.fixed_base:
        fj = UsdPhysics.FixedJoint.Define(stage, jbase.AppendChild("fixed_to_world"))
        fj.CreateBody1Rel().SetTargets([paths[asset.links[0].name]])
    return stage


def _name(name: str) -> str:
    from pxr import Tf

    return Tf.MakeValidIdentifier(name)


def _mesh(stage, path, V, F):
    from pxr import UsdGeom, Vt

    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(V, dtype=np.float32)))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(F), 3, dtype=np.int32)))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(np.asarray(F, dtype=np.int32).ravel()))
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    return mesh


def _collider(stage, asset, path, g) -> None:
    from pxr import UsdGeom, UsdPhysics

    T = np.asarray(g.pose, dtype=float)
    if g.kind == "box":
        gp = UsdGeom.Cube.Define(stage, path)
        gp.CreateSizeAttr(1.0)
        T = T @ np.diag([*g.size, 1.0])
    elif g.kind == "cylinder":
        gp = UsdGeom.Cylinder.Define(stage, path)
        gp.CreateRadiusAttr(float(g.size[0]))
        gp.CreateHeightAttr(float(g.size[1]))
        gp.CreateAxisAttr(UsdGeom.Tokens.z)
    elif g.kind == "sphere":
        gp = UsdGeom.Sphere.Define(stage, path)
        gp.CreateRadiusAttr(float(g.size[0]))
    else:
        gp = _mesh(stage, path, *geom_arrays(asset, g))
        UsdPhysics.MeshCollisionAPI.Apply(gp.GetPrim()).CreateApproximationAttr(UsdPhysics.Tokens.convexHull)
    gp.AddTransformOp().Set(_mat(T))
    UsdPhysics.CollisionAPI.Apply(gp.GetPrim())


def _joint(stage, path, j, paths, actuators: bool) -> None:
    from pxr import Gf, UsdPhysics

    if j.type == "fixed":
        joint = UsdPhysics.FixedJoint.Define(stage, path)
        A = np.eye(3)
    elif j.type == "prismatic":
        joint = UsdPhysics.PrismaticJoint.Define(stage, path)
        A = axis_frame(j.axis)
    else:
        joint = UsdPhysics.RevoluteJoint.Define(stage, path)
        A = axis_frame(j.axis)
    joint.CreateBody0Rel().SetTargets([paths[j.parent]])
    joint.CreateBody1Rel().SetTargets([paths[j.child]])
    joint.CreateLocalPos0Attr().Set(Gf.Vec3f(*[float(v) for v in j.origin[:3, 3]]))
    joint.CreateLocalRot0Attr().Set(_quat(j.origin[:3, :3] @ A))
    joint.CreateLocalPos1Attr().Set(Gf.Vec3f(0.0, 0.0, 0.0))
    joint.CreateLocalRot1Attr().Set(_quat(A))
    if j.type == "fixed":
        return
    joint.CreateAxisAttr(UsdPhysics.Tokens.x)
    unit = 1.0 if j.type == "prismatic" else _DEG
    if j.type != "continuous":
        joint.CreateLowerLimitAttr(float(j.limits[0] * unit))
        joint.CreateUpperLimitAttr(float(j.limits[1] * unit))
    drive = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "linear" if j.type == "prismatic" else "angular")
    kp, kv = j.servo_gains() if actuators else (0.0, 0.0)
    drive.CreateTypeAttr(UsdPhysics.Tokens.force)
    drive.CreateTargetPositionAttr(0.0)
    drive.CreateStiffnessAttr(float(kp / unit))  # angular drives: per degree
    drive.CreateDampingAttr(float((j.damping + kv) / unit))


def usd_bytes(asset: Asset, actuators: bool = False) -> bytes:
    """The bytes of ``mobility.usd`` (binary crate) of ``asset``."""
    stage = build_stage(asset, actuators)
    fd, path = tempfile.mkstemp(suffix=".usd", prefix="artipg-")
    os.close(fd)
    try:
        stage.GetRootLayer().Export(path)
        with open(path, "rb") as fh:
            return fh.read()
    finally:
        os.unlink(path)
