"""Solids of revolution about the local z axis: frustum (cylinder, cone), ring (hollow
cylinder), sphere segment and torus, the last three optionally cut to an arc
``0 <= θ <= arc`` measured from +x towards +y."""

from __future__ import annotations

import functools
import math

import numpy as np

from artipg.geometry.base import (
    TWO_PI,
    convex_hull,
    CollisionPiece,
    GeometryTemplate,
    Primitive,
    disk,
    polygon_sdf_rows,
    wedge_sdf,
)
from artipg.geometry.patches import Patch, compile_linear, linear, rects, sectors
from artipg.geometry.transforms import IDENTITY, rot_z

# Primitive(...) without the NamedTuple's Python-level __new__ (same tuple): the
# constructors below run dozens of times per object
_tuple_new = tuple.__new__

FULL = TWO_PI
# patch layouts shared by the solids of revolution: (2, 1) columns broadcast over rows
_X, _Y = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
_DOWN_UP = np.array([[-1.0], [1.0]])
_CAP_COMP = (1, 2)
_WALL_COMP, _INWARD = (0, 1), np.array([[False], [True]])
_ANNULUS_COMP = (2, 3)
_END_COMP = (4, 5)
# the same layouts as index arrays, and constant columns, for the hand-written blocks
_COMP0, _COMP01, _COMP12 = np.array([0]), np.array([0, 1]), np.array([1, 2])
_OUT_IN_SIGN = np.array([[1.0], [-1.0]])  # outer wall normals outward, inner inward
_QUARTERS = np.array([0.5 * np.pi, np.pi, 1.5 * np.pi])


def _is_full(arc) -> np.ndarray:
    return np.asarray(arc) >= TWO_PI - 1e-9


