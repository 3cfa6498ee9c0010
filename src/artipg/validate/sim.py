"""Simulator checks: the URDF loads in pybullet and MuJoCo and behaves.

For each engine (short simulations, a few hundred milliseconds per object):

- **load**: the URDF loads (MuJoCo through ``MjSpec``, so that a floor, a free joint
  and position servos can be added);
- **rest contacts**: with parent-child contacts turned on (pybullet
  ``URDF_USE_SELF_COLLISION | URDF_USE_SELF_COLLISION_INCLUDE_PARENT`` with
  ``getClosestPoints``; MuJoCo ``mjDSBL_FILTERPARENT``), no two links of the
  collision geometry penetrate deeper than the tolerance at rest: this is where a
  hollow body exported as one convex hull shows up;
- **drive**: with the root fixed, contacts frictionless and gravity off (so that only
  geometry can block a joint, not friction between touching parts or a servo too
  weak to lift a lid), position control drives all movable joints from rest to their
  upper limits and then back to their lower limits (continuous joints have no
  limits: they must turn a quarter turn either way, +-pi/2); each must get within
  ``joint_tol`` of its target. A joint that is still closing in on its target gets
  more time (up to three times ``drive_seconds``); one that stalls is blocked.
  Joints that miss are driven again alone, first with the others held at rest, then
  with the others opened first (a dishwasher rack comes out only past its open door):
  a joint is blocked when it misses both ways;
- **drop**: the object, free on a floor with its joints held rigidly at rest (made
  fixed in a copy of the URDF), settles for ``settle_seconds`` and then moves less
  than ``drift_tol`` in ``drop_seconds`` (largest displacement of the corners of the
  root link's bounding box); the engines' default contact filters apply here.
  Fixtures (``Category.fixed_base``: faucets, switches, doors, windows) are used
  mounted: they are not dropped, and ``info["drop"]`` says ``"fixed base"``.

Engine settings, each fixing a simulator artefact that would otherwise read as a
defect (they never relax a tolerance):

- pybullet pads every convex mesh with a 1 mm collision margin
  (:data:`PYBULLET_MESH_MARGIN`, fixed for URDF links) and turns cylinders into
  padded 32-gon hulls: cylinders are loaded as exact shapes
  (``URDF_USE_IMPLICIT_CYLINDER``) and every mesh as its hull shrunk by the margin
  (:func:`pybullet_urdf`), so that pybullet sees the exported geometry as MuJoCo does
  (pieces thinner than 2 mm keep part of the padding, which the rest-contact
  tolerance adds back, per link);
- pybullet keeps contact points from earlier steps until they drift 2 cm; a lid's edge
  sliding round a hinge barrel leaves stale points behind that jam it
  (:data:`CONTACT_BREAKING`);
- a contact no joint can move along (a knuckle between its cheeks pressed along the
  hinge axis, a knob's back face on its panel, a cap on its neck) has zero effective
  mass: pybullet divides by it (:data:`GLOBAL_CFM` regularises) and MuJoCo makes it
  infinitely stiff when the body cannot translate (:data:`INVWEIGHT_FLOOR`); either
  way round-off turns the unbounded force into torque that flings the part.
"""

from __future__ import annotations

import math
import os
import re
import tempfile
import xml.etree.ElementTree as ET
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from artipg.validate.report import CheckResult, Issue


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


@dataclass(frozen=True)
class SimOptions:
    """Settings of the simulator checks (seconds, metres, radians).

    Attributes
    ----------
    engines : tuple of str
        ``"pybullet"`` and / or ``"mujoco"``.
    settle_seconds : float
        Time the object settles into its contacts before the drift is measured.
    drop_seconds : float
        Simulated time on the floor over which the drift is measured.
    drift_tol : float
        Largest accepted displacement on the floor, metres.
    drive_seconds : float
        Simulated time per drive phase (all joints to upper, then to lower limits);
        joints still closing in on their targets get up to twice as much again.
    joint_tol : float
        Accepted joint error as a fraction of the joint's range (at least 0.01 rad
        or 2 mm).
    contact_tol : float
        Largest accepted penetration between links of the collision geometry at rest.
    """

    engines: tuple = ("pybullet", "mujoco")
    settle_seconds: float = 0.25
    drop_seconds: float = 1.0
    drift_tol: float = 1e-3
    drive_seconds: float = 1.0
    joint_tol: float = 0.03
    contact_tol: float = 1e-3

    def to_json(self) -> dict:
        return {k: list(v) if isinstance(v, tuple) else v for k, v in asdict(self).items()}


