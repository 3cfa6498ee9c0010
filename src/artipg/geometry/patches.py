"""Surface patches: the units in which every geometry template is sampled.

Each template cuts its surface into components (faces, walls, caps, ends) and each
component into one or more *patches* of six families, each with a closed-form
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
========  =========================================================================

Sampling an object draws a multinomial count per patch and then runs each family's
sampler once for all its points, with arithmetic only (no boolean masks), which is
what makes labelled point clouds cheap. Templates return their patches from
``patches(P)`` as :class:`Patch` blocks; :func:`sample_family` evaluates them.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

TWO_PI = 2.0 * np.pi

#: Families in sampling order, with their parameter counts.
FAMILIES = {"rect": 12, "tri": 12, "sector": 15, "band": 7, "zone": 3, "torus": 3}


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
    shape = (len(comp), area.shape[-1])
    params = np.empty((shape[0], len(cols), shape[1]))
    for j, col in enumerate(cols):
        params[:, j] = col
    return Patch(family, comp, np.broadcast_to(area, shape), params)


def _cross_norm(a, b):
    ax, ay, az = a
    bx, by, bz = b
    return np.sqrt((ay * bz - az * by) ** 2 + (az * bx - ax * bz) ** 2 + (ax * by - ay * bx) ** 2)


def rects(comp, o, a, b, n, scale=1.0) -> Patch:
    """Parallelograms ``o + u a + v b`` (o, a, b, n: 3-tuples of columns; unit normal n).

    ``scale`` (0 or 1 per patch) switches patches off without changing their shape.
    """
    return block("rect", comp, _cross_norm(a, b) * scale, *o, *a, *b, *n)


def tris(comp, o, a, b, n, scale=1.0) -> Patch:
    """Triangles ``o + u a + v b``, u, v >= 0, u + v <= 1."""
    return block("tri", comp, 0.5 * _cross_norm(a, b) * scale, *o, *a, *b, *n)


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
    flat = table.reshape(c * p, -1)
    params = flat[:, :-1] @ P.T + flat[:, -1:]
    return Patch(family, np.asarray(comp, dtype=np.int64), area, params.reshape(c, p, len(P)))


# ---------------------------------------------------------------- samplers
# Each takes the parameters gathered per point, (p, k), and returns (6, k): x y z nx ny nz.

def _affine(q, u, v):
    """Points ``o + u a + v b`` with normal n from rows o a b n of ``q``."""
    out = np.empty((6, len(u)))
    out[0:3] = q[0:3] + u * q[3:6] + v * q[6:9]
    out[3:6] = q[9:12]
    return out


def _rect(q, rng):
    u, v = rng.random((2, q.shape[1]))
    return _affine(q, u, v)


def _tri(q, rng):
    u, v = rng.random((2, q.shape[1]))
    flip = u + v > 1.0  # reflect the far half of the unit square onto the triangle
    return _affine(q, np.where(flip, 1.0 - u, u), np.where(flip, 1.0 - v, v))


def _sector(q, rng):
    s, t = rng.random((2, q.shape[1]))
    r0, r1, arc = q[12], q[13], q[14]
    rho = np.sqrt(r0 * r0 + s * (r1 * r1 - r0 * r0))
    phi = t * arc
    return _affine(q, rho * np.cos(phi), rho * np.sin(phi))


def _band(q, rng):
    u, t = rng.random((2, q.shape[1]))
    r0, r1, z0, z1, arc, nr, nz = q
    rho = np.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
    # slant fraction (rho - r0) / (r1 - r0), written to stay exact for cylinders
    s = u * (r0 + r1) / (rho + r0 + 1e-300)
    th = t * arc
    c, d = np.cos(th), np.sin(th)
    return np.stack([rho * c, rho * d, z0 + s * (z1 - z0), nr * c, nr * d, nz])


def _zone(q, rng):
    u, t = rng.random((2, q.shape[1]))
    R, z0, z1 = q
    z = z0 + u * (z1 - z0)  # Archimedes: z is uniform on a sphere zone
    rho = np.sqrt(np.maximum(R * R - z * z, 0.0))
    th = t * TWO_PI
    c, d = np.cos(th), np.sin(th)
    return np.stack([rho * c, rho * d, z, rho * c / R, rho * d / R, z / R])


def _torus(q, rng):
    R, r, arc = q
    k = len(R)
    # tube angle v has density ∝ R + r cos v: rejection, acceptance >= 1/2 since r < R
    v = np.empty(k)
    todo = np.arange(k)
    while len(todo):
        cand = rng.random(len(todo)) * TWO_PI
        Rt, rt = R[todo], r[todo]
        ok = rng.random(len(todo)) * (Rt + rt) <= Rt + rt * np.cos(cand)
        v[todo[ok]] = cand[ok]
        todo = todo[~ok]
    th = rng.random(k) * arc
    cv, sv, ct, st = np.cos(v), np.sin(v), np.cos(th), np.sin(th)
    rho = R + r * cv
    return np.stack([rho * ct, rho * st, r * sv, cv * ct, cv * st, sv])


_SAMPLERS = {"rect": _rect, "tri": _tri, "sector": _sector, "band": _band, "zone": _zone, "torus": _torus}


def sample_family(family: str, q: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """One area-uniform point per column of ``q`` (p, k) on patches of ``family``.

    Returns
    -------
    (6, k) ndarray
        Rows x, y, z, nx, ny, nz in the primitive's local frame (unit normals).
    """
    return _SAMPLERS[family](q, rng)
