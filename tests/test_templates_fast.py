"""Shortcuts in the category rules and part templates: each gives exactly what the
plain computation it replaces gives (the same bits), or skips it only where it cannot
change the result."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import artipg
from artipg.rules import ParamRecorder
from artipg.templates.extents import span
from artipg.templates.handles import FRONT_HANDLES, MAX_HALF_WIDTH
from artipg.templates.office import ARMS, arm_top


def _half_width(part) -> float:
    return float(np.abs(part.bounds()[:, 1]).max())


@pytest.mark.parametrize("template", list(FRONT_HANDLES), ids=lambda t: t.__name__)
def test_front_handles_stay_within_max_half_width(template):
    rec = ParamRecorder(np.random.default_rng(0))
    template(rec, length=0.1)
    names = [k for k, p in rec.record.items() if p.kind == "uniform"]
    widest = 0.0
    # every corner of the parameter box (overrides are clamped into each range) ...
    for corner in itertools.product((-1e9, 1e9), repeat=len(names)):
        for length in (0.02, 0.35):
            part = template(ParamRecorder(np.random.default_rng(0), overrides=dict(zip(names, corner))), length=length)
            widest = max(widest, _half_width(part))
    # ... and random draws
    for seed in range(200):
        widest = max(widest, _half_width(template(ParamRecorder(np.random.default_rng(seed)), length=0.2)))
    assert 0.0 < widest <= MAX_HALF_WIDTH




@pytest.mark.parametrize("category", artipg.categories())
def test_span_is_the_part_bounds(category):
    for seed in range(3):
        for link in artipg.generate(category, seed).links:
            for part in link.parts:
                b = part.bounds()
                for axis in range(3):
                    assert np.array(span(part.primitives, axis)).tobytes() == b[:, axis].tobytes()


@pytest.mark.parametrize("template", list(ARMS), ids=lambda t: t.__name__)
def test_stapler_arm_top_is_the_bounds_top(template):
    for seed in range(200):
        rng = np.random.default_rng(seed)
        radius, axle = rng.uniform(0.005, 0.013), rng.uniform(0.0015, 0.0025)
        y0 = rng.uniform(0.0075, 0.018)
        part = template(ParamRecorder(rng), rng.uniform(0.07, 0.45), 2 * y0, radius, rng.uniform(0.001, 0.003),
                        (y0, y0 + rng.uniform(0.0015, 0.0022)), axle, rng.uniform(0.001, 0.002))
        assert arm_top(part) == part.bounds()[1, 2]






def test_choices_take_constant_option_sets():
    # a dict, a list or a tuple of variables is a new object per call: it misses the
    # recorder's option cache (keyed by identity) and fills it; weights belong in module
    # constants (a tuple of literals is one constant object)
    import ast
    import pathlib

    def fresh(node):
        if isinstance(node, ast.Tuple):
            try:
                ast.literal_eval(node)
            except ValueError:
                return True
            return False
        return isinstance(node, (ast.Dict, ast.List, ast.Set, ast.DictComp, ast.ListComp, ast.SetComp))

    src = pathlib.Path(artipg.__file__).parent
    bad = []
    for path in sorted([*src.glob("categories/*.py"), *src.glob("templates/*.py")]):
        for node in ast.walk(ast.parse(path.read_text())):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr in ("choice", "choose") and len(node.args) > 1 and fresh(node.args[1])):
                bad.append(f"{path.name}:{node.lineno}")
    assert not bad, bad






def test_door_edge_grasps_are_the_edge_grasps():
    from artipg.templates.panels import door_edge_grasps, edge_grasp

    rng = np.random.default_rng(2)
    for t, w, h in rng.uniform(0.005, 1.0, (300, 3)):
        want = [edge_grasp(t, w / 2, 0.0, 1.0, 0.0), edge_grasp(t, -w / 2, 0.0, -1.0, 0.0),
                edge_grasp(t, 0.0, h / 2, 0.0, 1.0), edge_grasp(t, 0.0, -h / 2, 0.0, -1.0)]
        for g, e in zip(door_edge_grasps(t, w, h), want):
            assert g.pose.tobytes() == e.pose.tobytes()
            assert g.width == e.width and g.open_dir.tobytes() == e.open_dir.tobytes()


def test_keypad_copies_are_dataclass_replacements():
    from dataclasses import fields, replace

    from artipg.templates.controls import BUTTONS, _copy, button_bezel

    for button in BUTTONS:
        key = button(ParamRecorder(np.random.default_rng(3)))
        for part in (key, button_bezel(ParamRecorder(np.random.default_rng(4)), key)):
            got, want = _copy(part), replace(part)
            assert got is not part
            for f in fields(part):
                assert getattr(got, f.name) is getattr(want, f.name), f.name


def test_span_of_turned_curved_primitives_is_their_bounds():
    from artipg.geometry import cuboid, cylinder, frustum, prism, rect_ring, ring, sphere, torus
    from artipg.geometry.transforms import rot_x, rot_y, rot_z, translation

    rng = np.random.default_rng(7)
    # axis permutations and half turns (single non-zero entries, some -1), and a few
    # general rotations (the plain path)
    turns = [np.eye(4), rot_x(np.pi / 2), rot_y(np.pi / 2), rot_z(np.pi / 2), rot_x(np.pi), rot_y(-np.pi / 2),
             rot_z(np.pi) @ rot_x(np.pi / 2), rot_y(0.3), rot_x(1.1) @ rot_z(0.4)]
    for _ in range(300):
        a, b, c = rng.uniform(0.005, 0.2, 3)
        lo, hi = np.sort(rng.uniform(-a, a, 2))
        prims = [cuboid(a, b, c), cylinder(a, b), frustum(a, b, c), frustum(a, 0.0, c), ring(a + b, a, c),
                 ring(a + b, a, c, rng.uniform(0.2, 6.0), taper=rng.uniform(-0.5, 0.5) * a),
                 torus(a + b, min(a, b) / 2), torus(a + b, min(a, b) / 2, rng.uniform(0.2, 6.0)),
                 sphere(a), sphere(a, lo, hi), sphere(a, abs(lo), a), prism(a, b, 6), rect_ring(a, b, c, a / 2, b / 2)]
        for pr in prims:
            for R in turns:
                T = translation(*rng.uniform(-0.5, 0.5, 3)) @ R
                placed = pr.placed(T)
                for axis in range(3):
                    assert np.array(span([placed], axis)).tobytes() == placed.bounds()[:, axis].tobytes()


def test_spout_outlet_direction_is_the_unit_exit_direction():
    from artipg.templates.spouts import _spout

    rng = np.random.default_rng(0)
    for _ in range(500):
        a = rng.uniform(-np.pi, np.pi)
        d = rng.uniform(0.1, 2.0) * np.array([np.cos(a), 0.0, np.sin(a)])
        got = np.array(_spout("arc_spout", [], (0.0, 0.0, 0.0), tuple(map(float, d))).anchors["outlet_dir"])
        assert abs(np.linalg.norm(got) - 1.0) < 1e-12
        assert np.allclose(got, d / np.linalg.norm(d), rtol=0.0, atol=1e-12)
