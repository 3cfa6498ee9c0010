"""Reading many object folders (in parallel) into one array of clouds."""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from artipg.io.reader import read_object
from artipg.workers import default_workers


@dataclass
class ObjectSet:
    """Point clouds and structures of a list of object folders.

    Attributes
    ----------
    folders : list of Path
        The folders that were read, in input order (failed ones left out).
    points : (M, N, 3) float64
        One cloud per folder (metres, unnormalised, rest pose).
    link : (M, N) int64
        Per-point link index into ``link_names[i]``.
    link_names : list of tuple of str
    structures : list of ObjectStructure
    errors : list of (Path, str)
        Folders that could not be read and why.
    """

    folders: list
    points: np.ndarray
    link: np.ndarray
    link_names: list
    structures: list
    errors: list = field(default_factory=list)

    def __len__(self) -> int:
        return len(self.folders)


def _read(task):
    folder, n, source, seed = task
    try:
        return read_object(folder, n, source=source, seed=seed)
    except Exception as e:  # noqa: BLE001 - one broken folder (bad XML, bad mesh ...) must not stop a whole set
        return f"{type(e).__name__}: {e}"


def load_set(folders: Sequence[str | Path], n_points: int = 2048, source: str = "auto", seed: int = 0,
             workers: int | None = None, progress: Callable[[int], None] | None = None) -> ObjectSet:
    """Read object folders with :func:`artipg.io.read_object`, in worker processes.

    Parameters
    ----------
    folders : sequence of str or Path
    n_points : int
        Points per object.
    source : {"auto", "mesh", "npz"}
        See :func:`artipg.io.read_object`.
    seed : int
        Sampling seed, the same for every folder (identical folders -> identical clouds).
    workers : int, optional
        Processes (default: all usable cores; 1 reads in this process).
    progress : callable, optional
        Called with 1 after each folder.

    Returns
    -------
    ObjectSet
        Unreadable folders are listed in ``errors`` and left out of the arrays.
    """
    workers = default_workers() if workers is None else max(1, int(workers))
    tasks = [(Path(f), int(n_points), source, int(seed)) for f in folders]
    out, errors = [], []
    if workers == 1 or len(tasks) < 8:
        results = map(_read, tasks)
        pool = None
    else:
        pool = ProcessPoolExecutor(max_workers=min(workers, len(tasks)))
        results = pool.map(_read, tasks, chunksize=max(1, min(16, len(tasks) // (4 * workers))))
    try:
        for task, r in zip(tasks, results):
            if isinstance(r, str):
                errors.append((task[0], r))
            else:
                out.append(r)
            if progress is not None:
                progress(1)
    finally:
        if pool is not None:
            pool.shutdown(cancel_futures=True)
    return ObjectSet(
        folders=[o.folder for o in out],
        points=np.stack([o.points for o in out]) if out else np.zeros((0, n_points, 3)),
        link=np.stack([o.link for o in out]) if out else np.zeros((0, n_points), dtype=np.int64),
        link_names=[o.link_names for o in out],
        structures=[o.structure for o in out],
        errors=errors,
    )
