"""Fast paths of the export against the plain computations they replace, bit for bit.

Each test below carries the plain version (the code the fast path replaced) and checks
that the fast one gives the same bytes: object folders must not change when the
exporter gets faster.
"""

from __future__ import annotations

import json
import math
import os
import re
import stat

import numpy as np
import pytest

import artipg
from artipg.annotate import grasps as G
from artipg.annotate.sdf import primitive_params
from artipg.export import meshes as M
from artipg.export.annotation import _r, annotation_dict, annotation_text
from artipg.export.folder import write_files_atomic
from artipg.export.jsontext import dumps_indented
from artipg.export.urdf import _fmt, build_urdf
from artipg.geometry import BOX, Lathe
from artipg.geometry.base import TWO_PI
from artipg.geometry.revolve import revolve_arrays

CATEGORIES = artipg.categories()


@pytest.fixture(scope="module")
def objects():
    return [artipg.generate(c, s) for c in CATEGORIES for s in (0, 1)]


def _same(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


# ---------------------------------------------------------------- revolve_arrays

def _plain_revolve(profile, arc, sections, cap_start, cap_end, closed_profile):
    prof = np.asarray(profile, dtype=float)
    full = arc >= TWO_PI - 1e-9
    n_sec = max(2, int(math.ceil(sections * arc / TWO_PI)))
    n_th = n_sec if full else n_sec + 1
    th = np.linspace(0.0, arc, n_sec + 1)[:n_th]
    P = len(prof)
    rho, z = prof[:, 0], prof[:, 1]
    V = np.empty((n_th, P, 3))
    V[..., 0] = rho[None, :] * np.cos(th)[:, None]
    V[..., 1] = rho[None, :] * np.sin(th)[:, None]
    V[..., 2] = z[None, :]
    idx = np.arange(n_th * P).reshape(n_th, P)
    axis = rho <= 0.0
    idx[:, axis] = idx[0, axis]
    n_edges = P if closed_profile else P - 1
    i = np.arange(n_edges)
    i1 = (i + 1) % P
    j = np.arange(n_sec)
    j1 = (j + 1) % n_th
    a, b = idx[j][:, i].ravel(), idx[j][:, i1].ravel()
    c, d = idx[j1][:, i1].ravel(), idx[j1][:, i].ravel()
    faces = [np.stack([a, c, b], 1), np.stack([a, d, c], 1)]
    verts = V.reshape(-1, 3)
    if not full:
        ccw = float(np.sum(prof[:, 0] * np.roll(prof[:, 1], -1) - np.roll(prof[:, 0], -1) * prof[:, 1])) > 0
        centroid = prof.mean(axis=0)
        extra = []
        for on, jj, start in ((cap_start, 0, True), (cap_end, n_th - 1, False)):
            if not on:
                continue
            t = th[jj]
            cidx = len(verts) + len(extra)
            extra.append([centroid[0] * math.cos(t), centroid[0] * math.sin(t), centroid[1]])
            ring = idx[jj]
            tri = np.stack([np.full(P, cidx), ring, np.roll(ring, -1)], 1)
            faces.append(tri if start == ccw else tri[:, ::-1])
        verts = np.concatenate([verts, np.array(extra).reshape(-1, 3)])
    F = np.concatenate(faces)
    F = F[(F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])]
    used, F = np.unique(F, return_inverse=True)
    return verts[used], F.reshape(-1, 3).astype(np.int64)


def test_revolve_arrays_with_cached_topology_matches_plain():
    rng = np.random.default_rng(0)
    for it in range(600):
        P = int(rng.integers(2, 10))
        prof = np.column_stack([rng.random(P) * (rng.random(P) > 0.3), rng.normal(size=P)])
        arc = [TWO_PI, rng.random() * TWO_PI, TWO_PI - 1e-10, 4.0][it % 4]
        sections = int(rng.integers(3, 40))
        flags = tuple(bool(f) for f in rng.random(3) < 0.7)
        V, F = revolve_arrays(prof, arc, sections, *flags)
        V0, F0 = _plain_revolve(prof, arc, sections, *flags)
        assert _same(V, V0) and _same(F, F0)
        F[:] = 0  # the faces handed out are the caller's own: the cache is untouched
        assert _same(revolve_arrays(prof, arc, sections, *flags)[1], F0)


