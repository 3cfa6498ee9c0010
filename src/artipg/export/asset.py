"""The simulator-neutral description of an object folder, read from its URDF.

The MJCF, USD and GLB writers (:mod:`artipg.export.mjcf`, :mod:`~artipg.export.usd`,
:mod:`~artipg.export.glb`) all start from an :class:`Asset`: links with one inertial
each (mass, centre of mass, full inertia), visual and collision geometry in the link
frame, and joints with their frames, axes, limits and dynamics. An asset is read from
a URDF (:func:`asset_from_urdf`, with ``yourdfpy``), so a generated object and any
third-party folder (PartNet-Mobility's) go through the same writers, and every number
the URDF exporter computed (inertials, damping) is reused, never recomputed.

Units: metres, kilograms, radians; poses are (4, 4) matrices, child frame to parent.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: Static friction of a joint as the damping force at this speed (m/s or rad/s):
#: a part stays where it is left instead of creeping, and is still easy to move.
FRICTION_SPEED = 0.01

#: Armature (reflected rotor inertia) of a joint as a fraction of its moving link's
#: effective inertia, with a floor (kg m^2 or kg) that keeps tiny knobs stable at a
#: 2 ms time step.
ARMATURE_RATIO, ARMATURE_MIN = 0.1, 1e-4

#: Natural frequency (Hz) of the optional position actuators: critically damped
#: servos this fast move a door through its range in well under a second.
SERVO_HZ = 4.0


@dataclass
class Geom:
    """A visual or collision element in its link's frame.

    ``kind``: ``"box"`` (size = full extents (3,)), ``"cylinder"`` (size = (radius,
    length), along local z), ``"sphere"`` (size = (radius,)) or ``"mesh"`` (``mesh``:
    path relative to the object folder, ``scale`` (3,)).
    """

    kind: str
    pose: np.ndarray
    size: tuple = ()
    mesh: str | None = None
    scale: tuple = (1.0, 1.0, 1.0)


@dataclass
class LinkDesc:
    """A link: name, inertial (mass kg, com (3,), inertia (3, 3) about the com, link
    frame), visual and collision geoms, and a semantic label (for colours)."""

    name: str
    mass: float
    com: np.ndarray
    inertia: np.ndarray
    visuals: list = field(default_factory=list)
    collisions: list = field(default_factory=list)
    label: str = "body"


@dataclass
class JointDesc:
    """A joint as in URDF (origin = child frame at q = 0 in the parent frame, unit axis
    in that frame, limits in rad or m) with its dynamics: viscous ``damping``,
    ``friction`` (Coulomb, N or N m), ``armature`` and the effective inertia
    ``effective`` (kg m^2 or kg) of the child link about / along the axis."""

    name: str
    type: str
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray
    limits: tuple
    damping: float = 0.0
    friction: float = 0.0
    armature: float = 0.0
    effective: float = 0.0

    def servo_gains(self) -> tuple[float, float]:
        """Stiffness and damping (kp, kv) of a critically damped position servo at
        :data:`SERVO_HZ` on this joint's effective inertia plus armature (SI units,
        per rad or per m); the joint's own damping counts towards kv."""
        inertia = self.effective + self.armature
        w = 2.0 * math.pi * SERVO_HZ
        return inertia * w * w, max(2.0 * inertia * w - self.damping, 0.0)


