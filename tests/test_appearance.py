"""Appearance: visual materials per part (one source of truth, consistent with the
densities), procedural textures, and their export (OBJ normals/UVs, MTL, URDF)."""

from __future__ import annotations

import numpy as np
import pytest

import artipg
from artipg.appearance import FAMILIES, materials_of, texture_image, texture_png
from artipg.materials import CLASS_DENSITY, FINISHES, material_class

CATEGORIES = artipg.categories()
WOODY = {"wood", "lacquered_wood", "painted_wood"}
APPLIANCES = ("refrigerator", "microwave", "oven", "dishwasher", "washing_machine", "safe")


@pytest.mark.parametrize("category", CATEGORIES)
def test_every_part_has_a_material_consistent_with_its_density(category):
    for seed in range(3):
        obj = artipg.generate(category, seed)
        mats = materials_of(obj)
        assert set(mats) == {p.name for p in obj.parts}
        for part in obj.parts:
            m = mats[part.name]
            cls = material_class(part.semantic, obj.materials)
            # the look and the weight agree: the material dresses the part's density class
            assert m.density_class == cls and cls in CLASS_DENSITY
            assert m.family in FINISHES[cls], (part.semantic, m.family, cls)
            assert 0 <= m.metallic <= 1 and 0 <= m.roughness <= 1 and 0 < m.opacity <= 1
            assert all(0 <= c <= 1 for c in m.color)


def test_finishes_name_known_families():
    for cls, fams in FINISHES.items():
        assert cls in CLASS_DENSITY
        assert set(fams) <= set(FAMILIES), cls
    assert set(CLASS_DENSITY) == set(FINISHES)


def test_same_seed_same_materials_and_textures():
    a, b = artipg.generate("storage_furniture", 7), artipg.generate("storage_furniture", 7)
    ma, mb = materials_of(a), materials_of(b)
    assert ma == mb
    tex = [m for m in ma.values() if m.texture]
    assert tex and all(texture_png(m) == texture_png(mb[k]) for k, m in ma.items() if m.texture)
    # another seed draws other materials somewhere in a few objects
    others = [materials_of(artipg.generate("storage_furniture", s)) for s in range(8, 12)]
    assert any(set(m.values()) != set(ma.values()) for m in others)


def test_cabinet_fronts_match_the_carcass_and_handles_contrast():
    for seed in range(10):
        obj = artipg.generate("storage_furniture", seed)
        mats = materials_of(obj)
        by_label = {}
        for p in obj.parts:
            by_label.setdefault(p.semantic, set()).add(mats[p.name])
        body = by_label["body"]
        assert len(body) == 1
        for label in ("door", "drawer"):
            assert by_label.get(label, body) == body, (seed, label)
        if "handle" in by_label:
            assert {m.family for m in by_label["handle"]}.isdisjoint({m.family for m in body})


@pytest.mark.parametrize("category", APPLIANCES)
def test_appliances_are_never_wood(category):
    for seed in range(6):
        obj = artipg.generate(category, seed)
        fams = {m.family for m in materials_of(obj).values()}
        assert not fams & WOODY, (category, seed, fams)


def test_glass_is_see_through_and_displays_are_not():
    obj = artipg.generate("window", 0)
    mats = materials_of(obj)
    panes = [mats[p.name] for p in obj.parts if p.semantic == "glass"]
    assert panes and all(m.opacity < 0.5 and m.transmission > 0.5 for m in panes)
    obj = artipg.generate("microwave", 0)
    screens = [materials_of(obj)[p.name] for p in obj.parts if p.semantic == "screen"]
    assert all(m.family == "display" and m.opacity == 1 for m in screens)


def test_to_pbr_is_linear_and_points_at_the_texture():
    obj = artipg.generate("storage_furniture", 1)
    for m in set(materials_of(obj).values()):
        pbr = m.to_pbr()
        assert len(pbr["baseColorFactor"]) == 4 and pbr["baseColorFactor"][3] == m.opacity
        if m.texture:
            assert pbr["texture"] == f"textures/{m.name}.png" and pbr["baseColorFactor"][:3] == (1, 1, 1)
        else:  # linear values are darker than sRGB ones
            assert pbr["texture"] is None
            assert all(lin <= s + 1e-12 for lin, s in zip(pbr["baseColorFactor"][:3], m.color))


