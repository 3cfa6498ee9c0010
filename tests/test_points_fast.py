"""The fast paths of the geometry after the rule code, byte for byte against the plain
computations they replace.

Patch blocks, component areas, local boxes, the primitive table, the object bounds and
the labelled point draw are compared with straightforward versions written here with
the generic helpers of :mod:`artipg.geometry.patches` (stacking, tiling, one primitive
at a time): every array must have the same bytes, not just close values, because the
validation replays patch tables and samplers and objects must not change. The compiled
point draw is also compared with its numpy definition, and the torus's exact tube-angle
draw with its law.
"""

from __future__ import annotations

import numpy as np
import pytest

import artipg
from artipg.annotate.points import (FAMILY_CODE, SAMPLING_STREAM, PrimitiveTable, draw_plain, sample_points,
                                    transform_boxes)
from artipg.geometry import Cuboid, Frustum, Prism, RectRing, Ring, Sphere, Torus, TriPrism
from artipg.geometry.box import _BOX_TABLE, _RING_COMP, _RING_SIDES, _RING_TABLE, _RING_TABLES
from artipg.geometry.patches import (FAMILIES, TWO_PI, Patch, bands, block, linear, place_family, rects,
                                     sample_family, sectors, tori, torus_tube_angles, torus_tube_quantiles, tris,
                                     zones)
from artipg.geometry.revolve import _FRUSTUM_CAPS, _RING_CAPS
from artipg.rules.streams import streams
from artipg.vocabulary import label_id


