"""Fast paths of the rule framework against the plain computations they replace.

Each test computes the same thing the straightforward way (scalar ``Generator.random()``
calls, ``bit_generator.advance``, the nested-array rotation formula, ...) and asks for
bit-identical results.
"""

from __future__ import annotations

import dataclasses
import gc
import math
import pickle
import weakref

import numpy as np
import pytest

import artipg
import artipg.rules.category as category_module
from artipg.geometry import cuboid
from artipg.geometry.transforms import IDENTITY, Placer, rot_x, rot_y, rot_z, rotation, translation
from artipg.model import Grasp, ObjectBuilder, Part, Region
from artipg.rules import Param, ParamRecorder
from artipg.rules.streams import stream, stream_key

def _script(rec: ParamRecorder, rng: np.random.Generator) -> list:
    """A mixed sequence of draws through ``rec``; ``rng`` (separate) picks the calls."""
    out = []
    scopes = [rec, rec.scope("a"), rec.scope("a").scope("b"), rec.scope("c")]
    for i in range(400):
        p = scopes[int(rng.integers(len(scopes)))]
        op = int(rng.integers(6))
        name = f"x{i}"
        if op == 0:
            lo = float(rng.uniform(-1, 1))
            out.append(p.uniform(name, lo, lo + float(rng.uniform(0, 2))))
        elif op == 1:
            out.append(p.integers(name, -3, int(rng.integers(-3, 9))))
        elif op == 2:
            out.append(p.choice(name, {"s": 1.0, "t": 2.5, "u": 0.5}))
        elif op == 3:
            out.append(p.choice(name, ("q", "r")))
        elif op == 4:
            out.append(p.flag(name, float(rng.random())))
        else:
            out.append(p.uniform(name, 0.0, 1.0, fixed=float(rng.random())))
    return out


def test_recorder_draws_are_reproducible_and_scopes_share_the_stream():
    def run(seed):
        return _script(ParamRecorder(stream(seed, stream_key("door"))), np.random.default_rng(2))

    a, b, c = run(7), run(7), run(8)
    assert a == b and a != c


def test_streams_depend_only_on_seed_and_key():
    k1, k2 = stream_key("door"), stream_key("handle")
    first = stream(11, k1).random(8)
    stream(11, k2).random(100)  # opening and drawing from another stream changes nothing
    assert np.array_equal(stream(11, k1).random(8), first)
    assert not np.array_equal(stream(11, k2).random(8), first)
    assert not np.array_equal(stream(12, k1).random(8), first)
    assert stream_key("door") == stream_key("door") != stream_key("doors")


def test_param_keeps_its_dataclass_api():
    p = Param("a.w", "uniform", 0.25, 0.1, 0.4)
    assert p == Param("a.w", "uniform", 0.25, 0.1, 0.4) and p != Param("a.w", "uniform", 0.26, 0.1, 0.4)
    assert (p.lo, p.hi, p.options) == (0.1, 0.4, ())
    assert repr(p) == "Param(name='a.w', kind='uniform', value=0.25, lo=0.1, hi=0.4, options=())"
    assert [f.name for f in dataclasses.fields(Param)] == ["name", "kind", "value", "lo", "hi", "options"]
    assert p.to_json() == {"kind": "uniform", "value": 0.25, "range": [0.1, 0.4]}
    c = Param("c", "choice", "x", options=("x", "y"))
    assert c.to_json() == {"kind": "choice", "value": "x", "options": ["x", "y"]}
    assert pickle.loads(pickle.dumps(c)) == c
    p.value = 0.3
    assert p.value == 0.3


def test_uniform_records_what_param_init_does():
    rec = ParamRecorder(np.random.default_rng(3), overrides={"s.b": 0.7})
    p = rec.scope("s")
    vals = [p.uniform("a", 0.1, 0.4), p.uniform("b", -1, 2), rec.uniform("c", 3, 3)]
    for (key, got), v, (lo, hi) in zip(rec.record.items(), vals, [(0.1, 0.4), (-1.0, 2.0), (3.0, 3.0)]):
        ref = Param(key, "uniform", v, lo, hi)
        assert type(got) is Param and got == ref and repr(got) == repr(ref)
        assert [type(getattr(got, f.name)) for f in dataclasses.fields(Param)] == \
            [type(getattr(ref, f.name)) for f in dataclasses.fields(Param)]
    assert rec.record["s.b"].value == 0.7


