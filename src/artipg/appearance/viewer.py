"""Interactive browser viewer of exported object folders (viser; ``pip install artipg[view]``).

:class:`Viewer` serves one object folder, or every object folder below a path, at
``http://HOST:PORT``: the textured meshes of ``mobility.urdf`` with a slider per movable
joint (forward kinematics by yourdfpy), colour modes (material, semantic, instance, one
per affordance; labels from ``points.npz`` carried to the mesh vertices by the nearest
labelled point of the same link), the labelled points, grasp poses and NPCS boxes on
demand, and a picker for the objects of a folder. Everything attached to a link (meshes,
points, grasps, boxes) lives under that link's scene frame, so it moves with the joints.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from artipg.vocabulary import AFFORDANCES

#: Colour modes of the meshes.
MODES = ("material", "semantic", "instance", *(f"affordance: {a}" for a in AFFORDANCES))


def object_folders(path: Path) -> list[Path]:
    """Object folders (holding ``mobility.urdf``) at or below ``path``, sorted."""
    path = Path(path)
    if (path / "mobility.urdf").is_file():
        return [path]
    return sorted(p.parent for p in path.rglob("mobility.urdf") if not p.parent.name.startswith("."))


def label_colors(ids: np.ndarray) -> np.ndarray:
    """Distinct, stable colours (N, 3) uint8 of integer labels (golden-ratio hues)."""
    h = (np.asarray(ids, dtype=float) * 0.618034 + 0.1) % 1.0
    k = (np.array([5.0, 3.0, 1.0])[None, :] + h[:, None] * 6.0) % 6.0
    rgb = 0.85 - 0.65 * np.clip(np.minimum(k, 4.0 - k), 0.0, 1.0)
    return (rgb * 255).astype(np.uint8)


def read_mtl(path: Path) -> dict[str, dict]:
    """{material name: {Kd, d, Pr, Pm, map_Kd}} of a Wavefront MTL file."""
    out: dict[str, dict] = {}
    cur: dict = {}
    for line in Path(path).read_text().splitlines():
        key, _, rest = line.partition(" ")
        if key == "newmtl":
            cur = out[rest.strip()] = {"Kd": (0.8, 0.8, 0.8), "d": 1.0, "Pr": 0.5, "Pm": 0.0, "map_Kd": None}
        elif key == "Kd":
            cur["Kd"] = tuple(float(v) for v in rest.split())
        elif key in ("d", "Pr", "Pm"):
            cur[key] = float(rest)
        elif key == "map_Kd":
            cur["map_Kd"] = (Path(path).parent / rest.strip()).resolve()
    return out


def _wxyz(T: np.ndarray) -> tuple:
    from scipy.spatial.transform import Rotation

    x, y, z, w = Rotation.from_matrix(T[:3, :3]).as_quat()
    return (float(w), float(x), float(y), float(z))


class Viewer:
    """A viser server showing object folders (see the module docstring).

    Attributes
    ----------
    q : dict
        {joint name: value} currently shown (radians or metres).
    frames : dict
        {link name: viser frame handle}; their poses follow ``q``.
    """

    def __init__(self, path: Path, host: str = "127.0.0.1", port: int = 8080):
        import viser

        self.folders = object_folders(path)
        if not self.folders:
            raise ValueError(f"no object folder (with mobility.urdf) at or below {path}")
        self.root = Path(path)
        self.server = viser.ViserServer(host=host, port=port, verbose=False)
        self.server.scene.set_up_direction("+z")
        # a neutral studio for reflections (the default warehouse tints metals brown), z up
        self.server.scene.configure_environment_map("studio", environment_intensity=0.5,
                                                  environment_wxyz=(0.7071068, 0.7071068, 0.0, 0.0))
        gui = self.server.gui
        names = [str(f.relative_to(self.root)) if f != self.root else f.name for f in self.folders]
        self.picker = gui.add_dropdown("object", names, initial_value=names[0])
        self.mode = gui.add_dropdown("colour", MODES)
        self.show_points = gui.add_checkbox("points", False)
        self.show_grasps = gui.add_checkbox("grasps", False)
        self.show_boxes = gui.add_checkbox("NPCS boxes", False)
        self.info = gui.add_markdown("")
        self.joint_folder = None
        self.q: dict[str, float] = {}
        self.frames: dict = {}
        self.sliders: dict = {}
        self._root = None
        self.picker.on_update(lambda _: self.load(self.folders[names.index(self.picker.value)]))
        self.mode.on_update(lambda _: self._recolor())
        for box, kind in ((self.show_points, "points"), (self.show_grasps, "grasps"), (self.show_boxes, "boxes")):
            box.on_update(lambda _, k=kind, b=box: self._show(k, b.value))
        self.load(self.folders[0])

    @property
    def url(self) -> str:
        host = self.server.get_host()
        return f"http://{'localhost' if host in ('0.0.0.0', '::') else host}:{self.server.get_port()}"

    # ------------------------------------------------------------ loading
    def load(self, folder: Path) -> None:
        """Show object ``folder`` (replacing the one shown)."""
        import yourdfpy

        if self._root is not None:  # removes everything below it too
            self._root.remove()
        if self.joint_folder is not None:
            self.joint_folder.remove()
        self.frames, self.sliders, self.q = {}, {}, {}
        self._layers: dict[str, list] = {"points": [], "grasps": [], "boxes": []}
        self._meshes: list = []  # [link, node name, mesh, MTL entry, handle]
        self.folder = Path(folder)
        self.urdf = yourdfpy.URDF.load(str(folder / "mobility.urdf"), build_scene_graph=True, load_meshes=False)
        scene = self.server.scene
        self._root = scene.add_frame("/object", show_axes=False)
        for link in self.urdf.robot.links:
            self.frames[link.name] = scene.add_frame(f"/object/{link.name}", show_axes=False)
        self._labels = self._load_points()
        mtl = self.folder / "meshes" / "materials.mtl"
        self._mtl = read_mtl(mtl) if mtl.is_file() else {}
        for link in self.urdf.robot.links:
            for k, vis in enumerate(link.visuals):
                if vis.geometry.mesh is not None:
                    self._add_visual(link.name, k, vis)
        self._add_sliders()
        self._update_poses()
        if self.mode.value != "material":
            self._recolor()
        for kind, box in (("points", self.show_points), ("grasps", self.show_grasps), ("boxes", self.show_boxes)):
            self._show(kind, box.value)
        self._frame_camera()
        self.info.content = f"**{self.folder.name}** · {len(self.urdf.robot.links)} links · {len(self.sliders)} joints"

    def _load_points(self) -> dict | None:
        """Labelled points of ``points.npz`` in their links' frames, grasps and boxes."""
        path = self.folder / "points.npz"
        if not path.is_file():
            return None
        d = np.load(path)
        link_names = [str(n) for n in d["link_names"]]
        inv = np.linalg.inv(d["link_poses"].astype(float))
        pts = np.asarray(d["points"], dtype=float)
        link = d["link"]
        local = np.einsum("nij,nj->ni", inv[link][:, :3, :3], pts) + inv[link][:, :3, 3]
        out = {"link": link, "local": local, "semantic": d["semantic"], "instance": d["instance"],
               "affordance": d["affordance"], "affordance_names": [str(n) for n in d["affordance_names"]],
               "link_names": link_names}
        scene = self.server.scene
        for i, name in enumerate(link_names):
            sel = link == i
            if name in self.frames and sel.any():
                h = scene.add_point_cloud(f"/object/{name}/points", local[sel].astype(np.float32),
                                          label_colors(d["semantic"][sel]), point_size=0.006, visible=False)
                self._layers["points"].append(h)
        part_link = d["part_link"]
        for g, (T, part) in enumerate(zip(d["grasp_poses"].astype(float), d["grasp_parts"])):
            name = link_names[part_link[part]]
            Tl = inv[part_link[part]] @ T
            h = scene.add_frame(f"/object/{name}/grasp_{g}", axes_length=0.04, axes_radius=0.002,
                                wxyz=_wxyz(Tl), position=Tl[:3, 3], visible=False)
            self._layers["grasps"].append(h)
        for p, (T, size) in enumerate(zip(d["part_poses"].astype(float), d["part_sizes"].astype(float))):
            name = link_names[part_link[p]]
            Tl = inv[part_link[p]] @ T
            h = scene.add_box(f"/object/{name}/npcs_{p}", color=tuple(int(c) for c in label_colors([p])[0]),
                              dimensions=tuple(np.maximum(size, 1e-4)), wireframe=True, wxyz=_wxyz(Tl),
                              position=Tl[:3, 3], visible=False)
            self._layers["boxes"].append(h)
        return out

    def _add_visual(self, link: str, k: int, vis) -> None:
        import trimesh

        path = (self.folder / vis.geometry.mesh.filename).resolve()
        loaded = trimesh.load(str(path), group_material=True, process=False)
        geoms = loaded.geometry.values() if isinstance(loaded, trimesh.Scene) else [loaded]
        T = vis.origin if vis.origin is not None else np.eye(4)
        for j, mesh in enumerate(geoms):
            mesh = mesh.copy()
            mesh.apply_transform(T)
            mat = self._mtl.get(getattr(getattr(mesh.visual, "material", None), "name", None) or "", None)
            node = f"/object/{link}/visual_{k}_{j}"
            self._meshes.append([link, node, mesh, mat, self._material_mesh(node, mesh, mat)])

    def _material_mesh(self, node: str, mesh, mat: dict | None):
        """Add ``mesh`` at ``node`` with its material; returns the handle."""
        if mat is not None and mat["d"] < 1.0:  # glass: a plain transparent mesh
            return self.server.scene.add_mesh_simple(node, mesh.vertices, mesh.faces, color=tuple(mat["Kd"]),
                                                     opacity=mat["d"], side="double")
        if mat is not None:
            mesh = mesh.copy()
            mesh.visual = _pbr_visual(mesh, mat)
        return self.server.scene.add_mesh_trimesh(node, mesh)

    def _frame_camera(self) -> None:
        """Look at the object from the front-left, above, at a distance that fits it."""
        lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
        for link, _, mesh, _, _ in self._meshes:
            T = self.urdf.get_transform(link, self.urdf.base_link)
            V = mesh.vertices @ T[:3, :3].T + T[:3, 3]
            lo, hi = np.minimum(lo, V.min(axis=0)), np.maximum(hi, V.max(axis=0))
        if not np.isfinite(lo).all():
            return
        centre, radius = (lo + hi) / 2, max(float(np.linalg.norm(hi - lo)) / 2, 0.05)
        eye = centre + radius * 2.6 * np.array([-0.75, -0.45, 0.5])
        cams = [self.server.initial_camera] + [c.camera for c in self.server.get_clients().values()]
        for cam in cams:
            cam.position, cam.look_at, cam.up = tuple(eye), tuple(centre), (0.0, 0.0, 1.0)

    def _add_sliders(self) -> None:
        self.joint_folder = self.server.gui.add_folder("joints")
        with self.joint_folder:
            for j in self.urdf.robot.joints:
                if j.type not in ("revolute", "prismatic", "continuous"):
                    continue
                lo, hi = (-np.pi, np.pi) if j.type == "continuous" else (j.limit.lower, j.limit.upper)
                step = (hi - lo) / 200.0
                s = self.server.gui.add_slider(j.name, float(lo), float(hi), float(step), float(np.clip(0.0, lo, hi)))
                s.on_update(lambda _, name=j.name, sl=s: self.set_joint(name, sl.value))
                self.sliders[j.name] = s
                self.q[j.name] = float(s.value)

    # ------------------------------------------------------------ state
    def set_joint(self, name: str, value: float) -> None:
        """Move joint ``name`` to ``value`` (what its slider does)."""
        self.q[name] = float(value)
        self._update_poses()

    def _update_poses(self) -> None:
        names = self.urdf.actuated_joint_names
        self.urdf.update_cfg(np.array([self.q.get(n, 0.0) for n in names], dtype=float))
        base = self.urdf.base_link
        with self.server.atomic():
            for name, frame in self.frames.items():
                T = self.urdf.get_transform(name, base)
                frame.wxyz, frame.position = _wxyz(T), T[:3, 3]

    def _show(self, kind: str, visible: bool) -> None:
        for h in self._layers.get(kind, []):
            h.visible = visible

    def _recolor(self) -> None:
        """Colour the meshes by the chosen mode (labels from the nearest labelled point)."""
        from scipy.spatial import cKDTree

        mode = self.mode.value
        lab = self._labels
        for entry in self._meshes:
            link, node, mesh, mat, h = entry
            h.remove()
            if mode == "material" or lab is None or link not in lab["link_names"]:
                entry[4] = self._material_mesh(node, mesh, mat)
                continue
            sel = lab["link"] == lab["link_names"].index(link)
            if not sel.any():
                entry[4] = self._material_mesh(node, mesh, mat)
                continue
            _, nearest = cKDTree(lab["local"][sel]).query(mesh.vertices)
            key = mode.split(": ")[-1]
            if key in lab["affordance_names"]:
                on = lab["affordance"][sel][nearest, lab["affordance_names"].index(key)]
                cols = np.where(on[:, None], [[230, 60, 40]], [[190, 190, 190]]).astype(np.uint8)
            else:
                cols = label_colors(lab[mode][sel][nearest])
            colored = mesh.copy()
            colored.visual = _vertex_visual(colored, cols)
            entry[4] = self.server.scene.add_mesh_trimesh(node, colored)


def _pbr_visual(mesh, mat: dict):
    """A trimesh visual with the PBR values of an MTL entry (texture, metallic, roughness)."""
    import trimesh

    image = None
    if mat["map_Kd"] is not None and Path(mat["map_Kd"]).is_file():
        from PIL import Image

        image = Image.open(mat["map_Kd"]).convert("RGB")
    pbr = trimesh.visual.material.PBRMaterial(
        baseColorFactor=[255, 255, 255, 255] if image is not None else [int(c * 255) for c in mat["Kd"]] + [255],
        baseColorTexture=image, metallicFactor=mat["Pm"], roughnessFactor=mat["Pr"])
    uv = getattr(mesh.visual, "uv", None)
    return trimesh.visual.TextureVisuals(uv=uv, material=pbr)


def _vertex_visual(mesh, colors: np.ndarray):
    import trimesh

    rgba = np.concatenate([colors, np.full((len(colors), 1), 255, np.uint8)], axis=1)
    return trimesh.visual.ColorVisuals(mesh, vertex_colors=rgba)
