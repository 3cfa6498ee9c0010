"""Products that templates make without a matrix product must be the product, bit for bit.

transforms.translated, mounting.handle_pose, mounting.mount_hinged, controls.mount_poses
and the spray arm's turns skip a (4, 4) product when one factor is a pure translation;
these tests compare them with the plain product (signed zeros, cancelling sums and
rotated frames included).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry.transforms import IDENTITY, rot_x, rot_y, rot_z, rotation, translated, translation
from artipg.model.builder import ObjectBuilder
from artipg.rules.params import ParamRecorder
from artipg.templates import controls, mounting, racks
from artipg.templates.panels import slab_door

_VALUES = [0.0, -0.0, 1.0, -1.0, 0.25, -1.5, 1e-300, -1e-300, 1e300, 3, -2, np.float64(-0.0), np.float32(0.1),
           np.float32(-0.0), np.int64(5), True]


def _poses(rng):
    """Pure translations (zeros of either sign, IDENTITY itself) and rigid poses that are not."""
    out = [IDENTITY, np.eye(4), translation(-0.0, -0.0, -0.0)]
    for _ in range(150):
        T = np.eye(4)
        T[:3, 3] = [_VALUES[i] if i < len(_VALUES) else rng.normal() for i in rng.integers(len(_VALUES) + 4, size=3)]
        if rng.random() < 0.3:  # -0.0 off the diagonal: still a pure translation
            T[0, 1] = T[2, 0] = T[3, 2] = -0.0
        out.append(T)
    for angle in (math.pi / 2, -math.pi, 0.3):
        out += [rot_x(angle), rot_y(angle) @ translation(0.1, -0.0, 2.0), rot_z(angle)]
    for _ in range(20):
        T = rotation(rng.normal(size=3), rng.uniform(-7, 7))
        T[:3, 3] = rng.normal(size=3)
        out.append(T)
    return out


def _xyz(rng, T):
    xyz = [_VALUES[i] for i in rng.integers(len(_VALUES), size=3)]
    if rng.random() < 0.5:
        xyz[int(rng.integers(3))] = float(rng.normal())
    if rng.random() < 0.3:  # cancels the translation: a zero sum
        k = int(rng.integers(3))
        xyz[k] = -float(T[k, 3])
    return xyz






def test_handle_pose_is_the_plain_product():
    rng = np.random.default_rng(12)
    for F in _poses(rng):
        for _ in range(10):
            t, y, z = (float(v) for v in _xyz(rng, F))
            for horizontal in (False, True):
                ref = F @ translation(-t, y, z)
                if horizontal:
                    ref = ref @ mounting._HORIZONTAL
                got = mounting.handle_pose(F, t, y, z, horizontal)
                assert got.tobytes() == ref.tobytes(), (F, t, y, z, horizontal)


def test_mount_hinged_origin_is_the_parent_pose_product():
    rng = np.random.default_rng(13)
    for parent_pose in _poses(rng)[::5]:
        b = ObjectBuilder()
        root = b.create_link("base")
        door = slab_door(ParamRecorder(np.random.default_rng(0)), 0.4, 0.7)
        front_x, cy, cz = (float(v) for v in rng.normal(size=3))
        link = mounting.mount_hinged(b, root, door, front_x=front_x, center_yz=(cy, cz), size_yz=(0.4, 0.7),
                                     side="+y", limits=(0.0, 1.5), parent_pose=parent_pose)
        t = mounting.front_thickness(door)
        ref = parent_pose @ translation(front_x - t, cy + 0.2, cz)
        assert link.link.joint.origin.tobytes() == ref.tobytes()


def test_mount_poses_are_the_products():
    rng = np.random.default_rng(14)
    for pose in _poses(rng):
        yz = [tuple(_xyz(rng, pose)[1:]) for _ in range(int(rng.integers(0, 6)))]
        got = controls.mount_poses(pose, yz)
        assert len(got) == len(yz)
        for T, (y, z) in zip(got, yz):
            ref = pose @ translation(0.0, y, z)
            assert T.tobytes() == ref.tobytes(), (pose, y, z, T, ref)


def test_spray_arm_turns_are_the_products():
    rng = np.random.default_rng(15)
    for placer, angle in zip(racks._ARM_TURNS, (0.0, math.pi / 2)):
        for z in [0.0, -0.0, 1e-300] + list(rng.uniform(0.0, 0.05, 50)):
            assert placer.at(0, 0, z).tobytes() == (rot_z(angle) @ translation(0, 0, z)).tobytes()


def test_button_region_box():
    p = ParamRecorder(np.random.default_rng(3))
    for tmpl in (controls.rect_button, controls.round_button):
        part = tmpl(p.scope(tmpl.__name__))
        x = part.anchors["front"][0]
        prim = part.primitives[0]
        face = prim.params[1:3] if tmpl is controls.rect_button else (2 * prim.params[0],) * 2
        ref = np.array([[x - 1e-4, -face[0] / 2, -face[1] / 2], [x + 1e-4, face[0] / 2, face[1] / 2]])
        assert part.regions["press"].box.tobytes() == ref.tobytes()


def test_tube_function_is_the_tube_primitives():
    from artipg.geometry.tube import Tube, arc, line, tube

    paths = [([line(0.03), arc(0.01, -math.pi / 2), line(0.2), arc(0.01, -math.pi / 2), line(0.03)], math.pi),
             ([line(0.1)], 0.3), ([arc(0.05, math.pi)], -0.0), ([line(0.02), arc(0.03, 2.0)], math.pi / 2)]
    for segs, heading in paths:
        for pose in (IDENTITY, translation(0.1, -0.0, -0.2), rot_y(0.4) @ translation(0.0, 0.1, 0.0)):
            got = tube(0.004, segs, heading, pose, role="grip")
            ref = Tube(0.004, tuple(segs), heading).primitives(pose, "grip")
            assert len(got) == len(ref) == len(segs)
            for a, b in zip(got, ref):
                assert a.geom is b.geom and a.params == b.params and a.role == b.role == "grip"
                assert a.pose.tobytes() == b.pose.tobytes()