@pytest.mark.parametrize("overrides", [{}, {"s.n": 9, "s.c": "y", "s.f": True}])
def test_integer_choice_and_flag_record_what_param_init_does(overrides):
    rec = ParamRecorder(np.random.default_rng(4), overrides=overrides)
    p = rec.scope("s")
    opts = {"x": 1.0, "y": 2.0, "z": 0.5}
    n, c, f = p.integers("n", 2, 5), p.choice("c", opts), p.flag("f", 0.4)
    refs = [Param("s.n", "integer", n, 2, 5), Param("s.c", "choice", c, None, None, ("x", "y", "z")),
            Param("s.f", "flag", f, None, None, (False, True))]
    assert list(rec.record) == [r.name for r in refs]
    for got, ref in zip(rec.record.values(), refs):
        assert type(got) is Param and got == ref and repr(got) == repr(ref)
        assert [type(getattr(got, fl.name)) for fl in dataclasses.fields(Param)] == \
            [type(getattr(ref, fl.name)) for fl in dataclasses.fields(Param)]
    if overrides:
        assert (n, c, f) == (5, "y", True)


def test_choose_records_the_option_names_of_choice():
    def tmpl_a():
        pass

    def tmpl_b():
        pass

    record, templates = {}, {}
    ctx = category_module.SlotContext(ParamRecorder(np.random.default_rng(6), record).scope("door"), "sub", {},
                                      ObjectBuilder(record), templates, "door")
    ref = ParamRecorder(np.random.default_rng(6)).scope("door")
    options = [{tmpl_a: 1.0, tmpl_b: 3.0}, ("p", "q"), [tmpl_b, tmpl_a]]
    got = [ctx.choose(f"t{i % 3}_{i}", options[i % 3]) for i in range(30)]
    want = [ref.choice(f"t{i % 3}_{i}", options[i % 3]) for i in range(30)]
    assert got == want and ref.record == record
    assert ctx.choose("fixed", options[0], fixed=tmpl_a) is tmpl_a and record["door.fixed"].value == "tmpl_a"
    names = [getattr(t, "__name__", t) for t in want] + ["tmpl_a"]
    assert templates == {"door": names}


def test_create_link_makes_the_dataclass_link():
    import artipg.model.articulation as art

    b = ObjectBuilder()
    root = b.create_link("base")
    child = b.create_link("lid", root)
    for lb, name in [(root, "base_0"), (child, "lid_0")]:
        ref = art.Link(name)
        assert type(lb.link) is art.Link and vars(lb.link) == vars(ref) and lb.link.parts is not ref.parts
    assert root.link.parts is not child.link.parts


def test_scoped_keys_are_the_dotted_names():
    rec = ParamRecorder(np.random.default_rng(3), prefix="")
    a = rec.scope("a")
    b = a.scope("b")
    top = ParamRecorder(np.random.default_rng(3), rec.record, prefix="slot")
    a.uniform("u", 0, 1), b.integers("i", 0, 3), b.choice("c", ("x", "y")), rec.flag("f", 0.5), top.uniform("w", 0, 1)
    top.scope("door").uniform("h", 0, 1, fixed=0.5)
    assert list(rec.record) == ["a.u", "a.b.i", "a.b.c", "f", "slot.w", "slot.door.h"]
    assert all(k == p.name for k, p in rec.record.items())
    assert (rec.prefix, a.prefix, b.prefix, top.scope("door").prefix) == ("", "a", "a.b", "slot.door")
    with pytest.raises(AttributeError):
        a.prefix = "z"


