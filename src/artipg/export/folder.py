"""Writing an object folder (DESIGN.md section 3) atomically."""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

from artipg.export.annotation import annotation_text
from artipg.export.npz import npz_bytes
from artipg.export.semantics import semantics_text
from artipg.export.urdf import build_urdf, urdf_text

TMP_PREFIX = ".tmp-"


def point_arrays(obj, n_points: int, seed: int = 0) -> dict[str, np.ndarray]:
    """Arrays stored in ``points.npz`` (see the README's table)."""
    pc = obj.sample_points(n_points, seed=seed)
    return {
        "points": pc.points.astype(np.float32),
        "normals": pc.normals.astype(np.float32),
        "semantic": pc.semantic.astype(np.int32),
        "instance": pc.instance.astype(np.int32),
        "link": pc.link.astype(np.int32),
        "semantic_names": np.array(pc.semantic_names),
        "instance_names": np.array(pc.instance_names),
        "link_names": np.array(pc.link_names),
    }


def object_files(obj, n_points: int = 2048) -> dict[str, bytes]:
    """All files of the object folder as {relative path: bytes}."""
    robot, meshes = build_urdf(obj)
    files = {"mobility.urdf": urdf_text(robot).encode(), "semantics.txt": semantics_text(obj).encode(),
             "annotation.json": annotation_text(obj).encode()}
    files.update({k: v.encode() for k, v in meshes.items()})
    if n_points > 0:
        files["points.npz"] = npz_bytes(point_arrays(obj, n_points))
    return files


def write_files_atomic(files: dict[str, bytes], dest: Path, overwrite: bool = False) -> Path:
    """Write ``files`` into a temporary sibling of ``dest`` and rename it into place.

    An interrupted write leaves only a ``.tmp-*`` folder, never a half-written ``dest``.
    """
    dest = Path(dest)
    dest.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f"{TMP_PREFIX}{dest.name}-", dir=dest.parent))
    try:
        for rel, data in files.items():
            p = tmp / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_bytes(data)
        os.chmod(tmp, 0o755)
        if dest.exists():
            if not overwrite:
                raise FileExistsError(f"{dest} exists")
            old = dest.with_name(f"{TMP_PREFIX}{dest.name}-old-{os.getpid()}")
            os.rename(dest, old)
            os.rename(tmp, dest)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.rename(tmp, dest)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return dest


def export_object(obj, dest, n_points: int = 2048, overwrite: bool = False) -> Path:
    """Write the object folder of ``obj`` at ``dest`` (atomically)."""
    return write_files_atomic(object_files(obj, n_points), Path(dest), overwrite=overwrite)


def clean_stale_tmp(folder: Path) -> int:
    """Remove ``.tmp-*`` leftovers of interrupted runs in ``folder``; returns how many."""
    n = 0
    if folder.is_dir():
        for p in folder.iterdir():
            if p.name.startswith(TMP_PREFIX) and p.is_dir():
                shutil.rmtree(p, ignore_errors=True)
                n += 1
    return n
