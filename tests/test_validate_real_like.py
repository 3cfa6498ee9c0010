"""``artipg validate`` on folders built like real (PartNet-Mobility) objects.

A cabinet is written by code as a URDF of boxes: an empty ``base``, a carcass, an
inset door on a hinge and a drawer on a slide, both with 3 mm clearance all round,
and a handle on the door. The clean cabinet passes; three planted faults fail the
check that should catch them. Real objects are used only when ``ARTIPG_REALDATA``
names a folder of them (CI has none).
"""

from __future__ import annotations

import json
import math
import os
import time
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from artipg.validate.checks import Tolerances
from artipg.validate.folder import find_objects, validate_folder
from artipg.validate.isolation import run_isolated

D, W, H, T = 0.4, 0.6, 0.8, 0.02  # carcass depth (x), width (y), height (z), panel thickness (metres)
C = 0.003  # clearance round the door and the drawer


def _box(center, size) -> str:
    c = " ".join(f"{v:.6f}" for v in center)
    s = " ".join(f"{v:.6f}" for v in size)
    return f'<visual><origin xyz="{c}" rpy="0 0 0"/><geometry><box size="{s}"/></geometry></visual>'


def _link(name, boxes) -> str:
    return f'<link name="{name}">' + "".join(_box(c, s) for c, s in boxes) + "</link>"


def _joint(name, jtype, parent, child, xyz, axis=(0, 0, 1), limit=None) -> str:
    lim = f'<limit lower="{limit[0]}" upper="{limit[1]}" effort="10" velocity="1"/>' if limit else ""
    return (f'<joint name="{name}" type="{jtype}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{" ".join(map(str, xyz))}" rpy="0 0 0"/><axis xyz="{" ".join(map(str, axis))}"/>{lim}'
            "</joint>")


def cabinet_urdf(door_axis=(0, 0, 1), drawer_half_width=W / 2 - T - C, handle_gap=0.0, hinge_forward=0.0) -> str:
    """The cabinet's URDF text (front faces -x, z up, metres); the arguments plant faults."""
    iw = W - 2 * T  # inner width
    body = [((0, -(W - T) / 2, H / 2), (D, T, H)), ((0, (W - T) / 2, H / 2), (D, T, H)),  # sides
            ((0, 0, T / 2), (D, iw, T)), ((0, 0, H - T / 2), (D, iw, T)),  # bottom, top
            ((0, 0, H / 2), (D, iw, T)),  # shelf
            ((D / 2 - T / 2, 0, H / 2), (T, iw, H - 2 * T))]  # back
    # door: the upper opening less the clearance, flush with the front, hinged on its left edge
    dz0, dz1 = H / 2 + T / 2 + C, H - T - C
    dw = iw - 2 * C
    door = [((T / 2 + hinge_forward, dw / 2, (dz1 - dz0) / 2), (T, dw, dz1 - dz0))]
    handle = [((-T / 2, 0, 0), (T, T, 0.12))]
    # drawer: front, bottom, sides and back touching each other, in the lower opening
    z0, z1 = T + C, H / 2 - T / 2 - C
    hw, zs = drawer_half_width, T + C + T + 0.1  # half width, centre height of the sides and back
    drawer = [((-D / 2 + T / 2, 0, (z0 + z1) / 2), (T, 2 * hw, z1 - z0)),  # front
              ((-T / 2, 0, z0 + T / 2), (D - 3 * T, 2 * hw, T)),  # bottom, short of the back panel
              ((-T / 2, -hw + T / 2, zs), (D - 3 * T, T, 0.2)), ((-T / 2, hw - T / 2, zs), (D - 3 * T, T, 0.2)),
              ((D / 2 - 2.5 * T, 0, zs), (T, 2 * hw - 2 * T, 0.2))]  # sides, back
    parts = [
        '<?xml version="1.0"?><robot name="cabinet">',
        '<link name="base"/>', _link("body", body), _link("door", door), _link("door_handle", handle),
        _link("drawer", drawer),
        _joint("base_body", "fixed", "base", "body", (0, 0, 0)),
        _joint("door_hinge", "revolute", "body", "door", (-D / 2 - hinge_forward, -dw / 2, dz0), door_axis,
               (0, math.pi / 2)),
        _joint("door_handle_fix", "fixed", "door", "door_handle", (hinge_forward - handle_gap, dw - 0.05,
                                                                     (dz1 - dz0) / 2)),
        _joint("drawer_slide", "prismatic", "body", "drawer", (0, 0, 0), (-1, 0, 0), (0, 0.3)),
        "</robot>",
    ]
    return "\n".join(parts)


FAULTS = {
    "clean": ({}, None),
    "door axis flipped": ({"door_axis": (0, 0, -1)}, "joint_sweep"),
    "drawer too wide": ({"drawer_half_width": W / 2 - T + 0.01}, "penetration"),
    "handle floating": ({"handle_gap": 0.02}, "floating"),
}