@pytest.mark.parametrize("kind", ["wood", "brushed", "noise"])
def test_textures_tile_and_carry_the_colour(kind):
    params = (3, 0.7, 0.5, 0.3, 0.5, 0.35, 0.2, 10.0, 0.6) if kind == "wood" else (3, 0.7, 0.5, 0.3, 0.1)
    img = texture_image(kind, params, 128).astype(float)
    assert img.shape == (128, 128, 3)
    # seamless: the jump across the tile border is no bigger than inside the tile
    inner = np.abs(np.diff(img, axis=1)).mean()
    border = np.abs(img[:, 0] - img[:, -1]).mean()
    assert border < 3 * inner + 1.0
    assert np.allclose(img.reshape(-1, 3).mean(0) / 255, params[1:4], atol=0.12)
    assert img.std() > 0.5  # not a flat colour


def test_unknown_texture_kind_fails_clearly():
    with pytest.raises(ValueError, match="unknown texture kind"):
        texture_image("marble", (0,))


# ---------------------------------------------------------------- export

@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    from artipg.export import export_object

    root = tmp_path_factory.mktemp("appearance")
    return {c: export_object(artipg.generate(c, 2), root / c, n_points=0) for c in ("storage_furniture", "window",
                                                                                    "faucet", "kettle")}


def _obj_records(text: str) -> dict:
    out = {}
    for line in text.splitlines():
        tag = line.split(" ", 1)[0]
        out.setdefault(tag, []).append(line)
    return out


def test_every_visual_obj_has_normals_uvs_and_known_materials(exported):
    for dest in exported.values():
        mtl = (dest / "meshes" / "materials.mtl").read_text()
        names = {line.split()[1] for line in mtl.splitlines() if line.startswith("newmtl")}
        for line in mtl.splitlines():
            if line.startswith("map_Kd"):
                assert (dest / "meshes" / line.split()[1]).resolve().is_file()
        for path in (dest / "meshes").glob("*.obj"):
            rec = _obj_records(path.read_text())
            if "_c" in path.stem and "vt" not in rec:
                continue  # a collision hull
            assert len(rec["v"]) == len(rec["vn"]) == len(rec["vt"]) > 0, path
            assert {line.split()[1] for line in rec["usemtl"]} <= names
            assert all(len(f.split()) == 4 and f.count("/") == 6 for f in rec["f"])


def test_normals_point_out_of_the_faces(exported):
    import trimesh

    from artipg.export.meshes import link_visual_surface

    obj = artipg.generate("kettle", 2)
    for link in obj.links:
        surf = link_visual_surface(link, materials_of(obj))
        if surf is None:
            continue
        V, N, UV, F, groups = surf
        fn = trimesh.triangles.normals(V[F])[0]
        valid = trimesh.triangles.normals(V[F])[1]
        corner = N[F[valid]]  # (F, 3, 3)
        dots = np.einsum("fkj,fj->fk", corner, fn)
        assert (dots > 0.5).mean() > 0.99, link.name  # smooth normals stay within the crease angle
        assert groups[-1][2] == len(F) and UV.shape == (len(V), 2)


def test_urdf_materials_and_textures_load(exported):
    import trimesh
    import yourdfpy

    dest = exported["storage_furniture"]
    robot = yourdfpy.URDF.load(str(dest / "mobility.urdf"), build_scene_graph=False, load_meshes=False)
    mats = [v.material for link in robot.robot.links for v in link.visuals]
    assert mats and all(m is not None and m.color is not None for m in mats)
    tex = [m.texture.filename for m in mats if m.texture is not None]
    assert tex and all((dest / t).is_file() for t in tex)
    mesh = trimesh.load(dest / "meshes" / "base_0.obj", force="mesh")
    assert isinstance(mesh.visual, trimesh.visual.TextureVisuals) and mesh.visual.uv is not None


def test_window_glass_is_exported_transparent(exported):
    mtl = (exported["window"] / "meshes" / "materials.mtl").read_text()
    opacity = {}
    for line in mtl.splitlines():
        if line.startswith("newmtl"):
            name = line.split()[1]
        elif line.startswith("d "):
            opacity[name] = float(line.split()[1])
    assert opacity["glass_glass"] < 0.5 and opacity["main_wood"] == 1.0


def test_export_is_byte_identical_per_seed(exported, tmp_path):
    from artipg.export import export_object

    again = export_object(artipg.generate("storage_furniture", 2), tmp_path / "again", n_points=0)
    a = {p.relative_to(exported["storage_furniture"]): p.read_bytes() for p in exported["storage_furniture"].rglob("*")
         if p.is_file()}
    b = {p.relative_to(again): p.read_bytes() for p in again.rglob("*") if p.is_file()}
    assert a == b and any(str(k).startswith("textures/") for k in a)


