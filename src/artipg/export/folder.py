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
from artipg.io.manifest import ANNOTATION_NAME, file_records

TMP_PREFIX = ".tmp-"


def point_arrays(obj, n_points: int, seed: int = 0, qpos=None, grasps=True) -> dict[str, np.ndarray]:
    """Arrays stored in ``points.npz`` (see ``docs/annotations.md``)."""
    from artipg.annotate.arrays import point_arrays as _arrays

    return _arrays(obj, n_points, seed=seed, qpos=qpos, grasps=grasps)


def object_files(obj, n_points: int = 2048, views: int = 0, view_points: int = 2048, formats=None,
                 actuators: bool = False, rgb: str | None = None, detail_model=None) -> dict[str, bytes]:
    """All files of the object folder as {relative path: bytes}.

    ``views`` > 0 adds ``views.npz`` with that many partial views of ``view_points``
    points each (rest pose; see ``docs/annotations.md``). ``formats`` (default
    :data:`artipg.export.formats.DEFAULT_FORMATS`) adds ``mobility.xml`` (``"mjcf"``),
    ``mobility.usd`` and ``mobility.glb`` beside the URDF, with position servos when
    ``actuators`` (see ``docs/formats.md``). ``rgb`` (``"studio"`` or ``"random"``
    lighting and background per view; needs Mitsuba 3, the ``render`` extra) adds
    ``views_rgb.npz``: a colour image of every partial view, pixel for pixel with its
    label images. ``detail_model`` (a :class:`artipg.detail.application.DetailModel`)
    replaces the cloud of ``points.npz`` by its detailed cloud (docs/detail_learned.md).
    ``annotation.json`` comes last and lists every other file with its size and hash.
    """
    from artipg.annotate.arrays import view_arrays
    from artipg.annotate.grasps import world_grasps

    grasps = world_grasps(obj)
    robot, meshes = build_urdf(obj)
    files = {"mobility.urdf": urdf_text(robot).encode(), "semantics.txt": semantics_text(obj).encode()}
    files.update({k: v if isinstance(v, bytes) else v.encode() for k, v in meshes.items()})  # PNGs are bytes
    if formats is None:
        from artipg.export.formats import DEFAULT_FORMATS as formats
    if any(f != "urdf" for f in formats):
        from artipg.export.asset import object_asset
        from artipg.export.formats import format_files

        files.update(format_files(object_asset(obj, files["mobility.urdf"].decode(), meshes), formats, actuators))
    if n_points > 0:
        arrays = point_arrays(obj, n_points, grasps=grasps)
        if detail_model is not None:
            from artipg.detail.application import detail_arrays

            arrays = detail_arrays(detail_model, arrays, seed=obj.seed)[0]
        files["points.npz"] = npz_bytes(arrays)
    if views > 0:
        varr = view_arrays(obj, views, view_points, seed=obj.seed)
        files["views.npz"] = npz_bytes(varr)
        if rgb is not None:
            from artipg.appearance.rgb import rgb_view_arrays

            files["views_rgb.npz"] = npz_bytes(rgb_view_arrays(obj, varr, seed=obj.seed, randomize=rgb == "random"))
    # the file list covers everything above: add files before this line
    files[ANNOTATION_NAME] = annotation_text(obj, grasps, file_records(files)).encode()
    return files


def write_files_atomic(files: dict[str, bytes], dest: Path, overwrite: bool = False) -> Path:
    """Write ``files`` into a temporary sibling of ``dest`` and rename it into place.

    An interrupted write leaves only a ``.tmp-*`` folder, never a half-written ``dest``;
    inside it ``annotation.json`` is written last, so even a folder moved by hand out
    of an interrupted write is recognisably incomplete (:mod:`artipg.io.manifest`).
    """
    dest = Path(dest)
    dest.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f"{TMP_PREFIX}{dest.name}-", dir=dest.parent))
    try:
        made = {""}
        for rel, data in sorted(files.items(), key=lambda kv: kv[0] == ANNOTATION_NAME):
            folder = os.path.dirname(rel)
            if folder not in made:
                (tmp / folder).mkdir(parents=True, exist_ok=True)
                made.add(folder)
            _write_file(os.path.join(tmp, rel), data)
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


def _write_file(path: str, data: bytes) -> None:
    """Create ``path`` (mode 0o666 less the umask, as ``Path.write_bytes``) holding
    ``data``, with the fewest system calls: an object folder has dozens of small files."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o666)
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
    finally:
        os.close(fd)


def export_object(obj, dest, n_points: int = 2048, overwrite: bool = False, views: int = 0, formats=None,
                  actuators: bool = False, rgb: str | None = None, detail_model=None) -> Path:
    """Write the object folder of ``obj`` at ``dest`` (atomically); ``views`` > 0 adds
    ``views.npz`` with that many partial views; ``formats`` (names of
    :data:`artipg.export.formats.FORMATS`, default ``DEFAULT_FORMATS``) the simulator
    files beside the URDF."""
    files = object_files(obj, n_points, views=views, formats=formats, actuators=actuators, rgb=rgb,
                         detail_model=detail_model)
    return write_files_atomic(files, Path(dest), overwrite=overwrite)


def clean_stale_tmp(folder: Path) -> int:
    """Remove ``.tmp-*`` leftovers of interrupted runs in ``folder``; returns how many."""
    n = 0
    if folder.is_dir():
        for p in folder.iterdir():
            if p.name.startswith(TMP_PREFIX) and p.is_dir():
                shutil.rmtree(p, ignore_errors=True)
                n += 1
    return n
