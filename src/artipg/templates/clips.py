"""Clip parts: a binder clip's folded steel body and wire levers, and the two legs of
a spring-pivot clip (clothes peg, bag clip) with their spring coil.

Binder body frame: the spine on z = 0 (``spine`` wide along x, centred), the two
side plates rising and meeting at the mouth at z = ``height``, the clip ``width``
long along y; a rolled edge (curl) along y at each side of the mouth, centred at
x = +-``curl_x(...)``, z = ``height`` (anchors ``pivot_+x`` / ``pivot_-x``).
Lever frame: origin on the pivot axis (+y), the wire loop standing up along +z in the
y-z plane, its legs starting outside the body (``half`` + bend radius off the
middle), their bent ends running inward along the axis into the curl; anchor
``grip`` = the loop's top bar. Regions ``grasp`` / ``push`` on the wire.

Leg frame (spring clips, lying on a side face): the pivot (the spring coil's axis,
+z) at the origin on the contact plane y = 0; the jaw reaches to x = -``jaw`` (the
front), the handle to x = +``handle``; the legs are ``width`` tall along z (centred);
the lower leg fills -T <= y <= 0 (``side`` = -1), the upper leg 0 <= y <= T
(``side`` = +1), both moved ``FACE_GAP`` off y = 0; the handle's inner face leaves
the contact plane at a slope ``taper`` behind the pivot, and a square slot of
half-width ``notch`` round the pivot holds the coil. Regions: ``grasp`` / ``press`` on the handle (role ``grip``). Metres.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid_between, cylinder, ring, tube
from artipg.geometry import profile
from artipg.geometry.extrusion import extrusion
from artipg.geometry.transforms import Placer, rot_x, rot_z, translation
from artipg.geometry.tube import arc, line
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.levers import top_grasp

CURL_CLEAR = 0.0015   # radial clearance of a lever's wire in its curl (simulators: >= 0.8 mm, thin wires more)
COIL_CLEAR = 0.0009   # radial clearance of the spring coil in a moving leg's notch
FACE_GAP = 0.0004     # each leg's inner face off the contact plane (closed jaws nearly touch)
_Y = Placer(rot_x(-math.pi / 2))   # local z -> +y (cylinders and rings along y)
_XZ = rot_x(math.pi / 2)           # outline (x, y) -> object (x, z), extruded along y
_QUARTER = rot_z(math.pi / 2)      # a tube's path plane x -> +y


def curl_x(t: float, wire: float) -> float:
    """x of a binder curl's axis: the curl (inner radius ``wire + CURL_CLEAR``, sheet
    ``t``) rolled outward from the plate's outer face at the mouth."""
    return t + wire + CURL_CLEAR


def binder_body(p, width: float, spine: float, height: float, t: float, wire: float) -> Part:
    """Folded sheet of a binder clip: spine, two side plates pressed together at the
    mouth (a triangular tube, extruded along y) and the two curls."""
    slope = (spine / 2 - t) / height  # of the plates' outer faces (dx / dz)
    a = t * math.sqrt(1.0 + slope * slope)  # plate thickness measured along x
    outer = profile.polygon([(-spine / 2, 0.0), (spine / 2, 0.0), (t, height), (-t, height)])
    za = height - max((a - t) / slope, 2 * t)  # the plates' inner faces meet below the mouth
    hx = (za - t) * slope
    hole = profile.polygon([(-hx, t), (0.0, za), (hx, t)])
    prims = [extrusion([outer, hole], width, pose=_XZ, role="plate")]
    ri = wire + CURL_CLEAR
    xc = curl_x(t, wire)
    prims += [ring(ri + t, ri, width, pose=_Y.at(s * xc, 0.0, height), role="curl") for s in (1.0, -1.0)]
    return Part("body", "binder_body", prims,
                anchors={"pivot_+x": (xc, 0.0, height), "pivot_-x": (-xc, 0.0, height)},
                regions={"grasp": Region(("plate",))})


