"""Geometry templates: parametric solids with exact sampling, SDF, bounds and meshes."""

from artipg.geometry.base import CollisionPiece, GeometryTemplate, Primitive
from artipg.geometry.box import Cuboid, RectRing, cuboid, cuboid_between, rect_ring
from artipg.geometry.prism import Prism, TriPrism, prism, tri_prism
from artipg.geometry.revolve import Frustum, Ring, Sphere, Torus, cylinder, frustum, ring, sphere, torus
from artipg.geometry.tube import Tube, arc, line, tube

#: Every geometry template, by name (the registry used by exporters and tests).
GEOMETRY_TEMPLATES = {g.name: g for g in (Cuboid, RectRing, Frustum, Ring, Sphere, Torus, Prism, TriPrism)}

__all__ = [
    "CollisionPiece", "GeometryTemplate", "Primitive", "GEOMETRY_TEMPLATES",
    "Cuboid", "RectRing", "Frustum", "Ring", "Sphere", "Torus", "Prism", "TriPrism", "Tube",
    "cuboid", "cuboid_between", "rect_ring", "cylinder", "frustum", "ring", "sphere", "torus",
    "prism", "tri_prism", "tube", "line", "arc",
]
