"""Validate object folders on disk: artipg's own and PartNet-Mobility style.

A folder holds a URDF (``mobility.urdf``, or the only ``*.urdf`` in it) and its
meshes, and possibly an artipg ``annotation.json``. The geometric checks run on

- the exact primitives, when the annotation names a registered category and
  regenerating it from the recorded seed and parameters reproduces the URDF's
  joints (the folder is then an untouched artipg export);
- otherwise the URDF's visual geometry: meshes loaded with trimesh (each visual
  element is a part; an artipg link mesh is split back into its closed
  components), boxes, cylinders and spheres as exact primitives. Links on fixed
  joints are parts of their parent's rigid body (:func:`rigid_bodies`). Mesh
  distances come from :mod:`artipg.validate.mesh_sdf`: penetration depths into
  closed meshes, open meshes (most PartNet-Mobility parts) as shells.

The simulator checks always run on the URDF file itself.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from artipg.validate.checks import Tolerances, run_checks
from artipg.validate.kinematics import Kinematics
from artipg.validate.report import Report
from artipg.validate.mesh_sdf import MeshPieces
from artipg.export.annotation import annotated_fixed_base

#: Largest difference (metres / radians) between a folder's URDF joints and the
#: regenerated object's for the exact path to be used.
MATCH_TOL = 1e-4
#: A mesh is split into its connected components (one piece each) when it has at
#: most this many; otherwise it stays one piece.
MAX_COMPONENTS = 64


def find_urdf(folder: Path) -> Path:
    """The object's URDF in ``folder``; raises FileNotFoundError."""
    folder = Path(folder)
    if folder.is_file() and folder.suffix == ".urdf":
        return folder
    p = folder / "mobility.urdf"
    if p.is_file():
        return p
    cands = sorted(folder.glob("*.urdf"))
    if len(cands) == 1:
        return cands[0]
    raise FileNotFoundError(f"no mobility.urdf (or single *.urdf) in {folder}")


def find_objects(paths) -> list[Path]:
    """Object folders under ``paths``: a folder with a URDF is an object, any other
    folder is searched recursively for ``mobility.urdf`` files (not inside object
    folders)."""
    out: list[Path] = []
    for p in map(Path, paths):
        try:
            find_urdf(p)
            out.append(p)
            continue
        except FileNotFoundError:
            pass
        if p.is_dir():
            found = sorted(u.parent for u in p.rglob("mobility.urdf") if not u.parent.name.startswith(".tmp-"))
            # a folder inside an object folder is part of that object (a copy's leftovers)
            keep = set(found)
            out += [f for f in found if not any(q in keep for q in f.parents)]
        else:
            raise FileNotFoundError(f"{p}: not an object folder")
    return out


def validate_folder(folder, tol: Tolerances | None = None, simulate: bool = True, sim_options=None,
                    seed: int = 0, fixed_base: bool | None = None) -> tuple[Report, dict]:
    """Validate the object folder ``folder``.

    Parameters
    ----------
    folder : path
    tol : Tolerances, optional
        Default: :class:`Tolerances` (metres) for artipg's own exports checked on
        their exact primitives; :func:`relative_tolerances` of the object's
        bounding-box diagonal for any other folder (third-party objects are often
        unitless: PartNet-Mobility normalises them to a diagonal of about 2).
    simulate : bool
        Run the pybullet / MuJoCo checks on the URDF.
    sim_options : artipg.validate.sim.SimOptions, optional
    seed : int
        Seed of the surface samples of mesh geometry.
    fixed_base : bool, optional
        Simulate the object mounted instead of dropping it on a floor; by default
        what its ``annotation.json`` says (``validation.fixed_base``, else its
        category's policy), False for folders without one.

    Returns
    -------
    report : Report
    meta : dict
        ``{"path", "urdf", "geometry": "exact" | "mesh", "category", "seed", "fixed_base"}``.
    """
    folder = Path(folder)
    urdf = find_urdf(folder)
    meta = {"path": str(folder), "urdf": str(urdf), "geometry": "mesh", "category": None, "seed": None}
    obj = _regenerate(folder / "annotation.json", urdf) if (folder / "annotation.json").is_file() else None
    if obj is not None:
        from artipg.validate.api import check_object

        tol = tol or Tolerances()
        report = check_object(obj, tol)
        meta.update(geometry="exact", category=obj.category, seed=int(obj.seed))
    else:
        kin, pieces = load_urdf_geometry(urdf, np.random.default_rng([seed, 0x6E0]))
        diag = rest_diagonal(kin, pieces)
        tol = tol or relative_tolerances(diag)
        meta["diagonal"] = diag
        report = Report(run_checks(kin, pieces, tol), tol.to_json())
        floor_z = rest_floor(kin, pieces)
    if fixed_base is None:
        fixed_base = annotated_fixed_base(folder / "annotation.json")
    meta["fixed_base"] = bool(fixed_base)
    if simulate:
        from artipg.validate.sim import SimOptions, simulate_urdf

        opts = sim_options or SimOptions()
        if obj is not None:
            report.checks["simulator"] = simulate_urdf(urdf, opts, fixed_base)
        else:  # third-party: on the floor, flat collision meshes left out, tolerances scaled
            import tempfile

            from artipg.validate import third_party

            if sim_options is None:
                opts = third_party.sim_options(opts, tol.penetration / Tolerances().penetration)
            with tempfile.TemporaryDirectory(prefix="artipg-tp-") as tmp:
                copy = third_party.prepared_urdf(urdf, floor_z, Path(tmp) / urdf.name)
                report.checks["simulator"] = simulate_urdf(copy, opts, fixed_base)
    return report, meta