def same(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and np.ascontiguousarray(a).tobytes() == \
        np.ascontiguousarray(b).tobytes()


# ---------------------------------------------------------------- plain definitions

def _plain_block(family, comp, area, *cols):
    comp = np.asarray(comp, dtype=np.int64).reshape(-1)
    area = np.asarray(area, dtype=float)
    shape = (len(comp), area.shape[-1])
    params = np.empty((shape[0], len(cols), shape[1]))
    for j, col in enumerate(cols):
        params[:, j] = col
    return Patch(family, comp, np.broadcast_to(area, shape), params)


def _plain_linear(family, comp, P, table, area):
    c, p, _ = table.shape
    flat = table.reshape(c * p, -1)
    params = flat[:, :-1] @ P.T + flat[:, -1:]
    return Patch(family, np.asarray(comp, dtype=np.int64), area, params.reshape(c, p, len(P)))


def _is_full(arc):
    return np.asarray(arc) >= TWO_PI - 1e-9


def _plain_areas(name, P):
    if name == "Frustum":
        r0, r1, h, c0, c1 = P.T
        return np.column_stack([np.pi * (r0 + r1) * np.hypot(h, r1 - r0), np.pi * c0 * r0 * r0,
                                np.pi * c1 * r1 * r1])
    if name == "Ring":
        ro, ri, h, arc, tp = P.T
        sl = np.hypot(h, tp)
        end = np.where(_is_full(arc), 0.0, (ro - ri) * h)
        bot = arc / 2 * (ro * ro - ri * ri)
        top = arc / 2 * ((ro + tp) ** 2 - (ri + tp) ** 2)
        return np.column_stack([arc * (ro + tp / 2) * sl, arc * (ri + tp / 2) * sl, bot, top, end, end])
    if name == "Sphere":
        R, lo, hi = P.T
        return np.column_stack([TWO_PI * R * (hi - lo), np.pi * np.maximum(R * R - lo * lo, 0.0),
                                np.pi * np.maximum(R * R - hi * hi, 0.0)])
    if name == "Torus":
        R, r, arc, c0, c1 = P.T
        part = ~_is_full(arc)
        cap = np.pi * r * r
        return np.column_stack([TWO_PI * r * R * arc, cap * c0 * part, cap * c1 * part])
    if name == "Cuboid":
        sx, sy, sz = P[:, 0], P[:, 1], P[:, 2]
        a, b, c = sy * sz, sx * sz, sx * sy
        return np.column_stack([a, a, b, b, c, c])
    if name == "RectRing":
        C, S, N, A0, A1 = _RING_TABLES
        sizes = np.einsum("kp,prc->krc", P, S)
        rows = np.arange(16)
        return sizes[:, rows, A0] * sizes[:, rows, A1]
    return {"Prism": Prism, "TriPrism": TriPrism}[name].component_areas(P)


def _plain_patches(name, P):
    """The patch blocks as the generic helpers build them."""
    X, Y = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
    down_up = np.array([[-1.0], [1.0]])
    if name == "Frustum":
        r0, r1, h = P[:, 0], P[:, 1], P[:, 2]
        caps = _plain_linear("sector", (1, 2), P, _FRUSTUM_CAPS, _plain_areas(name, P)[:, 1:].T)
        return [bands(0, r0, r1, -h / 2, h / 2, TWO_PI), caps]
    if name == "Ring":
        ro, ri, h, arc, tp = P.T
        z = h / 2
        out = [bands((0, 1), np.stack([ro, ri]), np.stack([ro + tp, ri + tp]), -z, z, arc,
                     inward=np.array([[False], [True]])),
               _plain_linear("sector", (2, 3), P, _RING_CAPS, _plain_areas(name, P)[:, 2:4].T)]
        partial = ~_is_full(arc)
        if partial.any():
            ends = np.stack([np.zeros_like(arc), arc])
            ce, se = np.cos(ends), np.sin(ends)
            sg = np.array([[-1.0], [1.0]])
            out.append(rects((4, 5), (ri * ce, ri * se, -z), ((ro - ri) * ce, (ro - ri) * se, 0.0),
                             (tp * ce, tp * se, h), (-se * sg, ce * sg, 0.0), scale=partial))
        return out
    if name == "Sphere":
        R, lo, hi = P.T
        zc = np.stack([lo, hi])
        caps = sectors((1, 2), (0.0, 0.0, zc), X, Y, (0.0, 0.0, down_up), 0.0,
                       np.sqrt(np.maximum(R * R - zc * zc, 0.0)), TWO_PI)
        return [zones(0, R, lo, hi), caps]
    if name == "Torus":
        R, r, arc, c0, c1 = P.T
        on = ~_is_full(arc) * np.stack([c0, c1])
        if not on.any():
            return [tori(0, R, r, arc)]
        ends = np.stack([np.zeros_like(arc), arc])
        ce, se = np.cos(ends), np.sin(ends)
        sg = np.array([[-1.0], [1.0]])
        caps = sectors((1, 2), (R * ce, R * se, 0.0), (ce, se, 0.0), (0.0, 0.0, 1.0),
                       (-se * sg, ce * sg, 0.0), 0.0, r, TWO_PI, scale=on)
        return [tori(0, R, r, arc), caps]
    if name == "Cuboid":
        return [_plain_linear("rect", np.arange(6), P, _BOX_TABLE, _plain_areas(name, P).T)]
    if name == "RectRing":
        return [_plain_linear("rect", _RING_COMP, P, _RING_TABLE, _plain_areas(name, P).T)]
    if name == "Prism":
        out = []
        for n in np.unique(P[:, 2]).astype(int):
            on = (P[:, 2] == n).astype(float)
            r, h = P[:, 0], P[:, 1]
            a = (np.pi / n + TWO_PI * np.arange(n) / n)[:, None]
            x0, y0 = r * np.cos(a), r * np.sin(a)
            x1, y1 = r * np.cos(a + TWO_PI / n), r * np.sin(a + TWO_PI / n)
            mid = a + np.pi / n
            out.append(rects(np.zeros(n, dtype=int), (x0, y0, -h / 2), (x1 - x0, y1 - y0, 0.0), (0.0, 0.0, h),
                             (np.cos(mid), np.sin(mid), 0.0), scale=on))
            z = np.concatenate([np.broadcast_to(-h / 2, x0.shape), np.broadcast_to(h / 2, x0.shape)])
            nz = np.repeat([[-1.0], [1.0]], n, axis=0)
            out.append(tris(np.repeat([1, 2], n), (0.0, 0.0, z), (np.tile(x0, (2, 1)), np.tile(y0, (2, 1)), 0.0),
                            (np.tile(x1, (2, 1)), np.tile(y1, (2, 1)), 0.0), (0.0, 0.0, nz), scale=on))
        return out
    if name == "TriPrism":
        w, t, a, d = P.T
        z0 = np.zeros_like(w)
        V = np.stack([np.column_stack([-w / 2, z0]), np.column_stack([w / 2, z0]), np.column_stack([a, t])],
                     axis=1).transpose(1, 2, 0)
        E = np.roll(V, -1, axis=0) - V
        L = np.hypot(E[:, 0], E[:, 1])
        sides = rects((0, 1, 2), (V[:, 0], V[:, 1], -d / 2), (E[:, 0], E[:, 1], 0.0), (0.0, 0.0, d),
                      (E[:, 1] / L, -E[:, 0] / L, 0.0))
        ends = tris((3, 4), (V[0, 0], V[0, 1], np.stack([-d / 2, d / 2])), (E[0, 0], E[0, 1], 0.0),
                    (-E[2, 0], -E[2, 1], 0.0), (0.0, 0.0, np.array([[-1.0], [1.0]])))
        return [sides, ends]
    raise KeyError(name)


def _plain_arc_bounds_batch(r_lo, r_hi, arc, z0, z1):
    def boxes(lo, hi):
        out = np.empty((len(arc), 2, 3))
        for k in range(3):
            out[:, 0, k] = lo[k]
            out[:, 1, k] = hi[k]
        return out
    if (arc >= TWO_PI - 1e-9).all():
        return boxes((-r_hi, -r_hi, z0), (r_hi, r_hi, z1))
    arc = np.minimum(arc, TWO_PI)
    cand = np.stack([np.zeros_like(arc), arc, np.full_like(arc, 0.5 * np.pi), np.full_like(arc, np.pi),
                     np.full_like(arc, 1.5 * np.pi)], axis=1)
    ok = np.ones_like(cand, dtype=bool)
    ok[:, 2:] = cand[:, 2:] < arc[:, None]
    c, s = np.cos(cand), np.sin(cand)
    xs = np.concatenate([c * r_lo[:, None], c * r_hi[:, None]], axis=1)
    ys = np.concatenate([s * r_lo[:, None], s * r_hi[:, None]], axis=1)
    ok2 = np.concatenate([ok, ok], axis=1)
    return boxes((np.where(ok2, xs, np.inf).min(1), np.where(ok2, ys, np.inf).min(1), z0),
                 (np.where(ok2, xs, -np.inf).max(1), np.where(ok2, ys, -np.inf).max(1), z1))


def _plain_bounds_batch(name, P):
    if name in ("Cuboid", "RectRing"):
        h = P[:, :3] * 0.5
        return np.stack([-h, h], axis=1)
    if name == "Frustum":
        r = np.maximum(P[:, 0], P[:, 1])
        z = P[:, 2] * 0.5
        return np.stack([np.column_stack([-r, -r, -z]), np.column_stack([r, r, z])], axis=1)
    if name == "Ring":
        ro, ri, h, arc, tp = P.T
        return _plain_arc_bounds_batch(np.minimum(ri, ri + tp), np.maximum(ro, ro + tp), arc, -h / 2, h / 2)
    if name == "Torus":
        R, r, arc = P[:, 0], P[:, 1], P[:, 2]
        return _plain_arc_bounds_batch(R - r, R + r, arc, -r, r)
    if name == "Sphere":
        R, lo, hi = P.T
        r = np.where((lo <= 0) & (hi >= 0), R, np.sqrt(np.maximum(R * R - np.minimum(lo * lo, hi * hi), 0.0)))
        return np.stack([np.column_stack([-r, -r, lo]), np.column_stack([r, r, hi])], axis=1)
    if name == "TriPrism":
        w, t, a, d = P.T
        return np.stack([np.column_stack([np.minimum(-w / 2, a), np.minimum(0.0, t), -d / 2]),
                         np.column_stack([np.maximum(w / 2, a), np.maximum(0.0, t), d / 2])], axis=1)
    return Prism.bounds_batch(P)


GEOMS = {"Frustum": Frustum, "Ring": Ring, "Sphere": Sphere, "Torus": Torus, "Cuboid": Cuboid,
         "RectRing": RectRing, "Prism": Prism, "TriPrism": TriPrism}


def _random_params(name, M, rng):
    r = rng.random
    if name == "Frustum":
        P = np.column_stack([r(M), r(M), r(M), rng.integers(0, 2, M), rng.integers(0, 2, M)]).astype(float)
        P[r(M) < 0.3, 1] = 0.0  # cones
        eq = r(M) < 0.4
        P[eq, 1] = P[eq, 0]  # cylinders
        return P
    if name == "Ring":
        ro = r(M) + 0.5
        arc = np.where(r(M) < 0.5, TWO_PI, 6.0 * r(M))
        return np.column_stack([ro, ro * r(M), r(M), arc, (r(M) - 0.5) * 0.2 * (r(M) < 0.5)])
    if name == "Sphere":
        R = r(M) + 0.1
        hi = R * (2.0 * r(M) - 1.0)
        return np.column_stack([R, np.minimum(-R * r(M), hi - 0.01), hi])
    if name == "Torus":
        R = r(M) + 0.5
        arc = np.where(r(M) < 0.3, TWO_PI, 6.0 * r(M))
        return np.column_stack([R, 0.3 * R * r(M), arc, rng.integers(0, 2, M), rng.integers(0, 2, M)]).astype(float)
    if name == "Cuboid":
        return r((M, 3))
    if name == "RectRing":
        ox, oy = r(M) + 1.0, r(M) + 1.0
        P = np.column_stack([ox, oy, r(M), ox * r(M), oy * r(M)])
        eq = r(M) < 0.3
        P[eq, 3] = P[eq, 0]  # no side strips: zero-area patches
        return P
    if name == "Prism":
        return np.column_stack([r(M), r(M), rng.integers(3, 17, M)]).astype(float)
    return np.column_stack([r(M), r(M), r(M) - 0.5, r(M)])


def _object_groups(n_seeds=3):
    for c in artipg.categories():
        for s in range(n_seeds):
            for g in artipg.generate(c, s).primitive_table.groups:
                yield g.geom.__name__, g.P


def _param_cases():
    rng = np.random.default_rng(7)
    for name in GEOMS:
        for M in (1, 2, 5, 17):
            for _ in range(6):
                yield name, _random_params(name, M, rng)


# ---------------------------------------------------------------- geometry templates

@pytest.mark.parametrize("name", sorted(GEOMS))
def test_patches_areas_and_boxes_match_the_plain_definitions(name):
    cases = [P for n, P in _param_cases() if n == name] + [P for n, P in _object_groups(2) if n == name]
    assert cases
    geom = GEOMS[name]
    for P in cases:
        got, want = geom.patches(P), _plain_patches(name, P)
        assert len(got) == len(want)
        for g, w in zip(got, want):
            assert g.family == w.family and same(g.comp, w.comp), name
            assert same(g.area, w.area) and same(g.params, w.params), (name, g.family)
        assert same(geom.component_areas(P), _plain_areas(name, P)), name
        assert same(geom.bounds_batch(P), _plain_bounds_batch(name, P)), name
        # and the batch boxes are the one-row boxes
        np.testing.assert_allclose(geom.bounds_batch(P), np.stack([geom.bounds(p) for p in P]),
                                   rtol=1e-12, atol=1e-15)


def test_rect_ring_side_table_is_exact_in_any_summation_order():
    """RectRing areas use a matrix product for the side lengths; it matches the einsum
    definition bit for bit because every side is at most two exact products."""
    nonzero = _RING_SIDES != 0.0
    assert nonzero.sum(axis=0).max() <= 2
    assert set(np.abs(_RING_SIDES[nonzero]).tolist()) <= {0.5, 1.0}
    rng = np.random.default_rng(3)
    for _ in range(200):
        P = _random_params("RectRing", int(rng.integers(1, 40)), rng)
        assert same(RectRing.component_areas(P), _plain_areas("RectRing", P))


def test_block_and_linear_helpers_match_their_plain_versions():
    rng = np.random.default_rng(4)
    M = 6
    a, b = rng.random(M), rng.random((2, M))
    cases = [("rect", (0, 1), b, (a, 0.0, b, 1.0, a, a, b, 0.0, 0.0, -1.0, a, 2.0)),
             ("zone", 0, a, (a, b[0], 3.0))]
    for family, comp, area, cols in cases:
        g, w = block(family, comp, area, *cols), _plain_block(family, comp, area, *cols)
        assert same(g.comp, w.comp) and same(g.area, w.area) and same(g.params, w.params)
    P = rng.random((M, 3))
    area = rng.random((6, M))
    g, w = linear("rect", np.arange(6), P, _BOX_TABLE, area), _plain_linear("rect", np.arange(6), P, _BOX_TABLE, area)
    assert same(g.params, w.params)


# ---------------------------------------------------------------- samplers

def _plain_sampler(family, q, rng):
    """The family samplers as first written: two uniforms per point then the plain
    placement, except for the torus, whose tube angle is drawn by rejection."""
    if family != "torus":
        u, v = rng.random((2, q.shape[1]))
        return _plain_place(family, q, u, v)
    R, r, arc = q
    v = torus_tube_angles(R, r, rng)  # the rejection step is shared; the assembly is under test
    th = rng.random(len(R)) * arc
    cv, sv, ct, st = np.cos(v), np.sin(v), np.cos(th), np.sin(th)
    rho = R + r * cv
    return np.stack([rho * ct, rho * st, r * sv, cv * ct, cv * st, sv])


def _plain_place(family, q, u, v):
    """The family placements from uniforms (the point draw's), written plainly."""
    if family in ("rect", "tri", "sector"):
        if family == "tri":
            flip = u + v > 1.0
            u, v = np.where(flip, 1.0 - u, u), np.where(flip, 1.0 - v, v)
        elif family == "sector":
            r0, r1, arc = q[12], q[13], q[14]
            rho = np.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
            phi = v * arc
            u, v = rho * np.cos(phi), rho * np.sin(phi)
        out = np.empty((6, q.shape[1]))
        out[0:3] = q[0:3] + u * q[3:6] + v * q[6:9]
        out[3:6] = q[9:12]
        return out
    if family == "band":
        r0, r1, z0, z1, arc, nr, nz = q
        rho = np.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
        s = u * (r0 + r1) / (rho + r0 + 1e-300)
        c, d = np.cos(v * arc), np.sin(v * arc)
        return np.stack([rho * c, rho * d, z0 + s * (z1 - z0), nr * c, nr * d, nz])
    if family == "zone":
        R, z0, z1 = q
        z = z0 + u * (z1 - z0)
        rho = np.sqrt(np.maximum(R * R - z * z, 0.0))
        c, d = np.cos(v * TWO_PI), np.sin(v * TWO_PI)
        return np.stack([rho * c, rho * d, z, rho * c / R, rho * d / R, z / R])
    R, r, arc = q
    cv, sv = torus_tube_quantiles(R, r, u)  # tested on its own below; the assembly is under test
    ct, st = np.cos(v * arc), np.sin(v * arc)
    rho = R + r * cv
    return np.stack([rho * ct, rho * st, r * sv, cv * ct, cv * st, sv])


def _family_params(family, k, rng):
    q = rng.random((FAMILIES[family], k)) + 0.1
    if family == "torus":
        q[1] *= 0.3
    if family == "zone":
        q[1], q[2] = -q[0] * rng.random(k), q[0] * rng.random(k)
    return q


@pytest.mark.parametrize("family", list(FAMILIES))
def test_placements_match_the_plain_placements_with_and_without_out(family):
    rng = np.random.default_rng(6)
    for k in (0, 1, 9, 500):
        q = _family_params(family, k, rng)
        u, v = rng.random((2, k))
        if k > 4:  # the ends of [0, 1)
            u[:4] = v[:4] = (0.0, 2.0 ** -53, 0.5, 1.0 - 2.0 ** -53)
        want = _plain_place(family, q, u, v)
        assert same(place_family(family, q, u, v), want)
        big = np.full((6, k + 7), 3.0)
        place_family(family, q, u, v, out=big[:, 4:4 + k])
        assert same(big[:, 4:4 + k], want) and (big[:, :4] == 3.0).all() and (big[:, 4 + k:] == 3.0).all()


@pytest.mark.parametrize("family", list(FAMILIES))
def test_samplers_match_the_plain_samplers_with_and_without_out(family):
    rng = np.random.default_rng(5)
    for k in (0, 1, 9, 500):
        q = _family_params(family, k, rng)
        want = _plain_sampler(family, q, np.random.default_rng(k))
        assert same(sample_family(family, q, np.random.default_rng(k)), want)
        big = np.full((6, k + 7), 3.0)
        sample_family(family, q, np.random.default_rng(k), out=big[:, 4:4 + k])
        assert same(big[:, 4:4 + k], want) and (big[:, :4] == 3.0).all() and (big[:, 4 + k:] == 3.0).all()


# ---------------------------------------------------------------- primitive table and draw

class _PlainTable:
    """The primitive table built one primitive at a time."""

    def __init__(self, obj):
        by_geom, part_poses, prim_poses, prim_part, prim_link, sem = {}, [], [], [], [], []
        for li, link in enumerate(obj.links):
            for part in link.parts:
                pi = len(part_poses)
                part_poses.append(part.pose)
                sem.append(label_id(part.semantic))
                for prim in part.primitives:
                    rows = by_geom.setdefault(prim.geom, ([], []))
                    rows[0].append(prim.params)
                    rows[1].append(len(prim_poses))
                    prim_poses.append(prim.pose)
                    prim_part.append(pi)
                    prim_link.append(li)
        self.prim_part = np.array(prim_part, dtype=np.int64)
        self.prim_link = np.array(prim_link, dtype=np.int64)
        self.prim_T = np.array(part_poses)[self.prim_part] @ np.array(prim_poses)
        self.part_semantic = np.array(sem, dtype=np.int64)
        self.groups = [(geom, np.array(params, dtype=float), np.array(idx, dtype=np.int64))
                       for geom, (params, idx) in by_geom.items()]
        parts = {f: [] for f in FAMILIES}
        for geom, P, k in self.groups:
            for b in geom.patches(P):
                c, p, M = b.params.shape
                parts[b.family].append((b.params.transpose(1, 0, 2).reshape(p, c * M), np.tile(k, c),
                                        b.area.reshape(c * M)))
        self.families, start = [], 0
        for name, blocks in parts.items():
            if not blocks:
                continue
            area = np.concatenate([b[2] for b in blocks])
            keep = area > 0.0
            if not keep.any():
                continue
            params = np.concatenate([b[0] for b in blocks], axis=1)[:, keep]
            prim = np.concatenate([b[1] for b in blocks])[keep]
            self.families.append((name, params, prim, area[keep], start, start + int(keep.sum())))
            start += int(keep.sum())
        self.cell_areas = np.concatenate([f[3] for f in self.families])
        self.cell_prim = np.concatenate([f[2] for f in self.families])
        self.cell_p = self.cell_areas / self.cell_areas.sum()

    def local_boxes(self):
        out = np.empty((len(self.prim_T), 2, 3))
        for geom, P, k in self.groups:
            out[k] = _plain_bounds_batch(geom.__name__, P)
        return out

    def bounds(self, L):
        W = (L[self.prim_link] @ self.prim_T)[:, :3]
        boxes = self.local_boxes()
        c = (boxes[:, 0] + boxes[:, 1]) * 0.5
        h = (boxes[:, 1] - boxes[:, 0]) * 0.5
        R = W[:, :3, :3]
        wc = (R @ c[:, :, None])[:, :, 0] + W[:, :3, 3]
        wh = (np.abs(R) @ h[:, :, None])[:, :, 0]
        b = np.stack([wc - wh, wc + wh], axis=1)
        return np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])