# ---------------------------------------------------------------- memoised primitives

def test_primitive_cache_keys_on_exact_parameters():
    calls = []
    cache = M.PrimitiveCache(lambda geom, p, s: calls.append(p) or (geom, tuple(p), s), maxsize=2)
    assert cache(BOX, (0.1, 0.2, 0.3), 24) == (BOX, (0.1, 0.2, 0.3), 24)
    cache(BOX, (0.1, 0.2, 0.3), 24)
    assert len(calls) == 1
    cache(BOX, (0.0, 0.2, 0.3), 24)
    cache(BOX, (-0.0, 0.2, 0.3), 24)  # equal floats, different bytes: kept apart
    assert len(calls) == 3
    cache(BOX, np.array([0.1, 0.2, 0.3]), 24)  # evicted (maxsize 2): computed again
    assert len(calls) == 4
    cache(BOX, (0.1, 0.2, 0.3), 12)
    cache(Lathe(2), (0.1, 0.2, 0.3), 12)
    assert len(calls) == 6


def test_memoised_meshes_pieces_and_mass_match_direct_calls(objects):
    for obj in objects[::3]:
        for link in obj.links:
            for part in link.parts:
                for prim in part.primitives:
                    V, F = M.primitive_mesh_arrays(prim.geom, prim.params, 24)
                    V0, F0 = prim.geom.mesh_arrays(prim.params, 24)
                    assert _same(V, V0) and _same(F, np.asarray(F0, dtype=np.int64))
                    assert not V.flags.writeable
                    pieces = M.primitive_collision(prim.geom, prim.params)
                    plain = prim.geom.collision(prim.params)
                    assert len(pieces) == len(plain)
                    for a, b in zip(pieces, plain):
                        assert a.shape == b.shape and a.size == b.size and _same(a.pose, b.pose)
                        if b.vertices is not None:
                            assert _same(a.vertices, b.vertices) and _same(a.faces, b.faces)
                    vol, c, I = M.primitive_mass_properties(prim.geom, prim.params)
                    vol0, c0, I0 = M._mass_properties(prim.geom, prim.params, 24)
                    assert vol == vol0 and _same(c, np.asarray(c0, float)) and _same(I, np.asarray(I0, float))


def _plain_hull_texts(link) -> list[str | None]:
    """OBJ text of each collision piece of ``link`` in order (None for native shapes),
    from pieces every primitive builds afresh (no cache)."""
    pieces = [piece for part in link.parts for prim in part.primitives for piece in prim.geom.collision(prim.params)]
    return [M.obj_text(p.vertices, p.faces) if p.shape == "mesh" else None for p in pieces]


def test_each_collision_element_loads_its_own_hull_and_no_file_is_repeated():
    """Identical hulls (equal primitives of a link, or across links: the handle ends of
    drawers are equal tori) share one file, yet every collision element still loads
    the hull of its own piece, and no two hull files hold the same bytes."""
    shared = 0
    for seed in range(4):
        obj = artipg.generate("storage_furniture", seed)
        robot, files = build_urdf(obj)
        for link, el in zip(obj.links, robot.findall("link")):
            expected = _plain_hull_texts(link)
            cols = el.findall("collision")
            assert len(cols) == len(expected)
            for col, text in zip(cols, expected):
                mesh = col.find("geometry/mesh")
                assert (mesh is None) == (text is None)
                if mesh is not None:
                    assert files[mesh.get("filename")] == text
        hulls = [v for k, v in files.items() if re.fullmatch(r"meshes/.*_c\d+\.obj", k)]
        assert len(hulls) == len(set(hulls))
        refs = [m.get("filename") for m in robot.iter("mesh") if "_c" in m.get("filename")]
        shared += len(refs) - len(set(refs))
        assert set(refs) == {k for k in files if re.fullmatch(r"meshes/.*_c\d+\.obj", k)}
    assert shared  # the case this test is about did occur


# ---------------------------------------------------------------- inertials

