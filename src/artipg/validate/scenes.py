"""The scenes the geometric checks measure: which pairs of pieces, in which poses.

- *rest*: every pair of pieces of different parts whose boxes come within the
  floating tolerance;
- *sweep*: each movable joint at ``sweep_poses`` values over its range, its subtree
  moving against the pieces at rest, culled by swept and then per-pose boxes;
- *open*: all joints together at fractions of their ranges, pairs of links whose
  relative pose changed.

All pairs of all scenes get their distances in one
:func:`artipg.validate.contacts.pair_distance` pass.
"""

from __future__ import annotations

import numpy as np

from artipg.validate.contacts import close_pairs, overlapping, pair_distance, world_boxes
from artipg.validate.kinematics import Kinematics, rigid_inverse, rotations
from artipg.validate.shapes import Pieces

#: Boxes must overlap by this much on every axis before a pair is checked for
#: penetration (metres): touching faces are skipped, real overlaps are not.
OVERLAP = 1e-4


def scenes(kin: Kinematics, pieces: Pieces, tol) -> tuple:
    """The rest, sweep and open scenes with their distances ``"d"`` (metres).

    Returns ``(W0, c0, h0, [rest, sweep, open...])``: W0 (M, 4, 4) the piece frames
    at rest, c0, h0 (M, 3) their world boxes, and each scene as a dict of its pairs
    ``a``, ``b``, their frames ``Wa``, ``Wb`` and distances ``d`` (see
    :mod:`artipg.validate.checks` for the scenes; ``tol``: its ``Tolerances``)."""
    rest = kin.poses()
    W0 = rest[pieces.link] @ pieces.T
    c0, h0 = world_boxes(pieces, W0)
    scenes = [_rest_pairs(pieces, c0, h0, tol), _sweep_pairs(kin, pieces, rest, W0, c0, h0, tol)]
    movable = kin.movable()
    if len(movable) >= 2:
        scenes += [_open_pairs(kin, pieces, rest, f) for f in tol.open_fractions]
    a = np.concatenate([s["a"] for s in scenes])
    b = np.concatenate([s["b"] for s in scenes])
    Wa = np.concatenate([s["Wa"] if s["Wa"] is not None else W0[s["a"]] for s in scenes])
    Wb = np.concatenate([s["Wb"] if s["Wb"] is not None else W0[s["b"]] for s in scenes])
    margin = np.array([s["margin"] for s in scenes]).repeat([len(s["a"]) for s in scenes])
    d = pair_distance(pieces, a, b, Wa, Wb, margin)
    k = 0
    for s in scenes:
        n = len(s["a"])
        s["d"] = d[k:k + n]
        s["Wa"], s["Wb"] = Wa[k:k + n], Wb[k:k + n]
        k += n
    return W0, c0, h0, scenes


# -------------------------------------------------------------------- pair building

def _rest_pairs(pieces, c0, h0, tol) -> dict:
    """Pieces of different parts within the floating tolerance of each other at rest."""
    a, b = close_pairs(c0, h0, tol.floating, pieces.part)
    return {"a": a, "b": b, "Wa": None, "Wb": None, "margin": tol.floating}


def _sweep_pairs(kin, pieces, rest, W0, c0, h0, tol) -> dict:
    """Each movable joint at ``tol.sweep_poses`` values: moving pieces against the
    pieces that stay at rest, culled first by swept then by per-pose boxes.

    Rows come grouped by (joint, moving piece), then by static piece, then by pose."""
    movable = kin.movable()
    empty = np.zeros(0, dtype=np.int64)
    out = {"a": empty, "b": empty, "Wa": np.zeros((0, 4, 4)), "Wb": np.zeros((0, 4, 4)), "margin": 0.0,
           "scene": empty, "joint": empty, "q": np.zeros(0), "movable": movable}
    if not len(movable) or pieces.n == 0:
        return out
    axes = kin.world_axes(rest)
    subtree = kin.descendants[movable][:, pieces.link]  # (J, M): pieces each joint moves
    scene_joint, scene_q = kin.sweep_table(tol.sweep_poses)
    out["joint"], out["q"] = scene_joint, scene_q
    # a solid of revolution turning about its own axis occupies the same space at
    # every joint value: its rest result stands for the whole sweep
    moving = subtree & ~_turns_in_place(kin, pieces, axes, W0)
    uj, up = np.nonzero(moving)  # (joint, moving piece) pairs
    if not len(uj):
        return out
    # every pose of each pair: the scenes of a joint are consecutive
    n_pose = np.bincount(scene_joint, minlength=len(movable))
    first = n_pose.cumsum() - n_pose
    counts = n_pose[uj]
    starts = counts.cumsum() - counts
    s_idx = np.arange(counts.sum()) + (first[uj] - starts).repeat(counts)
    p_idx = up.repeat(counts)
    GR, Gt = _world_motions(kin, axes, scene_joint, scene_q)  # (S, 3, 3), (S, 3)
    GR, Gt = GR[s_idx], Gt[s_idx]  # every row's
    Rm, cm, hm = _moved_boxes(GR, Gt, W0[p_idx], c0[p_idx], pieces.half[p_idx])
    # swept box of each (joint, moving piece) over all its poses
    lo = np.minimum.reduceat(cm - hm, starts)
    hi = np.maximum.reduceat(cm + hm, starts)
    cand = overlapping(0.5 * (lo + hi), 0.5 * (hi - lo), c0, h0, -OVERLAP) & ~subtree[uj]
    u, b = np.nonzero(cand)
    if not len(u):
        return out
    # expand the candidates over the poses of their joint and test per-pose boxes
    n_rep = counts[u]
    rows = np.arange(n_rep.sum()) + (starts[u] - (n_rep.cumsum() - n_rep)).repeat(n_rep)
    bb = b.repeat(n_rep)
    ok = (np.abs(cm[rows] - c0[bb]) - (hm[rows] + h0[bb]) < -OVERLAP).all(axis=1)
    rows, bb = rows[ok], bb[ok]
    Wm = np.zeros((len(rows), 4, 4))
    Wm[:, :3, :3] = Rm[rows]
    Rr, t0 = GR[rows], W0[p_idx[rows], :3, 3]
    Wm[:, :3, 3] = (Rr[:, :, 0] * t0[:, 0, None] + Rr[:, :, 1] * t0[:, 1, None] + Rr[:, :, 2] * t0[:, 2, None]
                    + Gt[rows])
    Wm[:, 3, 3] = 1.0
    out.update(a=p_idx[rows], b=bb, Wa=Wm, Wb=W0[bb], scene=s_idx[rows])
    return out


