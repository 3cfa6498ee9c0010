"""Materials travel in every format: MuJoCo compiles the MJCF's textures and materials,
``pxr`` resolves the USD's preview surfaces and texture files, trimesh reads the GLB's
PBR values, all equal to :func:`artipg.appearance.materials_of` (see docs/formats.md)."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

import artipg
from artipg.appearance import materials_of
from artipg.export.folder import export_object
from artipg.export.meshes import link_visual_surface

mujoco = pytest.importorskip("mujoco")

ALL = ("urdf", "mjcf", "usd", "glb")
#: textured and plain materials, glass, links with one and with several materials
CASES = (("microwave", 0), ("storage_furniture", 1), ("faucet", 0), ("laptop", 2))
#: MTL files keep 4 decimals: the formats carry the materials to that precision
TOL = 6e-4


@pytest.fixture(scope="module")
def out(tmp_path_factory):
    return tmp_path_factory.mktemp("matfmt")


_made: dict = {}


def case(out: Path, category: str, seed: int):
    """(object, folder with all formats, {material name: Material}, {link: [material names]})."""
    key = (category, seed)
    if key not in _made:
        obj = artipg.generate(category, seed)
        f = export_object(obj, out / category / str(seed), n_points=0, formats=ALL)
        parts = materials_of(obj)
        mats = {m.name: m for m in parts.values()}
        groups = {}
        for lk in obj.links:
            surf = link_visual_surface(lk, parts)
            if surf is not None:
                groups[lk.name] = [m.name for m, *_ in surf[4]]
        _made[key] = obj, f, mats, groups
    return _made[key]


@pytest.mark.parametrize("category,seed", CASES)
def test_mujoco_compiles_textures_and_materials(out, category, seed, capfd):
    obj, f, mats, groups = case(out, category, seed)
    m = mujoco.MjModel.from_xml_path(str(f / "mobility.xml"))
    assert m.nmat == len({n for g in groups.values() for n in g})
    assert m.ntex == len({n for g in groups.values() for n in g if mats[n].texture})
    rgb_role = int(mujoco.mjtTextureRole.mjTEXROLE_RGB)
    name = lambda t, i: mujoco.mj_id2name(m, t, i)  # noqa: E731
    for i in range(m.nmat):
        mat = mats[name(mujoco.mjtObj.mjOBJ_MATERIAL, i)]
        want = (1.0, 1.0, 1.0) if mat.texture else mat.color
        assert np.abs(m.mat_rgba[i] - [*want, mat.opacity]).max() < TOL
        assert abs(m.mat_metallic[i] - mat.metallic) < TOL and abs(m.mat_roughness[i] - mat.roughness) < TOL
        tex = m.mat_texid[i, rgb_role]
        assert (tex >= 0) == bool(mat.texture)
        if tex >= 0:
            assert name(mujoco.mjtObj.mjOBJ_TEXTURE, tex) == mat.name
            assert (m.tex_width[tex], m.tex_height[tex]) == (256, 256)
    # one visual geom per material of each link, wearing it, on a mesh with texture coordinates
    seen: dict = {}
    for g in range(m.ngeom):
        if m.geom_group[g] != 2:
            continue
        body = name(mujoco.mjtObj.mjOBJ_BODY, m.geom_bodyid[g])
        seen.setdefault(body, []).append(name(mujoco.mjtObj.mjOBJ_MATERIAL, m.geom_matid[g]))
        mesh = m.geom_dataid[g]
        assert mesh >= 0 and m.mesh_texcoordnum[mesh] > 0
    assert seen == groups
    captured = capfd.readouterr()
    assert "warning" not in (captured.out + captured.err).lower()


def test_mujoco_refuses_a_missing_texture(out, tmp_path):
    """Planted fault: the MJCF names texture files that must exist."""
    _, f, _, _ = case(out, "microwave", 0)
    bad = tmp_path / "bad"
    shutil.copytree(f, bad)
    next((bad / "textures").glob("*.png")).unlink()
    with pytest.raises(ValueError):
        mujoco.MjModel.from_xml_path(str(bad / "mobility.xml"))


def _input_value(shader, name: str):
    """The value of a shader input, or the shader its connection comes from."""
    from pxr import UsdShade

    inp = shader.GetInput(name)
    if inp.HasConnectedSource():
        src = inp.GetConnectedSources()[0][0]
        return UsdShade.Shader(src.source.GetPrim())
    return inp.Get()


@pytest.mark.parametrize("category,seed", CASES)
def test_usd_preview_surfaces_resolve(out, category, seed):
    from pxr import Usd, UsdGeom, UsdShade

    obj, f, mats, groups = case(out, category, seed)
    stage = Usd.Stage.Open(str(f / "mobility.usd"))
    root = stage.GetDefaultPrim()
    for link, names in groups.items():
        mesh = stage.GetPrimAtPath(root.GetPath().AppendPath(f"{link}/visuals/mesh"))
        assert mesh.IsValid()
        n_points = len(UsdGeom.Mesh(mesh).GetPointsAttr().Get())
        st = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("st")
        assert st.GetInterpolation() == UsdGeom.Tokens.vertex and len(st.Get()) == n_points
        assert len(UsdGeom.Mesh(mesh).GetNormalsAttr().Get()) == n_points
        binding = UsdShade.MaterialBindingAPI(mesh)
        bound = binding.ComputeBoundMaterial()[0]
        assert bound and bound.GetPrim().GetName() in names
        subsets = binding.GetMaterialBindSubsets()
        if len(names) == 1:
            assert not subsets
            pairs = [(bound, names[0])]
        else:
            assert [s.GetPrim().GetName() for s in subsets] == names
            pairs = [(UsdShade.MaterialBindingAPI(s.GetPrim()).ComputeBoundMaterial()[0], n)
                     for s, n in zip(subsets, names)]
        for material, want in pairs:
            mat = mats[want]
            assert material.GetPrim().GetName() == want
            shader = material.ComputeSurfaceSource()[0]
            assert shader.GetIdAttr().Get() == "UsdPreviewSurface"
            for key, value in (("metallic", mat.metallic), ("roughness", mat.roughness), ("opacity", mat.opacity)):
                assert abs(_input_value(shader, key) - value) < TOL
            diffuse = _input_value(shader, "diffuseColor")
            if mat.texture:
                assert diffuse.GetIdAttr().Get() == "UsdUVTexture"
                path = diffuse.GetInput("file").Get().resolvedPath
                assert path and Path(path).is_file() and Path(path).name == f"{want}.png"
                reader = _input_value(diffuse, "st")
                assert reader.GetIdAttr().Get() == "UsdPrimvarReader_float2"
                assert reader.GetInput("varname").Get() == "st"
            else:
                linear = mat.to_pbr()["baseColorFactor"][:3]
                assert np.abs(np.array(diffuse) - linear).max() < TOL


@pytest.mark.parametrize("category,seed", CASES)
def test_glb_carries_pbr_materials(out, category, seed):
    import trimesh
    from PIL import Image

    from artipg.appearance import texture_png

    obj, f, mats, groups = case(out, category, seed)
    scene = trimesh.load(f / "mobility.glb")
    found = {}
    for link, names in groups.items():
        nodes = [link] + [f"{link}_visual{k}" for k in range(1, len(names))]
        found[link] = []
        for node in nodes:
            geom = scene.geometry[scene.graph[node][1]]
            material = geom.visual.material
            assert isinstance(material, trimesh.visual.material.PBRMaterial)
            found[link].append(material.name)
            mat, pbr = mats[material.name], mats[material.name].to_pbr()
            factor = np.asarray(material.baseColorFactor, dtype=float) / 255.0
            assert np.abs(factor - pbr["baseColorFactor"]).max() <= 1.0 / 255 + TOL
            assert abs(material.metallicFactor - mat.metallic) < TOL
            assert abs(material.roughnessFactor - mat.roughness) < TOL
            assert geom.visual.uv.shape == (len(geom.vertices), 2)
            if mat.texture:
                import io

                want = np.asarray(Image.open(io.BytesIO(texture_png(mat))))
                assert np.array_equal(np.asarray(material.baseColorTexture), want)
            else:
                assert material.baseColorTexture is None
    assert found == groups


def test_every_format_is_deterministic_and_convert_gives_the_same(tmp_path):
    """Same seed, same bytes in every format and texture; converting the URDF-only
    folder reads the materials back from its OBJ and MTL files to the same bytes."""
    obj = artipg.generate("storage_furniture", 2)
    a = export_object(obj, tmp_path / "a", n_points=0, formats=ALL)
    b = export_object(artipg.generate("storage_furniture", 2), tmp_path / "b", n_points=0, formats=ALL)
    names = ["mobility.xml", "mobility.usd", "mobility.glb"]
    names += [f"textures/{p.name}" for p in (a / "textures").iterdir()]
    assert len(names) > 3
    for name in names:
        assert (a / name).read_bytes() == (b / name).read_bytes(), name
    from artipg.export.convert import convert_folder

    c = export_object(obj, tmp_path / "c", n_points=0, formats=("urdf",))
    convert_folder(c, formats=("mjcf", "usd", "glb"))
    for name in ("mobility.xml", "mobility.usd", "mobility.glb"):
        assert (c / name).read_bytes() == (a / name).read_bytes(), name


def test_third_party_folders_keep_label_colours(tmp_path):
    """A folder without artipg's materials (an MTL with colours only, as
    PartNet-Mobility's) converts as before: no MJCF materials or textures, GLB vertex
    colours, no USD material."""
    import trimesh
    from pxr import Usd, UsdShade

    from artipg.export.convert import convert_folder

    f = tmp_path / "thing"
    (f / "m").mkdir(parents=True)
    box = trimesh.creation.box(extents=(0.3, 0.2, 0.1))
    lines = ["mtllib body.mtl"] + [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in box.vertices]
    lines += ["vt 0 0" for _ in box.vertices] + ["vn 0 0 1" for _ in box.vertices] + ["usemtl paint"]
    lines += [f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}" for a, b, c in box.faces + 1]
    (f / "m" / "body.obj").write_text("\n".join(lines) + "\n")
    (f / "m" / "body.mtl").write_text("newmtl paint\nKd 0.8 0.1 0.1\nd 1\n")
    link = ('<link name="{n}"><visual><geometry><mesh filename="m/body.obj"/></geometry></visual>'
            '<collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision></link>')
    (f / "mobility.urdf").write_text(
        f'<robot name="thing">{link.format(n="base")}{link.format(n="lid")}'
        '<joint name="j" type="revolute"><parent link="base"/><child link="lid"/><origin xyz="0 0 0.1"/>'
        '<axis xyz="0 1 0"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint></robot>')
    convert_folder(f, formats=("mjcf", "usd", "glb"))
    text = (f / "mobility.xml").read_text()
    assert "<material" not in text and "<texture" not in text
    m = mujoco.MjModel.from_xml_path(str(f / "mobility.xml"))
    assert m.nmat == 0 and m.ntex == 0
    scene = trimesh.load(f / "mobility.glb")
    assert all(g.visual.kind == "vertex" for g in scene.geometry.values())
    stage = Usd.Stage.Open(str(f / "mobility.usd"))
    assert not any(p.IsA(UsdShade.Material) for p in stage.Traverse())