def _plain_link_inertial(link, materials):
    masses, coms, inertias = [], [], []
    for part in link.parts:
        rho = M.density(part.semantic, materials)
        for prim in part.primitives:
            vol, c, I1 = M.primitive_mass_properties(prim.geom, prim.params, 24)
            if vol <= 0:
                continue
            T = part.pose @ prim.pose
            mass = rho * vol
            R = T[:3, :3]
            masses.append(mass)
            coms.append(R @ c + T[:3, 3])
            inertias.append(mass * (R @ I1 @ R.T))
    if not masses:
        return 1e-3, np.zeros(3), np.eye(3) * 1e-6
    Mt = float(sum(masses))
    com = np.sum([m * c for m, c in zip(masses, coms)], axis=0) / Mt
    I = np.zeros((3, 3))
    for m, c, Ii in zip(masses, coms, inertias):
        d = c - com
        I += Ii + m * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    I = (I + I.T) / 2 + np.eye(3) * 1e-9
    return Mt, com, I


def test_stacked_link_inertial_matches_plain_loop(objects):
    for obj in objects:
        for link in obj.links:
            m, c, I = M.link_inertial(link, 24, obj.materials)
            m0, c0, I0 = _plain_link_inertial(link, obj.materials)
            assert m == m0 and _same(c, c0) and _same(I, I0)


# ---------------------------------------------------------------- text

def test_obj_text_and_urdf_numbers_match_plain_formatting():
    rng = np.random.default_rng(3)
    V = rng.normal(size=(50, 3)) * 10.0 ** rng.integers(-8, 3, size=(50, 3))
    V[0] = [-0.0, 0.0, -1e-9]
    F = rng.integers(0, 50, size=(70, 3))
    plain = (("v %.6f %.6f %.6f\n" * len(V)) % tuple(V.ravel())
             + ("f %d %d %d\n" * len(F)) % tuple((F + 1).ravel()))
    assert M.obj_text(V, F) == plain
    for v in list(V) + [(), [1.5, -0.0], (np.float32(0.1), 2), np.array([1e300, -np.inf, np.nan])]:
        assert _fmt(v) == " ".join(f"{float(x) + 0.0:.9g}" for x in v)


def _plain_r(x, nd=6):
    if isinstance(x, np.ndarray) and x.dtype.kind == "f":
        return (np.round(x, nd) + 0.0).tolist()
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_plain_r(v, nd) for v in x]
    if isinstance(x, (float, np.floating)):
        v = round(float(x), nd)
        return 0.0 if v == 0 else v
    if isinstance(x, np.integer):
        return int(x)
    return x


def test_rounding_fast_paths_match_plain():
    rng = np.random.default_rng(4)
    values = [0.0, -0.0, -4e-7, 5e-7, 0.1234565, True, False, 3, "x", None, np.float64(-1e-9), np.int64(4),
              np.float32(0.1), [1.0, -0.0, 2.5e-7], (1.0, 2), [], [[1.0, 2.0], [-0.0]], np.array([1.0, -1e-8]),
              np.array([1, 2]), math.inf, [math.nan]]
    values += list(rng.normal(size=200) * 10.0 ** rng.integers(-9, 4, size=200))
    for x in values:
        assert json.dumps(_r(x)) == json.dumps(_plain_r(x)) and type(_r(x)) is type(_plain_r(x))
    A = rng.normal(size=(5, 4, 4)) * 1e-6
    assert _r(A) == [_plain_r(a) for a in A]  # whole arrays round as row by row


def test_annotation_json_text_matches_json_dumps(objects):
    for obj in objects:
        d = annotation_dict(obj)
        assert annotation_text(obj) == json.dumps(d, indent=1, sort_keys=False) + "\n"


class _Int(int):
    def __repr__(self):
        return "Int!"


class _Float(float):
    def __repr__(self):
        return "Float!"


