"""PartNet-Mobility style ``semantics.txt``: one ``<link> <motion> <label>`` per link."""

from __future__ import annotations

_MOTION = {None: "static", "fixed": "static", "revolute": "hinge", "continuous": "hinge", "prismatic": "slider"}


def semantics_text(obj) -> str:
    """One line per link; the label is the semantic of the link's first part."""
    lines = []
    for link in obj.links:
        motion = _MOTION[link.joint.type if link.joint else None]
        label = link.parts[0].semantic if link.parts else "body"
        lines.append(f"{link.name} {motion} {label}")
    return "\n".join(lines) + "\n"
