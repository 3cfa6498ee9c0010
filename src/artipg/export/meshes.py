"""Meshes of links: visual OBJ files and convex collision pieces, plus inertials.

OBJ files are written with a fixed number format so that the same object always gives
the same bytes.
"""

from __future__ import annotations

import numpy as np
import trimesh

#: Densities (kg/m^3) per semantic label; the rest use DEFAULT_DENSITY (wood/plastic).
DENSITY = {"glass": 2500.0, "knob": 1100.0, "button": 1100.0, "handle": 2700.0, "spout": 8000.0,
           "lever": 8000.0, "hinge": 7800.0, "wheel": 1200.0}
DEFAULT_DENSITY = 600.0


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """Wavefront OBJ text of a triangle mesh (vertices (V, 3) metres, faces (F, 3))."""
    v = ("v %.6f %.6f %.6f\n" * len(vertices)) % tuple(np.asarray(vertices, dtype=float).ravel())
    f = ("f %d %d %d\n" * len(faces)) % tuple((np.asarray(faces, dtype=np.int64) + 1).ravel())
    return v + f


def link_visual_mesh(link, sections: int = 24) -> trimesh.Trimesh | None:
    """All primitives of ``link`` as one mesh in the link frame (None if empty)."""
    meshes = [prim.placed(part.pose).mesh(sections) for part in link.parts for prim in part.primitives]
    if not meshes:
        return None
    return trimesh.util.concatenate(meshes)


def link_collision_pieces(link):
    """Convex collision pieces of ``link``: list of (CollisionPiece, pose (4, 4) in link frame)."""
    out = []
    for part in link.parts:
        for prim in part.primitives:
            T = part.pose @ prim.pose
            for piece in prim.geom.collision(prim.params):
                out.append((piece, T @ piece.pose))
    return out


def link_inertial(link, sections: int = 24) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass (3,) and inertia tensor (3, 3) about it, link frame.

    Each primitive is a solid of its part's material density; overlaps are counted
    twice, which is a small over-estimate for the few primitives that intersect.
    """
    masses, coms, inertias = [], [], []
    for part in link.parts:
        rho = DENSITY.get(part.semantic, DEFAULT_DENSITY)
        for prim in part.primitives:
            m = prim.geom.mesh(prim.geom.solid_params(prim.params), sections=sections)
            T = part.pose @ prim.pose
            vol = abs(m.volume)
            if vol <= 0:
                continue
            mass = rho * vol
            R = T[:3, :3]
            c = R @ m.center_mass + T[:3, 3]
            inertia = R @ (m.moment_inertia * (mass / m.mass)) @ R.T
            masses.append(mass)
            coms.append(c)
            inertias.append(inertia)
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
