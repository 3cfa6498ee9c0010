"""Panel controls: rotary knobs and dials, push buttons and rocker switches.

Frame convention (every template here; reuse them on ovens, washing machines, safes):
the control is mounted on a flat surface whose outward normal is **-x**; the origin is
the mount point on that surface (the surface is the plane x = 0), the control protrudes
along -x and +z is "up" on the panel. To mount on a surface facing another way, rotate
the mount pose (e.g. ``rot_z(pi / 2)`` for a surface facing -y).

Joints (set them with :func:`mount_knob`, :func:`mount_button` / :func:`mount_keypad`,
:func:`mount_rocker`):

- knobs: revolute or continuous about +x through the origin (positive = clockwise seen
  from the front). Their back face lies on x = 0, so any angle is collision free.
- push buttons: prismatic along +x (into the surface), limits (0, travel). The cap
  stands off the surface by ``travel + clearance``: anchor ``back`` is its back face at
  rest and ``stop`` where that face is when fully pressed, so a flat surface (or the
  floor of a keypad well) behind the cap is all it needs to press freely. Every link
  must touch the object at rest, so surround the cap within 2 mm: put it in a keypad
  well with tight gaps, or add a :func:`button_bezel` (a collar) to the parent link.
- rockers: revolute about +z through the origin; the rest pose is tilted by ``-tilt``
  (one side pressed), limits (0, 2 tilt); the stand-off keeps the cap off the surface.

Anchors: ``front`` (centre of the face a finger touches) and ``back``; buttons also
``stop``.
Every template takes the recorder ``p`` first; sizes fixed by the caller (the largest
radius or cap size the panel layout allows) are keyword arguments.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import BOX, cuboid, frustum, prism, rect_ring, ring
from artipg.geometry.transforms import Placer, rot_y, rot_z, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.detail import edge_radius, rbox, rounded_disc

_ALONG_X = rot_y(math.pi / 2)    # local z -> +x (frustum r_bottom at the front, -x)
_ALONG_X_PLACER = Placer(_ALONG_X)  # translation(x, y, z) @ _ALONG_X as _ALONG_X_PLACER.at(x, y, z)
_ALONG_MX = rot_y(-math.pi / 2)  # local z -> -x (frustum r_bottom at the back, +x)
# gripper frames approaching +x (towards the surface); jaws closing along y or along z
_JAW_Y = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_JAW_Z = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_GRIP = Region(("grip",))  # regions are frozen: one object serves every knob
_EYES = np.tile(np.eye(4), (32, 1, 1))  # translations for up to 32 mount frames (mount_poses)


def _x_disc(r_back: float, r_front: float, x0: float, x1: float, role: str, edge: float = 0.0):
    """Frustum along x from x0 (back, > x1) to x1 (front), radii at each end; its
    front rim rounded by ``edge`` (metres)."""
    T = _ALONG_MX.copy()  # translation((x0 + x1) / 2, 0, 0) @ _ALONG_MX, bit for bit
    T[0, 3] = (x0 + x1) / 2
    if edge > 0.0:
        return rounded_disc(r_back, x0 - x1, edge, 0.0, False, T, role=role, R_top=r_front)
    return frustum(r_back, r_front, x0 - x1, T, role=role)


def _knob_edge(p, size: float) -> float:
    """Rounding (metres) of a knob grip's front rim (a softer grip), with detail."""
    return edge_radius(p, size, "grip_edge", lo=0.0008, hi=0.004, share=0.3)


def _knob_grasps(x_grip: float, width_y: float, width_z: float) -> list[Grasp]:
    """Grasps on a knob's grip at depth ``x_grip``, jaws closing along y and along z."""
    grasps = []
    for base, w in ((_JAW_Y, width_y), (_JAW_Z, width_z)):
        T = base.copy()
        T[0, 3] = x_grip
        grasps.append(Grasp(T, w + 0.02))
    return grasps


def _knob_part(template, prims, x_grip, width_y, width_z, depth) -> Part:
    return Part("knob", template, prims, anchors={"front": (-depth, 0.0, 0.0), "back": (0.0, 0.0, 0.0)},
                regions={"rotate": _GRIP, "grasp": _GRIP}, grasps=Deferred(_knob_grasps, x_grip, width_y, width_z),
                actionable="hinge_knob")


