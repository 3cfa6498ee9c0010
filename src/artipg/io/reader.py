"""One object folder -> a labelled point cloud at the rest pose plus its structure."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from artipg.io.folders import URDF_NAME, metadata_category
from artipg.io.sampling import sample_surface
from artipg.io.urdf import load_urdf
from artipg.io.structure import ObjectStructure

SOURCES = ("auto", "mesh", "npz")


@dataclass
class ObjectSample:
    """A point cloud of one object folder.

    Attributes
    ----------
    folder : Path
    category : str or None
        From the folder's metadata (None if it has none).
    points : (N, 3) float64
        Area-uniform surface points at the rest pose, in the URDF root frame (metres,
        +Z up, unnormalised).
    link : (N,) int64
        Index into ``link_names`` of the link each point lies on.
    link_names : tuple of str
    structure : ObjectStructure
    source : str
        ``"npz"`` (artipg's analytic ``points.npz``) or ``"mesh"`` (sampled from the
        URDF's visual meshes).
    """

    folder: Path
    category: str | None
    points: np.ndarray
    link: np.ndarray
    link_names: tuple
    structure: ObjectStructure
    source: str


def _npz_points(path: Path, n: int, rng: np.random.Generator):
    """``n`` points of an artipg ``points.npz`` (a uniform random subset if it has more),
    or None when the file lacks the arrays or has fewer than ``n`` points."""
    try:
        with np.load(path, allow_pickle=False) as d:
            if not {"points", "link", "link_names"} <= set(d.files) or len(d["points"]) < n:
                return None
            pts, link, names = d["points"], d["link"], tuple(str(s) for s in d["link_names"])
    except (OSError, ValueError):
        return None
    if len(pts) > n:
        idx = np.sort(rng.choice(len(pts), size=n, replace=False))
        pts, link = pts[idx], link[idx]
    return pts.astype(np.float64), link.astype(np.int64), names


def read_object(folder: str | Path, n_points: int = 2048, source: str = "auto", seed: int = 0) -> ObjectSample:
    """Read an object folder into ``n_points`` area-uniform labelled points at rest.

    The URDF is always loaded (through its kinematics, see :mod:`artipg.io.urdf`) for
    the structure (joints, links) and the rest-pose bounding box. Points come from:

    - ``source="mesh"``: the URDF's visual meshes, placed by the kinematics at q = 0
      and sampled area-uniformly (:func:`artipg.io.sampling.sample_surface`);
    - ``source="npz"``: artipg's ``points.npz`` (exact samples of the analytic
      surfaces at rest; a seeded uniform subset when it holds more than ``n_points``);
    - ``source="auto"``: ``npz`` when the folder has a ``points.npz`` with at least
      ``n_points`` points, else ``mesh``.

    Both are i.i.d. area-uniform samples of the same surfaces (the meshes are the
    primitives tessellated), so sets read either way are comparable.

    Parameters
    ----------
    folder : str or Path
        An object folder (``mobility.urdf`` + meshes, optionally artipg's extra files).
    n_points : int
        Points per object.
    source : {"auto", "mesh", "npz"}
    seed : int
        Seed of the sampling stream. The same folder read with the same seed gives the
        same cloud, so identical folders give identical clouds.

    Returns
    -------
    ObjectSample

    Raises
    ------
    FileNotFoundError
        Missing URDF or mesh; or ``source="npz"`` and no usable ``points.npz``.
    ValueError
        Unknown ``source``, ``n_points < 1`` or a URDF without visual geometry.
    """
    if source not in SOURCES:
        raise ValueError(f"source must be one of {SOURCES}, got {source!r}")
    if n_points < 1:
        raise ValueError(f"n_points must be >= 1, got {n_points}")
    folder = Path(folder)
    loaded = load_urdf(folder / URDF_NAME)
    if not len(loaded.faces):
        raise ValueError(f"{folder}: the URDF has no visual geometry")
    structure = ObjectStructure(joint_types=tuple(j[1] for j in loaded.joints), n_links=len(loaded.visual_links),
                                extents=np.diff(loaded.bounds, axis=0)[0])
    rng = np.random.default_rng(seed)
    got = None
    if source in ("auto", "npz") and (folder / "points.npz").is_file():
        got = _npz_points(folder / "points.npz", n_points, rng)
    if got is not None:
        pts, link, names = got
        used = "npz"
    elif source == "npz":
        raise FileNotFoundError(f"{folder}: no points.npz with >= {n_points} labelled points")
    else:
        pts, link = sample_surface(loaded.vertices, loaded.faces, n_points, rng, loaded.face_link)
        names, used = loaded.link_names, "mesh"
    return ObjectSample(folder=folder, category=metadata_category(folder), points=pts, link=link, link_names=names,
                        structure=structure, source=used)
