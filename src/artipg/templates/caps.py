"""Closures of bottles and jars: screw caps, stoppers, flip-tops, push-pull sport caps
and lotion pumps.

Part frame: origin at the centre of the neck's top face, +z out of the neck. Caps sit
*on* the neck (their top disc rests on its rim, their skirt clears its outside by
:data:`CLEAR`); stoppers and pump stems go *into* the bore with the same clearance.

Each closure template ``f(p, builder, parent, pose, neck)`` builds its links on
``parent`` at ``pose`` (the neck-top frame in the parent link) for a neck given as
``(outer radius, bore radius, height)`` and returns the links it made:

- :func:`screw_top`: one cap, continuous about z (unscrewing);
- :func:`stopper_top`: a T-stopper, prismatic along +z (pulled out);
- :func:`flip_top`: a screw cap (continuous) carrying a lid hinged at its back
  (revolute about y, opening up to 100-150 deg);
- :func:`sport_top`: a screw cap carrying a push-pull spout (prismatic along +z);
- :func:`pump_top`: a screw collar (continuous) carrying a pump (prismatic along -z,
  pressed down) with its head and nozzle.
"""

from __future__ import annotations

import math

from artipg.geometry import cylinder, frustum, ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.levers import top_grasp

#: Radial clearance (metres) between a cap's skirt and the neck, or a stopper / stem and
#: a bore: the room a real cap's threads take. It must exceed the 0.5 mm by which the
#: flat faces of the convex sectors that simulators use for a ring cut inside its
#: round surface (``artipg.geometry.revolve.SECTOR_SAGITTA``), or the skirt the simulators
#: see cuts into the neck they see.
CLEAR = 0.0008
_ALONG_X = Placer(rot_y(math.pi / 2))  # local z -> +x


def screw_cap(p, neck_r: float, neck_h: float, height: float | None = None) -> Part:
    """Cap: a top disc resting on the neck rim and a skirt around the neck."""
    t = p.uniform("wall", 0.0015, 0.0025)
    top = p.uniform("top", 0.0015, 0.003)
    skirt = min(p.uniform("skirt", 0.01, 0.02, fixed=height), neck_h - 0.0035)
    r_in = neck_r + CLEAR
    prims = [cylinder(r_in + t, top, translation(0, 0, top / 2), role="top"),
             ring(r_in + t, r_in, skirt, pose=translation(0, 0, -skirt / 2), role="skirt")]
    return Part("cap", "screw_cap", prims, anchors={"top": (0.0, 0.0, top), "edge": (r_in + t, 0.0, top)},
                regions={"rotate": Region(("skirt",)), "grasp": Region(("skirt",))})


def _continuous(builder, parent, pose, part, name="cap"):
    link = builder.create_link(name, parent)
    link.set_joint("continuous", pose, axis=(0.0, 0.0, 1.0))
    link.add(part)
    return link


def screw_top(p, builder, parent, pose, neck):
    """A screw cap turning freely about the neck axis."""
    return [_continuous(builder, parent, pose, screw_cap(p, neck[0], neck[2]))]


