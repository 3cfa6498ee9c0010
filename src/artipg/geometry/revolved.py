"""The ``revolved`` patch family: one profile segment (a line or a circular arc, see
:mod:`artipg.geometry.profile`) revolved about an axis, the curved cells of the lathe,
extrusion, rounded-box and swept-tube families.

Cell parameters (15 rows, the widest family, primitive-local frame, metres/radians):

=========  ==================================================================
o (3)      a point of the axis (the profile's origin)
e1 (3)     unit direction of the θ = 0 half-plane, orthogonal to e3
e3 (3)     unit axis direction (the profile's z); e2 = e3 x e1
r0 z0      start of the segment in the (ρ, z) half-plane
r1 z1      its end
b          its bulge (0: straight, a cone / cylinder / annulus band)
arc        swept angle, 0 <= θ <= arc from e1 towards e2
=========  ==================================================================

The outward normal is the right normal of the segment's direction in (ρ, z) (a
counter-clockwise profile loop faces outwards), so reversing a segment flips it.
A point is placed from two uniforms, as the families of :mod:`artipg.geometry.patches`:
``v`` sets θ = v arc, ``u`` the position along the segment by the exact inverse of its
area CDF (∝ ρ ds): a square root for straight segments, safeguarded Newton steps on
``c δ t + R (sin(a0 + δ t) - sin a0)`` for arcs of centre radius c and radius R.
It is registered in :data:`artipg.geometry.patches.FAMILIES`, so
:func:`artipg.geometry.patches.sample_family` draws it like the other families.
"""

from __future__ import annotations

import numpy as np

from artipg.geometry.patches import block
from artipg.geometry.profile import arc_geometry

NAME = "revolved"
N_PARAMS = 15
#: Most Newton/bisection steps of the arc inverse CDF (it converges in 3-6 for
#: well-conditioned arcs; bisection alone halves the bracket each step).
MAX_STEPS = 80


def _segment_terms(r0, z0, r1, z1, b):
    """(straight mask, centre (..., 2), radius, start angle, sweep, H1) of segments, where
    H1 = c δ + R (sin(a0 + δ) - sin a0) is the arc's area integral over R."""
    p0 = np.stack([r0, z0], axis=-1)
    p1 = np.stack([r1, z1], axis=-1)
    c, R, a0, d = arc_geometry(p0, p1, b)
    Rf = np.where(np.isfinite(R), R, 0.0)
    H1 = c[..., 0] * d + Rf * (np.sin(a0 + d) - np.sin(a0))
    return b == 0.0, c, Rf, a0, d, H1


def revolved_area(r0, z0, r1, z1, b, arc) -> np.ndarray:
    """Area (...) of revolved segments (Pappus for lines; ∫ ρ ds over the arc), m^2."""
    line = 0.5 * (np.asarray(r0) + r1) * np.hypot(np.asarray(r1) - r0, np.asarray(z1) - z0)
    if not np.any(b):  # straight segments only: no arc terms
        return arc * line
    straight, c, R, a0, d, H1 = _segment_terms(*np.broadcast_arrays(r0, z0, r1, z1, b))
    return arc * np.where(straight, line, R * np.abs(H1))


def cells(comp, o, e1, e3, r0, z0, r1, z1, b, arc, scale=1.0):
    """A :class:`artipg.geometry.patches.Patch` block of revolved cells (every argument
    broadcasts to (c, M); ``o``, ``e1``, ``e3`` are 3-tuples of such columns; ``scale``
    0/1 switches cells off)."""
    area = revolved_area(*np.broadcast_arrays(r0, z0, r1, z1, b), arc) * scale
    return block(NAME, comp, area, *o, *e1, *e3, r0, z0, r1, z1, b, arc)


def _profile_point(q, u):
    """(ρ, z, nρ, nz) (k,) each: the point at area fraction ``u`` of each cell's segment."""
    r0, z0, r1, z1, b = q[9], q[10], q[11], q[12], q[13]
    straight, c, R, a0, d, H1 = _segment_terms(r0, z0, r1, z1, b)
    # straight segments: ρ² is uniform (as the band family), the slant fraction from it
    rho = np.sqrt(r0 * r0 + u * (r1 * r1 - r0 * r0))
    s = u * (r0 + r1) / (rho + r0 + 1e-300)
    L = np.hypot(r1 - r0, z1 - z0)
    Ls = np.where(L > 0, L, 1.0)
    r, z = r0 + s * (r1 - r0), z0 + s * (z1 - z0)
    nr, nz = (z1 - z0) / Ls, -(r1 - r0) / Ls
    arcs = np.flatnonzero(~straight)
    if len(arcs):
        t = _arc_fraction(c[arcs, 0], R[arcs], a0[arcs], d[arcs], H1[arcs], u[arcs])
        a = a0[arcs] + d[arcs] * t
        ca, sa = np.cos(a), np.sin(a)
        sg = np.sign(d[arcs])
        r[arcs] = c[arcs, 0] + R[arcs] * ca
        z[arcs] = c[arcs, 1] + R[arcs] * sa
        nr[arcs] = sg * ca
        nz[arcs] = sg * sa
    return r, z, nr, nz


def _arc_fraction(cr, R, a0, d, H1, u):
    """Fractions t (k,) in [0, 1] with F(t) = (cr δ t + R (sin(a0 + δ t) - sin a0)) / H1 = u:
    Newton steps kept inside the bracket (bisection otherwise); F is increasing as the
    arc stays at ρ >= 0."""
    t = u.copy()
    lo, hi = np.zeros_like(u), np.ones_like(u)
    Hs = np.where(H1 != 0, H1, 1.0)
    todo = np.arange(len(u))
    for _ in range(MAX_STEPS):
        if not len(todo):
            break
        tt, dd = t[todo], d[todo]
        a = a0[todo] + dd * tt
        g = (cr[todo] * dd * tt + R[todo] * (np.sin(a) - np.sin(a0[todo]))) / Hs[todo] - u[todo]
        gp = dd * (cr[todo] + R[todo] * np.cos(a)) / Hs[todo]
        lo[todo] = np.where(g < 0, tt, lo[todo])
        hi[todo] = np.where(g > 0, tt, hi[todo])
        nt = tt - g / np.where(gp > 0, gp, 1.0)
        ok = (gp > 0) & (nt > lo[todo]) & (nt < hi[todo])
        nt = np.where(ok, nt, 0.5 * (lo[todo] + hi[todo]))
        done = np.abs(nt - tt) <= 1e-15
        t[todo] = nt
        todo = todo[~done]
    return t


def place_revolved(q: np.ndarray, u: np.ndarray, v: np.ndarray, out: np.ndarray | None = None) -> np.ndarray:
    """One area-uniform point per column of ``q`` (15, k) on revolved cells, from
    uniforms ``u`` (along the segment) and ``v`` (around the axis) in [0, 1) (k,).

    Returns (6, k) rows x, y, z, nx, ny, nz (unit normals), local frame."""
    if out is None:
        out = np.empty((6, q.shape[1]))
    r, z, nr, nz = _profile_point(q, u)
    th = v * q[14]
    ct, st = np.cos(th), np.sin(th)
    o, e1, e3 = q[0:3], q[3:6], q[6:9]
    e2 = np.cross(e3, e1, axis=0)
    radial = ct * e1 + st * e2
    out[0:3] = o + r * radial + z * e3
    out[3:6] = nr * radial + nz * e3
    return out