def simulate_object(obj, opts: SimOptions = SimOptions(), fixed_base: bool | None = None) -> CheckResult:
    """Export ``obj`` (URDF + meshes) to a temporary folder and simulate it.

    ``fixed_base`` defaults to the registered category's policy
    (:func:`category_fixed_base`): fixtures are simulated mounted, not dropped.
    """
    from artipg.export.urdf import build_urdf, urdf_text

    if fixed_base is None:
        fixed_base = category_fixed_base(obj.category)

    robot, meshes = build_urdf(obj, visuals=False)
    with tempfile.TemporaryDirectory(prefix="artipg-sim-") as d:
        for rel, text in meshes.items():
            p = Path(d) / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text)
        urdf = Path(d) / "mobility.urdf"
        urdf.write_text(urdf_text(robot))
        return simulate_urdf(urdf, opts, fixed_base)


def category_fixed_base(name: str) -> bool:
    """``fixed_base`` of the registered category ``name`` (False for unknown names)."""
    import artipg

    try:
        return bool(getattr(artipg.get_category(name), "fixed_base", False))
    except (KeyError, ValueError):
        return False


def simulate_urdf(urdf, opts: SimOptions = SimOptions(), fixed_base: bool = False) -> CheckResult:
    """Run the simulator checks on the URDF file ``urdf`` (see module docstring).

    Parameters
    ----------
    urdf : path
    opts : SimOptions
    fixed_base : bool
        The object is a fixture (mounted on a wall, a sink, in a frame): it is not
        dropped on a floor; ``info["drop"]`` says ``"fixed base"`` instead of giving a
        drift.
    """
    urdf = Path(urdf).resolve()
    joints = _urdf_joints(urdf)
    issues, info = [], {"fixed_base": bool(fixed_base)}
    for engine in opts.engines:
        run = {"pybullet": _pybullet, "mujoco": _mujoco}[engine]
        try:
            eng_issues, eng_info = run(urdf, joints, opts, fixed_base)
        except Exception as e:  # an engine that cannot load the file is a failure, not a crash
            eng_issues, eng_info = [Issue("simulator", "load_failed", 1.0, detail=f"{engine}: {e}".strip()[:300])], {}
        issues += eng_issues
        info[engine] = eng_info
    return CheckResult("simulator", not issues, max([0.0] + [i.amount for i in issues]), issues, info)


# ------------------------------------------------------------------ URDF helpers

@dataclass
class _Joint:
    name: str
    type: str
    lo: float
    hi: float

    def targets(self) -> tuple[float, float]:
        if self.type == "continuous":
            return (-0.5 * math.pi, 0.5 * math.pi)
        return (self.lo, self.hi)

    def span(self) -> float:
        lo, hi = self.targets()
        return hi - lo

    def tol(self, frac: float) -> float:
        return max(frac * self.span(), 0.002 if self.type == "prismatic" else 0.01)


def _urdf_joints(urdf: Path) -> list[_Joint]:
    """Movable joints of a URDF (name, type, limits), in file order."""
    out = []
    for j in ET.parse(urdf).getroot().iter("joint"):
        t = j.get("type")
        if t not in ("revolute", "prismatic", "continuous"):
            continue
        lim = j.find("limit")
        lo = float(lim.get("lower", 0.0)) if lim is not None else 0.0
        hi = float(lim.get("upper", 0.0)) if lim is not None else 0.0
        out.append(_Joint(j.get("name"), t, lo, hi))
    return out


def rigid_urdf(urdf: Path, out: Path) -> Path:
    """Write a copy of ``urdf`` to ``out`` with every movable joint made fixed.

    The drop test holds the joints at rest this way: position servos (pybullet's
    velocity-level motors above all) give way a little under the object's weight, and
    an office chair then creeps on its casters; what is tested is whether the object
    as a whole stands.
    """
    tree = ET.parse(urdf)
    for j in tree.getroot().iter("joint"):
        if j.get("type") in ("revolute", "prismatic", "continuous"):
            j.set("type", "fixed")
    tree.write(out)
    return Path(out)


