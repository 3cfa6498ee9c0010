"""What the fit compares: an object's normalised clouds at a few joint states, its
links (label, area share, joint) and its proportions, for a generated object or a
folder on disk (PartNet-Mobility's or artipg's).

Pose convention. Both sides are compared at joint-state fractions ``t`` in
:data:`STATES`: ``t = 0`` closed, ``t = 1`` open, every limited joint moved together
(continuous joints stay at 0). "Closed" is decided by geometry, the same way on both
sides: of a joint's two ends (the others joints at 0), the one at which the object is
more compact, i.e. the mean squared distance of its surface points from their centroid
at q = 0 is smaller (the end nearer 0 on a tie within 0.1 %, e.g. a knob). A real
joint's ends are its limits (PartNet-Mobility's 0 is the modelled pose: laptops open,
so closed is a limit); ours are 0 and the limit farther from it (DESIGN.md: 0 is the
rest pose), and 0 is not always the compact end (eyeglasses rest unfolded, and are
compared folded). A whole-object bounding box would not do: folding one temple of a
pair leaves the box as it is.

Frames. Clouds are in the object frame (+Z up, front -X) at the closed state,
centred on the closed cloud's bounding-box centre and divided by its diagonal, and the
other states use the same centre and scale (an open door sticks out). Prismatic travel
is given in those units too, revolute travel in radians.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from artipg.fit.labels import BODY

#: semantics.txt motions of links that no joint moves.
BODY_MOTIONS = ("static", "free", "heavy")
#: Joint-state fractions compared: closed, half open, open.
STATES = (0.0, 0.5, 1.0)
LIMITED = ("revolute", "prismatic")


@dataclass
class Shape:
    """An object as the fit sees it.

    Attributes
    ----------
    clouds : (S, N, 3) float64
        Whole-object points at the states of :data:`STATES`, normalised (module doc).
    link : (N,) int64
        Link (index into ``names``) of every point (the same at every state).
    link_clouds : list of list of (n_i, 3) float64
        ``link_clouds[s][i]``: points of link ``i`` at state ``s``, normalised.
    names, labels, raw_labels : tuple of str
        Link names; their class for matching (``"body"`` for links no joint moves);
        the label as written (``semantics.txt``, or our part semantic).
    share : (L,) float64
        Area share of every link.
    joint_type : tuple of str
        Type of the joint moving each link (``"fixed"`` for body links).
    axis : (L, 3) float64
        Joint axis in the object frame at the closed state (zeros for body links).
    travel : (L,) float64
        |open - closed| of the link's joint (radians; normalised units for prismatic).
    extents : (3,) float64
        Bounding-box size (x depth, y width, z height) at the closed state, in the
        object's own units (metres for ours).
    """

    clouds: np.ndarray
    link: np.ndarray
    link_clouds: list
    names: tuple
    labels: tuple
    raw_labels: tuple
    share: np.ndarray
    joint_type: tuple
    axis: np.ndarray
    travel: np.ndarray
    extents: np.ndarray

    @property
    def centroids(self) -> np.ndarray:
        """Centre (L, 3) of every link's points at the closed state."""
        return np.array([c.mean(axis=0) if len(c) else np.full(3, np.nan) for c in self.link_clouds[0]])

    @property
    def link_extents(self) -> np.ndarray:
        """Bounding-box size (L, 3) of every link's points at the closed state."""
        return np.array([np.ptp(c, axis=0) if len(c) else np.zeros(3) for c in self.link_clouds[0]])


def bbox_frame(points: np.ndarray) -> tuple[np.ndarray, float]:
    """(centre (3,), diagonal) of the axis-aligned box of ``points`` (N, 3)."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    diag = float(np.linalg.norm(hi - lo))
    return (lo + hi) / 2, diag if diag > 0 else 1.0


def _split(points: np.ndarray, link: np.ndarray, n_links: int) -> list:
    order = np.argsort(link, kind="stable")
    return np.split(points[order], np.cumsum(np.bincount(link, minlength=n_links))[:-1])


def _assemble(clouds, link, names, labels, raw, jtype, axis, travel_raw, link_clouds=None) -> Shape:
    """Normalise raw clouds (S, N, 3) by the closed state's box and build the Shape."""
    centre, diag = bbox_frame(clouds[0])
    extents = np.ptp(clouds[0], axis=0)
    clouds = (clouds - centre) / diag
    L = len(names)
    if link_clouds is None:
        link_clouds = [_split(c, link, L) for c in clouds]
    else:
        link_clouds = [[(c - centre) / diag for c in per] for per in link_clouds]
    travel = np.array([t / diag if j == "prismatic" else t for t, j in zip(travel_raw, jtype)], dtype=float)
    share = np.bincount(link, minlength=L) / max(len(link), 1)
    return Shape(clouds, link, link_clouds, tuple(names), tuple(labels), tuple(raw), share, tuple(jtype),
                 np.asarray(axis, dtype=float).reshape(L, 3), travel, extents)