def revolve_arrays(profile, arc: float = FULL, sections: int = 32, cap_start: bool = True,
                   cap_end: bool = True, closed_profile: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of a (ρ, z) profile revolved about z from θ = 0 to θ = ``arc``.

    Parameters
    ----------
    profile : (P, 2) array_like
        Profile vertices (ρ >= 0, z) in counter-clockwise order in the (ρ, z) plane.
        Vertices on the axis (ρ = 0) are shared by all sections.
    arc : float
        Swept angle in radians; a full turn gives a closed surface of revolution.
    sections : int
        Segments for a full turn (scaled down for partial arcs, at least 2).
    cap_start, cap_end : bool
        Close a partial arc with the (convex) profile polygon at θ = 0 / θ = arc.
    closed_profile : bool
        Connect the last profile vertex back to the first.

    Returns
    -------
    vertices : (V, 3) float64
    faces : (F, 3) int64
        Outward-oriented triangles without degenerate faces or unused vertices
        (watertight for closed profiles and full or capped arcs).
    """
    prof = np.asarray(profile, dtype=float)
    full = arc >= TWO_PI - 1e-9
    n_sec = max(2, int(math.ceil(sections * arc / TWO_PI)))
    n_th = n_sec if full else n_sec + 1
    cos_th, sin_th, th = _section_angles(float(arc), n_sec, n_th)
    P = len(prof)
    rho, z = prof[:, 0], prof[:, 1]
    V = np.empty((n_th, P, 3))
    V[..., 0] = rho[None, :] * cos_th
    V[..., 1] = rho[None, :] * sin_th
    V[..., 2] = z[None, :]
    verts = V.reshape(-1, 3)
    caps, ccw = (False, False), False
    if not full:
        caps = (bool(cap_start), bool(cap_end))
        # a counter-clockwise profile makes the fan (centre, v_k, v_k+1) face -θ at θ = 0
        ccw = float(np.sum(prof[:, 0] * np.roll(prof[:, 1], -1) - np.roll(prof[:, 0], -1) * prof[:, 1])) > 0
        centroid = prof.mean(axis=0)
        extra = [[centroid[0] * math.cos(t), centroid[0] * math.sin(t), centroid[1]]
                 for on, t in zip(caps, (th[0], th[n_th - 1])) if on]
        verts = np.concatenate([verts, np.array(extra).reshape(-1, 3)])
    used, F = _revolve_topology(P, tuple((rho <= 0.0).tolist()), n_sec, n_th, bool(closed_profile), caps, ccw)
    return verts[used], F.copy()


@functools.lru_cache(maxsize=64)
def _section_angles(arc: float, n_sec: int, n_th: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cosines (n_th, 1), sines (n_th, 1) and angles (n_th,) of the sections of
    :func:`revolve_arrays` (read-only: they are shared)."""
    th = np.linspace(0.0, arc, n_sec + 1)[:n_th]
    out = np.cos(th)[:, None], np.sin(th)[:, None], th
    for a in out:
        a.flags.writeable = False
    return out


@functools.lru_cache(maxsize=256)
def _revolve_topology(P: int, on_axis: tuple, n_sec: int, n_th: int, closed_profile: bool,
                      caps: tuple[bool, bool], ccw: bool) -> tuple[np.ndarray, np.ndarray]:
    """Which vertices (U,) of :func:`revolve_arrays`'s grid (``n_th`` sections of ``P``
    profile vertices, then one centre per cap) are used, and the faces (F, 3) indexing
    them: they depend only on the counts, the on-axis vertices and the caps, so a
    template's meshes share them (read-only)."""
    idx = np.arange(n_th * P).reshape(n_th, P)
    axis = np.array(on_axis, dtype=bool)
    # every section's copy of an on-axis profile vertex is replaced by the first one
    idx[:, axis] = idx[0, axis]
    n_edges = P if closed_profile else P - 1
    i = np.arange(n_edges)
    i1 = (i + 1) % P
    j = np.arange(n_sec)
    j1 = (j + 1) % n_th
    a, b = idx[j][:, i].ravel(), idx[j][:, i1].ravel()
    c, d = idx[j1][:, i1].ravel(), idx[j1][:, i].ravel()
    faces = [np.stack([a, c, b], 1), np.stack([a, d, c], 1)]
    cidx = n_th * P
    for on, jj, start in ((caps[0], 0, True), (caps[1], n_th - 1, False)):
        if not on:
            continue
        ring = idx[jj]
        tri = np.stack([np.full(P, cidx), ring, np.roll(ring, -1)], 1)
        faces.append(tri if start == ccw else tri[:, ::-1])
        cidx += 1
    F = np.concatenate(faces)
    F = F[(F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])]
    used, F = np.unique(F, return_inverse=True)
    F = F.reshape(-1, 3).astype(np.int64)
    used.flags.writeable = False
    F.flags.writeable = False
    return used, F


def revolve_mesh(profile, arc: float = FULL, sections: int = 32, cap_start: bool = True,
                 cap_end: bool = True, closed_profile: bool = True) -> trimesh.Trimesh:
    """:func:`revolve_arrays` as a ``trimesh.Trimesh``."""
    import trimesh

    return trimesh.Trimesh(*revolve_arrays(profile, arc, sections, cap_start, cap_end, closed_profile),
                           process=False)


