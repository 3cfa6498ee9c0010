"""torch datasets of labelled clouds: generated on the fly, or read from written
folders or shards (torch is an optional extra: ``pip install artipg[learn]``).

Both are :class:`torch.utils.data.IterableDataset` s whose items are split across
data-loader workers and distributed ranks deterministically: item ``i`` of the list
goes to the reader ``i mod (world_size * num_workers)``, reader ``rank * num_workers
+ worker_id``. An item is a dict of numpy arrays (the ``points.npz`` arrays named in
``keys``, see ``docs/annotations.md``) plus ``"category"`` (str) and ``"seed"`` (int);
the default keys are the per-point ones, so the default collate stacks a batch.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Iterator, Sequence

import numpy as np
import torch
from torch.utils.data import IterableDataset, get_worker_info

#: Arrays of ``points.npz`` with one row per point (same shape for every object).
PER_POINT_KEYS = ("points", "normals", "semantic", "instance", "link", "primitive", "actionable", "affordance",
                  "npcs", "object_npcs")
#: Stream of the random joint states of :class:`ProceduralDataset` (qpos="random").
QPOS_STREAM = 0x9905


def _reader(rank: int | None, world_size: int | None) -> tuple[int, int]:
    """(index, count) of this reader among all ranks' loader workers."""
    dist = torch.distributed
    on = dist.is_available() and dist.is_initialized()
    rank = rank if rank is not None else dist.get_rank() if on else 0
    world_size = world_size if world_size is not None else dist.get_world_size() if on else 1
    info = get_worker_info()
    workers, wid = (1, 0) if info is None else (info.num_workers, info.id)
    return rank * workers + wid, world_size * workers


def qpos_for(obj, policy, seed: int):
    """Joint state of ``obj`` under ``policy``.

    Parameters
    ----------
    obj : ArticulatedObject
    policy : {"rest", "open", "random"} or callable
        ``rest``: every joint at 0 (the rest pose); ``open``: every movable joint at its
        upper limit; ``random``: uniform within the limits, drawn from
        ``default_rng([seed, QPOS_STREAM])``; a callable ``f(obj, rng) -> qpos`` gets
        that generator too.
    seed : int

    Returns
    -------
    None or (J,) float array
        In ``obj.movable_joints`` order (radians or metres).
    """
    if policy == "rest":
        return None
    limits = obj.limits()
    if policy == "open":
        return limits[:, 1].copy()
    rng = np.random.default_rng([int(seed), QPOS_STREAM])
    if policy == "random":
        return rng.uniform(limits[:, 0], limits[:, 1])
    if callable(policy):
        return policy(obj, rng)
    raise ValueError(f"unknown qpos policy {policy!r}: use 'rest', 'open', 'random' or a callable")


class ProceduralDataset(IterableDataset):
    """Labelled clouds generated on the fly, one per (category, seed).

    Parameters
    ----------
    categories : str or sequence of str
    seeds : sequence of int
        Seeds of every category; items run over categories within each seed
        (seed 0 of every category, then seed 1 ...).
    n_points : int
    qpos : {"rest", "open", "random"} or callable
        Joint state policy (:func:`qpos_for`).
    validate : bool
        Validate and repair as ``artipg generate`` does (:func:`artipg.generate`).
    keys : sequence of str or None
        Arrays to yield (None: all of ``points.npz``, variable shapes included).
    rank, world_size : int, optional
        This process's place among distributed ranks (default: torch.distributed's
        when initialised, else 0 of 1).

    Notes
    -----
    The points of an item are drawn with seed ``epoch`` (:meth:`set_epoch`, 0 by
    default), so with ``qpos="rest"`` and epoch 0 an item holds the arrays that
    ``artipg generate`` writes to the object's ``points.npz``.
    """

    def __init__(self, categories, seeds: Sequence[int], n_points: int = 2048, qpos="rest", validate: bool = True,
                 keys: Sequence[str] | None = PER_POINT_KEYS, rank: int | None = None,
                 world_size: int | None = None):
        import artipg

        cats = [categories] if isinstance(categories, str) else list(categories)
        for c in cats:
            artipg.get_category(c)  # unknown names fail here, not in a worker
        self.items = [(c, int(s)) for s in seeds for c in cats]
        self.n_points, self.qpos, self.validate = int(n_points), qpos, validate
        self.keys = None if keys is None else tuple(keys)
        self.rank, self.world_size = rank, world_size
        self.epoch = 0

    def set_epoch(self, epoch: int) -> None:
        """Draw the points of the next iterations with seed ``epoch``."""
        self.epoch = int(epoch)

    def sample(self, category: str, seed: int) -> dict:
        """The item of (category, seed)."""
        import artipg
        from artipg.annotate.arrays import point_arrays

        obj = artipg.generate(category, seed, validate=self.validate)
        arrays = point_arrays(obj, self.n_points, seed=self.epoch, qpos=qpos_for(obj, self.qpos, seed),
                              grasps=self.keys is None)
        return _item(arrays, self.keys, category, seed)

    def __iter__(self) -> Iterator[dict]:
        k, total = _reader(self.rank, self.world_size)
        for category, seed in self.items[k::total]:
            yield self.sample(category, seed)


class FolderDataset(IterableDataset):
    """Labelled clouds of written object folders, or of their tar shards.

    Parameters
    ----------
    root : str or Path
        An output folder of ``artipg generate`` (with ``index.jsonl``).
    shards : bool or None
        Read ``root/shards/*.tar`` (split across readers shard by shard) instead of the
        folders (split object by object); None: shards when they exist.
    keys : sequence of str or None
        Arrays of ``points.npz`` to yield (None: all).
    rank, world_size : int, optional
        As :class:`ProceduralDataset`.
    """

    def __init__(self, root, shards: bool | None = None, keys: Sequence[str] | None = PER_POINT_KEYS,
                 rank: int | None = None, world_size: int | None = None):
        from artipg.data.index import read_index
        from artipg.data.shards import SHARD_DIR

        self.root = Path(root)
        shard_files = sorted((self.root / SHARD_DIR).glob("shard-*.tar"))
        self.shards = bool(shard_files) if shards is None else shards
        if self.shards and not shard_files:
            raise FileNotFoundError(f"no shards in {self.root / SHARD_DIR}")
        self.items = shard_files if self.shards else [r["path"] for r in read_index(self.root)]
        if not self.items:
            raise FileNotFoundError(f"no indexed objects in {self.root} (run 'artipg index {self.root}')")
        self.keys = None if keys is None else tuple(keys)
        self.rank, self.world_size = rank, world_size

    def __iter__(self) -> Iterator[dict]:
        from artipg.data.shards import iter_shard

        k, total = _reader(self.rank, self.world_size)
        for item in self.items[k::total]:
            if self.shards:
                for key, members in iter_shard(item):
                    if "points.npz" in members:
                        yield _npz_item(io.BytesIO(members["points.npz"]), self.keys, key)
            else:
                yield _npz_item(self.root / item / "points.npz", self.keys, item)


def _npz_item(source, keys, path: str) -> dict:
    category, _, seed = path.rpartition("/")
    with np.load(source, allow_pickle=False) as z:
        arrays = {k: z[k] for k in (z.files if keys is None else keys)}
    return _item(arrays, keys, category, int(seed) if seed.isdigit() else seed)


def _item(arrays: dict, keys, category: str, seed) -> dict:
    out = dict(arrays) if keys is None else {k: arrays[k] for k in keys}
    out["category"], out["seed"] = category, seed
    return out


__all__ = ["FolderDataset", "PER_POINT_KEYS", "ProceduralDataset", "qpos_for"]