#: Tolerances of folders checked on their meshes, per unit of the object's
#: bounding-box diagonal at rest, calibrated on the PartNet-Mobility development
#: split (see docs/validation.md): penetration 0.25 % (2.5 mm on a 1 m object, 5
#: units/1000 at PartNet-Mobility's diagonal of 2), gaps 0.5 % (the pieces of one
#: rigid body in those models stand up to that far apart without being detached).
RELATIVE_PENETRATION = 2.5e-3
RELATIVE_FLOATING = 5e-3


def relative_tolerances(diagonal: float) -> Tolerances:
    """:class:`Tolerances` for an object whose bounding-box diagonal at rest is
    ``diagonal`` (in its own units): :data:`RELATIVE_PENETRATION` and
    :data:`RELATIVE_FLOATING` times it."""
    return Tolerances(penetration=RELATIVE_PENETRATION * diagonal, floating=RELATIVE_FLOATING * diagonal)


def rest_diagonal(kin: Kinematics, pieces) -> float:
    """Diagonal of the bounding box of all pieces at rest (object units)."""
    from artipg.validate.contacts import world_boxes

    W0 = kin.poses()[pieces.link] @ pieces.T
    c, h = world_boxes(pieces, W0)
    return float(np.linalg.norm((c + h).max(axis=0) - (c - h).min(axis=0)))


def rest_floor(kin: Kinematics, pieces) -> float:
    """Height (object units) of the lowest point of the pieces' boxes at rest."""
    from artipg.validate.contacts import world_boxes

    c, h = world_boxes(pieces, kin.poses()[pieces.link] @ pieces.T)
    return float((c - h)[:, 2].min())


# ------------------------------------------------------------------ artipg folders

def _regenerate(annotation: Path, urdf: Path):
    """The artipg object a folder was exported from, or None when it cannot be
    reproduced exactly (unknown category, other version, edited URDF)."""
    import artipg

    try:
        ann = json.loads(annotation.read_text())
        if ann.get("category") not in artipg.categories() or ann.get("version") != artipg.__version__:
            return None
        rep = (ann.get("validation") or {}).get("repair") or {}
        seed = int(rep.get("source_seed", ann["seed"]))
        overrides = {k: v["value"] for k, v in ann.get("parameters", {}).items() if v.get("kind") != "fixed"}
        obj = artipg.generate(ann["category"], seed, overrides)
    except (ValueError, KeyError, TypeError):
        return None
    kin = _urdf_kinematics(_load_robot(urdf))[0]
    ours = Kinematics.of(obj)
    if sorted(kin.names) != sorted(ours.names):
        return None
    idx = {n: i for i, n in enumerate(kin.names)}
    for i, n in enumerate(ours.names):
        k = idx[n]
        if ours.joint_types[i] != kin.joint_types[k] or not np.allclose(ours.origin[i], kin.origin[k], atol=MATCH_TOL):
            return None
        if ours.joint_types[i] in ("revolute", "prismatic") and not np.allclose(ours.limits[i], kin.limits[k],
                                                                              atol=MATCH_TOL):
            return None
    obj.seed = int(ann["seed"])
    return obj