# ------------------------------------------------------------------ generated objects
def _compact_end(spread_a: float, spread_b: float) -> int | None:
    """0 or 1: which of two spreads is smaller; None on a tie (within 0.1 %)."""
    if abs(spread_a - spread_b) <= 1e-3 * max(spread_a, spread_b):
        return None
    return 0 if spread_a < spread_b else 1


def _spread(points: np.ndarray, centre: np.ndarray) -> float:
    """Mean squared distance (units^2) of ``points`` (N, 3) from ``centre`` (3,)."""
    return float(np.mean(np.sum((points - centre) ** 2, axis=1)))


def joint_ends(obj, points: np.ndarray, point_link: np.ndarray) -> dict[str, tuple[float, float]]:
    """(closed, open) value of every limited joint of ``obj`` (module docstring): of 0 and
    the limit farther from 0, the more compact end is closed.

    ``points`` (N, 3) are surface points of ``obj`` at q = 0 and ``point_link`` (N,)
    their links (indices into ``obj.links``).
    """
    out = {}
    centre = points.mean(axis=0)
    at0 = _spread(points, centre)
    inv0 = np.linalg.inv(obj.link_poses())
    for j in obj.movable_joints:
        if j.type in LIMITED:
            lo, hi = j.limits
            far = float(hi if abs(hi) >= abs(lo) else lo)
            moved = _moved(points, point_link, obj.link_poses({j.name: far}) @ inv0)
            out[j.name] = (far, 0.0) if _compact_end(at0, _spread(moved, centre)) == 1 else (0.0, far)
    return out


def _state(ends: dict, t: float) -> dict | None:
    """Joint values at fraction ``t`` from closed to open (None: every joint at 0)."""
    q = {k: c + t * (o - c) for k, (c, o) in ends.items()}
    return q if any(q.values()) else None


def link_label(obj, i: int) -> tuple[str, str]:
    """(matching class, semantic) of link ``i`` of ``obj``: the semantic of its first part
    (the label ``semantics.txt`` gets), class ``"body"`` when no joint moves it."""
    link = obj.links[i]
    raw = link.parts[0].semantic if link.parts else BODY
    moving = link.joint is not None and link.joint.type != "fixed"
    return (raw if moving else BODY), raw


def object_shape(obj, n: int = 2048, seed: int = 0, per_link: int = 0) -> Shape:
    """The :class:`Shape` of a generated object.

    Parameters
    ----------
    obj : ArticulatedObject
    n : int
        Points of each whole-object cloud.
    seed : int
        Sampling seed (the same at every state, so a point stays on its link).
    per_link : int
        0: link clouds are the whole clouds split by link (fast, for the search);
        > 0: each link sampled on its own with this many points (for the report).
    """
    rest = obj.sample_points(n, seed=seed)
    ends = joint_ends(obj, rest.points, rest.link)
    clouds, link = [], None
    for t in STATES:
        pc = obj.sample_points(n, seed=seed, qpos=_state(ends, t))
        clouds.append(pc.points)
        link = pc.link if link is None else link
    used = np.unique(link)
    remap = np.full(len(obj.links), -1)
    remap[used] = np.arange(len(used))
    poses = obj.link_poses(_state(ends, 0.0))
    names, labels, raw, jtype, axis, travel = [], [], [], [], [], []
    for i in used:
        lk = obj.links[i]
        cls, sem = link_label(obj, i)
        names.append(lk.name)
        labels.append(cls)
        raw.append(sem)
        j = lk.joint
        moving = j is not None and j.type != "fixed"
        jtype.append(j.type if moving else "fixed")
        axis.append(poses[i][:3, :3] @ j.axis if moving else np.zeros(3))
        c, o = ends.get(j.name, (0.0, 0.0)) if moving else (0.0, 0.0)
        travel.append(abs(o - c))
    link_clouds = None
    if per_link > 0:
        link_clouds = []
        for t in STATES:
            link_clouds.append([obj.sample_points(per_link, seed=seed, qpos=_state(ends, t),
                                                  parts=np.flatnonzero(obj.part_link == i)).points for i in used])
    return _assemble(np.stack(clouds), remap[link], names, labels, raw, jtype, axis, travel, link_clouds)


# ------------------------------------------------------------------ folders on disk
def _semantics(folder: Path) -> dict[str, tuple[str, str]]:
    """{link: (motion, label)} of a ``semantics.txt`` (empty if there is none)."""
    p = folder / "semantics.txt"
    out = {}
    if p.is_file():
        for line in p.read_text().splitlines():
            f = line.split()
            if len(f) >= 3:
                out[f[0]] = (f[1], f[2])
    return out


