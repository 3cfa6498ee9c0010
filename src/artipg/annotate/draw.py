"""The compiled point draw: patch cells and uniform numbers in, labelled points out.

:func:`draw_kernel` takes three uniforms per point, picks each point's patch cell by
the inverse CDF of the cell areas, places the point with its family's closed-form
sampler (:func:`artipg.geometry.patches.place_family`), applies the primitive's pose and
gathers its labels, one point at a time (the cells of the planar families are posed
once, and their points placed in the object frame directly). Its arithmetic is that of
the numpy definition (:func:`artipg.annotate.points.draw_plain`), operation for
operation and in the same order, so the points are the same to the bit
(``tests/test_points_fast.py`` compares them).

:func:`artipg.annotate.points.sample_points` calls :func:`draw_stream` (or, for a fresh
object, :func:`draw_table`, which also makes the cells): the same draw, whose uniforms
are those of numpy's ``Generator(PCG64).random((3, n))`` on the sampling stream, drawn
in the loop by the same integer arithmetic as numpy's PCG64 (:func:`pcg64_next`); the
three rows of U are three stretches of the generator, stepped side by side.
:data:`PCG64_MATCHES` checks the doubles against numpy's when the module is imported;
were they to differ, ``sample_points`` draws them with numpy and calls :func:`draw_kernel`.

This module imports numba; import it only where points are drawn (``import artipg``
and generation stay light).
"""

from __future__ import annotations

import math
import sys

import numba
import numpy as np
from llvmlite import ir
from numba.core import types
from numba.extending import intrinsic

from artipg.annotate import points
from artipg.annotate.points import FAMILY_CODE
from artipg.geometry import kernels, patches
from artipg.geometry.kernels import cell_arrays
from artipg.geometry.patches import TUBE_MAX_STEPS, TUBE_TOL
from artipg.kernel_cache import drop_stale_caches
from artipg.rules import streams
from artipg.rules.streams import PCG64_MULTIPLIER, stream_state

# FAMILY_CODE, TUBE_*, the multiplier and the cells kernel are compiled in
drop_stale_caches(__file__, [points.__file__, patches.__file__, streams.__file__, kernels.__file__])

if list(FAMILY_CODE) != ["rect", "tri", "sector", "band", "zone", "torus"]:
    raise RuntimeError("draw_kernel hard-codes the family codes: update it with FAMILIES")
_TWO_PI = 2.0 * math.pi
_MASK64 = (1 << 64) - 1


@numba.njit(cache=True, nogil=True, error_model="numpy")
def tube_cos_sin(e, M):  # pragma: no cover - compiled
    """Cosine and sine of the tube angle v in [0, 2π] with ``v + e sin v = M``: one
    element of :func:`artipg.geometry.patches.torus_tube_quantiles` (e = r / R, M = 2π u)."""
    a = e / (1.0 - e)
    k = 0.25 * a * a + a / 6.0
    lo = 0.0
    hi = _TWO_PI
    v = M
    for _ in range(TUBE_MAX_STEPS):
        s = math.sin(v)
        c = math.cos(v)
        g = (v + e * s) - M
        if g == 0.0:
            return c, s
        if g < 0.0:
            lo = v
        elif g > 0.0:
            hi = v
        fp = 1.0 + e * c
        den = fp * fp + 0.5 * g * e * s
        halley = den >= 0.5 * fp * fp
        w = v - (g * fp / den if halley else g / fp)
        inside = w >= lo and w <= hi
        if not inside:
            w = 0.5 * (lo + hi)
        d = v - w
        dd = d * d
        if halley and inside and abs(d) * dd * k <= TUBE_TOL:
            cd = 1.0 - dd * (0.5 - dd / 24.0)
            sd = d * (1.0 - dd / 6.0)
            return c * cd + s * sd, s * cd - c * sd
        v = w
    return math.cos(v), math.sin(v)


# ---------------------------------------------------------------- numpy's PCG64, inline

