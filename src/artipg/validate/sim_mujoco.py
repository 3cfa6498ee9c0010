"""The MuJoCo simulator check (see :mod:`artipg.validate.sim`)."""

from __future__ import annotations

import math
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from artipg.validate.report import Issue
from artipg.validate.sim_common import (Joint, SimOptions, blocked_issues, body_drift, box_corners, mesh_path,
                                         others_state, rigid_urdf, run_until)


#: contacts of a jointed body (see :func:`_mj_model`).
INVWEIGHT_FLOOR = 0.1

_MJ_COMPILER = {"discardvisual": "true", "fusestatic": "false", "strippath": "false", "balanceinertia": "true"}


def _mujoco_urdf(urdf: Path, tmp: str) -> Path:
    """A copy of ``urdf`` MuJoCo can load: absolute mesh paths, links kept apart."""
    tree = ET.parse(urdf)
    root = tree.getroot()
    for m in root.iter("mesh"):
        m.set("filename", str(mesh_path(urdf, m.get("filename", ""))))
    for el in list(root.findall("mujoco")):
        root.remove(el)
    mj = ET.SubElement(root, "mujoco")
    ET.SubElement(mj, "compiler", **_MJ_COMPILER)
    out = Path(tmp) / "model.urdf"
    tree.write(out)
    return out


def run_mujoco(urdf: Path, joints: list[Joint], opts: SimOptions, fixed_base: bool = False):
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
        base = others_state(live, sel, others_open)
        d.ctrl[:] = 0.0
        for j in live:
            d.ctrl[act[j.name]] = base[j.name]
        if others_open:  # open the others first (a rack behind its door)
            run_until(lambda: mujoco.mj_step(m, d), m.opt.timestep, opts,
                       [(j, base[j.name]) for j in live if base[j.name] != 0.0], state)
        out = []
        for phase in (1, 0):  # to the upper targets, then back to the lower ones
            for j in sel:
                d.ctrl[act[j.name]] = j.targets()[phase]
            out += run_until(lambda: mujoco.mj_step(m, d), m.opt.timestep, opts,
                              [(j, j.targets()[phase]) for j in sel], state)
        return out

    issues += blocked_issues(run, live, opts, "mujoco")
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
    drift = body_drift(T0, T1, box_corners(lo, hi))
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
