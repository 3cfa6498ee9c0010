"""Coffee-machine parts: the housing with its front bay, drip trays, carafes, top lids,
portafilters, steam wands, capsule levers and water tanks.

Frames:
- ``coffee_housing``: the object frame (front at x = -depth / 2 facing -x, floor z = 0,
  centred on the z axis). The front *bay* (where the cup or carafe stands) is
  ``bay`` deep, between the plinth top ``floor`` and the head's underside ``roof``.
- ``drip_tray``, ``water_tank``: origin at the centre of the part's front bottom edge,
  the part extends along +x and up +z (slide them with a prismatic joint).
- ``swing_basket``: front-panel convention (back face on x = 0, the cup behind it).
- ``carafe``: origin at the centre of its base, +z up; the handle faces -x.
- ``top_lid``, ``capsule_lever``: the hinge frame, origin on the hinge axis (+y) at
  the back edge, the part extends along -x from it; positive rotation lifts the front.
- ``portafilter``: origin on the group-head axis (+z) at the basket's rim, the basket
  hangs below it and the handle reaches along -x.
- ``steam_wand``: origin at the pivot, the wand hangs along -z; its joint axis is +x.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, sphere
from artipg.geometry.lathe import lathe
from artipg.geometry.transforms import rot_y, translation
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.handles import front_grasp
from artipg.templates.panels import door_edge_grasps

# gripper approaching +x (a slab's front edge), jaws closing along z (pinch)
_EDGE = np.array([[0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
# gripper approaching -z (from above), jaws closing along y
_DOWN = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, -1.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 0.0, 0.0, 1.0]])
_UP = np.array([0.0, 0.0, 1.0])


def coffee_housing(p, depth: float, width: float, height: float, bay: float, floor: float, roof: float,
                   cavity: tuple[float, float] | None = None) -> Part:
    """Housing: a back tower, a plinth under the front bay and a head over it.

    ``cavity`` = (height, width) opens a slot in the head's front, ``bay`` deep, for a
    filter drawer (its floor 8-12 mm above ``roof``). Anchors: ``front`` (-depth / 2),
    ``bay_back`` (x of the tower's front face), ``floor``, ``roof``, ``cavity_lo`` /
    ``cavity_hi`` (corners of the cavity).
    """
    D, W = depth / 2, width / 2
    xb = -D + bay
    prims = [cuboid_between((xb, -W, 0.0), (D, W, height), role="tower"),
             cuboid_between((-D, -W, 0.0), (xb, W, floor), role="plinth")]
    anchors = {"front": (-D, 0.0, 0.0), "bay_back": (xb, 0.0, 0.0), "floor": (0.0, 0.0, floor),
               "roof": (0.0, 0.0, roof)}
    if cavity is None:
        prims.append(cuboid_between((-D, -W, roof), (xb, W, height), role="head"))
    else:
        ch, cw = cavity
        z0 = roof + p.uniform("cavity_floor", 0.008, 0.012)
        z1 = min(z0 + ch, height - 0.008)
        prims += [cuboid_between((-D, -W, roof), (xb, W, z0), role="head"),
                  cuboid_between((-D, -W, z1), (xb, W, height), role="head"),
                  cuboid_between((-D, -W, z0), (xb, -cw / 2, z1), role="head"),
                  cuboid_between((-D, cw / 2, z0), (xb, W, z1), role="head")]
        anchors.update(cavity_lo=(-D, -cw / 2, z0), cavity_hi=(xb, cw / 2, z1))
    return Part("body", "coffee_housing", prims, anchors=anchors,
                regions={"grasp": Region(("tower",)), "lift": Region(("tower",))})


def drip_tray(p, depth: float, width: float, height: float) -> Part:
    """Drip tray: a box ``depth`` x ``width`` x ``height`` under a grille 2-4 mm proud
    of it, the grille 80-90 % of its footprint; a finger lip on the front face."""
    g = p.uniform("grille", 0.002, 0.004)
    f = p.uniform("grille_share", 0.8, 0.9)
    lip = p.uniform("lip", 0.008, 0.012)
    prims = [cuboid_between((0.0, -width / 2, 0.0), (depth, width / 2, height - g), role="box"),
             cuboid(f * depth, f * width, g, translation(depth / 2, 0, height - g / 2), role="grille"),
             cuboid_between((-lip, -0.3 * width, 0.3 * height), (0.0, 0.3 * width, 0.7 * height), role="lip")]
    return Part("tray", "drip_tray", prims, anchors={"front": (-lip, 0.0, height / 2), "top": (0.0, 0.0, height)},
                regions={"pull": Region(("lip", "box")), "push": Region(("box",)), "grasp": Region(("lip",))},
                grasps=Deferred.one(_pinch, -lip + 0.002, 0.0, height / 2, 0.4 * height),
                actionable="slider_drawer")


def _pinch(x: float, y: float, z: float, t: float) -> Grasp:
    T = _EDGE.copy()
    T[0, 3], T[1, 3], T[2, 3] = x, y, z
    return Grasp(T, t + 0.02, _UP)


def _top_pinch(x: float, z: float, t: float) -> Grasp:
    """A grasp from above on a fin ``t`` thick across x at (x, 0), tips at height z."""
    G = _DOWN.copy()
    G[:3, :3] = ((0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, -1.0))  # jaws closing along x
    G[0, 3], G[2, 3] = x, z
    return Grasp(G, t + 0.02, _UP)


def top_lid(p, depth: float, width: float) -> Part:
    """Flat lid (water-tank or filter lid) ``depth`` x ``width``, 6-14 mm thick, its top
    face on the hinge plane (z = 0; it turns about its top back edge, so no point dips
    below its rest underside), with a finger fin standing on its front edge.
    Anchor ``bottom`` is its underside."""
    t = p.uniform("thickness", 0.006, 0.014)
    fh, ft = p.uniform("fin_height", 0.008, 0.015), p.uniform("fin_thickness", 0.005, 0.008)
    fw = p.uniform("fin_width", 0.3, 0.6) * width
    prims = [cuboid_between((-depth, -width / 2, -t), (0.0, width / 2, 0.0), role="slab"),
             cuboid_between((-depth, -fw / 2, 0.0), (-depth + ft, fw / 2, fh), role="fin")]
    box = np.array([[-depth - 1e-3, -fw / 2, -t - 1e-3], [-depth + 0.03, fw / 2, fh + 1e-3]])
    return Part("lid", "top_lid", prims, anchors={"front": (-depth, 0.0, -t / 2), "bottom": (0.0, 0.0, -t)},
                regions={"lift": Region(("slab", "fin"), box), "grasp": Region(("fin",))},
                grasps=Deferred.one(_top_pinch, -depth + ft / 2, 0.5 * fh, ft),
                actionable="hinge_lid")


def swing_basket(p, width: float, height: float, radius: float) -> Part:
    """Swing-out filter basket: a front panel ``width`` x ``height`` (front-panel
    convention, 8-14 mm thick) carrying a round filter cup of ``radius`` behind it
    (x > 0), 2-4 mm inside the panel's outline in z. Hinge it on a side edge."""
    t = p.uniform("thickness", 0.008, 0.014)
    hc = height - 2 * p.uniform("cup_inset", 0.004, 0.006)
    prims = [cuboid(t, width, height, translation(-t / 2, 0, 0), role="panel"),
             cylinder(radius, hc, translation(radius + 0.001, 0, 0), role="cup")]
    front = np.array([[-t - 1e-4, -width / 2, -height / 2], [-t + 1e-4, width / 2, height / 2]])
    return Part("drawer", "swing_basket", prims,
                anchors={"front": (-t, 0.0, 0.0), "edge_+y": (-t, width / 2, 0.0), "edge_-y": (-t, -width / 2, 0.0)},
                regions={"push": Region(("panel",), front), "pull": Region(("panel",), front)},
                grasps=Deferred(door_edge_grasps, t, width, height), actionable="hinge_door")


def carafe(p, radius: float, height: float) -> Part:
    """Glass carafe: a tapered jug (wall 2.5-4 mm) with a lid disc and a handle on its
    -x side. ``radius`` is its largest radius (at the base), ``height`` its full height."""
    w = p.uniform("wall", 0.0025, 0.004)
    rt = p.uniform("neck", 0.7, 0.9) * radius
    lt = p.uniform("lid", 0.008, 0.015)
    hj = height - lt
    # a base disc and the wall, a thin conical ring open at the top
    loop = np.array([[radius, w, 0.0], [rt, hj, 0.0], [rt - w, hj, 0.0], [radius - w, w, 0.0]])
    prims = [cylinder(radius, w, translation(0, 0, w / 2), role="jug"), lathe(loop, role="jug")]
    prims.append(cylinder(rt + 0.002, lt, translation(0, 0, hj + lt / 2), role="lid"))
    hw = p.uniform("handle_width", 0.012, 0.02)
    reach = p.uniform("handle_reach", 0.03, 0.045)
    z0, z1 = 0.3 * hj, 0.85 * hj
    xr = -0.5 * (radius + rt)  # the wall's mean radius under the handle
    bar = 0.008
    prims += [cuboid_between((xr - reach, -hw / 2, z0), (xr - reach + bar, hw / 2, z1), role="handle"),
              cuboid_between((xr - reach + bar, -hw / 2, z1 - bar), (xr + w, hw / 2, z1), role="handle"),
              cuboid_between((xr - reach + bar, -hw / 2, z0), (xr + w, hw / 2, z0 + bar), role="handle")]
    g = front_grasp(xr - reach + bar / 2, 0.0, 0.5 * (z0 + z1), hw + 0.02)
    return Part("container", "carafe", prims, anchors={"front": (xr - reach, 0.0, 0.0), "top": (0.0, 0.0, height)},
                regions={"grasp": Region(("handle",)), "pull": Region(("handle",)), "lift": Region(("handle",))},
                grasps=[g], actionable="line_fixed_handle")


def portafilter(p, radius: float, depth: float) -> Part:
    """Portafilter: a basket of ``radius`` and ``depth`` under the origin and a handle
    0.1-0.14 m long along -x, dipping 10-20 degrees."""
    L = p.uniform("handle_length", 0.1, 0.14)
    rh = p.uniform("handle_radius", 0.01, 0.015)
    dip = p.uniform("dip", 0.17, 0.35)
    lug = p.uniform("lug", 0.004, 0.008)
    prims = [cylinder(radius, depth, translation(0, 0, -depth / 2), role="basket"),
             cuboid(2 * (radius + lug), 0.012, 0.006, translation(0, 0, -0.003), role="basket")]
    c, s = math.cos(dip), math.sin(dip)
    T = translation(-radius - L / 2 * c, 0, -depth / 2 - L / 2 * s) @ rot_y(math.pi / 2 - dip)
    prims.append(cylinder(rh, L, T, role="handle"))
    xg, zg = -radius - 0.9 * L * c, -depth / 2 - 0.9 * L * s  # near its end
    # approaching -y (from the side it turns away from), jaws closing along z
    G = np.array([[1.0, 0.0, 0.0, xg], [0.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, zg], [0.0, 0.0, 0.0, 1.0]])
    return Part("portafilter", "portafilter", prims, anchors={"tip": (-radius - L * c, 0.0, -depth / 2 - L * s)},
                regions={"grasp": Region(("handle",)), "rotate": Region(("handle",))},
                grasps=[Grasp(G, 2 * rh + 0.02)], actionable="hinge_handle")


def steam_wand(p, length: float, ball: float | None = None) -> Part:
    """Steam wand: a pivot ball (radius ``ball``) and a tube ``length`` long hanging
    along -z, its tip bent 20-40 degrees towards -x."""
    rb = p.uniform("ball", 0.008, 0.012, fixed=ball)
    r = p.uniform("tube_radius", 0.004, 0.006)
    tip = p.uniform("tip", 0.02, 0.035)
    bend = p.uniform("bend", 0.35, 0.7)
    L = length - tip
    prims = [sphere(rb, role="pivot"), cylinder(r, L, translation(0, 0, -L / 2), role="tube"),
             cylinder(r, tip, translation(-math.sin(bend) * tip / 2, 0, -L - math.cos(bend) * tip / 2)
                      @ rot_y(-bend), role="tube")]
    # approaching +x (from the front), jaws closing along y across the tube
    G = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, -0.6 * L], [0.0, 0.0, 0.0, 1.0]])
    return Part("nozzle", "steam_wand", prims, anchors={"tip": (0.0, 0.0, -length)},
                regions={"grasp": Region(("tube",))}, grasps=[Grasp(G, 2 * r + 0.02)])


