"""Per-point labels at any joint state: actionable class, affordances, part pose, NPCS.

Any surface point whose global primitive index is known (sampled analytically by
:func:`artipg.annotate.points.sample_points` or hit by a ray in
:mod:`artipg.annotate.views`) is labelled by table lookups into
:func:`artipg.annotate.knowledge.knowledge` plus one rigid transform per point.

NPCS convention (GAPartNet): a point of part ``i`` is expressed in the part's
canonical frame, moved so that the centre of the part's canonical bounding box is the
origin and divided by the length of that box's diagonal. Values lie in
``[-0.5, 0.5]^3`` (a unit cube centred on the origin; add 0.5 for colours in
``[0, 1]``) and ``x = part_pose[i] @ (npcs * part_scale[i])`` maps them back.
Object-level NPCS does the same for the whole object at rest: a point is first moved
back to where it is at the rest state by its link's motion (articulation-aware, as
ANCSH's NAOCS), then normalised by the object's rest bounding box.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from artipg.annotate.knowledge import knowledge
from artipg.vocabulary import ACTIONABLE_CLASSES, AFFORDANCES

#: Affordance regions every part of an actionable class must carry: each inner tuple
#: is a requirement met by any one of its affordances.
REQUIRED_AFFORDANCES: dict[str, tuple[tuple[str, ...], ...]] = {
    "none": (),
    "line_fixed_handle": (("grasp",), ("pull", "lift")),
    "round_fixed_handle": (("grasp",), ("pull", "lift")),
    "slider_button": (("press",),),
    "hinge_door": (("push", "pull"),),
    "slider_drawer": (("push", "pull"),),
    "slider_lid": (("pull", "push", "lift"),),
    "hinge_lid": (("lift", "pull", "push"),),
    "hinge_knob": (("rotate",),),
    "hinge_handle": (("grasp",),),
}


def rigid_inverse(T: np.ndarray) -> np.ndarray:
    """Inverses (..., 4, 4) of rigid transforms (..., 4, 4)."""
    R = T[..., :3, :3]
    Rt = np.swapaxes(R, -1, -2)
    out = np.zeros_like(T)
    out[..., :3, :3] = Rt
    out[..., :3, 3] = -np.einsum("...ij,...j->...i", Rt, T[..., :3, 3])
    out[..., 3, 3] = 1.0
    return out


def apply_gathered(T: np.ndarray, idx: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Apply transform ``T[idx[n]]`` (affine, (K, 3|4, 4)) to point ``x[n]`` (N, 3).

    Structure-of-arrays layout (3, 4, N), which numpy handles several times faster
    than (N, 3, 3) einsums.
    """
    W = np.ascontiguousarray(T[:, :3].transpose(1, 2, 0))[:, :, idx]
    xt = x.T
    return (W[:, 0] * xt[0] + W[:, 1] * xt[1] + W[:, 2] * xt[2] + W[:, 3]).T


@dataclass
class PartFrames:
    """Pose knowledge of every part at one joint state (object frame, metres).

    Attributes
    ----------
    canonical : (P, 4, 4) float64
        Canonical frame of each part (as its template defines it).
    pose : (P, 4, 4) float64
        NPCS frame: canonical axes, origin at the centre of the canonical bounding box.
    size : (P, 3) float64
        Extents of the canonical bounding box along the canonical axes.
    scale : (P,) float64
        Diagonal of that box (the NPCS scale).
    """

    canonical: np.ndarray
    pose: np.ndarray
    size: np.ndarray
    scale: np.ndarray


def part_frames(obj, qpos=None) -> PartFrames:
    """Canonical frames, NPCS frames and sizes of all parts of ``obj`` at ``qpos``."""
    kn = knowledge(obj)
    L = obj.link_poses(qpos)
    C = L[obj.part_link] @ kn.part_canonical
    N = C.copy()
    N[:, :3, 3] += np.einsum("pij,pj->pi", C[:, :3, :3], kn.part_center)
    return PartFrames(C, N, kn.part_size.copy(), kn.part_diag.copy())


@dataclass
class PointLabels:
    """Labels of surface points (N of them) beyond semantic/instance/link.

    Attributes
    ----------
    actionable : (N,) int64
        Index into :data:`artipg.vocabulary.ACTIONABLE_CLASSES` (0 = ``"none"``).
    affordance : (N, A) bool
        Membership in each affordance region, columns in
        :data:`artipg.vocabulary.AFFORDANCES` order.
    npcs : (N, 3) float64
        Part-level NPCS in [-0.5, 0.5]^3 (every part, actionable or not).
    object_npcs : (N, 3) float64
        Object-level NPCS in [-0.5, 0.5]^3 (rest-state, articulation-aware).
    """

    actionable: np.ndarray
    affordance: np.ndarray
    npcs: np.ndarray
    object_npcs: np.ndarray


def point_labels(obj, points: np.ndarray, primitive: np.ndarray, qpos=None, npcs: bool = True) -> PointLabels:
    """Label surface points of ``obj`` posed at ``qpos``.

    Parameters
    ----------
    obj : ArticulatedObject
    points : (N, 3) array
        Points on the object's surface, object frame (metres).
    primitive : (N,) int array
        Global primitive index of each point (non-negative).
    qpos : None, dict or sequence
        Joint state the points were taken at.
    npcs : bool
        Compute the NPCS arrays (zeros otherwise).

    Returns
    -------
    PointLabels
    """
    kn = knowledge(obj)
    table = obj.primitive_table
    x = np.asarray(points, dtype=float).reshape(-1, 3)
    prim = np.asarray(primitive, dtype=np.int64).ravel()
    part = table.prim_part[prim]
    link = table.prim_link[prim]
    L = obj.link_poses(qpos)
    n = len(x)
    aff = np.zeros((n, len(AFFORDANCES)), dtype=bool)
    if kn.region_role.any():
        inv_part = rigid_inverse(L[obj.part_link] @ kn.part_pose)
        local = None
        for a in range(len(AFFORDANCES)):
            m = kn.region_role[a, prim]
            if not m.any():
                continue
            box = kn.region_box[a, prim[m]]
            if np.isfinite(box).any():
                if local is None:
                    local = apply_gathered(inv_part, part, x)
                q = local[m]
                m[m] = np.all((q >= box[:, 0]) & (q <= box[:, 1]), axis=1)
            aff[:, a] = m
    if npcs:
        # NPCS frame -> unit-scaled inverse: npcs = (R^T (x - t)) / diag
        F = part_frames(obj, qpos)
        Ninv = rigid_inverse(F.pose)[:, :3] / F.scale[:, None, None]
        pn = apply_gathered(Ninv, part, x)
        O = kn.rest_link_poses @ rigid_inverse(L)
        O[:, :3, 3] -= kn.object_center
        on = apply_gathered(O[:, :3] / kn.object_diag, link, x)
    else:
        pn = on = np.zeros((n, 3))
    return PointLabels(kn.part_actionable[part], aff, pn, on)


def affordance_names() -> tuple[str, ...]:
    """Column names of :attr:`PointLabels.affordance`."""
    return AFFORDANCES


def actionable_names() -> tuple[str, ...]:
    """Names of the values of :attr:`PointLabels.actionable`."""
    return ACTIONABLE_CLASSES