@pytest.mark.parametrize("indent", [0, 1, 2, "\t"])
def test_indented_json_matches_json_dumps(indent):
    data = {
        "a": [1.0, -0.0, 1e-300, 1e300, float("nan"), float("inf"), -float("inf")],
        "m": [[1.0, 2.0], [3.5, -4.25]],
        "e": [], "d": {}, "n": None, "t": True, "f": False, "i": 7, "neg": -3,
        "s": 'quote " backslash \\ tab \t unicode é ✓ \u2028',
        "mixed": [1, 2.5, "x", None, True, [], {}, [[]], {"k": [1.0]}],
        "tuple": (1.0, (2, 3)), 3: "int key", 2.5: "float key", True: "bool key", None: "none key",
        "sub": [_Int(5), _Float(0.5), np.float64(0.1), np.float64("nan")],
        "deep": [[[[{"x": [[0.1, 0.2]]}]]]],
    }
    assert dumps_indented(data, indent) == json.dumps(data, indent=indent)
    for scalar in ("s", 1, 2.5, None, True, float("nan"), [], {}):
        assert dumps_indented(scalar, indent) == json.dumps(scalar, indent=indent)
    with pytest.raises(TypeError):  # what json itself raises
        dumps_indented({"a": np.int64(3)}, indent)
    with pytest.raises(TypeError):
        dumps_indented({(1, 2): 3}, indent)
    loop: list = []
    loop.append(loop)
    with pytest.raises(ValueError):
        dumps_indented({"x": loop}, indent)


def test_indented_json_matches_json_dumps_on_random_data():
    rng = np.random.default_rng(8)
    alphabet = list('ab"\\[]{},: \n\té✓') + ['\\"', '\\\\']

    def rand(depth):
        r = rng.random()
        if depth > 4 or r < 0.3:
            c = rng.integers(0, 6)
            if c == 0:
                return "".join(rng.choice(alphabet, rng.integers(0, 6)))
            if c == 1:
                return float(rng.normal() * 10.0 ** rng.integers(-5, 5))
            if c == 2:
                return int(rng.integers(-100, 100))
            if c == 3:
                return [None, True, False][rng.integers(0, 3)]
            if c == 4:
                return [float("nan"), float("inf"), -0.0][rng.integers(0, 3)]
            return []
        if r < 0.65:
            return [rand(depth + 1) for _ in range(rng.integers(0, 4))]
        return {"".join(rng.choice(alphabet, rng.integers(0, 4))): rand(depth + 1) for _ in range(rng.integers(0, 4))}

    for _ in range(3000):
        data, indent = rand(0), int(rng.integers(-1, 4))
        assert dumps_indented(data, indent) == json.dumps(data, indent=indent)


# ---------------------------------------------------------------- grasps

def _plain_box_surface_grid(boxes, spacing):
    pts, idx = [], []
    for b, (lo, hi) in enumerate(boxes):
        n = np.maximum(2, np.ceil((hi - lo) / spacing).astype(int) + 1)
        g = lo + G._surface_lattice(*(int(k) for k in n)) * (hi - lo)
        pts.append(g)
        idx.append(np.full(len(g), b))
    return np.concatenate(pts), np.concatenate(idx)


def _plain_gripper_points(pose, width, gripper=G.DEFAULT_GRIPPER, spacing=0.004):
    pts, gi = [], []
    for k in range(len(width)):
        g, _ = _plain_box_surface_grid(gripper.boxes(round(float(width[k]), 6)), spacing)
        R = pose[k, :3, :3]
        pts.append(g[:, :1] * R[:, 0] + g[:, 1:2] * R[:, 1] + g[:, 2:] * R[:, 2] + pose[k, :3, 3])
        gi.append(np.full(len(g), k))
    return np.concatenate(pts), np.concatenate(gi)


