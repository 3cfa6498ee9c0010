"""All annotations of an object at one joint state as flat numpy arrays.

These are the arrays written to ``points.npz`` and ``views.npz`` (documented one by
one in ``docs/annotations.md``); they are plain dicts so that users who do not write
files (training loops, benchmarks) get the same data.
"""

from __future__ import annotations

import numpy as np

from artipg.annotate.grasps import world_grasps
from artipg.annotate.knowledge import knowledge
from artipg.annotate.labels import part_frames, point_labels
from artipg.annotate.views import partial_views
from artipg.vocabulary import ACTIONABLE_CLASSES, AFFORDANCES, SEMANTIC_LABELS


def qpos_vector(obj, qpos=None) -> np.ndarray:
    """Joint values (J,) of the movable joints (``obj.movable_joints`` order)."""
    q = obj.qpos_dict(qpos)
    return np.array([q.get(j.name, 0.0) for j in obj.movable_joints], dtype=float)


def pose_arrays(obj, qpos=None) -> dict[str, np.ndarray]:
    """Joint state, link poses and part pose knowledge at ``qpos`` (object frame)."""
    F = part_frames(obj, qpos)
    kn = knowledge(obj)
    return {
        "qpos": qpos_vector(obj, qpos),
        "joint_names": np.array([j.name for j in obj.movable_joints], dtype=str),
        "link_poses": obj.link_poses(qpos).astype(np.float32),
        "part_poses": F.pose.astype(np.float32),
        "part_sizes": F.size.astype(np.float32),
        "part_scales": F.scale.astype(np.float32),
        "part_semantic": obj.primitive_table.part_semantic.astype(np.int32),
        "part_actionable": kn.part_actionable.astype(np.int32),
        "part_link": obj.part_link.astype(np.int32),
    }


def grasp_arrays(obj, qpos=None, grasps=None) -> dict[str, np.ndarray]:
    """Grasp poses at ``qpos`` with their collision flags (see :func:`world_grasps`)."""
    g = world_grasps(obj, qpos) if grasps is None else grasps
    return {
        "grasp_poses": g.pose.astype(np.float32),
        "grasp_widths": g.width.astype(np.float32),
        "grasp_open_dirs": g.open_dir.astype(np.float32),
        "grasp_parts": g.part.astype(np.int32),
        "grasp_collision_free": g.collision_free.astype(bool),
    }


def point_arrays(obj, n: int = 2048, seed: int = 0, qpos=None, grasps=True) -> dict[str, np.ndarray]:
    """Labelled points with every per-point label, the pose knowledge and (with
    ``grasps``) the grasps, at joint state ``qpos``.

    Parameters
    ----------
    obj : ArticulatedObject
    n : int
        Number of surface points.
    seed : int
        Seed of the point sampling.
    qpos : None, dict or sequence
        Joint state.
    grasps : bool or WorldGrasps
        Include grasp arrays (computed here when True).
    """
    pc = obj.sample_points(n, seed=seed, qpos=qpos)
    lab = point_labels(obj, pc.points, pc.primitive, qpos)
    out = {
        "points": pc.points.astype(np.float32),
        "normals": pc.normals.astype(np.float32),
        "semantic": pc.semantic.astype(np.int32),
        "instance": pc.instance.astype(np.int32),
        "link": pc.link.astype(np.int32),
        "primitive": pc.primitive.astype(np.int32),
        "actionable": lab.actionable.astype(np.int32),
        "affordance": lab.affordance,
        "npcs": lab.npcs.astype(np.float32),
        "object_npcs": lab.object_npcs.astype(np.float32),
        "semantic_names": np.array(SEMANTIC_LABELS),
        "instance_names": np.array(pc.instance_names),
        "link_names": np.array(pc.link_names),
        "actionable_names": np.array(ACTIONABLE_CLASSES),
        "affordance_names": np.array(AFFORDANCES),
    }
    out.update(pose_arrays(obj, qpos))
    if grasps is not False:
        out.update(grasp_arrays(obj, qpos, None if grasps is True else grasps))
    return out


def view_arrays(obj, k: int = 8, n: int = 2048, qpos=None, seed: int = 0, width: int = 320, height: int = 240,
                images: bool = True) -> dict[str, np.ndarray]:
    """``k`` partial views from upper-hemisphere cameras at ``qpos``: labelled partial
    clouds of ``n`` points, cameras and (with ``images``) depth and instance images.

    Semantic and link images follow from the instance image through
    ``part_semantic`` / ``part_link`` (in :func:`pose_arrays`).
    """
    views = partial_views(obj, k, n, qpos, seed=seed, width=width, height=height)
    out = {
        "camera_poses": np.stack([v.camera.pose for v in views]).astype(np.float32),
        "camera_intrinsics": np.stack([v.camera.K for v in views]).astype(np.float32),
        "camera_azimuth": np.array([v.camera.azimuth for v in views], dtype=np.float32),
        "camera_elevation": np.array([v.camera.elevation for v in views], dtype=np.float32),
        "partial_points": np.stack([v.points for v in views]).astype(np.float32),
        "partial_pixels": np.stack([v.pixels for v in views]).astype(np.int32),
        "partial_semantic": np.stack([v.semantic for v in views]).astype(np.int32),
        "partial_instance": np.stack([v.instance for v in views]).astype(np.int32),
        "partial_link": np.stack([v.link for v in views]).astype(np.int32),
    }
    if images:
        out["depth"] = np.stack([v.view.depth for v in views]).astype(np.float32)
        out["instance_image"] = np.stack([v.view.instance for v in views]).astype(np.int16)
    return out
