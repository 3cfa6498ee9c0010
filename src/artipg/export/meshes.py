"""Meshes of links: visual OBJ files and convex collision pieces, plus inertials.

OBJ files are written with a fixed number format so that the same object always gives
the same bytes. Visual OBJ files carry normals, texture coordinates and one ``usemtl``
group per material (:func:`artipg.appearance.materials_of`); the UVs come from
:func:`primitive_surface_arrays`, the one place that maps a primitive to texture space.

Collision geometry is one element per convex piece of every primitive
(:meth:`artipg.geometry.GeometryTemplate.collision`): boxes, cylinders and spheres
as native shapes, hollow solids (rings, tori, frames) as several convex sectors or
boxes, so that simulators, which treat every collision mesh as its convex hull,
never fill a hollow body.

Inertials come from the solid geometry and a density per material class
(:mod:`artipg.materials`, with the category's overrides): exact formulas for boxes, frames and
cylinders, mass properties of the primitive's mesh for the other templates.
"""

from __future__ import annotations

import struct
from collections import OrderedDict

import numpy as np

from artipg.geometry import BOX, Primitive
from artipg.geometry.extrusion import frame_dims, frame_pieces
from artipg.geometry.lathe import ball_radius, frustum_dims
from artipg.materials import CLASS_DENSITY, DEFAULT_CLASS, MATERIAL, density, material_class  # noqa: F401


def obj_text(vertices: np.ndarray, faces: np.ndarray) -> str:
    """Wavefront OBJ text of a triangle mesh (vertices (V, 3) metres, faces (F, 3))."""
    # Python floats and ints format about twice as fast as numpy scalars
    v = ("v %.6f %.6f %.6f\n" * len(vertices)) % tuple(np.asarray(vertices, dtype=float).ravel().tolist())
    f = ("f %d %d %d\n" * len(faces)) % tuple((np.asarray(faces, dtype=np.int64) + 1).ravel().tolist())
    return v + f


def obj_surface_text(vertices, normals, uvs, faces, groups, mtllib: str = "materials.mtl") -> str:
    """Wavefront OBJ text with normals, UVs and material groups.

    ``vertices``, ``normals`` (V, 3), ``uvs`` (V, 2) share one index; ``faces`` (F, 3);
    ``groups`` is a list of (material name, first face, end face) covering the faces
    in order.
    """
    n = len(vertices)
    head = f"mtllib {mtllib}\n"
    v = ("v %.6f %.6f %.6f\n" * n) % tuple(np.asarray(vertices, dtype=float).ravel().tolist())
    vt = ("vt %.5f %.5f\n" * n) % tuple(np.asarray(uvs, dtype=float).ravel().tolist())
    vn = ("vn %.4f %.4f %.4f\n" * n) % tuple((np.asarray(normals, dtype=float) + 0.0).ravel().tolist())
    idx = np.repeat(np.asarray(faces, dtype=np.int64) + 1, 3, axis=1).ravel().tolist()
    out = [head, v, vt, vn]
    for name, a, b in groups:
        out.append(f"usemtl {name}\n")
        out.append(("f %d/%d/%d %d/%d/%d %d/%d/%d\n" * (b - a)) % tuple(idx[9 * a:9 * b]))
    return "".join(out)


def link_visual_arrays(link, sections: int = 24) -> tuple[np.ndarray, np.ndarray] | None:
    """All primitives of ``link`` as one mesh in the link frame: vertices (V, 3) and
    faces (F, 3), or None if the link is empty."""
    verts, faces = [], []
    n = 0
    for part in link.parts:
        for prim in part.primitives:
            V, F = primitive_mesh_arrays(prim.geom, prim.params, sections)
            T = part.pose @ prim.pose
            verts.append(V @ T[:3, :3].T + T[:3, 3])
            faces.append(F + n)
            n += len(V)
    if not verts:
        return None
    return np.concatenate(verts), np.concatenate(faces)


