"""Exporters: URDF + meshes, semantics.txt, annotation.json, points.npz (one module each)."""

from artipg.export.folder import export_object, object_files

__all__ = ["export_object", "object_files"]
