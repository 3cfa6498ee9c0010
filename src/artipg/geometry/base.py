"""Base class of the geometry templates and the primitive instance that places one.

A geometry template is a family of solids with a fixed-length parameter vector. Every
method works on *arrays* of parameter vectors so that an object's primitives of one
kind are sampled in a single vectorised call:

- ``area(P)``: surface area of each row of ``P`` (M, p), square metres;
- ``sample(P, rng)``: one area-uniform surface point and outward unit normal per row;
- ``sdf(p, x)``: signed distance (negative inside, exact on the surface) of points;
- ``bounds(p)``: (2, 3) axis-aligned bounding box in the template's local frame;
- ``mesh(p)``: a watertight ``trimesh.Trimesh`` (built only when exporting);
- ``collision(p)``: convex pieces for simulators (see :class:`CollisionPiece`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar, NamedTuple

import numpy as np

from artipg.geometry.patches import sample_family
from artipg.geometry.transforms import IDENTITY, apply

TWO_PI = 2.0 * np.pi


#: Named geometry templates (every subclass that sets ``name``), by name.
_BY_NAME: dict[str, type] = {}


def template_named(name: str) -> type:
    """The geometry template whose :attr:`GeometryTemplate.name` is ``name``.

    Raises
    ------
    KeyError
        With the known names, when no template has that name.
    """
    try:
        return _BY_NAME[name]
    except KeyError:
        raise KeyError(f"unknown geometry template {name!r}; known: {sorted(_BY_NAME)}") from None


@dataclass(frozen=True)
class CollisionPiece:
    """One convex collision element, in the primitive's local frame.

    ``shape`` is ``"box"`` (size = (sx, sy, sz)), ``"cylinder"`` (size = (radius,
    length), along local z), ``"sphere"`` (size = (radius,)) or ``"mesh"`` (vertices
    (V, 3) and faces (F, 3) of a convex mesh). ``pose`` is (4, 4) in the local frame.
    """

    shape: str
    size: tuple = ()
    pose: np.ndarray = field(default_factory=lambda: IDENTITY)
    vertices: np.ndarray | None = None
    faces: np.ndarray | None = None


class GeometryTemplate:
    """A parametric solid. Subclasses are stateless: all methods are classmethods.

    A template's identity is its :attr:`name` (snake_case, unique): every table that
    needs to tell templates apart keys on it, and :func:`template_named` finds a
    template by it. A subclass that sets no name of its own is an abstract base.
    """

    name: ClassVar[str] = ""
    params: ClassVar[tuple[str, ...]] = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        name = cls.__dict__.get("name")
        if not name:
            return
        other = _BY_NAME.get(name)
        if other is not None and other.__qualname__ != cls.__qualname__:
            raise ValueError(f"geometry template name {name!r} is taken by {other.__module__}.{other.__qualname__}")
        _BY_NAME[name] = cls

    @classmethod
    def component_areas(cls, P: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        """Areas (M, C) of the C surface components (faces, caps, walls) of each row."""
        raise NotImplementedError

    @classmethod
    def patches(cls, P: np.ndarray) -> list:  # pragma: no cover - abstract
        """The surface as :class:`artipg.geometry.patches.Patch` blocks, for rows of ``P``
        (M, p); patch areas of component c sum to ``component_areas(P)[:, c]``."""
        raise NotImplementedError

    @classmethod
    def sample_components(cls, P: np.ndarray, comp: np.ndarray, rng: np.random.Generator):
        """One area-uniform point and outward normal per row on component ``comp`` (k,).

        Returns points (k, 3) and unit normals (k, 3) in the local frame.
        """
        blocks = cls.patches(P)
        area = np.concatenate([b.area for b in blocks]).T  # (k, patches)
        pcomp = np.concatenate([b.comp for b in blocks])
        which = pick(np.where(pcomp[None, :] == comp[:, None], area, 0.0), rng)
        out = np.empty((6, len(P)))
        start = 0
        for b in blocks:
            sel = np.flatnonzero((which >= start) & (which < start + len(b.comp)))
            if len(sel):
                out[:, sel] = sample_family(b.family, b.params[which[sel] - start, :, sel].T, rng)
            start += len(b.comp)
        return out[:3].T, out[3:].T

    @classmethod
    def area(cls, P: np.ndarray) -> np.ndarray:
        """Surface area (M,) of each row of ``P`` (M, p), square metres."""
        return cls.component_areas(P).sum(axis=1)

    @classmethod
    def sample(cls, P: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """One area-uniform surface point and outward unit normal per row of ``P``."""
        return cls.sample_components(P, pick(cls.component_areas(P), rng), rng)

    @classmethod
    def sdf(cls, p, x: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    @classmethod
    def bounds(cls, p) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    @classmethod
    def bounds_batch(cls, P: np.ndarray) -> np.ndarray:
        """Local bounding boxes (M, 2, 3) of each row of ``P`` (M, p)."""
        return np.stack([cls.bounds(p) for p in P]) if len(P) else np.zeros((0, 2, 3))

    @classmethod
    def solid_params(cls, p) -> tuple:
        """Parameters of the closed solid (open tube pieces get their caps back)."""
        return tuple(p)

    @classmethod
    def mesh_arrays(cls, p, sections: int = 32) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - abstract
        """Vertices (V, 3) and outward triangles (F, 3) of a watertight mesh (local frame);
        curved surfaces use ``sections`` segments per full turn."""
        raise NotImplementedError

    @classmethod
    def mesh(cls, p, sections: int = 32):
        """:meth:`mesh_arrays` as a ``trimesh.Trimesh``."""
        import trimesh

        return trimesh.Trimesh(*cls.mesh_arrays(p, sections), process=False)

    @classmethod
    def collision(cls, p) -> list[CollisionPiece]:
        """Convex pieces; default: the convex hull of the mesh (exact for convex solids)."""
        V, F = convex_hull(cls.mesh_arrays(p, sections=24)[0])
        return [CollisionPiece("mesh", vertices=V, faces=F)]

    @classmethod
    def volume(cls, p) -> float:
        """Enclosed volume in cubic metres (from the mesh unless overridden)."""
        return float(cls.mesh(p, sections=48).volume)

    @classmethod
    def inside(cls, p, x: np.ndarray) -> np.ndarray:
        """Boolean (N,) mask of points strictly inside the solid."""
        return cls.sdf(p, x) < 0.0


class Primitive(NamedTuple):
    """A geometry template instance placed in its part's frame.

    Attributes
    ----------
    geom : type[GeometryTemplate]
        The geometry template.
    params : tuple of float
        Its parameter vector, in ``geom.params`` order (metres, radians).
    pose : (4, 4) ndarray
        Local frame of the primitive expressed in the part frame.
    role : str
        Name of the primitive's role inside its part (``"grip"``, ``"front"``...),
        used by region knowledge.
    """

    geom: type
    params: tuple
    pose: np.ndarray = IDENTITY
    role: str = ""

    def placed(self, T: np.ndarray) -> "Primitive":
        """The same primitive with ``T`` applied on the left of its pose."""
        return Primitive(self.geom, self.params, T @ self.pose, self.role)

    def area(self) -> float:
        return float(self.geom.area(np.asarray([self.params], dtype=float))[0])

    def bounds(self) -> np.ndarray:
        """Bounding box (2, 3) of the primitive in the part frame."""
        return corners_bounds(self.geom.bounds(self.params), self.pose)

    def sdf(self, x: np.ndarray) -> np.ndarray:
        """Signed distance of part-frame points (N, 3)."""
        Ti = np.linalg.inv(self.pose)
        return self.geom.sdf(self.params, apply(Ti, np.asarray(x, dtype=float)))

    def mesh(self, sections: int = 32):
        m = self.geom.mesh(self.params, sections=sections)
        m.apply_transform(self.pose)
        return m


_CORNER_SIGNS = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=float)


def corners_bounds(b: np.ndarray, T: np.ndarray) -> np.ndarray:
    """Bounding box (2, 3) of box ``b`` (2, 3) after transform ``T`` (4, 4)."""
    c = b[0] + _CORNER_SIGNS * (b[1] - b[0])
    w = c @ T[:3, :3].T + T[:3, 3]
    return np.stack([w.min(axis=0), w.max(axis=0)])


def corners_bounds_union(B: np.ndarray, T: np.ndarray) -> np.ndarray:
    """Bounding box (2, 3) of the union of boxes ``B`` (M, 2, 3) after transforms ``T``
    (M, 4, 4): the same values as the union of :func:`corners_bounds` of each pair
    (each slice of the stacked product is the same matrix product), in a few calls."""
    c = B[:, :1] + _CORNER_SIGNS * (B[:, 1:] - B[:, :1])  # (M, 8, 3)
    w = c @ T[:, :3, :3].transpose(0, 2, 1)
    w += T[:, None, :3, 3]
    out = np.empty((2, 3))
    w.min(axis=(0, 1), out=out[0])
    w.max(axis=(0, 1), out=out[1])
    return out


def boxes(lo, hi) -> np.ndarray:
    """Boxes (M, 2, 3) from corner columns ``lo``, ``hi`` (3-tuples of (M,) arrays or
    scalars; at least one an array), written in place rather than stacked."""
    M = max(len(v) if isinstance(v, np.ndarray) else 1 for v in (*lo, *hi))
    out = np.empty((M, 2, 3))
    for k in range(3):
        out[:, 0, k] = lo[k]
        out[:, 1, k] = hi[k]
    return out


def centred_boxes(hx, hy, hz) -> np.ndarray:
    """Boxes (M, 2, 3) centred on the origin with half extents ``hx``, ``hy``, ``hz``."""
    return boxes((-hx, -hy, -hz), (hx, hy, hz))


def convex_hull(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (V, 3) and outward triangles (F, 3) of the convex hull of ``points``."""
    from scipy.spatial import ConvexHull  # imported here: only collision meshes need it

    hull = ConvexHull(points)
    V = points[hull.vertices]
    remap = np.full(len(points), -1, dtype=np.int64)
    remap[hull.vertices] = np.arange(len(hull.vertices))
    F = remap[hull.simplices]
    # qhull's simplices are unoriented: flip those whose normal opposes the facet's
    tri = V[F]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    flip = np.einsum("ij,ij->i", n, hull.equations[:, :3]) < 0
    F[flip] = F[flip][:, ::-1]
    return V, F


