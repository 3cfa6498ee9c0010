"""Procedural geometric detail (issue 22, part 1): the ``detail`` switch, the detail
stream, and the exactness of rounded edges and lips.

Detail off must give the sharp structure with every structural parameter unchanged;
detail on must keep points on the surface, labels on every part, signed distances
and the radius bounds; both must be deterministic.
"""

from __future__ import annotations

import numpy as np
import pytest

import artipg
from artipg.annotate.points import sample_points
from artipg.geometry import BOX
from artipg.geometry.lathe import Lathe
from artipg.rules.detail import DETAIL_LEVELS, parse_detail
from artipg.templates.detail import lipped_wall, rbox, rounded_disc

#: Categories whose templates draw detail, with a seed that shows some of it.
DETAILED = ["storage_furniture", "table", "bucket", "mug", "kitchen_pot", "microwave", "trash_can", "kettle"]


def _prims(obj):
    return [pr for part in obj.parts for pr in part.primitives]


def _structure(obj):
    """The primitives' families, parameters and poses (what detail off must reproduce)."""
    return [(pr.geom, tuple(pr.params), np.asarray(pr.pose).tobytes(), pr.role) for pr in _prims(obj)]


def test_parse_detail_levels_and_errors():
    assert parse_detail(None) == "procedural" == DETAIL_LEVELS[0]
    assert parse_detail(" OFF ") == "off"
    with pytest.raises(ValueError, match="detail must be one of"):
        parse_detail("learnt")
    with pytest.raises(ValueError, match="detail must be one of"):
        artipg.generate("mug", 0, detail="fancy")


@pytest.mark.parametrize("category", DETAILED)
def test_detail_off_is_the_sharp_structure_with_the_same_parameters(category):
    for seed in range(4):
        off = artipg.generate(category, seed, detail="off")
        on = artipg.generate(category, seed, detail="procedural")
        # no rounded boxes and no detail draws when off
        assert all(pr.params[3] == 0.0 for pr in _prims(off) if pr.geom is BOX)
        # every structural parameter is drawn identically at both levels
        for name, p in off.params.items():
            assert on.params[name].value == p.value, name
        assert on.subcategory == off.subcategory
    # some seed of the category does draw detail
    assert any(len(artipg.generate(category, s).params) > len(artipg.generate(category, s, detail="off").params)
               for s in range(4))


def test_detail_off_builds_sharp_boxes_where_procedural_rounds_them():
    on, off = artipg.generate("storage_furniture", 2), artipg.generate("storage_furniture", 2, detail="off")
    r_on = [pr.params[3] for pr in _prims(on) if pr.geom is BOX]
    assert max(r_on) > 0.0
    assert all(pr.params[3] == 0.0 for pr in _prims(off) if pr.geom is BOX)
    # the same parts with the same sizes: rounding never changes a box's extents
    box_on = [pr.params[:3] for pr in _prims(on) if pr.geom is BOX]
    box_off = [pr.params[:3] for pr in _prims(off) if pr.geom is BOX]
    assert box_on == box_off


@pytest.mark.parametrize("category", DETAILED)
def test_detail_is_deterministic(category):
    a, b = artipg.generate(category, 7), artipg.generate(category, 7)
    assert _structure(a) == _structure(b)
    assert list(a.params.items()) == list(b.params.items())
    pa, pb = sample_points(a, 512, seed=3), sample_points(b, 512, seed=3)
    assert pa.points.tobytes() == pb.points.tobytes()
    assert pa.semantic.tobytes() == pb.semantic.tobytes()


@pytest.mark.parametrize("category", DETAILED)
def test_detail_points_lie_on_the_surface_and_label_every_part(category):
    obj = artipg.generate(category, 3)
    pc = sample_points(obj, 4096, seed=0)
    W = obj.primitive_table.world_all(obj.link_poses())
    prims = _prims(obj)
    for k in np.unique(pc.primitive):
        sel = pc.primitive == k
        local = (pc.points[sel] - W[k, :, 3]) @ W[k, :, :3]
        assert np.abs(prims[k].geom.sdf(prims[k].params, local)).max() < 1e-6
    table = obj.primitive_table
    area = np.array([pr.area() for pr in prims])
    part_area = np.bincount(table.prim_part, weights=area, minlength=len(obj.parts))
    assert set(np.flatnonzero(part_area / part_area.sum() > 5e-3)) <= set(pc.instance.tolist())
    assert np.array_equal(pc.semantic, table.part_semantic[pc.instance])


@pytest.mark.parametrize("category", ["storage_furniture", "table", "microwave", "dishwasher", "oven", "safe"])
def test_edge_radii_within_their_bounds(category):
    for seed in range(6):
        obj = artipg.generate(category, seed)
        for pr in _prims(obj):
            if pr.geom is BOX and pr.params[3] > 0.0:
                sx, sy, sz, r = pr.params
                assert r <= 0.5 * min(sx, sy, sz)
                assert r <= 0.006 + 1e-12  # never beyond the panels' 6 mm
        for name, p in obj.params.items():
            if name.endswith("edge_radius"):
                assert 0.0 < p.value <= min(0.006, p.hi) + 1e-12 and p.lo <= p.value, name


