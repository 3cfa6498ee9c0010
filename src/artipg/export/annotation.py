"""``annotation.json``: structure, parameters, part poses and grasps of an object."""

from __future__ import annotations

import json

import numpy as np

import artipg


def _r(x, nd=6):
    """Round floats (nested lists) for a stable, compact JSON."""
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_r(v, nd) for v in x]
    if isinstance(x, (float, np.floating)):
        v = round(float(x), nd)
        return 0.0 if v == 0 else v
    if isinstance(x, np.integer):
        return int(x)
    return x


def annotation_dict(obj) -> dict:
    """Everything about ``obj`` except geometry, as JSON-ready data."""
    poses = obj.part_poses()
    parts = []
    for i, part in enumerate(obj.parts):
        canon = poses[i] @ part.canonical
        parts.append({
            "name": part.name,
            "instance": i,
            "link": obj.links[int(obj.part_link[i])].name,
            "semantic": part.semantic,
            "template": part.template,
            "actionable": part.actionable,
            "pose": _r(canon),
            "size": _r(part.canonical_size()),
            "affordances": sorted(part.regions),
            "grasps": [{"pose": _r(poses[i] @ g.pose), "width": _r(g.width), "open_dir": _r(poses[i][:3, :3] @ g.open_dir)}
                       for g in part.grasps],
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
        "bounds": _r(obj.bounds()),
        "templates": obj.templates,
        "parameters": {k: {kk: _r(vv) for kk, vv in p.to_json().items()} for k, p in sorted(obj.params.items())},
        "links": [{"name": lk.name, "parts": [p.name for p in lk.parts],
                   "joint": lk.joint.name if lk.joint else None} for lk in obj.links],
        "joints": joints,
        "parts": parts,
        "validation": obj.report,
    }


def annotation_text(obj) -> str:
    return json.dumps(annotation_dict(obj), indent=1, sort_keys=False) + "\n"