def _corners(lo, hi) -> np.ndarray:
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def _drift(T0: np.ndarray, T1: np.ndarray, corners: np.ndarray) -> float:
    """Largest displacement (metres) of ``corners`` (8, 3) moved rigidly from T0 to T1."""
    D = T1 @ np.linalg.inv(T0)
    moved = corners @ D[:3, :3].T + D[:3, 3]
    return float(np.linalg.norm(moved - corners, axis=1).max())


# ------------------------------------------------------------------ pybullet

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


def _pybullet(urdf: Path, joints: list[_Joint], opts: SimOptions, fixed_base: bool = False):
    pb = _import_pybullet()
    with tempfile.TemporaryDirectory(prefix="artipg-pb-") as tmp:
        path, inflation = pybullet_urdf(urdf, tmp)
        cid = pb.connect(pb.DIRECT)
        try:
            return _pybullet_run(pb, cid, path, joints, opts, inflation, fixed_base)
        finally:
            pb.disconnect(cid)


def _mesh_path(urdf: Path, filename: str) -> Path:
    """A URDF mesh reference (relative, ``package://pkg/...`` or ``file://...``) as a path."""
    f = re.sub(r"^package://[^/]*/", "", filename)
    f = f[len("file://"):] if f.startswith("file://") else f
    return (urdf.parent / f).resolve()


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
                src = _mesh_path(urdf, m.get("filename", ""))
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
            m.set("filename", str(_mesh_path(urdf, m.get("filename", ""))))
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
        base = _others(live, sel, others_open)

        def drive(goal, watch):
            goal = {**base, **goal}
            pb.setJointMotorControlArray(b, ids, pb.POSITION_CONTROL,
                                         targetPositions=[goal[j.name] for j in live],
                                         forces=[200.0] * len(ids), physicsClientId=cid)
            return _run_until(lambda: pb.stepSimulation(physicsClientId=cid), dt, opts,
                              [(j, goal[j.name]) for j in watch], state)

        if others_open:  # open the others first (a rack behind its door)
            drive({}, [j for j in live if j.name in base and base[j.name] != 0.0])
        up = drive({j.name: j.targets()[1] for j in sel}, sel)
        down = drive({j.name: j.targets()[0] for j in sel}, sel)
        pb.removeBody(b, physicsClientId=cid)
        return up + down

    issues += _blocked_issues(run, live, opts, "pybullet")
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
    corners = _corners(lo, hi)
    for _ in range(int(round(opts.settle_seconds / dt))):
        pb.stepSimulation(physicsClientId=cid)
    T0 = _pb_pose(pb, cid, body)
    for _ in range(int(round(opts.drop_seconds / dt))):
        pb.stepSimulation(physicsClientId=cid)
    drift = _drift(T0, _pb_pose(pb, cid, body), corners)
    info["drift"] = drift
    if drift > opts.drift_tol:
        issues.append(Issue("simulator", "drift", drift, [names[-1]], detail="pybullet: object moves on the floor"))
    return issues, info


def _run_until(step, dt, opts, targets, state):
    """Step until every (joint, target) is within tolerance, for ``drive_seconds``, then
    on in quarter-second chunks (up to three times as long) while a joint that has not
    arrived still closes on its target by more than 2 % of its range per chunk.

    Returns [(joint, target, reached)] for every joint in ``targets``.
    """
    def missing():
        return [(j, t) for j, t in targets if abs(state(j) - t) > j.tol(opts.joint_tol)]

    check = max(1, int(round(0.1 / dt)))
    for k in range(int(round(opts.drive_seconds / dt))):
        step()
        if k % check == check - 1 and not missing():
            break
    chunk = int(round(0.25 / dt))
    extra = int(round(2 * opts.drive_seconds / 0.25))
    for _ in range(extra):
        todo = missing()
        if not todo:
            break
        before = {j.name: abs(state(j) - t) for j, t in todo}
        for _ in range(chunk):
            step()
        if all(before[j.name] - abs(state(j) - t) < 0.02 * j.span() for j, t in todo):
            break  # stalled: blocked, not slow
    return [(j, t, float(state(j))) for j, t in targets]


def _others(live, sel, others_open: bool) -> dict:
    """Targets of the joints not driven: rest, or their upper targets (``others_open``)."""
    names = {j.name for j in sel}
    return {j.name: (j.targets()[1] if others_open and j.name not in names else 0.0) for j in live}