class Frustum(GeometryTemplate):
    """Frustum of a cone along z: radius ``r0`` at z = -h/2, ``r1`` at z = +h/2.

    ``cap0``/``cap1`` (1 or 0) say whether the bottom/top discs are part of the surface
    (open pieces are used inside swept tubes). A cylinder has r0 = r1, a cone r1 = 0.
    """

    name = "frustum"
    params = ("r0", "r1", "h", "cap0", "cap1")

    @classmethod
    def component_areas(cls, P):
        Q = P.T.copy()  # contiguous rows r0 r1 h c0 c1: small 2-D strided operands are slow
        r0, r1, h = Q[0], Q[1], Q[2]
        out = np.empty((len(P), 3))
        np.multiply(np.pi * (r0 + r1), np.hypot(h, r1 - r0), out=out[:, 0])
        R = Q[0:2]
        np.multiply(np.pi * Q[3:5] * R, R, out=out[:, 1:].T)  # caps: π c0 r0², π c1 r1²
        return out

    @classmethod
    def patches(cls, P):
        # written out (the same arithmetic as ``bands(0, r0, r1, -h / 2, h / 2, TWO_PI)``
        # and the compiled caps) because it runs for every object
        Q = P.T.copy()  # contiguous rows r0 r1 h c0 c1
        q = np.empty((1, 7, len(P)))
        band = q[0]  # rows r0 r1 z0 z1 arc nr nz
        band[0:2] = Q[0:2]
        np.divide(Q[2], 2, out=band[3])
        np.negative(band[3], out=band[2])  # -(h / 2) is -h / 2 exactly
        band[4] = TWO_PI
        d = band[1:4:2] - band[0:3:2]  # (r1 - r0, z1 - z0)
        dd = d * d
        slant = np.sqrt(dd[0] + dd[1])
        s = 1.0 / np.where(slant > 0, slant, 1.0)
        np.multiply(s, d[1], out=band[5])
        np.multiply(-s, d[0], out=band[6])
        area = np.empty((1, len(P)))
        np.multiply((TWO_PI * 0.5) * (Q[0] + Q[1]), slant, out=area[0])
        R = Q[0:2]
        caps = linear("sector", _COMP12, P, _FRUSTUM_CAPS, np.pi * Q[3:5] * R * R)
        return [Patch("band", _COMP0, area, q), caps]

    @staticmethod
    def _caps(P):
        """The bottom and top discs (parameters affine in P: compiled once, below)."""
        r0, r1, h = P[:, 0], P[:, 1], P[:, 2]
        z = h / 2
        return sectors(_CAP_COMP, (0.0, 0.0, np.stack([-z, z])), _X, _Y, (0.0, 0.0, _DOWN_UP),
                       0.0, np.stack([r0, r1]), TWO_PI)

    @classmethod
    def _profile(cls, p):
        r0, r1, h = p[0], p[1], p[2]
        return np.array([[-r0, -h / 2], [r0, -h / 2], [r1, h / 2], [-r1, h / 2]])

    @classmethod
    def sdf(cls, p, x):
        rho = np.hypot(x[:, 0], x[:, 1])
        if abs(p[0] - p[1]) <= 1e-12:  # cylinder: the 2-D box distance in (ρ, z)
            dx, dz = rho - p[0], np.abs(x[:, 2]) - p[2] / 2
            return np.hypot(np.maximum(dx, 0.0), np.maximum(dz, 0.0)) + np.minimum(np.maximum(dx, dz), 0.0)
        return polygon_sdf_rows(rho, np.ascontiguousarray(x[:, 2]), cls._profile(p))

    @classmethod
    def bounds(cls, p):
        r = max(p[0], p[1])
        return np.array([[-r, -r, -p[2] / 2], [r, r, p[2] / 2]])

    @classmethod
    def bounds_batch(cls, P):
        out = np.empty((len(P), 2, 3))
        hi = out[:, 1]
        np.maximum(P[:, 0], P[:, 1], out=hi[:, 0])
        hi[:, 1] = hi[:, 0]
        np.multiply(P[:, 2], 0.5, out=hi[:, 2])
        np.negative(hi, out=out[:, 0])
        return out

    @classmethod
    def solid_params(cls, p):
        return (p[0], p[1], p[2], 1.0, 1.0)

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        r0, r1, h, c0, c1 = p
        prof = [[r0, -h / 2], [r1, h / 2]]
        if c1:
            prof.append([0.0, h / 2])
        if c0:
            prof.insert(0, [0.0, -h / 2])
        return revolve_arrays(prof, sections=sections, closed_profile=bool(c0 and c1))

    @classmethod
    def volume(cls, p):
        r0, r1, h = p[0], p[1], p[2]
        return float(np.pi * h / 3.0 * (r0 * r0 + r0 * r1 + r1 * r1))

    @classmethod
    def collision(cls, p):
        if abs(p[0] - p[1]) < 1e-9:
            return [CollisionPiece("cylinder", (float(p[0]), float(p[2])))]
        return super().collision((p[0], p[1], p[2], 1.0, 1.0))


