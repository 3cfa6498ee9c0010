"""The compiled (numba) kernels of the geometric checks equal the numpy code they
replace, bit for bit.

Every kernel is compared with the numpy path it stands in for
(``artipg.validate.compiled.ENABLED = False``): the sample draw (with and without
the templates' patches written out), the pieces' arrays, the SDF tables, the scenes
(poses, boxes, pairs, frames, distances), the pair distance on perturbed poses and
margins, the refinement, the contact graphs, the re-check of blocked joints and the
whole reports. Arrays are compared by their bytes (signed zeros included).
"""

from __future__ import annotations

import numpy as np
import pytest

import artipg
from artipg.geometry.box import Cuboid
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus
from artipg.validate import Tolerances, check_object, compiled
from artipg.validate.api import _SAMPLE_SEED
from artipg.validate.checks import _OVERLAP, _scenes, refine_rest
from artipg.validate.contacts import close_pairs, pair_distance, refine_distance, world_boxes
from artipg.validate.kinematics import Kinematics, rotations
from artipg.validate.shapes import Pieces, _sample_group
from artipg.validate.streams import UniformStream
from conftest import CATEGORIES

SEEDS = (0, 1)
TWO_PI = 2 * np.pi

jit_base = pytest.importorskip("artipg.validate.jit_base")


def _bytes(*arrays) -> bytes:
    return b"".join(np.ascontiguousarray(a).tobytes() + str(np.asarray(a).dtype).encode() for a in arrays)


def _variants(category: str, seed: int):
    """The generated object, its parameters pushed to the ends of their ranges, and a
    broken copy (a link moved by 12 mm, a hinge flipped)."""
    rule = artipg.get_category(category)
    obj = rule.generate(seed)
    rng = np.random.default_rng(seed)
    ends = {k: (p.lo if rng.random() < 0.5 else p.hi) for k, p in obj.params.items() if p.kind == "uniform"}
    broken = rule.generate(seed)
    if len(broken.links) > 1:
        k = 1 + int(rng.integers(len(broken.links) - 1))
        d = rng.normal(size=3)
        d *= 0.012 / np.linalg.norm(d)
        for part in broken.links[k].parts:
            part.pose = part.pose.copy()
            part.pose[:3, 3] += d
        hinges = [j for j in broken.joints if j.type == "revolute"]
        if hinges:
            j = hinges[int(rng.integers(len(hinges)))]
            j.axis = -j.axis
        broken.__dict__.pop("primitive_table", None)
    return obj, rule.generate(seed, overrides=ends), broken


@pytest.fixture
def numpy_path(monkeypatch):
    """Run a callable with the kernels off: ``numpy_path(f)``."""
    def run(f):
        before = compiled.ENABLED
        monkeypatch.setattr(compiled, "ENABLED", False)
        try:
            return f()
        finally:
            monkeypatch.setattr(compiled, "ENABLED", before)

    return run


def test_the_kernels_probe_this_machine():
    """Matrix products, einsum orders and the math library as the kernels assume;
    where not, the checks run numpy (the comparisons below then compare numpy)."""
    if not jit_base.kernels_match():
        pytest.skip("numpy's BLAS / einsum / libm differ from the kernels' here: numpy path")


# ---------------------------------------------------------------- samples

def _random_params(geom, m, rng):
    u = lambda lo, hi: rng.uniform(lo, hi, m)  # noqa: E731
    flags = lambda: rng.integers(0, 2, m).astype(float)  # noqa: E731
    if geom is Cuboid:
        return np.column_stack([u(0.001, 0.6), u(0.001, 0.6), u(0.001, 0.6)])
    if geom is Frustum:
        r1 = np.where(rng.random(m) < 0.2, 0.0, u(0.002, 0.2))
        return np.column_stack([u(0.002, 0.2), r1, u(0.001, 0.4), flags(), flags()])
    if geom is Ring:
        ro = u(0.01, 0.3)
        arc = np.where(rng.random(m) < 0.5, TWO_PI, u(0.3, 6.0))
        return np.column_stack([ro, ro * u(0.5, 0.98), u(0.005, 0.4), arc,
                                np.where(rng.random(m) < 0.5, 0.0, u(-0.05, 0.05))])
    if geom is Sphere:
        R = u(0.005, 0.2)
        lo = np.where(rng.random(m) < 0.5, -R, -R * u(-0.5, 1.0))
        hi = np.where(rng.random(m) < 0.5, R, R * u(0.5, 1.0))
        return np.column_stack([R, lo, np.maximum(hi, lo + 1e-3)])
    R = u(0.02, 0.2)
    return np.column_stack([R, R * u(0.05, 0.5), np.where(rng.random(m) < 0.4, TWO_PI, u(0.3, 6.0)), flags(), flags()])


