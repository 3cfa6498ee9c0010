"""Thin constructors of the geometry families: watertight meshes, exact extents, exact and uniform sampling."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from artipg.geometry import (GEOMETRY_FAMILIES, Sweep, Tube, arc, cuboid, cylinder, frustum, line, prism, rect_ring,
                             ring, sphere, torus, tri_prism)

CASES = {
    "cuboid": cuboid(0.3, 0.2, 0.1),
    "rect_ring": rect_ring(0.5, 0.8, 0.04, 0.4, 0.7),
    "cylinder": cylinder(0.1, 0.3),
    "frustum": frustum(0.15, 0.1, 0.3),
    "cone": frustum(0.15, 0.0, 0.3),
    "ring": ring(0.15, 0.14, 0.3),
    "ring_arc": ring(0.15, 0.12, 0.3, arc=2.0),
    "ring_arc_reflex": ring(0.15, 0.12, 0.3, arc=4.5),
    "ring_tapered_arc": ring(0.12, 0.10, 0.3, arc=4.0, taper=0.04),
    "sphere": sphere(0.1),
    "dome": sphere(0.1, z_lo=0.03),
    "sphere_band": sphere(0.1, z_lo=-0.05, z_hi=0.06),
    "torus": torus(0.2, 0.02),
    "torus_arc": torus(0.2, 0.02, arc=math.pi),
    "prism6": prism(0.1, 0.2, 6),
    "prism3": prism(0.1, 0.2, 3),
    "tri_prism": tri_prism(0.2, 0.1, 0.03, 0.05),
}


def test_every_geometry_family_is_covered():
    # the swept tube is covered by tests/test_families.py
    assert {type(p.geom) for p in CASES.values()} | {Sweep} == set(GEOMETRY_FAMILIES.values())


@pytest.mark.parametrize("name", sorted(CASES))
def test_mesh_watertight_and_bounds_exact(name):
    prim = CASES[name]
    m = prim.mesh(sections=64)
    assert m.is_watertight and m.is_winding_consistent
    assert m.volume > 0
    b = prim.geom.bounds(prim.params)
    # tessellated curved surfaces lie inside the exact solid; extents agree to < 0.5%
    assert np.allclose(b, m.bounds, atol=0.005 * np.ptp(b, axis=0).max())
    assert np.allclose(prim.geom.bounds_batch(np.array([prim.params]))[0], b)
    assert m.volume == pytest.approx(prim.geom.volume(prim.params), rel=0.02)


@pytest.mark.parametrize("name", sorted(CASES))
def test_samples_on_surface_with_outward_normals(name):
    prim = CASES[name]
    rng = np.random.default_rng(0)
    P = np.repeat(np.array([prim.params], dtype=float), 5000, axis=0)
    pts, nrm = prim.geom.sample(P, rng)
    sdf = prim.geom.sdf(prim.params, pts)
    assert np.abs(sdf).max() < 1e-9
    assert np.allclose(np.linalg.norm(nrm, axis=1), 1.0)
    assert (prim.geom.sdf(prim.params, pts + 1e-5 * nrm) > 0).all()
    assert (prim.geom.sdf(prim.params, pts - 1e-5 * nrm) < 0).mean() > 0.99  # thin edges excepted
    b = prim.geom.bounds(prim.params)
    assert (pts >= b[0] - 1e-12).all() and (pts <= b[1] + 1e-12).all()


@pytest.mark.parametrize("name", sorted(CASES))
def test_sampling_is_area_uniform(name):
    """Nearest-neighbour distances to a fine mesh sample are the same in both directions
    (a non-uniform sampler leaves holes one way) and areas match the mesh."""
    import trimesh

    prim = CASES[name]
    m = prim.mesh(sections=128)
    assert prim.area() == pytest.approx(m.area, rel=0.01)
    rng = np.random.default_rng(1)
    pts, _ = prim.geom.sample(np.repeat(np.array([prim.params], dtype=float), 8000, axis=0), rng)
    ref, _ = trimesh.sample.sample_surface(m, 8000, seed=2)
    d_ab = cKDTree(ref).query(pts)[0].mean()
    d_ba = cKDTree(pts).query(ref)[0].mean()
    assert d_ab == pytest.approx(d_ba, rel=0.08)


def test_partial_surfaces_respect_arc():
    prim = CASES["ring_arc"]
    pts, _ = prim.geom.sample(np.repeat(np.array([prim.params]), 3000, axis=0), np.random.default_rng(0))
    ang = np.arctan2(pts[:, 1], pts[:, 0]) % (2 * math.pi)
    assert ang.max() <= 2.0 + 1e-9


def test_tube_is_watertight_and_matches_its_pieces():
    t = Tube(0.01, (line(0.05), arc(0.03, math.pi / 2), line(0.1), arc(0.03, -math.pi / 3), line(0.05)))
    m = t.mesh(sections=48)
    assert m.is_watertight and m.volume > 0
    pieces = t.primitives()
    assert sum(p.area() for p in pieces) == pytest.approx(m.area, rel=0.01)
    rng = np.random.default_rng(0)
    pts = np.concatenate([
        p.geom.sample(np.repeat(np.array([p.params]), 500, axis=0), rng)[0] @ p.pose[:3, :3].T + p.pose[:3, 3]
        for p in pieces])
    assert np.abs(t.sdf(pts)).max() < 1e-9
    assert np.allclose(t.bounds(), m.bounds, atol=2e-4)
    end, heading = t.end()
    assert heading == pytest.approx(math.pi / 2 - math.pi / 3)


def test_collision_pieces_cover_hollow_shapes_without_filling_them():
    prim = ring(0.15, 0.14, 0.3)
    pieces = prim.geom.collision(prim.params)
    assert len(pieces) >= 16
    centre = np.zeros((1, 3))
    import trimesh

    covered = []
    for pc in pieces:
        V = pc.vertices @ pc.pose[:3, :3].T + pc.pose[:3, 3]
        hull = trimesh.Trimesh(V, pc.faces)
        assert hull.is_watertight and hull.volume > 0
        assert not hull.contains(centre)[0]
        covered.append(V)
    # the posed pieces go all the way round the wall
    angles = np.arctan2(*np.concatenate(covered)[:, 1::-1].T)
    assert np.ptp(np.sort(angles)) > 2 * np.pi - 0.5 and np.diff(np.sort(angles)).max() < 0.5


@pytest.mark.parametrize("name", sorted(CASES))
def test_patches_partition_the_components(name):
    """Patch areas sum to each component's closed-form area, and every patch family's
    parameters are those the sampler expects."""
    from artipg.geometry.patches import FAMILIES

    prim = CASES[name]
    P = np.array([prim.params, prim.params], dtype=float)
    comp_area = prim.geom.component_areas(P)
    got = np.zeros_like(comp_area)
    for b in prim.geom.patches(P):
        c, p, M = b.params.shape
        assert p == FAMILIES[b.family] and M == len(P) and b.area.shape == (c, M) and len(b.comp) == c
        assert np.all(b.area >= 0.0)
        np.add.at(got.T, b.comp, b.area)
    np.testing.assert_allclose(got, comp_area, rtol=1e-12, atol=1e-15)