def round_knob(p, radius: float | None = None) -> Part:
    """Two-tier round knob: a thin skirt disc and a narrower cylindrical grip."""
    R = p.uniform("radius", 0.012, 0.025, fixed=radius)
    skirt = p.uniform("skirt_depth", 0.002, 0.005)
    rg = p.uniform("grip_ratio", 0.6, 0.9) * R
    d = p.uniform("grip_depth", 0.012, 0.025)
    taper = p.uniform("grip_taper", 0.85, 1.0)
    prims = [_x_disc(R, R, 0.0, -skirt, "skirt"),
             _x_disc(rg, rg * taper, -skirt, -skirt - d, "grip", _knob_edge(p, min(d, rg)))]
    return _knob_part("round_knob", prims, -skirt - d / 2, 2 * rg, 2 * rg, skirt + d)


def pointer_knob(p, radius: float | None = None) -> Part:
    """Oven-style knob: a round base with a raised bar across its face (the grip)."""
    R = p.uniform("radius", 0.015, 0.028, fixed=radius)
    base = p.uniform("base_depth", 0.006, 0.012)
    bar_w = p.uniform("bar_width", 0.25, 0.4) * R
    bar_d = p.uniform("bar_depth", 0.012, 0.022)
    bar_l = p.uniform("bar_length", 0.8, 0.95) * 2 * R
    prims = [_x_disc(R, R * p.uniform("base_taper", 0.85, 1.0), 0.0, -base, "base"),
             rbox(bar_d, bar_w, bar_l, _knob_edge(p, bar_w), translation(-base - bar_d / 2, 0, 0), role="grip")]
    return _knob_part("pointer_knob", prims, -base - bar_d / 2, bar_w, bar_l, base + bar_d)


def fluted_knob(p, radius: float | None = None) -> Part:
    """Knurled knob: a many-sided prism grip on a tapered collar."""
    R = p.uniform("radius", 0.012, 0.025, fixed=radius)
    n = p.integers("flutes", 8, 14)
    collar = p.uniform("collar_depth", 0.003, 0.006)
    d = p.uniform("grip_depth", 0.012, 0.022)
    prims = [_x_disc(R, 0.9 * R, 0.0, -collar, "collar"),
             prism(0.9 * R, d, n, _ALONG_X_PLACER.at(-collar - d / 2, 0, 0), role="grip")]
    return _knob_part("fluted_knob", prims, -collar - d / 2, 1.8 * R, 1.8 * R, collar + d)


def dial_knob(p, radius: float | None = None) -> Part:
    """Large shallow timer dial: a tapered disc with a small pointer ridge."""
    R = p.uniform("radius", 0.02, 0.035, fixed=radius)
    d = p.uniform("depth", 0.008, 0.015)
    ridge = p.uniform("ridge_depth", 0.003, 0.006)
    rf = p.uniform("front_ratio", 0.8, 0.95) * R
    prims = [_x_disc(R, rf, 0.0, -d, "grip", _knob_edge(p, d)),
             cuboid(ridge, 0.2 * rf, 1.6 * rf, translation(-d - ridge / 2, 0, 0), role="grip")]
    return _knob_part("dial_knob", prims, -d / 2, 2 * rf, 2 * rf, d + ridge)


KNOBS = {round_knob: 2.0, pointer_knob: 1.5, fluted_knob: 1.0, dial_knob: 1.0}


def _button_part(template, prims, stand, depth, travel, face, sem="button", act="slider_button") -> Part:
    x = -stand - depth
    w, h = face[0] / 2, face[1] / 2
    box = np.array((x - 1e-4, -w, -h, x + 1e-4, w, h)).reshape(2, 3)  # a flat tuple converts faster
    cap = Region(("cap",), box)
    return Part(sem, template, prims,
                anchors={"front": (x, 0.0, 0.0), "back": (-stand, 0.0, 0.0), "stop": (-stand + travel, 0.0, 0.0)},
                regions={"press": cap, "push": cap}, actionable=act)


