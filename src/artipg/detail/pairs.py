"""Training pairs of the learned detail bridge: (structure cloud with labels, detailed cloud).

A pair file (``<Category>_<id>.npz``, one per reference object) holds, at the fit's
joint states (:data:`artipg.fit.shape.STATES`: closed, half, open):

- ``structure`` (S, N, 3) float32: points sampled from the object's procedural twin
  (:func:`artipg.fit.fit_object`), area-uniform;
- ``semantic`` (N,) int32: their labels (indices into
  :data:`artipg.vocabulary.SEMANTIC_LABELS`), the same at every state;
- ``detailed`` (S, N, 3) float32: points of the reference object itself, reordered so
  that ``detailed[s, i]`` is matched to ``structure[s, i]`` by the exact earth mover's
  assignment (a bijection, so the detailed cloud keeps the density of the structure's);
- ``projected`` (S, N, 3) float32: for every structure point, the nearest point of a
  dense sample (:data:`DENSE_POINTS`) of the reference object: its projection onto the
  real surface, with far less sampling noise than the matching (the training target by
  default, :mod:`artipg.detail.training`);
- ``diagonal`` () float64: the twin's closed-state bounding-box diagonal in metres;
- ``category``, ``name``: strings; ``fit_chamfer`` (S,): the fit's whole-object
  Chamfer-L1 at each state.

Frames and units: both clouds are in the object frame (+Z up, front -X), each centred on
its own closed-state bounding-box centre and divided by its diagonal (so the real
object's unknown units drop out, and so does the twin's size: the real proportions are
kept, the metric size is the twin's). Offsets ``detailed - structure`` are therefore in
units of the object's diagonal.

Real objects never enter the repository: pairs are written wherever the user says
(``artipg detail pairs --out DIR``), from their own reference folder.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

import numpy as np

#: Points per cloud of a pair (the exact assignment is O(N^3); 1024 takes ~0.1 s).
PAIR_POINTS = 1024
#: Points of the dense reference sample the structure points are projected onto.
DENSE_POINTS = 8192


@dataclass
class Pair:
    """One reference object's pair (module docstring for the arrays)."""

    structure: np.ndarray
    semantic: np.ndarray
    detailed: np.ndarray
    projected: np.ndarray
    diagonal: float
    category: str
    name: str
    fit_chamfer: np.ndarray | None = None

    def offsets(self, target: str = "projected") -> np.ndarray:
        """(S, N, 3) float32 per-point offsets to the ``"projected"`` or ``"matched"``
        (``detailed``) points (diagonal units)."""
        return (self.projected if target == "projected" else self.detailed) - self.structure


def normalise_states(clouds: np.ndarray) -> tuple[np.ndarray, float]:
    """Clouds (S, N, 3) centred on the first cloud's bounding-box centre and divided by its
    diagonal; returns (normalised clouds, diagonal in the input's units)."""
    from artipg.fit.shape import bbox_frame

    centre, diag = bbox_frame(clouds[0])
    return (clouds - centre) / diag, diag


def emd_match(structure: np.ndarray, detailed: np.ndarray) -> np.ndarray:
    """``detailed`` (N, 3) reordered so row i is matched to ``structure[i]`` (N, 3) by the
    assignment of least total Euclidean distance (the earth mover's matching)."""
    from scipy.optimize import linear_sum_assignment
    from scipy.spatial.distance import cdist

    rows, cols = linear_sum_assignment(cdist(structure, detailed))
    out = np.empty_like(detailed)
    out[rows] = detailed[cols]
    return out


def build_pair(structure: np.ndarray, semantic: np.ndarray, detailed: np.ndarray, diagonal: float,
               category: str, name: str, fit_chamfer=None, dense: np.ndarray | None = None) -> dict:
    """Arrays of a pair file from clouds already normalised (module docstring).

    Parameters
    ----------
    structure : (S, N, 3) float array
    semantic : (N,) int array
    detailed : (S, M, 3) float array, M >= N
        The first N points are used (pass an area-uniform, randomly ordered sample).
    diagonal : float
        Metres.
    dense : (S, K, 3) float array, optional
        A dense sample of the detailed surface for ``projected`` (default: ``detailed``
        whole).
    """
    from scipy.spatial import cKDTree

    structure = np.asarray(structure, dtype=np.float64)
    n = structure.shape[1]
    detailed = np.asarray(detailed, dtype=np.float64)
    dense = np.asarray(detailed if dense is None else dense, dtype=np.float64)
    detailed = detailed[:, :n]
    if detailed.shape != structure.shape:
        raise ValueError(f"detailed clouds {detailed.shape} do not match structure clouds {structure.shape}")
    matched = np.stack([emd_match(s, d) for s, d in zip(structure, detailed)])
    projected = np.stack([d[cKDTree(d).query(s)[1]] for s, d in zip(structure, dense)])
    return {"structure": structure.astype(np.float32), "semantic": np.asarray(semantic, dtype=np.int32),
            "detailed": matched.astype(np.float32), "projected": projected.astype(np.float32),
            "diagonal": np.float64(diagonal), "category": np.array(category), "name": np.array(name),
            "fit_chamfer": np.asarray(fit_chamfer if fit_chamfer is not None else np.full(len(structure), np.nan),
                                      dtype=np.float64)}