# ------------------------------------------------------------------ URDF + meshes

def _load_robot(urdf: Path):
    import yourdfpy

    return yourdfpy.URDF.load(str(urdf), build_scene_graph=False, load_meshes=False,
                              build_collision_scene_graph=False, load_collision_meshes=False).robot


def _urdf_kinematics(robot) -> tuple[Kinematics, dict]:
    """Kinematic tree of a yourdfpy robot model, root first; and link name -> index."""
    children = {j.child for j in robot.joints}
    by_child = {j.child: j for j in robot.joints}
    roots = [lk.name for lk in robot.links if lk.name not in children]
    if len(roots) != 1:
        raise ValueError(f"URDF must have one root link, found {roots}")
    order, todo = [], [roots[0]]
    kids: dict = {}
    for j in robot.joints:
        kids.setdefault(j.parent, []).append(j.child)
    while todo:
        n = todo.pop(0)
        order.append(n)
        todo += kids.get(n, [])
    idx = {n: i for i, n in enumerate(order)}
    L = len(order)
    parent = np.full(L, -1, dtype=np.int64)
    origin = np.tile(np.eye(4), (L, 1, 1))
    axis = np.tile([0.0, 0.0, 1.0], (L, 1))
    limits = np.zeros((L, 2))
    jn, jt = [""] * L, ["fixed"] * L
    for n in order[1:]:
        j = by_child[n]
        i = idx[n]
        parent[i] = idx[j.parent]
        origin[i] = j.origin if j.origin is not None else np.eye(4)
        if j.axis is not None:
            axis[i] = np.asarray(j.axis, dtype=float) / np.linalg.norm(j.axis)
        jt[i] = j.type if j.type in ("revolute", "prismatic", "continuous") else "fixed"
        jn[i] = j.name
        if j.type == "continuous":
            limits[i] = (-np.inf, np.inf)
        elif j.limit is not None and j.limit.lower is not None and j.limit.upper is not None:
            limits[i] = (j.limit.lower, j.limit.upper)
    return Kinematics(order, parent, jn, jt, origin, axis, limits), idx


