"""Whether the geometric checks run their compiled (numba) kernels.

The kernels (the ``jit_*`` modules of :mod:`artipg.validate`) reproduce the numpy
code they stand in for bit for bit; that code stays the definition and the fallback.
They run where :func:`artipg.validate.jit_base.kernels_match` finds numpy's matrix
products, einsum orders and math library to be the kernels' on this machine, and
``ENABLED`` is True. ``ENABLED = False`` (or the environment variable
``ARTIPG_NUMBA=0``) runs the plain numpy code everywhere, e.g. to compare both.

The first check in a process imports numba and loads the kernels from numba's disk
cache (``__pycache__`` next to the modules; compiled there on first use): about a
second, once per process.
"""

from __future__ import annotations

import os

#: Run the compiled kernels (True) or the numpy code they replace (False).
ENABLED = os.environ.get("ARTIPG_NUMBA", "1") != "0"
