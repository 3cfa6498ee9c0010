"""Datasets built from artipg output.

- :mod:`artipg.data.index`    ``OUT/index.jsonl``, one row per complete object folder;
- :mod:`artipg.data.shards`   WebDataset-style tar shards of points and annotations;
- :mod:`artipg.data.engine`   the local engine of ``artipg generate`` (process pool);
- :mod:`artipg.data.datasets` torch datasets (optional extra ``learn``):
  :class:`ProceduralDataset` (clouds generated on the fly) and :class:`FolderDataset`
  (written folders or shards), importable from here.

This package also ships ``fid_pointnet.npz``, the FID encoder of :mod:`artipg.metrics`.
"""

_TORCH_NAMES = ("FolderDataset", "PER_POINT_KEYS", "ProceduralDataset", "qpos_for")


def __getattr__(name):
    # torch loads only when a dataset class is asked for
    if name in _TORCH_NAMES:
        try:
            from artipg.data import datasets
        except ImportError as e:
            raise ImportError(f"artipg.data.{name} needs torch: pip install 'artipg[learn]' ({e})") from None
        return getattr(datasets, name)
    raise AttributeError(f"module 'artipg.data' has no attribute {name!r}")


__all__ = list(_TORCH_NAMES)