def _plain_gripper_clearance(obj, pose, width, qpos=None):
    pts, gi = _plain_gripper_points(pose, width)
    n = len(width)
    out = np.full(n, np.inf)
    start = np.searchsorted(gi, np.arange(n + 1))
    glo = np.minimum.reduceat(pts, start[:-1], axis=0) - G.CLEARANCE_RANGE
    ghi = np.maximum.reduceat(pts, start[:-1], axis=0) + G.CLEARANCE_RANGE
    table = obj.primitive_table
    B = table.world_boxes(obj.link_poses(qpos))
    near = np.all((B[None, :, 0] <= ghi[:, None]) & (B[None, :, 1] >= glo[:, None]), axis=2)
    W = table.world_all(obj.link_poses(qpos))
    geoms, params = primitive_params(obj)
    for k in np.flatnonzero(near.any(axis=0)):
        gs = np.flatnonzero(near[:, k])
        idx = np.concatenate([np.arange(start[g], start[g + 1]) for g in gs])
        R, t = W[k, :, :3], W[k, :, 3]
        d = geoms[k].sdf(params[k], (pts[idx] - t) @ R)
        seg = np.concatenate([[0], np.cumsum(start[gs + 1] - start[gs])[:-1]])
        out[gs] = np.minimum(out[gs], np.minimum.reduceat(d, seg))
    return out


def test_box_surface_grid_matches_plain():
    rng = np.random.default_rng(5)
    for _ in range(300):
        B = int(rng.integers(1, 5))
        lo = rng.normal(size=(B, 3)) * 0.05
        hi = lo + rng.random((B, 3)) * 0.1 * (rng.random((B, 3)) > 0.1)
        boxes = np.stack([lo, hi], 1)
        spacing = float(rng.choice([0.003, 0.004, 0.01]))
        a, b = G.box_surface_grid(boxes, spacing), _plain_box_surface_grid(boxes, spacing)
        assert _same(a[0], b[0]) and _same(a[1], b[1])


def test_gripper_points_and_clearance_match_plain(objects):
    for obj in objects:
        g = G.world_grasps(obj, check=False)
        if not len(g):
            continue
        a, b = G.gripper_points(g.pose, g.width), _plain_gripper_points(g.pose, g.width)
        assert _same(a[0], b[0]) and _same(a[1], b[1])
        for q in (None, obj.limits().mean(axis=1)):
            fast = G.gripper_clearance(obj, g.pose, g.width, q)
            assert _same(fast, _plain_gripper_clearance(obj, g.pose, g.width, q))


def test_world_grasp_directions_match_plain_loop(objects):
    for obj in objects:
        for q in (None, obj.limits().mean(axis=1)):
            g = G.world_grasps(obj, q, check=False)
            poses, L, pj = obj.part_poses(q), obj.link_poses(q), G.part_joint(obj)
            rows = [(i, gr) for i, part in enumerate(obj.parts) for gr in part.grasps]
            k = 0
            for i, gr in rows:  # the plain per-grasp computation, for the grasps kept
                T = poses[i] @ np.asarray(gr.pose, dtype=float)
                od = poses[i][:3, :3] @ np.asarray(gr.open_dir, dtype=float)
                lever = 0.0
                if pj[i] >= 0:
                    j = obj.joints[pj[i]]
                    Tj = L[obj.link_index[j.child]]
                    a = Tj[:3, :3] @ j.axis
                    s = G._opening_sign(j)
                    if j.type == "prismatic":
                        od = s * a
                    else:
                        t = np.cross(a, T[:3, 3] - Tj[:3, 3])
                        lever = np.linalg.norm(t)
                        if lever > 1e-6:
                            od = s * t / lever
                n = np.linalg.norm(od[None], axis=1)  # normalised as world_grasps does, unchanged
                od = np.where(n[:, None] > 1e-12, od[None] / np.maximum(n, 1e-12)[:, None], 0.0)[0]
                if k < len(g) and g.part[k] == i and _same(g.pose[k], T):
                    assert _same(g.open_dir[k], od) and g.lever[k] == lever
                    k += 1
            assert k == len(g)


# ---------------------------------------------------------------- files

def test_atomic_write_creates_plain_files(tmp_path):
    files = {"a.txt": b"hello", "meshes/x.obj": b"v 1 2 3\n" * 1000, "meshes/deep/y.obj": b"",
             "b.bin": bytes(range(256))}
    dest = write_files_atomic(files, tmp_path / "obj")
    umask = os.umask(0)
    os.umask(umask)
    for rel, data in files.items():
        p = dest / rel
        assert p.read_bytes() == data
        assert stat.S_IMODE(p.stat().st_mode) == 0o666 & ~umask  # as Path.write_bytes makes them
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".tmp-")]
