"""GLB writer: ``mobility.glb``, the object for viewers (glTF 2.0, binary).

One node per link in the kinematic hierarchy (node name = link name, transform = the
joint's origin, so the nodes stand at rest), each holding the link's visual mesh
with vertex colours per semantic part (the colours of :func:`artipg.viz.palette`).
The node's extras hold its semantic label and the joint that moves it: ``type``,
``axis`` (joint frame), ``limits`` (rad or m; null when unlimited), ``parent``,
``child`` and ``name``.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from artipg.export.asset import Asset


@lru_cache(maxsize=None)
def label_color(label: str) -> tuple[float, float, float]:
    """RGB in [0, 1] of a semantic label: its vocabulary colour, or for labels outside
    the vocabulary (third-party folders') one of 32 more picked by a hash of the name."""
    import zlib

    from artipg.viz import palette
    from artipg.vocabulary import LABEL_ID, SEMANTIC_LABELS

    n = len(SEMANTIC_LABELS)
    i = LABEL_ID.get(label, n + zlib.crc32(label.encode()) % 32)
    return tuple(float(c) for c in palette(n + 32)[i])


def _rgba(asset: Asset, link, n: int) -> np.ndarray:
    runs = asset.vertex_labels.get(link.name)
    if not runs or sum(c for _, c in runs) != n:
        runs = [(link.label, n)]
    rgb = np.concatenate([np.tile(label_color(lab), (c, 1)) for lab, c in runs])
    return np.column_stack([np.round(rgb * 255), np.full(n, 255)]).astype(np.uint8)


def joint_extras(j) -> dict:
    """JSON-ready description of a joint (the node extras of its child link)."""
    lim = None if j.type == "fixed" or not all(math.isfinite(v) for v in j.limits) else [float(v) for v in j.limits]
    return {"name": j.name, "type": j.type, "parent": j.parent, "child": j.child,
            "axis": [float(v) for v in j.axis], "limits": lim}


def build_scene(asset: Asset):
    """A ``trimesh.Scene`` of ``asset``: one node per link, parented as the joints."""
    import trimesh

    scene = trimesh.Scene(base_frame="world")
    joint_of = {j.child: j for j in asset.joints}
    for lk in asset.links:
        j = joint_of.get(lk.name)
        parent = "world" if j is None else j.parent
        T = np.eye(4) if j is None else j.origin
        extras = {"semantic": lk.label, "joint": None if j is None else joint_extras(j)}
        vm = asset.visual_mesh(lk)
        if vm is None:
            scene.graph.update(frame_from=parent, frame_to=lk.name, matrix=T, metadata=extras)
            continue
        mesh = trimesh.Trimesh(*vm, process=False)
        mesh.visual = trimesh.visual.ColorVisuals(mesh, vertex_colors=_rgba(asset, lk, len(vm[0])))
        scene.add_geometry(mesh, node_name=lk.name, geom_name=f"{lk.name}_visual", parent_node_name=parent,
                           transform=T, metadata=extras)
    return scene


def glb_bytes(asset: Asset) -> bytes:
    """The bytes of ``mobility.glb`` of ``asset``."""
    return build_scene(asset).export(file_type="glb")
