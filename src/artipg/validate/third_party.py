"""Simulating third-party URDFs (PartNet-Mobility) as the simulator check expects.

The simulator check (:mod:`artipg.validate.sim`) is written for artipg's exports: the
object frame's origin on the floor, metres, one convex piece per collision element.
A PartNet-Mobility folder differs in ways that are not defects of the object:

- its origin is the centre of the object (normalised to a bounding-box diagonal of
  about 2): dropped "on a floor" at z = 0 it starts half underground and is flung
  away. The copy simulated here gets a new root link, ``artipg_floor``, that holds
  the old root so that the lowest point of the visual geometry at rest is at z = 0;
- some collision meshes are flat (a decal, a glass pane modelled as one sheet):
  MuJoCo refuses the whole file ("mesh has coplanar vertices, cannot compute convex
  hull"). They enclose no volume, so they are left out of the copy's collision
  geometry (their visuals stay);
- it is unitless: the simulator's metric tolerances (drift, rest contact depth) are
  scaled like the geometric ones (:func:`sim_options`).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import replace
from pathlib import Path

import numpy as np

#: A mesh is flat when the smallest extent of its vertices across their best-fit
#: plane is below this fraction of its largest extent.
FLAT = 1e-6


def sim_options(opts, scale: float):
    """``opts`` (:class:`artipg.validate.sim.SimOptions`) with its length tolerances
    (``drift_tol``, ``contact_tol``) multiplied by ``scale`` (a length per metre)."""
    return replace(opts, drift_tol=opts.drift_tol * scale, contact_tol=opts.contact_tol * scale)


def _flat(path: Path) -> bool:
    import trimesh

    try:
        v = np.asarray(trimesh.load(str(path), force="mesh", process=False).vertices, dtype=float)
    except Exception:  # unreadable: let the engines say so
        return False
    if len(v) < 4:
        return True
    s = np.linalg.svd(v - v.mean(axis=0), compute_uv=False)
    return bool(s[-1] <= FLAT * max(s[0], 1e-300))


def prepared_urdf(urdf: Path, floor_z: float, out: Path) -> Path:
    """Write the copy of ``urdf`` described in the module docstring to ``out``.

    Parameters
    ----------
    urdf : Path
    floor_z : float
        Height of the object's lowest point at rest, in its root frame (object units).
    out : Path
        The copy (mesh references become absolute paths).
    """
    from artipg.validate.folder import _mesh_path

    urdf = Path(urdf).resolve()
    tree = ET.parse(urdf)
    robot = tree.getroot()
    flat: dict = {}
    for link in robot.iter("link"):
        for col in list(link.findall("collision")):
            for m in col.iter("mesh"):
                try:
                    p = _mesh_path(urdf, m.get("filename", ""))
                except FileNotFoundError:
                    continue
                if p not in flat:
                    flat[p] = _flat(p)
                if flat[p]:
                    link.remove(col)
                    break
    for m in robot.iter("mesh"):
        try:
            m.set("filename", str(_mesh_path(urdf, m.get("filename", ""))))
        except FileNotFoundError:
            pass
    children = {j.find("child").get("link") for j in robot.iter("joint") if j.find("child") is not None}
    roots = [lk.get("name") for lk in robot.iter("link") if lk.get("name") not in children]
    if len(roots) == 1 and floor_z != 0.0:
        floor = ET.Element("link", name="artipg_floor")
        joint = ET.Element("joint", name="artipg_floor_joint", type="fixed")
        ET.SubElement(joint, "parent", link="artipg_floor")
        ET.SubElement(joint, "child", link=roots[0])
        ET.SubElement(joint, "origin", xyz=f"0 0 {-floor_z!r}", rpy="0 0 0")
        robot.insert(0, joint)
        robot.insert(0, floor)
    tree.write(out)
    return Path(out)