def _wide(builder, lo, hi):
    i128 = ir.IntType(128)
    return builder.or_(builder.shl(builder.zext(hi, i128), ir.Constant(i128, 64)), builder.zext(lo, i128))


def _words_of(builder, x):
    i64 = ir.IntType(64)
    return builder.trunc(x, i64), builder.trunc(builder.lshr(x, ir.Constant(x.type, 64)), i64)


_U64x2 = types.UniTuple(types.uint64, 2)


@intrinsic
def _mul_add(typingctx, a_lo, a_hi, b_lo, b_hi, c_lo, c_hi):
    """``a * b + c`` mod 2^128 of 128-bit ints given and returned as (low, high) uint64
    words (LLVM's 128-bit integer arithmetic)."""
    args = (a_lo, a_hi, b_lo, b_hi, c_lo, c_hi)
    if not all(a == types.uint64 for a in args):
        return None

    def codegen(context, builder, signature, v):
        x = builder.add(builder.mul(_wide(builder, v[0], v[1]), _wide(builder, v[2], v[3])), _wide(builder, v[4], v[5]))
        return context.make_tuple(builder, signature.return_type, list(_words_of(builder, x)))

    return _U64x2(*args), codegen


@intrinsic
def _pcg_double(typingctx, lo, hi):
    """numpy's double of a PCG64 state (``pcg64_next_double`` after the step): the XSL-RR
    output ``rotr64(hi ^ lo, hi >> 58)``, its top 53 bits times 2^-53."""
    if not (lo == types.uint64 and hi == types.uint64):
        return None

    def codegen(context, builder, signature, v):
        i64, f64 = ir.IntType(64), ir.DoubleType()
        x = builder.xor(v[1], v[0])
        rot = builder.lshr(v[1], ir.Constant(i64, 58))
        r = builder.or_(builder.lshr(x, rot), builder.shl(x, builder.and_(builder.neg(rot), ir.Constant(i64, 63))))
        return builder.fmul(builder.uitofp(builder.lshr(r, ir.Constant(i64, 11)), f64), ir.Constant(f64, 2.0 ** -53))

    return types.float64(lo, hi), codegen


_MULT_LO, _MULT_HI = np.uint64(PCG64_MULTIPLIER & _MASK64), np.uint64(PCG64_MULTIPLIER >> 64)
_ZERO, _ONE = np.uint64(0), np.uint64(1)
_NO_WORDS = np.zeros(0, dtype=np.uint64)
_NO_U = np.zeros((3, 0))


@numba.njit(inline="always", nogil=True)
def pcg64_next(lo, hi, inc_lo, inc_hi):  # pragma: no cover - compiled
    """One draw of numpy's PCG64 (XSL-RR 128/64): the state ``(lo, hi)`` times the
    multiplier plus the increment, mod 2^128, and the double of the new state. Returns
    (new lo, new hi, double). Integer arithmetic only, so the doubles are numpy's to the
    bit wherever numpy's PCG64 is this generator (:data:`PCG64_MATCHES`)."""
    lo, hi = _mul_add(lo, hi, _MULT_LO, _MULT_HI, inc_lo, inc_hi)
    return lo, hi, _pcg_double(lo, hi)


@numba.njit(cache=True, nogil=True)
def pcg64_advance(lo, hi, inc_lo, inc_hi, n):  # pragma: no cover - compiled
    """The PCG64 state ``(lo, hi)`` advanced by ``n`` >= 0 draws, as
    :func:`artipg.rules.streams.advance_state` (Brown's jump: ``n`` steps are one
    affine map, composed by squaring)."""
    am_lo, am_hi, ap_lo, ap_hi = _ONE, _ZERO, _ZERO, _ZERO
    cm_lo, cm_hi, cp_lo, cp_hi = _MULT_LO, _MULT_HI, _ONE, _ZERO
    while n > 0:
        if n & 1:
            am_lo, am_hi = _mul_add(am_lo, am_hi, cm_lo, cm_hi, _ZERO, _ZERO)
            ap_lo, ap_hi = _mul_add(ap_lo, ap_hi, cm_lo, cm_hi, cp_lo, cp_hi)
        cp_lo, cp_hi = _mul_add(cm_lo, cm_hi, cp_lo, cp_hi, cp_lo, cp_hi)  # (cm + 1) cp
        cm_lo, cm_hi = _mul_add(cm_lo, cm_hi, cm_lo, cm_hi, _ZERO, _ZERO)
        n >>= 1
    t_lo, t_hi = _mul_add(inc_lo, inc_hi, ap_lo, ap_hi, _ZERO, _ZERO)
    return _mul_add(lo, hi, am_lo, am_hi, t_lo, t_hi)


