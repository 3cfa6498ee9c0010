"""The pybullet simulator check (see :mod:`artipg.validate.sim`)."""

from __future__ import annotations

import os
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from artipg.validate.report import Issue
from artipg.validate.sim_common import (Joint, SimOptions, blocked_issues, body_drift, box_corners, mesh_path,
                                         others_state, rigid_urdf, run_until)


#: Collision margin (metres) by which pybullet's URDF importer pads every convex mesh
#: (not changeable from Python for URDF links; :func:`pybullet_urdf` compensates).
PYBULLET_MESH_MARGIN = 1e-3

#: Penetration (metres) pybullet's solver leaves alone instead of pushing the bodies
#: apart (``contactSlop``): parts that touch, as many do at rest, stay put.
CONTACT_SLOP = 5e-4

#: How far (metres) a cached contact point of pybullet may drift before it is dropped
#: (``contactBreakingThreshold``, 2 cm by default). Its persistent contact manifolds
#: keep points from earlier steps; where a part slides along a curved surface (a lid's
#: edge round a hinge barrel), stale points left behind read as deep penetrations and
#: jam the joint. A few millimetres suits objects built to millimetres.
CONTACT_BREAKING = 2e-3

#: Constraint force mixing of pybullet's solver (``globalCFM``, 0 by default). A
#: contact whose normal no joint can move along (a hinge knuckle between its cheeks,
#: pressed along the hinge axis) is a constraint row with a zero Jacobian; pybullet
#: divides by its zero effective mass and the resulting impulses fling the links
#: apart. A tiny regularisation keeps such rows finite and leaves the others alone.
GLOBAL_CFM = 1e-6



def _import_pybullet():
    """Import pybullet without the build-time banner it prints (from C, to stderr)."""
    import sys

    if "pybullet" in sys.modules:
        return sys.modules["pybullet"]
    sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 2)
            import pybullet
    finally:
        os.dup2(saved, 2)
        os.close(saved)
    return pybullet


def run_pybullet(urdf: Path, joints: list[Joint], opts: SimOptions, fixed_base: bool = False):
    pb = _import_pybullet()
    with tempfile.TemporaryDirectory(prefix="artipg-pb-") as tmp:
        path, inflation = pybullet_urdf(urdf, tmp)
        cid = pb.connect(pb.DIRECT)
        try:
            return _pybullet_run(pb, cid, path, joints, opts, inflation, fixed_base)
        finally:
            pb.disconnect(cid)


def _mesh_vertices(path: Path) -> np.ndarray:
    """All vertices (V, 3) of a mesh file: what pybullet takes the convex hull of."""
    if path.suffix.lower() == ".obj":
        rows = [ln.split()[1:4] for ln in path.read_text().splitlines() if ln.startswith("v ")]
        return np.array(rows, dtype=float).reshape(-1, 3)
    import trimesh

    return np.asarray(trimesh.load(str(path), force="mesh").vertices, dtype=float)


def eroded_hull(vertices: np.ndarray, depth: float) -> tuple[np.ndarray, np.ndarray, float]:
    """The convex hull of ``vertices`` (V, 3) with every face moved inwards by up to
    ``depth`` (metres).

    The erosion stops 0.05 mm short of the radius of the largest ball about the
    vertex centroid inside the hull, so that a piece thinner than ``2 * depth`` keeps
    a sliver of volume (and pybullet pads it by more than it was eroded).

    Returns
    -------
    vertices : ndarray (V', 3)
    faces : ndarray (F, 3)
    eroded : float
        How far the faces moved, metres (``depth`` unless the piece is thinner than
        twice that).
    """
    from scipy.spatial import ConvexHull, HalfspaceIntersection

    hull = ConvexHull(vertices)
    eq = hull.equations  # (F, 4): n . x + d <= 0 inside
    c = vertices[hull.vertices].mean(axis=0)
    inner = float(-(eq[:, :3] @ c + eq[:, 3]).max())
    e = float(min(depth, max(inner - 5e-5, 0.0)))
    if e <= 0.0:
        return vertices, hull.simplices, 0.0
    hs = eq.copy()
    hs[:, 3] += e
    pts = HalfspaceIntersection(hs, c).intersections
    return pts, ConvexHull(pts).simplices, e


