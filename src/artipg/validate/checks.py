"""The geometric checks: penetration at rest, floating links and parts, joint sweeps.

All three share one batched distance pass
(:func:`artipg.validate.contacts.pair_distance`) over three kinds of scenes
(:mod:`artipg.validate.scenes`):

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

from artipg.validate.contacts import deepest_point, pair_distance, refine_distance, world_boxes
from artipg.validate.kinematics import Kinematics
from artipg.validate.report import CheckResult, Issue
from artipg.validate.scenes import OVERLAP, scenes
from artipg.validate.shapes import Pieces


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
    W0, c0, h0, found = scenes(kin, pieces, tol)
    rest_s = found[0]
    refine_rest(pieces, W0, c0, h0, rest_s, tol)
    return {
        "penetration": _penetration(kin, pieces, rest_s, tol),
        "floating": _floating(kin, pieces, W0, rest_s, tol),
        "joint_sweep": _sweep_result(kin, pieces, found[1], found[2:], tol),
    }


def refine_rest(pieces: Pieces, W0: np.ndarray, c0: np.ndarray, h0: np.ndarray, rest: dict,
                tol: Tolerances) -> np.ndarray:
    """Refine, in place, the rest scene's distances ``rest["d"]`` of curved pieces whose
    samples say "apart" while their boxes say "maybe touching" (a ball on a plane), before
    contact is judged. ``W0`` (N, 4, 4) are the piece frames at rest, ``c0``, ``h0`` (N, 3) the
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


def _penetration(kin, pieces, s, tol) -> CheckResult:
    """Pairs of pieces of different links at rest deeper in each other than the tolerance."""
    a, b, D = s["a"], s["b"], s["d"]
    cross = pieces.link[a] != pieces.link[b]
    bad = (cross & (D < -tol.penetration)).nonzero()[0]
    low = float(D[cross].min()) if cross.any() else np.inf
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
    """The contact graphs of the rest pairs (``D``: their distances) of ``L`` links
    and ``P`` parts: the component label of every link (touching across links) and
    of every part (touching within a link), whether each link / part has pieces, the
    lowest and highest part component of every link, and whether the links with
    geometry fall into several components."""
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


def _floating(kin, pieces, W0, s, tol) -> CheckResult:
    """Links that touch no other link (through the contact graph of the rest pairs
    ``s``) and parts that touch no other part of their link."""
    a, b, D = s["a"], s["b"], s["d"]
    issues = []
    L = kin.n_links
    P = len(pieces.part_names)
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
        # parts touching another link hold their link's parts (a seat moved off its
        # column floats, not the column that stands on the base)
        cross = (pieces.link[a] != pieces.link[b]) & (D <= tol.floating)
        touching = np.zeros(P, dtype=bool)
        touching[pieces.part[a[cross]]] = True
        touching[pieces.part[b[cross]]] = True
    for li in split:
        parts = ((pieces.part_link == li) & has_piece).nonzero()[0]
        cs = np.unique(pcomp[parts])
        size = {c: (touching[parts[pcomp[parts] == c]].any(), weight[parts[pcomp[parts] == c]].sum()) for c in cs}
        main = max(cs, key=lambda c: (*size[c], -c))
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
                       < -OVERLAP)
        si, ia, ib = np.nonzero(ok)
        A.append(a[ia]), B.append(b[ib]), Wa.append(W[si, ia]), Wb.append(W[si, na + ib])
        owner.append(np.full(len(ia), p))
    return (np.concatenate(A), np.concatenate(B), np.concatenate(Wa), np.concatenate(Wb), np.concatenate(owner))


def _sweep_result(kin, pieces, sw, opens, tol) -> CheckResult:
    """Collisions of the joint sweeps ``sw`` and the all-joints-open scenes ``opens``."""
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
