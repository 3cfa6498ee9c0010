"""URDF writer (xml.etree) for an :class:`ArticulatedObject`.

Links get one visual mesh, one collision element per convex piece (native box,
cylinder and sphere where possible) and an inertial from the geometry. A ``<mujoco>``
block lets MuJoCo import visuals and keep links separate.

Visual meshes are OBJ files with normals, UVs and one ``usemtl`` group per material,
sharing ``meshes/materials.mtl``; texture images go to ``textures/``. A URDF visual
holds a single ``<material>``: each link's visual names the material covering most of
its surface (its colour, and its texture file); the OBJ groups carry all of them.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np

from artipg.export.asset import effective_inertia
from artipg.export.meshes import (link_collision_entries, link_inertial, link_visual_surface, obj_surface_text,
                                  obj_text)
from artipg.geometry.transforms import matrix_to_rpy


def _fmt(v) -> str:
    """Numbers of ``v`` with 9 significant digits, space separated (-0 written as 0)."""
    x = v.tolist() if isinstance(v, np.ndarray) else [float(e) for e in v]
    return " ".join(["%.9g"] * len(x)) % tuple([float(e) + 0.0 for e in x])  # + 0.0 turns -0.0 into 0.0


def _origin(parent: ET.Element, T: np.ndarray) -> None:
    rpy = matrix_to_rpy(T)
    ET.SubElement(parent, "origin", xyz=_fmt(T[:3, 3]), rpy=_fmt(rpy))


#: Time constant (s) with which a freely coasting joint slows down: joint damping is
#: the moving link's inertia about (mass along) the joint axis divided by it, so a
#: knob and a wardrobe door feel alike instead of one fixed value for both.
DAMPING_TIME = 0.25


def joint_damping(jtype: str, axis: np.ndarray, mass: float, com: np.ndarray, inertia: np.ndarray) -> float:
    """Viscous damping of a joint (N*s/m or N*m*s/rad) from its child link's mass
    properties in the joint frame (mass kg, centre of mass (3,), inertia (3, 3) about it)."""
    return max(effective_inertia(jtype, axis, mass, com, inertia) / DAMPING_TIME, 1e-6)


def _material(parent: ET.Element, material) -> None:
    """A URDF ``<material>`` of an :class:`artipg.appearance.Material` inside ``parent``."""
    el = ET.SubElement(parent, "material", name=material.name)
    ET.SubElement(el, "color", rgba=_fmt(material.rgba))
    if material.texture_file:
        ET.SubElement(el, "texture", filename=material.texture_file)


def visual_files(obj, surfaces: dict) -> dict[str, str | bytes]:
    """The MTL file and texture images {relative path: text or PNG bytes} of the
    materials used in ``surfaces`` ({link name: :func:`link_visual_surface` result})."""
    from artipg.appearance import texture_png

    used = {}
    for surf in surfaces.values():
        for m, *_ in surf[4]:
            used.setdefault(m.name, m)
    files: dict[str, str | bytes] = {"meshes/materials.mtl": "".join(m.mtl_text() + "\n" for m in used.values())}
    for m in used.values():
        if m.texture_file:
            files[m.texture_file] = texture_png(m)
    return files


def build_urdf(obj, sections: int = 24, visuals: bool = True) -> tuple[ET.Element, dict[str, str | bytes]]:
    """URDF tree and its files {relative path: OBJ or MTL text, or PNG bytes} for ``obj``.

    ``visuals=False`` leaves out the visual meshes, materials and textures
    (simulation-only URDFs, faster; every file is text then).
    """
    files: dict[str, str | bytes] = {}
    surfaces = {}
    if visuals:
        from artipg.appearance import materials_of

        mats = materials_of(obj)
    robot = ET.Element("robot", name=f"{obj.category}_{obj.seed}")
    mj = ET.SubElement(robot, "mujoco")
    ET.SubElement(mj, "compiler", discardvisual="false", fusestatic="false", strippath="false",
                  balanceinertia="true")
    inertials = {}
    # collision hulls by OBJ text: identical hulls (the sectors of a ring, equal handles
    # or panels, in any link) share one file, each placed by its own <origin>
    hull_files: dict[str, str] = {}
    for link in obj.links:
        el = ET.SubElement(robot, "link", name=link.name)
        mass, com, I = inertials[link.name] = link_inertial(link, sections, obj.materials)
        inertial = ET.SubElement(el, "inertial")
        ET.SubElement(inertial, "origin", xyz=_fmt(com), rpy="0 0 0")
        ET.SubElement(inertial, "mass", value=f"{mass:.9g}")
        ET.SubElement(inertial, "inertia", ixx=f"{I[0, 0]:.9g}", ixy=f"{I[0, 1]:.9g}", ixz=f"{I[0, 2]:.9g}",
                      iyy=f"{I[1, 1]:.9g}", iyz=f"{I[1, 2]:.9g}", izz=f"{I[2, 2]:.9g}")
        surf = link_visual_surface(link, mats, sections) if visuals else None
        if surf is not None:
            surfaces[link.name] = surf
            path = f"meshes/{link.name}.obj"
            files[path] = obj_surface_text(*surf[:4], [(m.name, a, b) for m, a, b, _ in surf[4]])
            vis = ET.SubElement(el, "visual", name=f"{link.name}_visual")
            _origin(vis, np.eye(4))
            ET.SubElement(ET.SubElement(vis, "geometry"), "mesh", filename=path)
            _material(vis, max(surf[4], key=lambda g: g[3])[0])
        # ids of a hull's arrays -> its text (the arrays stay alive in the link's
        # entries, so their ids are unique meanwhile)
        hull_texts: dict[tuple[int, int], str] = {}
        entries = link_collision_entries(link)
        for k, (piece, T, prim) in enumerate(entries):
            col = ET.SubElement(el, "collision", name=f"{link.name}_c{k}")
            _origin(col, T)
            geom = ET.SubElement(col, "geometry")
            if piece.shape == "box":
                ET.SubElement(geom, "box", size=_fmt(piece.size))
            elif piece.shape == "cylinder":
                ET.SubElement(geom, "cylinder", radius=f"{piece.size[0]:.9g}", length=f"{piece.size[1]:.9g}")
            elif piece.shape == "sphere":
                ET.SubElement(geom, "sphere", radius=f"{piece.size[0]:.9g}")
            else:
                key = (id(piece.vertices), id(piece.faces))
                text = hull_texts.get(key)
                if text is None:
                    text = hull_texts[key] = obj_text(piece.vertices, piece.faces)
                path = hull_files.get(text)
                if path is None:
                    path = hull_files[text] = f"meshes/{link.name}_c{k}.obj"
                    files[path] = text
                ET.SubElement(geom, "mesh", filename=path)
    for j in obj.joints:
        el = ET.SubElement(robot, "joint", name=j.name, type=j.type)
        _origin(el, j.origin)
        ET.SubElement(el, "parent", link=j.parent)
        ET.SubElement(el, "child", link=j.child)
        if j.type != "fixed":
            ET.SubElement(el, "axis", xyz=_fmt(j.axis))
        if j.type in ("revolute", "prismatic"):
            ET.SubElement(el, "limit", lower=f"{j.limits[0]:.9g}", upper=f"{j.limits[1]:.9g}", effort="100",
                          velocity="1")
        if j.type != "fixed":
            damping = joint_damping(j.type, j.axis, *inertials[j.child])
            ET.SubElement(el, "dynamics", damping=f"{damping:.6g}", friction="0.0")
    if surfaces:
        files.update(visual_files(obj, surfaces))
    ET.indent(robot)
    return robot, files


def urdf_text(robot: ET.Element) -> str:
    return '<?xml version="1.0"?>\n' + ET.tostring(robot, encoding="unicode") + "\n"