class Ring(GeometryTemplate):
    """Hollow cylinder (tube wall) between radii ``r_in`` < ``r_out`` at its bottom,
    height ``h`` centred on z = 0, swept over ``0 <= θ <= arc``. With ``taper`` != 0
    both radii grow by ``taper`` from bottom to top (a tapered bucket or pot wall)."""

    name = "ring"
    params = ("r_out", "r_in", "h", "arc", "taper")

    @staticmethod
    def _slant(h, taper):
        return np.hypot(h, taper)

    @staticmethod
    def _radii(Q):
        """(2, 2, M): [bottom, top] x [outer, inner] radii of the columns of ``Q`` = P.T."""
        RR = np.empty((2, 2, Q.shape[1]))
        RR[0] = Q[0:2]
        np.add(Q[0:2], Q[4], out=RR[1])
        return RR

    @classmethod
    def component_areas(cls, P):
        Q = P.T.copy()  # contiguous rows ro ri h arc tp: small 2-D strided operands are slow
        ro, ri, h, arc, tp = Q
        out = np.empty((6, len(P)))
        # outer wall, inner wall, bottom, top, end at θ = 0, end at θ = arc
        np.multiply(arc * (Q[0:2] + tp / 2), np.hypot(h, tp), out=out[0:2])
        RR = cls._radii(Q)
        RR *= RR  # squared radii
        np.multiply(arc / 2, RR[:, 0] - RR[:, 1], out=out[2:4])
        out[4] = np.where(_is_full(arc), 0.0, (ro - ri) * h)
        out[5] = out[4]
        return out.T.copy()

    @classmethod
    def patches(cls, P):
        # the same arithmetic as ``bands(_WALL_COMP, [ro, ri], [ro + tp, ri + tp], -z, z, arc,
        # inward=_INWARD)`` and the compiled annuli, written out because it runs often
        Q = P.T.copy()
        ro, ri, h, arc, tp = Q
        z = h / 2
        RR = cls._radii(Q)
        r0, r1 = RR[0], RR[1]
        dr = r1 - r0
        dz = z - -z
        slant = np.sqrt(dr * dr + dz * dz)
        s = _OUT_IN_SIGN / np.where(slant > 0, slant, 1.0)
        q = np.empty((2, 7, len(P)))
        q[:, 0:2] = RR.transpose(1, 0, 2)
        q[:, 2] = -z
        q[:, 3] = z
        q[:, 4] = arc
        np.multiply(s, dz, out=q[:, 5])
        np.multiply(-s, dr, out=q[:, 6])
        walls = Patch("band", _COMP01, arc * 0.5 * (r0 + r1) * slant, q)
        RR *= RR  # squared radii
        annuli = linear("sector", _ANNULUS_COMP, P, _RING_CAPS, arc / 2 * (RR[:, 0] - RR[:, 1]))
        out = [walls, annuli]
        if not arc.min() >= TWO_PI - 1e-9:
            partial = ~_is_full(arc)
            ends = np.stack([np.zeros_like(arc), arc])
            ce, se = np.cos(ends), np.sin(ends)
            sg = np.array([[-1.0], [1.0]])  # the θ = 0 end faces -y, the θ = arc end faces +θ
            out.append(rects(_END_COMP, (ri * ce, ri * se, -z), ((ro - ri) * ce, (ro - ri) * se, 0.0),
                             (tp * ce, tp * se, h), (-se * sg, ce * sg, 0.0), scale=partial))
        return out

    @staticmethod
    def _caps(P):
        """The bottom and top annuli (parameters affine in P: compiled once, below)."""
        ro, ri, h, arc, tp = P.T
        z = h / 2
        return sectors(_ANNULUS_COMP, (0.0, 0.0, np.stack([-z, z])), _X, _Y, (0.0, 0.0, _DOWN_UP),
                       np.stack([ri, ri + tp]), np.stack([ro, ro + tp]), arc)

    @staticmethod
    def _profile(p):
        ro, ri, h, tp = p[0], p[1], p[2], p[4]
        return np.array([[ri, -h / 2], [ro, -h / 2], [ro + tp, h / 2], [ri + tp, h / 2]])

    @classmethod
    def sdf(cls, p, x):
        d = polygon_sdf_rows(np.hypot(x[:, 0], x[:, 1]), np.ascontiguousarray(x[:, 2]), cls._profile(p))
        return np.maximum(d, wedge_sdf(x, p[3]))

    @classmethod
    def bounds(cls, p):
        ro, ri, h, arc, tp = p
        return _arc_bounds(min(ri, ri + tp), max(ro, ro + tp), arc, -h / 2, h / 2)

    @classmethod
    def bounds_batch(cls, P):
        ro, ri, h, arc, tp = P.T
        r_hi = np.maximum(ro, ro + tp)
        if arc.min() >= FULL - 1e-9:
            return _turn_boxes(r_hi, -h / 2, h / 2)
        return _arc_bounds_batch(np.minimum(ri, ri + tp), r_hi, arc, -h / 2, h / 2)

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        return revolve_arrays(cls._profile(p), arc=min(p[3], FULL), sections=sections)

    @classmethod
    def volume(cls, p):
        ro, ri, h, arc, tp = p
        # Pappus: profile area times the path length of its centroid
        return float(min(arc, FULL) * (ro - ri) * h * ((ro + ri) / 2 + tp / 2))

    @classmethod
    def collision(cls, p):
        ro, ri, h, arc, tp = (float(v) for v in p)
        return sector_hulls(cls._profile(p), arc, min(ri, ri + tp))