def test_part_init_defaults_validation_and_replace():
    prim = [cuboid(0.1, 0.2, 0.3)]
    a, b = Part("door", "slab", prim), Part("door", "slab", prim)
    assert a.anchors == {} and a.regions == {} and a.grasps == [] and a.size is None
    assert a.anchors is not b.anchors and a.regions is not b.regions and a.grasps is not b.grasps
    assert a.canonical is IDENTITY and a.pose is IDENTITY and a.param_span == (0, 0)
    assert (a.actionable, a.name) == ("none", "")
    with pytest.raises(KeyError, match="vocabulary"):
        Part("no_such_label", "x", prim)
    with pytest.raises(ValueError, match="actionable"):
        Part("door", "x", prim, actionable="no_such_class")
    with pytest.raises(ValueError, match="affordance"):
        Part("door", "x", prim, regions={"no_such_affordance": None})
    c = Part("handle", "bar", prim, anchors={"h": (0.0, 0.0, 1.0)}, regions={"grasp": None},
             actionable="line_fixed_handle", name="handle_0", size=np.ones(3))
    d = dataclasses.replace(c, name="copy")
    for f in dataclasses.fields(Part):
        if f.name != "name":
            assert getattr(d, f.name) is getattr(c, f.name), f.name
    assert d.name == "copy"
    assert "semantic='handle'" in repr(c)


def test_region_and_grasp_init_as_the_generated_dataclass_init():
    r = Region(("grip",))
    assert (r.roles, r.box) == (("grip",), None) and Region() == Region((), None) and r == Region(roles=("grip",))
    assert repr(r) == "Region(roles=('grip',), box=None)" and hash(r) == hash(Region(("grip",)))
    box = np.zeros((2, 3))
    assert Region(box=box).box is box
    T = translation(1.0, 2.0, 3.0)
    a, b = Grasp(T, 0.02), Grasp(pose=T, width=0.02)
    assert a.pose is T and a.width == 0.02 and a.open_dir.tobytes() == np.zeros(3).tobytes()
    assert a.open_dir is not b.open_dir and a.open_dir.flags.writeable  # a fresh array each
    d = np.array([0.0, 0.0, 1.0])
    assert Grasp(T, 0.02, d).open_dir is d and Grasp(T, 0.02, open_dir=None).open_dir is None
    for obj, field in ((r, "roles"), (a, "width")):
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(obj, field, 1)
    assert [f.name for f in dataclasses.fields(Grasp)] == ["pose", "width", "open_dir"]
    c = dataclasses.replace(a, width=0.05)
    assert c.pose is T and c.open_dir is a.open_dir and c.width == 0.05
    assert pickle.loads(pickle.dumps(r)) == r and pickle.loads(pickle.dumps(a)).width == 0.02
    with pytest.raises(TypeError):
        Grasp(T)


def test_generated_objects_are_freed_without_the_cyclic_collector():
    # the link builders share their builder's counters, not the builder, and the
    # primitive table's groups hold its arrays, not the table: no reference cycle keeps
    # a dropped object's parts, parameter record or table alive until a collection
    enabled = gc.isenabled()
    gc.disable()
    try:
        for c in artipg.categories():
            obj = artipg.generate(c, 2)
            obj.sample_points(64)
            obj.primitive_table.groups[0].P  # the groups' views of the table's arrays
            parts = [weakref.ref(p) for p in obj.parts]
            table = weakref.ref(obj.primitive_table)  # its groups must not refer back to it
            del obj
            assert all(r() is None for r in parts), c
            assert table() is None, c
    finally:
        if enabled:
            gc.enable()
    b = ObjectBuilder()
    root = b.create_link("base")
    root.add(Part("body", "x", [cuboid(0.1, 0.1, 0.1)]))
    assert b.build("c", "s", 0).parts[0].name == "body_0"
    alive = weakref.ref(b)
    del b
    assert alive() is None  # a link builder does not keep its builder alive