def _write(folder: Path, text: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "mobility.urdf").write_text(text)
    return folder


@pytest.fixture(scope="module")
def cabinets(tmp_path_factory):
    root = tmp_path_factory.mktemp("cabinets")
    return {name: _write(root / name.replace(" ", "_"), cabinet_urdf(**kw)) for name, (kw, _) in FAULTS.items()}


def _failed(report) -> set:
    return {k for k, c in report.checks.items() if not c.ok}


@pytest.mark.parametrize("name", list(FAULTS))
@pytest.mark.parametrize("tol", [None, Tolerances()], ids=["relative", "metric"])
def test_cabinet_with_clearance_passes_and_planted_faults_fail(cabinets, name, tol):
    report, meta = validate_folder(cabinets[name], tol=tol, simulate=False)
    want = FAULTS[name][1]
    if want is None:
        assert report.ok, [i.to_json() for c in report.checks.values() for i in c.issues]
    else:
        assert want in _failed(report)
    if name == "handle floating":  # a handle on a fixed joint is a part of the door's rigid body
        (issue,) = report.checks["floating"].issues
        assert issue.kind == "floating_part" and issue.links == ["door"] and issue.parts == ["door_handle_visual0"]
        assert issue.amount == pytest.approx(0.02, abs=1e-6)
    if name == "door axis flipped":
        sweep = [i for i in report.checks["joint_sweep"].issues if i.kind == "sweep_penetration"]
        assert sweep and {i.joint for i in sweep} == {"door_hinge"}
    if name == "drawer too wide":
        assert all(set(i.links) == {"base", "drawer"} for i in report.checks["penetration"].issues)  # body: fixed to base


def test_clearance_is_a_gap_that_only_the_hinge_and_slide_bridge(cabinets):
    """Without the joints' anchoring the door and drawer would float: the 3 mm gap is
    wider than the metric floating tolerance, and a door fixed to the carcass (one
    rigid body) is a part that floats with its handle."""
    text = (cabinets["clean"] / "mobility.urdf").read_text()
    text = text.replace('name="door_hinge" type="revolute"', 'name="door_hinge" type="fixed"')
    folder = _write(cabinets["clean"].parent / "door_fixed", text)
    report, _ = validate_folder(folder, tol=Tolerances(), simulate=False)
    (issue,) = report.checks["floating"].issues
    assert issue.kind == "floating_part" and issue.links == ["base"]  # the door is now the carcass's part
    assert issue.parts == ["door_visual0", "door_handle_visual0"] and issue.amount == pytest.approx(C, abs=1e-6)


def test_hinge_far_from_the_carcass_does_not_hold_the_door(cabinets):
    """A hinge axis 5 cm in front of the carcass anchors nothing: the door floats."""
    folder = _write(cabinets["clean"].parent / "hinge_off", cabinet_urdf(hinge_forward=0.05))
    report, _ = validate_folder(folder, tol=Tolerances(), simulate=False)
    assert "floating" in _failed(report)


def test_relative_tolerances_scale_with_the_object(cabinets):
    """A folder checked on its meshes gets tolerances per unit of its diagonal: the
    same cabinet scaled by 2.5 (unitless, like PartNet-Mobility's diagonal of about 2)
    gives the same verdicts with tolerances 2.5 times larger."""
    from xml.etree import ElementTree as ET

    r1, m1 = validate_folder(cabinets["drawer too wide"], simulate=False)
    tree = ET.fromstring((cabinets["drawer too wide"] / "mobility.urdf").read_text())
    for el in tree.iter():
        for key in ("xyz", "size"):
            if key in el.attrib and el.tag != "axis":
                el.set(key, " ".join(str(2.5 * float(v)) for v in el.get(key).split()))
        if el.tag == "limit" and el.get("upper") == "0.3":
            el.set("upper", "0.75")
    folder = _write(cabinets["clean"].parent / "scaled", ET.tostring(tree, encoding="unicode"))
    r2, m2 = validate_folder(folder, simulate=False)
    assert m2["diagonal"] == pytest.approx(2.5 * m1["diagonal"], rel=1e-9)
    assert r2.tolerances["penetration"] == pytest.approx(2.5 * r1.tolerances["penetration"], rel=1e-9)
    assert _failed(r1) == _failed(r2) and "penetration" in _failed(r1)
    assert r2.checks["penetration"].worst == pytest.approx(2.5 * r1.checks["penetration"].worst, rel=1e-6)


# ---------------------------------------------------------------- mesh distances