def _blocked_issues(run, joints, opts, engine: str) -> list[Issue]:
    """One ``joint_blocked`` issue per joint :func:`_blocked` finds in ``engine``."""
    return [Issue("simulator", "joint_blocked", abs(reached - target), joint=j.name, q=reached,
                  detail=f"{engine}: target {target:.4g} not reached")
            for j, target, reached in _blocked(run, joints, opts)]


def _blocked(run, joints, opts):
    """Joints that miss a target when all are driven together, again when driven alone
    with the others held at rest, and again when driven alone after the others have
    been opened (a dishwasher rack cannot come out past its closed door, nor a drawer
    behind a cabinet door): [(joint, target, reached)] of the run with the others at
    rest. ``run(sel, others_open)`` returns [(joint, target, reached)] for ``sel``."""
    if not joints:
        return []

    def misses(res):
        return [(j, t, q) for j, t, q in res if abs(q - t) > j.tol(opts.joint_tol)]

    failed = {j.name for j, t, q in misses(run(joints, False))}
    out = []
    for j in joints:
        if j.name not in failed:
            continue
        miss = misses(run([j], False))
        if miss and len(joints) > 1 and not misses(run([j], True)):
            continue
        out += miss
    return out


# ------------------------------------------------------------------ MuJoCo

#: Least translational mobility estimate (times 1 / mass) MuJoCo may use to soften the
#: contacts of a jointed body (see :func:`_mj_model`).
INVWEIGHT_FLOOR = 0.1

_MJ_COMPILER = {"discardvisual": "true", "fusestatic": "false", "strippath": "false", "balanceinertia": "true"}


def _mujoco_urdf(urdf: Path, tmp: str) -> Path:
    """A copy of ``urdf`` MuJoCo can load: absolute mesh paths, links kept apart."""
    tree = ET.parse(urdf)
    root = tree.getroot()
    for m in root.iter("mesh"):
        m.set("filename", str(_mesh_path(urdf, m.get("filename", ""))))
    for el in list(root.findall("mujoco")):
        root.remove(el)
    mj = ET.SubElement(root, "mujoco")
    ET.SubElement(mj, "compiler", **_MJ_COMPILER)
    out = Path(tmp) / "model.urdf"
    tree.write(out)
    return out


def _mujoco(urdf: Path, joints: list[_Joint], opts: SimOptions, fixed_base: bool = False):
    import mujoco

    with tempfile.TemporaryDirectory(prefix="artipg-mj-") as tmp:
        path = _mujoco_urdf(urdf, tmp)
        return _mujoco_run(mujoco, path, joints, opts, fixed_base)


def _mj_model(mujoco, path, joints, free: bool, parent_contacts: bool = True):
    spec = mujoco.MjSpec.from_file(str(path))
    root = spec.worldbody.first_body()
    if free:
        root.add_freejoint()
        spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 1])
    names = {j.name for j in joints}
    for j in spec.joints:
        if j.name in names:
            j.armature = max(j.armature, 1e-4)
            a = spec.add_actuator()
            a.target = j.name
            a.trntype = mujoco.mjtTrn.mjTRN_JOINT
            a.set_to_position(kp=1.0, kv=0.1)  # gains are set per joint below
    m = spec.compile()
    # MuJoCo softens a contact in proportion to an estimate of how easily its bodies
    # translate (body_invweight0); a body that can only turn about an axis through its
    # centre of mass (a knob, a cap, a turntable) gets none, so a contact pressing it
    # along its axis is an infinitely stiff row of zero effective mass, whose unbounded
    # force leaks into the joint as round-off torque and spins it. Floor the estimate.
    jointed = (m.body_jntnum > 0) & (m.body_mass > 0)
    m.body_invweight0[jointed, 0] = np.maximum(m.body_invweight0[jointed, 0],
                                               INVWEIGHT_FLOOR / m.body_mass[jointed])
    if parent_contacts:
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_FILTERPARENT)
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    # servo gains from each joint's own inertia and damping: critically damped, at
    # least 4 Hz, at most a quarter of the step rate (explicit stiffness stays stable)
    for a in range(m.nu):
        dof = m.jnt_dofadr[m.actuator_trnid[a, 0]]
        inertia, damping = m.dof_M0[dof] + 1e-9, m.dof_damping[dof]
        w = min(max(damping / (2.0 * inertia), 8.0 * math.pi), 0.25 / m.opt.timestep)
        kp, kv = inertia * w * w, max(2.0 * inertia * w - damping, 0.0)
        m.actuator_gainprm[a, 0] = kp
        m.actuator_biasprm[a, 1] = -kp
        m.actuator_biasprm[a, 2] = -kv
        m.actuator_forcerange[a] = (-1e4, 1e4)
    return m, d


