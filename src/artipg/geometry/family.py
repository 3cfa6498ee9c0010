"""Base class of the general geometry families (lathe, extrusion, rounded box).

A family's parameter count depends on its shape (how many profile segments, how many
holes), while the :class:`artipg.geometry.base.GeometryTemplate` interface works on
stacked rows ``P`` (M, p) of one fixed width. So a family is an *instance* per shape
key (for example ``Lathe(4)``: four-segment profiles), made once and cached: equal keys
give the same object, which is what :class:`artipg.annotate.points.PrimitiveTable`
groups rows by. Every method works on rows of that one width, as for the templates.

Sampling goes through patch cells: the families of :mod:`artipg.geometry.patches` plus
the ``revolved`` cells of :mod:`artipg.geometry.revolved`. Planar faces bounded by arcs
(an extrusion cap with a rounded corner, the end of a partial torus) have no
closed-form two-uniform cell here; a family returns them from :meth:`Family.regions`
and they are sampled exactly by rejection in their bounding rectangle against the
exact inside test of :mod:`artipg.geometry.profile`.
"""

from __future__ import annotations

from typing import Callable, ClassVar, NamedTuple

import numpy as np

from artipg.geometry.base import GeometryTemplate, pick
from artipg.geometry.patches import sample_family


class Region(NamedTuple):
    """A planar face sampled by rejection: component ``comp``, areas (M,) and
    ``draw(p, k, rng)`` giving (6, k) points and normals on the face of row ``p``."""

    comp: int
    area: np.ndarray
    draw: Callable


