"""Distance between a candidate twin and the target: whole clouds, matched links, joints.

``total = mean_s CD(whole_s) + LINK_WEIGHT * link_term + JOINT_WEIGHT * joint_term``

- ``CD(whole_s)``: Chamfer-L1 of the normalised whole clouds at state ``s``;
- links are matched one-to-one (Hungarian assignment) among label-compatible pairs
  (:func:`artipg.fit.labels.compatible_labels`; body links with body links) on a cheap
  descriptor: centroid distance + mean extent difference + a joint-type mismatch.
  Leaving a link unmatched costs :data:`UNMATCHED` in the assignment;
- ``link_term``: sum over matched pairs of their mean area share times their
  Chamfer-L1 at the closed state, plus ``0.02 + 0.2 * share`` per unmatched link of
  either side (a missing door costs more than a missing button);
- ``joint_term``: mean over matched moving pairs of (type differs) + (axis angle as
  lines / 90 deg) + (relative travel difference, capped at 1), divided by 3.

All distances are in units of the closed object's bounding-box diagonal.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import linear_sum_assignment

from artipg.fit.labels import BODY, compatible_labels
from artipg.fit.shape import Shape
from artipg.metrics.chamfer import chamfer_distance

LINK_WEIGHT = 0.5
JOINT_WEIGHT = 0.03
UNMATCHED = 0.5
_FORBIDDEN = 1e6


@dataclass
class Score:
    """A comparison; ``pairs`` are (target link, twin link) indices."""

    total: float
    whole: list
    pairs: list
    link_cd: list
    unmatched_target: list
    unmatched_twin: list
    joints: list = field(default_factory=list)
    joint_term: float = 0.0
    link_term: float = 0.0


def _compatible(target: Shape, twin: Shape) -> np.ndarray:
    """(Lr, Lt) bool: which target link may match which twin link."""
    ok = np.zeros((len(target.labels), len(twin.labels)), dtype=bool)
    for i, a in enumerate(target.labels):
        allowed = {BODY} if a == BODY else compatible_labels(a)
        ok[i] = [b in allowed for b in twin.labels]
    return ok


def _family(t: str) -> str:
    return "revolute" if t == "continuous" else t


def joint_errors(target: Shape, twin: Shape, i: int, j: int) -> dict:
    """Type / axis / travel disagreement of target link ``i`` and twin link ``j``."""
    a, b = target.joint_type[i], twin.joint_type[j]
    out = {"type": [a, b], "type_error": float(_family(a) != _family(b)) if a != b else 0.0}
    if a == "fixed" or b == "fixed":
        return out
    u, v = target.axis[i], twin.axis[j]
    nu, nv = np.linalg.norm(u), np.linalg.norm(v)
    cos = abs(float(u @ v)) / (nu * nv) if nu > 0 and nv > 0 else 0.0
    out["axis_deg"] = float(np.degrees(np.arccos(min(1.0, cos))))
    if "continuous" not in (a, b) and _family(a) == _family(b):
        ta, tb = target.travel[i], twin.travel[j]
        out["travel"] = [float(ta), float(tb)]
        out["travel_error"] = float(min(1.0, abs(ta - tb) / max(ta, 1e-2)))
    return out


def compare(target: Shape, twin: Shape, per_state_links: bool = False) -> Score:
    """Score ``twin`` against ``target`` (lower is better; see the module docstring).

    Parameters
    ----------
    target, twin : Shape
    per_state_links : bool
        Report each matched link's Chamfer at every state (else at the closed one only).
    """
    whole = [chamfer_distance(a, b) for a, b in zip(target.clouds, twin.clouds)]
    ok = _compatible(target, twin)
    cr, ct = target.centroids, twin.centroids
    er, et = target.link_extents, twin.link_extents
    cost = (np.linalg.norm(cr[:, None] - ct[None], axis=-1)
            + np.abs(er[:, None] - et[None]).mean(axis=-1)
            + 0.2 * (np.array(target.joint_type)[:, None] != np.array(twin.joint_type)[None]))
    cost = np.where(ok & np.isfinite(cost), cost, _FORBIDDEN)
    nr, nt = cost.shape
    # square assignment with a "leave unmatched" slot for every link of either side
    big = np.full((nr + nt, nr + nt), _FORBIDDEN)
    big[:nr, :nt] = cost
    big[:nr, nt:][np.diag_indices(nr)] = UNMATCHED
    big[nr:, :nt][np.diag_indices(nt)] = UNMATCHED
    big[nr:, nt:] = 0.0
    rows, cols = linear_sum_assignment(big)
    pairs = [(int(r), int(c)) for r, c in zip(rows, cols) if r < nr and c < nt and cost[r, c] < _FORBIDDEN]
    mr = {r for r, _ in pairs}
    mt = {c for _, c in pairs}
    states = range(len(target.clouds)) if per_state_links else (0,)
    link_cd, link_term, joints = [], 0.0, []
    for r, c in pairs:
        d = [chamfer_distance(target.link_clouds[s][r], twin.link_clouds[s][c])
             if len(target.link_clouds[s][r]) and len(twin.link_clouds[s][c]) else np.nan for s in states]
        link_cd.append(d)
        w = 0.5 * (target.share[r] + twin.share[c])
        link_term += w * (d[0] if np.isfinite(d[0]) else 0.2)
        joints.append(joint_errors(target, twin, r, c))
    un_r = [i for i in range(nr) if i not in mr]
    un_t = [j for j in range(nt) if j not in mt]
    link_term += sum(0.02 + 0.2 * target.share[i] for i in un_r) + sum(0.02 + 0.2 * twin.share[j] for j in un_t)
    moving = [e for e in joints if e["type"] != ["fixed", "fixed"]]
    joint_term = 0.0
    if moving:
        joint_term = float(np.mean([(e["type_error"] + e.get("axis_deg", 90.0) / 90.0 + e.get("travel_error", 0.0)) / 3
                                    for e in moving]))
    total = float(np.mean(whole)) + LINK_WEIGHT * link_term + JOINT_WEIGHT * joint_term
    return Score(total, whole, pairs, link_cd, un_r, un_t, joints, joint_term, float(link_term))
