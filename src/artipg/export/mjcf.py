"""MJCF writer: ``mobility.xml`` for MuJoCo (and MJX), beside ``mobility.urdf``.

The body tree follows the URDF's links (body frame = link frame), with

- one ``<inertial>`` per body: the link's mass, centre of mass and full inertia as the
  URDF holds them (``fullinertia``, so nothing is re-derived from geoms);
- ``hinge`` / ``slide`` joints with the URDF's axis, range, damping, and friction
  loss and armature from the moving link's effective inertia
  (:mod:`artipg.export.asset`); continuous joints are unlimited hinges;
- collision geoms, one per convex piece (class ``collision``, group 3), apart from
  visual geoms (class ``visual``, group 2, ``contype = conaffinity = 0``, massless);
  cylinders become inline 20-sided prisms (MJX slows down on faces of more than 20 vertices), since MJX collides cylinders only with
  planes, spheres and capsules;
- ``<contact><exclude>`` for every parent-child pair (touching by construction) and
  the asset's other excluded pairs (third-party links that overlap at rest);
- a free joint on the root of a free-standing object; a fixture's root has none, so
  it is welded to the world where it is placed;
- optionally (``actuators=True``) a position servo per joint, critically damped at
  :data:`artipg.export.asset.SERVO_HZ`, its control range the joint's range.

Mesh files are shared with the URDF (``meshes/`` or the folder's own). Convex
hulls are capped at :data:`MAX_HULL_VERTICES` vertices, within MJX's limits.

Materials (artipg's own objects, :attr:`artipg.export.asset.Asset.surfaces`): a
``<texture type="2d">`` per texture image (``textures/*.png``, shared with the URDF)
and a ``<material>`` per material (:func:`material_attributes`); a link's visual geom
wears its material, and a link with several materials gets one visual geom per
material, on an inline mesh of that material's faces (with normals and texture
coordinates). Third-party folders keep one grey visual geom per URDF visual.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np

from artipg.export.asset import Asset

#: Most vertices MuJoCo keeps of a collision mesh's convex hull (``maxhullvert``):
#: MJX collides convex meshes by their hull vertices, and large hulls make it slow.
MAX_HULL_VERTICES = 64

#: Simulation time step written into the file (seconds).
TIMESTEP = 0.002


#: Sides of the prisms that stand for collision cylinders.
CYLINDER_SIDES = 20


def prism_vertices(radius: float, length: float, sides: int = CYLINDER_SIDES, phase: float = 0.0) -> np.ndarray:
    """Vertices (2 * sides, 3) of a regular prism inscribed in a cylinder of ``radius``
    and ``length`` (m) along z, centred: it lies within 1.3 % of the radius of it.
    One face's outward normal points at angle ``phase`` (rad) in the xy-plane."""
    a = phase + np.pi / sides + 2.0 * np.pi * np.arange(sides) / sides
    ring = np.column_stack([radius * np.cos(a), radius * np.sin(a)])
    return np.concatenate([np.column_stack([ring, np.full(sides, z)]) for z in (-length / 2, length / 2)])


def _f(v) -> str:
    x = np.asarray(v, dtype=float).ravel().tolist()
    return " ".join(["%.9g"] * len(x)) % tuple(e + 0.0 for e in x)


def _fm(v, digits: int) -> str:
    """Mesh numbers with ``digits`` significant digits (vertices 7, texture coordinates
    5, normals 4: about what the OBJ files hold)."""
    x = np.asarray(v, dtype=float).ravel().tolist()
    return " ".join([f"%.{digits}g"] * len(x)) % tuple(e + 0.0 for e in x)