def _zero_rich_rotations(rng):
    """Rigid (4, 4) transforms with many (signed) zeros, and random ones."""
    flip = -np.eye(4)  # -0.0 everywhere off the diagonal, bottom row included
    flip[3, 3] = 1.0
    out = [np.eye(4), flip, IDENTITY]
    for angle in (0.0, -0.0, math.pi / 2, -math.pi / 2, math.pi, -math.pi, 2 * math.pi):
        out += [rot_x(angle), rot_y(angle), rot_z(angle)]
    for _ in range(100):  # signed permutation matrices with -0.0 sprinkled in
        M = np.eye(4)
        M[:3, :3] = np.eye(3)[rng.permutation(3)] * rng.choice([-1.0, 1.0], 3)
        M[:3, :3][M[:3, :3] == 0] *= rng.choice([-1.0, 1.0], 6)
        out.append(M)
    for _ in range(100):
        out.append(rotation(rng.normal(size=3), rng.uniform(-7, 7)))
    for M in list(out[-60:]):  # with a translation, some of it -0.0 or cancelling
        M = M.copy()
        M[:3, 3] = rng.choice([0.0, -0.0, 0.25, -1.5, 1e-300, rng.normal()], 3)
        out.append(M)
    M = rot_y(math.pi / 2)
    M[:3, 3] = (-0.0, -0.0, -0.0)
    out.append(M)
    return out


def test_placer_is_the_translation_product():
    rng = np.random.default_rng(6)
    values = [0.0, -0.0, 1.0, -1.0, 0.25, -1.5, 1e-300, -1e-300, 1e300, 3, -2, np.float64(-0.0),
              np.float32(0.1), np.float32(-0.0), np.int64(5), True]
    for M in _zero_rich_rotations(rng):
        P = Placer(M)
        assert P.matrix.tobytes() == np.asarray(M, dtype=float).tobytes() and not P.matrix.flags.writeable
        for _ in range(20):
            xyz = [values[i] for i in rng.integers(len(values), size=3)]
            if rng.random() < 0.5:
                xyz[int(rng.integers(3))] = float(rng.normal())
            if rng.random() < 0.2:
                xyz[int(rng.integers(3))] = -float(M[int(rng.integers(3)), 3])  # cancels: a zero sum
            T = P.at(*xyz)
            ref = translation(*xyz) @ M
            assert np.allclose(T, ref, rtol=1e-15, atol=0.0), (M, xyz, T, ref)
            assert T.flags.writeable and T.flags.c_contiguous and T.dtype == np.float64
    T = Placer(rot_x(0.3)).at(1.0)
    T[0, 0] = 7.0
    assert Placer(rot_x(0.3)).at(1.0)[0, 0] == 1.0 and Placer(IDENTITY).at().tobytes() == np.eye(4).tobytes()
    for bad in (np.eye(3), np.diag([1.0, 1.0, 1.0, 2.0]), np.full((4, 4), np.nan)):
        with pytest.raises(ValueError, match="bottom row"):
            Placer(bad)