def link_visual_mesh(link, sections: int = 24) -> trimesh.Trimesh | None:
    """:func:`link_visual_arrays` as a ``trimesh.Trimesh`` (None if the link is empty)."""
    arrays = link_visual_arrays(link, sections)
    import trimesh

    return None if arrays is None else trimesh.Trimesh(*arrays, process=False)


class PrimitiveCache:
    """A bounded memo of a pure function of a primitive, ``fn(geom, params, *args)``.

    Primitives repeat within an object (the handles of a chest of drawers, the legs of a
    table) and a mesh serves the visual, the inertial and the collision hull, so their
    export computes each result once. Keys are the template, the exact bytes of the
    parameters as float64 (so that -0.0 and 0.0 stay apart) and ``args``; results are
    shared: callers must not modify them.
    """

    def __init__(self, fn, maxsize: int = 512):
        self.fn, self.maxsize = fn, maxsize
        self.store: OrderedDict = OrderedDict()

    def __call__(self, geom, params, *args):
        try:  # parameters are a tuple of floats: packing them is the cheapest exact key
            raw = struct.pack(f"{len(params)}d", *params)
        except (TypeError, OverflowError, struct.error):
            raw = np.asarray(params, dtype=float).tobytes()
        key = (geom, raw, args)
        store = self.store
        out = store.get(key)
        if out is None:
            out = store[key] = self.fn(geom, params, *args)
            while len(store) > self.maxsize:
                try:
                    store.popitem(last=False)
                except KeyError:  # emptied by another thread meanwhile
                    break
        else:
            try:
                store.move_to_end(key)
            except KeyError:  # evicted by another thread meanwhile: still a valid result
                pass
        return out


def _readonly(*arrays):
    """Mark the arrays (created by this module's memos) read-only; returns them."""
    for a in arrays:
        if isinstance(a, np.ndarray) and a.flags.writeable:
            a.flags.writeable = False
    return arrays


def _mesh_arrays(geom, params, sections):
    V, F = geom.mesh_arrays(params, sections)
    return _readonly(np.array(V, dtype=float), np.array(F, dtype=np.int64))


#: :meth:`GeometryTemplate.mesh_arrays` of a primitive, memoised (read-only arrays).
primitive_mesh_arrays = PrimitiveCache(_mesh_arrays)