class Family(GeometryTemplate):
    """A geometry family of one shape key (instances are cached per key)."""

    _cache: ClassVar[dict]
    kind: ClassVar[str] = ""

    def __new__(cls, key):
        key = tuple(key) if isinstance(key, (list, tuple)) else key
        got = cls.__dict__.get("_cache")
        if got is None:
            got = cls._cache = {}
        if key not in got:
            obj = super().__new__(cls)
            obj.key = key
            obj.name = f"{cls.kind}{key}"
            obj.params = obj.param_names()
            got[key] = obj
        return got[key]

    def __reduce__(self):
        return (type(self), (self.key,))

    def __repr__(self):
        return f"{type(self).__name__}({self.key!r})"

    # ------------------------------------------------------------ to implement
    def param_names(self) -> tuple[str, ...]:  # pragma: no cover - abstract
        raise NotImplementedError

    def _patches(self, P) -> list:  # pragma: no cover - abstract
        """The cells of rows ``P`` (M, p) (see :meth:`patches`)."""
        raise NotImplementedError

    def regions(self, P) -> list[Region]:
        """Planar faces sampled by rejection (none by default)."""
        return []

    def uv(self, p, x: np.ndarray, n: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        """Texture coordinates (N, 2) of surface points ``x`` with normals ``n`` (N, 3)."""
        raise NotImplementedError

    def uv_bounds(self, p) -> np.ndarray:  # pragma: no cover - abstract
        """Range (2, 2) of :meth:`uv` on the surface of row ``p``: [[u_lo, v_lo], [u_hi, v_hi]]."""
        raise NotImplementedError

    def uv_seams(self, p, n: np.ndarray | None = None) -> list[tuple]:
        """Where :meth:`uv` wraps around: (coordinate, lo, hi, mask) for each interval of
        a texture coordinate that is periodic with period hi - lo (a closed surface of
        revolution, a closed outline's sides); ``mask`` (N,) marks the points of normals
        ``n`` (N, 3) that the wrap concerns (None: all). None by default."""
        return []

    def uv_poles(self, p, x: np.ndarray, n: np.ndarray | None = None) -> np.ndarray | None:
        """Mask (N,) of points ``x`` (normals ``n``) where :meth:`uv` is undefined along
        its first coordinate (a lathe's axis), or None where there are none."""
        return None

    # ------------------------------------------------------------ shared
    def patches(self, P) -> list:
        """The surface of rows ``P`` (M, p) as :class:`artipg.geometry.patches.Patch`
        blocks. The last rows' blocks are kept (read-only): a table asks for the areas,
        then the cells, of the same rows."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        key = (P.shape, P.tobytes())
        last = self.__dict__.get("_last")
        if last is not None and last[0] == key:
            return last[1]
        blocks = self._patches(P)
        for b in blocks:
            b.area.flags.writeable = False
            b.params.flags.writeable = False
        self._last = (key, blocks)
        return blocks

    def component_areas(self, P) -> np.ndarray:
        P = np.atleast_2d(np.asarray(P, dtype=float))
        C = self.n_components()
        out = np.zeros((len(P), C))
        for b in self.patches(P):
            np.add.at(out.T, b.comp, b.area)
        for r in self.regions(P):
            out[:, r.comp] += r.area
        return out

    def n_components(self) -> int:  # pragma: no cover - abstract
        raise NotImplementedError

    def sample_components(self, P, comp, rng):
        """One area-uniform point and outward normal per row of ``P`` on component
        ``comp`` (k,): each point picks a cell (or region) of its component by area."""
        P = np.atleast_2d(np.asarray(P, dtype=float))
        blocks, regions = self.patches(P), self.regions(P)
        area = np.concatenate([b.area for b in blocks] + [r.area[None] for r in regions]).T
        pcomp = np.concatenate([b.comp for b in blocks] + [np.array([r.comp]) for r in regions])
        which = pick(np.where(pcomp[None, :] == comp[:, None], area, 0.0), rng)
        out = np.empty((6, len(P)))
        start = 0
        for b in blocks:
            sel = np.flatnonzero((which >= start) & (which < start + len(b.comp)))
            if len(sel):
                out[:, sel] = sample_family(b.family, b.params[which[sel] - start, :, sel].T, rng)
            start += len(b.comp)
        for r in regions:
            sel = np.flatnonzero(which == start)
            if len(sel):  # one rejection draw per distinct primitive row, not per point
                U, inv = np.unique(P[sel], axis=0, return_inverse=True)
                inv = inv.reshape(-1)
                for j, p in enumerate(U):
                    hit = sel[inv == j]
                    out[:, hit] = r.draw(p, len(hit), rng)
            start += 1
        return out[:3].T, out[3:].T

    def sample_many(self, p, k: int, rng) -> tuple[np.ndarray, np.ndarray]:
        """``k`` area-uniform points (k, 3) and outward normals (k, 3) of one row ``p``:
        the cells of the row are made once, each point picks one by area."""
        P = np.asarray(p, dtype=float)[None]
        blocks, regions = self.patches(P), self.regions(P)
        area = np.concatenate([b.area[:, 0] for b in blocks] + [r.area for r in regions])
        cum = np.cumsum(area)
        which = np.minimum(np.searchsorted(cum, rng.random(k) * cum[-1], side="right"), len(area) - 1)
        out = np.empty((6, k))
        start = 0
        for b in blocks:
            sel = np.flatnonzero((which >= start) & (which < start + len(b.comp)))
            if len(sel):
                out[:, sel] = sample_family(b.family, b.params[which[sel] - start, :, 0].T, rng)
            start += len(b.comp)
        for r in regions:
            sel = np.flatnonzero(which == start)
            if len(sel):
                out[:, sel] = r.draw(P[0], len(sel), rng)
            start += 1
        return out[:3].T, out[3:].T


def weld(V: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Merge bit-identical vertices and drop the faces that collapse (mesh helpers build
    parts separately and join them where they compute the same coordinates)."""
    U, inv = np.unique(V, axis=0, return_inverse=True)
    F = inv.reshape(-1)[F]
    keep = (F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])
    F = F[keep]
    used, F2 = np.unique(F, return_inverse=True)
    return U[used], F2.reshape(-1, 3).astype(np.int64)


def triangulate(rings: list[np.ndarray]) -> np.ndarray:
    """Counter-clockwise triangles (T, 3) of a polygon with holes: ``rings`` (k_i, 2),
    the outer first; indices into their concatenation (mapbox earcut)."""
    import mapbox_earcut

    V = np.concatenate(rings)
    ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
    T = np.asarray(mapbox_earcut.triangulate_float64(V, ends), dtype=np.int64).reshape(-1, 3)
    a, b, c = V[T[:, 0]], V[T[:, 1]], V[T[:, 2]]
    cw = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    T[cw] = T[cw][:, ::-1]
    return T