def _lever(template: str, wire: float, half: float, reach: float, corner: float, bend: float, insert: float,
           lean: float, opens: float) -> Part:
    """A U-shaped wire lever (see module docstring): bent ends ``insert`` long on the
    axis out to y = +-``half``, bends of radius ``bend`` into legs leaning inward by
    ``lean`` (rad), corners of radius ``corner`` and the grip bar at z = ``reach``;
    opening moves the bar along x by the sign of ``opens``."""
    cl, sl = math.cos(lean), math.sin(lean)
    leg = (reach - bend * (1.0 + sl) - corner * (1.0 - sl)) / cl
    top = 2.0 * (half + bend * cl - leg * sl - corner * cl)
    segs = [line(insert), arc(bend, -(math.pi / 2 + lean)), line(leg), arc(corner, -(math.pi / 2 - lean))]
    if top > 1e-5:
        segs.append(line(top))
    segs += [arc(corner, -(math.pi / 2 - lean)), line(leg), arc(bend, -(math.pi / 2 + lean)), line(insert)]
    prims = tube(wire, segs, heading=math.pi, pose=_QUARTER @ translation(-(half - insert), 0.0, 0.0), role="wire")
    return Part("lever", template, prims, anchors={"grip": (0.0, 0.0, reach)},
                regions={"grasp": Region(("wire",)), "push": Region(("wire",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, reach - wire, 2 * wire + 0.02, "x", (opens, 0.0, 0.0)),
                actionable="hinge_handle")


def square_lever(p, wire: float, half: float, reach: float, insert: float, opens: float) -> Part:
    """Wire lever whose legs lean inward to a straight grip bar (a trapezoid loop with
    rounded corners). ``half``: half-width of the axis ends (the curl's half length
    plus the end gap)."""
    bend = p.uniform("bend", 1.5, 2.5) * wire
    corner = p.uniform("corner", 0.15, 0.3) * half
    return _lever("square_lever", wire, half, reach, corner, bend, insert, p.uniform("lean", 0.06, 0.2), opens)


def round_lever(p, wire: float, half: float, reach: float, insert: float, opens: float) -> Part:
    """Wire lever with straight legs and a round (semicircular) top."""
    bend = p.uniform("bend", 1.5, 2.5) * wire
    return _lever("round_lever", wire, half, reach, half + bend, bend, insert, 0.0, opens)


LEVERS = {square_lever: 3.0, round_lever: 1.0}


# ---------------------------------------------------------------- spring-pivot legs
def _leg_outlines(kind: str, jaw: float, handle: float, T: float, taper: float, notch: float, end: float,
                  groove: float) -> list[tuple[np.ndarray, str]]:
    """Convex outlines (x, y) of a lower leg (y <= 0) with their roles: the jaw, the
    block under the square slot (half-width ``notch``) that holds the coil, and the
    handle, ``end`` thick at its end, its inner face sloping ``taper`` from the pivot.
    ``kind`` "square", "rounded" or "flared" shapes the ends and the handle's outer
    face; a ``groove`` > 0 (radius) cuts the line groove across the jaw's inner face.
    Convex pieces keep the simulators' collision pieces whole (no thin slivers)."""
    k = math.tan(taper)
    zi = -handle * k  # inner face at the handle's end
    zo = zi - end  # outer face there

    def z_out(x):
        return -T + (zo + T) * (x - notch) / (handle - notch)

    tip = {"rounded": [(-jaw, -0.6 * T), (-jaw + 0.4 * T, -T)], "flared": [(-jaw, -0.8 * T), (-jaw + 0.1 * T, -T)]}
    front = tip.get(kind, [(-jaw, -T)])
    x0 = -jaw  # the jaw, cut in three at the groove
    pieces = []
    if groove > 0:
        xg = -0.65 * jaw
        pieces.append((profile.polygon([*front, (xg - groove, -T), (xg - groove, 0.0), (x0, 0.0)]), "jaw"))
        pieces.append((profile.polygon([(xg - groove, -T), (xg + groove, -T), (xg + groove, -0.85 * groove),
                                        (xg - groove, -0.85 * groove)]), "jaw"))
        front, x0 = [(xg + groove, -T)], xg + groove
    pieces.append((profile.polygon([*front, (-notch, -T), (-notch, 0.0), (x0, 0.0)]), "jaw"))
    pieces.append((profile.polygon([(-notch, -T), (notch, -T), (notch, -notch), (-notch, -notch)]), "grip"))
    xi = -notch * k
    if kind == "flared":  # the outer face flares at the end (two pieces: each convex)
        xm = 0.5 * (notch + handle)
        ym, yi = z_out(xm), -xm * k
        pieces.append((profile.polygon([(notch, -T), (xm, ym), (xm, yi), (notch, xi)]), "grip"))
        pieces.append((profile.polygon([(xm, ym), (handle, zo - 0.3 * T), (handle, zi), (xm, yi)]), "grip"))
    elif kind == "rounded":
        e = 0.45 * end
        pieces.append((profile.polygon([(notch, -T), (handle - e, z_out(handle - e)), (handle, zo + e), (handle, zi),
                                        (notch, xi)]), "grip"))
    else:
        pieces.append((profile.polygon([(notch, -T), (handle, zo), (handle, zi), (notch, xi)]), "grip"))
    return pieces


def spring_leg(kind: str, semantic: str, side: float, jaw: float, handle: float, width: float, T: float,
               taper: float, notch: float, end: float, groove: float, moving: bool) -> Part:
    """One leg of a spring clip (see module docstring), ``width`` tall along z,
    ``T`` thick at the pivot and ``end`` at the handle's end, with a line groove of
    radius ``groove`` (0: none) in the jaw."""
    pieces = _leg_outlines(kind, jaw, handle, T, taper, notch, end, groove)
    # off the contact plane by FACE_GAP, mirrored for the upper leg (the extrusion orients the loops)
    prims = [_piece(np.column_stack([l[:, 0], -side * (l[:, 1] - FACE_GAP)]), width, role) for l, role in pieces]
    # from outside the leg, jaws closing along z across the leg's width (both legs
    # pass between the fingers); the handle opens towards the other leg
    xg = 0.6 * handle
    yg = side * (FACE_GAP + T + (handle * math.tan(taper) + end - T) * (xg - notch) / (handle - notch))
    g = Deferred(_side_grasp, xg, yg, side, width + 0.02)
    return Part(semantic, f"{kind}_leg", prims, regions={"grasp": Region(("grip",)), "press": Region(("grip",))},
                grasps=g, actionable="hinge_handle" if moving else "none")


def _piece(pts: np.ndarray, width: float, role: str):
    """An outline (n, 2) extruded ``width`` along z: a box where it is an axis-aligned
    rectangle (the cheaper primitive), else an extrusion."""
    xs, ys = np.unique(pts[:, 0]), np.unique(pts[:, 1])
    if len(pts) == 4 and len(xs) == 2 and len(ys) == 2:
        return cuboid_between((xs[0], ys[0], -width / 2), (xs[1], ys[1], width / 2), role=role)
    return extrusion([profile.polygon(pts)], width, role=role)


def _side_grasp(x: float, y: float, side: float, width: float) -> list[Grasp]:
    """A grasp approaching along -``side`` y at (x, y, 0), jaws closing along z; the
    point opens along the tangent of its circle about the pivot."""
    T = np.array([[side, 0.0, 0.0, x], [0.0, 0.0, -side, y], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
    return [Grasp(T, width, np.array([side * y, -side * x, 0.0]) / math.hypot(x, y))]


def coil(radius: float, width: float) -> Part:
    """The spring coil along z through the pivot (``width`` long)."""
    return Part("hinge", "spring_coil", [cylinder(radius, width, role="coil")])


LEG_SHAPES = {"square": 2.0, "rounded": 2.0, "flared": 1.0}
