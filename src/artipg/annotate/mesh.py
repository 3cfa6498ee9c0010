"""A labelled triangle mesh of an object at any joint state (for ray casting).

Every face remembers the global primitive it comes from (the index used by
:class:`artipg.annotate.points.PrimitiveTable`), so a ray hit gives the semantic,
instance and link labels by table lookup. The per-primitive meshes are built once per
object in their link frames and cached; posing the object is one vectorised
transform of the vertices.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np
import trimesh

_CACHE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


@dataclass
class LinkFrameMesh:
    """All primitives of an object meshed in their link frames.

    Attributes
    ----------
    vertices : (V, 3) float64
        Vertex positions in the frame of the vertex's link (metres).
    faces : (F, 3) int64
    vertex_link : (V,) int64
        Link index of every vertex.
    face_prim : (F,) int64
        Global primitive index of every face.
    """

    vertices: np.ndarray
    faces: np.ndarray
    vertex_link: np.ndarray
    face_prim: np.ndarray


def link_frame_mesh(obj, sections: int = 24) -> LinkFrameMesh:
    """The cached :class:`LinkFrameMesh` of ``obj`` (built on first use)."""
    per_obj = _CACHE.setdefault(obj, {})
    if sections in per_obj:
        return per_obj[sections]
    verts, faces, vlink, fprim = [], [], [], []
    nv = 0
    k = 0
    for li, link in enumerate(obj.links):
        for part in link.parts:
            for prim in part.primitives:
                m = prim.placed(part.pose).mesh(sections)
                v = np.asarray(m.vertices, dtype=float)
                f = np.asarray(m.faces, dtype=np.int64)
                verts.append(v)
                faces.append(f + nv)
                vlink.append(np.full(len(v), li, dtype=np.int64))
                fprim.append(np.full(len(f), k, dtype=np.int64))
                nv += len(v)
                k += 1
    out = LinkFrameMesh(np.concatenate(verts), np.concatenate(faces), np.concatenate(vlink), np.concatenate(fprim))
    per_obj[sections] = out
    return out


def posed_mesh(obj, qpos=None, sections: int = 24) -> tuple[trimesh.Trimesh, np.ndarray]:
    """The object at ``qpos`` as one mesh in the object frame.

    Parameters
    ----------
    obj : ArticulatedObject
    qpos : None, dict or sequence
        Joint state (see :meth:`ArticulatedObject.qpos_dict`).
    sections : int
        Segments of curved primitives.

    Returns
    -------
    mesh : trimesh.Trimesh
        Not processed (vertices are not merged, faces keep their order).
    face_prim : (F,) int64
        Global primitive index of every face.
    """
    lm = link_frame_mesh(obj, sections)
    L = obj.link_poses(qpos)
    # vertices are stored link by link: one matrix product per link
    v = np.empty_like(lm.vertices)
    bounds = np.searchsorted(lm.vertex_link, np.arange(len(L) + 1))
    for li in range(len(L)):
        a, b = bounds[li], bounds[li + 1]
        v[a:b] = lm.vertices[a:b] @ L[li, :3, :3].T + L[li, :3, 3]
    return trimesh.Trimesh(v, lm.faces, process=False, validate=False), lm.face_prim
