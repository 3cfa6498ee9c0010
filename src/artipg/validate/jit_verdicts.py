"""From the scenes' pairs to the checks' verdicts in two compiled calls.

:func:`artipg.validate.checks.run_checks` measures every pair of the scenes, refines
the rest pairs whose samples may miss a curved contact, and reduces the distances to
the penetration, floating and joint-sweep results. With the kernels on, that is

- :func:`distances`: the pair distances
  (:func:`artipg.validate.jit_contacts._pair_distance`) and the rest pairs to refine;
- :func:`verdicts`: their refinement (:func:`artipg.validate.jit_contacts._refine`,
  written into the distances) and what the results are made of: each scene's
  colliding rows and lowest distance, the contact graphs
  (:func:`artipg.validate.jit_scenes.contact_graphs`) and the links whose parts fall
  apart.

The same comparisons and sums in the same order as the numpy code of ``run_checks``,
``_penetration``, ``_floating`` and ``_sweep_result``
(``tests/test_validate_compiled.py``).

This module imports numba: import it lazily (``import artipg`` stays light).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from artipg.kernel_cache import drop_stale_caches
from artipg.validate import jit_base, jit_contacts, jit_pairs, jit_scenes, kinematics
from artipg.validate.jit_contacts import _pair_distance, _refine
from artipg.validate.jit_scenes import contact_graphs

drop_stale_caches(__file__, [jit_base.__file__, jit_contacts.__file__, jit_pairs.__file__, jit_scenes.__file__,
                             kinematics.__file__])


@numba.njit(cache=True)
def distances(a, b, Wa, Wb, margin, box, ball, other, src, tgt, rel, keep, params, code, aux, center, half, radial,
              pts, start, count, n_rest, c0, h0, is_box, drawn, floating):
    """:func:`artipg.validate.jit_contacts._pair_distance` of all rows, then
    :func:`ambiguous` of the first ``n_rest`` (the rest scene): ``(d, amb,
    undrawn)``."""
    d = _pair_distance(a, b, Wa, Wb, margin, box, ball, other, src, tgt, rel, keep, params, code, aux, center, half,
                       radial, pts, start, count)
    amb, undrawn = ambiguous(a, b, d, n_rest, is_box, c0, h0, drawn, floating)
    return d, amb, undrawn


@numba.njit(cache=True)
def ambiguous(a, b, d, n_rest, is_box, c0, h0, drawn, floating):
    """The rest rows (of the first ``n_rest``) that ``run_checks`` refines: not two
    boxes, apart by more than ``floating`` by their samples, with world boxes (``c0``,
    ``h0``) within ``floating``; and whether one of their pieces has no samples yet."""
    out = np.empty(n_rest, dtype=np.int64)
    n = 0
    undrawn = False
    for r in range(n_rest):
        i, j = a[r], b[r]
        if (is_box[i] and is_box[j]) or not d[r] > floating:
            continue
        s = 0.0
        for k in range(3):  # sqrt(sum(maximum(|c_i - c_j| - h_i - h_j, 0) ** 2))
            v = abs(c0[i, k] - c0[j, k]) - h0[i, k] - h0[j, k]
            if v < 0.0:
                v = 0.0
            s += v * v
        if math.sqrt(s) <= floating:
            out[n] = r
            n += 1
            undrawn |= not (drawn[i] and drawn[j])
    return out[:n].copy(), undrawn


@numba.njit(cache=True)
def _min(x, m):
    """``min(m, x)`` where a NaN, once met, stays (numpy's ``min``)."""
    return x if (x < m or x != x) else m


@numba.njit(cache=True)
def verdicts(amb, a, b, W0, d, sizes, starts, iters, params, code, aux, pts, start, count, H, on_surface, offs, link,
             part, part_link, L, P, floating, penetration):
    """Refine the distances ``d`` of the rest rows ``amb`` in place (as ``run_checks``:
    :func:`artipg.validate.jit_contacts._refine` at rest frames ``W0``, at most
    ``iters`` steps, stopping below ``floating``; a row keeps the smaller value), then
    reduce every scene (``sizes``: rows of rest, sweep, open...).

    Returns
    -------
    bad : (n,) int64
        Colliding rows (distance below ``-penetration``; rest: of different links),
        each scene's in turn, numbered within their scene.
    n_bad, low : (S,) int64, float64
        Their count per scene and each scene's lowest distance (rest: over the rows of
        different links; inf without rows, NaN where a distance is NaN; a zero's sign
        may differ from numpy's ``min``, which the results only use as ``max(0.0,
        -low)``).
    comp, pcomp, has_geom, has_piece, several
        :func:`artipg.validate.jit_scenes.contact_graphs` of the rest rows.
    split : (k,) int64
        Links whose parts fall into more than one contact component.
    """
    K = len(amb)
    if K:
        ia, ib = a[amb], b[amb]
        got = _refine(ia, ib, W0[ia], W0[ib], starts, iters, floating, params, code, aux, pts, start, count, H,
                      on_surface, offs)
        for k in range(K):
            x = d[amb[k]]
            d[amb[k]] = x if x < got[k] else got[k]  # np.minimum (x > floating: no NaN, no zero)
    S = len(sizes)
    bad = np.empty(len(d), dtype=np.int64)
    n_bad = np.zeros(S, dtype=np.int64)
    low = np.full(S, np.inf)
    nb = 0
    row = 0
    for s in range(S):
        for r in range(row, row + sizes[s]):
            if s == 0 and link[a[r]] == link[b[r]]:
                continue
            low[s] = _min(d[r], low[s])
            if d[r] < -penetration:
                bad[nb] = r - row
                nb += 1
                n_bad[s] += 1
        row += sizes[s]
    n0 = sizes[0]
    comp, pcomp, has_geom, has_piece, lo, hi, several = contact_graphs(L, P, link, part, part_link, a[:n0], b[:n0],
                                                                       d[:n0], floating)
    split = np.nonzero(hi > lo)[0]
    return bad[:nb].copy(), n_bad, low, comp, pcomp, has_geom, has_piece, several, split
