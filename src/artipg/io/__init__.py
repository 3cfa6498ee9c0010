"""Readers: object folders (artipg's or PartNet-Mobility's) -> labelled point clouds.

- :mod:`artipg.io.folders`  find object folders and their categories under a directory;
- :mod:`artipg.io.manifest` the file list of an object folder, and checking a folder against it;
- :mod:`artipg.io.urdf`     load a ``mobility.urdf`` through its kinematics at the rest pose;
- :mod:`artipg.io.sampling` area-uniform surface sampling with per-point labels;
- :mod:`artipg.io.reader`   one folder -> :class:`ObjectSample` (points, link labels, structure);
- :mod:`artipg.io.dataset`  many folders in parallel -> a :class:`ObjectSet`.

The names below load their module on first use, so importing a light module of this
package (``folders``, ``manifest``) does not load the mesh libraries.
"""

import importlib

_WHERE = {
    "ObjectSet": "dataset", "load_set": "dataset",
    "find_object_folders": "folders", "is_object_folder": "folders",
    "ObjectSample": "reader", "read_object": "reader",
    "sample_surface": "sampling",
    "LoadedURDF": "urdf", "load_urdf": "urdf",
}


def __getattr__(name):
    if name in _WHERE:
        return getattr(importlib.import_module(f"artipg.io.{_WHERE[name]}"), name)
    raise AttributeError(f"module 'artipg.io' has no attribute {name!r}")


__all__ = sorted(_WHERE)
