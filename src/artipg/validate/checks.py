"""The geometric checks: penetration at rest, floating links and parts, joint sweeps.

All three share one batched distance pass (:func:`artipg.validate.contacts.evaluate`)
over three kinds of scenes:

- *rest*: every pair of pieces of different parts whose boxes come within the
  floating tolerance; gives penetration depths between links (parent-child pairs
  included) and the contact graphs of links and of the parts inside each link;
- *sweep*: each movable joint at ``sweep_poses`` values over its range (continuous:
  a full turn), its subtree moving and everything else at rest;
- *open*: all joints together at half and at full opening, for objects with
  several movable joints (two doors of one cabinet, a drawer under a lid).

Penetration depth is minus the lowest signed distance of one piece's surface samples
to another piece (both directions); a gap is the lowest positive one.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from artipg.validate.contacts import deepest_point, evaluate, overlapping, pair_jobs, world_boxes
from artipg.validate.kinematics import Kinematics, motion, rigid_inverse
from artipg.validate.report import CheckResult, Issue
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
    open_fractions: tuple = (0.5, 1.0)

    def to_json(self) -> dict:
        return {k: list(v) if isinstance(v, tuple) else v for k, v in asdict(self).items()}


_REST, _SWEEP, _OPEN = 0, 1, 2
#: Boxes must overlap by this much on every axis before a pair is checked for
#: penetration (metres): touching faces are skipped, real overlaps are not.
_OVERLAP = 1e-4


class _Jobs:
    """Accumulates distance jobs with their scene bookkeeping."""

    def __init__(self):
        self.cols = {k: [] for k in ("src", "tgt", "rel", "margin", "kind", "scene", "pair")}

    def add(self, src, tgt, rel, margin, kind, scene, pair):
        n = len(src)
        c = self.cols
        c["src"].append(src)
        c["tgt"].append(tgt)
        c["rel"].append(rel)
        c["margin"].append(np.full(n, margin))
        c["kind"].append(np.full(n, kind, dtype=np.int64))
        c["scene"].append(np.broadcast_to(np.asarray(scene, dtype=np.int64), (n,)))
        c["pair"].append(np.asarray(pair, dtype=np.int64))

    def arrays(self) -> dict:
        out = {}
        for k, v in self.cols.items():
            if v:
                out[k] = np.concatenate(v)
            else:
                out[k] = np.zeros((0, 4, 4)) if k == "rel" else np.zeros(0, dtype=np.int64)
        return out


def run_checks(kin: Kinematics, pieces: Pieces, tol: Tolerances = Tolerances()) -> dict[str, CheckResult]:
    """Run penetration, floating and joint-sweep checks.

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
    rest = kin.poses()
    W0 = rest[pieces.link] @ pieces.T
    c0, h0 = world_boxes(pieces, W0)
    jobs = _Jobs()

    # ---------------------------------------------------------------- rest scene
    M = pieces.n
    a, b = np.triu_indices(M, 1)
    ov = overlapping(c0, h0, c0, h0, tol.floating)[a, b] & (pieces.part[a] != pieces.part[b])
    ra, rb = a[ov], b[ov]
    rel_ab, rel_ba = pair_jobs(W0[ra], W0[rb])
    pid = np.arange(len(ra))
    jobs.add(ra, rb, rel_ab, tol.floating, _REST, 0, pid)
    jobs.add(rb, ra, rel_ba, tol.floating, _REST, 0, pid)

    # ---------------------------------------------------------------- sweeps
    movable = kin.movable()
    sweep_meta = _sweep_jobs(kin, pieces, rest, W0, c0, h0, movable, tol, jobs)

    # ---------------------------------------------------------------- all open
    open_meta = []
    if len(movable) >= 2:
        for s, frac in enumerate(tol.open_fractions):
            open_meta.append(_open_jobs(kin, pieces, rest, frac, s, jobs))

    J = jobs.arrays()
    d = evaluate(pieces, J["src"], J["tgt"], J["rel"], J["margin"])

    rest_sel = J["kind"] == _REST
    D = np.full(len(ra), np.inf)
    np.minimum.at(D, J["pair"][rest_sel], d[rest_sel])
    out = {
        "penetration": _penetration(kin, pieces, W0, ra, rb, D, tol),
        "floating": _floating(kin, pieces, W0, ra, rb, D, tol),
    }
    out["joint_sweep"] = _sweep_result(kin, pieces, J, d, sweep_meta, open_meta, tol)
    return out


# -------------------------------------------------------------------- job building

