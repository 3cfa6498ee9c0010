"""numba's disk cache of the compiled kernels, kept in step with their sources.

numba invalidates a kernel's cached machine code only when the file that defines the
kernel changes, not when a module whose functions or constants it compiled in does
(a patch table in ``geometry/box.py``, a helper in another kernel module). Each kernel
module therefore calls :func:`drop_stale_caches` with those modules when imported.
An installed release replaces every file at once, so this matters while editing.
"""

from __future__ import annotations

import os


def drop_stale_caches(module_file: str, deps: list) -> None:
    """Remove the numba cache indexes of the kernels of ``module_file`` (in its
    ``__pycache__``) that are older than one of the modules ``deps`` (their files)
    whose functions or constants they compiled in: numba then compiles them again."""
    folder = os.path.join(os.path.dirname(module_file), "__pycache__")
    try:
        names = os.listdir(folder)
    except OSError:
        return
    newest = max(os.stat(d).st_mtime for d in deps)
    stem = os.path.splitext(os.path.basename(module_file))[0] + "."
    for name in names:
        if name.startswith(stem) and name.endswith(".nbi"):
            path = os.path.join(folder, name)
            try:
                if os.stat(path).st_mtime < newest:
                    os.remove(path)
            except OSError:  # another process got there first
                pass