#: Faces whose normals differ by less than this angle (degrees) share smooth vertex
#: normals; sharper edges (a box's) split the vertices.
CREASE_DEGREES = 40.0


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise cross products (N, 3) (``np.cross`` costs several times more on small arrays)."""
    return np.column_stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]])


def _surface(geom, params, sections):
    from artipg.appearance.textures import TILE_METRES

    V, F = primitive_mesh_arrays(geom, params, sections)
    tri = V[F]
    fn = _cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])  # twice the area times the normal
    dbl = np.sqrt(np.einsum("ij,ij->i", fn, fn))
    unit = fn / np.maximum(dbl, 1e-300)[:, None]
    # every corner (face f, vertex v) against every corner of the same vertex
    cv = F.ravel()
    cf = np.repeat(np.arange(len(F)), 3)
    order = np.argsort(cv, kind="stable")
    deg = np.bincount(cv, minlength=len(V))
    start = np.cumsum(deg) - deg
    reps = deg[cv]
    i = np.repeat(np.arange(len(cv)), reps)
    j = order[np.repeat(start[cv] - (np.cumsum(reps) - reps), reps) + np.arange(len(i))]
    near = np.einsum("ij,ij->i", unit[cf[i]], unit[cf[j]]) > np.cos(np.radians(CREASE_DEGREES))
    N = np.zeros((len(cv), 3))
    np.add.at(N, i[near], fn[cf[j[near]]])
    N /= np.maximum(np.sqrt(np.einsum("ij,ij->i", N, N)), 1e-300)[:, None]
    uv = _corner_uvs(geom, params, V[cv], unit[cf]) / TILE_METRES
    # corners with the same vertex, texture coordinates and normal (to 1e-3) become one vertex
    q = np.rint(N * 1000.0).astype(np.int64) + 1024
    nkey = (q[:, 0] << 22) | (q[:, 1] << 11) | q[:, 2]
    uvkey = np.rint(uv * 1e6)
    srt = np.lexsort((nkey, uvkey[:, 1], uvkey[:, 0], cv))
    new = np.ones(len(srt), dtype=bool)
    new[1:] = ((np.diff(cv[srt]) != 0) | (np.diff(nkey[srt]) != 0)
               | (np.diff(uvkey[srt, 0]) != 0) | (np.diff(uvkey[srt, 1]) != 0))
    first = srt[new]
    inverse = np.empty(len(srt), dtype=np.int64)
    inverse[srt] = np.cumsum(new) - 1
    return _readonly(V[cv[first]], N[first], uv[first], inverse.reshape(-1, 3), np.array(0.5 * dbl.sum()))


def _corner_uvs(geom, params, x: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Texture coordinates (3F, 2), metres, of the corners ``x`` (3F, 3) of F triangles
    (three rows each) with face normals ``n`` (3F, 3): the family's analytic UVs, made
    continuous across each triangle where the family's coordinates wrap around (seams)
    or are undefined (poles: a corner on a lathe's axis takes its face's other corners'
    mean)."""
    uv = np.array(geom.uv(params, x, n), dtype=float)
    tri = uv.reshape(-1, 3, 2)  # a view: the fixes below write through to uv
    pole = geom.uv_poles(params, x, n)
    P = np.zeros(tri.shape[:2], dtype=bool) if pole is None else pole.reshape(-1, 3)
    for c, lo, hi, mask in geom.uv_seams(params, n):
        period, t = hi - lo, tri[:, :, c]
        eps = 1e-9 * max(period, 1.0)
        inside = ((t >= lo - eps) & (t <= hi + eps)).all(axis=1)
        if mask is not None:
            inside &= mask.reshape(-1, 3).all(axis=1)
        spread = np.where(P, -np.inf, t).max(axis=1) - np.where(P, np.inf, t).min(axis=1)
        low = (inside & (spread > 0.5 * period))[:, None] & (t < lo + 0.5 * period) & ~P
        t[low] += period
    if P.any():
        others = (~P).sum(axis=1)
        mean = np.where(~P, tri[:, :, 0], 0.0).sum(axis=1) / np.maximum(others, 1)
        tri[:, :, 0] = np.where(P, mean[:, None], tri[:, :, 0])
    return uv


#: Surface of a primitive for rendering, in its local frame: vertices (V, 3) metres,
#: unit normals (V, 3), texture coordinates (V, 2), faces (F, 3) and the area (m^2, a
#: 0-d array) (memoised, read-only). Vertices are split along creases sharper than :data:`CREASE_DEGREES` and
#: where the texture coordinates change. UVs are the geometry family's analytic ones
#: (metres: arc length along a profile or outline, angle times the rim radius, planar
#: on box faces and caps; see each family's ``uv``) divided by
#: :data:`artipg.appearance.textures.TILE_METRES`, so textures keep their real scale.
#: This is the one place that maps primitives to texture space.
primitive_surface_arrays = PrimitiveCache(_surface)