def test_primitive_constructors_make_the_named_tuple():
    import importlib

    base, box, prism, revolve, tube = (importlib.import_module(f"artipg.geometry.{m}")  # geometry.prism is a function too
                                       for m in ("base", "box", "prism", "revolve", "tube"))
    T = translation(0.1, -0.2, 0.3)
    f32, i64 = np.float32(0.25), np.int64(2)
    cases = [
        (box.cuboid(0.1, f32, i64, T, "r"), (box.Cuboid, (0.1, float(f32), 2.0), T, "r")),
        (box.cuboid_between((0, -0.5, f32), np.array([1.0, 0.5, 2.0])),
         (box.Cuboid, (1.0, 1.0, 2.0 - float(f32)), translation(0.5, 0.0, 0.5 * (float(f32) + 2.0)), "")),
        (box.rect_ring(1, 2, 3, 0.5, 0.25), (box.RectRing, (1.0, 2.0, 3.0, 0.5, 0.25), IDENTITY, "")),
        (prism.prism(0.1, 0.2, 6, T), (prism.Prism, (0.1, 0.2, 6.0), T, "")),
        (prism.tri_prism(0.1, 0.2, 0.0, 0.3), (prism.TriPrism, (0.1, 0.2, 0.0, 0.3), IDENTITY, "")),
        (revolve.cylinder(0.1, 0.2, role="c"), (revolve.Frustum, (0.1, 0.1, 0.2, 1.0, 1.0), IDENTITY, "c")),
        (revolve.frustum(0.1, f32, 0.2), (revolve.Frustum, (0.1, float(f32), 0.2, 1.0, 1.0), IDENTITY, "")),
        (revolve.ring(0.2, 0.1, 0.3, 1.0, T, "w", 0.01), (revolve.Ring, (0.2, 0.1, 0.3, 1.0, 0.01), T, "w")),
        (revolve.sphere(0.2, -0.1, 0.1), (revolve.Sphere, (0.2, -0.1, 0.1), IDENTITY, "")),
        (revolve.torus(0.2, 0.05, 1.0, T, "t", (1.0, 0.0)), (revolve.Torus, (0.2, 0.05, 1.0, 1.0, 0.0), T, "t")),
    ]
    for got, (geom, params, pose, role) in cases:
        ref = base.Primitive(geom, params, pose, role)
        assert type(got) is base.Primitive and got._fields == ref._fields
        assert (got.geom, got.params, got.role) == (ref.geom, ref.params, ref.role)
        assert [type(v) for v in got.params] == [float] * len(params)
        assert got.pose.tobytes() == ref.pose.tobytes()
    for got in tube.tube(0.01, [tube.line(0.1), tube.arc(0.05, 1.0)], pose=T, role="tube"):
        assert type(got) is base.Primitive and got.role == "tube" and got.geom in (revolve.Frustum, revolve.Torus)


def test_part_bounds_are_the_stacked_min_max():
    rng = np.random.default_rng(2)
    for n in (1, 2, 7):
        prims = [cuboid(*rng.uniform(0.01, 0.5, 3), rotation(rng.normal(size=3), rng.uniform(-3, 3))
                        @ translation(*rng.normal(size=3))) for _ in range(n)]
        part = Part("body", "x", prims)
        b = np.stack([p.bounds() for p in prims])
        ref = np.stack([b[:, 0].min(axis=0), b[:, 1].max(axis=0)])
        assert part.bounds().tobytes() == ref.tobytes()


