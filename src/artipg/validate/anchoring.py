"""Links held by their joint: a door with clearance round it is not floating.

The floating check asks whether every link touches the rest of the object at rest.
Real objects are modelled with clearance: a door stands a few millimetres off its
carcass and is held by its hinge, a drawer by its slide. A link group that touches
nothing counts as held when the movable joint that carries it is *anchored in both
links' geometry*:

- revolute / continuous: the joint's axis line passes within ``reach`` of the
  child's geometry and of the parent's, both measured over the stretch of the axis
  that the child spans (a hinge along the door's edge and the carcass's edge);
- prismatic: the child lies within the parent's footprint across the slide (its
  extent perpendicular to the axis inside the parent's, grown by ``reach``), and
  their extents along the axis overlap (a drawer in its carcass).

``reach`` is :data:`REACH_FACTOR` times the floating tolerance. Fixed joints hold
nothing: a handle on a fixed joint must touch its door. Geometry is taken from the
pieces' surface samples at rest; the parent side is the parent link's pieces, or
every piece outside the child's subtree when the parent link has none (an empty
PartNet-Mobility ``base``).
"""

from __future__ import annotations

import numpy as np

#: Anchoring reach as a multiple of the floating tolerance (a hinge pin may sit
#: this far from either leaf, a slide's runner this far outside its carcass).
REACH_FACTOR = 5.0


def _world_samples(pieces, W0: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Surface samples (n, 3), world frame at rest, of the pieces ``mask`` (M,) bool."""
    rows = mask.nonzero()[0]
    if not len(rows):
        return np.zeros((0, 3))
    pieces.require(rows)
    counts = pieces.count[rows]
    idx = np.concatenate([np.arange(s, s + c) for s, c in zip(pieces.start[rows], counts)])
    owner = rows.repeat(counts)
    X = pieces.points[idx]
    W = W0[owner]
    return np.einsum("nij,nj->ni", W[:, :3, :3], X) + W[:, :3, 3]


def joint_anchored(kin, pieces, W0: np.ndarray, child: int, reach: float) -> bool:
    """Whether link ``child``'s movable joint is anchored in the geometry of both its
    subtree and its parent (see module docstring).

    Parameters
    ----------
    kin : artipg.validate.kinematics.Kinematics
    pieces : artipg.validate.shapes.Pieces
    W0 : (M, 4, 4) float64
        Piece frames at rest (object frame).
    child : int
        Link index (not the root).
    reach : float
        Largest gap between the joint and either side's geometry (object units).
    """
    jt = kin.joint_types[child]
    if jt not in ("revolute", "continuous", "prismatic") or kin.parent[child] < 0:
        return False
    sub = kin.subtree(child)[pieces.link]
    par = pieces.link == kin.parent[child]
    if not par.any():
        par = ~sub
    A, B = _world_samples(pieces, W0, sub), _world_samples(pieces, W0, par)
    if not len(A) or not len(B):
        return False
    axes = kin.world_axes(kin.poses())
    j = int(np.searchsorted(kin.movable(), child))
    a, p = axes[0][j], axes[1][j]
    ta, tb = (A - p) @ a, (B - p) @ a
    if jt == "prismatic":
        basis = np.linalg.svd(a[None, :])[2][1:]  # two unit vectors across the axis
        ua, ub = A @ basis.T, B @ basis.T
        inside = (ua.min(axis=0) >= ub.min(axis=0) - reach).all() and (ua.max(axis=0) <= ub.max(axis=0) + reach).all()
        return bool(inside and ta.min() <= tb.max() + reach and tb.min() <= ta.max() + reach)
    lo, hi = ta.min() - reach, ta.max() + reach  # the stretch of axis the child spans

    def near(X, t):
        sel = (t >= lo) & (t <= hi)
        if not sel.any():
            return False
        r = (X[sel] - p) - t[sel, None] * a
        return bool((r * r).sum(axis=1).min() <= reach * reach)

    return near(A, ta) and near(B, tb)


def held_components(kin, pieces, W0: np.ndarray, comp: np.ndarray, has_geom: np.ndarray, reach: float) -> np.ndarray:
    """Link contact components (L,) with every component that an anchored joint holds
    merged into its parent's component (repeated until nothing changes: a knob
    touching a held door is held too).

    Parameters
    ----------
    comp : (L,) int64
        Component label of every link (the contact graph at rest).
    has_geom : (L,) bool
        Links with geometry.
    reach : float
        See :func:`joint_anchored`.
    """
    comp = np.asarray(comp, dtype=np.int64).copy()
    has_geom = np.asarray(has_geom, dtype=bool)
    cache: dict = {}
    changed = True
    while changed:
        changed = False
        for child in range(1, kin.n_links):
            par = int(kin.parent[child])
            if par < 0 or not has_geom[child]:
                continue
            if not has_geom[par]:  # an empty parent: the first link with geometry outside the subtree
                out = (has_geom & ~kin.subtree(child)).nonzero()[0]
                if not len(out):
                    continue
                par = int(out[0])
            if comp[child] == comp[par]:
                continue
            if child not in cache:
                cache[child] = joint_anchored(kin, pieces, W0, child, reach)
            if cache[child]:
                comp[comp == comp[child]] = comp[par]
                changed = True
    return comp
