"""Simulator checks: the URDF loads in pybullet and MuJoCo and behaves.

For each engine (short simulations, a few hundred milliseconds per object):

- **load**: the URDF loads (MuJoCo through ``MjSpec``, so that a floor, a free joint
  and position servos can be added);
- **rest contacts**: with parent-child contacts turned on (pybullet
  ``URDF_USE_SELF_COLLISION | URDF_USE_SELF_COLLISION_INCLUDE_PARENT`` with
  ``getClosestPoints``; MuJoCo ``mjDSBL_FILTERPARENT``), no two links of the
  collision geometry penetrate deeper than the tolerance at rest: this is where a
  hollow body exported as one convex hull shows up. pybullet pads every convex
  mesh of a URDF with a fixed 1 mm collision margin (:data:`PYBULLET_MESH_MARGIN`),
  so touching meshes read as up to 2 mm deep there and its tolerance is 2 mm
  wider; MuJoCo measures the exported geometry exactly;
- **drop**: the object, free on a floor with its joints held at rest, settles for
  ``settle_seconds`` and then moves less than ``drift_tol`` in ``drop_seconds``
  (largest displacement of the corners of the root link's bounding box); the
  engines' default contact filters apply here;
- **drive**: with the root fixed, contacts frictionless and gravity off (so that only
  geometry can block a joint, not friction between touching parts or a servo too
  weak to lift a lid), position control drives all movable joints from rest to their
  upper limits and then back to their lower limits (continuous joints: +-π/2); each
  must get within ``joint_tol`` of its target. A joint that is still closing in on
  its target gets more time (up to three times ``drive_seconds``); one that stalls is
  blocked. Joints that miss are driven again alone (the others held at rest) to tell
  a blocked joint from one that only interferes with another.
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


#: Collision margin (metres) pybullet's URDF importer gives every convex mesh (not
#: changeable from Python for URDF links): reported distances are this much smaller
#: per mesh involved.
PYBULLET_MESH_MARGIN = 1e-3


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


def simulate_object(obj, opts: SimOptions = SimOptions()) -> CheckResult:
    """Export ``obj`` (URDF + meshes) to a temporary folder and simulate it."""
    from artipg.export.urdf import build_urdf, urdf_text

    robot, meshes = build_urdf(obj, visuals=False)
    with tempfile.TemporaryDirectory(prefix="artipg-sim-") as d:
        for rel, text in meshes.items():
            p = Path(d) / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text)
        urdf = Path(d) / "mobility.urdf"
        urdf.write_text(urdf_text(robot))
        return simulate_urdf(urdf, opts)


def simulate_urdf(urdf, opts: SimOptions = SimOptions()) -> CheckResult:
    """Run the simulator checks on the URDF file ``urdf`` (see module docstring)."""
    urdf = Path(urdf).resolve()
    joints = _urdf_joints(urdf)
    issues, info = [], {}
    for engine in opts.engines:
        run = {"pybullet": _pybullet, "mujoco": _mujoco}[engine]
        try:
            eng_issues, eng_info = run(urdf, joints, opts)
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


def _pybullet(urdf: Path, joints: list[_Joint], opts: SimOptions):
    pb = _import_pybullet()
    cid = pb.connect(pb.DIRECT)
    try:
        return _pybullet_run(pb, cid, urdf, joints, opts)
    finally:
        pb.disconnect(cid)


def _pb_pose(pb, cid, body) -> np.ndarray:
    pos, orn = pb.getBasePositionAndOrientation(body, physicsClientId=cid)
    T = np.eye(4)
    T[:3, :3] = np.array(pb.getMatrixFromQuaternion(orn)).reshape(3, 3)
    T[:3, 3] = pos
    return T


def _pybullet_run(pb, cid, urdf, joints, opts):
    issues, info = [], {}
    flags = pb.URDF_USE_SELF_COLLISION | pb.URDF_USE_SELF_COLLISION_INCLUDE_PARENT
    dt = 1.0 / 240.0
    pb.setTimeStep(dt, physicsClientId=cid)
    # leave the margin overlap of touching meshes alone instead of pushing them apart
    pb.setPhysicsEngineParameter(contactSlop=2 * PYBULLET_MESH_MARGIN + 5e-4, physicsClientId=cid)
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
            d = min(c[8] for c in cps)
            worst = max(worst, -d)
            if d < -(opts.contact_tol + 2 * PYBULLET_MESH_MARGIN):
                issues.append(Issue("simulator", "sim_rest_penetration", -d, [names[a], names[b]],
                                    detail="pybullet: collision geometry penetrates at rest"))
    info["rest_penetration"] = worst
    pb.removeBody(body, physicsClientId=cid)
    # drive: all joints to their upper then back to their lower targets, root fixed,
    # frictionless, no gravity (only geometry may stop a joint); fresh body per run
    pb.setGravity(0, 0, 0, physicsClientId=cid)

    def run(sel):
        b = pb.loadURDF(str(urdf), useFixedBase=True, flags=flags, physicsClientId=cid)
        for i in range(-1, n):
            pb.changeDynamics(b, i, lateralFriction=0.0, spinningFriction=0.0, rollingFriction=0.0,
                              physicsClientId=cid)
        live = [j for j in joints if j.name in index]
        ids = [index[j.name] for j in live]
        state = lambda j: pb.getJointState(b, index[j.name], physicsClientId=cid)[0]  # noqa: E731

        def drive(goal):
            pb.setJointMotorControlArray(b, ids, pb.POSITION_CONTROL,
                                         targetPositions=[goal.get(j.name, 0.0) for j in live],
                                         forces=[200.0] * len(ids), physicsClientId=cid)
            return _run_until(lambda: pb.stepSimulation(physicsClientId=cid), dt, opts,
                              [(j, goal[j.name]) for j in sel], state)

        up = drive({j.name: j.targets()[1] for j in sel})
        down = drive({j.name: j.targets()[0] for j in sel})
        pb.removeBody(b, physicsClientId=cid)
        return up + down

    for j, target, reached in _blocked(run, [j for j in joints if j.name in index], opts):
        issues.append(Issue("simulator", "joint_blocked", abs(reached - target), joint=j.name, q=reached,
                            detail=f"pybullet: target {target:.4g} not reached"))
    pb.setGravity(0, 0, -9.81, physicsClientId=cid)
    # drop on a floor, joints held at rest (the joints' own contacts were checked above)
    plane = pb.createCollisionShape(pb.GEOM_PLANE, physicsClientId=cid)
    pb.createMultiBody(0, plane, physicsClientId=cid)
    body = pb.loadURDF(str(urdf), useFixedBase=False, physicsClientId=cid)
    mov = [index[j.name] for j in joints if j.name in index]
    if mov:
        pb.setJointMotorControlArray(body, mov, pb.POSITION_CONTROL, targetPositions=[0.0] * len(mov),
                                     forces=[200.0] * len(mov), physicsClientId=cid)
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


def _blocked(run, joints, opts):
    """Joints that miss a target when all are driven together and again when driven
    alone (the others held at rest): [(joint, target, reached)]."""
    if not joints:
        return []
    failed = {j.name for j, t, q in run(joints) if abs(q - t) > j.tol(opts.joint_tol)}
    out = []
    for j in joints:
        if j.name in failed:
            out += [(jj, t, q) for jj, t, q in run([j]) if abs(q - t) > jj.tol(opts.joint_tol)]
    return out


# ------------------------------------------------------------------ MuJoCo

_MJ_COMPILER = {"discardvisual": "true", "fusestatic": "false", "strippath": "false", "balanceinertia": "true"}


def _mujoco_urdf(urdf: Path, tmp: str) -> Path:
    """A copy of ``urdf`` MuJoCo can load: absolute mesh paths, links kept apart."""
    tree = ET.parse(urdf)
    root = tree.getroot()
    for m in root.iter("mesh"):
        f = re.sub(r"^package://[^/]*/", "", m.get("filename", ""))
        f = f[len("file://"):] if f.startswith("file://") else f
        m.set("filename", str((urdf.parent / f).resolve()))
    for el in list(root.findall("mujoco")):
        root.remove(el)
    mj = ET.SubElement(root, "mujoco")
    ET.SubElement(mj, "compiler", **_MJ_COMPILER)
    out = Path(tmp) / "model.urdf"
    tree.write(out)
    return out


def _mujoco(urdf: Path, joints: list[_Joint], opts: SimOptions):
    import mujoco

    with tempfile.TemporaryDirectory(prefix="artipg-mj-") as tmp:
        path = _mujoco_urdf(urdf, tmp)
        return _mujoco_run(mujoco, path, joints, opts)


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


def _mujoco_run(mujoco, path, joints, opts):
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

    def run(sel):
        mujoco.mj_resetData(m, d)
        d.ctrl[:] = 0.0
        out = []
        for phase in (1, 0):  # to the upper targets, then back to the lower ones
            for j in sel:
                d.ctrl[act[j.name]] = j.targets()[phase]
            out += _run_until(lambda: mujoco.mj_step(m, d), m.opt.timestep, opts,
                              [(j, j.targets()[phase]) for j in sel], state)
        return out

    for j, target, reached in _blocked(run, live, opts):
        issues.append(Issue("simulator", "joint_blocked", abs(reached - target), joint=j.name, q=reached,
                            detail=f"mujoco: target {target:.4g} not reached"))
    # drop on a floor with a free root, joints held at rest
    m, d = _mj_model(mujoco, path, joints, free=True, parent_contacts=False)
    d.ctrl[:] = 0.0
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
