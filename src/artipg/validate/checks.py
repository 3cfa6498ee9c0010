"""The geometric checks: penetration at rest, floating links and parts, joint sweeps.

All three share one batched distance pass
(:func:`artipg.validate.contacts.pair_distance`) over three kinds of scenes:

- *rest*: every pair of pieces of different parts whose boxes come within the
  floating tolerance; gives penetration depths between links (parent-child pairs
  included) and the contact graphs of links and of the parts inside each link;
- *sweep*: each movable joint at ``sweep_poses`` values over its range (continuous:
  a full turn), its subtree moving and everything else at rest;
- *open*: all joints together at the upper end of their ranges (continuous: a half
  turn), for objects with several movable joints (two doors of one cabinet, a
  drawer under a lid); only pairs of links whose relative pose changed are tested.

A pair's penetration depth is the exact minimum translation that separates two boxes,
otherwise minus the lowest signed distance of either piece's surface samples to the
other; a gap is the (exact, for boxes) distance between them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from artipg.validate import compiled
from artipg.validate.contacts import (_DENSE, close_pairs, deepest_point, overlapping, pair_distance, refine_distance,
                                      world_boxes)
from artipg.validate.kinematics import Kinematics, rigid_inverse, rotations
from artipg.validate.report import CheckResult, Issue
from artipg.validate.shapes import Pieces, _kernels_match


@dataclass(frozen=True)
class Tolerances:
    """Thresholds of the geometric checks.

    Attributes
    ----------
    penetration : float
        Largest accepted penetration depth between two links, metres.
    floating : float
        Largest accepted gap for two links / parts to count as touching, metres.
    sweep_poses : int
        Joint values checked per movable joint (besides the rest pose).
    open_fractions : tuple of float
        Fractions of every joint's range for the all-joints-open poses.
    """

    penetration: float = 1e-3
    floating: float = 2e-3
    sweep_poses: int = 16
    open_fractions: tuple = (1.0,)

    def to_json(self) -> dict:
        return {"penetration": self.penetration, "floating": self.floating, "sweep_poses": self.sweep_poses,
                "open_fractions": list(self.open_fractions)}


#: Boxes must overlap by this much on every axis before a pair is checked for
#: penetration (metres): touching faces are skipped, real overlaps are not.
_OVERLAP = 1e-4


def run_checks(kin: Kinematics, pieces: Pieces, tol: Tolerances = Tolerances()) -> dict[str, CheckResult]:
    """Run the penetration, floating and joint-sweep checks.

    Parameters
    ----------
    kin : Kinematics
    pieces : Pieces
    tol : Tolerances

    Returns
    -------
    dict
        ``{"penetration": CheckResult, "floating": ..., "joint_sweep": ...}``.
    """
    if compiled.ENABLED and pieces.n <= _DENSE and _kernels_match():
        from artipg.validate.jit_scenes import measure

        W0, c0, h0, scenes, rows = measure(kin, pieces, tol, _OVERLAP)
        if rows[4] is not None:
            return _compiled_results(kin, pieces, W0, scenes, rows, tol)
    else:
        W0, c0, h0, scenes = _scenes(kin, pieces, tol)
    rest_s = scenes[0]
    refine_rest(pieces, W0, c0, h0, rest_s, tol)
    return {
        "penetration": _penetration(kin, pieces, rest_s, tol),
        "floating": _floating(kin, pieces, W0, rest_s, tol),
        "joint_sweep": _sweep_result(kin, pieces, scenes[1], scenes[2:], tol),
    }


def refine_rest(pieces: Pieces, W0: np.ndarray, c0: np.ndarray, h0: np.ndarray, rest: dict,
                tol: Tolerances) -> np.ndarray:
    """Refine, in place, the rest scene's distances ``rest["d"]`` of curved pieces whose
    samples say "apart" while their boxes say "maybe touching" (a ball on a plane), before
    contact is judged: the numpy step that :func:`artipg.validate.jit_verdicts.verdicts`
    compiles. ``W0`` (N, 4, 4) are the piece frames at rest, ``c0``, ``h0`` (N, 3) the
    centres and half extents of their world boxes (metres). Returns the refined rows (k,)."""
    ra, rb, rd = rest["a"], rest["b"], rest["d"]
    amb = (~(pieces.is_box[ra] & pieces.is_box[rb]) & (rd > tol.floating)).nonzero()[0]
    if len(amb):
        ia, ib = ra[amb], rb[amb]
        lb = np.sqrt((np.maximum(np.abs(c0[ia] - c0[ib]) - h0[ia] - h0[ib], 0.0) ** 2).sum(axis=1))
        amb = amb[lb <= tol.floating]
    if len(amb):
        rd[amb] = np.minimum(rd[amb], refine_distance(pieces, ra[amb], rb[amb], W0[ra[amb]], W0[rb[amb]],
                                                      iters=3, stop_below=tol.floating))
    return amb


def _compiled_results(kin, pieces, W0, scenes, rows, tol) -> dict[str, CheckResult]:
    """:func:`run_checks` from the scenes of :func:`artipg.validate.jit_scenes.measure`
    (``rows``: their pairs and distances concatenated, the rest rows to refine): the
    refinement and the reductions of the distances in one kernel
    (:func:`artipg.validate.jit_verdicts.verdicts`), the issues as the numpy code."""
    from artipg.validate.jit_contacts import _H, _OFFS, _ON_SURFACE
    from artipg.validate.jit_verdicts import verdicts

    a, b, d, sizes, amb, undrawn = rows
    if undrawn:
        pieces.require(np.concatenate([a[amb], b[amb]]))
    code, aux, _ = pieces.jit_table
    (bad, n_bad, low, comp, pcomp, has_geom, has_piece, several, split) = verdicts(
        amb, a, b, W0, d, sizes, 3, 3, pieces.params, code, aux, pieces.points_t, pieces.start, pieces.count, _H,
        _ON_SURFACE, _OFFS, pieces.link, pieces.part, pieces.part_link, kin.n_links, len(pieces.part_names),
        float(tol.floating), float(tol.penetration))
    cut = np.concatenate([[0], n_bad.cumsum()])
    low = low.tolist()
    per = [(bad[cut[i]:cut[i + 1]], low[i]) for i in range(len(low))]
    graphs = (comp, pcomp, has_geom, has_piece, split, several)
    return {
        "penetration": _penetration(kin, pieces, scenes[0], tol, per[0]),
        "floating": _floating(kin, pieces, W0, scenes[0], tol, graphs),
        "joint_sweep": _sweep_result(kin, pieces, scenes[1], scenes[2:], tol, per[1:]),
    }


def _scenes(kin, pieces, tol):
    """The rest, sweep and open scenes with their distances ``"d"``: ``(W0, c0, h0,
    [rest, sweep, open...])`` (W0: piece frames at rest, c0, h0: their world boxes)."""
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
    cand = overlapping(0.5 * (lo + hi), 0.5 * (hi - lo), c0, h0, -_OVERLAP) & ~subtree[uj]
    u, b = np.nonzero(cand)
    if not len(u):
        return out
    # expand the candidates over the poses of their joint and test per-pose boxes
    n_rep = counts[u]
    rows = np.arange(n_rep.sum()) + (starts[u] - (n_rep.cumsum() - n_rep)).repeat(n_rep)
    bb = b.repeat(n_rep)
    ok = (np.abs(cm[rows] - c0[bb]) - (hm[rows] + h0[bb]) < -_OVERLAP).all(axis=1)
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
    a, b = close_pairs(c, h, -_OVERLAP, np.array(label)[pieces.link])
    return {"a": a, "b": b, "Wa": W[a], "Wb": W[b], "margin": 0.0, "frac": frac}


# -------------------------------------------------------------------- results

def _names(pieces, kin, a, b):
    links = [kin.names[pieces.link[a]], kin.names[pieces.link[b]]]
    parts = [pieces.part_names[pieces.part[a]], pieces.part_names[pieces.part[b]]]
    return links, parts


def _worst_per_group(keys: np.ndarray, values: np.ndarray):
    """Indices of the minimum value within each group of equal ``keys`` rows."""
    if not len(values):
        return np.zeros(0, dtype=np.int64)
    # depths equal to 1e-12 m are ties (rounding noise must not choose): the first row wins
    order = np.lexsort((np.round(values, 12), *keys.T[::-1]))
    k = keys[order]
    first = np.ones(len(order), dtype=bool)
    first[1:] = (k[1:] != k[:-1]).any(axis=1)
    return order[first]


def _penetration(kin, pieces, s, tol, verdict=None) -> CheckResult:
    """``verdict``: the colliding rows and the lowest distance between different
    links (inf: none) when known (:func:`artipg.validate.jit_verdicts.verdicts`)."""
    a, b, D = s["a"], s["b"], s["d"]
    if verdict is None:
        cross = pieces.link[a] != pieces.link[b]
        bad = (cross & (D < -tol.penetration)).nonzero()[0]
        low = float(D[cross].min()) if cross.any() else np.inf
    else:
        bad, low = verdict
    issues = []
    if len(bad):
        parts = np.sort(np.column_stack([pieces.part[a[bad]], pieces.part[b[bad]]]), axis=1)
        for w in bad[_worst_per_group(parts, D[bad])]:
            links, names = _names(pieces, kin, a[w], b[w])
            pt = deepest_point(pieces, a[w], b[w], s["Wa"][w], s["Wb"][w])
            issues.append(Issue("penetration", "penetration", -float(D[w]), links, names, point=list(pt)))
    issues.sort(key=lambda i: -round(i.amount, 12))  # stable: ties keep their order
    worst = max(0.0, -low)
    return CheckResult("penetration", not issues, worst, issues)


def _components(n: int, i: np.ndarray, j: np.ndarray) -> np.ndarray:
    """Connected-component label (n,) of every node of the undirected edges (i, j):
    the smallest node index of its component (union-find; graphs here are small)."""
    parent = list(range(n))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    if len(i):
        e = np.unique(np.minimum(i, j) * n + np.maximum(i, j))  # each undirected edge once
        for a, b in zip((e // n).tolist(), (e % n).tolist()):
            ra, rb = root(a), root(b)
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
    return np.array([root(x) for x in range(n)], dtype=np.int64)


def _gap(pieces, W0, src_mask, tgt_mask) -> float:
    """Smallest distance (metres) between two sets of pieces at rest."""
    a, b = src_mask.nonzero()[0], tgt_mask.nonzero()[0]
    if not len(a) or not len(b):
        return float("inf")
    A, B = a.repeat(len(b)), np.tile(b, len(a))
    # box-distance lower bounds: evaluate the most promising pairs, then only the
    # pairs that could still beat the best distance found
    c, h = world_boxes(pieces, W0)
    lb = np.sqrt((np.maximum(np.abs(c[A] - c[B]) - h[A] - h[B], 0.0) ** 2).sum(axis=1))
    order = np.argsort(lb, kind="stable")
    first = order[:8]
    d = pair_distance(pieces, A[first], B[first], W0[A[first]], W0[B[first]], np.inf)
    best = float(d.min())
    rest = order[8:][lb[order[8:]] < best]
    if len(rest):
        d2 = pair_distance(pieces, A[rest], B[rest], W0[A[rest]], W0[B[rest]], np.inf)
        first, d = np.concatenate([first, rest]), np.concatenate([d, d2])
        best = float(d.min())
    # sampled distances of curved pieces overshoot: refine the closest candidates
    cand = first[np.argsort(d, kind="stable")[:4]]
    cand = cand[~(pieces.is_box[A[cand]] & pieces.is_box[B[cand]])]
    if len(cand):
        best = min(best, float(refine_distance(pieces, A[cand], B[cand], W0[A[cand]], W0[B[cand]]).min()))
    return max(best, 0.0)


def _contact_graphs(L, P, pieces, a, b, D, tol):
    """:func:`artipg.validate.jit_scenes.contact_graphs` in numpy: the link and part
    contact graphs of the rest pairs (see there)."""
    touch = D <= tol.floating
    has_geom = np.bincount(pieces.link, minlength=L) > 0
    cross = touch & (pieces.link[a] != pieces.link[b])
    comp = _components(L, pieces.link[a[cross]], pieces.link[b[cross]])
    geo = has_geom.nonzero()[0]
    several = len(geo) > 0 and len(np.unique(comp[geo])) > 1
    same = touch & (pieces.link[a] == pieces.link[b])
    pcomp = _components(P, pieces.part[a[same]], pieces.part[b[same]])
    has_piece = np.bincount(pieces.part, minlength=P) > 0
    hp = has_piece.nonzero()[0]
    lo, hi = np.full(L, P), np.full(L, -1)
    np.minimum.at(lo, pieces.part_link[hp], pcomp[hp])
    np.maximum.at(hi, pieces.part_link[hp], pcomp[hp])
    return comp, pcomp, has_geom, has_piece, lo, hi, several


def _floating(kin, pieces, W0, s, tol, graphs=None) -> CheckResult:
    """``graphs``: ``(comp, pcomp, has_geom, has_piece, split, several)`` when known
    (:func:`artipg.validate.jit_verdicts.verdicts`)."""
    a, b, D = s["a"], s["b"], s["d"]
    issues = []
    L = kin.n_links
    P = len(pieces.part_names)
    if graphs is not None:
        comp, pcomp, has_geom, has_piece, split, several = graphs
    else:
        if compiled.ENABLED:
            from artipg.validate.jit_scenes import contact_graphs

            comp, pcomp, has_geom, has_piece, lo, hi, several = contact_graphs(
                L, P, pieces.link, pieces.part, pieces.part_link, a, b, D, float(tol.floating))
        else:
            comp, pcomp, has_geom, has_piece, lo, hi, several = _contact_graphs(L, P, pieces, a, b, D, tol)
        split = (hi > lo).nonzero()[0]
    # links held by an anchored joint (a door with clearance) join their parent's graph
    if several:
        comp, several = _held(kin, pieces, W0, comp, has_geom, tol)
    # links: one contact graph holding the root (or the first link with geometry)
    if several:
        geo = has_geom.nonzero()[0]
        main = comp[geo[0]]
        for c in np.unique(comp[geo]):
            if c == main:
                continue
            links = ((comp == c) & has_geom).nonzero()[0]
            gap = _gap(pieces, W0, np.isin(pieces.link, links), comp[pieces.link] == main)
            if gap <= tol.floating:  # a curved contact the quick pass could not confirm
                continue
            parents = sorted({kin.names[kin.parent[i]] for i in links if kin.parent[i] >= 0})
            issues.append(Issue("floating", "floating_link", gap, [kin.names[i] for i in links], [],
                                detail="does not touch the rest of the object (parent: " + ", ".join(parents) + ")"))
    # parts: the parts of each link form one contact graph; links whose parts fall
    # into more than one component
    split = split.tolist()
    if split:
        weight = np.bincount(pieces.part, weights=np.prod(2 * pieces.half, axis=1), minlength=P)
    for li in split:
        parts = ((pieces.part_link == li) & has_piece).nonzero()[0]
        cs = np.unique(pcomp[parts])
        size = {c: weight[parts[pcomp[parts] == c]].sum() for c in cs}
        main = max(cs, key=lambda c: (size[c], -c))
        for c in cs:
            if c == main:
                continue
            group = parts[pcomp[parts] == c]
            others = parts[pcomp[parts] != c]
            gap = _gap(pieces, W0, np.isin(pieces.part, group), np.isin(pieces.part, others))
            if gap <= tol.floating:
                continue
            issues.append(Issue("floating", "floating_part", gap, [kin.names[li]],
                                [pieces.part_names[p] for p in group], detail="does not touch the other parts of its link"))
    issues.sort(key=lambda i: -round(i.amount, 12))  # stable: ties keep their order
    worst = max([0.0] + [i.amount for i in issues])
    return CheckResult("floating", not issues, worst, issues)


def _held(kin, pieces, W0, comp, has_geom, tol):
    """The link components with those held by an anchored joint merged into their
    parent's (:func:`artipg.validate.anchoring.held_components`), and whether several
    remain among the links with geometry."""
    from artipg.validate.anchoring import REACH_FACTOR, held_components

    comp = held_components(kin, pieces, W0, comp, has_geom, REACH_FACTOR * tol.floating)
    geo = np.asarray(has_geom, dtype=bool).nonzero()[0]
    return comp, len(geo) > 0 and len(np.unique(comp[geo])) > 1


def _blocker(kin, link: int, j: int) -> int:
    """The movable joint closest to the root among those at or above ``link`` that
    joint ``j`` does not ride on (its link index), or -1: opening it moves ``link``
    (a knob on a door moves with the door)."""
    out = -1
    while link > 0:
        if kin.joint_types[link] != "fixed" and not kin.descendants[link, j]:
            out = link
        link = int(kin.parent[link])
    return out


def _blockers(kin, pieces, sw, bad):
    """Moving joint and :func:`_blocker` (link indices, (len(bad),) int64 arrays) of
    each sweep row ``bad``."""
    j = sw["movable"][sw["joint"][sw["scene"][bad]]]
    lb = pieces.link[sw["b"][bad]]
    _, first, inv = np.unique(j * kin.n_links + lb, return_index=True, return_inverse=True)
    k = np.array([_blocker(kin, int(lb[f]), int(j[f])) for f in first.tolist()], dtype=np.int64)[inv]
    return j, k


def _needs_open(kin, pieces, sw, tol, bad):
    """Sweep collisions with a part that another joint moves (a rack behind a
    dishwasher door): re-checked with that joint open. All (moving joint, blocking
    joint) pairs share one batch of poses and one distance pass.

    Returns ``(pairs, depth, row_pair)``: the (j, k) link index pairs of the colliding
    sweep rows ``bad`` with a blocker (:func:`_blocker`), in order of first occurrence;
    the deepest penetration (P,) of each with k open (< 0: opening k clears the way for
    j; 0 where no pair of pieces overlaps); the index into ``pairs`` of each bad row
    (-1: no blocker)."""
    if compiled.ENABLED and _kernels_match():
        from artipg.validate.jit_scenes import needs_open_rows

        row_pair, pj, pk, A, B, Wa, Wb, owner = needs_open_rows(
            bad, sw["scene"], sw["joint"], sw["q"], sw["b"], sw["movable"], kin.parent, kin.not_fixed,
            kin.type_codes, kin.limits, kin.origin, kin.axis, kin.descendants, pieces.link, pieces.T, pieces.center,
            pieces.half, -_OVERLAP)
        pairs = list(zip(pj.tolist(), pk.tolist()))
    else:
        j, k = _blockers(kin, pieces, sw, bad)
        sel = (k > 0).nonzero()[0]
        keys, first, inv = np.unique(j[sel] * kin.n_links + k[sel], return_index=True, return_inverse=True)
        order = np.argsort(first)  # in order of first occurrence
        rank = np.empty(len(order), dtype=np.int64)
        rank[order] = np.arange(len(order))
        row_pair = np.full(len(bad), -1, dtype=np.int64)
        row_pair[sel] = rank[inv.reshape(-1)]
        pairs = [(int(x) // kin.n_links, int(x) % kin.n_links) for x in keys[order]]
        if not pairs:
            return pairs, np.zeros(0), row_pair
        up = kin.open_values(1.0)
        Qs = []
        for j, k in pairs:
            qs = kin.sweep_values(j, tol.sweep_poses)
            Q = np.zeros((len(qs), kin.n_links))
            Q[:, j], Q[:, k] = qs, up[kin.joint_names[k]]
            Qs.append(Q)
        A, B, Wa, Wb, owner = _blocked_rows(kin, pieces, pairs, Qs)
    worst = np.full(len(pairs), -np.inf)
    if len(A):
        np.maximum.at(worst, owner, -pair_distance(pieces, A, B, Wa, Wb, 0.0))
    return pairs, np.where(np.isfinite(worst), worst, 0.0), row_pair


def _blocked_rows(kin, pieces, pairs, Qs):
    """The pairs of pieces :func:`_needs_open` measures: for each (moving joint j,
    blocking joint k) and its joint values ``Qs`` (rows (S, L)), the pieces only j
    moves against those only k moves, where their boxes overlap; ``(a, b, Wa, Wb,
    owner)`` (owner: the index of the (j, k) pair)."""
    rows, A, B, Wa, Wb, owner = 0, [], [], [], [], []
    P = kin.poses_batch(np.concatenate(Qs))
    for p, (j, k) in enumerate(pairs):
        S = len(Qs[p])
        sub_j = kin.subtree(j)[pieces.link]
        sub_k = kin.subtree(k)[pieces.link]
        a, b = (sub_j & ~sub_k).nonzero()[0], (sub_k & ~sub_j).nonzero()[0]
        both = np.concatenate([a, b])
        W = P[rows:rows + S][:, pieces.link[both]] @ pieces.T[both]  # (S, |a| + |b|, 4, 4)
        rows += S
        c, h = world_boxes(pieces, W.reshape(-1, 4, 4), np.tile(both, S))
        c, h = c.T.reshape(3, S, len(both)), h.T.reshape(3, S, len(both))  # one axis at a time
        na = len(a)
        ok = True
        for k in range(3):
            ok = ok & (np.abs(c[k, :, :na, None] - c[k, :, None, na:]) - (h[k, :, :na, None] + h[k, :, None, na:])
                       < -_OVERLAP)
        si, ia, ib = np.nonzero(ok)
        A.append(a[ia]), B.append(b[ib]), Wa.append(W[si, ia]), Wb.append(W[si, na + ib])
        owner.append(np.full(len(ia), p))
    return (np.concatenate(A), np.concatenate(B), np.concatenate(Wa), np.concatenate(Wb), np.concatenate(owner))


def _sweep_result(kin, pieces, sw, opens, tol, verdicts=None) -> CheckResult:
    """``verdicts``: the colliding rows and the lowest distance (inf: no rows) of the
    sweep and of each open scene when known (:func:`artipg.validate.jit_verdicts.verdicts`)."""
    if verdicts is None:
        verdicts = [((s["d"] < -tol.penetration).nonzero()[0], float(s["d"].min()) if len(s["d"]) else np.inf)
                    for s in [sw] + list(opens)]
    issues = []
    D = sw["d"]
    bad, low = verdicts[0]
    worst = max(0.0, -low)
    info = {"joints": int(len(sw["movable"])), "poses": int(len(sw["q"])), "open_poses": len(opens)}
    if len(bad):
        # a collision with a part another joint moves is no fault when opening that
        # joint clears the way (racks behind a door): keep the rest
        pairs, depth, row_pair = _needs_open(kin, pieces, sw, tol, bad)
        clear = depth <= tol.penetration
        if clear.any():
            cleared = [pairs[p] for p in clear.nonzero()[0].tolist()]
            info["needs_open"] = {kin.joint_names[j]: sorted(kin.joint_names[k] for jj, k in cleared if jj == j)
                                  for j in sorted({j for j, _ in cleared})}
            bad = bad[~np.append(clear, False)[row_pair]]  # row_pair -1: the appended False
            worst = max(0.0, float(-D[bad].min())) if len(bad) else 0.0
    if len(bad):
        joint = sw["joint"][sw["scene"][bad]]
        keys = np.column_stack([joint, pieces.link[sw["a"][bad]], pieces.link[sw["b"][bad]]])
        for w in bad[_worst_per_group(keys, D[bad])]:
            sc = sw["scene"][w]
            i = sw["movable"][sw["joint"][sc]]
            links, names = _names(pieces, kin, sw["a"][w], sw["b"][w])
            pt = deepest_point(pieces, sw["a"][w], sw["b"][w], sw["Wa"][w], sw["Wb"][w])
            issues.append(Issue("joint_sweep", "sweep_penetration", -float(D[w]), links, names,
                                joint=kin.joint_names[i], q=float(sw["q"][sc]), point=list(pt)))
    for s, (bad, low) in zip(opens, verdicts[1:]):
        D = s["d"]
        worst = max(worst, -low)
        if len(bad):
            keys = np.column_stack([pieces.link[s["a"][bad]], pieces.link[s["b"][bad]]])
            for w in bad[_worst_per_group(keys, D[bad])]:
                links, names = _names(pieces, kin, s["a"][w], s["b"][w])
                pt = deepest_point(pieces, s["a"][w], s["b"][w], s["Wa"][w], s["Wb"][w])
                issues.append(Issue("joint_sweep", "open_penetration", -float(D[w]), links, names, q=float(s["frac"]),
                                    point=list(pt), detail=f"all joints at {s['frac']:g} of their range"))
    issues.sort(key=lambda i: -round(i.amount, 12))  # stable: ties keep their order
    return CheckResult("joint_sweep", not issues, worst, issues, info)