def _rotation_nested(axis, angle):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(angle), math.sin(angle)
    C = 1.0 - c
    return np.array([
        [c + x * x * C, x * y * C - z * s, x * z * C + y * s, 0.0],
        [y * x * C + z * s, c + y * y * C, y * z * C - x * s, 0.0],
        [z * x * C - y * s, z * y * C + x * s, c + z * z * C, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ])


def test_rotation_is_the_nested_formula_in_a_fresh_array():
    rng = np.random.default_rng(3)
    axes = [(1, 0, 0), (0, -1, 0), (0.0, 0.0, 1.0)] + [tuple(rng.normal(size=3)) for _ in range(200)]
    angles = [0.0, -0.0, math.pi / 2, math.pi, -math.pi / 2] + list(rng.uniform(-7, 7, 200))
    for i, axis in enumerate(axes):
        angle = angles[i % len(angles)]
        T = rotation(axis, angle)
        assert T.tobytes() == _rotation_nested(axis, angle).tobytes()
        assert T.shape == (4, 4) and T.dtype == np.float64 and T.flags.writeable
    for angle in angles:
        for rot, axis in ((rot_x, (1, 0, 0)), (rot_y, (0, 1, 0)), (rot_z, (0, 0, 1))):
            assert rot(angle).tobytes() == _rotation_nested(axis, angle).tobytes()
    about = rng.normal(size=3)
    T = rotation((1.0, 2.0, -2.0), 0.7, about=about)
    R = _rotation_nested((1.0, 2.0, -2.0), 0.7)
    R[:3, 3] = about - R[:3, :3] @ about
    assert T.tobytes() == R.tobytes()
    A, B = rotation((0, 0, 1), 0.3), rotation((0, 0, 1), 0.3)
    A[0, 3] = 5.0
    assert B[0, 3] == 0.0
    T = translation(1.0, 2.0, 3.0)
    T[0, 0] = 7.0
    assert translation(1.0, 2.0, 3.0)[0, 0] == 1.0


def test_names_count_uses_of_each_base_name():
    b = ObjectBuilder()
    root = b.create_link("base")
    links = [b.create_link("door", root) for _ in range(70)]
    assert [lb.name for lb in links] == [f"door_{k}" for k in range(70)] and root.name == "base_0"
    parts = [root.add(Part("handle", "bar", [cuboid(0.1, 0.1, 0.1)]), name=n) for n in ["knob"] * 70 + [None] * 3]
    assert [p.name for p in parts] == [f"knob_{k}" for k in range(70)] + ["handle_0", "handle_1", "handle_2"]


def test_set_joint_makes_the_dataclass_joint():
    import artipg.model.articulation as art

    b = ObjectBuilder()
    root = b.create_link("base")
    child = b.create_link("lid", root)
    T = np.eye(4)
    for kind, limits in [("revolute", (0.0, 1.5)), ("prismatic", (0, 1)), ("continuous", (0.0, 0.0)), ("fixed", (0.0, 0.0))]:
        j = child.set_joint(kind, T, axis=(0, 1, 0), limits=limits, name=None if kind != "fixed" else "pin")
        ref = art.Joint("pin" if kind == "fixed" else "joint_lid_0", kind, "base_0", "lid_0", T, np.array([0.0, 1.0, 0.0]),
                        (-np.inf, np.inf) if kind == "continuous" else (float(limits[0]), float(limits[1])))
        assert type(j) is art.Joint and vars(j).keys() == vars(ref).keys() and child.link.joint is j
        for f in dataclasses.fields(art.Joint):
            a, r = getattr(j, f.name), getattr(ref, f.name)
            assert (a.tobytes() == r.tobytes()) if isinstance(r, np.ndarray) else (a == r and type(a) is type(r)), f.name


def test_joint_axis_is_normalised_as_before():
    b = ObjectBuilder()
    root = b.create_link("base")
    child = b.create_link("x", root)
    for axis in [(0, 0, 1), (0.0, -0.0, -1.0), (-1, 0, 0), (1, 2, 3), np.array([0.3, -0.4, 0.5]), [-0.0, 2, 0]]:
        j = child.set_joint("revolute", np.eye(4), axis=axis, limits=(0.0, 1.0))
        x, y, z = (float(v) for v in axis)
        n = math.sqrt(x * x + y * y + z * z)
        assert j.axis.tobytes() == np.array((x / n, y / n, z / n)).tobytes()
    with pytest.raises(ValueError, match="non-zero"):
        child.set_joint("revolute", np.eye(4), axis=(0, 0, 0), limits=(0.0, 1.0))
    j = child.set_joint("continuous", np.eye(4))
    assert j.limits == (-np.inf, np.inf)


def _link_poses_plain(obj, qpos=None):
    q = obj.qpos_dict(qpos)
    T = np.empty((len(obj.links), 4, 4))
    T[0] = np.eye(4)
    for i, link in enumerate(obj.links[1:], start=1):
        j = link.joint
        Tj = T[obj.link_index[j.parent]] @ j.origin
        v = q.get(j.name, 0.0)
        T[i] = Tj @ j.motion(v) if v else Tj
    return T


def test_link_poses_are_the_plain_chain_products():
    rng = np.random.default_rng(4)
    for c in artipg.categories():
        obj = artipg.generate(c, 1)
        assert obj.link_poses().tobytes() == _link_poses_plain(obj).tobytes()
        lim = obj.limits()
        q = rng.uniform(lim[:, 0], lim[:, 1])
        q[rng.random(len(q)) < 0.3] = 0.0
        assert obj.link_poses(q).tobytes() == _link_poses_plain(obj, q).tobytes()
