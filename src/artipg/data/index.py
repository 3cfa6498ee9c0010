"""``OUT/index.jsonl``: one line per complete object folder of an output folder.

A row is built from the folder's ``annotation.json`` alone (:func:`index_row`), so
the index written as a run goes and the index rebuilt from disk
(:func:`rebuild_index`, ``artipg index OUT``) are the same. Rows are sorted by
(category, seed, path) whenever the file is rewritten whole; while a run goes its
parent process (the only writer) appends one line per finished object.
"""

from __future__ import annotations

import json
import os
from collections import Counter
from pathlib import Path
from typing import Callable, Iterable

from artipg.io.manifest import check_folder

INDEX_NAME = "index.jsonl"


def index_row(annotation: dict, path: str) -> dict:
    """The index row of one object folder.

    Parameters
    ----------
    annotation : dict
        The folder's parsed ``annotation.json`` (with its file list).
    path : str
        The folder relative to the output folder, ``/`` separators
        (``"storage_furniture/12"``).

    Returns
    -------
    dict
        ``path``, ``category``, ``subcategory``, ``seed``, ``version``, ``joints``
        ({joint type: count}), ``valid`` (the validation verdict; None when the object
        was not validated), ``failed`` (names of failed checks), ``repair``
        ({"iterations", "replaced", "source_seed"}, or None), ``files`` (the file list).
    """
    report = annotation.get("validation") or {}
    checks = report.get("checks") or {}
    repair = report.get("repair")
    return {
        "path": path,
        "category": annotation.get("category"),
        "subcategory": annotation.get("subcategory"),
        "seed": annotation.get("seed"),
        "version": annotation.get("version"),
        "joints": dict(sorted(Counter(j.get("type") for j in annotation.get("joints", [])).items())),
        "valid": report.get("ok"),
        "failed": sorted(k for k, v in checks.items() if isinstance(v, dict) and not v.get("ok", True)),
        "repair": None if repair is None else {k: repair.get(k) for k in ("iterations", "replaced", "source_seed")},
        "files": annotation.get("files", []),
    }


def row_line(row: dict) -> str:
    """One JSONL line (with its newline) for ``row``."""
    return json.dumps(row, separators=(",", ":")) + "\n"


def _key(row: dict):
    seed = row.get("seed")
    return (str(row.get("category")), seed if isinstance(seed, int) else -1, str(row.get("path")))


def read_index(out: str | Path) -> list[dict]:
    """Rows of ``OUT/index.jsonl`` (none when absent); lines that do not parse (a line
    torn by a killed run) are skipped."""
    path = Path(out) / INDEX_NAME
    rows = []
    try:
        text = path.read_text()
    except FileNotFoundError:
        return rows
    for line in text.splitlines():
        try:
            row = json.loads(line)
        except ValueError:
            continue
        if isinstance(row, dict) and isinstance(row.get("path"), str):
            rows.append(row)
    return rows


def write_index(out: str | Path, rows: Iterable[dict]) -> Path:
    """Write ``rows`` as ``OUT/index.jsonl`` atomically, one row per path (the last
    one given wins), sorted by (category, seed, path)."""
    by_path = {r["path"]: r for r in rows}
    path = Path(out) / INDEX_NAME
    tmp = path.with_name(f".{INDEX_NAME}.tmp-{os.getpid()}")
    tmp.write_text("".join(row_line(r) for r in sorted(by_path.values(), key=_key)))
    os.replace(tmp, path)
    return path


class IndexAppender:
    """Appends rows to ``OUT/index.jsonl`` as objects finish (one writer: the run's
    parent process). Each row is one ``write`` of a whole line, so an interrupted
    run leaves whole lines (and at worst one torn last line, which :func:`read_index`
    skips)."""

    def __init__(self, out: str | Path):
        self.path = Path(out) / INDEX_NAME
        self._fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_APPEND, 0o666)

    def append(self, row: dict) -> None:
        os.write(self._fd, row_line(row).encode())

    def close(self) -> None:
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def object_folders(out: str | Path) -> list[Path]:
    """Candidate object folders ``OUT/<category>/<id>/`` (hidden and ``.tmp-*`` names
    skipped), sorted by category then numeric id."""
    out = Path(out)
    found = []
    for cat in sorted(p for p in out.iterdir() if p.is_dir() and not p.name.startswith(".")):
        ids = [p for p in cat.iterdir() if p.is_dir() and not p.name.startswith(".")]
        found += sorted(ids, key=lambda p: (0, int(p.name), "") if p.name.isdigit() else (1, 0, p.name))
    return found


def rebuild_index(out: str | Path, hashes: bool = True,
                  progress: Callable[[int], None] | None = None) -> tuple[list[dict], list[tuple[str, str]]]:
    """Rebuild ``OUT/index.jsonl`` from the folders on disk.

    Parameters
    ----------
    out : str or Path
        An output folder of ``artipg generate``.
    hashes : bool
        Check file hashes as well as sizes (:func:`artipg.io.manifest.check_folder`).
    progress : callable, optional
        Called with 1 after each folder.

    Returns
    -------
    rows : list of dict
        The rows written: one per complete folder.
    bad : list of (str, str)
        (relative path, reason) of folders left out as incomplete or damaged.
    """
    out = Path(out)
    rows, bad = [], []
    for folder in object_folders(out):
        rel = folder.relative_to(out).as_posix()
        check = check_folder(folder, hashes=hashes)
        if check.ok:
            rows.append(index_row(check.annotation, rel))
        else:
            bad.append((rel, check.reason))
        if progress is not None:
            progress(1)
    write_index(out, rows)
    return rows, bad
