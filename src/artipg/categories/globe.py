"""Globes: desk globes on a post, swivelling desk globes, and floor globes.

Parts: the sphere (the globe itself), spinning on two axle pins held by a meridian
(round wire or flat band; a half ring on one side or a full ring); desk globes stand
on a plinth (domed disc, stepped discs or a square block) and a post (plain or turned);
floor globes stand on three or four splayed legs joined by a horizon ring at the
equator and by spokes to a cradle under the meridian.
Joints: the sphere spins continuously about its axis, tilted 23.4 deg from the
vertical in the meridian plane; on swivel globes the meridian turns continuously
about the vertical on a collar at the top of the post; on floor globes the full
meridian slides round in its own plane (revolute about the plane's normal, +-30-70
deg), which tilts the axis.
Sub-categories: desk_globe, swivel_globe, floor_globe. Sizes (metres): desk globes
0.2-0.32 in diameter (8-12.5 in), 0.3-0.55 tall; floor globes 0.4-0.52 in diameter
(16-20 in), 0.8-1.05 tall. The sphere is modelled solid: its material class stands for
a hollow shell (see ``materials``).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.globes import MERIDIANS, PLINTHS, POSTS, floor_stand, globe_sphere, swivel_collar

# sub-category -> sphere radius, P(full meridian), swivelling meridian
SUBS = {"desk_globe": ((0.1, 0.16), 0.3, False), "swivel_globe": ((0.1, 0.16), 0.5, True),
        "floor_globe": ((0.2, 0.26), 1.0, False)}
PLANE = rot_z(math.pi / 2)  # the meridian plane is the object's y-z plane (seen from the front)


def stand(ctx):
    """Stand and meridian; returns the meridian's link and the meridian frame in it."""
    p = ctx.p
    rr, p_full, swivel = SUBS[ctx.sub]
    R = p.uniform("radius", *rr)
    tilt = p.uniform("axis_tilt", 0.405, 0.412)  # the Earth's obliquity, 23.2-23.6 deg
    mer = ctx.choose("meridian", MERIDIANS)(p.scope("meridian"), R, p.flag("full", p_full))
    Rm, half, _ = mer.anchors["bottom_r"]
    root = ctx.builder.create_link("base")
    if ctx.sub == "floor_globe":
        zc = p.uniform("centre_height", 0.55, 0.72)
        horizon = Rm + half + p.uniform("horizon_gap", 0.02, 0.04)
        root.add(floor_stand(p.scope("stand"), zc, horizon, zc - Rm - half - 0.0005))
        link = ctx.builder.create_link("meridian", root)
        link.set_joint("revolute", translation(0, 0, zc) @ PLANE, axis=(0.0, 1.0, 0.0),
                       limits=(-(lim := p.uniform("slide", 0.5, 1.2)), lim))
        return link, link.add(mer, rot_y(tilt)), R
    plinth = root.add(ctx.choose("plinth", PLINTHS)(p.scope("plinth"), p.uniform("base_radius", 0.45, 0.7) * R))
    zt = plinth.anchors["top"][2]
    hp = p.uniform("post_height", 0.03, 0.15)
    post = root.add(ctx.choose("post", POSTS)(p.scope("post"), hp), translation(0, 0, zt))
    if not swivel:  # the post reaches into the ring at its lowest point
        M = translation(0, 0, zt + hp + half + Rm) @ PLANE @ rot_y(tilt)
        return root, root.add(mer, M), R
    hc = p.uniform("collar_height", 0.015, 0.03)
    link = ctx.builder.create_link("meridian", root)
    link.set_joint("continuous", translation(0, 0, zt + hp + 0.0005), axis=(0.0, 0.0, 1.0))
    link.add(swivel_collar(p.scope("collar"), post.anchors["radius"][0] + p.uniform("collar_wall", 0.002, 0.005), hc))
    return link, link.add(mer, translation(0, 0, hc + Rm) @ PLANE @ rot_y(tilt)), R


def ball(ctx):
    link, mer, R = ctx.out["stand"]
    sph = ctx.builder.create_link("sphere", link)
    sph.set_joint("continuous", mer.pose, axis=(0.0, 0.0, 1.0))
    sph.add(globe_sphere(ctx.p, R))


RULE = Category(
    name="globe",
    subcategories={"desk_globe": 3.0, "swivel_globe": 1.5, "floor_globe": 1.5},
    materials={"sphere": "insulated", "frame": "steel", "base": "wood", "stand": "wood"},
    mass_range=(0.5, 30.0),  # kg: 8 in desk globes (~0.6 kg) to 20 in floor globes on wooden stands
    slots=(Slot("stand", stand), Slot("ball", ball, after=("stand",))),
)
