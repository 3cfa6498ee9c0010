"""How many threads an OpenMP-parallel extension may use."""

from __future__ import annotations

import ctypes
from functools import lru_cache
from typing import Callable


@lru_cache(maxsize=None)
def openmp_thread_setter(extension_file: str) -> Callable[[int], None] | None:
    """``omp_set_num_threads`` of the OpenMP runtime an extension module is linked against.

    The symbol is looked up through the (already loaded) extension's own library handle,
    which searches that library and its dependencies, so it is the runtime the extension
    really calls, also when the runtime is vendored into the wheel (e.g.
    ``pykdtree.libs/libgomp-<hash>.so``) and several OpenMP runtimes are loaded.

    In OpenMP the thread count is a per-thread setting (the ``nthreads-var`` ICV of the
    calling thread's task): calling the setter changes parallel regions started *from
    the calling thread* only, not those of other threads.

    Parameters
    ----------
    extension_file : str
        Path of a loaded extension module (its ``__file__``).

    Returns
    -------
    callable or None
        ``set_threads(n)``; None when the extension is not linked against OpenMP (its
        parallel regions, if any, then cannot be controlled; a non-OpenMP build is
        single-threaded) or the platform does not resolve symbols through dependencies
        (Windows).
    """
    try:
        fn = ctypes.CDLL(extension_file).omp_set_num_threads
    except (OSError, AttributeError):
        return None
    fn.argtypes, fn.restype = [ctypes.c_int], None
    return fn