def _plain_draw(obj, plain, n, seed, qpos=None):
    """The point draw written plainly: 3 n uniforms; each point takes the first cell whose
    cumulative area exceeds its first uniform times the total, and is placed with the
    other two: on the posed cell for the planar families, on the local cell and then
    posed for the others."""
    with streams(seed) as st:
        U = st.open(SAMPLING_STREAM).random((3, n))
    L = obj.link_poses(qpos)
    cum = np.cumsum(plain.cell_areas)
    cell = np.searchsorted(cum, U[0] * cum[-1], side="right")
    prim = plain.cell_prim.take(cell)
    G = np.ascontiguousarray((L[plain.prim_link] @ plain.prim_T)[:, :3].reshape(-1, 12).T).take(prim, axis=1)
    pts = np.empty((n, 3))
    nrm = np.empty((n, 3))
    for name, params, fprim, area, start, stop in plain.families:
        sel = np.flatnonzero((cell >= start) & (cell < stop))
        if not len(sel):
            continue
        q = params.take(cell[sel] - start, axis=1)
        g = G[:, sel]
        if name in ("rect", "tri", "sector"):
            q = q.copy()
            for k in range(0, 12, 3):
                x, y, z = q[k:k + 3].copy()
                for i in range(3):
                    r = 4 * i
                    q[k + i] = g[r] * x + g[r + 1] * y + g[r + 2] * z
                    if k == 0:  # o is a point; a, b and n are directions
                        q[k + i] += g[r + 3]
            out = _plain_place(name, q, U[1, sel], U[2, sel])
            pts[sel], nrm[sel] = out[:3].T, out[3:].T
            continue
        x, y, z, nx, ny, nz = _plain_place(name, q, U[1, sel], U[2, sel])
        for i in range(3):
            r = 4 * i
            pts[sel, i] = g[r] * x + g[r + 1] * y + g[r + 2] * z + g[r + 3]
            nrm[sel, i] = g[r] * nx + g[r + 1] * ny + g[r + 2] * nz
    part = plain.prim_part.take(prim)
    return pts, nrm, plain.part_semantic.take(part), part, plain.prim_link.take(prim), prim