def twin_clouds(obj, n: int = PAIR_POINTS, seed: int = 0) -> tuple[np.ndarray, np.ndarray, float]:
    """A generated object sampled at the fit's states (closed, half, open; the closed end
    of each joint decided as the fit decides it): (S, n, 3) normalised clouds, (n,)
    semantic labels, closed-state diagonal in metres."""
    from artipg.fit.shape import STATES, joint_ends

    rest = obj.sample_points(2048, seed=seed)
    ends = joint_ends(obj, rest.points, rest.link)
    clouds, semantic = [], None
    for t in STATES:
        q = {k: c + t * (o - c) for k, (c, o) in ends.items()}
        pc = obj.sample_points(n, seed=seed, qpos=q or None)
        clouds.append(pc.points)
        semantic = pc.semantic if semantic is None else semantic
    clouds, diag = normalise_states(np.stack(clouds))
    return clouds, np.asarray(semantic), diag


def fitted_category(name: str) -> str | None:
    """Our category for a reference category name (``StorageFurniture``, ``Keyboard``,
    ``keyboard``), or None when artipg has no such category."""
    import artipg
    from artipg.fit.labels import our_category

    valid = artipg.categories()
    for c in (our_category(name), re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()):
        if c in valid:
            return c
    return None


def fit_pair(folder: Path, category: str, budget=None, n: int = PAIR_POINTS, seed: int = 0) -> dict:
    """Fit a twin to a reference object folder and build its pair (arrays of a pair file).

    Raises what :func:`artipg.fit.fit_object` raises on an unreadable folder.
    """
    from artipg.fit import FitBudget, fit_object
    from artipg.fit.shape import folder_shape

    res = fit_object(folder, category, budget or FitBudget(), seed=seed)
    structure, semantic, diag = twin_clouds(res.obj, n, seed=seed)
    real = res.target.clouds  # normalised by its own closed box, area-uniform
    rng = np.random.default_rng(seed)
    take = rng.choice(real.shape[1], size=n, replace=False)
    dense = folder_shape(folder, DENSE_POINTS, seed=seed + 1, per_link=1).clouds
    return build_pair(structure, semantic, real[:, take], diag, category, Path(folder).name,
                      fit_chamfer=res.score.whole, dense=dense)


def reference_objects(reference: Path, categories: Iterable[str] | None = None) -> list[tuple[str, Path]]:
    """(our category, folder) of every object folder under ``reference`` whose category
    artipg has (``categories``: only those, ours or the reference's names)."""
    from artipg.io import find_object_folders

    want = None if categories is None else {fitted_category(c) or c for c in categories}
    out = []
    for cat, folders in find_object_folders(reference).items():
        ours = fitted_category(cat)
        if ours is None or (want is not None and ours not in want):
            continue
        out += [(ours, Path(f)) for f in folders]
    return out


def pair_path(out: Path, category: str, folder: Path) -> Path:
    """Where the pair of ``folder`` goes under ``out``."""
    return Path(out) / f"{category}_{Path(folder).name}.npz"


def make_pairs(reference: Path, out: Path, categories=None, budget=None, n: int = PAIR_POINTS,
               progress: Callable[[str, str], None] | None = None) -> tuple[list[Path], list[tuple[Path, str]]]:
    """Pairs of every reference object (existing pair files are kept: re-running resumes).

    Returns
    -------
    (written or kept pair files, [(folder, one-line error), ...])
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    done, errors = [], []
    for cat, folder in reference_objects(reference, categories):
        dest = pair_path(out, cat, folder)
        status = "kept"
        if not dest.is_file():
            try:
                arrays = fit_pair(folder, cat, budget, n)
            except Exception as e:  # noqa: BLE001 - one unreadable object must not stop the others
                errors.append((folder, f"{type(e).__name__}: {e}"))
                status = "error"
            else:
                tmp = dest.with_suffix(".tmp.npz")
                np.savez_compressed(tmp, **arrays)
                tmp.replace(dest)
                status = "new"
        if status != "error":
            done.append(dest)
        if progress is not None:
            progress(f"{cat}/{folder.name}", status)
    return done, errors


def load_pairs(folder: Path, names: Iterable[str] | None = None) -> list[Pair]:
    """Read the pair files of a folder (``names``: only those stems).

    Raises
    ------
    FileNotFoundError
        No folder, or no pair file in it.
    ValueError
        A file that is not a pair file.
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"{folder} is not a folder")
    files = sorted(p for p in folder.glob("*.npz") if not p.name.endswith(".tmp.npz"))
    if names is not None:
        keep = set(names)
        files = [p for p in files if p.stem in keep]
    if not files:
        raise FileNotFoundError(f"no pair files (*.npz) in {folder}")
    pairs = []
    for p in files:
        try:
            with np.load(p) as z:
                pairs.append(Pair(z["structure"], z["semantic"], z["detailed"], z["projected"], float(z["diagonal"]),
                                  str(z["category"]), p.stem, z["fit_chamfer"] if "fit_chamfer" in z else None))
        except (KeyError, ValueError, OSError) as e:
            raise ValueError(f"{p}: not a pair file ({e})") from e
    return pairs