@dataclass
class Asset:
    """An articulated object ready for the writers.

    Attributes
    ----------
    name : str
    links : list of LinkDesc
        Root first, every parent before its children.
    joints : list of JointDesc
        One per non-root link.
    fixed_base : bool
        A fixture (mounted): welded to the world, not free.
    folder : Path or None
        The object folder that mesh paths are relative to.
    files : dict
        {relative path: OBJ or MTL text, or PNG bytes} of files not (yet) on disk.
    vertex_labels : dict
        {link name: [(label, vertex count), ...]} semantic labels of the runs of
        vertices of a link's visual mesh (else the link's ``label`` colours it all).
    excludes : list
        [(link, link)] pairs that must not collide besides parent and child (links of
        third-party meshes that overlap at rest).
    surfaces : dict
        {link name: :class:`artipg.export.surfaces.Surface`}: visual surfaces with
        materials, read from the OBJ and MTL files of artipg's own objects
        (:func:`artipg.export.surfaces.read_surfaces`); empty for third-party folders,
        whose writers then colour the visual geoms by semantic label.
    """

    name: str
    links: list
    joints: list
    fixed_base: bool = False
    folder: Path | None = None
    files: dict = field(default_factory=dict)
    vertex_labels: dict = field(default_factory=dict)
    excludes: list = field(default_factory=list)
    surfaces: dict = field(default_factory=dict)

    def link(self, name: str) -> LinkDesc:
        return self.links[[lk.name for lk in self.links].index(name)]

    def link_poses(self) -> dict[str, np.ndarray]:
        """Pose (4, 4) of every link in the root frame at rest (all joints at 0)."""
        T = {self.links[0].name: np.eye(4)}
        for j in self.joints:
            T[j.child] = T[j.parent] @ j.origin
        return T

    def mesh_arrays(self, rel: str, scale=(1.0, 1.0, 1.0)) -> tuple[np.ndarray, np.ndarray]:
        """Vertices (V, 3) and triangles (F, 3) of mesh file ``rel`` times ``scale``."""
        text = self.files.get(rel)
        if text is not None:
            V, F = obj_arrays(text)
        else:
            import trimesh

            m = trimesh.load(str(Path(self.folder) / rel), force="mesh", process=False)
            V, F = np.asarray(m.vertices, dtype=float), np.asarray(m.faces, dtype=np.int64)
        return V * np.asarray(scale, dtype=float), F

    def file_bytes(self, rel: str) -> bytes:
        """The bytes of file ``rel`` (relative to the object folder): held in memory or on disk."""
        data = self.files.get(rel)
        if data is not None:
            return data if isinstance(data, bytes) else data.encode()
        return (Path(self.folder) / rel).read_bytes()

    def visual_mesh(self, link: LinkDesc) -> tuple[np.ndarray, np.ndarray] | None:
        """All visual geoms of ``link`` as one mesh in the link frame, or None."""
        verts, faces, n = [], [], 0
        for g in link.visuals:
            V, F = geom_arrays(self, g)
            verts.append(V @ g.pose[:3, :3].T + g.pose[:3, 3])
            faces.append(F + n)
            n += len(V)
        if not verts:
            return None
        return np.concatenate(verts), np.concatenate(faces)


