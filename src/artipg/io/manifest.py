"""The file list of an object folder, and checking a folder against it.

``annotation.json`` records every other file of its folder (relative path, size in
bytes, SHA-256) and is written last, so a folder is *complete* exactly when its
``annotation.json`` exists, parses, lists files, and the files on disk are those
files with those sizes and hashes (DESIGN.md section 3). ``artipg generate``
rebuilds folders that are not; the index (:mod:`artipg.data.index`) lists only
complete ones.
"""

from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass, field
from pathlib import Path

ANNOTATION_NAME = "annotation.json"


def file_records(files: dict[str, bytes]) -> list[dict]:
    """File list of a folder about to be written.

    Parameters
    ----------
    files : dict
        {relative path with ``/`` separators: bytes}; ``annotation.json`` is left out.

    Returns
    -------
    list of dict
        ``{"path", "size", "sha256"}`` per file, sorted by path.
    """
    return [{"path": rel, "size": len(data), "sha256": hashlib.sha256(data).hexdigest()}
            for rel, data in sorted(files.items()) if rel != ANNOTATION_NAME]


@dataclass
class FolderCheck:
    """Verdict on one object folder.

    Attributes
    ----------
    status : {"complete", "missing", "incomplete", "damaged"}
        ``missing``: no folder; ``incomplete``: no ``annotation.json`` or one without
        a file list (an interrupted or older write); ``damaged``: a listed file is
        missing or differs in size or hash, an unlisted file is present, or
        ``annotation.json`` does not parse.
    reason : str
        What was wrong, for messages ("" when complete).
    annotation : dict
        The parsed ``annotation.json`` when complete, else empty.
    """

    status: str
    reason: str = ""
    annotation: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.status == "complete"


def _disk_files(folder: Path) -> dict[str, int]:
    """{relative path: size} of every regular file under ``folder`` (``/`` separators)."""
    out = {}
    for root, dirs, names in os.walk(folder):
        rel_root = os.path.relpath(root, folder)
        for name in names:
            rel = name if rel_root == "." else f"{rel_root}/{name}".replace(os.sep, "/")
            out[rel] = os.stat(os.path.join(root, name)).st_size
    return out


def _sha256_file(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()  # files of a folder are small


def check_folder(folder: str | Path, hashes: bool = True) -> FolderCheck:
    """Check an object folder against the file list of its ``annotation.json``.

    Parameters
    ----------
    folder : str or Path
    hashes : bool
        Also compare SHA-256 hashes (reads every file; about 1 ms for a typical
        folder of half a megabyte). Sizes and the set of files are always compared.

    Returns
    -------
    FolderCheck
    """
    folder = Path(folder)
    if not folder.is_dir():
        return FolderCheck("missing", "no folder")
    try:
        text = (folder / ANNOTATION_NAME).read_bytes()
    except FileNotFoundError:
        return FolderCheck("incomplete", f"no {ANNOTATION_NAME}")
    except OSError as e:
        return FolderCheck("damaged", f"{ANNOTATION_NAME}: {e.strerror or e}")
    try:
        ann = json.loads(text)
        listed = ann["files"]
    except (ValueError, UnicodeDecodeError):
        return FolderCheck("damaged", f"{ANNOTATION_NAME} does not parse")
    except (KeyError, TypeError):
        return FolderCheck("incomplete", f"{ANNOTATION_NAME} has no file list")
    disk = _disk_files(folder)
    disk.pop(ANNOTATION_NAME, None)
    try:
        expected = {r["path"]: (int(r["size"]), r["sha256"]) for r in listed}
    except (KeyError, TypeError, ValueError):
        return FolderCheck("damaged", "malformed file list")
    for rel, (size, digest) in expected.items():
        if rel not in disk:
            return FolderCheck("damaged", f"{rel} missing")
        if disk[rel] != size:
            return FolderCheck("damaged", f"{rel} has {disk[rel]} bytes, listed {size}")
        if hashes and _sha256_file(folder / rel) != digest:
            return FolderCheck("damaged", f"{rel} differs from its listed hash")
    extra = sorted(set(disk) - set(expected))
    if extra:
        return FolderCheck("damaged", f"unlisted file {extra[0]}")
    return FolderCheck("complete", "", ann)
