"""Visual surfaces with materials, read back from an object folder's OBJ and MTL files.

The MJCF, USD and GLB writers take a link's materials from here: artipg's visual OBJ
files (normals, UVs and one ``usemtl`` group per material, written from
:func:`artipg.appearance.materials_of`) and ``meshes/materials.mtl`` (whose ``Pr`` /
``Pm`` lines, the PBR extension of MTL, mark it as artipg's). A generated object (files
in memory) and a converted artipg folder (files on disk) so give the same bytes in
every format. Third-party meshes (an MTL without ``Pr`` and ``Pm``, several visuals per
link, OBJ corners with separate position, texture and normal indices) give no surface:
their writers keep colours per semantic label.
"""

from __future__ import annotations

import posixpath
from dataclasses import dataclass
from pathlib import Path

import numpy as np


@dataclass
class Surface:
    """A link's visual surface for rendering, in the link frame, grouped by material.

    ``vertices`` (V, 3) metres, unit ``normals`` (V, 3), ``uvs`` (V, 2) (OBJ
    convention: v up; in texture tiles, repeating), triangles ``faces`` (F, 3) and
    ``groups``: a list of (PBR dict, first face, end face) covering the faces in order,
    the dict as :meth:`artipg.appearance.Material.to_pbr` gives it (``texture``: path
    relative to the object folder, or None).
    """

    vertices: np.ndarray
    normals: np.ndarray
    uvs: np.ndarray
    faces: np.ndarray
    groups: list

    def group(self, k: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Vertices, normals, uvs and faces (indices into its own vertices) of group ``k``."""
        _, f0, f1 = self.groups[k]
        used, inverse = np.unique(self.faces[f0:f1], return_inverse=True)
        return self.vertices[used], self.normals[used], self.uvs[used], inverse.reshape(-1, 3)

    def main_group(self) -> int:
        """Index of the group with the most faces (the one a single-material element names)."""
        return int(np.argmax([f1 - f0 for _, f0, f1 in self.groups]))


def mtl_materials(text: str, folder: str = "") -> dict[str, dict]:
    """{name: PBR dict} of the materials of artipg's MTL ``text``; ``folder``: the MTL
    file's folder relative to the object folder (texture paths are made relative to
    the object folder). Materials without ``Pr`` and ``Pm`` (not artipg's) are left out."""
    from artipg.appearance.material import Material

    blocks: list[dict] = []
    for ln in text.splitlines():
        key, _, rest = ln.strip().partition(" ")
        if key == "newmtl":
            blocks.append({"name": rest.strip()})
        elif blocks and key in ("Kd", "d", "Pr", "Pm", "map_Kd"):
            blocks[-1][key] = rest.strip()
    out = {}
    for b in blocks:
        if "Pr" not in b or "Pm" not in b or "Kd" not in b:
            continue
        tex = b.get("map_Kd")
        m = Material(b["name"], "", "", tuple(float(c) for c in b["Kd"].split()[:3]), metallic=float(b["Pm"]),
                     roughness=float(b["Pr"]), opacity=float(b.get("d", 1.0)), texture="image" if tex else None)
        pbr = m.to_pbr()
        pbr["texture"] = posixpath.normpath(posixpath.join(folder, tex)) if tex else None
        out[m.name] = pbr
    return out


def obj_surface(text: str):
    """Vertices (V, 3), normals (V, 3), uvs (V, 2), faces (F, 3) and [(material name,
    first face, end face)] of OBJ ``text`` whose face corners are ``i/i/i`` (one index
    for position, texture and normal) and all ``v``, ``vt``, ``vn`` lines before the first
``usemtl``, as artipg writes them; None for other OBJ files."""
    import re

    chunks = text.split("\nusemtl ")
    head = "\n" + chunks[0]  # artipg writes every v, vt and vn line before the first usemtl
    if len(chunks) < 2 or "\nf " in head:
        return None  # faces before any material
    f, groups = [], []
    for chunk in chunks[1:]:
        name, _, body = chunk.partition("\n")
        faces = re.findall(r"^f (.*)$", body, re.M)
        groups.append([name.strip(), len(f)])
        f += faces
    v, vt, vn = (re.findall(rf"^{key} (.*)$", head, re.M) for key in ("v", "vt", "vn"))
    try:
        V = np.array(" ".join(v).split(), dtype=float).reshape(-1, 3)
        UV = np.array(" ".join(vt).split(), dtype=float).reshape(-1, 2)
        N = np.array(" ".join(vn).split(), dtype=float).reshape(-1, 3)
        idx = np.array(" ".join(f).replace("/", " ").split(), dtype=np.int64).reshape(-1, 3, 3) - 1
    except ValueError:
        return None
    if (len(UV) != len(V) or len(N) != len(V) or not len(idx)
            or np.any(idx != idx[:, :, :1]) or idx.min() < 0 or idx.max() >= len(V)):
        return None
    ends = [g[1] for g in groups[1:]] + [len(idx)]
    return V, N, UV, idx[:, :, 0], [(name, a, b) for (name, a), b in zip(groups, ends) if b > a]


def _text(asset, rel: str, first_line: bool = False) -> str | None:
    data = asset.files.get(rel)
    if data is not None:
        data = data if isinstance(data, str) else data.decode(errors="replace")
        return data.split("\n", 1)[0] if first_line else data
    if asset.folder is None:
        return None
    path = Path(asset.folder) / rel
    if not path.is_file():
        return None
    with open(path, encoding="utf-8", errors="replace") as fh:
        return fh.readline() if first_line else fh.read()


def read_surfaces(asset) -> dict[str, Surface]:
    """{link name: :class:`Surface`} of the links of ``asset``
    (:class:`artipg.export.asset.Asset`) whose one visual is an artipg OBJ file with
    materials (see the module's description); in the link frame."""
    out: dict[str, Surface] = {}
    libraries: dict[str, dict] = {}
    for lk in asset.links:
        if len(lk.visuals) != 1:
            continue
        g = lk.visuals[0]
        if g.kind != "mesh" or not g.mesh.lower().endswith(".obj") or tuple(g.scale) != (1.0, 1.0, 1.0):
            continue
        head = _text(asset, g.mesh, first_line=True)
        if not head or not head.startswith("mtllib "):
            continue
        folder = posixpath.dirname(g.mesh)
        lib = posixpath.normpath(posixpath.join(folder, head[7:].strip()))
        if lib not in libraries:
            text = _text(asset, lib)
            libraries[lib] = {} if text is None else mtl_materials(text, posixpath.dirname(lib))
        mats = libraries[lib]
        if not mats:
            continue
        parsed = obj_surface(_text(asset, g.mesh))
        if parsed is None or any(name not in mats for name, _, _ in parsed[4]):
            continue
        V, N, UV, F, groups = parsed
        R, t = np.asarray(g.pose, dtype=float)[:3, :3], np.asarray(g.pose, dtype=float)[:3, 3]
        out[lk.name] = Surface(V @ R.T + t, N @ R.T, UV, F, [(mats[name], a, b) for name, a, b in groups])
    return out