def _uv_stretch(prim):
    """Per triangle of a primitive's render surface: the largest ratio of a texture-space
    edge length (m) to the same edge's length in space."""
    from artipg.appearance.textures import TILE_METRES
    from artipg.export.meshes import primitive_surface_arrays

    V, _, UV, F, _ = primitive_surface_arrays(prim.geom, prim.params, 24)
    e3 = np.linalg.norm(V[F] - V[np.roll(F, 1, axis=1)], axis=2)
    e2 = np.linalg.norm(UV[F] - UV[np.roll(F, 1, axis=1)], axis=2) * TILE_METRES
    return (e2 / np.maximum(e3, 1e-12)).max(axis=1)


def test_analytic_uvs_keep_real_scale_and_do_not_wrap_at_seams():
    """Cylinders, rings, boxes, extrusions and tubes: texture space is metres on the
    surface, so no triangle stretches its texture (a triangle across a seam would span
    the whole period)."""
    from artipg.geometry import cylinder, ring, torus, tube, line, arc
    from artipg.geometry.extrusion import extrusion
    from artipg.geometry.profile import circle, rectangle
    from artipg.geometry.rounded_box import rounded_box

    # bound: 1 + chord slack, or the rim radius over the smallest radius of a curved
    # surface (a lathe's u is the angle times its largest radius)
    cases = [(cylinder(0.2, 0.5), 1.01), (rounded_box(0.6, 0.4, 0.05, 0.01), 1.01), (rounded_box(0.3, 0.3, 0.3), 1.01),
             (extrusion([rectangle(0.5, 0.3, 0.04), circle(0.05)], 0.02), 1.01), (extrusion([circle(0.1)], 0.3), 1.01),
             (ring(0.3, 0.25, 0.1), 0.3 / 0.25 * 1.01), (torus(0.1, 0.02), 0.12 / 0.08 * 1.01),
             *[(p, 0.06 / 0.04 * 1.05) for p in tube(0.01, [line(0.3), arc(0.05, 1.5)], 0.0)]]
    for prim, bound in cases:
        assert _uv_stretch(prim).max() < bound, prim


def test_round_table_tops_are_mapped_flat():
    """Faces of a lathe facing up take planar coordinates: no texture converging to the
    centre of a round top (one texel per unit area everywhere)."""
    from artipg.geometry import cylinder

    prim = cylinder(0.4, 0.03)
    from artipg.export.meshes import primitive_surface_arrays

    V, N, UV, F, _ = primitive_surface_arrays(prim.geom, prim.params, 24)
    top = np.abs(N[:, 2]) > 0.999
    from artipg.appearance.textures import TILE_METRES

    assert np.allclose(UV[top] * TILE_METRES, V[top, :2] + 0.4)


def test_rules_carry_graduations_at_their_real_spacing():
    """Rule segments, arms and tape blades wear a printed scale: ticks every millimetre of
    surface (texture space is metres), centimetre ticks longer than millimetre ones,
    the ground in the part's own colour; the same seed gives the same image."""
    from artipg.appearance.textures import TILE_METRES

    for seed in range(6):
        obj = artipg.generate("ruler", seed)
        mats = materials_of(obj)
        marked = [mats[p.name] for p in obj.parts if p.semantic in ("segment", "arm", "blade")]
        assert marked and all(m.texture == "scale" for m in marked)
        others = [mats[p.name] for p in obj.parts if p.semantic not in ("segment", "arm", "blade")]
        assert all(m.texture != "scale" for m in others)
    m = marked[0]
    img = texture_image(m.texture, m.texture_params)
    size = img.shape[0]
    ground = np.rint(np.array(m.color) * 255)
    inked = (np.abs(img.astype(int) - ground).sum(axis=2) > 60)  # (rows, cols)
    tick = inked[:, 0]  # every tick starts at the edge u = 0
    rows = np.flatnonzero(tick & ~np.roll(tick, -1))  # one row per tick (its last line)
    mm = np.diff(np.sort(rows)) / size * TILE_METRES
    assert len(rows) == round(TILE_METRES * 1000)
    assert np.allclose(mm, 0.001, atol=TILE_METRES / size)
    lengths = inked.sum(axis=1)[rows]
    assert lengths.max() > 2 * lengths.min()  # centimetre ticks reach further in
    assert np.array_equal(img, texture_image(m.texture, m.texture_params))