@numba.njit(cache=True, nogil=True)
def pcg_fill(words, out):  # pragma: no cover - compiled
    """Fill ``out`` (n,) with the doubles numpy's ``Generator(PCG64).random`` draws from
    the state of ``words`` (:func:`stream_words`): the definition of the draws of
    :func:`draw_stream`, checked against numpy."""
    lo, hi, inc_lo, inc_hi = words[0], words[1], words[2], words[3]
    for j in range(out.shape[0]):
        lo, hi, out[j] = pcg64_next(lo, hi, inc_lo, inc_hi)


def stream_words(seed: int, key: int) -> np.ndarray:
    """PCG64 state and increment (4,) uint64, read-only (state low, high, increment low,
    high) at the start of stream ``key`` of seed ``seed``
    (:func:`artipg.rules.streams.stream_state`)."""
    hit = _RECENT_WORDS.get((seed, key))
    if hit is None:
        state, inc = stream_state(seed, key)
        hit = np.frombuffer((state | inc << 128).to_bytes(32, "little"), dtype=np.uint64)
        if len(_RECENT_WORDS) >= 16:
            _RECENT_WORDS.clear()
        _RECENT_WORDS[(seed, key)] = hit
    return hit


# The words of the last few (sampling seed, stream): the same sampling seed (the default
# 0) is the usual one for every object.
_RECENT_WORDS: dict[tuple, np.ndarray] = {}