def pybullet_urdf(urdf: Path, tmp: str, margin: float = PYBULLET_MESH_MARGIN) -> tuple[Path, dict]:
    """A copy of ``urdf`` whose collision meshes pybullet sees as exported.

    pybullet replaces every collision mesh by the convex hull of its vertices, padded
    by a fixed collision margin (:data:`PYBULLET_MESH_MARGIN`; its boxes, spheres and,
    with ``URDF_USE_IMPLICIT_CYLINDER``, cylinders keep their size). The copy holds
    each mesh's hull eroded by that margin (:func:`eroded_hull`, written to ``tmp``),
    so that the padded hull is the hull itself, with rounded edges, as MuJoCo sees it.

    Returns
    -------
    path : Path
        The copy (in ``tmp``).
    inflation : dict
        {link name: metres} how much larger than its hulls a link's meshes still are
        in pybullet (pieces thinner than twice the margin cannot be eroded fully).
    """
    from artipg.export.meshes import obj_text

    urdf = Path(urdf).resolve()
    Path(tmp).mkdir(parents=True, exist_ok=True)
    tree = ET.parse(urdf)
    inflation = {}
    done: dict = {}  # (file, scale) -> (eroded file or None, erosion): sectors share one hull
    for link in tree.getroot().iter("link"):
        worst = 0.0
        for col in link.findall("collision"):
            for m in col.iter("mesh"):
                src = mesh_path(urdf, m.get("filename", ""))
                key = (str(src), m.get("scale", "1 1 1"))
                if key not in done:
                    try:
                        V = _mesh_vertices(src) * np.array([float(x) for x in key[1].split()])
                        V, F, e = eroded_hull(V, margin)
                        dst = Path(tmp) / f"c{len(done)}.obj"
                        dst.write_text(obj_text(V, F))
                        done[key] = (dst, e)
                    except Exception:  # unreadable or flat: leave it to pybullet as it is
                        done[key] = (None, 0.0)
                dst, e = done[key]
                if dst is None:
                    m.set("filename", str(src))
                else:
                    m.set("filename", str(dst))
                    m.attrib.pop("scale", None)
                worst = max(worst, margin - e)
        inflation[link.get("name")] = worst
    for m in tree.getroot().iter("mesh"):  # visual meshes: absolute paths
        if not Path(m.get("filename", "")).is_absolute():
            m.set("filename", str(mesh_path(urdf, m.get("filename", ""))))
    out = Path(tmp) / urdf.name
    tree.write(out)
    return out, inflation


def _pb_pose(pb, cid, body) -> np.ndarray:
    pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=cid)
    T = np.eye(4)
    T[:3, :3] = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
    T[:3, 3] = pos
    return T


#: Time step of the pybullet simulations, seconds.
PYBULLET_STEP = 1.0 / 240.0


def pybullet_configure(pb, cid) -> tuple[int, int]:
    """Apply the check's engine settings to pybullet client ``cid``.

    Returns
    -------
    shapes : int
        ``loadURDF`` flags for the collision shapes (exact cylinders).
    flags : int
        ``shapes`` plus self-collision, parent-child pairs included.
    """
    shapes = pb.URDF_USE_IMPLICIT_CYLINDER  # exact cylinders, not 32-gon hulls padded by the margin
    flags = pb.URDF_USE_SELF_COLLISION | pb.URDF_USE_SELF_COLLISION_INCLUDE_PARENT | shapes
    pb.setTimeStep(PYBULLET_STEP, physicsClientId=cid)
    pb.setPhysicsEngineParameter(contactSlop=CONTACT_SLOP, contactBreakingThreshold=CONTACT_BREAKING,
                                 globalCFM=GLOBAL_CFM, physicsClientId=cid)
    return shapes, flags


