"""Readers: object folders (artipg's or PartNet-Mobility's) -> labelled point clouds.

- :mod:`artipg.io.folders`  find object folders and their categories under a directory;
- :mod:`artipg.io.urdf`     load a ``mobility.urdf`` through its kinematics at the rest pose;
- :mod:`artipg.io.sampling` area-uniform surface sampling with per-point labels;
- :mod:`artipg.io.reader`   one folder -> :class:`ObjectSample` (points, link labels, structure);
- :mod:`artipg.io.dataset`  many folders in parallel -> a :class:`ObjectSet`.
"""

from artipg.io.dataset import ObjectSet, load_set
from artipg.io.folders import find_object_folders, is_object_folder
from artipg.io.reader import ObjectSample, read_object
from artipg.io.sampling import sample_surface
from artipg.io.urdf import LoadedURDF, load_urdf

__all__ = ["LoadedURDF", "ObjectSample", "ObjectSet", "find_object_folders", "is_object_folder", "load_set",
           "load_urdf", "read_object", "sample_surface"]