class Sphere(GeometryTemplate):
    """Sphere of radius ``R`` about the origin, cut to the slab ``z_lo <= z <= z_hi``
    (a dome, a bowl bottom, a knob cap); cut planes are closed by flat discs."""

    name = "sphere"
    params = ("R", "z_lo", "z_hi")

    @classmethod
    def component_areas(cls, P):
        R, lo, hi = P.T
        out = np.empty((len(P), 3))
        out[:, 0] = TWO_PI * R * (hi - lo)
        zc = P[:, 1:3]
        out[:, 1:] = np.pi * np.maximum((R * R)[:, None] - zc * zc, 0.0)
        return out

    @classmethod
    def patches(cls, P):
        # ``zones(0, R, lo, hi)`` and ``sectors(_CAP_COMP, (0, 0, [lo, hi]), _X, _Y,
        # (0, 0, _DOWN_UP), 0, sqrt(R² - z²), TWO_PI)`` written out
        R, lo, hi = P.T
        zone = Patch("zone", _COMP0, (TWO_PI * R * (hi - lo))[None], P.T[None].copy())
        zc = P[:, 1:3].T
        r1 = np.sqrt(np.maximum(R * R - zc * zc, 0.0))
        q = np.zeros((2, 15, len(P)))
        q[:, 2] = zc
        q[:, 3] = 1.0
        q[:, 7] = 1.0
        q[:, 11] = _DOWN_UP
        q[:, 13] = r1
        q[:, 14] = TWO_PI
        return [zone, Patch("sector", _COMP12, (0.5 * TWO_PI) * (r1 * r1), q)]

    @classmethod
    def sdf(cls, p, x):
        R, lo, hi = p
        return np.maximum.reduce([np.linalg.norm(x, axis=1) - R, lo - x[:, 2], x[:, 2] - hi])

    @classmethod
    def bounds(cls, p):
        R, lo, hi = p
        r = R if lo <= 0.0 <= hi else math.sqrt(max(R * R - min(lo * lo, hi * hi), 0.0))
        return np.array([[-r, -r, lo], [r, r, hi]])

    @classmethod
    def bounds_batch(cls, P):
        R, lo, hi = P.T
        out = np.empty((len(P), 2, 3))
        r = np.where((lo <= 0) & (hi >= 0), R, np.sqrt(np.maximum(R * R - np.minimum(lo * lo, hi * hi), 0.0)))
        out[:, 1, 0] = r
        out[:, 1, 1] = r
        np.negative(out[:, 1, 0:2], out=out[:, 0, 0:2])
        out[:, :, 2] = P[:, 1:3]
        return out

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        R, lo, hi = p
        a0, a1 = math.asin(max(-1.0, lo / R)), math.asin(min(1.0, hi / R))
        n = max(4, int(sections * (a1 - a0) / math.pi) + 1)
        a = np.linspace(a0, a1, n)
        prof = np.stack([R * np.cos(a), R * np.sin(a)], axis=1)
        prof[np.abs(prof[:, 0]) < 1e-12, 0] = 0.0
        prof = list(prof)
        if prof[-1][0] > 0:
            prof.append(np.array([0.0, hi]))
        if prof[0][0] > 0:
            prof.insert(0, np.array([0.0, lo]))
        return revolve_arrays(prof, sections=sections)

    @classmethod
    def volume(cls, p):
        R, lo, hi = p
        return float(np.pi * ((R * R * hi - hi ** 3 / 3) - (R * R * lo - lo ** 3 / 3)))

    @classmethod
    def collision(cls, p):
        R, lo, hi = p
        if lo <= -R + 1e-9 and hi >= R - 1e-9:
            return [CollisionPiece("sphere", (float(R),))]
        return super().collision(p)


