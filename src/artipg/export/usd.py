"""USD writer: ``mobility.usd``, a UsdPhysics articulation (Isaac Sim, Isaac Lab).

Layout (``metersPerUnit`` 1, Z up, the object's prim the default prim)::

    /<object>                 Xform, PhysicsArticulationRootAPI
      /<link>                 Xform at the link's rest pose, RigidBodyAPI, MassAPI
        /visuals/mesh         Mesh, vertex colours per semantic part, no collision
        /collisions/c<k>      Cube / Cylinder / Sphere, or Mesh with MeshCollisionAPI
                              convexHull: one per convex piece, purpose "guide"
      /joints/<joint>         RevoluteJoint / PrismaticJoint / FixedJoint
      /joints/fixed_to_world  FixedJoint to the world (fixtures only)
      /Looks/<material>       Material with a UsdPreviewSurface (artipg's own objects)

Materials (:attr:`artipg.export.asset.Asset.surfaces`): a visual mesh carries
vertex normals and ``st`` texture coordinates, is bound to the material covering
most of it and, with several materials, holds one ``materialBind`` GeomSubset per
material bound to its own; each material is a ``UsdPreviewSurface`` (diffuse colour,
or a ``UsdUVTexture`` reading ``./textures/<name>.png`` through the ``st`` primvar;
metallic, roughness, opacity) (:func:`define_material`). Third-party folders keep
vertex colours per semantic part only.

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
    looks: dict = {}
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
        surf = asset.surfaces.get(lk.name)
        vm = None if surf is not None else asset.visual_mesh(lk)
        if surf is not None:
            UsdGeom.Xform.Define(stage, path.AppendChild("visuals"))
            mesh = _mesh(stage, path.AppendChild("visuals").AppendChild("mesh"), surf.vertices, surf.faces)
            _surface(stage, mesh, surf, looks, base)
            col = UsdGeom.Gprim(mesh.GetPrim()).CreateDisplayColorPrimvar(UsdGeom.Tokens.vertex)
            col.Set(Vt.Vec3fArray.FromNumpy(_colors(asset, lk, len(surf.vertices)).astype(np.float32)))
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


def _surface(stage, mesh, surf, looks: dict, base) -> None:
    """Normals, ``st`` and material bindings of a visual ``mesh`` from its :class:`Surface`."""
    from pxr import Sdf, UsdGeom, UsdShade, Vt

    mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(np.asarray(surf.normals, dtype=np.float32)))
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    st = UsdGeom.PrimvarsAPI(mesh.GetPrim()).CreatePrimvar("st", Sdf.ValueTypeNames.TexCoord2fArray,
                                                          UsdGeom.Tokens.vertex)
    st.Set(Vt.Vec2fArray.FromNumpy(np.asarray(surf.uvs, dtype=np.float32)))

    def material(pbr):
        if not looks:
            UsdGeom.Scope.Define(stage, base.AppendChild("Looks"))
        if pbr["name"] not in looks:
            looks[pbr["name"]] = define_material(stage, base.AppendChild("Looks").AppendChild(_name(pbr["name"])), pbr)
        return looks[pbr["name"]]

    UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material(surf.groups[surf.main_group()][0]))
    if len(surf.groups) > 1:
        for pbr, f0, f1 in surf.groups:
            subset = UsdGeom.Subset.CreateGeomSubset(
                mesh, _name(pbr["name"]), UsdGeom.Tokens.face, Vt.IntArray.FromNumpy(np.arange(f0, f1, dtype=np.int32)),
                UsdShade.Tokens.materialBind, UsdGeom.Tokens.nonOverlapping)
            UsdShade.MaterialBindingAPI.Apply(subset.GetPrim()).Bind(material(pbr))
        UsdShade.MaterialBindingAPI(mesh.GetPrim()).SetMaterialBindSubsetsFamilyType(UsdGeom.Tokens.partition)


def define_material(stage, path, pbr: dict):
    """A ``UsdShade.Material`` at ``path`` with a ``UsdPreviewSurface`` of a material's
    PBR values (:meth:`artipg.appearance.Material.to_pbr`): linear ``diffuseColor``, or
    the texture image (sRGB, repeating, read at the ``st`` primvar); ``metallic``,
    ``roughness`` and ``opacity`` (glass is see-through)."""
    from pxr import Gf, Sdf, UsdShade

    mat = UsdShade.Material.Define(stage, path)
    shader = UsdShade.Shader.Define(stage, path.AppendChild("PreviewSurface"))
    shader.CreateIdAttr("UsdPreviewSurface")
    shader.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(pbr["metallic"])
    shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(pbr["roughness"])
    shader.CreateInput("opacity", Sdf.ValueTypeNames.Float).Set(pbr["opacity"])
    diffuse = shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f)
    if pbr["texture"]:
        reader = UsdShade.Shader.Define(stage, path.AppendChild("stReader"))
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", Sdf.ValueTypeNames.String).Set("st")
        tex = UsdShade.Shader.Define(stage, path.AppendChild("diffuseTexture"))
        tex.CreateIdAttr("UsdUVTexture")
        tex.CreateInput("file", Sdf.ValueTypeNames.Asset).Set(Sdf.AssetPath("./" + pbr["texture"]))
        tex.CreateInput("sourceColorSpace", Sdf.ValueTypeNames.Token).Set("sRGB")
        tex.CreateInput("wrapS", Sdf.ValueTypeNames.Token).Set("repeat")
        tex.CreateInput("wrapT", Sdf.ValueTypeNames.Token).Set("repeat")
        tex.CreateInput("st", Sdf.ValueTypeNames.Float2).ConnectToSource(
            reader.CreateOutput("result", Sdf.ValueTypeNames.Float2))
        diffuse.ConnectToSource(tex.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
    else:
        diffuse.Set(Gf.Vec3f(*pbr["baseColorFactor"][:3]))
    mat.CreateSurfaceOutput().ConnectToSource(shader.CreateOutput("surface", Sdf.ValueTypeNames.Token))
    return mat


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