def _mujoco_run(mujoco, path, joints, opts, fixed_base=False):
    issues, info = [], {}
    m, d = _mj_model(mujoco, path, joints, free=False)
    body = lambda i: mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_BODY, int(i)) or str(i)  # noqa: E731
    worst = 0.0
    seen = set()
    for c in d.contact[:d.ncon]:
        b1, b2 = m.geom_bodyid[c.geom1], m.geom_bodyid[c.geom2]
        worst = max(worst, -c.dist)
        if c.dist < -opts.contact_tol and (b1, b2) not in seen:
            seen.add((b1, b2))
            issues.append(Issue("simulator", "sim_rest_penetration", -float(c.dist), [body(b1), body(b2)],
                                detail="mujoco: collision geometry penetrates at rest"))
    info["rest_penetration"] = worst
    # drive, root welded to the world, frictionless (condim 1: a zero friction
    # coefficient alone still resists sliding in MuJoCo's solver), no gravity
    m.geom_friction[:] = 0.0
    m.geom_condim[:] = 1
    m.opt.gravity[:] = 0.0
    act = {mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, int(m.actuator_trnid[a, 0])): a for a in range(m.nu)}
    qadr = {j.name: m.jnt_qposadr[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, j.name)] for j in joints
            if j.name in act}
    live = [j for j in joints if j.name in act]
    state = lambda j: d.qpos[qadr[j.name]]  # noqa: E731

    def run(sel, others_open=False):
        mujoco.mj_resetData(m, d)
        base = _others(live, sel, others_open)
        d.ctrl[:] = 0.0
        for j in live:
            d.ctrl[act[j.name]] = base[j.name]
        if others_open:  # open the others first (a rack behind its door)
            _run_until(lambda: mujoco.mj_step(m, d), m.opt.timestep, opts,
                       [(j, base[j.name]) for j in live if base[j.name] != 0.0], state)
        out = []
        for phase in (1, 0):  # to the upper targets, then back to the lower ones
            for j in sel:
                d.ctrl[act[j.name]] = j.targets()[phase]
            out += _run_until(lambda: mujoco.mj_step(m, d), m.opt.timestep, opts,
                              [(j, j.targets()[phase]) for j in sel], state)
        return out

    issues += _blocked_issues(run, live, opts, "mujoco")
    if fixed_base:
        info["drop"] = "fixed base"
        return issues, info
    # drop on a floor with a free root, joints held rigidly at rest
    m, d = _mj_model(mujoco, rigid_urdf(path, Path(path).with_name("rigid.urdf")), [], free=True,
                     parent_contacts=False)
    root = 1
    for _ in range(int(round(opts.settle_seconds / m.opt.timestep))):
        mujoco.mj_step(m, d)
    T0 = np.eye(4)
    T0[:3, :3] = d.xmat[root].reshape(3, 3)
    T0[:3, 3] = d.xpos[root]
    lo, hi = _mj_body_box(m, d, root)
    for _ in range(int(round(opts.drop_seconds / m.opt.timestep))):
        mujoco.mj_step(m, d)
    T1 = np.eye(4)
    T1[:3, :3] = d.xmat[root].reshape(3, 3)
    T1[:3, 3] = d.xpos[root]
    drift = _drift(T0, T1, _corners(lo, hi))
    info["drift"] = drift
    if drift > opts.drift_tol or not np.isfinite(drift):
        issues.append(Issue("simulator", "drift", float(drift) if np.isfinite(drift) else 1.0, [body(root)],
                            detail="mujoco: object moves on the floor"))
    return issues, info


def _mj_body_box(m, d, b):
    """World bounding box of the geoms of body ``b`` (from their bounding radii)."""
    g = np.flatnonzero(m.geom_bodyid == b)
    if not len(g):
        return d.xpos[b] - 0.01, d.xpos[b] + 0.01
    c = d.geom_xpos[g]
    r = m.geom_rbound[g][:, None]
    return (c - r).min(axis=0), (c + r).max(axis=0)
