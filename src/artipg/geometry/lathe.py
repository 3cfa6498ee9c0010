"""The lathe family: a closed (ρ, z) profile of line segments and arcs revolved about
the local z axis over ``0 <= θ <= arc`` (from +x towards +y).

``Lathe(n)`` is the family of ``n``-segment profiles. A row holds, per profile vertex,
``(r, z, b, on)`` (the vertex, the bulge of the segment leaving it, see
:mod:`artipg.geometry.profile`, and whether that segment's surface is part of the
sampled surface), then ``arc``, ``cap0``, ``cap1`` (whether the flat ends at θ = 0 and
θ = arc are sampled; they exist only for partial turns). The profile runs
counter-clockwise in the (ρ, z) plane with ρ >= 0; a profile that touches the axis
gives a solid, one that does not a hollow (ring-like) solid; segments on the axis have
no area. ``on = 0`` segments and ends are open joints (the inside of a swept tube):
the solid (SDF, mesh, volume) stays closed, only sampling and area leave them out.

The flat ends of partial turns are triangle cells for polygonal profiles, disc
(sector) cells for circle profiles (the torus), and regions sampled by rejection for
other profiles with arcs (:mod:`artipg.geometry.family`).

Thin constructors: :func:`cylinder`, :func:`frustum` (a cone), :func:`ring` (a hollow
wall, optionally tapered or partial), :func:`sphere` (a slab) and :func:`torus`.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import profile
from artipg.geometry.base import TWO_PI, CollisionPiece, Primitive, convex_hull, wedge_sdf
from artipg.geometry.family import Family, Region, convex_pieces, rejection_region, row_triangles, triangulate, weld
from artipg.geometry.patches import sectors, tris
from artipg.geometry.revolve import arc_bounds, revolve_arrays, sector_hulls
from artipg.geometry.revolved import cells
from artipg.geometry.transforms import IDENTITY

_FULL = TWO_PI - 1e-9


class Lathe(Family):
    """Profiles of ``key`` segments revolved about z (see the module docstring)."""

    kind = "lathe"

    def param_names(self):
        n = self.key
        return tuple(f"{c}{i}" for i in range(n) for c in ("r", "z", "b", "on")) + ("arc", "cap0", "cap1")

    def n_components(self):
        return self.key + 2  # the segments' surfaces, then the ends at θ = 0 and θ = arc

    @staticmethod
    def loop(p) -> np.ndarray:
        """The profile loop (n, 3) of row ``p``: rows (ρ, z, bulge)."""
        p = np.asarray(p, dtype=float)
        return p[:-3].reshape(-1, 4)[:, :3]

    def _split(self, P):
        n = self.key
        V = P[:, :4 * n].reshape(len(P), n, 4)
        return V, P[:, 4 * n], P[:, 4 * n + 1:4 * n + 3]

    def _patches(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        V, arc, caps = self._split(P)
        arc = np.minimum(arc, TWO_PI)
        r0, z0, b, on = V[..., 0].T, V[..., 1].T, V[..., 2].T, V[..., 3].T
        r1, z1 = np.roll(r0, -1, axis=0), np.roll(z0, -1, axis=0)
        walls = cells(np.arange(self.key), (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0),
                      r0, z0, r1, z1, b, arc, scale=on)
        out = [walls]
        if not (V[..., 2] != 0).any() and (arc < _FULL).any():
            out += self._end_tris(V, arc, caps)
        circ = self._circles(V)
        if circ.any() and (arc < _FULL).any():
            out.append(self._end_discs(V, arc, caps * (circ * (arc < _FULL))[:, None]))
        return out

    def _circles(self, V) -> np.ndarray:
        """(M,) 1.0 where the profile is a circle (two half circles: a torus): its ends
        are discs, sector cells, instead of rejection-sampled regions."""
        if self.key != 2:
            return np.zeros(len(V))
        return ((V[:, 0, 2] == 1.0) & (V[:, 1, 2] == 1.0)).astype(float)

    def _end_discs(self, V, arc, on):
        """The disc ends (comps n, n+1) of circle profiles, switched on by ``on`` (M, 2)."""
        centre = 0.5 * (V[:, 0, :2] + V[:, 1, :2])
        rad = 0.5 * np.hypot(*(V[:, 0, :2] - V[:, 1, :2]).T)
        ends = np.stack([np.zeros_like(arc), arc])
        ce, se = np.cos(ends), np.sin(ends)
        sg = np.array([[-1.0], [1.0]])  # the θ = 0 end faces -θ, the θ = arc end +θ
        rho, z = centre[:, 0], centre[:, 1]
        return sectors(np.array([self.key, self.key + 1]), (rho * ce, rho * se, z), (ce, se, 0.0), (0.0, 0.0, 1.0),
                       (-se * sg, ce * sg, 0.0), 0.0, rad, TWO_PI, scale=on.T)

    def _end_tris(self, V, arc, caps):
        """The flat ends of partial turns of polygonal profiles as triangles (comps n, n+1)."""
        n = self.key
        T = row_triangles(V.reshape(len(V), -1), lambda row: [row.reshape(n, 4)[:, :2]], V[..., :2], (n,),
                          self.__dict__.setdefault("_tri", {}))
        part = (arc < _FULL).astype(float)
        A, B, C = (V[np.arange(len(V))[:, None], T[:, :, k], :2].transpose(1, 0, 2) for k in range(3))
        out = []
        for e, ang in ((0, np.zeros_like(arc)), (1, arc)):
            c, s = np.cos(ang), np.sin(ang)
            sg = -1.0 if e == 0 else 1.0
            # (ρ, z) -> (ρ cos a, ρ sin a, z); the θ = 0 end faces -y, the θ = arc end +θ
            def lift(Q):
                return (Q[..., 0] * c, Q[..., 0] * s, Q[..., 1])
            o, a1, b1 = lift(A), lift(B - A), lift(C - A)
            t = tris(np.full(T.shape[1], self.key + e), o, a1, b1, (-s * sg, c * sg, 0.0),
                     scale=part * caps[:, e])
            out.append(t)
        return out

    def regions(self, P):
        P = np.atleast_2d(np.asarray(P, dtype=float))
        V, arc, caps = self._split(P)
        if not (V[..., 2] != 0).any() or not (arc < _FULL).any():
            return []
        area = np.abs(profile.loop_area(V[..., :3])) * (arc < _FULL) * (1.0 - self._circles(V))
        out = []
        for e in (0, 1):
            def ang(p, e=e):
                return 0.0 if e == 0 else min(p[-3], TWO_PI)

            def ex(p, ang=ang):
                return np.array([math.cos(ang(p)), math.sin(ang(p)), 0.0])

            def nrm(p, e=e, ang=ang):
                sg = -1.0 if e == 0 else 1.0
                return sg * np.array([-math.sin(ang(p)), math.cos(ang(p)), 0.0])

            draw = rejection_region(lambda p: [self.loop(p)], lambda p: np.zeros(3), ex,
                                    lambda p: np.array([0.0, 0.0, 1.0]), nrm)
            out.append(Region(self.key + e, area * caps[:, e], draw))
        return out

    def sdf(self, p, x):
        """Exact for full turns (the 2-D distance in the meridian half-plane); partial
        turns take the max with the wedge's planes: exact sign, a lower bound of the
        distance outside the wedge."""
        x = np.asarray(x, dtype=float)
        q = np.column_stack([np.hypot(x[:, 0], x[:, 1]), x[:, 2]])
        loop = self.loop(p)
        d = profile.sdf([loop], q, [_on_axis(loop)])
        return np.maximum(d, wedge_sdf(x, min(p[-3], TWO_PI)))

    def bounds(self, p):
        return self.bounds_batch(np.asarray(p, dtype=float)[None])[0]

    def bounds_batch(self, P):
        V, arc, _ = self._split(np.asarray(P, dtype=float))
        b = profile.bounds(V[..., :3])  # (M, 2, 2) in (ρ, z)
        return arc_bounds(np.maximum(b[:, 0, 0], 0.0), b[:, 1, 0], np.minimum(arc, TWO_PI), b[:, 0, 1], b[:, 1, 1])

    def _poly(self, p, sections):
        """The profile as a polygon: arcs get ``sections`` chords per half turn (a
        sphere's meridian as fine as its ``sections`` per turn around the axis)."""
        poly = profile.polygonise(self.loop(p), 2 * sections)
        keep = np.any(poly != np.roll(poly, 1, axis=0), axis=1)  # drop repeated vertices
        poly = poly[keep]
        poly[:, 0] = np.maximum(poly[:, 0], 0.0)
        return poly

    def mesh_arrays(self, p, sections=32):
        poly = self._poly(p, sections)
        arc = min(float(p[-3]), TWO_PI)
        if arc >= _FULL:
            return revolve_arrays(poly, sections=sections)
        V, F = revolve_arrays(poly, arc=arc, sections=sections, cap_start=False, cap_end=False)
        T = triangulate([poly])
        parts_V, parts_F = [V], [F]
        base = len(V)
        n_sec = max(2, int(math.ceil(sections * arc / TWO_PI)))
        th_end = np.linspace(0.0, arc, n_sec + 1)[-1]
        for th, flip in ((0.0, False), (th_end, True)):
            E = np.column_stack([poly[:, 0] * math.cos(th), poly[:, 0] * math.sin(th), poly[:, 1]])
            parts_V.append(E)
            parts_F.append((T[:, ::-1] if flip else T) + base)
            base += len(E)
        return weld(np.concatenate(parts_V), np.concatenate(parts_F))

    def volume(self, p):
        """Pappus: arc x ∫∫ ρ dA of the profile, in closed form."""
        return float(min(p[-3], TWO_PI) * moment(self.loop(p)))

    def collision(self, p):
        """Convex pieces of the profile (triangulation merged greedily), each revolved:
        one hull for a full turn of a piece on the axis, else equal convex sectors; a
        cylinder and a whole sphere give the simulators' own shapes."""
        prim = Primitive(self, tuple(p))
        cyl = frustum_dims(prim)
        if cyl is not None and abs(cyl[0] - cyl[1]) < 1e-9 and p[-3] >= _FULL:
            return [CollisionPiece("cylinder", (float(cyl[0]), float(cyl[2])))]
        R = ball_radius(prim)
        if R is not None:
            return [CollisionPiece("sphere", (float(R),))]
        arc = min(float(p[-3]), TWO_PI)
        out = []
        for piece in convex_pieces([self._poly(p, 24)]):
            if arc >= _FULL and piece[:, 0].min() <= 1e-12:
                V, F = convex_hull(revolve_arrays(piece, sections=24)[0])
                out.append(CollisionPiece("mesh", vertices=V, faces=F))
            else:
                out += sector_hulls(piece, arc, piece[:, 0].min())
        return out

    def uv_bounds(self, p):
        R = _rim(self.loop(p))
        return np.array([[0.0, 0.0], [max(min(float(p[-3]), TWO_PI) * R, 2 * R),
                                       max(profile.perimeter(self.loop(p))[-1], 2 * R)]])

    def uv_seams(self, p, n=None):
        loop = self.loop(p)
        side = None if n is None else ~_flat(n)
        out = [(0, 0.0, TWO_PI * _rim(loop), side)] if min(float(p[-3]), TWO_PI) >= _FULL else []
        if not _on_axis(loop).any():  # a profile off the axis (a torus, a bent tube) wraps at its start
            out.append((1, 0.0, float(profile.perimeter(loop)[-1]), side))
        return out

    def uv_poles(self, p, x, n=None):
        pole = np.hypot(x[:, 0], x[:, 1]) <= 1e-9 * max(_rim(self.loop(p)), 1e-9)
        return pole if n is None else pole & ~_flat(n)

    def uv(self, p, x, n=None):
        """Faces facing up or down (normals ``n`` within 2.6 degrees of z, when given):
        planar, u = x + R, v = y + R (m), R the profile's largest radius (a round table
        top is cut from straight planks). Elsewhere u = θ R (m), so a texture keeps its
        scale on the rim, and v = arc length (m) along the profile of the closest profile
        point, in [0, perimeter]."""
        x = np.asarray(x, dtype=float)
        arc = min(float(p[-3]), TWO_PI)
        th = np.mod(np.arctan2(x[:, 1], x[:, 0]), TWO_PI)
        if arc < _FULL:
            th = np.where(th > 0.5 * (arc + TWO_PI), 0.0, np.minimum(th, arc))
        q = np.column_stack([np.hypot(x[:, 0], x[:, 1]), x[:, 2]])
        loop = self.loop(p)
        R = _rim(loop)
        uv = np.column_stack([th * R, profile.loop_length_at(loop, q, _on_axis(loop))])
        if n is not None:
            flat = _flat(n)
            uv[flat] = x[flat, :2] + R
        return uv


def _flat(n) -> np.ndarray:
    """Mask (N,) of normals ``n`` (N, 3) within 2.6 degrees of the z axis."""
    return np.abs(np.asarray(n, dtype=float)[:, 2]) > 0.999


def _rim(loop) -> float:
    """The largest radius (m) of a profile loop."""
    return float(profile.bounds(loop)[1, 0])


def _on_axis(loop) -> np.ndarray:
    """Mask (n,) of the straight profile segments lying on the axis (no surface)."""
    return (loop[:, 0] == 0.0) & (np.roll(loop[:, 0], -1) == 0.0) & (loop[:, 2] == 0.0)


def moment(loop) -> float:
    """∫∫ ρ dA over a counter-clockwise (ρ, z) profile loop (n, 3), m^3: Green's
    ∮ ρ²/2 dz, in closed form per line segment and arc."""
    p0, p1, b = profile.segments(np.asarray(loop, dtype=float))
    r0, z0, r1, z1 = p0[:, 0], p0[:, 1], p1[:, 0], p1[:, 1]
    line = (z1 - z0) * (r0 * r0 + r0 * r1 + r1 * r1) / 6.0
    c, R, a0, d = profile.arc_geometry(p0, p1, b)
    R = np.where(np.isfinite(R), R, 0.0)
    a1 = a0 + d

    def F(a):  # ∫ (c + R cos a)² R cos a / 2 da
        cr = c[:, 0]
        return 0.5 * R * (cr * cr * np.sin(a) + 2 * cr * R * (a / 2 + np.sin(2 * a) / 4)
                          + R * R * (np.sin(a) - np.sin(a) ** 3 / 3))

    return float(np.where(b == 0.0, line, F(a1) - F(a0)).sum())


# ---------------------------------------------------------------- constructors

def lathe(loop, arc: float = TWO_PI, on=None, caps=(True, True), pose: np.ndarray = IDENTITY,
          role: str = "") -> Primitive:
    """A lathe primitive of a (ρ, z) profile loop (n, 3) (oriented counter-clockwise
    here); ``on`` (n,) flags the sampled segments (default all)."""
    loop = np.array(loop, dtype=float)
    if (loop[:, 0] < -1e-12).any():
        raise ValueError("a lathe profile needs ρ >= 0")
    flip = profile.loop_area(loop) < 0
    loop = profile.oriented(loop, True)
    n = len(loop)
    on = np.ones(n) if on is None else np.asarray(on, dtype=float)
    if flip:  # keep each flag with its segment: reversed segment k is old n-2-k
        on = np.roll(on[::-1], -1)
    row = np.column_stack([loop, on]).ravel()
    params = tuple(float(v) for v in row) + (float(arc), float(caps[0]), float(caps[1]))
    return Primitive(Lathe(n), params, pose, role)


def frustum(r_bottom: float, r_top: float, height: float, pose: np.ndarray = IDENTITY, role: str = "",
            caps=(True, True)) -> Primitive:
    """A frustum (a cone when ``r_top`` = 0) along local z, centred on the origin;
    ``caps`` (bottom, top) False leaves that disc out of the sampled surface (the solid
    stays closed)."""
    h = float(height) / 2
    return _counter_clockwise(_L4, (0.0, -h, 0.0, float(caps[0]), float(r_bottom), -h, 0.0, 1.0,
                                    float(r_top), h, 0.0, float(caps[1]), 0.0, h, 0.0, 0.0, TWO_PI, 1.0, 1.0),
                              pose, role)


def cylinder(radius: float, height: float, pose: np.ndarray = IDENTITY, role: str = "", caps=(True, True)) -> Primitive:
    """A cylinder of ``radius`` and ``height`` (metres) along local z, centred."""
    return frustum(radius, radius, height, pose, role, caps)


def ring(r_out: float, r_in: float, height: float, arc: float = TWO_PI, pose: np.ndarray = IDENTITY,
         role: str = "", taper: float = 0.0) -> Primitive:
    """A hollow cylinder wall between radii ``r_in`` < ``r_out`` (at the bottom; both
    grow by ``taper`` to the top), height ``height`` centred on z = 0, over ``arc``
    radians from +x."""
    h, ri, ro, tp = float(height) / 2, float(r_in), float(r_out), float(taper)
    return _counter_clockwise(_L4, (ri, -h, 0.0, 1.0, ro, -h, 0.0, 1.0, ro + tp, h, 0.0, 1.0, ri + tp, h, 0.0, 1.0,
                                    float(arc), 1.0, 1.0), pose, role)


def sphere(radius: float, z_lo: float | None = None, z_hi: float | None = None, pose: np.ndarray = IDENTITY,
           role: str = "", arc: float = TWO_PI) -> Primitive:
    """The slab ``z_lo <= z <= z_hi`` of a sphere of ``radius`` about the origin (a
    dome, a bowl bottom, a knob cap), closed by flat discs, optionally over a partial
    turn."""
    R = float(radius)
    lo = -R if z_lo is None else float(z_lo)
    hi = R if z_hi is None else float(z_hi)
    a0, a1 = math.asin(max(-1.0, lo / R)), math.asin(min(1.0, hi / R))
    r_lo, r_hi = math.sqrt(max(R * R - lo * lo, 0.0)), math.sqrt(max(R * R - hi * hi, 0.0))
    return _counter_clockwise(_L4, (0.0, lo, 0.0, 1.0, r_lo, lo, math.tan((a1 - a0) / 4), 1.0, r_hi, hi, 0.0, 1.0,
                                    0.0, hi, 0.0, 1.0, float(arc), 1.0, 1.0), pose, role)


def torus(R: float, r: float, arc: float = TWO_PI, pose: np.ndarray = IDENTITY, role: str = "",
          caps=(True, True)) -> Primitive:
    """A torus (arc) about local z: centre-line radius ``R``, tube radius ``r`` (two
    half-circle arcs revolved); ``caps`` close the ends of a partial arc."""
    R, r = float(R), float(r)
    return _counter_clockwise(_L2, (R + r, 0.0, 1.0, 1.0, R - r, 0.0, 1.0, 1.0, float(arc), float(caps[0]),
                                    float(caps[1])), pose, role)


def _counter_clockwise(geom, params: tuple, pose, role) -> Primitive:
    """A lathe primitive of a row whose profile the caller built counter-clockwise
    (the thin constructors: no orientation test, no arrays; they run dozens of times
    per object)."""
    return tuple.__new__(Primitive, (geom, params, pose, role))


_L2, _L4 = Lathe(2), Lathe(4)


def ring_dims(prim: Primitive) -> tuple | None:
    """``(r_out, r_in, height, arc, taper)`` of a primitive :func:`ring` made (a
    four-segment profile off the axis), else None."""
    p = prim.params
    if prim.geom is not _L4 or p[0] <= 0.0:
        return None
    return p[4], p[0], p[9] - p[1], p[16], p[8] - p[4]


def frustum_dims(prim: Primitive) -> tuple | None:
    """``(r_bottom, r_top, height)`` of a primitive :func:`frustum` or :func:`cylinder`
    made (a straight four-segment profile closed on the axis), else None."""
    p = prim.params
    if prim.geom is not _L4 or p[0] != 0.0 or p[12] != 0.0 or p[16] < _FULL:
        return None
    straight = p[2] == 0.0 and p[6] == 0.0 and p[10] == 0.0
    flat_ends = p[1] == p[5] and p[9] == p[13]
    if not (straight and flat_ends and p[1] == -p[9]):  # a centred frustum, nothing else
        return None
    return p[4], p[8], p[9] - p[1]


def ball_radius(prim: Primitive) -> float | None:
    """The radius of a primitive :func:`sphere` made whole (both poles, a full turn),
    else None."""
    p = prim.params
    if prim.geom is not _L4 or p[0] != 0.0 or p[12] != 0.0 or p[6] == 0.0 or p[16] < _FULL:
        return None
    R = -p[1]
    return R if p[4] == 0.0 and p[8] == 0.0 and p[9] == R > 0.0 else None