def capsule_lever(p, length: float, width: float) -> Part:
    """Capsule lever: a plate ``length`` x ``width``, 8-14 mm thick, its top face on
    the hinge plane (z = 0), with a grip lip hanging 12-25 mm below the plate in front
    of the head (its back 2 mm ahead of x = -length). Anchor ``bottom``: the underside."""
    t = p.uniform("thickness", 0.008, 0.014)
    lt, lh = p.uniform("lip_thickness", 0.006, 0.01), p.uniform("lip_drop", 0.012, 0.025)
    x0 = -length - 0.002
    gap = -t
    prims = [cuboid_between((x0, -width / 2, gap), (0.0, width / 2, gap + t), role="plate"),
             cuboid_between((x0 - lt, -width / 2, gap + t - lh - t), (x0, width / 2, gap + t), role="grip")]
    return Part("lever", "capsule_lever", prims, anchors={"front": (x0 - lt, 0.0, gap), "bottom": (0.0, 0.0, -t)},
                regions={"grasp": Region(("grip",)), "lift": Region(("grip", "plate")), "pull": Region(("grip",))},
                grasps=Deferred.one(_pinch, x0 - lt + 0.005, 0.0, gap + t - (lh + t) / 2, lh + t),
                actionable="hinge_handle")


def water_tank(p, depth: float, width: float, height: float) -> Part:
    """Removable water tank: an open box (walls 2.5-4 mm) under a lid plate, with a
    carry grip on top at the back."""
    w = p.uniform("wall", 0.0025, 0.004)
    lt = p.uniform("lid", 0.004, 0.008)
    hb = height - lt
    prims = [cuboid_between((0.0, -width / 2, 0.0), (depth, width / 2, w), role="tank"),
             cuboid_between((0.0, -width / 2, w), (w, width / 2, hb), role="tank"),
             cuboid_between((depth - w, -width / 2, w), (depth, width / 2, hb), role="tank"),
             cuboid_between((w, -width / 2, w), (depth - w, -width / 2 + w, hb), role="tank"),
             cuboid_between((w, width / 2 - w, w), (depth - w, width / 2, hb), role="tank"),
             cuboid_between((0.0, -width / 2, hb), (depth, width / 2, height), role="lid")]
    gw = p.uniform("grip_width", 0.03, 0.05)
    gh = p.uniform("grip_height", 0.012, 0.02)
    prims.append(cuboid_between((0.55 * depth, -gw / 2, height), (0.55 * depth + 0.012, gw / 2, height + gh),
                                role="grip"))
    return Part("container", "water_tank", prims, anchors={"top": (0.0, 0.0, height + gh)},
                regions={"grasp": Region(("grip",)), "lift": Region(("grip",)), "pull": Region(("grip",))},
                grasps=Deferred.one(_top_pinch, 0.55 * depth + 0.006, height + 0.5 * gh, 0.012),
                actionable="line_fixed_handle")
