"""Surface patches: the units in which every geometry template is sampled.

Each template cuts its surface into components (faces, walls, caps, ends) and each
component into one or more *patches* of seven families, each with an exact
area-uniform sampler:

========  =========================================================================
family    parameters (rows of a (p, k) array, primitive-local frame, metres/radians)
========  =========================================================================
rect      o(3) a(3) b(3) n(3): the parallelogram ``o + u a + v b``, unit normal n
tri       o(3) a(3) b(3) n(3): the triangle ``o + u a + v b``, u + v <= 1
sector    c(3) a(3) b(3) n(3) r0 r1 arc: ``c + ρ (cos φ a + sin φ b)`` with a, b
          orthonormal, r0 <= ρ <= r1, 0 <= φ <= arc (discs, annuli, their sectors)
band      r0 r1 z0 z1 arc nr nz: the conical band about z from (ρ = r0, z0) to
          (r1, z1), 0 <= θ <= arc, normal ``(nr cos θ, nr sin θ, nz)``
zone      R z0 z1: the sphere of radius R between z0 and z1
torus     R r arc: the torus about z, centre-line radius R, tube radius r
revolved  o(3) e1(3) e3(3) r0 z0 r1 z1 bulge arc: one profile segment (line or arc)
          revolved about an axis (:mod:`artipg.geometry.revolved`; the families'
          curved cells)
========  =========================================================================

:func:`sample_family` is the one sampler of every family (two uniforms per point in
closed form; the torus's tube angle by rejection): a point cloud picks a patch per
point in proportion to area and places it there
(:func:`artipg.annotate.points.sample_points`), and the validation samples through
the same function. Templates return their patches from ``patches(P)`` as
:class:`Patch` blocks.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

TWO_PI = 2.0 * np.pi

#: Families in sampling order, with their parameter counts.
FAMILIES = {"rect": 12, "tri": 12, "sector": 15, "band": 7, "zone": 3, "torus": 3, "revolved": 15}


class Patch(NamedTuple):
    """A block of c patches of one family on each of M primitives.

    Attributes
    ----------
    family : str
        A key of :data:`FAMILIES`.
    comp : (c,) int ndarray
        The template component (face, wall, cap) each patch belongs to.
    area : (c, M) ndarray
        Patch areas, square metres (zero for absent patches, e.g. open caps).
    params : (c, p, M) ndarray
        Family parameters in the primitive's local frame.
    """

    family: str
    comp: np.ndarray
    area: np.ndarray
    params: np.ndarray


def block(family: str, comp, area, *cols) -> Patch:
    """A :class:`Patch` of ``len(comp)`` patches per primitive.

    ``area`` and every parameter column broadcast to (c, M); M is the last axis of
    ``area``. Columns are written in place, which is much cheaper than stacking.
    """
    comp = np.asarray(comp, dtype=np.int64).reshape(-1)
    area = np.asarray(area, dtype=float)
    c, M = len(comp), area.shape[-1]
    params = np.empty((c, len(cols), M))
    for j, col in enumerate(cols):
        params[:, j] = col
    if area.shape != (c, M):
        full = np.empty((c, M))
        full[...] = area
        area = full
    return Patch(family, comp, area, params)


def cross_norm(a, b):
    """Length of the cross product of vectors ``a`` and ``b``, each a 3-tuple of columns
    (arrays that broadcast, or scalars): the area of the parallelogram they span."""
    ax, ay, az = a
    bx, by, bz = b
    return np.sqrt((ay * bz - az * by) ** 2 + (az * bx - ax * bz) ** 2 + (ax * by - ay * bx) ** 2)


def rects(comp, o, a, b, n, scale=1.0) -> Patch:
    """Parallelograms ``o + u a + v b`` (o, a, b, n: 3-tuples of columns; unit normal n).

    ``scale`` (0 or 1 per patch) switches patches off without changing their shape.
    """
    return block("rect", comp, cross_norm(a, b) * scale, *o, *a, *b, *n)


def tris(comp, o, a, b, n, scale=1.0) -> Patch:
    """Triangles ``o + u a + v b``, u, v >= 0, u + v <= 1."""
    return block("tri", comp, 0.5 * cross_norm(a, b) * scale, *o, *a, *b, *n)


def sectors(comp, c, a, b, n, r0, r1, arc, scale=1.0) -> Patch:
    """Planar annulus sectors about centre ``c`` in the plane of orthonormal axes a, b."""
    area = 0.5 * arc * (r1 * r1 - r0 * r0) * scale
    return block("sector", comp, area, *c, *a, *b, *n, r0, r1, arc)


def bands(comp, r0, r1, z0, z1, arc, inward=False) -> Patch:
    """Conical bands about the local z axis (``inward``: normals towards the axis)."""
    dr = r1 - r0
    dz = z1 - z0
    slant = np.sqrt(dr * dr + dz * dz)
    s = np.where(inward, -1.0, 1.0) / np.where(slant > 0, slant, 1.0)
    return block("band", comp, arc * 0.5 * (r0 + r1) * slant, r0, r1, z0, z1, arc, s * dz, -s * dr)


def zones(comp, R, z0, z1) -> Patch:
    """Sphere zones (Archimedes: area 2πR (z1 - z0))."""
    return block("zone", comp, TWO_PI * R * (z1 - z0), R, z0, z1)


def tori(comp, R, r, arc) -> Patch:
    """Torus arcs (Pappus: area 2πr · R · arc)."""
    return block("torus", comp, TWO_PI * r * R * arc, R, r, arc)


def compile_linear(build, q: int) -> np.ndarray:
    """The table (c, p, q + 1) of a patch builder whose parameters are affine in the
    template parameters: ``build(P)`` evaluated at the origin and the unit vectors of
    R^q. Use it with :func:`linear`; the builder stays the definition."""
    basis = np.vstack([np.zeros(q), np.eye(q)])
    prm = build(basis).params  # (c, p, q + 1)
    const = prm[..., :1]
    return np.concatenate([prm[..., 1:] - const, const], axis=2)


def linear(family: str, comp, P: np.ndarray, table: np.ndarray, area: np.ndarray) -> Patch:
    """Patches whose parameters are affine in the template parameters (one matrix product).

    ``table`` (c, p, q + 1) maps each row of ``P`` (M, q), with a trailing 1, to the p
    parameters of each of its c patches (see :func:`compile_linear`); ``area`` (c, M)
    are the patch areas.
    """
    c, p, _ = table.shape
    A, b = _split_table(table)
    params = A @ P.T + b
    return Patch(family, np.asarray(comp, dtype=np.int64), area, params.reshape(c, p, len(P)))


_SPLIT: dict = {}


def _split_table(table: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The coefficient and constant views of a :func:`compile_linear` table, made once
    per table (the same views every call, so the matrix product is the same call)."""
    got = _SPLIT.get(id(table))
    if got is None or got[0] is not table:
        flat = table.reshape(table.shape[0] * table.shape[1], -1)
        got = _SPLIT[id(table)] = (table, flat[:, :-1], flat[:, -1:].copy())
    return got[1], got[2]