def _stand_depth(p, reach, travel):
    tr = p.uniform("travel", 0.003, 0.006, fixed=travel)
    stand = tr + p.uniform("clearance", 0.001, 0.002)
    d = p.uniform("depth", 0.004, 0.01) if reach is None else p.uniform("depth", 0, 0, fixed=reach - stand)
    return tr, stand, d


def rect_button(p, width: float | None = None, height: float | None = None, reach: float | None = None,
                travel: float | None = None) -> Part:
    """Rectangular push-button cap (keypads, door-release buttons).

    ``reach`` (metres) is how far the cap's front stands off the mount surface (a
    caller with a keypad well sets it to the well depth plus the proud height).
    """
    w = p.uniform("width", 0.012, 0.03, fixed=width)
    h = p.uniform("height", 0.008, 0.02, fixed=height)
    tr, stand, d = _stand_depth(p, reach, travel)
    prim = cuboid(d, w, h, translation(-stand - d / 2, 0, 0), role="cap")
    return _button_part("rect_button", [prim], stand, d, tr, (w, h))


def round_button(p, radius: float | None = None, reach: float | None = None, travel: float | None = None) -> Part:
    """Round push-button cap, optionally with a bevelled face (``reach`` as in :func:`rect_button`)."""
    r = p.uniform("radius", 0.005, 0.012, fixed=radius)
    tr, stand, d = _stand_depth(p, reach, travel)
    prim = _x_disc(r, r * p.uniform("bevel", 0.8, 1.0), -stand, -stand - d, "cap")
    return _button_part("round_button", [prim], stand, d, tr, (2 * r, 2 * r))


BUTTONS = {rect_button: 2.0, round_button: 1.0}


def button_bezel(p, button: Part, gap: float | None = None) -> Part:
    """Collar around a push button's cap, for the parent link at the button's mount pose.

    The collar stands from the surface (x = 0) to a little past the cap's back face,
    ``gap`` (< 2 mm) around the cap, so the button touches it at rest and slides in it.
    """
    g = p.uniform("gap", 0.0005, 0.0015, fixed=gap)
    wall = p.uniform("wall", 0.0015, 0.003)
    prim = button.primitives[0]
    back, front = -button.anchors["back"][0], -button.anchors["front"][0]
    depth = back + p.uniform("cover", 0.2, 0.5) * (front - back)
    T = _ALONG_X.copy()  # translation(-depth / 2, 0, 0) @ _ALONG_X, bit for bit
    T[0, 3] = -depth / 2
    if prim.geom is BOX:
        _, w, h = prim.params[:3]
        ring_ = rect_ring(h + 2 * (g + wall), w + 2 * (g + wall), depth, h + 2 * g, w + 2 * g, T, role="bezel")
    else:
        r = float(prim.geom.bounds(prim.params)[1, 0])  # the largest radius
        ring_ = ring(r + g + wall, r + g, depth, pose=T, role="bezel")
    return Part("panel", "button_bezel", [ring_], anchors={"front": (-depth, 0.0, 0.0)})


def rocker_switch(p, width: float | None = None, height: float | None = None) -> Part:
    """Rocker: a cap that tilts about the vertical axis through its centre.

    Anchor ``edge_+y`` is the back edge of the cap; :func:`mount_rocker` derives the
    largest tilt that keeps the back edges off the surface from it.
    """
    w = p.uniform("width", 0.012, 0.025, fixed=width)
    h = p.uniform("height", 0.015, 0.03, fixed=height)
    d = p.uniform("depth", 0.006, 0.01)
    stand = p.uniform("stand_off", 0.002, 0.004)
    part = _button_part("rocker_switch", [cuboid(d, w, h, translation(-stand - d / 2, 0, 0), role="cap")],
                        stand, d, 0.0, (w, h), sem="switch", act="none")
    part.anchors["edge_+y"] = (-stand, w / 2, 0.0)
    return part


def rocker_tilt(part) -> float:
    """Largest safe tilt (radians) of a rocker cap: 0.9 atan(stand-off / half width)."""
    x, y, _ = part.anchors["edge_+y"]
    return 0.9 * math.atan(-x / y)


