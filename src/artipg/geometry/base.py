"""The interface of the geometry families and the primitive instance that places one.

A geometry family instance is a set of solids with a fixed-length parameter vector. Every
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

from artipg.geometry.transforms import IDENTITY, apply

TWO_PI = 2.0 * np.pi


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
    """The interface of a parametric solid: the geometry families
    (:class:`artipg.geometry.family.Family`, one instance per shape key) implement it;
    every method works on parameter rows of the instance's one width."""

    name: ClassVar[str] = ""
    params: ClassVar[tuple[str, ...]] = ()

    def component_areas(self, P: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        """Areas (M, C) of the C surface components (faces, caps, walls) of each row."""
        raise NotImplementedError

    def patches(self, P: np.ndarray) -> list:  # pragma: no cover - abstract
        """The surface as :class:`artipg.geometry.patches.Patch` blocks, for rows of ``P``
        (M, p); patch areas of component c sum to ``component_areas(P)[:, c]``."""
        raise NotImplementedError

    def sample_components(self, P: np.ndarray, comp: np.ndarray, rng: np.random.Generator):  # pragma: no cover
        """One area-uniform point and outward normal per row on component ``comp`` (k,).

        Returns points (k, 3) and unit normals (k, 3) in the local frame.
        """
        raise NotImplementedError

    def area(self, P: np.ndarray) -> np.ndarray:
        """Surface area (M,) of each row of ``P`` (M, p), square metres."""
        return self.component_areas(P).sum(axis=1)

    def sample(self, P: np.ndarray, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """One area-uniform surface point and outward unit normal per row of ``P``."""
        return self.sample_components(P, pick(self.component_areas(P), rng), rng)

    def sdf(self, p, x: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def bounds(self, p) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def bounds_batch(self, P: np.ndarray) -> np.ndarray:
        """Local bounding boxes (M, 2, 3) of each row of ``P`` (M, p)."""
        return np.stack([self.bounds(p) for p in P]) if len(P) else np.zeros((0, 2, 3))

    def solid_params(self, p) -> tuple:
        """Parameters of the closed solid (open tube pieces get their caps back)."""
        return tuple(p)

    def mesh_arrays(self, p, sections: int = 32) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - abstract
        """Vertices (V, 3) and outward triangles (F, 3) of a watertight mesh (local frame);
        curved surfaces use ``sections`` segments per full turn."""
        raise NotImplementedError

    def mesh(self, p, sections: int = 32):
        """:meth:`mesh_arrays` as a ``trimesh.Trimesh``."""
        import trimesh

        return trimesh.Trimesh(*self.mesh_arrays(p, sections), process=False)

    def collision(self, p) -> list[CollisionPiece]:
        """Convex pieces; default: the convex hull of the mesh (exact for convex solids)."""
        V, F = convex_hull(self.mesh_arrays(p, sections=24)[0])
        return [CollisionPiece("mesh", vertices=V, faces=F)]

    def volume(self, p) -> float:
        """Enclosed volume in cubic metres (from the mesh unless overridden)."""
        return float(self.mesh(p, sections=48).volume)

    def inside(self, p, x: np.ndarray) -> np.ndarray:
        """Boolean (N,) mask of points strictly inside the solid."""
        return self.sdf(p, x) < 0.0


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
