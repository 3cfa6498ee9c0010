"""What both simulator checks share: the URDF's joints, a rigid copy of it, mesh
paths, drift of a body, and driving joints to targets (see :mod:`artipg.validate.sim`)."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from artipg.validate.report import Issue


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


@dataclass
class Joint:
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


def urdf_joints(urdf: Path) -> list[Joint]:
    """Movable joints of a URDF (name, type, limits), in file order."""
    out = []
    for j in ET.parse(urdf).getroot().iter("joint"):
        t = j.get("type")
        if t not in ("revolute", "prismatic", "continuous"):
            continue
        lim = j.find("limit")
        lo = float(lim.get("lower", 0.0)) if lim is not None else 0.0
        hi = float(lim.get("upper", 0.0)) if lim is not None else 0.0
        out.append(Joint(j.get("name"), t, lo, hi))
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


def box_corners(lo, hi) -> np.ndarray:
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def body_drift(T0: np.ndarray, T1: np.ndarray, corners: np.ndarray) -> float:
    """Largest displacement (metres) of ``corners`` (8, 3) moved rigidly from T0 to T1."""
    D = T1 @ np.linalg.inv(T0)
    moved = corners @ D[:3, :3].T + D[:3, 3]
    return float(np.linalg.norm(moved - corners, axis=1).max())

def mesh_path(urdf: Path, filename: str) -> Path:
    """A URDF mesh reference (relative, ``package://pkg/...`` or ``file://...``) as a path."""
    f = re.sub(r"^package://[^/]*/", "", filename)
    f = f[len("file://"):] if f.startswith("file://") else f
    return (urdf.parent / f).resolve()


def run_until(step, dt, opts, targets, state):
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


def others_state(live, sel, others_open: bool) -> dict:
    """Targets of the joints not driven: rest, or their upper targets (``others_open``)."""
    names = {j.name for j in sel}
    return {j.name: (j.targets()[1] if others_open and j.name not in names else 0.0) for j in live}


def blocked_issues(run, joints, opts, engine: str) -> list[Issue]:
    """One ``joint_blocked`` issue per joint :func:`blocked` finds in ``engine``."""
    return [Issue("simulator", "joint_blocked", abs(reached - target), joint=j.name, q=reached,
                  detail=f"{engine}: target {target:.4g} not reached")
            for j, target, reached in blocked(run, joints, opts)]


def blocked(run, joints, opts):
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