def obj_arrays(text: str) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) and triangles (F, 3) of Wavefront OBJ text with ``v`` and
    triangular ``f`` lines (as :mod:`artipg.export.meshes` writes them, with or without
    texture and normal indices)."""
    lines = text.splitlines()
    v = [ln[2:] for ln in lines if ln.startswith("v ")]
    f = [ln[2:] for ln in lines if ln.startswith("f ")]
    V = np.array(" ".join(v).split(), dtype=float).reshape(-1, 3)
    # face corners may be "v", "v/vt" or "v/vt/vn": the vertex index comes first
    F = np.array([c.split("/", 1)[0] for c in " ".join(f).split()], dtype=np.int64).reshape(-1, 3) - 1
    return V, F


def geom_arrays(asset: Asset, g: Geom, sections: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """A geom as a triangle mesh (vertices (V, 3), faces (F, 3)) in its own frame."""
    import trimesh

    if g.kind == "mesh":
        return asset.mesh_arrays(g.mesh, g.scale)
    if g.kind == "box":
        m = trimesh.creation.box(extents=g.size)
    elif g.kind == "cylinder":
        m = trimesh.creation.cylinder(radius=g.size[0], height=g.size[1], sections=sections)
    else:
        m = trimesh.creation.icosphere(subdivisions=2, radius=g.size[0])
    return np.asarray(m.vertices, dtype=float), np.asarray(m.faces, dtype=np.int64)


# ------------------------------------------------------------------ reading a URDF

def _geom(origin, geometry) -> Geom | None:
    T = np.array(origin if origin is not None else np.eye(4), dtype=float)
    if geometry.box is not None:
        return Geom("box", T, tuple(float(s) for s in geometry.box.size))
    if geometry.cylinder is not None:
        return Geom("cylinder", T, (float(geometry.cylinder.radius), float(geometry.cylinder.length)))
    if geometry.sphere is not None:
        return Geom("sphere", T, (float(geometry.sphere.radius),))
    if geometry.mesh is not None:
        s = geometry.mesh.scale
        scale = (1.0, 1.0, 1.0) if s is None else tuple(np.broadcast_to(np.asarray(s, dtype=float), (3,)).tolist())
        return Geom("mesh", T, mesh=relative_mesh_path(geometry.mesh.filename), scale=scale)
    return None


def relative_mesh_path(filename: str) -> str:
    """A URDF mesh reference (``package://pkg/...``, ``file://...``, relative) as a path
    relative to the folder of the URDF."""
    import re

    f = re.sub(r"^package://[^/]*/", "", filename)
    return f[len("file://"):] if f.startswith("file://") else f


def load_robot(source):
    """The ``yourdfpy`` robot of a URDF file path or URDF text (meshes not loaded)."""
    import yourdfpy

    if isinstance(source, str) and source.lstrip().startswith("<"):
        source = io.BytesIO(source.encode())
    elif isinstance(source, Path):
        source = str(source)
    urdf = yourdfpy.URDF.load(source, build_scene_graph=False, load_meshes=False,
                              build_collision_scene_graph=False, load_collision_meshes=False)
    return urdf.robot


def effective_inertia(jtype: str, axis, mass: float, com, inertia) -> float:
    """Inertia (kg m^2) of a link about a revolute joint's axis through the joint origin
    (parallel axis theorem), or its mass (kg) for a prismatic joint; mass kg, com (3,)
    and inertia (3, 3) about the com in the joint frame, unit axis (3,)."""
    if jtype == "prismatic":
        return float(mass)
    a = np.asarray(axis, dtype=float)
    c = np.asarray(com, dtype=float)
    return float(a @ np.asarray(inertia) @ a) + float(mass) * (float(c @ c) - float(a @ c) ** 2)


def asset_from_urdf(robot, folder=None, files=None, fixed_base: bool = False, name: str | None = None,
                    inertials=None, labels=None) -> Asset:
    """An :class:`Asset` from a ``yourdfpy`` robot (:func:`load_robot`).

    Parameters
    ----------
    robot : yourdfpy.Robot
    folder : path, optional
        Where the URDF's mesh paths are relative to.
    files : dict, optional
        {relative path: OBJ text} of meshes held in memory.
    fixed_base : bool
    name : str, optional
        Defaults to the robot's name.
    inertials : callable, optional
        ``inertials(link_desc) -> (mass, com, inertia)`` for links without an
        ``<inertial>`` (third-party URDFs); such links get 1 g otherwise.
    labels : dict, optional
        {link name: semantic label}.
    """
    from artipg.export.urdf import joint_damping

    labels = labels or {}
    links = {}
    for lk in robot.links:
        visuals = [g for g in (_geom(v.origin, v.geometry) for v in lk.visuals) if g is not None]
        collisions = [g for g in (_geom(c.origin, c.geometry) for c in lk.collisions) if g is not None]
        d = LinkDesc(lk.name, 1e-3, np.zeros(3), np.eye(3) * 1e-6, visuals, collisions,
                     labels.get(lk.name, "body"))
        if lk.inertial is not None and lk.inertial.mass is not None:
            T = np.eye(4) if lk.inertial.origin is None else np.asarray(lk.inertial.origin, dtype=float)
            I = np.zeros((3, 3)) if lk.inertial.inertia is None else np.asarray(lk.inertial.inertia, dtype=float)
            d.mass, d.com, d.inertia = float(lk.inertial.mass), T[:3, 3].copy(), T[:3, :3] @ I @ T[:3, :3].T
        elif inertials is not None:
            d.mass, d.com, d.inertia = inertials(d)
        links[lk.name] = d
    children = {j.child for j in robot.joints}
    roots = [n for n in links if n not in children]
    if len(roots) != 1:
        raise ValueError(f"the URDF must have one root link, it has {len(roots)}")
    by_parent: dict[str, list] = {}
    for j in robot.joints:
        by_parent.setdefault(j.parent, []).append(j)
    order, joints, stack = [roots[0]], [], [roots[0]]
    while stack:  # depth first, children in file order
        p = stack.pop(0)
        for j in by_parent.get(p, []):
            order.append(j.child)
            stack.append(j.child)
            joints.append(_joint(j, links[j.child], joint_damping))
    if len(order) != len(links):
        raise ValueError("the URDF's links do not form one tree")
    from artipg.export.surfaces import read_surfaces

    asset = Asset(name or robot.name, [links[n] for n in order], joints, bool(fixed_base),
                  None if folder is None else Path(folder), dict(files or {}))
    asset.surfaces = read_surfaces(asset)
    return asset


def _joint(j, child: LinkDesc, joint_damping) -> JointDesc:
    jtype = j.type if j.type in ("revolute", "prismatic", "continuous") else "fixed"
    axis = np.array([1.0, 0.0, 0.0] if j.axis is None else j.axis, dtype=float)
    axis /= max(np.linalg.norm(axis), 1e-12)
    if jtype == "continuous" or j.limit is None:
        limits = (-math.inf, math.inf) if jtype != "fixed" else (0.0, 0.0)
    else:
        limits = (float(j.limit.lower or 0.0), float(j.limit.upper or 0.0))
    origin = np.eye(4) if j.origin is None else np.asarray(j.origin, dtype=float)
    out = JointDesc(j.name, jtype, j.parent, j.child, origin, axis, limits)
    if jtype == "fixed":
        return out
    eff = effective_inertia(jtype, axis, child.mass, child.com, child.inertia)
    dyn = j.dynamics
    damping = float(dyn.damping) if dyn is not None and dyn.damping else 0.0
    if damping <= 0.0:  # third-party URDFs: the rule of artipg's own exporter
        damping = joint_damping(jtype, axis, child.mass, child.com, child.inertia)
    out.damping, out.effective = damping, eff
    out.friction = (float(dyn.friction) if dyn is not None and dyn.friction else 0.0) or FRICTION_SPEED * damping
    out.armature = max(ARMATURE_RATIO * eff, ARMATURE_MIN)
    return out


def object_asset(obj, urdf_text: str, files: dict, sections: int = 24) -> Asset:
    """The :class:`Asset` of a generated object from its exported URDF text and
    {relative path: OBJ or MTL text, or PNG bytes} files, with per-part semantic labels
    of the visuals (its materials are read back from the OBJ and MTL files, as for a
    converted folder, so both give the same bytes)."""
    from artipg.export.meshes import primitive_mesh_arrays
    from artipg.export.annotation import category_fixed_base

    labels = {lk.name: (lk.parts[0].semantic if lk.parts else "body") for lk in obj.links}
    asset = asset_from_urdf(load_robot(urdf_text), files=files, fixed_base=category_fixed_base(obj.category),
                            labels=labels)
    for lk in obj.links:
        runs = []
        for part in lk.parts:
            n = sum(len(primitive_mesh_arrays(p.geom, p.params, sections)[0]) for p in part.primitives)
            runs.append((part.semantic, n))
        asset.vertex_labels[lk.name] = runs
    return asset
