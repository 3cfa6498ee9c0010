"""Colour images of objects with their materials, on the CPU with Mitsuba 3 (optional:
``pip install mitsuba``).

The scene holds each link's visual surface (:func:`artipg.export.meshes.link_visual_surface`,
the exported meshes' normals and UVs) at the requested joint state, one principled BSDF
per material (base colour or texture, metallic, roughness; glass as a dielectric), a
constant sky and a sun. Cameras are :class:`artipg.annotate.views.Camera` (OpenCV axes),
so a colour image lines up with the depth and label images of
:func:`artipg.annotate.views.render_view` for the same camera. The sampler is seeded,
so the same seed gives the same image on one machine.
"""

from __future__ import annotations

import numpy as np

#: Mitsuba variants tried in order (the first that loads is used). scalar_rgb first:
#: the LLVM variant failed to compile its kernels on our machines.
VARIANTS = ("scalar_rgb", "llvm_ad_rgb")


def _mitsuba():
    import mitsuba as mi

    if mi.variant() is None:
        for v in VARIANTS:
            try:
                mi.set_variant(v)
                break
            except (ImportError, AttributeError, RuntimeError):
                continue
    return mi


def _bsdf(mi, material) -> dict:
    """A Mitsuba BSDF dict of an :class:`artipg.appearance.Material`."""
    from artipg.appearance.textures import texture_image

    if material.opacity < 1.0:  # glass: a smooth dielectric tinted by its colour
        return {"type": "dielectric", "int_ior": 1.5, "specular_transmittance": {"type": "rgb",
                                                                              "value": list(material.color)}}
    if material.texture:
        img = texture_image(material.texture, material.texture_params)
        base = {"type": "bitmap", "bitmap": mi.Bitmap(img), "filter_type": "bilinear", "wrap_mode": "repeat"}
    else:
        lin = material.to_pbr()["baseColorFactor"][:3]
        base = {"type": "rgb", "value": list(lin)}
    return {"type": "principled", "base_color": base, "metallic": float(material.metallic),
            "roughness": float(max(material.roughness, 0.02))}


def build_scene(obj, qpos=None, sections: int = 32, sun: tuple = (0.4, -0.6, 0.7), sky: float = 0.7):
    """The Mitsuba scene of ``obj`` at joint state ``qpos`` (object frame, metres).

    ``sun`` is the direction towards the sun (object frame), ``sky`` the radiance of the
    constant environment.
    """
    from artipg.appearance import materials_of
    from artipg.export.meshes import link_visual_surface

    mi = _mitsuba()
    mats = materials_of(obj)
    poses = obj.link_poses(qpos)
    bsdfs: dict = {}
    scene: dict = {"type": "scene", "integrator": {"type": "path", "max_depth": 8, "hide_emitters": True},
                   "sky": {"type": "constant", "radiance": {"type": "rgb", "value": [sky] * 3}},
                   "sun": {"type": "directional", "direction": list(-np.asarray(sun, dtype=float)),
                           "irradiance": {"type": "rgb", "value": [2.2, 2.1, 2.0]}}}
    for li, link in enumerate(obj.links):
        surf = link_visual_surface(link, mats, sections)
        if surf is None:
            continue
        V, N, UV, F, groups = surf
        R, t = poses[li][:3, :3], poses[li][:3, 3]
        Vw, Nw = V @ R.T + t, N @ R.T
        for material, f0, f1, _ in groups:
            if material.name not in bsdfs:
                bsdfs[material.name] = mi.load_dict(_bsdf(mi, material))
            used, faces = np.unique(F[f0:f1], return_inverse=True)
            props = mi.Properties()
            props["bsdf"] = bsdfs[material.name]
            mesh = mi.Mesh(f"{link.name}_{material.name}", len(used), f1 - f0, props=props,
                           has_vertex_normals=True, has_vertex_texcoords=True)
            p = mi.traverse(mesh)
            uv = UV[used].copy()
            uv[:, 1] = 1.0 - uv[:, 1]  # Mitsuba's bitmaps have v = 0 at the top row
            for key, arr, kind in (("vertex_positions", Vw[used], np.float32), ("vertex_normals", Nw[used], np.float32),
                                   ("vertex_texcoords", uv, np.float32), ("faces", faces, np.uint32)):
                p[key] = type(p[key])(np.ascontiguousarray(arr, dtype=kind).ravel())
            p.update()
            scene[f"{link.name}_{material.name}"] = mesh
    return mi.load_dict(scene)


