"""Geometry: four general families (lathe, extrusion, rounded box, swept tube) with
exact sampling, SDF, bounds and meshes, and the thin constructors the templates use."""

from artipg.geometry import extrusion, lathe, profile, rounded_box, sweep
from artipg.geometry.base import CollisionPiece, GeometryTemplate, Primitive
from artipg.geometry.extrusion import Extrusion, prism, rect_ring, tri_prism
from artipg.geometry.lathe import Lathe, cylinder, frustum, ring, sphere, torus
from artipg.geometry.rounded_box import BOX, RoundedBox, cuboid, cuboid_between
from artipg.geometry.sweep import Sweep
from artipg.geometry.tube import Tube, arc, line, tube

#: The geometry families (classes; an instance per shape key), by kind.
GEOMETRY_FAMILIES = {f.kind: f for f in (Lathe, Extrusion, RoundedBox, Sweep)}

__all__ = [
    "CollisionPiece", "GeometryTemplate", "Primitive", "GEOMETRY_FAMILIES", "BOX",
    "Extrusion", "Lathe", "RoundedBox", "Sweep", "Tube",
    "cuboid", "cuboid_between", "rect_ring", "cylinder", "frustum", "ring", "sphere", "torus",
    "prism", "tri_prism", "tube", "line", "arc",
    "extrusion", "lathe", "profile", "rounded_box", "sweep",
]
