"""Physical validation and repair (issue 3).

- the distance machinery is exact where it claims to be (row SDFs, box-box);
- deliberately broken objects are caught by the right check: a door whose hinge
  axis is flipped, a drawer 5 mm wider than its opening, a handle floating 1 cm off
  its door, a lid sunk into its pot; first on generated objects of real categories,
  then on small categories whose defect is a recorded parameter, which repair must
  find and fix;
- every registered category validates, deterministically, and reproduces from its
  recorded parameters (what repair relies on);
- collision pieces are convex and never fill a hollow body; inertials are sane;
- ``artipg validate`` on artipg and PartNet-Mobility-style folders.
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import artipg
from artipg.export.folder import export_object
from artipg.geometry import Primitive, cuboid, cylinder, frustum, prism, ring, sphere, torus, tri_prism
from artipg.geometry.transforms import rotation, translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.bodies import carcass, cylindrical_shell
from artipg.templates.handles import flat_bar_handle
from artipg.templates.mounting import front_thickness, handle_pose, mount_hinged, mount_sliding
from artipg.templates.panels import box_drawer, slab_door
from artipg.validate import check_object, generate_valid, replacement_seed
from artipg.validate.blame import part_params
from artipg.validate.contacts import box_box
from conftest import CATEGORIES

SEEDS = (0, 1, 2)


def _invalidate(obj):
    """Drop cached geometry after editing an object in place."""
    obj.__dict__.pop("primitive_table", None)


def _find(obj, pred):
    for li, link in enumerate(obj.links):
        for part in link.parts:
            if pred(link, part):
                return li, link, part
    return None


# ---------------------------------------------------------------- exact distances

@pytest.mark.parametrize("prim", [cuboid(0.1, 0.2, 0.3), frustum(0.1, 0.05, 0.2), cylinder(0.08, 0.1),
                                  ring(0.1, 0.08, 0.1, arc=2.0), ring(0.12, 0.1, 0.2, arc=4.5, taper=0.03),
                                  sphere(0.1, -0.02, 0.05), torus(0.1, 0.02, arc=1.0), torus(0.1, 0.01),
                                  prism(0.1, 0.2, 5), prism(0.1, 0.05, 3), tri_prism(0.1, 0.05, 0.02, 0.1)],
                         ids=lambda p: p.geom.name)
def test_piece_sdfs_have_the_right_sign_and_distance(prim):
    """The validation SDF of every template against dense surface samples of the
    template's own sampler and against its mesh: negative exactly inside the mesh
    (for points more than a millimetre off the surface); never farther than the
    nearest sample (a lower bound of the distance: a cut or a wedge only bounds it
    outside); the distance itself, within the sample spacing, for the solids whose
    SDF is exact (all but partial turns of lathes)."""
    from scipy.spatial import cKDTree

    from artipg.validate.shapes import Pieces

    g, p = prim.geom, np.array(prim.params, dtype=float)
    b = g.bounds(p)
    pieces = Pieces([0], [0], np.eye(4)[None], ((b[0] + b[1]) / 2)[None], ((b[1] - b[0]) / 2)[None], [g], p[None],
                    ["p"], [0], 0)
    rng = np.random.default_rng(3)
    S, _ = g.sample(np.repeat(p[None], 200_000, axis=0), rng)
    spacing = 3.0 * np.sqrt(g.area(p[None])[0] / len(S))
    x = (b[0] + b[1]) / 2 + rng.uniform(-0.75, 0.75, (4000, 3)) * (b[1] - b[0]) + rng.normal(size=(4000, 3)) * 0.01
    d = pieces.sdf(np.zeros(len(x), dtype=np.int64), x)
    nn, _ = cKDTree(S).query(x)
    assert (np.abs(d) <= nn + 1e-9).all()
    partial = g.kind == "lathe" and p[-3] < 2 * np.pi  # the wedge only bounds the distance
    exact = np.full(len(x), not partial)
    assert exact.sum() > 300 or partial
    assert (np.abs(d[exact]) >= nn[exact] - spacing).all()
    far = np.abs(d) > 1e-3
    assert (d[far] > 0).sum() > 100 and (d[far] < 0).sum() > 100
    assert np.array_equal(d[far] < 0, g.mesh(tuple(p), sections=256).contains(x[far]))


def test_unknown_template_fails_with_a_clear_error():
    from artipg.geometry.base import GeometryTemplate
    from artipg.validate.shapes import Pieces

    class Blob(GeometryTemplate):
        name = "blob"
        params = ("r",)

    with pytest.raises(ValueError, match="Blob"):
        Pieces([0], [0], np.eye(4)[None], np.zeros((1, 3)), np.ones((1, 3)), [Blob], np.ones((1, 1)), ["p"], [0], 0)


def test_box_box_depth_and_distance_are_exact():
    h = np.array([[0.05, 0.05, 0.05]])
    I = np.eye(4)[None]
    # overlapping by 3 mm along x: depth 3 mm
    d = box_box(h, h, I, translation(0.097, 0.01, 0.0)[None], np.array([1.0]))
    assert d[0] == pytest.approx(-0.003, abs=1e-12)
    # apart by 2 mm in x and 3 mm in y (corner to corner): distance sqrt(13) mm
    d = box_box(h, h, I, translation(0.102, 0.103, 0.0)[None], np.array([1.0]))
    assert d[0] == pytest.approx(math.sqrt(0.002 ** 2 + 0.003 ** 2), abs=1e-12)
    # a box rotated 45 degrees about z, its edge 2 mm from the other's face: 2 mm
    R = rotation((0, 0, 1), math.pi / 4)
    R[0, 3] = 0.05 + 0.05 * math.sqrt(2) + 0.002
    d = box_box(h, h, I, R[None], np.array([1.0]))
    assert d[0] == pytest.approx(0.002, abs=1e-12)
    # random poses: negative exactly when a corner or sampled surface point of one box
    # lies inside the other, and never deeper than the sampled estimate allows
    rng = np.random.default_rng(1)
    K = 200
    ha, hb = rng.uniform(0.02, 0.1, (K, 3)), rng.uniform(0.02, 0.1, (K, 3))
    Wa = np.array([rotation(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(K)])
    Wb = np.array([rotation(rng.normal(size=3), rng.uniform(0, 3)) for _ in range(K)])
    Wb[:, :3, 3] = rng.normal(size=(K, 3)) * 0.08
    d = box_box(ha, hb, Wa, Wb, np.full(K, np.inf))
    u = rng.uniform(-1, 1, (K, 4000, 3))
    for k in range(K):
        pts = (u[k] * ha[k]) @ Wa[k][:3, :3].T + Wa[k][:3, 3]  # points of solid a
        loc = (pts - Wb[k][:3, 3]) @ Wb[k][:3, :3]
        inside = (np.abs(loc) < hb[k]).all(axis=1).any()
        if inside:
            assert d[k] < 0
        if d[k] > 0:
            assert not inside


# ---------------------------------------------------------------- every category

@pytest.mark.parametrize("category", CATEGORIES)
def test_validated_generation_passes_and_is_deterministic(category):
    for seed in SEEDS:
        a = generate_valid(category, seed)
        assert a.report["ok"], f"{category}/{seed}: {json.dumps(a.report)[:2000]}"
        assert a.seed == seed
        b = generate_valid(category, seed)
        assert json.dumps(a.report, sort_keys=True) == json.dumps(b.report, sort_keys=True)
        assert np.array_equal(a.link_poses(), b.link_poses())


@pytest.mark.parametrize("category", CATEGORIES)
def test_recorded_parameters_reproduce_the_object(category):
    """Repair regenerates with overrides: every perturbable draw must have a unique name."""
    for seed in SEEDS:
        a = artipg.generate(category, seed)
        b = artipg.generate(category, seed, {k: p.value for k, p in a.params.items() if p.kind != "fixed"})
        assert [p.name for p in a.parts] == [p.name for p in b.parts], f"{category}/{seed}"
        assert np.allclose(a.part_poses(), b.part_poses(), atol=1e-12), f"{category}/{seed}"
        for pa, pb in zip(a.parts, b.parts):
            assert [q.params for q in pa.primitives] == [q.params for q in pb.primitives], f"{category}/{seed}"


@pytest.mark.parametrize("category", CATEGORIES)
def test_parts_know_the_parameters_that_built_them(category):
    for seed in SEEDS:
        obj = artipg.generate(category, seed)
        names = list(obj.params)
        spans = sorted(p.param_span for p in obj.parts)  # add order
        assert all(0 <= a <= b <= len(names) for a, b in spans)
        # consecutive adds tile the record: every draw before the last add belongs to one part
        assert spans[0][0] == 0 and all(spans[i][1] == spans[i + 1][0] for i in range(len(spans) - 1))
        blame = part_params(obj)
        assert any(blame.values()), "no part records any parameter"


def test_storage_furniture_door_blames_its_own_parameters():
    for seed in range(20):
        obj = artipg.generate("storage_furniture", seed)
        hit = _find(obj, lambda lk, p: p.semantic == "door")
        if hit:
            names = part_params(obj)[hit[2].name]
            assert any(n.endswith(".thickness") and ".door" in n for n in names), names
            return
    pytest.skip("no door in seeds 0..19")


# ---------------------------------------------------------------- broken real objects

def _first(category, pred, seeds=range(40)):
    for seed in seeds:
        obj = generate_valid(category, seed)
        hit = _find(obj, pred)
        if hit is not None:
            return obj, hit
    pytest.skip(f"no matching {category} object")


def _failed(report) -> set:
    return set(report.failed())


def test_flipped_hinge_is_caught_by_the_joint_sweep():
    obj, (li, link, door) = _first("storage_furniture", lambda lk, p: p.semantic == "door" and lk.joint.type == "revolute")
    assert check_object(obj).ok
    link.joint.axis = -link.joint.axis  # the door now swings into the body
    r = check_object(obj)
    assert _failed(r) == {"joint_sweep"}
    sweep = [i for i in r.checks["joint_sweep"].issues if i.joint == link.joint.name]
    assert sweep and max(i.amount for i in sweep) > 0.01
    assert any(obj.links[0].name in i.links for i in sweep)
    assert any(p in sweep[0].params for p in part_params(obj)[door.name])


def test_drawer_wider_than_its_opening_is_caught_as_penetration():
    obj, (li, link, drawer) = _first("storage_furniture", lambda lk, p: p.template == "box_drawer")
    # the carcass opening is the drawer box plus 4 mm on each side: make the box
    # 5 mm wider than the opening (6.5 mm more on each side)
    grow = 0.004 + 0.0025
    boxes = [pr for pr in drawer.primitives if pr.role == "box"]
    y0 = min(pr.bounds()[0, 1] for pr in boxes)
    y1 = max(pr.bounds()[1, 1] for pr in boxes)
    new = []
    for pr in drawer.primitives:
        if pr.role == "box":  # axis-aligned boxes in the part frame: extend those on the sides
            lo, hi = pr.bounds()
            lo[1] -= grow if abs(lo[1] - y0) < 1e-9 else 0.0
            hi[1] += grow if abs(hi[1] - y1) < 1e-9 else 0.0
            pr = Primitive(pr.geom, tuple(hi - lo) + (0.0,), translation(*((lo + hi) / 2)), pr.role)
        new.append(pr)
    drawer.primitives = new
    _invalidate(obj)
    r = check_object(obj)
    assert "penetration" in _failed(r)
    pen = [i for i in r.checks["penetration"].issues if link.name in i.links]
    assert pen and max(i.amount for i in pen) == pytest.approx(0.0025, abs=2e-4)


def test_handle_floating_off_its_door_is_caught():
    obj, (li, link, handle) = _first("storage_furniture",
                                     lambda lk, p: p.semantic == "handle" and any(q.semantic == "door" for q in lk.parts))
    handle.pose = handle.pose @ translation(-0.01, 0.0, 0.0)  # 1 cm off the door's face
    _invalidate(obj)
    r = check_object(obj)
    assert "floating" in _failed(r) and "penetration" not in _failed(r)
    (issue,) = [i for i in r.checks["floating"].issues if handle.name in i.parts]
    assert issue.kind == "floating_part" and issue.links == [link.name]
    assert issue.amount == pytest.approx(0.01, abs=5e-4)


@pytest.mark.parametrize("category", ["kitchen_pot", "bucket"])
def test_lid_sunk_into_its_pot_is_caught(category):
    if category not in artipg.categories():
        pytest.skip(f"{category} is not registered")
    obj, (li, link, lid) = _first(category, lambda lk, p: p.semantic == "lid")
    link.joint.origin = translation(0.0, 0.0, -0.01) @ link.joint.origin  # 1 cm down
    r = check_object(obj)
    assert "penetration" in _failed(r)
    # the depth is capped by the wall it sinks into (half its thickness), not by the drop
    assert any(link.name in i.links and i.amount > 0.001 for i in r.checks["penetration"].issues)


# ---------------------------------------------------------------- broken, then repaired

W, D, H = 0.5, 0.4, 0.6


def _cabinet(ctx):
    root = ctx.builder.create_link("base")
    body = carcass(ctx.p, D, W, H)
    pose = translation(0, 0, H / 2)
    root.add(body, pose)
    return root, body, pose


def _door_cabinet(with_defect: str):
    """A cabinet with one door; its defect is a recorded parameter of the door."""

    def door(ctx):
        root, body, pose = ctx.out["body"]
        q = ctx.p  # names: door.*
        lo = body.anchor("cavity_lo")
        w, h = W - 0.003, H - 0.003
        panel = slab_door(q, w, h)
        inward = q.choice("swing", ("outward", "inward")) == "inward" if with_defect == "hinge" else False
        link = mount_hinged(ctx.builder, root, panel, front_x=lo[0], center_yz=(0.0, 0.0), size_yz=(w, h),
                            side="+y", limits=(0.0, q.uniform("limit", 1.2, 1.9)), parent_pose=pose)
        if inward:
            link.link.joint.axis = -link.link.joint.axis
        hq = q.scope("handle")
        gap = hq.uniform("gap", 0.0, 0.012) if with_defect == "handle" else 0.0
        handle = flat_bar_handle(hq, length=0.2)
        link.add(handle, handle_pose(panel.pose, front_thickness(panel), -w / 2 + 0.04, 0.0, False)
                 @ translation(-gap, 0.0, 0.0))

    return Category(f"test_{with_defect}", {"plain": 1.0},
                    (Slot("body", _cabinet), Slot("door", door, after=("body",))))


def _drawer_cabinet():
    def drawer(ctx):
        root, body, pose = ctx.out["body"]
        q = ctx.p  # names: drawer.*
        lo, hi = body.anchor("cavity_lo"), body.anchor("cavity_hi")
        c = q.uniform("clearance", -0.003, 0.004)  # per side; negative: wider than the opening
        centre = (0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]))
        size = (hi[1] - lo[1] + 2 * 0.018 - 0.003, hi[2] - lo[2] + 2 * 0.018 - 0.003)
        opening = (lo[1] + c - centre[0], hi[1] - c - centre[0], lo[2] + 0.003 - centre[1], hi[2] - 0.003 - centre[1])
        part = box_drawer(q, size[0], size[1], hi[0] - lo[0] - 0.01, opening=opening)
        mount_sliding(ctx.builder, root, part, origin=pose @ translation(lo[0], *centre), limits=(0.0, 0.25))

    return Category("test_drawer", {"plain": 1.0}, (Slot("body", _cabinet), Slot("drawer", drawer, after=("body",))))


def _pot():
    def body(ctx):
        root = ctx.builder.create_link("base")
        shell = cylindrical_shell(ctx.p, 0.12, 0.15)
        root.add(shell)
        return root, shell

    def lid(ctx):
        root, shell = ctx.out["body"]
        q = ctx.p  # names: lid.*
        t = q.uniform("thickness", 0.004, 0.008)
        seat = q.uniform("seat", -0.015, 0.0)  # lid bottom relative to the rim: < 0 sinks it
        r = 0.12 + q.uniform("overhang", 0.002, 0.01)
        disc = Part("lid", "test_lid", [cylinder(r, t, translation(0, 0, t / 2)),
                                        cylinder(0.015, 0.02, translation(0, 0, t + 0.01))])
        link = ctx.builder.create_link("lid", root)
        link.set_joint("prismatic", translation(0, 0, 0.15 + seat), axis=(0, 0, 1), limits=(0.0, 0.1))
        link.add(disc)

    return Category("test_pot", {"plain": 1.0}, (Slot("body", body), Slot("lid", lid, after=("body",))))


BROKEN = {
    "flipped hinge": (lambda: _door_cabinet("hinge"), {"door.swing": "inward"}, "joint_sweep", "door.swing"),
    "drawer 5 mm too wide": (_drawer_cabinet, {"drawer.clearance": -0.0025}, "penetration", "drawer.clearance"),
    "handle 1 cm off": (lambda: _door_cabinet("handle"), {"door.handle.gap": 0.01}, "floating", "door.handle.gap"),
    "lid sunk 1 cm": (_pot, {"lid.seat": -0.01}, "penetration", "lid.seat"),
}


@pytest.mark.parametrize("name", list(BROKEN))
def test_broken_object_is_caught_then_repaired(name):
    make, overrides, check, param = BROKEN[name]
    rule = make()
    broken = rule.generate(0, overrides)
    r = check_object(broken)
    assert check in r.failed(), r.to_json()
    blamed = {n for i in r.checks[check].issues for n in i.params}
    assert param in blamed, f"{param} not blamed: {sorted(blamed)}"
    fixed = generate_valid(rule, 0, overrides)
    rep = fixed.report
    assert rep["ok"], json.dumps(rep)[:3000]
    assert not rep["repair"]["replaced"] and rep["repair"]["iterations"] >= 1
    assert param in rep["repair"]["attempts"][0]["changed"]
    assert check_object(fixed).ok
    again = generate_valid(rule, 0, overrides)
    assert json.dumps(again.report, sort_keys=True) == json.dumps(rep, sort_keys=True)


def test_unrepairable_object_is_replaced_from_a_derived_seed():
    # a lid that can never clear its pot: the seat range excludes valid values
    def lid(ctx):
        root = ctx.builder.create_link("base")
        root.add(cylindrical_shell(ctx.p, 0.12, 0.15))
        link = ctx.builder.create_link("lid", root)
        sunk = ctx.p.flag("sunk", 0.5)
        link.set_joint("prismatic", translation(0, 0, 0.14 if sunk else 0.15), axis=(0, 0, 1), limits=(0.0, 0.1))
        link.add(Part("lid", "test_lid", [cylinder(0.125, 0.005, translation(0, 0, 0.0025))]))

    rule = Category("test_replace", {"plain": 1.0}, (Slot("lid", lid),))
    # a sunk seed whose first replacement is not (which seeds those are depends on the streams)
    seed = next(s for s in range(200) if rule.generate(s).params["lid.sunk"].value
                and not rule.generate(replacement_seed(s, 1)).params["lid.sunk"].value)
    from artipg.validate import RepairBudget

    obj = generate_valid(rule, seed, budget=RepairBudget(iterations=0))
    rep = obj.report["repair"]
    assert obj.report["ok"] and rep["replaced"] and obj.seed == seed
    assert rep["source_seed"] == replacement_seed(seed, len(rep["attempts"]) - 1)
    assert replacement_seed(seed, 1) != replacement_seed(seed, 2) and replacement_seed(seed, 1) > 2 ** 32


# ---------------------------------------------------------------- export: collision and inertials

@pytest.mark.parametrize("category", CATEGORIES)
def test_collision_pieces_are_convex_and_do_not_fill_hollow_bodies(category):
    import trimesh

    from artipg.export.meshes import link_collision_pieces

    for seed in (0, 1):
        obj = artipg.generate(category, seed)
        for link in obj.links:
            solid = sum(pr.geom.volume(pr.geom.solid_params(pr.params)) for p in link.parts for pr in p.primitives)
            vol = 0.0
            for piece, _ in link_collision_pieces(link):
                if piece.shape == "box":
                    vol += float(np.prod(piece.size))
                elif piece.shape == "cylinder":
                    vol += math.pi * piece.size[0] ** 2 * piece.size[1]
                elif piece.shape == "sphere":
                    vol += 4 / 3 * math.pi * piece.size[0] ** 3
                else:
                    m = trimesh.Trimesh(piece.vertices, piece.faces)
                    assert m.is_convex
                    vol += m.volume
            # convex pieces cover the solid (hulls of curved sectors add a little),
            # never a filled hollow (which would multiply the volume)
            assert 0.9 * solid < vol < 1.25 * solid + 1e-7, f"{category}/{seed} {link.name}: {vol} vs {solid}"


def test_every_label_has_a_material_and_inertials_are_valid():
    from artipg.export.meshes import MATERIAL, density, link_inertial
    from artipg.vocabulary import SEMANTIC_LABELS

    missing = [lab for lab in SEMANTIC_LABELS if lab not in MATERIAL]
    assert not missing, f"give these labels a material class in artipg.export.meshes.MATERIAL: {missing}"
    assert all(100.0 < density(lab) < 20000.0 for lab in SEMANTIC_LABELS)
    for category in CATEGORIES:
        obj = artipg.generate(category, 0)
        for link in obj.links:
            m, c, I = link_inertial(link)
            ev = np.linalg.eigvalsh(I)
            assert m > 0 and (ev > 0).all()
            assert ev[2] <= ev[0] + ev[1] + 1e-9  # triangle inequality


# ---------------------------------------------------------------- folders and the CLI

def _cli(*args, timeout=600):
    return subprocess.run([sys.executable, "-m", "artipg.cli", *args], capture_output=True, text=True,
                          timeout=timeout)


def _partnet_style(src: Path, dest: Path) -> Path:
    """Copy an exported artipg folder into PartNet-Mobility's layout: textured_objs/,
    no annotation.json, no <mujoco> block."""
    (dest / "textured_objs").mkdir(parents=True)
    tree = ET.parse(src / "mobility.urdf")
    root = tree.getroot()
    for el in root.findall("mujoco"):
        root.remove(el)
    for m in root.iter("mesh"):
        name = Path(m.get("filename")).name
        shutil.copy(src / m.get("filename"), dest / "textured_objs" / name)
        m.set("filename", f"textured_objs/{name}")
    tree.write(dest / "mobility.urdf")
    return dest


def test_validate_command_on_artipg_and_partnet_style_folders(tmp_path):
    good = generate_valid("storage_furniture", 3)
    export_object(good, tmp_path / "ours" / "good", n_points=0)
    # the sharp structure: an inward door only fails the sweep (a rounded carcass edge
    # would also meet it at rest)
    broken = BROKEN["flipped hinge"][0]().with_detail("off").generate(0, {"door.swing": "inward"})
    export_object(broken, tmp_path / "ours" / "broken", n_points=0)
    _partnet_style(tmp_path / "ours" / "broken", tmp_path / "partnet" / "7128")
    _partnet_style(tmp_path / "ours" / "good", tmp_path / "partnet" / "101")
    report = tmp_path / "r.json"
    r = _cli("validate", str(tmp_path / "ours"), str(tmp_path / "partnet"), "--json", str(report), "--no-sim")
    assert r.returncode == 1, r.stdout + r.stderr
    res = {Path(o["path"]).name: o for o in json.loads(report.read_text())["objects"]}
    assert set(res) == {"good", "broken", "7128", "101"}
    assert res["good"]["ok"] and res["good"]["geometry"] == "exact"
    assert res["101"]["ok"] and res["101"]["geometry"] == "mesh"
    for k in ("broken", "7128"):
        assert not res[k]["ok"] and not res[k]["checks"]["joint_sweep"]["ok"]
        assert res[k]["checks"]["penetration"]["ok"] and res[k]["checks"]["floating"]["ok"]
    # every object passing: exit code 0, simulators included
    r = _cli("validate", str(tmp_path / "partnet" / "101"), "--json", str(report))
    assert r.returncode == 0, r.stdout + r.stderr
    sim = json.loads(report.read_text())["objects"][0]["checks"]["simulator"]
    assert sim["ok"] and {"pybullet", "mujoco"} <= set(sim["info"]) and sim["info"]["fixed_base"] is False


def test_simulators_catch_a_hollow_body_exported_as_one_hull(tmp_path):
    """The gotcha the collision export avoids: a carcass as one convex hull swallows its drawer."""
    import trimesh

    from artipg.validate.sim import simulate_urdf

    obj = _drawer_cabinet().generate(0, {"drawer.clearance": 0.004})
    assert check_object(obj).ok
    dest = export_object(obj, tmp_path / "cabinet", n_points=0)
    assert simulate_urdf(dest / "mobility.urdf").ok
    tree = ET.parse(dest / "mobility.urdf")
    base = next(lk for lk in tree.getroot().iter("link") if lk.get("name") == "base_0")
    for c in base.findall("collision"):
        base.remove(c)
    hull = trimesh.load(dest / "meshes" / "base_0.obj", force="mesh").convex_hull
    (dest / "meshes" / "hull.obj").write_text(hull.export(file_type="obj"))
    col = ET.SubElement(base, "collision")
    ET.SubElement(ET.SubElement(col, "geometry"), "mesh", filename="meshes/hull.obj")
    tree.write(dest / "mobility.urdf")
    r = simulate_urdf(dest / "mobility.urdf")
    assert not r.ok
    found = {(i.kind, i.detail.split(":")[0]) for i in r.issues}
    assert {("sim_rest_penetration", "pybullet"), ("sim_rest_penetration", "mujoco")} <= found


def test_a_rack_behind_a_door_needs_the_door_open_but_a_knob_on_its_door_does_not():
    """Sweep collisions with a part another joint moves count only if opening that
    joint does not clear the way; a part riding on the blocking joint gets no pass."""
    def cab(ctx):
        root, body, pose = _cabinet(ctx)
        lo = body.anchor("cavity_lo")
        w, h = W - 0.003, H - 0.003
        door = mount_hinged(ctx.builder, root, slab_door(ctx.p.scope("door"), w, h), front_x=lo[0],
                            center_yz=(0.0, 0.0), size_yz=(w, h), side="+y", limits=(0.0, 1.6), parent_pose=pose)
        tray = Part("tray", "test_tray", [cuboid(0.3, 0.3, 0.01)])
        rack = ctx.builder.create_link("tray", root)
        rack.set_joint("prismatic", pose @ translation(lo[0] + 0.16, 0.0, 0.0), axis=(-1, 0, 0), limits=(0.0, 0.3))
        rack.add(tray)
        # a lever on the door that turns into the door itself: a real fault
        knob = ctx.builder.create_link("knob", door)
        knob.set_joint("revolute", translation(-0.02, -w / 2 + 0.06, 0.0), axis=(0, 0, 1), limits=(0.0, 1.5))
        knob.add(Part("knob", "test_knob", [cuboid(0.01, 0.08, 0.01)]))

    obj = Category("test_rack", {"plain": 1.0}, (Slot("body", cab),)).generate(0)
    r = check_object(obj).checks["joint_sweep"]
    assert r.info["needs_open"] == {"joint_tray_0": ["joint_door_0"]}
    assert {i.joint for i in r.issues if i.kind == "sweep_penetration"} == {"joint_knob_0"}
    assert all("knob_0" in i.links for i in r.issues)


@pytest.mark.parametrize("shape", ["sphere", "cylinder on its side", "torus", "cone on its tip"])
def test_point_and_line_contacts_touch_and_gaps_are_measured(shape):
    """Curved pieces touching a plane in a point or a line are not floating; lifted by
    3 mm they are, and the gap is measured (samples alone would miss the contact)."""
    from artipg.geometry.transforms import rot_x
    from artipg.model import ObjectBuilder

    R = 0.02
    prim = {"sphere": sphere(R, pose=translation(0, 0, R)),
            "cylinder on its side": cylinder(R, 0.1, translation(0, 0, R) @ rot_x(math.pi / 2)),
            "torus": torus(3 * R, R, pose=translation(0, 0, R)),
            "cone on its tip": frustum(0.0, R, 2 * R, translation(0, 0, R))}[shape]
    for lift in (0.0, 0.003):
        b = ObjectBuilder()
        root = b.create_link("base")
        root.add(Part("body", "test_plate", [cuboid(0.4, 0.4, 0.02, translation(0, 0, 0.01))]))
        root.add(Part("knob", "test_knob", [prim]), translation(0, 0, 0.02 + lift))
        obj = b.build("test", "plain", 0)
        r = check_object(obj).checks["floating"]
        if lift == 0.0:
            assert r.ok, [i.to_json() for i in r.issues]
        else:
            (issue,) = r.issues
            assert issue.kind == "floating_part" and issue.amount == pytest.approx(lift, abs=2e-4)
