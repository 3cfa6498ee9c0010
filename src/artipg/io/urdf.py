"""Load a ``mobility.urdf`` (artipg's or PartNet-Mobility's) at its rest pose.

Visual geometry is placed through the URDF's own kinematics with :mod:`yourdfpy`:
each visual is ``T_link(q = 0) @ visual.origin @ scale(mesh)`` in the frame of the
URDF's root link. That is the only frame convention a reader needs: PartNet-Mobility
meshes are modelled Y-up, and the rotation that makes them +Z up (front facing -X)
sits in the URDF itself (in a visual ``<origin rpy>`` or in the fixed joint from the
empty ``base`` link), so loading through the kinematics yields +Z-up points for both
datasets without any per-dataset special case. Do not read the OBJ files directly.

The rest pose is every joint at 0 (artipg's convention; PartNet-Mobility's URDFs are
modelled at q = 0 too).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh

@dataclass
class LoadedURDF:
    """Visual geometry and joint structure of a URDF at its rest pose.

    Attributes
    ----------
    path : Path
        The URDF file.
    link_names : tuple of str
        All links, in URDF document order.
    link_poses : (L, 4, 4) float64
        Pose of every link frame in the root link frame at q = 0.
    joints : tuple of (name, type, parent, child)
        All joints (fixed ones included), in document order.
    vertices : (V, 3) float64
        Every visual mesh vertex in the root frame at q = 0 (URDF units, metres).
    faces : (F, 3) int64
        Triangles indexing ``vertices``.
    face_link : (F,) int64
        Index into ``link_names`` of the link each face belongs to.
    """

    path: Path
    link_names: tuple
    link_poses: np.ndarray
    joints: tuple
    vertices: np.ndarray
    faces: np.ndarray
    face_link: np.ndarray

    @property
    def visual_links(self) -> tuple:
        """Names of the links that carry visual geometry (PartNet-Mobility's empty
        ``base`` link and artipg's links without parts are left out)."""
        used = np.unique(self.face_link)
        return tuple(self.link_names[i] for i in used)

    @property
    def bounds(self) -> np.ndarray:
        """Axis-aligned box (2, 3) of the visual geometry in the root frame at q = 0."""
        if not len(self.vertices):
            return np.zeros((2, 3))
        used = self.vertices[np.unique(self.faces)]
        return np.stack([used.min(axis=0), used.max(axis=0)])


def resolve_mesh_path(filename: str, base_dir: Path) -> Path:
    """Find the file a URDF ``<mesh filename>`` refers to.

    Accepts paths relative to the URDF's folder (artipg, PartNet-Mobility), absolute
    paths, ``file://`` and ``package://<pkg>/<path>`` (resolved by dropping leading
    components until the rest exists under ``base_dir``).

    Raises
    ------
    FileNotFoundError
    """
    f = filename
    for prefix in ("package://", "file://"):
        if f.startswith(prefix):
            f = f[len(prefix):]
    p = Path(f)
    if p.is_absolute() and p.is_file():
        return p
    parts = Path(f.lstrip("/")).parts
    for i in range(len(parts)):
        cand = base_dir.joinpath(*parts[i:])
        if cand.is_file():
            return cand
    raise FileNotFoundError(f"mesh {filename!r} not found under {base_dir}")


def _geometry_mesh(geometry, base_dir: Path) -> trimesh.Trimesh | None:
    """The visual geometry as a mesh in the visual frame (scale applied)."""
    if geometry.mesh is not None:
        path = resolve_mesh_path(geometry.mesh.filename, base_dir)
        mesh = trimesh.load(str(path), force="mesh", process=False, skip_materials=True)
        if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
            return None
        mesh = trimesh.Trimesh(np.asarray(mesh.vertices, dtype=float), np.asarray(mesh.faces), process=False)
        if geometry.mesh.scale is not None:
            s = np.broadcast_to(np.asarray(geometry.mesh.scale, dtype=float), (3,))
            mesh.vertices = mesh.vertices * s
        return mesh
    if geometry.box is not None:
        return trimesh.creation.box(extents=np.asarray(geometry.box.size, dtype=float))
    if geometry.cylinder is not None:
        return trimesh.creation.cylinder(radius=float(geometry.cylinder.radius), height=float(geometry.cylinder.length),
                                         sections=32)
    if geometry.sphere is not None:
        return trimesh.creation.icosphere(subdivisions=3, radius=float(geometry.sphere.radius))
    return None


def load_urdf(path: str | Path) -> LoadedURDF:
    """Load a URDF's visual meshes at the rest pose (all joints 0) in its root frame.

    Parameters
    ----------
    path : str or Path
        A URDF file; mesh paths inside are resolved relative to its folder.

    Returns
    -------
    LoadedURDF

    Raises
    ------
    FileNotFoundError
        If the URDF or a referenced mesh file is missing.
    """
    import yourdfpy

    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path} is not a file")
    urdf = yourdfpy.URDF.load(str(path), build_scene_graph=True, load_meshes=False)
    if urdf.num_actuated_joints:
        urdf.update_cfg(np.zeros(urdf.num_actuated_joints))
    base = urdf.base_link
    links = urdf.robot.links
    names = tuple(lk.name for lk in links)
    poses = np.stack([np.asarray(urdf.get_transform(frame_to=n, frame_from=base), dtype=float) for n in names])
    verts, faces, face_link = [], [], []
    offset = 0
    for li, link in enumerate(links):
        for vis in link.visuals:
            mesh = _geometry_mesh(vis.geometry, path.parent)
            if mesh is None:
                continue
            T = poses[li] @ (np.eye(4) if vis.origin is None else np.asarray(vis.origin, dtype=float))
            v = mesh.vertices @ T[:3, :3].T + T[:3, 3]
            verts.append(v)
            faces.append(np.asarray(mesh.faces, dtype=np.int64) + offset)
            face_link.append(np.full(len(mesh.faces), li, dtype=np.int64))
            offset += len(v)
    joints = tuple((j.name, j.type, j.parent, j.child) for j in urdf.robot.joints)
    return LoadedURDF(
        path=path,
        link_names=names,
        link_poses=poses,
        joints=joints,
        vertices=np.concatenate(verts) if verts else np.zeros((0, 3)),
        faces=np.concatenate(faces) if faces else np.zeros((0, 3), dtype=np.int64),
        face_link=np.concatenate(face_link) if face_link else np.zeros(0, dtype=np.int64),
    )
