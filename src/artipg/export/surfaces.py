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


def _numbers(block: str, prefix: str, width: int) -> np.ndarray:
    """The numbers of ``block``, lines all starting with ``prefix`` and holding ``width``
    numbers each, as an (n, width) array; ValueError for anything else."""
    import warnings

    lines = block.count("\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # numpy warns where a token is not a number
        x = np.fromstring(block.replace(prefix, " "), dtype=float, sep=" ")
    if block.count(prefix) != lines or x.size != lines * width:
        raise ValueError("not a block of numbers")
    return x.reshape(-1, width)


def obj_surface(text: str):
    """Vertices (V, 3), normals (V, 3), uvs (V, 2), faces (F, 3) and [(material name,
    first face, end face)] of OBJ ``text`` as artipg writes them
    (:func:`artipg.export.meshes.obj_surface_text`): ``mtllib``, then blocks of ``v``,
    ``vt`` and ``vn`` lines, then ``usemtl`` groups of triangles whose corners are
    ``i/i/i`` (one index for position, texture and normal); None for other OBJ files."""
    chunks = text.split("\nusemtl ")
    head = chunks[0] + "\n"
    iv, ivt, ivn = head.find("\nv "), head.find("\nvt "), head.find("\nvn ")
    if len(chunks) < 2 or not 0 <= iv < ivt < ivn:
        return None
    try:
        V = _numbers(head[iv + 1:ivt + 1], "v ", 3)
        UV = _numbers(head[ivt + 1:ivn + 1], "vt ", 2)
        N = _numbers(head[ivn + 1:], "vn ", 3)
        groups = []
        for chunk in chunks[1:]:
            name, _, body = chunk.partition("\n")
            body = body if body.endswith("\n") else body + "\n"
            idx = _numbers(body.replace("/", " "), "f ", 9) if body.strip() else np.zeros((0, 9))
            groups.append((name.strip(), idx.astype(np.int64) - 1))
    except ValueError:
        return None
    idx = np.concatenate([g[1] for g in groups]).reshape(-1, 3, 3)
    if (len(UV) != len(V) or len(N) != len(V) or not len(idx)
            or np.any(idx != idx[:, :, :1]) or idx.min() < 0 or idx.max() >= len(V)):
        return None
    ends = np.cumsum([len(g[1]) for g in groups]).tolist()
    starts = [0] + ends[:-1]
    return V, N, UV, idx[:, :, 0], [(g[0], a, b) for g, a, b in zip(groups, starts, ends) if b > a]


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