def _sensor(mi, cam, spp: int):
    """A Mitsuba perspective sensor for an OpenCV :class:`Camera`."""
    fy = float(cam.K[1, 1])
    fov = float(np.degrees(2.0 * np.arctan(cam.height / (2.0 * fy))))
    # Mitsuba cameras look along +z with +x left and +y up: OpenCV's x and y flipped
    to_world = np.asarray(cam.pose, dtype=float) @ np.diag([-1.0, -1.0, 1.0, 1.0])
    return mi.load_dict({
        "type": "perspective", "fov": fov, "fov_axis": "y", "to_world": mi.ScalarTransform4f(to_world.tolist()),
        "principal_point_offset_x": float(cam.K[0, 2] / cam.width - 0.5),
        "principal_point_offset_y": float(cam.K[1, 2] / cam.height - 0.5),
        "sampler": {"type": "independent", "sample_count": spp},
        "film": {"type": "hdrfilm", "width": int(cam.width), "height": int(cam.height), "pixel_format": "rgba",
                 "rfilter": {"type": "box"}}})


def random_lighting(rng: np.random.Generator) -> dict:
    """Randomised lighting and background of one view, for domain randomisation:
    keyword arguments of :func:`build_scene` (``sun``, ``sky``) and :func:`render_rgb`
    (``background``), drawn from ``rng``."""
    az, el = rng.uniform(0.0, 2.0 * np.pi), rng.uniform(0.35, 1.3)
    return {"sun": (float(np.cos(az) * np.cos(el)), float(np.sin(az) * np.cos(el)), float(np.sin(el))),
            "sky": float(rng.uniform(0.4, 1.0)), "background": tuple(float(v) for v in rng.uniform(0.1, 0.95, 3))}


def render_rgb(scene, cam, spp: int = 16, seed: int = 0,
               background: tuple = (0.85, 0.85, 0.85)) -> tuple[np.ndarray, np.ndarray]:
    """Colour image (H, W, 3) uint8 sRGB and coverage (H, W) float in [0, 1] of ``scene``
    (:func:`build_scene`) seen by ``cam`` over a plain ``background`` (sRGB); ``seed``
    seeds the sampler. Coverage above 0.5 marks the pixels whose centre ray hits the
    object, as the label images of :func:`artipg.annotate.views.render_view` do."""
    from artipg.appearance.material import srgb_to_linear

    mi = _mitsuba()
    img = np.asarray(mi.render(scene, sensor=_sensor(mi, cam, spp), spp=spp, seed=seed))
    alpha = np.clip(img[..., 3], 0.0, 1.0)
    rgb = np.clip(img[..., :3] + (1.0 - alpha)[..., None] * srgb_to_linear(background), 0.0, 1.0)
    srgb = np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * rgb ** (1 / 2.4) - 0.055)
    return np.rint(srgb * 255).astype(np.uint8), alpha


def rgb_view_arrays(obj, views: dict, qpos=None, spp: int = 16, seed: int = 0,
                    randomize: bool = False) -> dict[str, np.ndarray]:
    """Colour images of the partial views ``views`` (the dict of
    :func:`artipg.annotate.arrays.view_arrays`, whose cameras they reuse, so pixel (r, c)
    of ``rgb[i]`` is pixel (r, c) of ``instance_image[i]``).

    Returns ``{"rgb": (V, H, W, 3) uint8, "rgb_coverage": (V, H, W) float32}``. With
    ``randomize`` every view draws its own sun, sky and background
    (:func:`random_lighting`) from a stream keyed by (``seed``, 'appearance-lighting', view).
    """
    from artipg.annotate.views import Camera
    from artipg.rules.streams import stream_key

    poses, Ks = views["camera_poses"].astype(float), views["camera_intrinsics"].astype(float)
    h, w = views["depth"].shape[1:] if "depth" in views else (240, 320)
    scene = None if randomize else build_scene(obj, qpos)
    rgbs, covs = [], []
    for i, (T, K) in enumerate(zip(poses, Ks)):
        cam = Camera(T, K, int(w), int(h))
        background = (0.85, 0.85, 0.85)
        if randomize:
            rng = np.random.Generator(np.random.PCG64(np.random.SeedSequence(
                int(seed), spawn_key=(stream_key("appearance-lighting"), i))))
            light = random_lighting(rng)
            background = light.pop("background")
            scene = build_scene(obj, qpos, **light)
        rgb, cov = render_rgb(scene, cam, spp=spp, seed=seed * 1009 + i, background=background)
        rgbs.append(rgb)
        covs.append(cov.astype(np.float32))
    return {"rgb": np.stack(rgbs), "rgb_coverage": np.stack(covs)}