def _pybullet_run(pb, cid, urdf, joints, opts, inflation, fixed_base=False):
    issues, info = [], {}
    shapes, flags = pybullet_configure(pb, cid)
    dt = PYBULLET_STEP
    body = pb.loadURDF(str(urdf), useFixedBase=True, flags=flags, physicsClientId=cid)
    n = pb.getNumJoints(body, physicsClientId=cid)
    index = {pb.getJointInfo(body, i, physicsClientId=cid)[1].decode(): i for i in range(n)}
    names = {i: pb.getJointInfo(body, i, physicsClientId=cid)[12].decode() for i in range(n)}
    names[-1] = pb.getBodyInfo(body, physicsClientId=cid)[0].decode()
    # rest contacts between every pair of links, parents included
    worst = 0.0
    for a in range(-1, n):
        for b in range(a + 1, n):
            cps = pb.getClosestPoints(body, body, 0.0, linkIndexA=a, linkIndexB=b, physicsClientId=cid)
            if not cps:
                continue
            d = min(c[8] for c in cps) + inflation.get(names[a], 0.0) + inflation.get(names[b], 0.0)
            worst = max(worst, -d)
            if d < -opts.contact_tol:
                issues.append(Issue("simulator", "sim_rest_penetration", -d, [names[a], names[b]],
                                    detail="pybullet: collision geometry penetrates at rest"))
    info["rest_penetration"] = worst
    pb.removeBody(body, physicsClientId=cid)
    # drive: all joints to their upper then back to their lower targets, root fixed,
    # frictionless, no gravity (only geometry may stop a joint); fresh body per run
    pb.setGravity(0, 0, 0, physicsClientId=cid)

    live = [j for j in joints if j.name in index]

    def run(sel, others_open=False):
        b = pb.loadURDF(str(urdf), useFixedBase=True, flags=flags, physicsClientId=cid)
        for i in range(-1, n):
            pb.changeDynamics(b, i, lateralFriction=0.0, spinningFriction=0.0, rollingFriction=0.0,
                              physicsClientId=cid)
        ids = [index[j.name] for j in live]
        state = lambda j: pb.getJointState(b, index[j.name], physicsClientId=cid)[0]  # noqa: E731
        base = others_state(live, sel, others_open)

        def drive(goal, watch):
            goal = {**base, **goal}
            pb.setJointMotorControlArray(b, ids, pb.POSITION_CONTROL,
                                         targetPositions=[goal[j.name] for j in live],
                                         forces=[200.0] * len(ids), physicsClientId=cid)
            return run_until(lambda: pb.stepSimulation(physicsClientId=cid), dt, opts,
                              [(j, goal[j.name]) for j in watch], state)

        if others_open:  # open the others first (a rack behind its door)
            drive({}, [j for j in live if j.name in base and base[j.name] != 0.0])
        up = drive({j.name: j.targets()[1] for j in sel}, sel)
        down = drive({j.name: j.targets()[0] for j in sel}, sel)
        pb.removeBody(b, physicsClientId=cid)
        return up + down

    issues += blocked_issues(run, live, opts, "pybullet")
    if fixed_base:
        info["drop"] = "fixed base"
        return issues, info
    pb.setGravity(0, 0, -9.81, physicsClientId=cid)
    # drop on a floor, joints held rigidly at rest (their own contacts were checked above)
    plane = pb.createCollisionShape(pb.GEOM_PLANE, physicsClientId=cid)
    pb.createMultiBody(0, plane, physicsClientId=cid)
    rigid = rigid_urdf(urdf, Path(urdf).with_name("rigid.urdf"))
    body = pb.loadURDF(str(rigid), useFixedBase=False, flags=shapes, physicsClientId=cid)
    lo, hi = pb.getAABB(body, -1, physicsClientId=cid)
    corners = box_corners(lo, hi)
    for _ in range(int(round(opts.settle_seconds / dt))):
        pb.stepSimulation(physicsClientId=cid)
    T0 = _pb_pose(pb, cid, body)
    for _ in range(int(round(opts.drop_seconds / dt))):
        pb.stepSimulation(physicsClientId=cid)
    drift = body_drift(T0, _pb_pose(pb, cid, body), corners)
    info["drift"] = drift
    if drift > opts.drift_tol:
        issues.append(Issue("simulator", "drift", drift, [names[-1]], detail="pybullet: object moves on the floor"))
    return issues, info
