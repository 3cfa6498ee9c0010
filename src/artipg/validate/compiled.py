"""Whether the geometric checks run their compiled (numba) kernels.

The kernels (:mod:`artipg.validate.jit_samples` and the other ``jit_*`` modules)
reproduce the numpy code they stand in for bit for bit; that code stays the
definition and the fallback. ``ENABLED = False`` (or the environment variable
``ARTIPG_NUMBA=0``) runs the plain numpy code everywhere, e.g. to compare both.
Kernels are compiled on first use and cached on disk by numba.
"""

from __future__ import annotations

import os

#: Run the compiled kernels (True) or the numpy code they replace (False).
ENABLED = os.environ.get("ARTIPG_NUMBA", "1") != "0"