CATS = artipg.categories()


@pytest.mark.parametrize("category", CATS)
def test_primitive_table_and_draw_match_the_plain_construction(category):
    for seed in range(2):
        obj = artipg.generate(category, seed)
        table = PrimitiveTable.of(obj)
        plain = _PlainTable(obj)
        assert same(table.prim_T, plain.prim_T) and same(table.prim_link, plain.prim_link)
        assert same(table.prim_part, plain.prim_part) and same(table.part_semantic, plain.part_semantic)
        assert [g.geom for g in table.groups] == [g[0] for g in plain.groups]
        for g, (geom, P, k) in zip(table.groups, plain.groups):
            assert same(g.P, P) and same(g.prim, k) and same(g.T, plain.prim_T[k])
            assert same(g.link, plain.prim_link[k]) and same(g.part, plain.prim_part[k])
        assert same(table.local_boxes, plain.local_boxes())
        for qpos in (None, obj.limits()[:, 1]):
            L = obj.link_poses(qpos)
            assert same(table.bounds(L), plain.bounds(L))
            W = table.world_all(L)
            assert same(table.world_boxes(L), transform_boxes(plain.local_boxes(), W))
        assert len(table.families) == len(plain.families)
        for f, (name, params, prim, area, start, stop) in zip(table.families, plain.families):
            assert (f.name, f.start, f.stop) == (name, start, stop)
            assert same(f.params, params) and same(f.prim, prim) and same(f.area, area)
        assert same(table.cell_p, plain.cell_p) and same(table.cell_prim, plain.cell_prim)
        # the draw, at rest and moved, whole and for some parts
        obj.__dict__["primitive_table"] = table
        for qpos, n in ((None, 2048), (obj.limits()[:, 1], 333)):
            pc = sample_points(obj, n, seed=seed + 11, qpos=qpos)
            want = _plain_draw(obj, plain, n, seed + 11, qpos)
            for got, w in zip((pc.points, pc.normals, pc.semantic, pc.instance, pc.link, pc.primitive), want):
                assert same(got, w)
        # shifting the root moves the root primitives' frames, and the groups follow
        S = np.eye(4)
        S[:3, 3] = (0.25, -0.5, 0.125)
        table.shift_root(S)
        root = plain.prim_link == 0
        plain.prim_T[root] = S @ plain.prim_T[root]
        assert same(table.prim_T, plain.prim_T)
        for g, (geom, P, k) in zip(table.groups, plain.groups):
            assert same(g.T, plain.prim_T[k])