def _pcg_matches_numpy() -> bool:
    """Whether :func:`pcg_fill` and :func:`pcg64_advance` give numpy's doubles and
    states (from a probe state and a stream of :mod:`artipg.rules.streams`)."""
    if sys.byteorder != "little":  # stream_words
        return False
    bitgen = np.random.PCG64(0)
    gen = np.random.Generator(bitgen)
    for words in (np.array([0xFEDCBA9876543210, 0x0123456789ABCDEF, 0x8796A5B4C3D2E1F1, 0x0F1E2D3C4B5A6978],
                           dtype=np.uint64), stream_words(7, 0x5A3D1E)):
        lo, hi, inc_lo, inc_hi = (int(w) for w in words)
        bitgen.state = {"bit_generator": "PCG64", "state": {"state": hi << 64 | lo, "inc": inc_hi << 64 | inc_lo},
                        "has_uint32": 0, "uinteger": 0}
        got = np.empty(300)
        pcg_fill(words, got)
        if got.tobytes() != gen.random(300).tobytes():
            return False
        bitgen.advance(1000)
        lo, hi = pcg64_advance(words[0], words[1], words[2], words[3], 1300)
        if bitgen.state["state"]["state"] != int(hi) << 64 | int(lo):
            return False
    return True


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_kernel(U, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic,
                out, labels):  # pragma: no cover - compiled
    """Labelled points of an object from their uniforms (in place).

    Parameters
    ----------
    U : (3, n) float64
        Uniforms in [0, 1) of the n points: ``U[0]`` picks the cell (the first whose
        cumulative weight exceeds ``U[0]`` times the total), ``U[1]`` and ``U[2]`` are
        the family sampler's u and v.
    weight : (K,) float64
        Cell weights >= 0 (areas, or probabilities), not all zero.
    code : (K,) int64
        Family code of each cell (:data:`FAMILY_CODE`).
    Q : (K, 15) float64
        Family parameters of each cell, primitive-local frame (unused columns ignored).
    W : (N, 3, 4) float64
        Pose of every primitive in the object frame.
    cell_prim, prim_part, prim_link, part_semantic : int64 arrays
        Primitive of each cell; part and link of each primitive; semantic id of each part.
    out : (2, n, 3) float64
        Output positions (metres) and unit normals, object frame.
    labels : (4, n) int64
        Output primitive, part, semantic id and link of each point.
    """
    _draw(U, _NO_WORDS, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out, labels)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_stream(words, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic,
                out, labels):  # pragma: no cover - compiled
    """:func:`draw_kernel` of the uniforms that numpy's ``Generator(PCG64).random((3, n))``
    draws from a given state, drawn here (n = ``out.shape[1]``).

    Parameters
    ----------
    words : (4,) uint64
        PCG64 state and increment (:func:`stream_words`) before the first draw.
    weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out, labels
        As for :func:`draw_kernel`.
    """
    _draw(_NO_U, words, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out, labels)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def draw_table(flat, foff, start, prim, code, cos_f, sin_f, W, prim_part, prim_link, part_semantic, words, out,
               labels):  # pragma: no cover - compiled
    """:func:`draw_stream` of an object's cells weighted by their areas, the cells made
    here (:func:`artipg.geometry.kernels.cell_arrays` of the first seven arguments,
    ``PrimitiveTable._packed``) and dropped. Returns the number of cells; with none,
    nothing is drawn."""
    cell_code, Q, area, cell_prim, _, _ = cell_arrays(flat, foff, start, prim, code, cos_f, sin_f)
    K = area.shape[0]
    if K:
        _draw(_NO_U, words, area, cell_code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out, labels)
    return K


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _prepare(weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic):  # pragma: no cover - compiled
    """The per-cell tables of the draw: running weights, guide table, labels and the
    posed parameters of the planar cells."""
    K = weight.shape[0]
    cum = np.empty(K)
    acc = 0.0
    for c in range(K):  # np.cumsum: a running sum
        acc += weight[c]
        cum[c] = acc
    total = cum[K - 1]
    # The cell of x = U[0, j] * total is np.searchsorted(cum, x, side="right"): the first
    # with cum > x (< K, as x < total). It is found by a scan from guide[int(U[0, j] * K)],
    # the first cell with cum > y_b, where y_b = b total / K shrunk by 2^-40 stays below
    # every x of bucket b despite rounding: so the scan starts at or before the answer,
    # and is about one step long.
    guide = np.empty(K, np.int64)
    scale = total / K * (1.0 - 2.0 ** -40)
    c = 0
    for b in range(K):
        y = b * scale
        while cum[c] <= y:
            c += 1
        guide[b] = c
    # per cell: its labels, and for the planar families (affine in o, a, b) its
    # parameters posed in the object frame, so that their points need no transform
    lab = np.empty((K, 4), np.int64)
    P = np.empty((K, 15))
    for c in range(K):
        p = cell_prim[c]
        part = prim_part[p]
        lab[c, 0] = p
        lab[c, 1] = part
        lab[c, 2] = part_semantic[part]
        lab[c, 3] = prim_link[p]
        if code[c] <= 2:
            for a in range(3):
                P[c, a] = ((W[p, a, 0] * Q[c, 0] + W[p, a, 1] * Q[c, 1]) + W[p, a, 2] * Q[c, 2]) + W[p, a, 3]
                for r in range(3, 12, 3):
                    P[c, r + a] = (W[p, a, 0] * Q[c, r] + W[p, a, 1] * Q[c, r + 1]) + W[p, a, 2] * Q[c, r + 2]
            P[c, 12] = Q[c, 12]
            P[c, 13] = Q[c, 13]
            P[c, 14] = Q[c, 14]
    return cum, total, guide, lab, P


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _draw(U, words, weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic, out,
          labels):  # pragma: no cover - compiled
    """:func:`draw_kernel` (``words`` empty) and :func:`draw_stream` (``U`` not read).
    Arrays are read element by element in the loop: a row view (``P[c]``) or a tuple of
    arrays unpacked per point costs reference count updates that take longer than the
    rest of a planar point."""
    cum, total, guide, lab, P = _prepare(weight, code, Q, W, cell_prim, prim_part, prim_link, part_semantic)
    K = cum.shape[0]
    n = out.shape[1]
    stream = words.shape[0] == 4
    if stream:
        il, ih = words[2], words[3]
        # the rows of U are three independent stretches of the generator: stepped together
        l0, h0 = words[0], words[1]
        l1, h1 = pcg64_advance(l0, h0, il, ih, n)
        l2, h2 = pcg64_advance(l1, h1, il, ih, n)
    else:
        il = ih = l0 = h0 = l1 = h1 = l2 = h2 = _ZERO
    for j in range(n):
        if stream:
            l0, h0, u0 = pcg64_next(l0, h0, il, ih)
            l1, h1, u = pcg64_next(l1, h1, il, ih)
            l2, h2, v = pcg64_next(l2, h2, il, ih)
        else:
            u0, u, v = U[0, j], U[1, j], U[2, j]
        x = u0 * total
        c = guide[int(u0 * K)]
        while cum[c] <= x:
            c += 1
        for a in range(4):
            labels[a, j] = lab[c, a]
        f = code[c]
        if f <= 2:  # rect, tri, sector: o + u a + v b, posed
            if f == 1 and u + v > 1.0:  # the far half of the unit square folds onto the triangle
                u = 1.0 - u
                v = 1.0 - v
            elif f == 2:  # polar (rho, phi) -> (u, v) in the sector's plane
                r0 = P[c, 12]
                r1 = P[c, 13]
                rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
                phi = v * P[c, 14]
                u = math.cos(phi) * rho
                v = math.sin(phi) * rho
            for a in range(3):
                out[0, j, a] = P[c, a] + u * P[c, 3 + a] + v * P[c, 6 + a]
                out[1, j, a] = P[c, 9 + a]
            continue
        if f == 3:  # band
            r0 = Q[c, 0]
            r1 = Q[c, 1]
            rho = math.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
            s = u * (r0 + r1) / (rho + r0 + 1e-300)
            th = v * Q[c, 4]
            ct = math.cos(th)
            st = math.sin(th)
            x = rho * ct
            y = rho * st
            z = Q[c, 2] + s * (Q[c, 3] - Q[c, 2])
            nx, ny, nz = ct * Q[c, 5], st * Q[c, 5], Q[c, 6]
        elif f == 4:  # zone
            R = Q[c, 0]
            z = u * (Q[c, 2] - Q[c, 1]) + Q[c, 1]
            rho = math.sqrt(max(R * R - z * z, 0.0))
            th = v * _TWO_PI
            x = math.cos(th) * rho
            y = math.sin(th) * rho
            nx, ny, nz = x / R, y / R, z / R
        else:  # torus: the tube angle by its inverse CDF, then the arc angle
            R = Q[c, 0]
            r = Q[c, 1]
            cv, sv = tube_cos_sin(r / R, u * _TWO_PI)
            th = v * Q[c, 2]
            ct = math.cos(th)
            st = math.sin(th)
            rho = R + r * cv
            x = rho * ct
            y = rho * st
            z = r * sv
            nx, ny, nz = cv * ct, cv * st, sv
        p = lab[c, 0]
        for a in range(3):
            out[0, j, a] = ((W[p, a, 0] * x + W[p, a, 1] * y) + W[p, a, 2] * z) + W[p, a, 3]
            out[1, j, a] = (W[p, a, 0] * nx + W[p, a, 1] * ny) + W[p, a, 2] * nz


#: Whether :func:`draw_stream` draws numpy's uniforms (else the caller draws them
#: with numpy and calls :func:`draw_kernel`).
PCG64_MATCHES = _pcg_matches_numpy()