def test_rounded_box_sdf_sign_against_the_sharp_box():
    prim = rbox(0.02, 0.4, 0.6, 0.005, np.eye(4))
    g, p = prim.geom, prim.params
    inside = np.array([[0.0, 0.0, 0.0], [0.009, 0.19, 0.29]])
    corner = np.array([[0.0099, 0.1999, 0.2999]])  # inside the sharp box, outside its rounding
    face = np.array([[0.01, 0.0, 0.0]])
    assert (g.sdf(p, inside) < 0).all()
    assert g.sdf(p, corner)[0] > 0
    assert abs(g.sdf(p, face)[0]) < 1e-12
    assert rbox(0.02, 0.4, 0.6, 0.0, np.eye(4)).params[3] == 0.0


def test_lipped_wall_stays_inside_the_sharp_ring_and_keeps_its_top():
    ro, ri, h, zc = 0.1, 0.096, 0.2, 0.1
    for lip in ("round", "eased"):
        wall, cap = lipped_wall(ro, ri, h, zc, lip)
        assert isinstance(cap.geom, Lathe)
        top = float(cap.pose[2, 3]) + cap.geom.bounds(cap.params)[1, 2]
        assert abs(top - (zc + h / 2)) < 1e-12
        # the sharp ring's outer top corner is outside the rounded lip; its mid-top inside
        x = np.array([[ro - 1e-5, 0.0, h / 2 - 1e-5], [0.5 * (ro + ri), 0.0, h / 2 - 2e-4]])
        local = x - [0.0, 0.0, float(cap.pose[2, 3]) - zc]
        d = cap.geom.sdf(cap.params, local)
        assert d[0] > 0 and d[1] < 0
        # the ring's top face is inside the lip: left out of the sampled surface
        assert wall.params[11] == 0.0
    assert len(lipped_wall(ro, ri, h, zc, "flat")) == 1


def test_rounded_disc_profiles():
    T = np.eye(4)
    plain = rounded_disc(0.1, 0.03, 0.0, 0.0, False, T)
    assert plain.geom.volume(plain.params) == pytest.approx(np.pi * 0.01 * 0.03)
    for bevel in (False, True):
        d = rounded_disc(0.1, 0.03, 0.006, 0.003, bevel, T)
        g, p = d.geom, d.params
        assert g.volume(p) < np.pi * 0.01 * 0.03
        assert np.allclose(g.bounds(p), [[-0.1, -0.1, -0.015], [0.1, 0.1, 0.015]])
        assert g.sdf(p, np.array([[0.0999, 0.0, 0.0149]]))[0] > 0  # the sharp corner is cut
        assert g.sdf(p, np.array([[0.09, 0.0, 0.0]]))[0] < 0


def test_generated_set_passes_the_detail_level():
    from artipg.io.generated import generated_set

    a = generated_set("table", [0, 1], 256, detail="off")
    b = generated_set("table", [0, 1], 256, detail="procedural")
    c = generated_set("table", [0, 1], 256, detail="off")
    assert np.array_equal(a.points, c.points)
    assert not np.array_equal(a.points, b.points)


def test_cli_detail_option(tmp_path):
    from typer.testing import CliRunner

    from artipg.cli import app

    runner = CliRunner()
    bad = runner.invoke(app, ["generate", "mug", "-n", "1", "--out", str(tmp_path), "--detail", "bogus"])
    assert bad.exit_code == 2
    assert "detail must be one of" in bad.output
    ok = runner.invoke(app, ["generate", "table", "-n", "1", "--out", str(tmp_path / "o"), "--detail", "off",
                             "--no-validate", "--points", "64", "-q"])
    assert ok.exit_code == 0, ok.output


def test_choose_detail_and_the_detail_stream_on_a_toy_category():
    from artipg.geometry import cuboid
    from artipg.model.part import Part
    from artipg.rules import Category, Slot

    STYLES = {"a": 1.0, "b": 1.0}

    def build(ctx):
        size = ctx.p.uniform("size", 0.1, 0.2)
        style = ctx.choose_detail("style", STYLES, "flat")
        r = ctx.p.detail_uniform("r", 0.001, 0.002)
        flag = ctx.p.detail_flag("f", 0.5)
        link = ctx.builder.create_link("base")
        link.add(Part("body", "toy", [cuboid(size, size, size)]))
        return ctx.p.detail, style, r, flag

    toy = Category("toy", {"only": 1.0}, (Slot("body", build),))
    assert toy.with_detail("procedural") is toy and toy.with_detail("off") is toy.with_detail("off")
    for seed in range(5):
        off, on = toy.with_detail("off").generate(seed), toy.generate(seed)
        assert off.params["body.size"].value == on.params["body.size"].value
        assert set(on.params) - set(off.params) == {"body.style", "body.r", "body.f"}
        assert on.templates["body"] == [on.params["body.style"].value] and "body" not in off.templates
        assert 0.001 <= on.params["body.r"].value <= 0.002
    # overrides reach detail draws like any other
    assert toy.generate(0, {"body.style": "b"}).params["body.style"].value == "b"


def test_validation_keeps_the_detail_level():
    obj = artipg.generate("table", 1, validate=True, detail="off")
    assert obj.report["ok"]
    assert all(pr.params[3] == 0.0 for pr in _prims(obj) if pr.geom is BOX)
    assert not any(n.endswith("edge_radius") for n in obj.params)