# ---------------------------------------------------------------- the compiled point draw

def _draw_both(args, n):
    from artipg.annotate.draw import draw_kernel

    got = (np.full((2, n, 3), np.nan), np.full((4, n), -7, dtype=np.int64))
    want = (np.full((2, n, 3), np.nan), np.full((4, n), -7, dtype=np.int64))
    draw_kernel(*args, *got)
    draw_plain(*args, *want)
    return got, want


@pytest.mark.parametrize("category", CATS)
def test_draw_kernel_matches_its_numpy_definition(category):
    for seed in range(3):
        obj = artipg.generate(category, seed)
        t = obj.primitive_table
        code, Q = t.cell_rows
        rng = np.random.default_rng(seed)
        for qpos, parts, n in ((None, None, 2048), (obj.limits()[:, 1], None, 999),
                               (None, [len(obj.parts) - 1], 300), (None, [0, len(obj.parts) // 2], 300)):
            weight = t.cell_areas if parts is None else t.part_cell_p(parts)
            U = rng.random((3, n))
            U[:, :3] = [[0.0], [2.0 ** -53], [1.0 - 2.0 ** -53]]
            args = (U, weight, code, Q, t.world_all(obj.link_poses(qpos)), t.cell_prim, t.prim_part,
                    t.prim_link, t.part_semantic)
            (pts, lab), (wpts, wlab) = _draw_both(args, n)
            assert same(pts, wpts) and same(lab, wlab), (category, seed, parts)
            if parts is not None:
                assert np.isin(lab[1], parts).all()


def test_draw_kernel_cell_choice_is_the_searchsorted_one_on_hard_weights():
    """The guide-table scan picks np.searchsorted's cell for weights with zeros, tiny
    and huge cells, and uniforms on bucket edges and cumulative-weight edges."""
    rng = np.random.default_rng(11)
    for K in (1, 2, 3, 7, 64, 1000):
        for trial in range(6 if K < 1000 else 4):
            w = rng.random(K) ** 8
            w[rng.random(K) < 0.3] = 0.0
            if trial == 1:
                w[rng.integers(K)] = 1e6
            if trial == 2:
                w *= 1e-300
            if trial == 3:  # cell ends just above the guide's bucket edges j / K
                w = np.diff(np.arange(K + 1) / K * (1.0 + 2.0 ** -rng.integers(31, 53, K + 1)), prepend=0.0)[1:]
            if w.sum() == 0:
                w[-1] = 1.0
            cum = np.cumsum(w)
            edges = np.arange(K) / K
            for b in range(K):  # and the smallest uniforms of each bucket
                u = edges[b]
                while u > 0.0 and int(np.nextafter(u, 0.0) * K) == b:
                    u = np.nextafter(u, 0.0)
                edges[b] = u
            U0 = np.concatenate([edges, np.nextafter(edges, 0.0), np.nextafter(edges, 1.0), cum / cum[-1],
                                 np.nextafter(cum / cum[-1], 0.0), rng.random(500), [0.0, 1.0 - 2.0 ** -53]])
            U0 = U0[(U0 >= 0.0) & (U0 < 1.0)]
            n = len(U0)
            U = np.vstack([U0, rng.random((2, n))])
            code = np.zeros(K, dtype=np.int64)  # all rects
            Q = rng.random((K, 15))
            W = np.tile(np.eye(4)[:3], (K, 1, 1))
            ids = np.arange(K, dtype=np.int64)
            (pts, lab), (wpts, wlab) = _draw_both((U, w, code, Q, W, ids, ids, ids, ids), n)
            cell = np.searchsorted(cum, U0 * cum[-1], side="right")
            assert same(lab[0], cell) and same(wlab[0], cell) and same(pts, wpts)
            assert (w[cell] > 0).all()


def _all_families_case(rng, K):
    """K cells of every family with random parameters and poses."""
    code = rng.integers(0, len(FAMILIES), K)
    Q = np.zeros((K, 15))
    for name, f in FAMILY_CODE.items():
        sel = np.flatnonzero(code == f)
        Q[sel, :FAMILIES[name]] = _family_params(name, len(sel), rng).T
    W = np.empty((K, 3, 4))
    for i in range(K):
        A = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        W[i] = np.column_stack([A, rng.normal(size=3)])
    ids = np.arange(K, dtype=np.int64)
    return rng.random(K) + 0.01, code, Q, W, ids


def test_draw_kernel_matches_its_numpy_definition_on_every_family():
    rng = np.random.default_rng(12)
    for K, n in ((1, 50), (6, 3000), (40, 5000)):
        w, code, Q, W, ids = _all_families_case(rng, K)
        U = rng.random((3, n))
        U[1:, :4] = [[0.0, 2.0 ** -53, 0.5, 1.0 - 2.0 ** -53]] * 2
        (pts, lab), (wpts, wlab) = _draw_both((U, w, code, Q, W, ids, ids, ids, ids), n)
        assert same(pts, wpts) and same(lab, wlab)


# ---------------------------------------------------------------- the uniforms drawn in the kernel

def _numpy_doubles(words, n):
    lo, hi, inc_lo, inc_hi = (int(w) for w in words)
    bitgen = np.random.PCG64(0)
    bitgen.state = {"bit_generator": "PCG64", "state": {"state": hi << 64 | lo, "inc": inc_hi << 64 | inc_lo},
                    "has_uint32": 0, "uinteger": 0}
    return bitgen, np.random.Generator(bitgen).random(n)


def test_compiled_pcg64_draws_numpys_doubles_and_jumps():
    from artipg.annotate.draw import PCG64_MATCHES, pcg64_advance, pcg_fill, stream_words

    assert PCG64_MATCHES
    rng = np.random.default_rng(15)
    top = np.uint64(2 ** 64 - 1)
    cases = [stream_words(s, SAMPLING_STREAM) for s in (0, 1, 2 ** 70 + 3)]
    cases += [np.array([0, 0, 1, 0], dtype=np.uint64), np.array([top, top, top, top], dtype=np.uint64)]
    cases += [rng.integers(0, 2 ** 64, 4, dtype=np.uint64) | np.array([0, 0, 1, 0], dtype=np.uint64) for _ in range(6)]
    for words in cases:
        bitgen, want = _numpy_doubles(words, 5000)
        got = np.empty(5000)
        pcg_fill(words, got)
        assert same(got, want)
        state = int(words[1]) << 64 | int(words[0])
        for n in (0, 1, 2, 2047, 2048, 6144, 2 ** 40 + 5, 2 ** 62 + 2 ** 61 + 9):
            bitgen.state = {"bit_generator": "PCG64", "state": {"state": state, "inc": bitgen.state["state"]["inc"]},
                            "has_uint32": 0, "uinteger": 0}
            bitgen.advance(n)
            lo, hi = pcg64_advance(words[0], words[1], words[2], words[3], n)
            assert int(hi) << 64 | int(lo) == bitgen.state["state"]["state"], n


def test_stream_words_are_the_sampling_streams_state():
    from artipg.annotate.draw import pcg_fill, stream_words

    for seed in (0, 5, 123456789, 2 ** 100 + 7):
        words = stream_words(seed, SAMPLING_STREAM)
        with streams(seed) as st:
            want = st.open(SAMPLING_STREAM).random(999)
        got = np.empty(999)
        pcg_fill(words, got)
        assert same(got, want)


@pytest.mark.parametrize("category", CATS)
def test_draw_stream_is_draw_kernel_of_numpys_uniforms(category):
    from artipg.annotate.draw import draw_kernel, draw_stream, stream_words

    for seed in range(2):
        obj = artipg.generate(category, seed)
        t = obj.primitive_table
        code, Q = t.cell_rows
        for qpos, parts, n in ((None, None, 2048), (obj.limits()[:, 1], None, 999), (None, [0], 1), (None, None, 0)):
            weight = t.cell_areas if parts is None else t.part_cell_p(parts)
            with streams(seed + 3) as st:
                U = st.open(SAMPLING_STREAM).random((3, n))
            args = (weight, code, Q, t.world_all(obj.link_poses(qpos)), t.cell_prim, t.prim_part, t.prim_link,
                    t.part_semantic)
            got = (np.full((2, n, 3), np.nan), np.full((4, n), -7, dtype=np.int64))
            want = (np.full((2, n, 3), np.nan), np.full((4, n), -7, dtype=np.int64))
            draw_stream(stream_words(seed + 3, SAMPLING_STREAM), *args, *got)
            draw_kernel(U, *args, *want)
            assert same(got[0], want[0]) and same(got[1], want[1]), (category, seed, n)


def test_sample_points_is_the_same_with_numpys_uniforms(monkeypatch):
    from artipg.annotate import draw

    obj = artipg.generate("oven", 4)
    fields = ("points", "normals", "semantic", "instance", "link", "primitive", "instance_names", "link_names")
    fast = [getattr(sample_points(obj, 700, seed=9, parts=[0]), f) for f in fields]
    monkeypatch.setattr(draw, "PCG64_MATCHES", False)
    plain = [getattr(sample_points(obj, 700, seed=9, parts=[0]), f) for f in fields]
    for a, b in zip(fast, plain):
        assert (a == b) if isinstance(a, tuple) else same(a, b)


@pytest.mark.parametrize("category", CATS)
def test_sample_points_with_the_cells_made_in_the_draw_or_kept(category):
    """A fresh object's draw makes its cells in the kernel (draw_table, not kept); once
    the table holds them, the draw reads them (draw_stream): the same clouds, and those
    of draw_kernel on numpy's uniforms."""
    from artipg.annotate.draw import draw_kernel

    fields = ("points", "normals", "semantic", "instance", "link", "primitive")
    for seed in range(2):
        for qpos in (None, "open"):
            fresh, kept = artipg.generate(category, seed), artipg.generate(category, seed)
            q = None if qpos is None else fresh.limits()[:, 1]
            a = sample_points(fresh, 777, seed=seed + 5, qpos=q)
            assert "_cells" not in fresh.primitive_table.__dict__
            t = kept.primitive_table
            code, Q = t.cell_rows
            b = sample_points(kept, 777, seed=seed + 5, qpos=q)
            with streams(seed + 5) as st:
                U = st.open(SAMPLING_STREAM).random((3, 777))
            want = (np.empty((2, 777, 3)), np.empty((4, 777), dtype=np.int64))
            draw_kernel(U, t.cell_areas, code, Q, t.world_all(kept.link_poses(q)), t.cell_prim, t.prim_part,
                        t.prim_link, t.part_semantic, *want)
            for f in fields:
                assert same(getattr(a, f), getattr(b, f)), (category, seed, f)
            assert same(a.points, want[0][0]) and same(a.normals, want[0][1])
            assert same(np.stack([a.primitive, a.instance, a.semantic, a.link]), want[1])
            assert (a.instance_names, a.link_names) == (b.instance_names, b.link_names)


def test_sample_points_refuses_an_object_without_surface():
    from artipg.geometry import cuboid_between
    from artipg.model.builder import ObjectBuilder
    from artipg.model.part import Part

    b = ObjectBuilder()
    b.create_link("base").add(Part("body", "box", [cuboid_between((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))]))
    for cached in (False, True):
        obj = b.build("test", "a", 0, normalize=False)
        if cached:
            obj.primitive_table._cells
        with pytest.raises(ValueError, match="no surface"):
            sample_points(obj, 10)


# ---------------------------------------------------------------- the torus's tube angles

def _tube_cases(rng, n=4000):
    """(R, r, u) over the whole range of r / R, with the ends of [0, 1) for u."""
    R = rng.random(n) + 0.5
    e = np.concatenate([np.zeros(8), 10.0 ** rng.uniform(-16, -1, n // 4), rng.random(n - n // 4 - 16),
                        1.0 - 10.0 ** rng.uniform(-9, -2, 6), [1.0, 1.0]])
    u = rng.random(n)
    u[:8] = (0.0, 2.0 ** -53, 0.25, 0.5, 0.75, 1.0 - 2.0 ** -53, 1e-300, np.nextafter(0.5, 0.0))
    u[-8:] = u[:8]
    return R, e * R, u


def test_tube_kernel_matches_the_numpy_quantiles():
    import numba

    from artipg.annotate.draw import tube_cos_sin

    @numba.njit
    def all_of(R, r, u, cv, sv):
        for i in range(len(u)):
            cv[i], sv[i] = tube_cos_sin(r[i] / R[i], u[i] * TWO_PI)

    rng = np.random.default_rng(13)
    for _ in range(3):
        R, r, u = _tube_cases(rng)
        cv, sv = np.empty(len(u)), np.empty(len(u))
        all_of(R, r, u, cv, sv)
        want = torus_tube_quantiles(R, r, u)
        assert same(cv, want[0]) and same(sv, want[1])


def test_tube_quantiles_solve_the_cdf_to_machine_precision():
    """cos v and sin v are unit, and v solves (v + e sin v) / (2π) = u to rounding."""
    rng = np.random.default_rng(14)
    R, r, u = _tube_cases(rng, 20000)
    keep = r < 0.9 * R  # conditioning: dv = dM / (1 + e cos v)
    R, r, u = R[keep], r[keep], u[keep]
    cv, sv = torus_tube_quantiles(R, r, u)
    assert np.abs(cv * cv + sv * sv - 1.0).max() < 1e-15
    v = np.arctan2(sv, cv) % TWO_PI
    v[(u < 0.25) & (v > np.pi)] -= TWO_PI  # v = 2π - tiny for u = 0 rounds to 0
    e = r / R
    residual = (v + e * np.sin(v)) - TWO_PI * u
    assert np.abs(residual).max() < 8 * np.spacing(TWO_PI)
    # a = 0: v = 2π u exactly, so cos and sin are numpy's
    R0, u0 = np.ones(50), rng.random(50)
    cv0, sv0 = torus_tube_quantiles(R0, np.zeros(50), u0)
    assert same(cv0, np.cos(u0 * TWO_PI)) and same(sv0, np.sin(u0 * TWO_PI))


@pytest.mark.parametrize("e", [0.05, 0.3, 0.67, 0.95])
def test_torus_points_follow_the_area_law(e):
    """Tube angles of drawn torus points (from their positions, through the compiled
    draw) against the exact law (v + e sin v) / (2π): Kolmogorov-Smirnov and
    chi-square, and against the rejection sampler (two-sample KS)."""
    from scipy import stats

    n = 200_000
    R, r, arc = 1.0, e, 4.0
    K = 3
    Q = np.zeros((K, 15))
    Q[:, :3] = (R, r, arc)
    W = np.tile(np.eye(4)[:3], (K, 1, 1))
    ids = np.arange(K, dtype=np.int64)
    U = np.random.default_rng(int(e * 1000)).random((3, n))
    torus = np.full(K, FAMILY_CODE["torus"])
    (pts, lab), (wpts, wlab) = _draw_both((U, np.ones(K), torus, Q, W, ids, ids, ids, ids), n)
    assert same(pts, wpts)
    x, y, z = pts[0].T
    v = np.arctan2(z, np.hypot(x, y) - R) % TWO_PI
    cdf = lambda t: (t + e * np.sin(t)) / TWO_PI  # noqa: E731
    assert stats.kstest(v, cdf).pvalue > 1e-3
    edges = np.linspace(0.0, TWO_PI, 41)
    expected = np.diff(cdf(edges)) * n
    assert stats.chisquare(np.histogram(v, edges)[0], expected).pvalue > 1e-3
    ref = torus_tube_angles(np.full(n, R), np.full(n, r), np.random.default_rng(5))
    assert stats.ks_2samp(v, ref).pvalue > 1e-3
    # the arc angle is uniform on [0, arc], the normals unit and radial from the tube centre
    th = np.arctan2(y, x) % TWO_PI
    assert stats.kstest(th / arc, "uniform").pvalue > 1e-3
    centre = np.stack([R * np.cos(th), R * np.sin(th), np.zeros(n)], axis=1)
    np.testing.assert_allclose(pts[1], (pts[0] - centre) / r, atol=1e-9)
