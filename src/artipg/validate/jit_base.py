"""Shared pieces of the compiled kernels, and the probes that say where they may run.

The kernels reproduce numpy's results bit for bit by doing the same IEEE operations
in the same order. Three of numpy's operations depend on the machine (its BLAS, its
SIMD loops, its math library), so :func:`kernels_match` checks them once per process
against the kernels' versions before any kernel that relies on them runs:

- ``A @ B`` of (4, 4) frames: numpy hands it to BLAS, whose kernels here sum each
  entry as one fused multiply-add chain in k order (:func:`matmul4`);
- ``np.einsum("nij,nj->ni", R, x)`` sums the three products as (0 + 2) + 1 and
  ``np.einsum("nji,nj->ni", R, x)`` in order (:func:`apply`, :func:`apply_t`);
- ``np.cos``, ``np.sin`` and ``np.hypot`` are the C library's, which the kernels
  call.

Where a probe fails, the checks run the numpy code instead (slower, same results).

Every kernel module passes the modules its kernels use to
:func:`artipg.kernel_cache.drop_stale_caches` when imported.

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math

import numba
import numpy as np
from numba import types
from numba.extending import intrinsic


@intrinsic
def fma(typingctx, a, b, c):
    """``a * b + c`` with one rounding (the machine's fused multiply-add)."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        return builder.fma(*args)

    return sig, codegen


@numba.njit(cache=True)
def copy4(src, out):
    """``out[:] = src`` for (4, 4) frames (a loop: cheaper to compile than a slice)."""
    for i in range(4):
        for j in range(4):
            out[i, j] = src[i, j]


@numba.njit(cache=True)
def set_identity(out):
    """``out[:] = np.eye(4)``."""
    for i in range(4):
        for j in range(4):
            out[i, j] = 1.0 if i == j else 0.0


@numba.njit(cache=True)
def mm_entry(A, B, i, j):
    """Entry (i, j) of ``A @ B`` for (4, 4) frames, as this machine's BLAS computes it
    (a zero accumulator, then one fused multiply-add per term)."""
    s = fma(A[i, 0], B[0, j], 0.0)
    s = fma(A[i, 1], B[1, j], s)
    s = fma(A[i, 2], B[2, j], s)
    return fma(A[i, 3], B[3, j], s)


@numba.njit(cache=True)
def matmul4(A, B, out):
    """``out[:] = A @ B`` for (4, 4) frames (see :func:`mm_entry`)."""
    for i in range(4):
        for j in range(4):
            out[i, j] = mm_entry(A, B, i, j)


@numba.njit(cache=True)
def rigid_inverse(T, out):
    """``out[:] =`` :func:`artipg.validate.kinematics.rigid_inverse` of one frame."""
    for i in range(3):
        for j in range(3):
            out[i, j] = T[j, i]
        out[i, 3] = -apply_t(T, T[0, 3], T[1, 3], T[2, 3], i)
        out[3, i] = 0.0
    out[3, 3] = 1.0


@numba.njit(cache=True)
def apply(W, x0, x1, x2, i):
    """Row i of ``np.einsum("nij,nj->ni", W[:, :3, :3], x)`` for one row, in the order
    numpy sums it (from zero, terms 0 and 2 first)."""
    return 0.0 + W[i, 0] * x0 + W[i, 2] * x2 + W[i, 1] * x1


@numba.njit(cache=True)
def apply_t(W, x0, x1, x2, i):
    """Row i of ``np.einsum("nji,nj->ni", W[:, :3, :3], x)`` for one row (from zero,
    in order)."""
    return 0.0 + W[0, i] * x0 + W[1, i] * x1 + W[2, i] * x2


@numba.njit(cache=True)
def vmax(a, b):
    """``np.maximum`` of two numbers (not NaN)."""
    return a if a > b else b


@numba.njit(cache=True)
def vmin(a, b):
    """``np.minimum`` of two numbers (not NaN)."""
    return a if a < b else b


@numba.njit(cache=True)
def clip01(x):
    """``np.clip(x, 0.0, 1.0)``."""
    return 0.0 if x < 0.0 else (1.0 if x > 1.0 else x)


@numba.njit(cache=True)
def _probe(A, B, x, q):
    n = len(A)
    prod = np.empty((n, 4, 4))
    inv = np.empty((n, 4, 4))
    ein = np.empty((2, n, 3))
    trig = np.empty((3, len(q)))
    for k in range(n):
        matmul4(A[k], B[k], prod[k])
        rigid_inverse(A[k], inv[k])
        for i in range(3):
            ein[0, k, i] = apply(A[k], x[k, 0], x[k, 1], x[k, 2], i)
            ein[1, k, i] = apply_t(A[k], x[k, 0], x[k, 1], x[k, 2], i)
    for k in range(len(q)):
        trig[0, k] = math.cos(q[k])
        trig[1, k] = math.sin(q[k])
        trig[2, k] = math.hypot(q[k], q[len(q) - 1 - k])
    return prod, inv, ein, trig


_MATCH: list = []


def kernels_match() -> bool:
    """Whether numpy's matrix products, einsum orders and sines / cosines are those of
    the kernels on this machine (probed once per process on random frames)."""
    if not _MATCH:
        from artipg.validate.kinematics import rigid_inverse as rigid_inverse_np

        rng = np.random.default_rng(7)
        A = rng.normal(size=(256, 4, 4)) * np.array([1.0, 1e3, 1e-3, 7.0])
        B = rng.normal(size=(256, 4, 4))
        x = rng.normal(size=(256, 3)) * np.array([1.0, 1e3, 1e-3])
        # and entries of few values with (signed) zeros: the order and the start of sums show
        zeros = rng.random((3, 256, 4, 4)) < 0.5
        values = np.array([0.0, -0.0, 1.0, -1.0, 0.5, -2.0])
        A = np.concatenate([A, values[rng.integers(0, 6, (256, 4, 4))] * zeros[0]])
        B = np.concatenate([B, values[rng.integers(0, 6, (256, 4, 4))] * zeros[1]])
        x = np.concatenate([x, values[rng.integers(0, 6, (256, 3))] * zeros[2, :, 0, :3]])
        q = np.concatenate([rng.random(512) * 2 * np.pi, rng.normal(size=256) * 30.0])
        prod, inv, ein, trig = _probe(A, B, x, q)
        same = [(prod, A @ B), (prod[:1], A[0] @ B[:1]), (prod[300], A[300] @ B[300]), (inv, rigid_inverse_np(A)),
                (ein[0], np.einsum("nij,nj->ni", A[:, :3, :3], x)), (ein[1], np.einsum("nji,nj->ni", A[:, :3, :3], x)),
                (trig[0], np.cos(q)), (trig[1], np.sin(q)), (trig[2], np.hypot(q, q[::-1]))]
        _MATCH.append(all(a.tobytes() == np.ascontiguousarray(b).tobytes() for a, b in same))
    return _MATCH[0]


@numba.njit(cache=True)
def box_near(R, cs, hs, ct, ht, m):
    """Whether the box (centre ``cs``, half extents ``hs``) moved by frame ``R`` (4, 4)
    comes within ``m`` of the box (``ct``, ``ht``) on every axis of the latter's frame."""
    ok = True
    for r in range(3):
        c = R[r, 0] * cs[0] + R[r, 1] * cs[1] + R[r, 2] * cs[2] + R[r, 3]
        e = abs(R[r, 0]) * hs[0] + abs(R[r, 1]) * hs[1] + abs(R[r, 2]) * hs[2]
        if not (abs(c - ct[r]) - e - ht[r] <= m):
            ok = False
    return ok