def link_visual_surface(link, materials: dict, sections: int = 24):
    """The visual surface of ``link`` in the link frame, grouped by material.

    Parameters
    ----------
    link : Link
    materials : dict
        {part name: :class:`artipg.appearance.Material`} (:func:`artipg.appearance.materials_of`).

    Returns
    -------
    (vertices (V, 3), normals (V, 3), uvs (V, 2), faces (F, 3), groups) or None for an
    empty link; ``groups`` lists (Material, first face, end face, area m^2), faces of one
    material contiguous, in the order of the materials' first parts.
    """
    by_mat: dict[str, list] = {}
    mats = {}
    for part in link.parts:
        m = materials[part.name]
        mats[m.name] = m
        for prim in part.primitives:
            by_mat.setdefault(m.name, []).append((part.pose @ prim.pose, prim))
    if not by_mat:
        return None
    Vs, Ns, Us, Fs, groups = [], [], [], [], []
    nv = nf = 0
    for name, items in by_mat.items():
        f0, area = nf, 0.0
        for T, prim in items:
            V, N, UV, F, a = primitive_surface_arrays(prim.geom, prim.params, sections)
            R = T[:3, :3]
            Vs.append(V @ R.T + T[:3, 3])
            Ns.append(N @ R.T)
            Us.append(UV)
            Fs.append(F + nv)
            area += float(a)  # poses are rigid
            nv += len(V)
            nf += len(F)
        groups.append((mats[name], f0, nf, area))
    return np.concatenate(Vs), np.concatenate(Ns), np.concatenate(Us), np.concatenate(Fs), groups


def _collision(geom, params):
    pieces = tuple(geom.collision(params))
    for pc in pieces:  # poses may be shared constants (IDENTITY): left as they are
        if pc.vertices is not None:
            _readonly(pc.vertices, pc.faces)
    return pieces


#: :meth:`GeometryTemplate.collision` of a primitive, memoised (a tuple of pieces with
#: read-only vertices and faces; the pieces of one primitive may share them).
primitive_collision = PrimitiveCache(_collision)


def link_collision_entries(link) -> list[tuple]:
    """Convex collision pieces of ``link``: list of (CollisionPiece, pose (4, 4) in link
    frame, index of the primitive in the link).

    The pieces of one primitive may share one hull (the same vertex array, e.g. the
    sectors of a ring); equal primitives share their memoised pieces too, so a writer
    that writes each hull once must tell hulls apart by primitive index and array."""
    out = []
    k = 0
    for part in link.parts:
        for prim in part.primitives:
            T = part.pose @ prim.pose
            for piece in primitive_collision(prim.geom, prim.params):
                out.append((piece, T @ piece.pose, k))
            k += 1
    return out


def link_collision_pieces(link):
    """Convex collision pieces of ``link``: list of (CollisionPiece, pose (4, 4) in link frame)."""
    return [(piece, T) for piece, T, _ in link_collision_entries(link)]


def _box_inertia(sx: float, sy: float, sz: float) -> np.ndarray:
    """Inertia tensor (3, 3) per unit mass of a box about its centre."""
    return np.diag([sy * sy + sz * sz, sx * sx + sz * sz, sx * sx + sy * sy]) / 12.0


def primitive_mass_properties(geom, params, sections: int = 24) -> tuple[float, np.ndarray, np.ndarray]:
    """Volume (m^3), centre of mass (3,) and inertia per unit mass (3, 3) about the
    centre of mass, in the primitive's local frame.

    Exact for boxes, rectangular frames, cylinders and full spheres; from the
    primitive's closed mesh otherwise.
    """
    vol, c, I = _primitive_mass(geom, params, sections)
    return vol, c.copy(), I.copy()


