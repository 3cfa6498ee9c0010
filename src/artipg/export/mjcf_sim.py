"""Short MuJoCo checks of an exported ``mobility.xml`` (tests, benchmarks, convert).

- :func:`rest_drift`: the object as written (free on a floor, or a welded fixture),
  its joints held at rest by their position servos (or passive without actuators),
  settles for ``settle`` seconds and then moves its root by at most the returned
  distance (metres) in ``seconds``;
- :func:`drive_limits`: with the root welded and gravity off (so that only geometry
  can stop a joint), each joint's servo drives it to its upper and then its lower
  limit (continuous joints: +-pi/2), the others held at rest, and again with the
  others opened first when it misses (a rack behind its door).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np


def _spec(path, floor: bool, weld: bool = False):
    """The model of ``path``; ``floor``: plus a floor under its lowest collision point
    at rest; ``weld``: its free joint removed."""
    import mujoco

    spec = mujoco.MjSpec.from_file(str(Path(path)))
    if weld:
        for j in list(spec.joints):
            if j.type == mujoco.mjtJoint.mjJNT_FREE:
                spec.delete(j)
    if floor:
        m = spec.compile()
        d = mujoco.MjData(m)
        mujoco.mj_forward(m, d)
        spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 1], pos=[0, 0, lowest_point(m, d)])
    return spec


def lowest_point(m, d) -> float:
    """Lowest world z (m) of the collision geoms (contype > 0) of model ``m`` in state ``d``."""
    import mujoco

    G = mujoco.mjtGeom
    low = np.inf
    for g in np.flatnonzero(m.geom_contype > 0):
        c, R, s = d.geom_xpos[g], d.geom_xmat[g].reshape(3, 3), m.geom_size[g]
        t = m.geom_type[g]
        if t == G.mjGEOM_MESH:
            k = m.geom_dataid[g]
            V = m.mesh_vert[m.mesh_vertadr[k]:m.mesh_vertadr[k] + m.mesh_vertnum[k]]
            z = float((V @ R[2]).min()) + c[2]
        elif t == G.mjGEOM_BOX:
            z = c[2] - float(np.abs(R[2]) @ s)
        elif t == G.mjGEOM_CYLINDER:
            az = abs(R[2, 2])
            z = c[2] - s[1] * az - s[0] * math.sqrt(max(0.0, 1.0 - az * az))
        elif t == G.mjGEOM_SPHERE:
            z = c[2] - s[0]
        else:
            z = c[2] - m.geom_rbound[g]
        low = min(low, z)
    return float(low) if np.isfinite(low) else 0.0


def _root_pose(d, b: int) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = d.xmat[b].reshape(3, 3)
    T[:3, 3] = d.xpos[b]
    return T


def rest_drift(path, settle: float = 0.25, seconds: float = 1.0) -> float:
    """Largest displacement (m) of the corners of the root body's geom bounding box
    over ``seconds`` after ``settle`` seconds on a floor (joints' servos at rest)."""
    import mujoco

    m = _spec(path, floor=True).compile()
    d = mujoco.MjData(m)
    d.ctrl[:] = 0.0
    mujoco.mj_forward(m, d)
    b = 1
    welded = np.flatnonzero(m.body_weldid == m.body_weldid[b])  # the root and the links fixed to it
    g = np.flatnonzero(np.isin(m.geom_bodyid, welded) & (m.geom_contype > 0))
    c, r = d.geom_xpos[g], m.geom_rbound[g][:, None]
    lo, hi = (c - r).min(axis=0), (c + r).max(axis=0)
    corners = np.array(np.meshgrid(*zip(lo, hi), indexing="ij")).reshape(3, -1).T
    for _ in range(int(round(settle / m.opt.timestep))):
        mujoco.mj_step(m, d)
    T0 = _root_pose(d, b)
    for _ in range(int(round(seconds / m.opt.timestep))):
        mujoco.mj_step(m, d)
    D = _root_pose(d, b) @ np.linalg.inv(T0)
    moved = corners @ D[:3, :3].T + D[:3, 3]
    drift = float(np.linalg.norm(moved - corners, axis=1).max())
    return drift if np.isfinite(drift) else math.inf


def drive_limits(path, seconds: float = 2.0, frac: float = 0.03) -> dict[str, tuple[float, float]]:
    """Error (rad or m) at the upper and at the lower limit of every actuated joint,
    {joint name: (upper error, lower error)}: the best of driving it alone with the
    others at rest and with the others opened first. A joint reaches a limit when
    the error is within ``frac`` of its range (at least 0.01 rad or 2 mm), checked
    every 0.1 s for up to ``seconds``."""
    import mujoco

    m = _spec(path, floor=False, weld=True).compile()
    m.opt.gravity[:] = 0.0
    d = mujoco.MjData(m)
    joints = [int(m.actuator_trnid[a, 0]) for a in range(m.nu)]
    adr = [int(m.jnt_qposadr[j]) for j in joints]
    lo, hi = m.actuator_ctrlrange[:, 0].copy(), m.actuator_ctrlrange[:, 1].copy()
    cont = np.array([not m.jnt_limited[j] for j in joints], dtype=bool)
    lo[cont], hi[cont] = -0.5 * math.pi, 0.5 * math.pi
    slide = np.array([m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE for j in joints])
    tol = np.maximum(frac * (hi - lo), np.where(slide, 0.002, 0.01))
    check = max(1, int(round(0.1 / m.opt.timestep)))

    def go(ctrl, k):
        d.ctrl[:] = ctrl
        err = math.inf
        for s in range(int(round(seconds / m.opt.timestep))):
            mujoco.mj_step(m, d)
            if s % check == check - 1:
                err = abs(d.qpos[adr[k]] - ctrl[k])
                if err <= tol[k] and np.all(np.abs(d.qpos[adr] - ctrl) <= tol):
                    break
        return float(abs(d.qpos[adr[k]] - ctrl[k]))

    out = {}
    for k, j in enumerate(joints):
        best = None
        for others in (np.zeros(m.nu), hi):
            mujoco.mj_resetData(m, d)
            base = np.where(np.arange(m.nu) == k, 0.0, others)
            if others is hi:
                go(base, k)
            up = base.copy()
            up[k] = hi[k]
            e_up = go(up, k)
            down = base.copy()
            down[k] = lo[k]
            e_lo = go(down, k)
            if best is None or max(e_up, e_lo) < max(best):
                best = (e_up, e_lo)
            if max(best) <= tol[k]:
                break
        out[mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j)] = best
    return out


def drive_tolerance(path, frac: float = 0.03) -> dict[str, float]:
    """{joint name: tolerance} used by :func:`drive_limits`."""
    import mujoco

    m = mujoco.MjModel.from_xml_path(str(path))
    out = {}
    for a in range(m.nu):
        j = int(m.actuator_trnid[a, 0])
        lo, hi = m.actuator_ctrlrange[a]
        if not m.jnt_limited[j]:
            lo, hi = -0.5 * math.pi, 0.5 * math.pi
        slide = m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE
        out[mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j)] = max(frac * (hi - lo), 0.002 if slide else 0.01)
    return out