def mat_to_quat(R: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a rotation matrix (3, 3), w >= 0."""
    from scipy.spatial.transform import Rotation

    x, y, z, w = Rotation.from_matrix(np.asarray(R, dtype=float)[:3, :3]).as_quat()
    q = np.array([w, x, y, z])
    return q if w >= 0 else -q


def material_attributes(pbr: dict) -> dict[str, str]:
    """MJCF ``<material>`` attributes of a material's PBR values (:meth:`Material.to_pbr`).

    ``rgba``: the sRGB colour (MuJoCo does no colour management; white under a texture,
    which holds the colour) with the opacity as alpha; ``metallic`` and ``roughness``
    as they are (MuJoCo's PBR renderers); for its classic Phong renderer a highlight
    that grows with gloss and metalness (``specular`` = (1 - roughness + metallic) / 2,
    ``shininess`` = (1 - roughness)^2, the MTL file's ``Ns`` / 1000) and a mirror
    ``reflectance`` = metallic (1 - roughness)^2 / 2 for polished metals.
    """
    rgb = (1.0, 1.0, 1.0) if pbr["texture"] else pbr["color_srgb"]
    m, r = pbr["metallic"], pbr["roughness"]
    return {"rgba": _f([*rgb, pbr["opacity"]]), "metallic": f"{m:.4g}", "roughness": f"{r:.4g}",
            "specular": f"{min(1.0, (1.0 - r + m) / 2):.4g}", "shininess": f"{(1.0 - r) ** 2:.4g}",
            "reflectance": f"{m * (1.0 - r) ** 2 / 2:.4g}"}


def _pose(el: ET.Element, T: np.ndarray) -> None:
    if np.any(T[:3, 3] != 0):
        el.set("pos", _f(T[:3, 3]))
    if not np.allclose(T[:3, :3], np.eye(3), atol=0, rtol=0):
        el.set("quat", _f(mat_to_quat(T[:3, :3])))


def build_mjcf(asset: Asset, actuators: bool = False, mesh_prefix: str = "") -> ET.Element:
    """The MJCF tree of ``asset``.

    Parameters
    ----------
    asset : Asset
    actuators : bool
        Add a position actuator per movable joint.
    mesh_prefix : str
        Prefix of mesh file paths (relative to the MJCF file's folder), "" when the
        MJCF sits in the object folder.
    """
    root = ET.Element("mujoco", model=asset.name)
    ET.SubElement(root, "compiler", angle="radian", autolimits="true", inertiafromgeom="false",
                  balanceinertia="true", meshdir=".")
    ET.SubElement(root, "option", timestep=f"{TIMESTEP:g}")
    default = ET.SubElement(root, "default")
    vis = ET.SubElement(default, "default", {"class": "visual"})
    ET.SubElement(vis, "geom", group="2", contype="0", conaffinity="0", density="0")
    col = ET.SubElement(default, "default", {"class": "collision"})
    ET.SubElement(col, "geom", group="3", contype="1", conaffinity="1", density="0", rgba="0.5 0.5 0.5 1")
    assets = ET.SubElement(root, "asset")
    meshes: dict = {}

    def mesh_name(g, visual: bool) -> str:
        if g.kind == "cylinder":  # an inline prism (MJX has no cylinder-box or cylinder-mesh collisions)
            # a face, not an edge, down at rest: a wheel stands on it instead of rocking
            # (``lk``: the link whose geoms the loop below is writing)
            down = (poses[lk.name][:3, :3] @ g.pose[:3, :3]).T @ np.array([0.0, 0.0, -1.0])
            phase = round(float(np.arctan2(down[1], down[0])) if np.hypot(down[0], down[1]) > 1e-9 else 0.0, 6)
            key = ("cylinder", float(g.size[0]), float(g.size[1]), phase)
            if key not in meshes:
                meshes[key] = f"c{len(meshes)}"
                ET.SubElement(assets, "mesh", name=meshes[key],
                              vertex=_f(prism_vertices(key[1], key[2], CYLINDER_SIDES, phase)),
                              maxhullvert=str(MAX_HULL_VERTICES))
            return meshes[key]
        key = (g.mesh, tuple(g.scale), visual)
        if key not in meshes:
            name = meshes[key] = f"{'v' if visual else 'c'}{len(meshes)}"
            el = ET.SubElement(assets, "mesh", name=name, file=mesh_prefix + g.mesh)
            if tuple(g.scale) != (1.0, 1.0, 1.0):
                el.set("scale", _f(g.scale))
            if visual:  # visual meshes need not be closed: their mass is not used
                el.set("inertia", "shell")
            else:
                el.set("maxhullvert", str(MAX_HULL_VERTICES))
        return meshes[key]

    materials: dict = {}

    def material_name(pbr: dict) -> str:
        name = pbr["name"]
        if name not in materials:
            materials[name] = pbr
            if pbr["texture"]:
                ET.SubElement(assets, "texture", name=name, type="2d", file=mesh_prefix + pbr["texture"])
            el = ET.SubElement(assets, "material", name=name, **material_attributes(pbr))
            if pbr["texture"]:
                el.set("texture", name)
        return name

    poses = asset.link_poses()
    world = ET.SubElement(root, "worldbody")
    bodies = {}
    joint_of = {j.child: j for j in asset.joints}
    for lk in asset.links:
        j = joint_of.get(lk.name)
        parent = world if j is None else bodies[j.parent]
        body = bodies[lk.name] = ET.SubElement(parent, "body", name=lk.name)
        if j is not None:
            _pose(body, j.origin)
        I = lk.inertia
        ET.SubElement(body, "inertial", pos=_f(lk.com), mass=f"{lk.mass:.9g}",
                      fullinertia=_f([I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]))
        if j is None and not asset.fixed_base:
            ET.SubElement(body, "freejoint", name=f"{lk.name}_free")
        elif j is not None and j.type != "fixed":
            _joint(body, j)
        surf = asset.surfaces.get(lk.name)
        if surf is not None and len(lk.visuals) == 1 and len(surf.groups) == 1:  # the URDF's mesh file
            _geom(body, lk.visuals[0], f"{lk.name}_visual0", "visual", mesh_name)
            body[-1].set("material", material_name(surf.groups[0][0]))
        elif surf is not None:
            for k, (pbr, _, _) in enumerate(surf.groups):
                name = f"{lk.name}_m{k}"
                V, N, UV, F = surf.group(k)
                # MuJoCo's images run top row first: v down, as its OBJ reader turns them
                ET.SubElement(assets, "mesh", name=name, vertex=_fm(V, 7), normal=_fm(N, 4),
                              texcoord=_fm(np.column_stack([UV[:, 0], 1.0 - UV[:, 1]]), 5),
                              face=" ".join(map(str, F.ravel().tolist())), inertia="shell")
                ET.SubElement(body, "geom", {"name": f"{lk.name}_visual{k}", "class": "visual", "type": "mesh",
                                             "mesh": name, "material": material_name(pbr)})
        else:
            for k, g in enumerate(lk.visuals):
                _geom(body, g, f"{lk.name}_visual{k}", "visual", mesh_name)
        for k, g in enumerate(lk.collisions):
            _geom(body, g, f"{lk.name}_c{k}", "collision", mesh_name)
    pairs = [(j.parent, j.child) for j in asset.joints] + [tuple(p) for p in asset.excludes]
    if pairs:
        contact = ET.SubElement(root, "contact")
        for a, b in pairs:
            ET.SubElement(contact, "exclude", body1=a, body2=b)
    if actuators:
        act = ET.SubElement(root, "actuator")
        for j in asset.joints:
            if j.type == "fixed":
                continue
            kp, kv = j.servo_gains()
            lo, hi = (-math.pi, math.pi) if j.type == "continuous" else j.limits
            ET.SubElement(act, "position", name=f"{j.name}_servo", joint=j.name, kp=f"{kp:.6g}", kv=f"{kv:.6g}",
                          ctrlrange=_f([lo, hi]))
    if not len(assets):
        root.remove(assets)
    ET.indent(root)
    return root


def _joint(body: ET.Element, j) -> None:
    el = ET.SubElement(body, "joint", name=j.name, type="slide" if j.type == "prismatic" else "hinge",
                       axis=_f(j.axis), damping=f"{j.damping:.6g}", frictionloss=f"{j.friction:.6g}",
                       armature=f"{j.armature:.6g}")
    if j.type == "continuous":
        el.set("limited", "false")
    else:
        el.set("range", _f(j.limits))


def _geom(body: ET.Element, g, name: str, cls: str, mesh_name) -> None:
    el = ET.SubElement(body, "geom", {"name": name, "class": cls})
    if g.kind == "box":
        el.set("type", "box")
        el.set("size", _f(np.asarray(g.size) / 2))
    elif g.kind == "cylinder":
        el.set("type", "mesh")
        el.set("mesh", mesh_name(g, False))
    elif g.kind == "sphere":
        el.set("type", "sphere")
        el.set("size", _f(g.size[:1]))
    else:
        el.set("type", "mesh")
        el.set("mesh", mesh_name(g, cls == "visual"))
    _pose(el, g.pose)


def mjcf_text(root: ET.Element) -> str:
    """The text of an MJCF tree."""
    return ET.tostring(root, encoding="unicode") + "\n"