def _moved(points, point_link, rel) -> np.ndarray:
    """``points`` (N, 3) moved by their link's transform ``rel`` (L, 4, 4)."""
    R = rel[point_link]
    return np.einsum("nij,nj->ni", R[:, :3, :3], points) + R[:, :3, 3]


def folder_shape(folder: str | Path, n: int = 2048, seed: int = 0, per_link: int = 256) -> Shape:
    """The :class:`Shape` of an object folder (``mobility.urdf`` + meshes + ``semantics.txt``).

    Points are sampled area-uniformly at q = 0 and moved rigidly with their link to
    each state (area is invariant, so they stay area-uniform).

    Raises
    ------
    FileNotFoundError
        No ``mobility.urdf`` (or a mesh it names).
    ValueError
        A URDF without visual geometry.
    """
    import yourdfpy

    from artipg.io import load_urdf, sample_surface
    from artipg.io.folders import URDF_NAME

    folder = Path(folder)
    if not (folder / URDF_NAME).is_file():
        raise FileNotFoundError(f"{folder}: no {URDF_NAME}")
    loaded = load_urdf(folder / URDF_NAME)
    if not len(loaded.faces):
        raise ValueError(f"{folder}: the URDF has no visual geometry")
    rng = np.random.default_rng(seed)
    pts, plink = sample_surface(loaded.vertices, loaded.faces, n, rng, loaded.face_link)
    visual = np.unique(loaded.face_link)
    lpts, llink = [], []
    for li in visual:  # each link sampled on its own, so small ones get points too
        m = loaded.face_link == li
        p, _ = sample_surface(loaded.vertices, loaded.faces[m], per_link, rng)
        lpts.append(p)
        llink.append(np.full(per_link, li))
    lpts, llink = np.concatenate(lpts), np.concatenate(llink)

    urdf = yourdfpy.URDF.load(str(folder / URDF_NAME), build_scene_graph=True, load_meshes=False)
    names = loaded.link_names
    inv0 = np.linalg.inv(loaded.link_poses)
    act = list(urdf.actuated_joint_names)

    def rel(cfg: np.ndarray) -> np.ndarray:
        if act:
            urdf.update_cfg(cfg)
        T = np.stack([np.asarray(urdf.get_transform(frame_to=nm, frame_from=urdf.base_link), dtype=float)
                      for nm in names])
        return T @ inv0

    sem = _semantics(folder)
    child_joint = {j.child: j for j in urdf.robot.joints}

    def is_body(name: str) -> bool:
        """semantics.txt's motion decides (a few real URDFs hang the body on a
        prismatic joint, or a hinged handle on a fixed one); else the joint does."""
        if name in sem:
            return sem[name][0] in BODY_MOTIONS
        j = child_joint.get(name)
        return j is None or j.type == "fixed"

    closed, opened = np.zeros(len(act)), np.zeros(len(act))
    centre = pts.mean(axis=0)
    for k, jn in enumerate(act):  # each limited joint's closed end: the more compact one
        j = urdf.joint_map[jn]
        if (j.type not in LIMITED or j.limit is None or j.limit.lower is None or j.limit.upper is None
                or is_body(j.child)):
            continue
        ends = (float(j.limit.lower), float(j.limit.upper))
        spread = []
        for e in ends:
            cfg = np.zeros(len(act))
            cfg[k] = e
            spread.append(_spread(_moved(pts, plink, rel(cfg)), centre))
        c = _compact_end(*spread)
        c = int(np.argmin(np.abs(ends))) if c is None else c
        closed[k], opened[k] = ends[c], ends[1 - c]

    rels = [rel(closed + t * (opened - closed)) for t in STATES]
    clouds = np.stack([_moved(pts, plink, r) for r in rels])
    remap = np.full(len(names), -1)
    remap[visual] = np.arange(len(visual))
    link_clouds = [[_moved(lpts[llink == li], llink[llink == li], r) for li in visual] for r in rels]

    T0 = rels[0] @ loaded.link_poses  # link poses at the closed state
    labels, raw, jtype, axis, travel = [], [], [], [], []
    for li in visual:
        nm = names[li]
        j = child_joint.get(nm)
        body = is_body(nm)
        moving = not body and j is not None and j.type != "fixed"
        label = sem.get(nm, ("", BODY))[1]
        raw.append(label)
        labels.append(BODY if body else label)
        jtype.append(j.type if moving else "fixed")
        axis.append(T0[li][:3, :3] @ np.asarray(j.axis if j.axis is not None else (1.0, 0, 0), dtype=float)
                    if moving else np.zeros(3))
        k = act.index(j.name) if moving and j.name in act else None
        travel.append(abs(opened[k] - closed[k]) if k is not None else 0.0)
    return _assemble(clouds, remap[plink], [names[i] for i in visual], labels, raw, jtype, axis, travel,
                     link_clouds)