# ---------------------------------------------------------------- samplers
# Each places one point per column of the parameters gathered per point, (p, k), from
# two uniforms u, v (k,) in [0, 1) and writes (6, k) rows x y z nx ny nz into ``out``
# (which it returns).

def _affine(q, u, v, out):
    """Points ``o + u a + v b`` with normal n from rows o a b n of ``q``."""
    p = out[0:3]
    np.multiply(u, q[3:6], out=p)
    np.add(q[0:3], p, out=p)
    p += v * q[6:9]
    out[3:6] = q[9:12]
    return out


def _tri(q, u, v, out):
    flip = u + v > 1.0  # reflect the far half of the unit square onto the triangle
    return _affine(q, np.where(flip, 1.0 - u, u), np.where(flip, 1.0 - v, v), out)


def _sector(q, s, t, out):
    r0, r1, arc = q[12], q[13], q[14]
    rho = np.sqrt(r0 * r0 + s * (r1 * r1 - r0 * r0))
    uv = np.empty((2, len(s)))
    phi = np.multiply(t, arc, out=uv[1])
    np.cos(phi, out=uv[0])
    np.sin(phi, out=uv[1])
    uv *= rho
    return _affine(q, uv[0], uv[1], out)


def _band(q, u, t, out):
    r0, r1, z0, z1, arc, nr, nz = q
    rho = np.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
    # slant fraction (rho - r0) / (r1 - r0), written to stay exact for cylinders
    s = u * (r0 + r1) / (rho + r0 + 1e-300)
    cs = out[3:5]  # cos θ, sin θ, scaled in place into the normal below
    th = np.multiply(t, arc, out=cs[1])
    np.cos(th, out=cs[0])
    np.sin(th, out=cs[1])
    np.multiply(rho, cs, out=out[0:2])
    out[2] = z0 + s * (z1 - z0)
    cs *= nr
    out[5] = nz
    return out


