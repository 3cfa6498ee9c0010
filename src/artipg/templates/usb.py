"""USB flash drive parts: bodies, connectors, the cap, the swivel cover and the
retractable sleeve with its sliding carriage.

Frames (metres): the drive lies flat, its long axis along x with the connector
towards -x, +z up, centred on z = 0 through its thickness.
- bodies: origin at the centre of the body's front face (x = 0), the body extends
  to +x; anchors ``size`` (length, width, thickness) and ``back``;
- connectors: origin at the centre of their back end, extending to -x; anchor
  ``size`` (length, width, thickness);
- ``usb_cap``: origin at the centre of its open back end, extending to -x;
- ``swivel_cover``: origin on the pivot axis (z) at the body's mid-thickness;
- ``sleeve``: origin at the centre of its open front end, extending to +x; anchor
  ``cavity`` (length, width, height of the inside) and ``slot`` (x range, width);
- ``carriage``: origin at the centre of its front face (where the connector joins).
"""

from __future__ import annotations

import math

from artipg.geometry import cuboid_between, cylinder, rect_ring, torus
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part, Region

GAP = 0.0005  # clearance of box-shaped parts sliding or turning on each other
_ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x (rect_ring: ox along z, oy along y)
_GRIP = Region(("body",))


def _body(template, prims, L, w, t) -> Part:
    return Part("body", template, prims, anchors={"size": (L, w, t), "back": (L, 0.0, 0.0)},
                regions={"grasp": _GRIP, "lift": _GRIP})


def box_body(p, length: float, width: float, thickness: float) -> Part:
    """Plain rectangular body."""
    return _body("box_body", [cuboid_between((0.0, -width / 2, -thickness / 2), (length, width / 2, thickness / 2),
                                             role="body")], length, width, thickness)


def stadium_body(p, length: float, width: float, thickness: float) -> Part:
    """Body with a round back end (half a disc as wide as the body)."""
    r = width / 2
    return _body("stadium_body", [cuboid_between((0.0, -r, -thickness / 2), (length - r, r, thickness / 2), role="body"),
                                  cylinder(r, thickness, translation(length - r, 0, 0), role="body")],
                 length, width, thickness)


def keyring_body(p, length: float, width: float, thickness: float) -> Part:
    """Rectangular body with a key-ring loop at its back end."""
    rl = p.uniform("loop_radius", 0.003, 0.005)
    rw = p.uniform("loop_wire", 0.0008, 0.0014)
    prims = [cuboid_between((0.0, -width / 2, -thickness / 2), (length, width / 2, thickness / 2), role="body"),
             torus(rl, rw, pose=translation(length + rl - rw, 0, 0), role="loop")]
    part = _body("keyring_body", prims, length, width, thickness)
    part.anchors["back"] = (length + 2 * rl, 0.0, 0.0)
    return part


BODIES = {box_body: 2.0, stadium_body: 1.5, keyring_body: 1.0}


def _connector(template, L, w, t, wall, tongue) -> Part:
    prims = [rect_ring(t, w, L, t - 2 * wall, w - 2 * wall, _ALONG_X.at(-L / 2, 0, 0), role="shell"),
             cuboid_between((-L + 0.0015, -w / 2 + wall, -tongue / 2 - 0.0006), (0.0, w / 2 - wall, tongue / 2 - 0.0006),
                            role="tongue")]
    return Part("connector", template, prims, anchors={"size": (L, w, t)}, regions={"grasp": Region(("shell",))})


def usb_a(p) -> Part:
    """USB-A plug: a 12 x 4.5 mm steel shell with a plastic tongue inside."""
    return _connector("usb_a", p.uniform("length", 0.011, 0.0125), 0.012, 0.0045, 0.0003, 0.0018)


def usb_c(p) -> Part:
    """USB-C plug: an 8.3 x 2.5 mm shell with a thin tongue."""
    return _connector("usb_c", p.uniform("length", 0.0065, 0.0075), 0.0083, 0.0025, 0.0003, 0.0007)


CONNECTORS = {usb_a: 3.0, usb_c: 1.0}