def load_urdf_geometry(urdf, rng: np.random.Generator) -> tuple[Kinematics, MeshPieces]:
    """Kinematics and visual geometry pieces of a URDF file (see module docstring)."""
    import trimesh

    from artipg.geometry import cuboid, cylinder, sphere

    urdf = Path(urdf)
    robot = _load_robot(urdf)
    kin, idx = _urdf_kinematics(robot)
    body, moved = rigid_bodies(kin)
    prims, meshes, part_names, part_link = [], [], [], []
    for link in robot.links:
        li = body[idx[link.name]]
        for k, vis in enumerate(link.visuals):
            T = moved[idx[link.name]] @ (vis.origin if vis.origin is not None else np.eye(4))
            g = vis.geometry
            pi = len(part_names)
            part_names.append(vis.name or f"{link.name}_visual{k}")
            part_link.append(li)
            if g.box is not None:
                prims.append((li, pi, *cuboid(*np.asarray(g.box.size, dtype=float))[:2], T))
            elif g.cylinder is not None:
                prims.append((li, pi, *cylinder(g.cylinder.radius, g.cylinder.length)[:2], T))
            elif g.sphere is not None:
                prims.append((li, pi, *sphere(g.sphere.radius)[:2], T))
            elif g.mesh is not None:
                path = _mesh_path(urdf, g.mesh.filename)
                m = trimesh.load(str(path), force="mesh", process=False)
                # one vertex per position: texture and normal seams must not cut the
                # surface into pieces (the component split below reads connectivity)
                m.merge_vertices(merge_tex=True, merge_norm=True)
                if g.mesh.scale is not None:
                    m.apply_scale(np.broadcast_to(np.asarray(g.mesh.scale, dtype=float), (3,)))
                parts = [m]
                if len(m.faces) and 1 < _n_components(m) <= MAX_COMPONENTS:  # labels first: split is costly
                    parts = m.split(only_watertight=False)
                    if not all(p.is_watertight for p in parts):
                        parts = [m]
                for piece in parts:
                    box = _as_box(piece)
                    if box is not None:  # boxes get the exact box-box tests
                        prims.append((li, pi, *cuboid(*box[0])[:2], T @ box[1]))
                    else:
                        meshes.append((li, pi, piece, T))
    M = len(prims) + len(meshes)
    if M == 0:
        raise ValueError(f"{urdf}: no visual geometry")
    width = max([len(p[3]) for p in prims], default=1)
    link = np.array([p[0] for p in prims] + [m[0] for m in meshes], dtype=np.int64)
    part = np.array([p[1] for p in prims] + [m[1] for m in meshes], dtype=np.int64)
    Ts = np.array([p[4] for p in prims] + [m[3] for m in meshes], dtype=float).reshape(M, 4, 4)
    geom = [p[2] for p in prims] + [None] * len(meshes)
    params = np.zeros((M, width))
    center = np.zeros((M, 3))
    half = np.zeros((M, 3))
    for i, p in enumerate(prims):
        params[i, :len(p[3])] = p[3]
        b = p[2].bounds(p[3])
        center[i], half[i] = 0.5 * (b[0] + b[1]), 0.5 * (b[1] - b[0])
    mesh_map = {}
    for k, (_, _, m, _) in enumerate(meshes):
        i = len(prims) + k
        mesh_map[i] = m
        b = m.bounds
        center[i], half[i] = 0.5 * (b[0] + b[1]), 0.5 * (b[1] - b[0])
    return kin, MeshPieces(link, part, Ts, center, half, geom, params, part_names, np.array(part_link), rng, mesh_map)


def rigid_bodies(kin: Kinematics) -> tuple[np.ndarray, np.ndarray]:
    """The rigid body of every link: the link itself, or for a link on a fixed joint
    the body of its parent (a handle fixed to its door is part of the door).

    A third-party URDF's fixed joints join pieces of one rigid body (PartNet-Mobility
    names them so, and the simulators merge them); its geometry is checked as that
    body's parts, so a handle embedded in its door is its mounting, not a collision
    between links, and a handle off its door is a floating part.

    Returns
    -------
    body : (L,) int64
        Link index of each link's rigid body (the root's is 0).
    moved : (L, 4, 4) float64
        Pose of each link in its body's frame at rest.
    """
    P = kin.poses()
    body = np.arange(kin.n_links)
    for i in range(1, kin.n_links):  # parents come first
        if kin.joint_types[i] == "fixed":
            body[i] = body[kin.parent[i]]
    moved = np.linalg.inv(P[body]) @ P
    return body, moved


def _n_components(mesh) -> int:
    """Number of face-connected components of ``mesh``."""
    import trimesh

    labels = trimesh.graph.connected_component_labels(mesh.face_adjacency, node_count=len(mesh.faces))
    return int(labels.max()) + 1 if len(labels) else 0


def _as_box(mesh):
    """(extents (3,), pose (4, 4)) when ``mesh`` is a closed box (8 corners), else None."""
    v = np.unique(np.round(np.asarray(mesh.vertices), 9), axis=0)
    if len(v) != 8 or not mesh.is_watertight:
        return None
    obb = mesh.bounding_box_oriented
    ext = np.asarray(obb.primitive.extents, dtype=float)
    if ext.min() <= 0 or abs(obb.volume - abs(mesh.volume)) > 1e-6 * obb.volume:
        return None
    return tuple(ext), np.asarray(obb.primitive.transform, dtype=float)


def _mesh_path(urdf: Path, filename: str) -> Path:
    f = filename
    if f.startswith("package://"):
        f = f.split("/", 3)[-1] if f.count("/") >= 3 else f[len("package://"):]
    if f.startswith("file://"):
        f = f[len("file://"):]
    p = Path(f)
    p = p if p.is_absolute() else urdf.parent / p
    if not p.is_file():
        raise FileNotFoundError(f"{urdf}: mesh {filename} not found")
    return p