def _zone(q, u, t, out):
    R, z0, z1 = q
    z = np.multiply(u, z1 - z0, out=out[2])
    z += z0  # Archimedes: z is uniform on a sphere zone
    rho = np.sqrt(np.maximum(R * R - z * z, 0.0))
    th = np.multiply(t, TWO_PI, out=out[1])
    np.cos(th, out=out[0])
    np.sin(th, out=out[1])
    out[0:2] *= rho
    np.divide(out[0:3], R, out=out[3:6])
    return out


def torus_tube_angles(R: np.ndarray, r: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Area-uniform tube angles (k,) in [0, 2π) of tori with centre-line radii ``R`` and
    tube radii ``r`` (k,): density ∝ R + r cos v, by rejection (acceptance >= 1/2 as r < R)."""
    v = np.empty(len(R))
    todo = np.arange(len(R))
    while len(todo):
        cand = rng.random(len(todo)) * TWO_PI
        Rt, rt = R[todo], r[todo]
        ok = rng.random(len(todo)) * (Rt + rt) <= Rt + rt * np.cos(cand)
        v[todo[ok]] = cand[ok]
        todo = todo[~ok]
    return v


def _torus_at(q, cv, sv, th, out):
    """Torus points with tube angles of cosines ``cv`` and sines ``sv`` at arc angles ``th`` (k,)."""
    R, r, arc = q
    ct, st = np.cos(th), np.sin(th)
    rho = R + r * cv
    np.multiply(rho, ct, out=out[0])
    np.multiply(rho, st, out=out[1])
    np.multiply(r, sv, out=out[2])
    np.multiply(cv, ct, out=out[3])
    np.multiply(cv, st, out=out[4])
    out[5] = sv
    return out


def _revolved(q, u, v, out):
    # the family lives in its own module, which imports this one for ``block``
    from artipg.geometry.revolved import place_revolved

    return place_revolved(q, u, v, out)


_PLACE = {"rect": _affine, "tri": _tri, "sector": _sector, "band": _band, "zone": _zone, "revolved": _revolved}


def sample_family(family: str, q: np.ndarray, rng: np.random.Generator, out: np.ndarray | None = None) -> np.ndarray:
    """One area-uniform point per column of ``q`` (p, k) on patches of ``family``,
    drawing from ``rng``: the one sampler of each family, which annotation and
    validation both call. Two uniforms per point (``rng.random((2, k))``), except for
    the torus, whose tube angles are drawn by rejection (:func:`torus_tube_angles`)
    before one arc uniform per point.

    Parameters
    ----------
    family : str
        A key of :data:`FAMILIES`.
    q : (p, k) ndarray
        Family parameters of each point's patch, primitive-local frame.
    rng : numpy.random.Generator
    out : (6, k) ndarray, optional
        Where to write the result (rows may be strided views, e.g. columns of a larger
        array); a new array when None.

    Returns
    -------
    (6, k) ndarray
        Rows x, y, z, nx, ny, nz in the primitive's local frame (unit normals).
    """
    if family not in FAMILIES:
        raise ValueError(f"unknown patch family {family!r}; known: {sorted(FAMILIES)}")
    if out is None:
        out = np.empty((6, q.shape[1]))
    if family == "torus":
        v = torus_tube_angles(q[0], q[1], rng)
        return _torus_at(q, np.cos(v), np.sin(v), rng.random(q.shape[1]) * q[2], out)
    u, v = rng.random((2, q.shape[1]))
    return _PLACE[family](q, u, v, out)
