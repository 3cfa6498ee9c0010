"""Generated objects -> an :class:`artipg.io.dataset.ObjectSet`, without writing folders.

``artipg eval --generate N`` compares N freshly generated objects of each category with
a reference folder. The clouds are the exact labelled samples of
:meth:`artipg.model.ArticulatedObject.sample_points`, so a generated set read this way
equals the same seeds written by ``artipg generate`` and read back from ``points.npz``.

PartNet-Mobility models some categories in a pose other than artipg's rest pose (joint
value 0 is "the pose the object was modelled in"): its laptops are modelled open. With
``pose="partnet"`` each generated object is sampled in the pose PartNet-Mobility uses
for its category (:data:`PARTNET_POSE`), so shapes are compared like with like.
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from artipg.io.dataset import ObjectSet
from artipg.io.structure import ObjectStructure

#: Per category, the pose PartNet-Mobility models its objects in, as ranges for the
#: movable joints whose child link name starts with a given prefix: ``("value", lo,
#: hi)`` in the joint's units (radians, metres) or ``("fraction", lo, hi)`` of the
#: joint's range, with an optional fourth item, the share of objects so modelled (the
#: others at rest). Each object draws its values from its own seed, so the modelled
#: poses vary as the modellers left them; joints not listed stay at 0 (rest). From the
#: development split: laptop screens open 90-135 degrees (their closing ranges,
#: 1.57-2.36 rad); bucket bails stand up in 4 of 7 (within about 20 degrees of
#: upright, the middle of artipg's back-to-front swing) and lie down in the others.
PARTNET_POSE = {
    "laptop": {"screen": ("value", 1.57, 2.36)},
    "bucket": {"handle": ("fraction", 0.4, 0.6, 0.6)},
}

POSES = ("rest", "partnet")

#: Stream key of the modelled-pose draws (independent of generation and point sampling).
_POSE_STREAM = 0x9A57


def partnet_qpos(obj, category: str) -> dict:
    """Joint values (name -> value) of ``obj`` in PartNet-Mobility's modelled pose of
    ``category`` (:data:`PARTNET_POSE`), clipped to each joint's limits; joints not
    listed are left out (rest, 0)."""
    rule = PARTNET_POSE.get(category, {})
    if not rule:
        return {}
    rng = np.random.default_rng([int(obj.seed), _POSE_STREAM])
    q = {}
    for j in obj.movable_joints:
        spec = next((v for prefix, v in rule.items() if j.child.startswith(prefix)), None)
        if spec is None:
            continue
        kind, a, b, share = (*spec, 1.0)[:4]
        if rng.random() >= share:
            continue
        lo, hi = j.limits
        if kind == "fraction":
            a, b = lo + a * (hi - lo), lo + b * (hi - lo)
        q[j.name] = float(np.clip(a + rng.random() * (b - a), lo, hi))
    return q


def object_structure(obj, qpos: dict | None = None) -> ObjectStructure:
    """The :class:`ObjectStructure` of a generated object (joints, links with geometry,
    extents of its bounding box at ``qpos``; metres)."""
    b = obj.bounds(qpos)
    types = tuple(j.type for j in obj.joints)
    n_links = sum(1 for link in obj.links if link.parts)
    return ObjectStructure(joint_types=types, n_links=n_links, extents=b[1] - b[0])


def generated_set(category: str, seeds: Sequence[int], n_points: int = 2048, pose: str = "rest",
                  sampling_seed: int = 0, progress: Callable[[int], None] | None = None,
                  detail: str | None = None) -> ObjectSet:
    """Generate ``category`` at ``seeds`` and sample one labelled cloud per object.

    Parameters
    ----------
    category : str
        A registered category.
    seeds : sequence of int
        Object seeds.
    n_points : int
        Points per cloud.
    pose : {"rest", "partnet"}
        Sample at rest (all joints 0) or in PartNet-Mobility's modelled pose of the
        category (:func:`partnet_qpos`).
    sampling_seed : int
        Seed of the point sampling (the same for every object).
    progress : callable, optional
        Called with 1 after each object.
    detail : {"procedural", "off"}, optional
        Geometric detail level of the objects (None: the default, procedural).

    Returns
    -------
    ObjectSet
        ``folders`` holds ``"<category>/<seed>"`` labels instead of paths; points are in
        metres in the object frame.
    """
    import artipg

    if pose not in POSES:
        raise ValueError(f"pose must be one of {POSES}, got {pose!r}")
    labels, clouds, links, names, structures = [], [], [], [], []
    for seed in seeds:
        obj = artipg.generate(category, int(seed), detail=detail)
        q = partnet_qpos(obj, category) if pose == "partnet" else None
        pc = obj.sample_points(n_points, seed=sampling_seed, qpos=q)
        labels.append(f"{category}/{int(seed)}")
        clouds.append(np.asarray(pc.points, dtype=np.float64))
        links.append(np.asarray(pc.link, dtype=np.int64))
        names.append(tuple(link.name for link in obj.links))
        structures.append(object_structure(obj, q))
        if progress is not None:
            progress(1)
    return ObjectSet(folders=labels,
                     points=np.stack(clouds) if clouds else np.zeros((0, n_points, 3)),
                     link=np.stack(links) if links else np.zeros((0, n_points), dtype=np.int64),
                     link_names=names, structures=structures)