def _mass_properties(geom, params, sections):
    p = tuple(float(v) for v in params)
    prim = Primitive(geom, p)
    if geom is BOX and p[3] == 0.0:
        return p[0] * p[1] * p[2], np.zeros(3), _box_inertia(*p[:3])
    frame = frame_dims(prim)
    if frame is not None:
        vol, I = 0.0, np.zeros((3, 3))
        for size, T in frame_pieces(*frame):
            v = size[0] * size[1] * size[2]
            c = T[:3, 3]
            vol += v
            I += v * (_box_inertia(*size) + np.dot(c, c) * np.eye(3) - np.outer(c, c))
        return vol, np.zeros(3), I / max(vol, 1e-18)
    cyl = frustum_dims(prim)
    if cyl is not None and abs(cyl[0] - cyl[1]) < 1e-12:
        r, h = cyl[0], cyl[2]
        a = (3 * r * r + h * h) / 12.0
        return np.pi * r * r * h, np.zeros(3), np.diag([a, a, r * r / 2.0])
    R = ball_radius(prim)
    if R is not None:
        return 4.0 / 3.0 * np.pi * R ** 3, np.zeros(3), np.eye(3) * (0.4 * R * R)
    V, F = primitive_mesh_arrays(geom, geom.solid_params(p), sections)
    import trimesh  # only for mass properties: exporting a folder need not load it otherwise

    props = trimesh.triangles.mass_properties(V[F], density=1.0)
    vol = abs(float(props.volume))
    if vol <= 0:
        return 0.0, np.zeros(3), np.zeros((3, 3))
    return vol, np.asarray(props.center_mass), np.asarray(props.inertia) / props.mass


def _mass(geom, params, sections):
    vol, c, I = _mass_properties(geom, params, sections)
    return (vol, *_readonly(np.array(c, dtype=float), np.array(I, dtype=float)))


_primitive_mass = PrimitiveCache(_mass)


def link_inertial(link, sections: int = 24, materials=None) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass (3,) and inertia tensor (3, 3) about it, link frame.

    Each primitive is a solid of its part's material density (:func:`density`, with
    the category's ``materials`` overrides, e.g. ``obj.materials``);
    overlaps are counted twice, which is a small over-estimate for the few
    primitives that intersect.
    """
    masses, props, part_poses, prim_poses = [], [], [], []
    for part in link.parts:
        rho = density(part.semantic, materials)
        for prim in part.primitives:
            vol, c, I1 = _primitive_mass(prim.geom, prim.params, sections)
            if vol <= 0:
                continue
            masses.append(rho * vol)
            props.append((c, I1))
            part_poses.append(part.pose)
            prim_poses.append(prim.pose)
    if not masses:
        return 1e-3, np.zeros(3), np.eye(3) * 1e-6
    # all primitives at once: stacked matmuls run the same product per matrix as one
    # call per primitive, so the numbers are those of the loop they replace
    m = np.array(masses)
    T = np.stack(part_poses) @ np.stack(prim_poses)
    R = T[:, :3, :3]
    c = np.stack([cp[0] for cp in props])
    I1 = np.stack([cp[1] for cp in props])
    coms = (R @ c[:, :, None])[:, :, 0] + T[:, :3, 3]
    inertias = m[:, None, None] * (R @ I1 @ R.transpose(0, 2, 1))
    return combine_inertials(masses, coms, inertias)


def combine_inertials(masses, coms: np.ndarray, inertias: np.ndarray) -> tuple[float, np.ndarray, np.ndarray]:
    """Mass (kg), centre of mass (3,) and inertia (3, 3) about it of rigidly joined
    bodies: ``masses`` (n,) kg, ``coms`` (n, 3) and ``inertias`` (n, 3, 3) about their
    own centres of mass, all in one frame (parallel axis theorem)."""
    m = np.asarray(masses, dtype=float)
    M = float(sum(masses))
    com = np.sum(m[:, None] * coms, axis=0) / M
    d = coms - com
    dd = np.array([np.dot(di, di) for di in d])  # the dot products of the loop, one by one
    terms = inertias + m[:, None, None] * (dd[:, None, None] * np.eye(3) - d[:, :, None] * d[:, None, :])
    I = np.zeros((3, 3))
    for t in terms:  # summed in the same order
        I += t
    # keep the tensor physically valid for engines that check the triangle inequality
    I = (I + I.T) / 2 + np.eye(3) * 1e-9
    return M, com, I


def object_mass(obj, sections: int = 24) -> float:
    """Total mass (kg) of ``obj``: the sum of its links' :func:`link_inertial` masses,
    with the category's material overrides (``obj.materials``)."""
    return float(sum(link_inertial(link, sections, obj.materials)[0] for link in obj.links))