@pytest.mark.parametrize("geom", [Cuboid, Frustum, Ring, Sphere, Torus])
def test_compiled_template_draws_equal_the_numpy_draw(geom):
    """Random pieces (partial rings and tori with and without end caps, cones, cut
    spheres), all pieces or some wanted: the same points and counts as
    ``_sample_group`` with the templates' own areas and patches."""
    from artipg.validate.jit_samples import draw_group, draw_template

    rng = np.random.default_rng(11)
    for trial in range(60):
        m = int(rng.integers(1, 9))
        P = _random_params(geom, m, rng)
        for want in (None, rng.random(m) < 0.5):
            ref, cnt = _sample_group(geom, P, UniformStream(77, trial % 5), want)
            for draw in (draw_template, draw_group):
                got = draw(geom, P, 77, trial % 5, want)
                assert got is not None
                assert got[0].tobytes() == np.ascontiguousarray(ref.T).tobytes()
                assert np.array_equal(got[1], cnt)


#: The rows of each patch family's parameters that place its points (not its normals).
_POSITION_ROWS = {"rect": list(range(9)), "sector": list(range(9)) + [12, 13, 14], "band": list(range(5)),
                  "zone": [0, 1, 2], "torus": [0, 1, 2]}


@pytest.mark.parametrize("geom", [Cuboid, Frustum, Ring, Sphere, Torus])
def test_compiled_component_areas_and_patches_are_the_templates_own(geom):
    """Every component's area and patch parameters (random pieces; real ones below)."""
    from artipg.validate.jit_samples import _BLOCK, TEMPLATE_CODES, template_areas, template_patch

    rng = np.random.default_rng(12)
    code = TEMPLATE_CODES[geom]
    for trial in range(20):
        P = _random_params(geom, int(rng.integers(1, 12)), rng)
        if trial == 0 and geom in (Ring, Torus):
            P[:, 2 + (geom is Ring)] = 0.5  # every arc partial: all blocks present
        area = geom.component_areas(P)
        assert template_areas(geom, P).tobytes() == np.ascontiguousarray(area).tobytes()
        blocks = geom.patches(P)
        for c in range(area.shape[1]):
            b = _BLOCK[code, c]
            if b >= len(blocks):
                continue  # a block the template leaves out when no row has it
            local = list(blocks[b].comp).index(c)
            rows = _POSITION_ROWS[blocks[b].family]  # the normals are not drawn
            ref = blocks[b].params[local][rows]  # (rows, M)
            got = template_patch(geom, P, c)[:, rows]
            assert got.tobytes() == np.ascontiguousarray(ref.T).tobytes()


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_sample_draws_of_every_template_equal_the_numpy_draw(category):
    """Every template of real objects (prisms too, through the generic kernel), and
    the pieces' samples after several partial requests."""
    from artipg.validate.jit_samples import _draw, draw_template, TEMPLATE_CODES
    from artipg.validate.shapes import _BOX_FEATURES, DENSITY, MAX_PER_COMPONENT, MIN_PER_COMPONENT, _layout
    from artipg.validate.streams import _buffer

    for seed in SEEDS:
        obj = artipg.get_category(category).generate(seed)
        pieces = Pieces.of(obj, 4242 + seed)
        rng = np.random.default_rng(seed)
        for k, g in enumerate(pieces._kinds):
            P = pieces.params[pieces._kind == k][:, :pieces._nparams[k]]
            for want in (None, rng.random(len(P)) < 0.5):
                ref, cnt = _sample_group(g, P, UniformStream(pieces._seed, k), want)
                ref = np.ascontiguousarray(ref.T).tobytes()
                if g in TEMPLATE_CODES:
                    got = draw_template(g, P, pieces._seed, k, want)
                    assert got[0].tobytes() == ref and np.array_equal(got[1], cnt)
                # the generic kernel, from the templates' numpy patches
                area = g.component_areas(P)
                blocks = g.patches(P[(area > 0).any(axis=1)])
                lay = _layout(blocks, area.shape[1])
                direct = lay.one_per_comp and (lay.complete or (lay.patch[(area > 0).any(axis=0)] >= 0).all())
                w = np.ones(len(P), dtype=bool) if want is None else want
                out, per, short = _draw(area, P, w, lay.meta, np.concatenate([b.params.ravel() for b in blocks]),
                                        np.concatenate([np.ravel(b.area) for b in blocks]),
                                        _buffer(pieces._seed, k, 1 << 17), bool(direct), g is Cuboid, DENSITY,
                                        MIN_PER_COMPONENT, MAX_PER_COMPONENT, _BOX_FEATURES)
                assert not short and out.tobytes() == ref and np.array_equal(per, cnt)


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_requests_give_every_piece_the_numpy_samples(category, numpy_path):
    for seed in SEEDS:
        obj = artipg.get_category(category).generate(seed)

        def samples():
            p = Pieces.of(obj, 4242 + seed)
            rng = np.random.default_rng(seed)
            for _ in range(3):
                p.require(rng.choice(p.n, size=max(1, p.n // 3)))
            return [p.samples(i).tobytes() for i in range(p.n)]

        assert samples() == numpy_path(samples)


# ---------------------------------------------------------------- pieces and tables

def test_compiled_piece_flags_equal_the_numpy_ones():
    """The pieces' flags from the kernel (jit_pieces._flags) equal Pieces._flags on
    every template at and around its thresholds: whole and cut spheres, full and
    partial rings and tori (arcs at 2 pi - 1e-9 and just below), frusta, boxes."""
    from artipg.validate.jit_pieces import _flags
    from artipg.validate.shapes import _CODES

    rng = np.random.default_rng(3)
    geoms, rows = [], []
    for _ in range(40):
        R = rng.uniform(0.01, 0.1)
        cut = rng.choice([0.0, 0.3 * R, 1e-12])
        geoms.append(Sphere)
        rows.append([R, -R + rng.choice([0.0, cut]), R - rng.choice([0.0, cut]), 0.0, 0.0])
        arc = rng.choice([TWO_PI, TWO_PI - 1e-9, TWO_PI - 2e-9, 1.0])
        geoms += [Ring, Torus, Frustum, Cuboid]
        rows += [[0.1, 0.08, 0.2, arc, 0.0], [0.1, 0.02, arc, 1.0, 1.0], [0.1, 0.05, 0.2, 1.0, 0.0],
                 [0.1, 0.2, 0.3, 0.0, 0.0]]
    M = len(geoms)
    b = np.tile([[-0.1, -0.1, -0.1], [0.1, 0.1, 0.1]], (M, 1, 1))
    p = Pieces(np.zeros(M, dtype=np.int64), np.arange(M), np.tile(np.eye(4), (M, 1, 1)), (b[:, 0] + b[:, 1]) / 2,
               (b[:, 1] - b[:, 0]) / 2, geoms, np.array(rows), [str(i) for i in range(M)], np.zeros(M, dtype=np.int64),
               0)
    flags = _flags(p.params, p._kind, np.array([_CODES[g] for g in p._kinds], dtype=np.int64))
    assert p.is_ball.any() and not p.is_ball.all() and p.symmetric.any() and not p.symmetric.all()
    assert _bytes(*flags) == _bytes(p._code, p.is_box, p.is_ball, p.symmetric)


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_pieces_and_tables_equal_the_numpy_ones(category, numpy_path):
    """Pieces.of (rectangular rings as four boxes) and the SDF tables, with sines
    from the kernel and from numpy, and as Pieces.of computes them with the arrays;
    the tables' radial extents are Pieces.radial."""
    import artipg.validate.jit_contacts as jc

    def arrays(p):
        return _bytes(p.link, p.part, p.T, p.center, p.half, p.params, p._kind, p._code, p.is_box, p.is_ball,
                      p.symmetric)

    for seed in SEEDS:
        for obj in _variants(category, seed):
            p = Pieces.of(obj, 7)
            assert arrays(p) == numpy_path(lambda: arrays(Pieces.of(obj, 7)))
            assert p._kinds == numpy_path(lambda: Pieces.of(obj, 7)._kinds)
            table = jc.piece_table(p)
            assert _bytes(*p._sdf_table) == _bytes(*table)  # Pieces.of's, from the pieces' kernel
            saved = list(jit_base._MATCH)
            jit_base._MATCH[:] = [False]  # numpy's sines
            try:
                assert _bytes(*table) == _bytes(*jc.piece_table(p))
            finally:
                jit_base._MATCH[:] = saved
            assert table[2].tobytes() == p.radial.tobytes()


def test_kinematics_of_equals_a_link_by_link_construction():
    for category in CATEGORIES:
        obj = artipg.get_category(category).generate(3)
        kin = Kinematics.of(obj)
        L = len(obj.links)
        origin, axis, limits = np.tile(np.eye(4), (L, 1, 1)), np.zeros((L, 3)), np.zeros((L, 2))
        parent = np.full(L, -1, dtype=np.int64)
        for i, link in enumerate(obj.links[1:], start=1):
            parent[i] = obj.link_index[link.joint.parent]
            origin[i], axis[i], limits[i] = link.joint.origin, link.joint.axis, link.joint.limits
        assert _bytes(kin.parent, kin.origin, kin.axis, kin.limits) == _bytes(parent, origin, axis, limits)
        # the type codes and movable joints Kinematics.of fills in: the properties'
        plain = Kinematics(kin.names, kin.parent, kin.joint_names, kin.joint_types, kin.origin, kin.axis, kin.limits)
        assert _bytes(kin.type_codes, kin.movable()) == _bytes(plain.type_codes, plain.movable())


# ---------------------------------------------------------------- scenes and distances

def _scene_bytes(W0, c0, h0, scenes):
    out = [_bytes(W0, c0, h0)]
    for s in scenes:
        for k in sorted(s):
            v = s[k]
            out.append(k.encode() + (_bytes(v) if isinstance(v, np.ndarray) else repr(v).encode()))
    return b"".join(out)


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_scenes_equal_the_numpy_scenes(category, numpy_path):
    """Rest, sweep and open scenes (poses, boxes, pairs, frames and distances) of
    generated, stressed and broken objects, under two sets of tolerances."""
    from artipg.validate.jit_scenes import scenes

    for seed in SEEDS:
        for obj in _variants(category, seed):
            kin = Kinematics.of(obj)
            for tol in (Tolerances(), Tolerances(sweep_poses=5, floating=0.01, open_fractions=(0.5, 1.0))):
                got = _scene_bytes(*scenes(kin, Pieces.of(obj, _SAMPLE_SEED), tol, _OVERLAP))
                assert got == numpy_path(lambda: _scene_bytes(*_scenes(kin, Pieces.of(obj, _SAMPLE_SEED), tol)))


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_poses_motions_and_moved_boxes_equal_numpy(category):
    """Link poses (rest, all open, random joint values, batched), piece frames and
    boxes, the sweeps' rigid motions and the boxes of the moved pieces."""
    from artipg.validate.checks import _moved_boxes, _world_motions
    from artipg.validate.jit_pairs import moved_boxes, world_motions
    from artipg.validate.jit_scenes import _posed, _poses, descendants, poses_batch

    rng = np.random.default_rng(4)
    for obj in _variants(category, 1):
        kin, p = Kinematics.of(obj), Pieces.of(obj, _SAMPLE_SEED)
        L, mv = kin.n_links, kin.movable()
        assert descendants(kin.parent).tobytes() == kin.descendants.tobytes()
        Q = np.zeros((4, L))
        Q[1, mv] = [v for v in kin.open_values(1.0).values()]
        Q[2:, mv] = rng.normal(size=(2, len(mv)))
        for q in Q:
            ref = kin.poses(dict(zip(kin.joint_names, q)))
            assert _poses(kin.parent, kin.origin, kin.type_codes, kin.axis, q).tobytes() == ref.tobytes()
            W = ref[p.link] @ p.T
            assert _bytes(*_posed(ref, p.link, p.T, p.center, p.half)) == _bytes(W, *world_boxes(p, W))
        Qb = rng.normal(size=(5, L)) * (rng.random((5, L)) < 0.7)
        assert (poses_batch(kin.parent, kin.origin, kin.type_codes, kin.axis, Qb).tobytes()
                == kin.poses_batch(Qb).tobytes())
        if not len(mv):
            continue
        rest = kin.poses()
        axes = kin.world_axes(rest)
        joint, q = kin.sweep_table(16)
        ref = _world_motions(kin, axes, joint, q)
        qq = np.where(kin.slides[joint], 0.0, q)
        GR, Gt = world_motions(joint, q, np.cos(qq), np.sin(qq), kin.slides, axes[0], axes[1])
        assert _bytes(GR, Gt) == _bytes(*ref)
        W0 = rest[p.link] @ p.T
        c0, h0 = world_boxes(p, W0)
        s_idx, p_idx = rng.integers(0, len(joint), 200), rng.integers(0, p.n, 200)
        assert (_bytes(*moved_boxes(GR, Gt, W0, c0, p.half, s_idx, p_idx))
                == _bytes(*_moved_boxes(GR[s_idx], Gt[s_idx], W0[p_idx], c0[p_idx], p.half[p_idx])))


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_pair_distances_and_refinement_equal_numpy(category, numpy_path):
    """All pairs within 5 cm, at rest and with one piece turned and shifted (the
    separating-axis test, edge distances, culled samples), several margins; the
    refinement of the pairs that are not both boxes."""
    obj = artipg.get_category(category).generate(1)
    kin = Kinematics.of(obj)

    def run():
        p = Pieces.of(obj, _SAMPLE_SEED)
        W0 = kin.poses()[p.link] @ p.T
        c, h = world_boxes(p, W0)
        a, b = close_pairs(c, h, 0.05)
        rng = np.random.default_rng(5)
        Wb = W0[b].copy()
        ax = rng.normal(size=(len(b), 3))
        ax /= np.linalg.norm(ax, axis=1, keepdims=True)
        Wb[:, :3, :3] = rotations(ax, rng.normal(size=len(b)) * 0.2) @ Wb[:, :3, :3]
        Wb[:, :3, 3] += rng.normal(size=(len(b), 3)) * 0.01
        out = []
        for margin in (0.0, 2e-3, 0.05, np.inf, rng.choice([0.0, 1e-3, 0.02, np.inf], size=len(a))):
            out += [pair_distance(p, a, b, W0[a], W0[b], margin), pair_distance(p, a, b, W0[a], Wb, margin)]
        round_ = ~(p.is_box[a] & p.is_box[b])
        ra, rb = a[round_], b[round_]
        out += [refine_distance(p, ra, rb, W0[ra], W0[rb]), refine_distance(p, ra, rb, W0[ra], Wb[round_], iters=3,
                                                                              stop_below=2e-3)]
        return _bytes(*out)

    assert run() == numpy_path(run)


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_contact_graphs_equal_numpy(category):
    from artipg.validate.checks import _contact_graphs
    from artipg.validate.jit_scenes import contact_graphs

    for seed in SEEDS:
        for obj in _variants(category, seed):
            kin, p = Kinematics.of(obj), Pieces.of(obj, _SAMPLE_SEED)
            W0, c0, h0, scenes = _scenes(kin, p, Tolerances())
            s = scenes[0]
            L, P = kin.n_links, len(p.part_names)
            for floating in (2e-3, 0.0, 0.02):
                tol = Tolerances(floating=floating)
                ref = _contact_graphs(L, P, p, s["a"], s["b"], s["d"], tol)
                got = contact_graphs(L, P, p.link, p.part, p.part_link, s["a"], s["b"], s["d"], floating)
                assert _bytes(*got[:6]) == _bytes(*ref[:6]) and bool(got[6]) == bool(ref[6])


def _numpy_verdicts(pieces, W0, c0, h0, scenes, tol):
    """run_checks' numpy steps after the scenes: the refined rest rows, then each
    scene's colliding rows and lowest distance (inf: none; rest: different links)."""
    amb = refine_rest(pieces, W0, c0, h0, scenes[0], tol)
    out = []
    for i, s in enumerate(scenes):
        D = s["d"]
        use = pieces.link[s["a"]] != pieces.link[s["b"]] if i == 0 else np.ones(len(D), dtype=bool)
        out.append(((use & (D < -tol.penetration)).nonzero()[0], float(D[use].min()) if use.any() else np.inf))
    return amb, out


@pytest.mark.parametrize("category", CATEGORIES)
def test_compiled_verdicts_equal_numpy(category):
    """jit_verdicts: the rest rows refined (and whether their pieces lack samples),
    the refined distances, every scene's colliding rows and lowest distance and the
    contact graphs equal run_checks' numpy steps, under several tolerances, on
    generated, stressed and broken objects."""
    from artipg.validate.checks import _contact_graphs
    from artipg.validate.jit_contacts import _H, _OFFS, _ON_SURFACE
    from artipg.validate.jit_scenes import measure
    from artipg.validate.jit_verdicts import verdicts

    for seed in SEEDS:
        for obj in _variants(category, seed):
            kin = Kinematics.of(obj)
            for tol in (Tolerances(), Tolerances(penetration=2e-4, floating=5e-3, open_fractions=(0.5, 1.0)),
                        Tolerances(penetration=0.0, floating=0.03)):
                p = Pieces.of(obj, _SAMPLE_SEED)
                W0, c0, h0, scenes, (a, b, d, sizes, amb, undrawn) = measure(kin, p, tol, _OVERLAP)
                assert bool(undrawn) == (not p._drawn[np.concatenate([a[amb], b[amb]])].all())
                ref_d = [{**s, "d": s["d"].copy()} for s in scenes]
                ref_amb, ref = _numpy_verdicts(p, W0, c0, h0, ref_d, tol)
                assert amb.tobytes() == ref_amb.tobytes()
                if undrawn:
                    p.require(np.concatenate([a[amb], b[amb]]))
                code, aux, _ = p.jit_table
                L, P = kin.n_links, len(p.part_names)
                bad, n_bad, low, comp, pcomp, has_geom, has_piece, several, split = verdicts(
                    amb, a, b, W0, d, sizes, 3, 3, p.params, code, aux, p.points_t, p.start, p.count, _H,
                    _ON_SURFACE, _OFFS, p.link, p.part, p.part_link, L, P, float(tol.floating),
                    float(tol.penetration))
                assert d.tobytes() == np.concatenate([s["d"] for s in ref_d]).tobytes()
                assert _bytes(bad, n_bad) == _bytes(np.concatenate([r[0] for r in ref]), [len(r[0]) for r in ref])
                # the sign of a zero may differ (numpy's min picks either): both give the
                # same worst depth, max(0.0, -low)
                assert (low + 0.0).tobytes() == (np.array([r[1] for r in ref]) + 0.0).tobytes()  # -0.0 + 0.0: 0.0
                rest = ref_d[0]
                g = _contact_graphs(L, P, p, rest["a"], rest["b"], rest["d"], tol)
                assert _bytes(comp, pcomp, has_geom, has_piece, split) == _bytes(*g[:4], (g[5] > g[4]).nonzero()[0])
                assert bool(several) == bool(g[6])


def test_compiled_verdicts_lowest_distances_as_numpy_min():
    """The lowest distance of a scene keeps a NaN (numpy's min), is inf without rows,
    skips rest rows within one link; colliding rows are strictly below -penetration."""
    from artipg.validate.jit_verdicts import verdicts

    nan = np.nan
    d = np.array([0.5, -2e-3, -1e-3, 0.2, nan, -0.5, 0.1, -5e-3])
    a = np.array([0, 0, 1, 0, 0, 1, 0, 1])
    b = np.array([1, 2, 2, 1, 1, 2, 1, 2])
    link = np.array([0, 0, 1])  # pieces 0 and 1 share link 0
    sizes = np.array([3, 0, 3, 2])
    W0 = np.tile(np.eye(4), (3, 1, 1))
    none = np.zeros(0, dtype=np.int64)
    out = verdicts(none, a, b, W0, d, sizes, 3, 3, np.zeros((3, 5)), np.ones(3, dtype=np.int64),
                   np.zeros((3, 20)), np.zeros((3, 0)), np.zeros(3, dtype=np.int64), np.zeros(3, dtype=np.int64),
                   1e-6, 1e-5, np.zeros((6, 3)), link, np.arange(3), link, 2, 3, 2e-3, 1e-3)
    bad, n_bad, low = out[:3]
    assert bad.tolist() == [1, 2, 1] and n_bad.tolist() == [1, 0, 1, 1]  # rest row 2: -1e-3 is not below -1e-3
    assert low[0] == -2e-3 and low[1] == np.inf and np.isnan(low[2]) and low[3] == -5e-3


def test_compiled_blocked_joint_rows_equal_numpy():
    """The pairs re-checked with a blocking joint open (racks behind a dishwasher
    door), recorded from real checks."""
    import artipg.validate.checks as checks
    from artipg.validate.jit_scenes import blocked_rows

    calls = []
    original = checks._blocked_rows

    def record(kin, pieces, pairs, Qs):
        calls.append((kin, pieces, pairs, Qs))
        return original(kin, pieces, pairs, Qs)

    checks._blocked_rows = record
    saved = compiled.ENABLED
    compiled.ENABLED = False
    try:
        for category in ("dishwasher", "washing_machine", "oven"):
            for seed in range(4):
                for obj in _variants(category, seed)[:2]:
                    check_object(obj)
    finally:
        checks._blocked_rows = original
        compiled.ENABLED = saved
    assert calls
    found = 0
    for kin, pieces, pairs, Qs in calls:
        # as recorded (blockers open: mostly no overlap left), and with the blockers
        # closed or half open (overlaps: the rows and frames are compared too)
        for scale in (1.0, 0.0, 0.5):
            Qk = [Q.copy() for Q in Qs]
            for Q, (_, k) in zip(Qk, pairs):
                Q[:, k] *= scale
            got = blocked_rows(kin.parent, kin.origin, kin.type_codes, kin.axis, np.concatenate(Qk),
                               kin.descendants, pieces.link, pieces.T, pieces.center, pieces.half,
                               np.array([j for j, _ in pairs]), np.array([k for _, k in pairs]),
                               np.array([len(Q) for Q in Qk]), -_OVERLAP)
            assert _bytes(*got) == _bytes(*original(kin, pieces, pairs, Qk))
            found += len(got[0])
    assert found


def test_compiled_blockers_and_open_depths_equal_numpy():
    """The blockers of colliding sweep rows, their (moving, blocking) joint pairs, the
    pairs' depths with the blocker open and each row's pair (``checks._needs_open``),
    recorded from real checks, with the kernel and with numpy."""
    import artipg.validate.checks as checks

    calls = []
    original = checks._needs_open

    def record(kin, pieces, sw, tol, bad):
        out = original(kin, pieces, sw, tol, bad)
        calls.append((kin, pieces, sw, tol, bad, out))
        return out

    checks._needs_open = record
    try:
        for category in ("dishwasher", "washing_machine", "oven", "storage_furniture"):
            for seed in range(3):
                for obj in _variants(category, seed):
                    check_object(obj)
    finally:
        checks._needs_open = original
    assert calls and any(len(out[0]) for *_, out in calls)
    saved = compiled.ENABLED
    compiled.ENABLED = False
    try:
        for kin, pieces, sw, tol, bad, (pairs, depth, row_pair) in calls:
            ref = original(kin, pieces, sw, tol, bad)
            assert pairs == ref[0] and _bytes(depth, row_pair) == _bytes(ref[1], ref[2])
    finally:
        compiled.ENABLED = saved


# ---------------------------------------------------------------- reports

def _report(obj, tol=Tolerances()):
    r = check_object(obj, tol)
    return repr(r.to_json()) + repr([(n, c.worst, c.info, [vars(i) for i in c.issues]) for n, c in r.checks.items()])


@pytest.mark.parametrize("category", CATEGORIES)
def test_reports_are_the_same_with_and_without_the_kernels(category, numpy_path):
    for seed in SEEDS:
        for obj in _variants(category, seed):
            assert _report(obj) == numpy_path(lambda: _report(obj))
        obj = artipg.get_category(category).generate(seed)
        tol = Tolerances(penetration=2e-4, floating=5e-3, sweep_poses=7, open_fractions=(0.5, 1.0))
        assert _report(obj, tol) == numpy_path(lambda: _report(obj, tol))
