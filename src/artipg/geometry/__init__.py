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

# The general families (docs/extending.md, "Geometry families"), exported as modules
# (their constructors share names with them: lathe.lathe, extrusion.prism, ...); the
# thin constructors replace today's templates when the categories switch.
from artipg.geometry import extrusion, lathe, profile, rounded_box, sweep  # noqa: E402
from artipg.geometry.extrusion import Extrusion  # noqa: E402
from artipg.geometry.lathe import Lathe  # noqa: E402
from artipg.geometry.rounded_box import RoundedBox  # noqa: E402
from artipg.geometry.sweep import Sweep  # noqa: E402

__all__ += ["Extrusion", "Lathe", "RoundedBox", "Sweep", "extrusion", "lathe", "profile", "rounded_box", "sweep"]