def mount_poses(pose: np.ndarray, yz) -> list:
    """Mount frames ``pose @ translation(0, y, z)`` for every (y, z) of ``yz`` (metres).

    ``pose`` (4, 4) is a panel's front frame; the controls laid out on it get the frames
    from one stacked product. Returns a list of (4, 4) arrays (views of one stack).
    """
    n = len(yz)
    T = _EYES[:n].copy() if n <= len(_EYES) else np.tile(_EYES[0], (n, 1, 1))
    if not n:
        return []
    T[:, 1:3, 3] = yz
    return list(pose @ T)


def mount_knob(builder, parent, part, pose: np.ndarray, *, continuous: bool, limits=(0.0, 2 * math.pi),
               name: str = "knob"):
    """Attach ``part`` on a knob joint about the mount frame's +x (see module docstring)."""
    link = builder.create_link(name, parent)
    link.set_joint("continuous" if continuous else "revolute", pose, axis=(1.0, 0.0, 0.0), limits=limits)
    link.add(part)
    return link


def mount_button(builder, parent, part, pose: np.ndarray, name: str = "button"):
    """Attach a push button on a prismatic joint along the mount frame's +x."""
    travel = float(part.anchors["stop"][0] - part.anchors["back"][0])
    link = builder.create_link(name, parent)
    link.set_joint("prismatic", pose, axis=(1.0, 0.0, 0.0), limits=(0.0, travel))
    link.add(part)
    return link


def mount_keypad(builder, parent, key: Part, pose: np.ndarray, rows: int, cols: int, pitch: tuple[float, float],
                 collar: Part | None = None, name: str = "button") -> list:
    """Mount copies of ``key`` (and of its ``collar``) on a ``rows`` x ``cols`` grid.

    ``pose`` is the mount frame of the grid's centre; ``pitch`` = (dy, dz) the spacing in
    metres; row 0 is the top row. Returns the button links, row by row.
    """
    links = []
    grid = [((c - (cols - 1) / 2) * pitch[0], ((rows - 1) / 2 - r) * pitch[1])
            for r in range(rows) for c in range(cols)]
    for T in mount_poses(pose, grid):
        if collar is not None:
            parent.add(_copy(collar), T)
        links.append(mount_button(builder, parent, _copy(key), T, name=name))
    return links


def _copy(part: Part) -> Part:
    """A new part sharing the template knowledge of ``part`` (its name, pose and
    parameter span are set when it is added): what ``dataclasses.replace(part)``
    gives, a few times cheaper, which counts on 12-20 keys."""
    return Part(part.semantic, part.template, part.primitives, part.anchors, part.regions, part.canonical, part.size,
                part.grasp_source(), part.actionable)


def mount_rocker(builder, parent, part, pose: np.ndarray, name: str = "switch"):
    """Attach a rocker switch: revolute about the mount frame's +z, rest tilted by -tilt."""
    tilt = rocker_tilt(part)
    link = builder.create_link(name, parent)
    link.set_joint("revolute", pose @ rot_z(-tilt), axis=(0.0, 0.0, 1.0), limits=(0.0, 2 * tilt))
    link.add(part)
    return link


def mount_button_row(p, builder, root, tmpl, k: int, pose, y_lo: float, y_hi: float, z: float,
                     radius: float, square: tuple[float, float]) -> None:
    """Mount ``k`` bezelled push buttons of template ``tmpl`` evenly along y in
    [y_lo, y_hi] at height ``z`` of a panel whose front frame is ``pose``.

    Round buttons get ``radius``, others ``square`` = (width, height), metres.
    Parameters are drawn under ``button<i>``.
    """
    poses = mount_poses(pose, [(y_lo + (y_hi - y_lo) * (i + 0.5) / k, z) for i in range(k)])
    for i, T in enumerate(poses):
        q = p.scope(f"button{i}")
        b = tmpl(q, radius=radius) if tmpl.__name__ == "round_button" else tmpl(q, width=square[0], height=square[1])
        root.add(button_bezel(q.scope("bezel"), b, gap=0.0006), T)
        mount_button(builder, root, b, T)
