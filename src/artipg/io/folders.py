"""Finding object folders and their categories under a directory.

Accepted layouts (an *object folder* is a directory holding ``mobility.urdf``):

- ``DIR/<category>/<id>/`` as written by ``artipg generate`` (category = folder name,
  snake_cased: ``StorageFurniture/`` -> ``storage_furniture``);
- a flat ``DIR/<id>/`` of object folders (PartNet-Mobility's ``dataset/``, or a mix of
  artipg objects): the category comes from ``annotation.json`` (``category``, artipg)
  or ``meta.json`` (``model_cat``, PartNet-Mobility, e.g. ``StorageFurniture`` ->
  ``storage_furniture``), else it is ``"objects"``;
- ``DIR`` itself being one object folder.

Hidden folders and artipg's ``.tmp-*`` leftovers of interrupted writes are skipped.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

URDF_NAME = "mobility.urdf"
FALLBACK_CATEGORY = "objects"


def is_object_folder(path: str | Path) -> bool:
    """Whether ``path`` is a directory holding a ``mobility.urdf``."""
    return (Path(path) / URDF_NAME).is_file()


def snake_case(name: str) -> str:
    """``StorageFurniture`` / ``Storage Furniture`` / ``storage-furniture`` -> ``storage_furniture``."""
    s = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name.strip())
    return re.sub(r"[^0-9a-zA-Z]+", "_", s).strip("_").lower()


def metadata_category(folder: str | Path) -> str | None:
    """Category recorded inside an object folder (artipg's annotation.json or
    PartNet-Mobility's meta.json), snake_cased; None if neither says."""
    folder = Path(folder)
    for fname, key in (("annotation.json", "category"), ("meta.json", "model_cat")):
        p = folder / fname
        if p.is_file():
            try:
                value = json.loads(p.read_text()).get(key)
            except (OSError, ValueError, AttributeError):
                continue
            if isinstance(value, str) and value.strip():
                return snake_case(value)
    return None


def _sort_key(p: Path):
    return (0, int(p.name), "") if p.name.isdigit() else (1, 0, p.name)


def _visible_dirs(folder: Path) -> list[Path]:
    return sorted((p for p in folder.iterdir() if p.is_dir() and not p.name.startswith(".")), key=_sort_key)


def find_object_folders(root: str | Path) -> dict[str, list[Path]]:
    """Object folders under ``root`` grouped by category.

    Parameters
    ----------
    root : str or Path
        A directory in one of the layouts of this module's docstring.

    Returns
    -------
    dict
        {category: [object folder, ...]} with categories sorted by name and folders
        by numeric id (then name).

    Raises
    ------
    FileNotFoundError
        If ``root`` is not a directory.
    """
    root = Path(root)
    if not root.is_dir():
        raise FileNotFoundError(f"{root} is not a directory")
    found: dict[str, list[Path]] = {}
    if is_object_folder(root):
        found[metadata_category(root) or FALLBACK_CATEGORY] = [root]
        return found
    for child in _visible_dirs(root):
        if is_object_folder(child):
            found.setdefault(metadata_category(child) or FALLBACK_CATEGORY, []).append(child)
            continue
        objs = [g for g in _visible_dirs(child) if is_object_folder(g)]
        if objs:
            found.setdefault(snake_case(child.name), []).extend(objs)
    return {k: sorted(v, key=_sort_key) for k, v in sorted(found.items())}