class Torus(GeometryTemplate):
    """Torus about z with centre-line radius ``R`` and tube radius ``r`` (< R), swept over
    ``0 <= θ <= arc``; ``cap0``/``cap1`` close the ends of a partial arc with discs."""

    name = "torus"
    params = ("R", "r", "arc", "cap0", "cap1")

    @classmethod
    def component_areas(cls, P):
        R, r, arc, c0, c1 = P.T
        part = ~_is_full(arc)
        out = np.empty((len(P), 3))
        out[:, 0] = TWO_PI * r * R * arc
        out[:, 1:] = (np.pi * r * r)[:, None] * P[:, 3:5] * part[:, None]
        return out

    @classmethod
    def patches(cls, P):
        R, r, arc, c0, c1 = P.T
        # ``tori(0, R, r, arc)`` written out
        tube = Patch("torus", _COMP0, (TWO_PI * r * R * arc)[None], P[:, 0:3].T[None].copy())
        if arc.min() >= TWO_PI - 1e-9:
            return [tube]
        on = ~_is_full(arc) * P[:, 3:5].T
        if not on.any():
            return [tube]
        ends = np.stack([np.zeros_like(arc), arc])
        ce, se = np.cos(ends), np.sin(ends)
        sg = np.array([[-1.0], [1.0]])
        caps = sectors(_CAP_COMP, (R * ce, R * se, 0.0), (ce, se, 0.0), (0.0, 0.0, 1.0),
                       (-se * sg, ce * sg, 0.0), 0.0, r, TWO_PI, scale=on)
        return [tube, caps]

    @classmethod
    def sdf(cls, p, x):
        R, r, arc = p[0], p[1], p[2]
        rho = np.hypot(x[:, 0], x[:, 1])
        return np.maximum(np.hypot(rho - R, x[:, 2]) - r, wedge_sdf(x, arc))

    @classmethod
    def bounds(cls, p):
        R, r, arc = p[0], p[1], p[2]
        return _arc_bounds(R - r, R + r, arc, -r, r)

    @classmethod
    def solid_params(cls, p):
        return (p[0], p[1], p[2], 1.0, 1.0)

    @classmethod
    def bounds_batch(cls, P):
        R, r, arc = P[:, 0], P[:, 1], P[:, 2]
        if arc.min() >= FULL - 1e-9:
            return _turn_boxes(R + r, -r, r)
        return _arc_bounds_batch(R - r, R + r, arc, -r, r)

    @classmethod
    def _profile(cls, p, sections):
        R, r = p[0], p[1]
        n = max(8, sections // 2)
        a = np.linspace(0.0, TWO_PI, n, endpoint=False)
        return np.stack([R + r * np.cos(a), r * np.sin(a)], axis=1)

    @classmethod
    def mesh_arrays(cls, p, sections=32):
        R, r, arc, c0, c1 = p
        return revolve_arrays(cls._profile(p, sections), arc=min(arc, FULL), sections=sections,
                              cap_start=bool(c0), cap_end=bool(c1))

    @classmethod
    def volume(cls, p):
        R, r, arc = p[0], p[1], p[2]
        return float(np.pi * r * r * R * min(arc, FULL))

    @classmethod
    def collision(cls, p):
        R, r, arc = float(p[0]), float(p[1]), float(p[2])
        return sector_hulls(cls._profile(p, 32), arc, R - r)


def _arc_bounds(r_lo, r_hi, arc, z0, z1):
    """Bounding box of an annular sector r_lo..r_hi, 0..arc, extruded over z0..z1."""
    arc = min(float(arc), FULL)
    angles = [0.0, arc] + [a for a in (0.5 * np.pi, np.pi, 1.5 * np.pi) if a < arc]
    pts = [(r * math.cos(a), r * math.sin(a)) for a in angles for r in (r_lo, r_hi)]
    xy = np.array(pts)
    return np.array([[xy[:, 0].min(), xy[:, 1].min(), z0], [xy[:, 0].max(), xy[:, 1].max(), z1]])


def _turn_boxes(r, z0, z1):
    """Boxes (M, 2, 3) of full turns of radius ``r`` over z0..z1: a square footprint."""
    out = np.empty((len(r), 2, 3))
    out[:, 1, 0] = r
    out[:, 1, 1] = r
    np.negative(out[:, 1, 0:2], out=out[:, 0, 0:2])
    out[:, 0, 2] = z0
    out[:, 1, 2] = z1
    return out


def _arc_bounds_batch(r_lo, r_hi, arc, z0, z1):
    """Vectorised :func:`_arc_bounds` over rows; returns (M, 2, 3)."""
    if arc.min() >= FULL - 1e-9:  # full turns (the common case)
        return _turn_boxes(r_hi, z0, z1)
    M = len(arc)
    out = np.empty((M, 2, 3))
    out[:, 0, 2] = z0
    out[:, 1, 2] = z1
    arc = np.minimum(arc, FULL)
    # candidate angles 0, arc and the quarter turns inside the arc
    cand = np.empty((M, 5))
    cand[:, 0] = 0.0
    cand[:, 1] = arc
    cand[:, 2:] = _QUARTERS
    cs = np.empty((2, M, 5))  # their cosines and sines
    np.cos(cand, out=cs[0])
    np.sin(cand, out=cs[1])
    # x and y of the candidates at both radii, (2, M, 10): 5 angles at r_lo, 5 at r_hi
    v = np.empty((2, M, 10))
    np.multiply(cs, r_lo[:, None], out=v[:, :, :5])
    np.multiply(cs, r_hi[:, None], out=v[:, :, 5:])
    ok = np.ones((M, 10), dtype=bool)
    ok[:, 2:5] = _QUARTERS < arc[:, None]
    ok[:, 5:] = ok[:, :5]
    out[:, 0, 0:2] = np.where(ok, v, np.inf).min(2).T
    out[:, 1, 0:2] = np.where(ok, v, -np.inf).max(2).T
    return out


#: Largest gap (metres) between a curved surface and the flat faces of the convex
#: sectors that replace it in collision geometry: sets how many sectors a ring or torus
#: is cut into (8 to 48 per turn), so a bottle collar needs far fewer pieces than a
#: bucket wall (every piece costs simulators time).
SECTOR_SAGITTA = 5e-4


def sector_hulls(profile: np.ndarray, arc: float, r_concave: float) -> list[CollisionPiece]:
    """Convex hulls of equal sectors of ``profile`` (ρ, z) revolved over ``arc`` radians,
    as few as keep each hull within :data:`SECTOR_SAGITTA` of the concave side at
    radius ``r_concave``. All pieces share one hull (the same vertex and face arrays)
    placed by their ``pose``, a turn about z, so exporters can write it once."""
    arc = min(float(arc), FULL)
    r = max(float(r_concave), 1e-6)
    step = 2.0 * math.acos(max(-1.0, 1.0 - SECTOR_SAGITTA / r))
    n_turn = int(np.clip(math.ceil(FULL / step), 8, 48))
    n = max(1, int(math.ceil(arc / (FULL / n_turn) - 1e-9)))
    a = arc / n
    V, F = convex_hull(revolve_arrays(profile, arc=a, sections=max(2, int(math.ceil(FULL / a))))[0])
    return [CollisionPiece("mesh", pose=rot_z(i * a), vertices=V, faces=F) for i in range(n)]


# ---------------------------------------------------------------- constructors

def cylinder(radius: float, height: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Closed cylinder of ``radius`` and ``height`` (metres) along local z, centred."""
    return _tuple_new(Primitive, (Frustum, (float(radius), float(radius), float(height), 1.0, 1.0), pose, role))


def frustum(r_bottom: float, r_top: float, height: float, pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Closed frustum (a cone when ``r_top`` = 0) along local z, centred."""
    return _tuple_new(Primitive, (Frustum, (float(r_bottom), float(r_top), float(height), 1.0, 1.0), pose, role))


def ring(r_out: float, r_in: float, height: float, arc: float = FULL, pose: np.ndarray = IDENTITY,
         role: str = "", taper: float = 0.0) -> Primitive:
    """Hollow cylinder wall (radii at the bottom), optionally a partial arc (radians)
    starting at +x, optionally tapered (radii grow by ``taper`` towards the top)."""
    return _tuple_new(Primitive, (Ring, (float(r_out), float(r_in), float(height), float(arc), float(taper)),
                                  pose, role))


def sphere(radius: float, z_lo: float | None = None, z_hi: float | None = None,
           pose: np.ndarray = IDENTITY, role: str = "") -> Primitive:
    """Sphere (segment): keeps ``z_lo <= z <= z_hi`` of a sphere centred at ``pose``."""
    lo = -radius if z_lo is None else z_lo
    hi = radius if z_hi is None else z_hi
    return _tuple_new(Primitive, (Sphere, (float(radius), float(lo), float(hi)), pose, role))


def torus(R: float, r: float, arc: float = FULL, pose: np.ndarray = IDENTITY, role: str = "",
          caps: tuple[bool, bool] = (True, True)) -> Primitive:
    """Torus (arc) about local z; centre-line radius ``R``, tube radius ``r``."""
    return _tuple_new(Primitive, (Torus, (float(R), float(r), float(arc), float(caps[0]), float(caps[1])), pose, role))


# cap parameters are affine in the template parameters: one matrix product per object
_FRUSTUM_CAPS = compile_linear(Frustum._caps, len(Frustum.params))
_RING_CAPS = compile_linear(Ring._caps, len(Ring.params))