def _sweep_jobs(kin, pieces, rest, W0, c0, h0, movable, tol, jobs):
    """Jobs for every movable joint at ``tol.sweep_poses`` values; returns scene info."""
    M = pieces.n
    if not len(movable) or M == 0:
        return None
    G, scene_joint, scene_q = [], [], []
    moving = np.zeros((len(movable), M), dtype=bool)
    for k, i in enumerate(movable):
        moving[k] = kin.subtree(i)[pieces.link]
        v = kin.sweep_values(i, tol.sweep_poses)
        A = rest[i]
        G.append(A @ motion(kin.joint_types[i], kin.axis[i], v) @ rigid_inverse(A))
        scene_joint.append(np.full(len(v), k))
        scene_q.append(v)
    G = np.concatenate(G)
    scene_joint = np.concatenate(scene_joint)
    scene_q = np.concatenate(scene_q)
    s_idx, p_idx = np.nonzero(moving[scene_joint])  # (scene, moving piece) rows
    Wm = G[s_idx] @ W0[p_idx]
    cm, hm = world_boxes(pieces, Wm, p_idx)
    ov = overlapping(cm, hm, c0, h0, -_OVERLAP) & ~moving[scene_joint[s_idx]]
    r, b = np.nonzero(ov)
    if len(r):
        a = p_idx[r]
        rel_ab, rel_ba = pair_jobs(Wm[r], W0[b])
        scene = s_idx[r]
        pid = np.arange(len(r))
        jobs.add(a, b, rel_ab, 0.0, _SWEEP, scene, pid)
        jobs.add(b, a, rel_ba, 0.0, _SWEEP, scene, pid)
    return {"joint": scene_joint, "q": scene_q, "movable": movable, "a": p_idx[r], "b": b,
            "scene": s_idx[r], "Wa": Wm[r]}


def _open_jobs(kin, pieces, rest, frac, s, jobs):
    P = kin.poses(kin.open_values(frac))
    W = P[pieces.link] @ pieces.T
    c, h = world_boxes(pieces, W)
    # link pairs whose relative pose differs from rest (others were checked at rest)
    rel_rest = rigid_inverse(rest)[:, None] @ rest[None]
    rel_open = rigid_inverse(P)[:, None] @ P[None]
    changed = ~np.isclose(rel_rest, rel_open, atol=1e-9).all(axis=(2, 3))
    a, b = np.triu_indices(pieces.n, 1)
    la, lb = pieces.link[a], pieces.link[b]
    keep = (la != lb) & changed[la, lb]
    a, b = a[keep], b[keep]
    ov = overlapping(c[a], h[a], c[b], h[b], -_OVERLAP)[np.arange(len(a)), np.arange(len(a))] if len(a) else a
    a, b = a[ov], b[ov] if len(a) else (a, b)
    rel_ab, rel_ba = pair_jobs(W[a], W[b])
    pid = np.arange(len(a))
    jobs.add(a, b, rel_ab, 0.0, _OPEN, s, pid)
    jobs.add(b, a, rel_ba, 0.0, _OPEN, s, pid)
    return {"frac": frac, "a": a, "b": b, "W": W, "q": kin.open_values(frac)}


# -------------------------------------------------------------------- results

def _names(pieces, kin, a, b):
    links = [kin.names[pieces.link[a]], kin.names[pieces.link[b]]]
    parts = [pieces.part_names[pieces.part[a]], pieces.part_names[pieces.part[b]]]
    return links, parts


def _worst_per_group(keys: np.ndarray, values: np.ndarray):
    """Indices of the minimum value within each group of equal ``keys`` rows."""
    if not len(values):
        return np.zeros(0, dtype=np.int64)
    order = np.lexsort((values, *keys.T[::-1]))
    k = keys[order]
    first = np.ones(len(order), dtype=bool)
    first[1:] = (k[1:] != k[:-1]).any(axis=1)
    return order[first]


def _penetration(kin, pieces, W0, ra, rb, D, tol) -> CheckResult:
    cross = pieces.link[ra] != pieces.link[rb]
    bad = np.flatnonzero(cross & (D < -tol.penetration))
    issues = []
    if len(bad):
        parts = np.sort(np.column_stack([pieces.part[ra[bad]], pieces.part[rb[bad]]]), axis=1)
        for w in bad[_worst_per_group(parts, D[bad])]:
            a, b = ra[w], rb[w]
            rel_ab, rel_ba = pair_jobs(W0[a][None], W0[b][None])
            pa, da = deepest_point(pieces, a, b, rel_ab[0], W0[a])
            pb, db = deepest_point(pieces, b, a, rel_ba[0], W0[b])
            links, names = _names(pieces, kin, a, b)
            issues.append(Issue("penetration", "penetration", -float(D[w]), links, names,
                                point=list(pa if da <= db else pb)))
    issues.sort(key=lambda i: -i.amount)
    worst = max([0.0] + [float(-x) for x in D[cross]]) if cross.any() else 0.0
    return CheckResult("penetration", not issues, worst, issues)


def _components(n: int, i: np.ndarray, j: np.ndarray) -> np.ndarray:
    g = coo_matrix((np.ones(len(i)), (i, j)), shape=(n, n))
    return connected_components(g, directed=False)[1]


def _gap(pieces, W0, src_mask, tgt_mask) -> float:
    """Exact smallest distance (metres) between two sets of pieces at rest."""
    a, b = np.flatnonzero(src_mask), np.flatnonzero(tgt_mask)
    if not len(a) or not len(b):
        return float("inf")
    A, B = np.repeat(a, len(b)), np.tile(b, len(a))
    rel_ab, rel_ba = pair_jobs(W0[A], W0[B])
    d = evaluate(pieces, np.concatenate([A, B]), np.concatenate([B, A]), np.concatenate([rel_ab, rel_ba]), np.inf)
    return float(max(d.min(), 0.0))