def test_mesh_sdf_matches_a_sphere_and_treats_open_meshes_as_shells():
    import trimesh

    from artipg.validate.mesh_sdf import MeshSDF

    sphere = trimesh.creation.icosphere(subdivisions=4, radius=0.5)
    f = MeshSDF(sphere.vertices, sphere.faces)
    rng = np.random.default_rng(3)
    x = rng.uniform(-1, 1, (500, 3))
    want = np.linalg.norm(x, axis=1) - 0.5
    assert np.abs(f(x) - want).max() < 5e-3  # the facets' sag at subdivision 4
    # a closed box: inside is negative
    box = trimesh.creation.box((1.0, 1.0, 1.0))
    assert MeshSDF(box.vertices, box.faces).closed
    assert MeshSDF(box.vertices, box.faces)(np.array([[0.0, 0.0, 0.3]]))[0] == pytest.approx(-0.2, abs=1e-9)
    # a double-sided sheet is watertight but encloses nothing: a shell
    sheet = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 3], [0, 2, 1], [0, 3, 2]])
    assert not MeshSDF(sheet.vertices, sheet.faces).closed
    assert MeshSDF(sheet.vertices, sheet.faces)(np.array([[0.5, 0.5, -0.3]]))[0] == pytest.approx(0.3, abs=1e-9)
    # an inward-oriented closed box reads the same as the outward one
    inv = MeshSDF(box.vertices, box.faces[:, ::-1])
    assert inv(np.array([[0.0, 0.0, 0.3], [0.0, 0.0, 0.9]])) == pytest.approx([-0.2, 0.4], abs=1e-9)
    # an open cup (the box without its top) is a shell: unsigned everywhere
    keep = box.face_normals[:, 2] < 0.5
    cup = MeshSDF(box.vertices, box.faces[keep])
    assert not cup.closed
    d = cup(np.array([[0.0, 0.0, 0.6], [0.0, 0.0, 0.3], [0.0, 0.0, -0.7]]))
    assert d == pytest.approx([math.sqrt(0.26), 0.5, 0.2], abs=1e-9)


# ---------------------------------------------------------------- isolation and the CLI

def _flaky(item):
    if item == "crash":
        os._exit(3)
    if item == "hang":
        time.sleep(60)
    if item == "raise":
        raise ValueError("bad item")
    return {"value": item}


def test_a_crash_a_hang_and_an_error_fail_only_their_item():
    items = ["a", "crash", "b", "hang", "raise", "c"]
    out = run_isolated(_flaky, items, workers=2, timeout=3.0)
    assert [r.get("value") for r in out] == ["a", None, "b", None, None, "c"]
    assert "worker died" in out[1]["error"] and "timeout" in out[3]["error"]
    assert out[4]["error"] == "ValueError: bad item"
    assert all("seconds" in r for r in out)


def test_an_interrupted_run_returns_what_it_has():
    def stop(i, r):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt) as e:
        run_isolated(_flaky, ["a", "b", "c"], workers=1, timeout=30.0, on_result=stop)
    out = e.value.results
    assert out[0]["value"] == "a" and [r["error"] for r in out[1:]] == ["interrupted", "interrupted"]


def test_cli_reports_every_folder_even_broken_ones(cabinets, tmp_path):
    from artipg.cli import app

    root = tmp_path / "objects"
    _write(root / "good", cabinet_urdf())
    _write(root / "malformed", "<robot name='x'><link name='a'>")
    _write(root / "no_mesh", '<robot name="x"><link name="a"><visual><geometry><mesh filename="gone.obj"/>'
                             "</geometry></visual></link></robot>")
    _write(root / "good" / "leftover", cabinet_urdf())  # inside an object folder: not an object
    assert len(find_objects([root])) == 3
    out = tmp_path / "report.json"
    res = CliRunner().invoke(app, ["validate", str(root), "--no-sim", "-j", "2", "--json", str(out)])
    assert res.exit_code == 1, res.output
    assert "Traceback" not in res.output and "Warning" not in res.output
    rep = json.loads(out.read_text())
    by = {Path(o["path"]).name: o for o in rep["objects"]}
    assert by["good"]["ok"] and not by["malformed"]["ok"] and not by["no_mesh"]["ok"]
    assert "gone.obj" in by["no_mesh"]["error"]
    assert rep["passed"] == 1 and rep["failed"] == 2 and rep["workers"] == 2
    assert all(o["seconds"] >= 0 for o in rep["objects"])


# ---------------------------------------------------------------- real objects (optional)

REAL = os.environ.get("ARTIPG_REALDATA")


@pytest.mark.skipif(not REAL or not Path(REAL).is_dir(), reason="ARTIPG_REALDATA (a folder of real objects) not set")
def test_real_objects_validate_without_errors():
    """Every real object yields a report (no crash); storage furniture (doors and
    drawers with clearance) passes the geometric checks."""
    folders = find_objects([Path(REAL)])
    assert folders
    for f in folders:
        if f.parent.name != "StorageFurniture":
            continue
        report, meta = validate_folder(f, simulate=False)
        assert meta["geometry"] == "mesh"
        assert report.ok, (str(f), report.failed())
