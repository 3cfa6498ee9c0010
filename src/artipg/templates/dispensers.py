"""Dispenser parts: oval bottle bodies, lotion pumps with locking heads, trigger
sprayers and wall-mounted soap dispensers.

Bodies (:func:`oval_body`) use the frame of :mod:`artipg.templates.bottles`: origin at
the centre of the base on z = 0, axis +z, anchors ``neck_top``, ``neck_edge``,
``bore_edge`` and ``neck_base``. Heads (:func:`lotion_pump`, :func:`trigger_sprayer`)
follow :mod:`artipg.templates.caps`: ``f(p, builder, parent, pose, neck, ...)`` builds
links on ``parent`` at ``pose`` (the neck-top frame, +z out of the neck, front -x) for
a neck ``(outer radius, bore radius, height)``. :func:`wall_dispenser` builds a whole
wall unit on the root link (back on the wall at +x).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, prism, ring, sphere
from artipg.geometry.extrusion import extrusion
from artipg.geometry.lathe import lathe
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.profile import polygon
from artipg.geometry.transforms import Placer, rot_x, rot_y, translation
from artipg.geometry.tube import arc, line, tube
from artipg.model.part import Deferred, Grasp, Part, Region
from artipg.templates.caps import CLEAR
from artipg.templates.levers import top_grasp

GAP = 0.002  # clearance (m) kept between moving parts and the parts they pass
_ALONG_X = Placer(rot_y(-math.pi / 2))  # local z -> -x
_ALONG_Y = Placer(rot_x(math.pi / 2))  # local z -> -y (an x-z outline extruded across y)


# sides of a trigger sprayer's nozzle cap: square, hexagonal or round
NOZZLE_SIDES = {4: 2.0, 6: 1.0, 16: 1.0}

def oval_body(p, radius: float, height: float, neck_r: float, neck_h: float, flat=(0.45, 0.8),
              across: bool = False) -> Part:
    """Flat bottle: a rounded box ``2 radius`` long (x, the way the head points; y with
    ``across``) and ``flat`` times that the other way, its edges rounded by up to 60 %
    of the half depth (a rounded plan and shoulders; the flat bottom keeps 40 % or more
    of the depth to stand on), and a neck ring sunk into the top. Frame and anchors as
    :mod:`artipg.templates.bottles`."""
    sx = 2 * radius
    sy = sx * p.uniform("flatness", *flat)
    if across:
        sx, sy = sy, sx
    hb = height - neck_h
    r = p.uniform("rounding", 0.35, 0.6) * min(sx, sy, hb) / 2
    t = p.uniform("neck_wall", 0.0018, 0.0032)
    sink = r * 0.6  # the neck starts inside the rounded top so it meets the dome
    prims = [rounded_box(sx, sy, hb, r, translation(0, 0, hb / 2), role="wall"),
             ring(neck_r, neck_r - t, neck_h + sink, pose=translation(0, 0, hb + (neck_h - sink) / 2), role="neck")]
    anchors = {"neck_top": (0.0, 0.0, height), "neck_edge": (neck_r, 0.0, height),
               "bore_edge": (neck_r - t, 0.0, height), "neck_base": (0.0, 0.0, hb)}
    return Part("body", "oval_body", prims, anchors=anchors,
                regions={"grasp": Region(("wall",)), "lift": Region(("wall",))})


def turned_body(p, radius: float, height: float, neck_r: float, neck_h: float) -> Part:
    """Round bottle turned from one lathe profile (no hidden discs inside it, unlike a
    stack of solids): a straight wall, then a conical or rounded shoulder up to the
    neck ring. Frame and anchors as :mod:`artipg.templates.bottles`."""
    hs = p.uniform("shoulder", 0.05, 0.4) * (height - neck_h)
    hb = height - neck_h - hs
    rt = neck_r + p.uniform("shoulder_top", 0.001, 0.004)
    bulge = p.uniform("shoulder_round", 0.2, 0.4) if p.flag("rounded", 0.5) else 0.0  # no near-straight arcs: slow
    loop = [(0.0, 0.0, 0.0), (radius, 0.0, 0.0), (radius, hb, bulge), (rt, hb + hs, 0.0), (0.0, hb + hs, 0.0)]
    t = p.uniform("neck_wall", 0.0018, 0.0032)
    prims = [lathe(loop, role="wall"),
             ring(neck_r, neck_r - t, neck_h + 0.002, pose=translation(0, 0, height - (neck_h + 0.002) / 2),
                  role="neck")]
    anchors = {"neck_top": (0.0, 0.0, height), "neck_edge": (neck_r, 0.0, height),
               "bore_edge": (neck_r - t, 0.0, height), "neck_base": (0.0, 0.0, hb + hs)}
    return Part("body", "turned_body", prims, anchors=anchors,
                regions={"grasp": Region(("wall",)), "lift": Region(("wall",))})


def _collar(p, neck, height=(0.012, 0.02), hole: float = 0.0):
    """Screw collar around the neck: a skirt and a top plate with a hole for the stem.
    Returns (part, top z, outer radius)."""
    rn, _, hn = neck
    t = p.uniform("collar_wall", 0.0015, 0.0025)
    hc = min(p.uniform("collar_height", *height), hn - 0.0035)
    tt = p.uniform("collar_top", 0.002, 0.003)
    ro = rn + CLEAR + t
    prims = [ring(ro, rn + CLEAR, hc, pose=translation(0, 0, -hc / 2), role="skirt"),
             (ring(ro, hole, tt, pose=translation(0, 0, tt / 2), role="top") if hole
              else cylinder(ro, tt, translation(0, 0, tt / 2), role="top"))]
    part = Part("cap", "screw_collar", prims, regions={"rotate": Region(("skirt",)), "grasp": Region(("skirt",))})
    return part, tt, ro


def _spin(builder, parent, pose, part, name="collar"):
    link = builder.create_link(name, parent)
    link.set_joint("continuous", pose, axis=(0.0, 0.0, 1.0))
    link.add(part)
    return link


def round_head(p, rh: float, hh: float) -> list:
    """Round pump head (base at z = 0): a disc, domed on top in some."""
    if p.flag("dome", 0.5):
        d = min(p.uniform("dome", 0.3, 0.7) * rh, hh)
        rd = (rh * rh + d * d) / (2 * d)  # sphere through the rim, ``d`` above it
        return [cylinder(rh, hh - d, translation(0, 0, (hh - d) / 2), role="head"),
                sphere(rd, rd - d, rd, translation(0, 0, hh - rd), role="head")]
    return [cylinder(rh, hh, translation(0, 0, hh / 2), role="head")]


def block_head(p, rh: float, hh: float) -> list:
    """Square-shouldered pump head (base at z = 0): a rounded block, longer towards the
    spout (-x)."""
    w = 2 * rh * p.uniform("block_width", 0.7, 1.0)
    return [rounded_box(2 * rh, w, hh, min(0.3 * w, hh) / 2, translation(0, 0, hh / 2), role="head")]


def _spout(p, rh: float, rz: float, z: float, curved: bool):
    """Spout from the head's axis out along -x at height ``z``; curved ones bend down.
    Returns (primitives, lowest z of the tip's underside, reach from the axis)."""
    L = p.uniform("spout_length", 0.015, 0.04)
    if not curved:
        return [cylinder(rz, rh + L, _ALONG_X.at(-(rh + L) / 2, 0, z), role="spout")], z - rz, rh + L
    R = p.uniform("bend_radius", 0.006, 0.014)
    turn = p.uniform("bend", 0.5, 1.3)
    a = rh + L - R * math.sin(turn)  # straight run, the bend ending ``L`` beyond the head
    prims = tube(rz, [line(max(a, rh)), arc(R, turn)], math.pi, translation(0, 0, z), role="spout")
    return prims, z - R * (1 - math.cos(turn)) - rz, max(a, rh) + R * math.sin(turn)


HEADS = {round_head: 2.0, block_head: 1.5}


def lotion_pump(p, builder, parent, pose, neck, head, curved: bool, lock: bool, travel=(0.008, 0.016),
                stem=(0.008, 0.045), head_radius=(0.01, 0.018)):
    """Soap / lotion pump: a screw collar (continuous about z), a pump stem pressed down
    (prismatic -z by ``travel`` m) carrying a head (``head`` template: round or block,
    ``head_radius`` m) with a spout along -x; with ``lock`` the head is its own link that
    turns about z (revolute, a quarter turn) to lock the pump. The stem stands ``stem``
    m above the collar. Returns the links made."""
    rn, bore, hn = neck
    rs = min(p.uniform("stem_radius", 0.003, 0.005), bore - 2 * CLEAR - 0.0015)
    collar, tt, ro = _collar(p, neck, hole=rs + CLEAR)
    boss = p.uniform("boss_height", 0.004, 0.02)
    rb = rs + CLEAR + p.uniform("boss_wall", 0.0015, 0.003)
    collar.primitives.append(ring(rb, rs + CLEAR, boss, pose=translation(0, 0, tt + boss / 2), role="top"))
    links = [_spin(builder, parent, pose, collar)]
    top = tt + boss
    trav = min(p.uniform("travel", *travel), hn - 0.003)
    rh = p.uniform("head_radius", *head_radius)
    hh = p.uniform("head_height", 0.01, 0.022)
    rz = min(p.uniform("spout_radius", 0.0025, 0.0045), 0.45 * hh)
    zs = p.uniform("spout_height", 0.3, 0.6) * hh
    sprims, low, reach = _spout(p, rh, rz, zs, curved)
    z_head = top + trav + GAP + max(p.uniform("stem_length", *stem), -min(low, 0.0))  # tip clears the collar
    stem_lo = -p.uniform("stem_depth", 0.2, 1.0) * (hn - trav - 0.0015)
    head_prims = [pr for pr in head(p, rh, hh)] + sprims
    grasp = Deferred.one(top_grasp, 0.0, 0.0, hh / 2, 2 * rh + 0.02, "y", (0.0, 0.0, -1.0))
    regions = {"press": Region(("head",)), "push": Region(("head",))}
    pl = builder.create_link("pump", links[0])
    pl.set_joint("prismatic", translation(), axis=(0.0, 0.0, -1.0), limits=(0.0, trav))
    stem_prim = cylinder(rs, z_head - stem_lo, translation(0, 0, (z_head + stem_lo) / 2), role="stem")
    links.append(pl)
    if lock:
        pl.add(Part("pump", "pump_stem", [stem_prim]))
        hl = builder.create_link("head", pl)
        hl.set_joint("revolute", translation(0, 0, z_head), axis=(0.0, 0.0, 1.0),
                     limits=(0.0, p.uniform("lock_turn", 0.5 * math.pi, 0.75 * math.pi)))
        hl.add(Part("pump", "locking_pump_head", head_prims, regions={**regions, "rotate": Region(("head",))},
                    grasps=grasp, actionable="slider_button"))
        links.append(hl)
    else:
        head_part = Part("pump", "pump_head", head_prims, regions=regions, grasps=grasp, actionable="slider_button")
        pl.add(Part("pump", "pump_stem", [stem_prim]))
        pl.add(head_part, translation(0, 0, z_head))
    return links


#: gripper frame approaching along +x with its jaws closing along y (columns: x, y, z axes)
_FRONT = np.array([[0.0, 0.0, 1.0, 0.0], [0.0, 1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 1.0]])


def front_pinch(x: float, z: float, width: float, open_dir=(1.0, 0.0, 0.0)) -> Grasp:
    """Grasp approaching from the front (along +x), its finger tips at (x, 0, z), jaws
    closing along y: a trigger pinched across its width, fingers kept in front of
    what is behind it."""
    T = _FRONT.copy()
    T[0, 3], T[2, 3] = x, z
    return Grasp(T, width, np.asarray(open_dir, dtype=float))


def _trigger_outline(r: float, L: float, kick: float, tip: float) -> np.ndarray:
    """x-z outline of a trigger hanging from its pivot at the origin: ``r`` half width
    at the pivot, ``L`` long, its lower end ``kick`` back (+x) and ``tip`` wider."""
    return np.array([[r, 0.0], [r + kick, -L], [-r + kick - tip, -L], [-r - tip * 0.5, -0.5 * L], [-r, 0.0]])


def trigger_sprayer(p, builder, parent, pose, neck, trigger_pull=(0.3, 0.6), nozzle_turn=(0.5 * math.pi, math.pi)):
    """Trigger spray head: a screw collar (continuous about z) carrying a shroud (a tower
    over the collar and a nose out along -x), a trigger hinged under the nose (revolute
    about -y, pulled back by ``trigger_pull`` rad) and a nozzle cap at the nose's front
    turning about its axis (revolute about -x, ``nozzle_turn`` rad: off / spray /
    stream). Returns the links made."""
    rn, _, hn = neck
    collar, tt, ro = _collar(p, neck, height=(0.014, 0.022))
    ws = min(p.uniform("shroud_width", 0.024, 0.034), 2 * ro + 0.008)
    hs = p.uniform("shroud_height", 0.05, 0.085)
    hn_ = p.uniform("nose_height", 0.4, 0.6) * hs
    back = ro * p.uniform("shroud_back", 1.0, 2.0)
    # trigger: pivot under the nose, its swept outline kept in front of the collar and above the body
    r = p.uniform("trigger_half_width", 0.003, 0.005)
    tw = p.uniform("trigger_width", 0.7, 0.9) * ws
    kick, tip = p.uniform("trigger_kick", 0.0, 0.008), p.uniform("trigger_tip", 0.0, 0.004)
    z_nose = tt + hs - hn_
    zp = z_nose - r - 0.0012  # the pin hangs just under the nose
    pull = p.uniform("trigger_pull", *trigger_pull)
    # the swing lowers the front of the lower end by at most (r + tip) sin(pull): stay above the neck's base
    L = min(p.uniform("trigger_length", 0.035, 0.07), zp + hn - GAP - (r + tip) * math.sin(pull))
    pts = _trigger_outline(r, L, kick, tip)
    th = np.linspace(0.0, pull, 6)[:, None]
    xs = pts[:, 0] * np.cos(th) - pts[:, 1] * np.sin(th)  # rotation about -y moves the lower end to +x
    xp = -ro - GAP - float(xs.max())
    front = xp - p.uniform("nose_overhang", 0.006, 0.03) - r
    shroud = [rounded_box(back + ro, ws, hs, min(0.3 * ws, 0.006), translation((back - ro) / 2, 0, tt + hs / 2),
                          role="shroud"),
              rounded_box(-ro * 0.5 - front, ws, hn_, min(0.3 * ws, 0.3 * hn_, 0.006),
                          translation((front - ro * 0.5) / 2, 0, z_nose + hn_ / 2), role="shroud")]
    collar.primitives += shroud
    collar.template = "sprayer_collar"
    cl = _spin(builder, parent, pose, collar)
    trig = Part("lever", "trigger",
                [extrusion([polygon(pts)], tw, pose=_ALONG_Y.at(), role="trigger"),
                 cylinder(r, tw, _ALONG_Y.at(), role="pin")],
                regions={"grasp": Region(("trigger",)), "press": Region(("trigger",)), "pull": Region(("trigger",))},
                grasps=Deferred.one(front_pinch, r + 0.6 * kick, -0.6 * L, tw + 0.02),
                actionable="hinge_handle")
    tl = builder.create_link("trigger", cl)
    tl.set_joint("revolute", translation(xp, 0, zp), axis=(0.0, -1.0, 0.0), limits=(0.0, pull))
    tl.add(trig)
    rc = min(p.uniform("nozzle_radius", 0.004, 0.007), hn_ / 2, ws / 2)
    lc = p.uniform("nozzle_length", 0.005, 0.012)
    sides = p.choice("nozzle_sides", NOZZLE_SIDES)
    nozzle = Part("nozzle", "nozzle_cap", [prism(rc, lc, sides, _ALONG_X.at(-lc / 2), role="cap")],
                  regions={"rotate": Region(("cap",)), "grasp": Region(("cap",))},
                  grasps=Deferred.one(front_pinch, -0.3 * lc, 0.0, 2 * rc + 0.02, (0.0, 0.0, 0.0)),
                  actionable="hinge_knob")
    nl = builder.create_link("nozzle", cl)
    nl.set_joint("revolute", translation(front, 0, z_nose + hn_ / 2), axis=(-1.0, 0.0, 0.0),
                 limits=(0.0, p.uniform("nozzle_turn", *nozzle_turn)))
    nl.add(nozzle)
    return [cl, tl, nl]


def wall_dispenser(p, builder, root, D: float, W: float, H: float, plate: str, travel=(0.006, 0.012)):
    """Wall soap dispenser on ``root``: a housing ``D`` deep (x, back on the wall at
    x = +D/2), ``W`` wide and ``H`` tall, base on z = 0, whose lower front is recessed
    for a push plate (``plate`` "slide": prismatic +x by ``travel``; "hinge": revolute
    about -y at its top edge, its lower edge moving in as far), a nozzle under the
    housing's front, and a refill lid on top hinged at the back edge (revolute about
    +y, 70-100 degrees). Returns the links made (plate, lid)."""
    hp = p.uniform("plate_height", 0.3, 0.5) * H
    zb = p.uniform("plate_bottom", 0.03, 0.08) * H
    t = p.uniform("plate_thickness", 0.005, 0.01)
    trav = p.uniform("travel", *travel)
    rec = t + trav + GAP
    tl = p.uniform("lid_thickness", 0.008, 0.015)
    Hb = H - tl
    xf = -D / 2
    rr = min(p.uniform("rounding", 0.004, 0.012), 0.3 * rec + 0.002)
    z_top = zb + hp + 0.001  # within touching distance of the plate, which never rises
    prims = [rounded_box(D, W, Hb - z_top, rr, translation(0, 0, (z_top + Hb) / 2), role="housing"),
             rounded_box(D - rec, W, z_top, rr, translation(rec / 2, 0, z_top / 2), role="housing")]
    rz = p.uniform("nozzle_radius", 0.003, 0.006)
    nz = p.uniform("nozzle_length", 0.006, 0.015)
    x_n = xf + rec + rz + 0.004
    prims.append(cylinder(rz, nz, translation(x_n, 0, -nz / 2), role="nozzle"))
    # the mounting plate on the back reaches the floor with the nozzle's tip: the unit stands on both
    tb = p.uniform("back_plate", 0.004, 0.008)
    prims.append(cuboid(tb, 0.9 * W, 0.6 * Hb + nz, translation(D / 2 - tb / 2, 0, (0.6 * Hb - nz) / 2), role="mount"))
    house = Part("body", "wall_housing", prims, regions={"grasp": Region(("housing",))})
    # the nozzle pokes below the housing: lift everything so the object still stands on z = 0
    root.add(house, translation(0, 0, nz))
    if p.flag("window", 0.6):  # soap level window, half sunk into the front
        wh, ww = p.uniform("window_height", 0.3, 0.6) * (Hb - z_top), p.uniform("window_width", 0.3, 0.6) * W
        root.add(Part("glass", "level_window", [cuboid(0.002, ww, wh, role="window")]),
                 translation(xf - 0.0005, 0, nz + (z_top + Hb) / 2))
    wp = W * p.uniform("plate_width", 0.6, 0.9)
    plate_part = Part("button" if plate == "slide" else "lever", f"push_plate_{plate}",
                      [rounded_box(t, wp, hp, min(0.45 * t, 0.004), translation(t / 2, 0, -hp / 2), role="plate")],
                      regions={"press": Region(("plate",)), "push": Region(("plate",))},
                      actionable="slider_button" if plate == "slide" else "none")
    pl = builder.create_link("plate", root)
    if plate == "slide":
        pl.set_joint("prismatic", translation(xf, 0, nz + zb + hp), axis=(1.0, 0.0, 0.0), limits=(0.0, trav))
        pl.add(plate_part)
    else:  # hinge on the plate's back top edge
        pl.set_joint("revolute", translation(xf + t, 0, nz + zb + hp), axis=(0.0, -1.0, 0.0),
                     limits=(0.0, math.asin(min(trav / hp, 0.5))))
        pl.add(plate_part, translation(-t, 0, 0))
    lid = Part("lid", "refill_lid",
               [rounded_box(D, W, tl, min(rr, 0.45 * tl), translation(-D / 2, 0, -tl / 2), role="lid")],
               regions={"lift": Region(("lid",)), "pull": Region(("lid",))},
               grasps=Deferred.one(top_grasp, -D * 0.8, 0.0, -tl / 2, W + 0.02, "y"), actionable="hinge_lid")
    ll = builder.create_link("lid", root)
    ll.set_joint("revolute", translation(D / 2, 0, nz + H), axis=(0.0, 1.0, 0.0),
                 limits=(0.0, p.uniform("lid_open", 1.2, 1.7)))
    ll.add(lid)
    return [pl, ll]