def row_triangles(P: np.ndarray, rings_of, V: np.ndarray | None = None, sizes=(), memo: dict | None = None
                  ) -> np.ndarray:
    """Triangles (M, t, 3) of the polygon ``rings_of(p)`` of every row of ``P`` (M, p),
    triangulated once per distinct row and padded with degenerate (0, 0, 0) triangles
    to the largest count (n - 2 for a simple n-gon; fewer if earcut drops degenerate
    ones).

    With the rows' ring vertices ``V`` (M, v, 2) (rings of ``sizes`` vertices, one after
    the other) and a ``memo`` dict, one triangulation kept in the memo serves every row
    it is valid for (all its triangles counter-clockwise and their areas summing to
    the polygon's: the common case of rows of one shape), without earcut per row."""
    if V is not None and memo is not None:
        T0 = memo.get("T")
        if T0 is None:
            T0 = memo["T"] = triangulate(rings_of(P[0]))
        A, B, C = V[:, T0[:, 0]], V[:, T0[:, 1]], V[:, T0[:, 2]]
        cr = (B[..., 0] - A[..., 0]) * (C[..., 1] - A[..., 1]) - (B[..., 1] - A[..., 1]) * (C[..., 0] - A[..., 0])
        area, s0 = np.zeros(len(V)), 0
        for n in sizes:  # shoelace of each ring (holes clockwise: negative)
            R = V[:, s0:s0 + n]
            R1 = np.concatenate([R[:, 1:], R[:, :1]], axis=1)
            area += (R[..., 0] * R1[..., 1] - R1[..., 0] * R[..., 1]).sum(axis=1)
            s0 += n
        if (cr > 0).all() and (np.abs(cr.sum(axis=1) - area) <= 1e-9 * np.abs(area)).all():
            return np.broadcast_to(T0, (len(V),) + T0.shape)
    U, inv = np.unique(P, axis=0, return_inverse=True)
    Ts = [triangulate(rings_of(p)) for p in U]
    t = max(len(x) for x in Ts)
    T = np.stack([np.concatenate([x, np.zeros((t - len(x), 3), dtype=np.int64)]) for x in Ts])
    return T[inv.reshape(-1)]


def convex_pieces(rings: list[np.ndarray]) -> list[np.ndarray]:
    """Convex polygons (k, 2) covering a polygon with holes: its triangulation, with
    diagonals removed greedily while the merged piece stays convex (Hertel-Mehlhorn: at
    most four times the minimum number of pieces)."""
    V = np.concatenate(rings)
    pieces = [list(t) for t in triangulate(rings)]
    merged = True
    while merged:
        merged = False
        for i in range(len(pieces)):
            for j in range(i + 1, len(pieces)):
                m = _merge(pieces[i], pieces[j], V)
                if m is not None:
                    pieces[i] = m
                    del pieces[j]
                    merged = True
                    break
            if merged:
                break
    return [V[p] for p in pieces]


def _merge(a: list, b: list, V: np.ndarray):
    """The union of counter-clockwise convex polygons ``a``, ``b`` (vertex indices) if
    they share an edge and the union is convex, else None."""
    for i in range(len(a)):
        u, w = a[i], a[(i + 1) % len(a)]
        for j in range(len(b)):
            if b[j] == w and b[(j + 1) % len(b)] == u:
                poly = a[:i + 1] + [b[(j + 1 + k) % len(b)] for k in range(1, len(b) - 1)] + a[i + 1:]
                P = V[poly]
                e = np.roll(P, -1, axis=0) - P
                cr = e[:, 0] * np.roll(e, -1, axis=0)[:, 1] - e[:, 1] * np.roll(e, -1, axis=0)[:, 0]
                return poly if (cr >= -1e-12 * np.abs(e).max() ** 2).all() else None
    return None


def rejection_region(loops_of, origin, ex, ey, normal):
    """A :class:`Region` draw for planar outline faces: ``loops_of(p)`` gives the row's
    outline (loops of :mod:`artipg.geometry.profile`) in plane coordinates; the face is
    ``origin(p) + a ex(p) + b ey(p)`` with unit normal ``normal(p)`` (3-vectors)."""
    from artipg.geometry import profile

    def draw(p, k, rng):
        loops = loops_of(p)
        b = profile.bounds(loops[0])
        got = np.empty((0, 2))
        while len(got) < k:
            q = b[0] + rng.random((2 * k + 8, 2)) * (b[1] - b[0])
            got = np.concatenate([got, q[profile.inside(loops, q)]])
        q = got[:k]
        X = origin(p)[None] + q[:, :1] * ex(p)[None] + q[:, 1:] * ey(p)[None]
        return np.concatenate([X.T, np.repeat(np.asarray(normal(p), float)[:, None], k, axis=1)])

    return draw
