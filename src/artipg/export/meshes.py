"""Meshes of links: visual OBJ files and convex collision pieces, plus inertials.

OBJ files are written with a fixed number format so that the same object always gives
the same bytes.

Collision geometry is one element per convex piece of every primitive
(:meth:`artipg.geometry.GeometryTemplate.collision`): boxes, cylinders and spheres
as native shapes, hollow solids (rings, tori, frames) as several convex sectors or
boxes, so that simulators, which treat every collision mesh as its convex hull,
never fill a hollow body.

Inertials come from the solid geometry and a density per material class
(:mod:`artipg.materials`, with the category's overrides): exact formulas for boxes, frames and
cylinders, mass properties of the primitive's mesh for the other templates.
"""

from __future__ import annotations

import numpy as np
import trimesh

from artipg.geometry.box import Cuboid, RectRing
from artipg.geometry.revolve import Frustum, Sphere
from artipg.materials import CLASS_DENSITY, DEFAULT_CLASS, MATERIAL, density, material_class  # noqa: F401


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """Wavefront OBJ text of a triangle mesh (vertices (V, 3) metres, faces (F, 3))."""
    v = ("v %.6f %.6f %.6f\n" * len(vertices)) % tuple(np.asarray(vertices, dtype=float).ravel())
    f = ("f %d %d %d\n" * len(faces)) % tuple((np.asarray(faces, dtype=np.int64) + 1).ravel())
    return v + f


def link_visual_arrays(link, sections: int = 24) -> tuple[np.ndarray, np.ndarray] | None:
    """All primitives of ``link`` as one mesh in the link frame: vertices (V, 3) and
    faces (F, 3), or None if the link is empty."""
    verts, faces = [], []
    n = 0
    for part in link.parts:
        for prim in part.primitives:
            V, F = prim.geom.mesh_arrays(prim.params, sections)
            T = part.pose @ prim.pose
            verts.append(V @ T[:3, :3].T + T[:3, 3])
            faces.append(F + n)
            n += len(V)
    if not verts:
        return None
    return np.concatenate(verts), np.concatenate(faces)


def link_visual_mesh(link, sections: int = 24) -> trimesh.Trimesh | None:
    """:func:`link_visual_arrays` as a ``trimesh.Trimesh`` (None if the link is empty)."""
    arrays = link_visual_arrays(link, sections)
    return None if arrays is None else trimesh.Trimesh(*arrays, process=False)


def link_collision_pieces(link):
    """Convex collision pieces of ``link``: list of (CollisionPiece, pose (4, 4) in link frame)."""
    out = []
    for part in link.parts:
        for prim in part.primitives:
            T = part.pose @ prim.pose
            for piece in prim.geom.collision(prim.params):
                out.append((piece, T @ piece.pose))
    return out


def _box_inertia(sx: float, sy: float, sz: float) -> np.ndarray:
    """Inertia tensor (3, 3) per unit mass of a box about its centre."""
    return np.diag([sy * sy + sz * sz, sx * sx + sz * sz, sx * sx + sy * sy]) / 12.0


def primitive_mass_properties(geom, params, sections: int = 24) -> tuple[float, np.ndarray, np.ndarray]:
    """Volume (m^3), centre of mass (3,) and inertia per unit mass (3, 3) about the
    centre of mass, in the primitive's local frame.

    Exact for boxes, rectangular frames, cylinders and full spheres; from the
    primitive's closed mesh otherwise.
    """
    p = tuple(float(v) for v in params)
    if geom is Cuboid:
        return p[0] * p[1] * p[2], np.zeros(3), _box_inertia(*p)
    if geom is RectRing:
        vol, I = 0.0, np.zeros((3, 3))
        for size, T in RectRing.pieces(p):
            v = size[0] * size[1] * size[2]
            c = T[:3, 3]
            vol += v
            I += v * (_box_inertia(*size) + np.dot(c, c) * np.eye(3) - np.outer(c, c))
        return vol, np.zeros(3), I / max(vol, 1e-18)
    if geom is Frustum and abs(p[0] - p[1]) < 1e-12:
        r, h = p[0], p[2]
        a = (3 * r * r + h * h) / 12.0
        return np.pi * r * r * h, np.zeros(3), np.diag([a, a, r * r / 2.0])
    if geom is Sphere and p[1] <= -p[0] and p[2] >= p[0]:
        R = p[0]
        return 4.0 / 3.0 * np.pi * R ** 3, np.zeros(3), np.eye(3) * (0.4 * R * R)
    V, F = geom.mesh_arrays(geom.solid_params(p), sections=sections)
    props = trimesh.triangles.mass_properties(V[F], density=1.0)
    vol = abs(float(props.volume))
    if vol <= 0:
        return 0.0, np.zeros(3), np.zeros((3, 3))
    return vol, np.asarray(props.center_mass), np.asarray(props.inertia) / props.mass


def link_inertial(link, sections: int = 24, materials=None) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass (3,) and inertia tensor (3, 3) about it, link frame.

    Each primitive is a solid of its part's material density (:func:`density`, with
    the category's ``materials`` overrides, e.g. ``obj.materials``);
    overlaps are counted twice, which is a small over-estimate for the few
    primitives that intersect.
    """
    masses, coms, inertias = [], [], []
    for part in link.parts:
        rho = density(part.semantic, materials)
        for prim in part.primitives:
            vol, c, I1 = primitive_mass_properties(prim.geom, prim.params, sections)
            if vol <= 0:
                continue
            T = part.pose @ prim.pose
            mass = rho * vol
            R = T[:3, :3]
            masses.append(mass)
            coms.append(R @ c + T[:3, 3])
            inertias.append(mass * (R @ I1 @ R.T))
    if not masses:
        return 1e-3, np.zeros(3), np.eye(3) * 1e-6
    M = float(sum(masses))
    com = np.sum([m * c for m, c in zip(masses, coms)], axis=0) / M
    I = np.zeros((3, 3))
    for m, c, Ii in zip(masses, coms, inertias):
        d = c - com
        I += Ii + m * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    # keep the tensor physically valid for engines that check the triangle inequality
    I = (I + I.T) / 2 + np.eye(3) * 1e-9
    return M, com, I


def object_mass(obj, sections: int = 24) -> float:
    """Total mass (kg) of ``obj``: the sum of its links' :func:`link_inertial` masses,
    with the category's material overrides (``obj.materials``)."""
    return float(sum(link_inertial(link, sections, obj.materials)[0] for link in obj.links))