def stopper_top(p, builder, parent, pose, neck):
    """T-stopper (cork with a head) pulled straight out of the bore."""
    rn, bore, hn = neck
    head_r = rn + p.uniform("overhang", 0.001, 0.003)
    hh = p.uniform("head_height", 0.008, 0.016)
    shank = p.uniform("shank", 0.5, 0.9) * (hn - 0.001)
    prims = [frustum(head_r, head_r * p.uniform("head_taper", 0.85, 1.0), hh, translation(0, 0, hh / 2), role="head"),
             cylinder(bore - CLEAR, shank, translation(0, 0, -shank / 2), role="shank")]
    part = Part("cap", "stopper", prims, regions={"grasp": Region(("head",)), "pull": Region(("head",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, hh / 2, 2 * head_r + 0.02, "x"), actionable="slider_lid")
    link = builder.create_link("stopper", parent)
    link.set_joint("prismatic", pose, axis=(0.0, 0.0, 1.0), limits=(0.0, shank + p.uniform("lift", 0.005, 0.02)))
    link.add(part)
    return [link]


def flip_top(p, builder, parent, pose, neck):
    """Dispensing cap with a nozzle under a lid hinged at the back (+x)."""
    cap = screw_cap(p, neck[0], neck[2])
    R, z0 = cap.anchors["edge"][0], cap.anchors["top"][2]
    hl = p.uniform("lid_skirt", 0.004, 0.008)
    tl = p.uniform("lid_top", 0.0015, 0.0025)
    hn = hl - p.uniform("nozzle_clearance", 0.001, 0.002)
    rz = p.uniform("nozzle_radius", 0.0015, 0.0035)
    cap.primitives.append(cylinder(rz, hn, translation(0, 0, z0 + hn / 2), role="nozzle"))
    link = _continuous(builder, parent, pose, cap)
    lid = Part("lid", "flip_lid", [ring(R, R - 0.0015, hl, pose=translation(-R, 0, -tl - hl / 2), role="lid"),
                                   cylinder(R, tl, translation(-R, 0, -tl / 2), role="lid")],
               regions={"lift": Region(("lid",)), "push": Region(("lid",))},
               grasps=Deferred.one(top_grasp, -R, 0.0, -(tl + hl) / 2, 2 * R + 0.02, "y"), actionable="hinge_lid")
    lid_link = builder.create_link("lid", link)
    lid_link.set_joint("revolute", translation(R, 0, z0 + hl + tl), axis=(0.0, 1.0, 0.0),
                       limits=(0.0, p.uniform("lid_open", 1.8, 2.6)))
    lid_link.add(lid)
    return [link, lid_link]


def sport_top(p, builder, parent, pose, neck):
    """Screw cap with a push-pull spout sliding up a fixed core."""
    cap = screw_cap(p, neck[0], neck[2], height=p.uniform("skirt", 0.012, 0.02))
    R, z0 = cap.anchors["edge"][0], cap.anchors["top"][2]
    rc = p.uniform("core_radius", 0.35, 0.5) * R
    hc = p.uniform("core_height", 0.008, 0.014)
    cap.primitives.append(cylinder(rc, hc, translation(0, 0, z0 + hc / 2), role="core"))
    t = p.uniform("spout_wall", 0.0015, 0.002)
    ri = rc + CLEAR
    prims = [ring(ri + t, ri, hc + CLEAR, pose=translation(0, 0, z0 + (hc + CLEAR) / 2), role="spout"),
             ring(ri + t, 0.0012, t, pose=translation(0, 0, z0 + hc + CLEAR + t / 2), role="spout")]
    spout = Part("nozzle", "push_pull_spout", prims, regions={"pull": Region(("spout",)), "grasp": Region(("spout",))})
    link = _continuous(builder, parent, pose, cap)
    sl = builder.create_link("spout", link)
    travel = hc - p.uniform("engaged", 0.003, 0.005)  # stays on the core when pulled out
    sl.set_joint("prismatic", translation(), axis=(0.0, 0.0, 1.0), limits=(0.0, travel))
    sl.add(spout)
    return [link, sl]


def pump_top(p, builder, parent, pose, neck):
    """Lotion / soap pump: a screw collar, a stem in the bore and a head with a nozzle."""
    rn, bore, hn = neck
    t = p.uniform("collar_wall", 0.0015, 0.0025)
    hc = min(p.uniform("collar_height", 0.012, 0.02), hn - 0.0035)
    tt = p.uniform("collar_top", 0.002, 0.003)
    rs = min(p.uniform("stem_radius", 0.003, 0.005), bore - 2 * CLEAR - 0.0015)
    hole = rs + CLEAR
    boss = p.uniform("boss_height", 0.004, 0.01)
    travel = min(p.uniform("travel", 0.006, 0.012), hn - 0.002)
    collar = Part("cap", "pump_collar",
                  [ring(rn + CLEAR + t, rn + CLEAR, hc, pose=translation(0, 0, -hc / 2), role="skirt"),
                   ring(rn + CLEAR + t, hole, tt, pose=translation(0, 0, tt / 2), role="top"),
                   ring(hole + 0.002, hole, boss, pose=translation(0, 0, tt + boss / 2), role="top")],
                  regions={"rotate": Region(("skirt",)), "grasp": Region(("skirt",))})
    link = _continuous(builder, parent, pose, collar)
    z_head = tt + boss + travel + p.uniform("head_clearance", 0.001, 0.003)
    hh = p.uniform("head_height", 0.008, 0.014)
    rh = p.uniform("head_radius", 0.009, 0.015)
    stem_lo = -p.uniform("stem_depth", 0.0, 1.0) * (hn - travel - 0.0015)
    stem_hi = z_head + p.uniform("neck_length", 0.004, 0.02)
    rz = p.uniform("nozzle_radius", 0.0025, 0.004)
    nz = p.uniform("nozzle_length", 0.015, 0.03)
    head = Part("pump", "pump_head",
                [cylinder(rs, stem_hi - stem_lo, translation(0, 0, (stem_lo + stem_hi) / 2), role="stem"),
                 cylinder(rh, hh, translation(0, 0, stem_hi + hh / 2), role="head")],
                regions={"press": Region(("head",)), "push": Region(("head",))},
                grasps=Deferred.one(top_grasp, 0.0, 0.0, stem_hi + hh / 2, 2 * rh + 0.02, "y", (0.0, 0.0, -1.0)),
                actionable="slider_button")
    tip = Part("nozzle", "pump_nozzle", [cylinder(rz, nz + rh / 2, _ALONG_X.at(-(nz + rh / 2) / 2, 0, stem_hi + hh / 2),
                                                  role="nozzle")])
    pl = builder.create_link("pump", link)
    pl.set_joint("prismatic", translation(), axis=(0.0, 0.0, -1.0), limits=(0.0, travel))
    pl.add(head)
    pl.add(tip)
    return [link, pl]


CLOSURES = {screw_top: 3.0, stopper_top: 1.0, flip_top: 1.5, sport_top: 1.0, pump_top: 1.0}