# ---------------------------------------------------------------- sampling helpers

def pick(weights: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Choose one column per row of ``weights`` (k, c) with probability ∝ weight."""
    c = np.cumsum(weights, axis=1)
    u = rng.random(len(weights)) * c[:, -1]
    # a loop over the (few) columns beats a boolean reduction along a short axis
    out = np.zeros(len(weights), dtype=np.int64)
    for j in range(weights.shape[1] - 1):
        out += u >= c[:, j]
    return out


def disk(r: np.ndarray, rng: np.random.Generator, r_in: np.ndarray | float = 0.0, arc=TWO_PI):
    """Area-uniform points in annulus sectors ``r_in <= ρ <= r``, ``0 <= θ <= arc``.

    Returns x, y arrays of shape (k,).
    """
    u, v = rng.random((2, len(r)))
    rho = np.sqrt(r_in * r_in + u * (r * r - r_in * r_in))
    th = v * arc
    return rho * np.cos(th), rho * np.sin(th)


def rect_points(centers: np.ndarray, sizes: np.ndarray, rng) -> np.ndarray:
    """Uniform points on axis-aligned rectangles (k, 3): ``centers`` and ``sizes`` (k, 3),
    the size being zero along each rectangle's normal axis."""
    return centers + (rng.random(centers.shape) - 0.5) * sizes


def polygon_sdf(q: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """Signed distance of 2-D points ``q`` (N, 2) to a closed polygon ``poly`` (V, 2).

    Negative inside (even-odd rule), exact for any simple polygon.
    """
    return polygon_sdf_rows(q[:, 0], q[:, 1], poly)


def polygon_sdf_rows(qx: np.ndarray, qy: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """:func:`polygon_sdf` of the 2-D points with coordinates ``qx``, ``qy`` (N,).

    Works on (V, N) rows, which numpy runs several times faster than (N, V, 2) arrays;
    every sum has two terms, so the result does not depend on the layout.
    """
    a = poly
    b = np.roll(poly, -1, axis=0)
    e = b - a  # (V, 2)
    ax, ay, ex, ey = a[:, 0:1], a[:, 1:2], e[:, 0:1], e[:, 1:2]  # (V, 1)
    wx = qx[None, :] - ax
    wy = qy[None, :] - ay
    ee = np.maximum((e * e).sum(axis=1), 1e-30)
    t = np.clip((wx * ex + wy * ey) / ee[:, None], 0.0, 1.0)
    dx = wx - t * ex
    dy = wy - t * ey
    dist = np.sqrt((dx * dx + dy * dy).min(axis=0))
    # crossing-number inside test
    qyr = qy[None, :]
    cond = (ay > qyr) != (b[:, 1:2] > qyr)
    xint = ax + (qyr - ay) * ex / np.where(np.abs(ey) > 1e-30, ey, 1e-30)
    inside = (cond & (qx[None, :] < xint)).sum(axis=0) % 2 == 1
    return np.where(inside, -dist, dist)


def wedge_sdf(x: np.ndarray, arc: float) -> np.ndarray:
    """Signed distance-like field of the wedge ``0 <= atan2(y, x) <= arc`` (exact sign).

    Full turns (``arc >= 2π``) give -inf everywhere (no restriction).
    """
    if arc >= TWO_PI - 1e-9:
        return np.full(len(x), -np.inf)
    d0 = -x[:, 1]  # half-plane y >= 0
    n1 = np.array([-np.sin(arc), np.cos(arc)])  # outward normal of the end plane
    d1 = x[:, :2] @ n1
    return np.maximum(d0, d1) if arc <= np.pi else np.minimum(d0, d1)