def _moved_boxes(GR, Gt, W, c, h):
    """Pieces (frames ``W`` (n, 4, 4), world boxes ``c``, local half extents ``h``)
    moved by rotations ``GR`` (n, 3, 3) and translations ``Gt`` (n, 3): the rotation
    of each moved frame (n, 3, 3) and its world box (centres, half extents: (n, 3))."""
    R0 = W[:, :3, :3]
    Rm = (GR[:, :, 0, None] * R0[:, 0, None, :] + GR[:, :, 1, None] * R0[:, 1, None, :]
          + GR[:, :, 2, None] * R0[:, 2, None, :])
    cm = GR[:, :, 0] * c[:, 0, None] + GR[:, :, 1] * c[:, 1, None] + GR[:, :, 2] * c[:, 2, None] + Gt
    Am = np.abs(Rm)
    hm = Am[:, :, 0] * h[:, 0, None] + Am[:, :, 1] * h[:, 1, None] + Am[:, :, 2] * h[:, 2, None]
    return Rm, cm, hm


def _world_motions(kin, axes, joint, q):
    """Rigid motions (rotation (S, 3, 3), translation (S, 3)), object frame, that move
    the subtree of joint ``kin.movable()[joint]`` from rest to joint value ``q``: a
    turn about the joint's world axis line or a slide along its world axis (``axes``:
    :meth:`Kinematics.world_axes` at rest)."""
    a, p = axes[0][joint], axes[1][joint]
    slide = kin.slides[joint]
    M = rotations(a, np.where(slide, 0.0, q))
    Mp = M[:, :, 0] * p[:, 0, None] + M[:, :, 1] * p[:, 1, None] + M[:, :, 2] * p[:, 2, None]
    t = np.where(slide[:, None], q[:, None] * a, p - Mp)
    return M, t


def _turns_in_place(kin, pieces, axes, W0) -> np.ndarray:
    """Boolean (J, M): piece m is a full solid of revolution (frustum, full ring or
    torus, sphere) whose axis is joint j's (revolute or continuous) axis line."""
    J = len(axes[0])
    out = np.zeros((J, pieces.n), dtype=bool)
    m = pieces.symmetric_rows
    if not len(m) or kin.slides.all():
        return out
    z = W0[m, :3, 2][None]  # (1, m, 3)
    a = axes[0][:, None, :]  # (J, 1, 3)
    zx, zy, zz = z[..., 0], z[..., 1], z[..., 2]
    ax, ay, az = a[..., 0], a[..., 1], a[..., 2]
    cross = np.maximum(np.maximum(np.abs(zy * az - zz * ay), np.abs(zz * ax - zx * az)), np.abs(zx * ay - zy * ax))
    d = W0[m, :3, 3][None] - axes[1][:, None, :]  # (J, m, 3)
    r = d - (d * a).sum(axis=2, keepdims=True) * a
    out[:, m] = (cross < 1e-9) & (np.sqrt((r * r).sum(axis=2)) < 1e-9) & ~kin.slides[:, None]
    return out


def _open_pairs(kin, pieces, rest, frac) -> dict:
    """All joints at ``frac`` of their ranges: pairs of pieces on links whose relative
    pose differs from rest."""
    P = kin.poses(kin.open_values(frac))
    W = P[pieces.link] @ pieces.T
    c, h = world_boxes(pieces, W)
    # links moved by the same rigid motion keep their relative pose (checked at rest)
    G = (P @ rigid_inverse(rest))[:, :3].reshape(len(P), 12)
    first = (np.abs(G[:, None, :] - G[None, :, :]).max(axis=2) < 1e-9).argmax(axis=1).tolist()
    label = list(range(len(P)))
    for i, f in enumerate(first):  # the first earlier link with the same motion
        if f < i:
            label[i] = label[f]
    a, b = close_pairs(c, h, -OVERLAP, np.array(label)[pieces.link])
    return {"a": a, "b": b, "Wa": W[a], "Wb": W[b], "margin": 0.0, "frac": frac}
