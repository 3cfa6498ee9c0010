"""``annotation.json``: structure, parameters, part poses and grasps of an object."""

from __future__ import annotations

import numpy as np

import artipg
from artipg.export.jsontext import dumps_indented


def _r(x, nd=6):
    """Round floats (nested lists) for a stable, compact JSON."""
    t = type(x)
    if t is float:  # the common types first
        v = round(x, nd)
        return 0.0 if v == 0 else v
    if t is str or t is bool or t is int:
        return x
    if t is list and all(type(v) is float for v in x):
        return [0.0 if v == 0 else v for v in (round(v, nd) for v in x)]
    if isinstance(x, np.ndarray) and x.dtype.kind == "f":
        return (x.round(nd) + 0.0).tolist()  # + 0.0 turns -0.0 into 0.0
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_r(v, nd) for v in x]
    if isinstance(x, (float, np.floating)):
        v = round(float(x), nd)
        return 0.0 if v == 0 else v
    if isinstance(x, np.integer):
        return int(x)
    return x


def category_fixed_base(name: str) -> bool:
    """``fixed_base`` of the registered category ``name`` (False for unknown names)."""
    import artipg

    try:
        return bool(getattr(artipg.get_category(name), "fixed_base", False))
    except (KeyError, ValueError):
        return False


def annotation_dict(obj, grasps=None) -> dict:
    """Everything about ``obj`` except geometry, as JSON-ready data.

    Part poses and grasps are given at the rest state in the object frame (see
    ``docs/annotations.md``); ``grasps`` is a precomputed
    :class:`artipg.annotate.grasps.WorldGrasps` at rest (computed when None).
    """
    from artipg.annotate.grasps import world_grasps
    from artipg.annotate.labels import part_frames

    frames = part_frames(obj)
    g = world_grasps(obj) if grasps is None else grasps
    # arrays are rounded whole (element by element, as row by row); scalars one by one
    # with Python's round, as before
    pose, approach, open_dir = _r(g.pose), _r(g.approach), _r(g.open_dir)
    joint_name = [j.name for j in obj.joints]
    by_part: dict[int, list] = {}
    for k, (part, width, joint, free) in enumerate(zip(g.part.tolist(), g.width.tolist(), g.joint.tolist(),
                                                       g.collision_free.tolist())):
        by_part.setdefault(part, []).append({
            "pose": pose[k], "width": _r(width), "approach": approach[k], "open_dir": open_dir[k],
            "joint": joint_name[joint] if joint >= 0 else None, "collision_free": bool(free),
        })
    canonical, size, npcs_pose = _r(frames.canonical), _r(frames.size), _r(frames.pose)
    scale = [_r(v) for v in np.asarray(frames.scale, dtype=float).tolist()]
    parts = []
    for i, part in enumerate(obj.parts):
        parts.append({
            "name": part.name,
            "instance": i,
            "link": obj.links[int(obj.part_link[i])].name,
            "semantic": part.semantic,
            "template": part.template,
            "actionable": part.actionable,
            "pose": canonical[i],
            "size": size[i],
            "npcs_pose": npcs_pose[i],
            "npcs_scale": scale[i],
            "affordances": sorted(part.regions),
            "grasps": by_part.get(i, []),
        })
    joints = [{"name": j.name, "type": j.type, "parent": j.parent, "child": j.child, "origin": _r(j.origin),
               "axis": _r(j.axis), "limits": [None if not np.isfinite(v) else _r(v) for v in j.limits]}
              for j in obj.joints]
    return {
        "category": obj.category,
        "subcategory": obj.subcategory,
        "seed": obj.seed,
        "version": artipg.__version__,
        "frame": {"up": "+z", "front": "-x", "units": "m"},
        # fixtures (faucets, switches, doors, windows) are meant to be mounted: load them
        # with a fixed base in a simulator
        "fixed_base": category_fixed_base(obj.category),
        "bounds": _r(obj.bounds()),
        "templates": obj.templates,
        "parameters": {k: {kk: _r(vv) for kk, vv in p.to_json().items()} for k, p in sorted(obj.params.items())},
        "links": [{"name": lk.name, "parts": [p.name for p in lk.parts],
                   "joint": lk.joint.name if lk.joint else None} for lk in obj.links],
        "joints": joints,
        "parts": parts,
        "validation": obj.report,
    }


def annotation_text(obj, grasps=None) -> str:
    """``annotation.json`` of ``obj``: :func:`annotation_dict` as JSON indented by one
    space (the text of ``json.dumps(..., indent=1)``)."""
    return dumps_indented(annotation_dict(obj, grasps), indent=1) + "\n"
