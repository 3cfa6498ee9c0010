"""GLB writer: ``mobility.glb``, the object for viewers (glTF 2.0, binary).

One node per link in the kinematic hierarchy (node name = link name, transform = the
joint's origin, so the nodes stand at rest), each holding the link's visual mesh
with vertex colours per semantic part (the colours of :func:`artipg.viz.palette`).
The node's extras hold its semantic label and the joint that moves it: ``type``,
``axis`` (joint frame), ``limits`` (rad or m; null when unlimited), ``parent``,
``child`` and ``name``.

Materials (artipg's own objects, :attr:`artipg.export.asset.Asset.surfaces`): the
meshes carry normals, texture coordinates and a glTF metallic-roughness material
(:func:`pbr_material`; the texture image embedded), one mesh per material: a link's
node holds its first material's mesh and child nodes ``<link>_visual<k>`` (identity
transform) its further ones. Third-party folders keep vertex colours per semantic part.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from artipg.export.asset import Asset


@lru_cache(maxsize=None)
def label_color(label: str) -> tuple[float, float, float]:
    """RGB in [0, 1] of a semantic label: its vocabulary colour, or for labels outside
    the vocabulary (third-party folders') one of 32 more picked by a hash of the name."""
    import zlib

    from artipg.viz import palette
    from artipg.vocabulary import LABEL_ID, SEMANTIC_LABELS

    n = len(SEMANTIC_LABELS)
    i = LABEL_ID.get(label, n + zlib.crc32(label.encode()) % 32)
    return tuple(float(c) for c in palette(n + 32)[i])


def _rgba(asset: Asset, link, n: int) -> np.ndarray:
    runs = asset.vertex_labels.get(link.name)
    if not runs or sum(c for _, c in runs) != n:
        runs = [(link.label, n)]
    rgb = np.concatenate([np.tile(label_color(lab), (c, 1)) for lab, c in runs])
    return np.column_stack([np.round(rgb * 255), np.full(n, 255)]).astype(np.uint8)


def joint_extras(j) -> dict:
    """JSON-ready description of a joint (the node extras of its child link)."""
    lim = None if j.type == "fixed" or not all(math.isfinite(v) for v in j.limits) else [float(v) for v in j.limits]
    return {"name": j.name, "type": j.type, "parent": j.parent, "child": j.child,
            "axis": [float(v) for v in j.axis], "limits": lim}


def pbr_material(asset: Asset, pbr: dict, texture: bool = True):
    """A ``trimesh`` PBR material of a material's PBR values (:meth:`Material.to_pbr`):
    linear ``baseColorFactor`` with the opacity as alpha (blended when below 1),
    metallic and roughness factors, and (``texture``) the texture image (sRGB) as
    base colour."""
    import io

    import trimesh
    from PIL import Image

    image = None
    if texture and pbr["texture"]:
        image = Image.open(io.BytesIO(asset.file_bytes(pbr["texture"])))
        image.load()
    return trimesh.visual.material.PBRMaterial(
        name=pbr["name"], baseColorFactor=[float(v) for v in pbr["baseColorFactor"]],
        metallicFactor=pbr["metallic"], roughnessFactor=pbr["roughness"], baseColorTexture=image,
        alphaMode="BLEND" if pbr["opacity"] < 1.0 else "OPAQUE", doubleSided=pbr["opacity"] < 1.0)


def _surface_meshes(asset: Asset, surf, cache: dict, textures: bool) -> list:
    """One ``trimesh.Trimesh`` with UVs and a PBR material per material group of a
    :class:`Surface` (texture images left out unless ``textures``)."""
    import trimesh

    out = []
    for k, (pbr, _, _) in enumerate(surf.groups):
        if pbr["name"] not in cache:
            cache[pbr["name"]] = pbr_material(asset, pbr, textures)
        V, N, UV, F = surf.group(k)
        mesh = trimesh.Trimesh(V, F, vertex_normals=N, process=False)
        mesh.visual = trimesh.visual.TextureVisuals(uv=UV, material=cache[pbr["name"]])
        out.append(mesh)
    return out


def build_scene(asset: Asset, textures: bool = True):
    """A ``trimesh.Scene`` of ``asset``: one node per link, parented as the joints
    (``textures=False``: materials without their images, which :func:`glb_bytes` embeds)."""
    import trimesh

    scene = trimesh.Scene(base_frame="world")
    joint_of = {j.child: j for j in asset.joints}
    materials: dict = {}  # one material object per name: the GLB holds each once
    for lk in asset.links:
        j = joint_of.get(lk.name)
        parent = "world" if j is None else j.parent
        T = np.eye(4) if j is None else j.origin
        extras = {"semantic": lk.label, "joint": None if j is None else joint_extras(j)}
        surf = asset.surfaces.get(lk.name)
        if surf is not None:
            meshes = _surface_meshes(asset, surf, materials, textures)
            scene.add_geometry(meshes[0], node_name=lk.name, geom_name=f"{lk.name}_visual", parent_node_name=parent,
                               transform=T, metadata=extras)
            for k, mesh in enumerate(meshes[1:], 1):
                scene.add_geometry(mesh, node_name=f"{lk.name}_visual{k}", geom_name=f"{lk.name}_visual{k}",
                                   parent_node_name=lk.name)
            continue
        vm = asset.visual_mesh(lk)
        if vm is None:
            scene.graph.update(frame_from=parent, frame_to=lk.name, matrix=T, metadata=extras)
            continue
        mesh = trimesh.Trimesh(*vm, process=False)
        mesh.visual = trimesh.visual.ColorVisuals(mesh, vertex_colors=_rgba(asset, lk, len(vm[0])))
        scene.add_geometry(mesh, node_name=lk.name, geom_name=f"{lk.name}_visual", parent_node_name=parent,
                           transform=T, metadata=extras)
    return scene


def glb_bytes(asset: Asset) -> bytes:
    """The bytes of ``mobility.glb`` of ``asset``, texture images embedded as the very
    PNG files of the object folder."""
    images = {pbr["name"]: asset.file_bytes(pbr["texture"]) for surf in asset.surfaces.values()
              for pbr, _, _ in surf.groups if pbr["texture"]}
    data = build_scene(asset, textures=False).export(file_type="glb")
    return embed_textures(data, images) if images else data


def embed_textures(glb: bytes, images: dict[str, bytes]) -> bytes:
    """``glb`` with PNG ``images`` {material name: PNG bytes} as the base colour textures
    of its materials of those names (repeating, read at ``TEXCOORD_0``).

    trimesh would decode and encode every image again (most of the export time);
    appending the files' own bytes keeps them byte for byte.
    """
    import json
    import struct

    n_json = struct.unpack_from("<I", glb, 12)[0]
    tree = json.loads(glb[20:20 + n_json])
    rest = glb[20 + n_json:]
    binary = bytearray(rest[8:8 + struct.unpack_from("<I", rest, 0)[0]]) if rest else bytearray()
    tree.setdefault("samplers", []).append({"wrapS": 10497, "wrapT": 10497})  # REPEAT: UVs count tiles
    sampler = len(tree["samplers"]) - 1
    done: dict[str, int] = {}
    for mat in tree.get("materials", []):
        png = images.get(mat.get("name"))
        if png is None:
            continue
        if mat["name"] not in done:
            binary.extend(b"\0" * (-len(binary) % 4))
            tree.setdefault("bufferViews", []).append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(png)})
            binary.extend(png)
            tree.setdefault("images", []).append({"bufferView": len(tree["bufferViews"]) - 1, "mimeType": "image/png"})
            tree.setdefault("textures", []).append({"source": len(tree["images"]) - 1, "sampler": sampler})
            done[mat["name"]] = len(tree["textures"]) - 1
        mat.setdefault("pbrMetallicRoughness", {})["baseColorTexture"] = {"index": done[mat["name"]], "texCoord": 0}
    binary.extend(b"\0" * (-len(binary) % 4))
    if tree.get("buffers"):
        tree["buffers"][0]["byteLength"] = len(binary)
    else:
        tree["buffers"] = [{"byteLength": len(binary)}]
    text = json.dumps(tree, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = (struct.pack("<II", len(text), 0x4E4F534A) + text  # chunks "JSON" and "BIN\0"
            + struct.pack("<II", len(binary), 0x004E4942) + bytes(binary))
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body