def _floating(kin, pieces, W0, ra, rb, D, tol) -> CheckResult:
    issues = []
    touch = D <= tol.floating
    L = kin.n_links
    has_geom = np.bincount(pieces.link, minlength=L) > 0
    # links: one connected contact graph containing the root (or the first link with geometry)
    cross = touch & (pieces.link[ra] != pieces.link[rb])
    comp = _components(L, pieces.link[ra[cross]], pieces.link[rb[cross]])
    geo = np.flatnonzero(has_geom)
    if len(geo):
        main = comp[geo[0]]
        for c in np.unique(comp[geo]):
            if c == main:
                continue
            links = np.flatnonzero((comp == c) & has_geom)
            gap = _gap(pieces, W0, np.isin(pieces.link, links), comp[pieces.link] == main)
            parents = {kin.names[kin.parent[i]] for i in links if kin.parent[i] >= 0}
            issues.append(Issue("floating", "floating_link", gap, [kin.names[i] for i in links], [],
                                detail="not touching the rest of the object (parent: " + ", ".join(sorted(parents)) + ")"))
    # parts: the parts of each link form one connected contact graph
    P = len(pieces.part_names)
    same = touch & (pieces.link[ra] == pieces.link[rb])
    pcomp = _components(P, pieces.part[ra[same]], pieces.part[rb[same]])
    has_piece = np.bincount(pieces.part, minlength=P) > 0
    weight = np.bincount(pieces.part, weights=pieces.counts.astype(float), minlength=P)
    for li in range(L):
        parts = np.flatnonzero((pieces.part_link == li) & has_piece)
        cs = np.unique(pcomp[parts])
        if len(cs) < 2:
            continue
        size = {c: weight[parts[pcomp[parts] == c]].sum() for c in cs}
        main = max(cs, key=lambda c: (size[c], -c))
        for c in cs:
            if c == main:
                continue
            group = parts[pcomp[parts] == c]
            rest_parts = parts[pcomp[parts] != c]
            gap = _gap(pieces, W0, np.isin(pieces.part, group), np.isin(pieces.part, rest_parts))
            issues.append(Issue("floating", "floating_part", gap, [kin.names[li]],
                                [pieces.part_names[p] for p in group], detail="not touching the other parts of its link"))
    issues.sort(key=lambda i: -i.amount)
    worst = max([0.0] + [i.amount for i in issues])
    return CheckResult("floating", not issues, worst, issues)


def _sweep_result(kin, pieces, J, d, sweep_meta, open_meta, tol) -> CheckResult:
    issues = []
    worst = 0.0
    info = {"joints": 0, "poses": 0}
    sel = J["kind"] == _SWEEP
    if sweep_meta is not None:
        info["joints"] = int(len(sweep_meta["movable"]))
        info["poses"] = int(len(sweep_meta["q"]))
        Dp = np.full(len(sweep_meta["a"]), np.inf)
        np.minimum.at(Dp, J["pair"][sel], d[sel])
        if len(Dp):
            worst = max(worst, float(-Dp.min()))
        bad = np.flatnonzero(Dp < -tol.penetration)
        if len(bad):
            a, b = sweep_meta["a"][bad], sweep_meta["b"][bad]
            joint = sweep_meta["joint"][sweep_meta["scene"][bad]]
            keys = np.column_stack([joint, pieces.link[a], pieces.link[b]])
            for w in bad[_worst_per_group(keys, Dp[bad])]:
                a, b, s = sweep_meta["a"][w], sweep_meta["b"][w], sweep_meta["scene"][w]
                i = sweep_meta["movable"][sweep_meta["joint"][s]]
                links, names = _names(pieces, kin, a, b)
                issues.append(Issue("joint_sweep", "sweep_penetration", -float(Dp[w]), links, names,
                                    joint=kin.joint_names[i], q=float(sweep_meta["q"][s])))
    for s, meta in enumerate(open_meta):
        m = (J["kind"] == _OPEN) & (J["scene"] == s)
        Do = np.full(len(meta["a"]), np.inf)
        np.minimum.at(Do, J["pair"][m], d[m])
        if len(Do):
            worst = max(worst, float(-Do.min()))
        bad = np.flatnonzero(Do < -tol.penetration)
        if len(bad):
            keys = np.column_stack([pieces.link[meta["a"][bad]], pieces.link[meta["b"][bad]]])
            for w in bad[_worst_per_group(keys, Do[bad])]:
                links, names = _names(pieces, kin, meta["a"][w], meta["b"][w])
                issues.append(Issue("joint_sweep", "open_penetration", -float(Do[w]), links, names,
                                    q=float(meta["frac"]), detail=f"all joints at {meta['frac']:g} of their range"))
    issues.sort(key=lambda i: -i.amount)
    return CheckResult("joint_sweep", not issues, max(worst, 0.0), issues, info)