def usb_cap(p, conn, width: float, thickness: float) -> Part:
    """Cap over a connector of size ``conn`` (length, width, thickness), as wide and
    thick as the body, closed at the front."""
    L, wc, tc = conn
    end = p.uniform("end", 0.001, 0.002)
    ix, iy = tc + 2 * GAP, wc + 2 * GAP
    prims = [rect_ring(thickness, width, L + GAP, ix, iy, _ALONG_X.at(-(L + GAP) / 2, 0, 0), role="shell"),
             cuboid_between((-L - GAP - end, -width / 2, -thickness / 2), (-L - GAP, width / 2, thickness / 2),
                            role="end")]
    grip = Region(("shell", "end"))
    return Part("cap", "usb_cap", prims, regions={"grasp": grip, "pull": grip}, actionable="slider_lid")


def swivel_cover(p, reach: float, width: float, thickness: float, back: float) -> Part:
    """U-shaped metal strap turning about the pivot: a plate over and under the body
    from ``back`` behind the pivot to ``reach`` in front of it (-x), joined by a
    bridge at the front, with a rivet head on top."""
    tp = p.uniform("plate", 0.0005, 0.0008)
    z0 = thickness / 2 + GAP
    prims = [cuboid_between((-reach, -width / 2, s0), (back, width / 2, s1), role="plate")
             for s0, s1 in ((z0, z0 + tp), (-z0 - tp, -z0))]
    prims.append(cuboid_between((-reach - tp, -width / 2, -z0 - tp), (-reach, width / 2, z0 + tp), role="bridge"))
    rr = p.uniform("rivet", 0.002, 0.003)
    prims.append(cylinder(rr, 0.0006, translation(0, 0, z0 + tp + 0.0003), role="rivet"))
    grip = Region(("bridge", "plate"))
    return Part("cover", "swivel_cover", prims, regions={"grasp": grip, "push": grip, "rotate": grip},
                actionable="hinge_lid")


def sleeve(p, length: float, width: float, thickness: float, slot: tuple) -> Part:
    """Hollow body open at the front, with a slot (x0, x1, width) along the top."""
    wall = p.uniform("wall", 0.0012, 0.0018)
    W, T = width / 2, thickness / 2
    x0, x1, sw = slot
    prims = [cuboid_between((0.0, -W, -T), (length, W, -T + wall), role="body"),
             cuboid_between((0.0, -W, -T + wall), (length, -W + wall, T - wall), role="body"),
             cuboid_between((0.0, W - wall, -T + wall), (length, W, T - wall), role="body"),
             cuboid_between((length - wall, -W + wall, -T + wall), (length, W - wall, T - wall), role="body"),
             cuboid_between((0.0, -W, T - wall), (x0, W, T), role="body"),
             cuboid_between((x1, -W, T - wall), (length, W, T), role="body"),
             cuboid_between((x0, -W, T - wall), (x1, -sw / 2, T), role="body"),
             cuboid_between((x0, sw / 2, T - wall), (x1, W, T), role="body")]
    return Part("body", "sleeve", prims, anchors={"cavity": (length - wall, width - 2 * wall, thickness - 2 * wall),
                                                  "wall": (wall, 0.0, 0.0)},
                regions={"grasp": _GRIP, "lift": _GRIP})


def carriage(p, length: float, width: float, height: float, tab: tuple) -> Part:
    """Block sliding in the sleeve (origin at its front face), carrying the connector,
    with a thumb tab (x offset from the front, width, rise above the block) up
    through the sleeve's slot: ``tab`` is (x offset from the front, length, width,
    rise above the block)."""
    xt, tl, tw, rise = tab
    prims = [cuboid_between((0.0, -width / 2, -height / 2), (length, width / 2, height / 2), role="block"),
             cuboid_between((xt - tl / 2, -tw / 2, height / 2), (xt + tl / 2, tw / 2, height / 2 + rise), role="tab")]
    return Part("connector", "carriage", prims,
                regions={"push": Region(("tab",)), "pull": Region(("tab",))}, actionable="slider_drawer")
