"""WebDataset-style tar shards of an output folder's points and annotations.

``OUT/shards/shard-000000.tar``, ... hold the objects of ``OUT/index.jsonl`` in its
order, ``per_shard`` objects each. An object's members share its key, its folder
path (``storage_furniture/12``): ``<key>.annotation.json``, ``<key>.points.npz`` and,
when written, ``<key>.views.npz`` (the WebDataset convention: key up to the first
dot of the base name, extension after it). Tar headers carry no time or owner, so the
same objects give the same bytes.

``OUT/shards/shards.json`` records each shard's objects and a hash of their index
rows; a shard whose rows did not change is not rewritten.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import tarfile
from pathlib import Path

from artipg.data.index import read_index, row_line

SHARD_DIR = "shards"
MANIFEST_NAME = "shards.json"
MEMBERS = ("annotation.json", "points.npz", "views.npz")


def shard_name(k: int) -> str:
    return f"shard-{k:06d}.tar"


def _tar_bytes(out: Path, rows: list[dict]) -> bytes:
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w", format=tarfile.USTAR_FORMAT) as tar:
        for row in rows:
            for member in MEMBERS:
                path = out / row["path"] / member
                if not path.is_file():
                    continue
                data = path.read_bytes()
                info = tarfile.TarInfo(f"{row['path']}.{member}")
                info.size, info.mode, info.mtime = len(data), 0o644, 0
                tar.addfile(info, io.BytesIO(data))
    return buf.getvalue()


def write_shards(out: str | Path, per_shard: int) -> list[Path]:
    """Write (or bring up to date) the shards of ``OUT/index.jsonl``.

    Parameters
    ----------
    out : str or Path
        An output folder with its index.
    per_shard : int
        Objects per shard (the last one may hold fewer).

    Returns
    -------
    list of Path
        All shards, in order. Shards beyond the new count are removed.
    """
    if per_shard < 1:
        raise ValueError(f"per_shard must be >= 1, got {per_shard}")
    out = Path(out)
    folder = out / SHARD_DIR
    folder.mkdir(exist_ok=True)
    rows = read_index(out)
    try:
        old = json.loads((folder / MANIFEST_NAME).read_text())
        old = {s["name"]: s for s in old["shards"]} if old.get("per_shard") == per_shard else {}
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        old = {}
    shards, paths = [], []
    for k, start in enumerate(range(0, len(rows), per_shard)):
        group = rows[start:start + per_shard]
        name = shard_name(k)
        digest = hashlib.sha256("".join(row_line(r) for r in group).encode()).hexdigest()
        path = folder / name
        prev = old.get(name)
        if not (prev and prev.get("rows_sha256") == digest and path.is_file() and path.stat().st_size == prev["size"]):
            tmp = folder / f".{name}.tmp-{os.getpid()}"
            tmp.write_bytes(_tar_bytes(out, group))
            os.replace(tmp, path)
        shards.append({"name": name, "objects": [r["path"] for r in group], "rows_sha256": digest,
                       "size": path.stat().st_size})
        paths.append(path)
    keep = {s["name"] for s in shards}
    for p in folder.glob("shard-*.tar"):
        if p.name not in keep:
            p.unlink()
    manifest = folder / MANIFEST_NAME
    tmp = folder / f".{MANIFEST_NAME}.tmp-{os.getpid()}"
    tmp.write_text(json.dumps({"per_shard": per_shard, "shards": shards}, indent=1) + "\n")
    os.replace(tmp, manifest)
    return paths


def iter_shard(path: str | Path):
    """Objects of one shard: ``(key, {member: bytes})`` in shard order, members named
    as in :data:`MEMBERS` (``"points.npz"`` ...)."""
    key, members = None, {}
    with tarfile.open(path, mode="r:") as tar:
        for info in tar:
            if not info.isfile():
                continue
            base = info.name.rsplit("/", 1)[-1]
            prefix = info.name[: len(info.name) - len(base)]
            stem, _, ext = base.partition(".")
            k = prefix + stem
            if k != key and key is not None:
                yield key, members
                members = {}
            key = k
            members[ext] = tar.extractfile(info).read()
    if key is not None:
        yield key, members
