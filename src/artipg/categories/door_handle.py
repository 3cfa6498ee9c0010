"""Door handles: lever and knob sets on round roses or long back plates.

A door handle is a mounted fixture: the object is the hardware of one face of a door,
its rose or back plate fixed (``fixed_base``, simulated mounted), the door itself not
modelled. The mounting face is x = 0, the hardware protrudes along -x.
Parts: a round rose (25-31.5 mm radius, 8-12 mm thick) or a long back plate
(38-55 mm wide, 6-12 mm thick, 0.16-0.24 m tall) fixed; a lever (round bar with a
domed end, return-to-door, crescent or flat paddle; 0.11-0.15 m long, standing
40-56 mm off its rose) or a knob (ball, flared or beehive; 50-62 mm across) on a
round collar turning 1.2-2 mm in front of it; on back plates, 72, 85 or 92 mm under
the spindle (the DIN centre distances), a profile lock cylinder (fixed, 2-5 mm proud)
or a thumb turn, or nothing (passage sets).
Joints: levers revolute about the spindle (x), tip down 0..0.7-0.87 rad (40-50 deg,
the return spring's stop); knobs revolute ±1.2-1.57 rad; thumb turns revolute 0..pi/2.
Sub-categories: lever_rose, lever_plate, knob_rose, knob_plate.
Sizes from manufacturers' catalogues of EN 1906 lever sets (rose Ø50-63 mm, levers
120-140 mm, back plates 40-50 x 180-240 mm) and of knob sets (Ø50-60 mm).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.door_hardware import KNOBS, LEVERS, back_plate, euro_cylinder, rose, thumb_turn
from artipg.templates.turn_handles import mount_turning

ROSE = {"radius": (0.025, 0.0315), "thickness": (0.008, 0.012)}
PLATE = {"width": (0.038, 0.055), "thickness": (0.006, 0.012), "above": (0.045, 0.075), "margin": (0.04, 0.075)}
LEVER = {"length": (0.11, 0.15), "bar_radius": (0.0075, 0.0105), "standoff": (0.04, 0.056),
         "hub_radius": (0.0115, 0.015), "bar_thickness": (0.007, 0.011), "bar_height": (0.014, 0.022)}
KNOB = {"radius": (0.025, 0.031), "depth": (0.03, 0.042), "neck_radius": (0.009, 0.012), "neck_length": (0.008, 0.016)}
TURN = {"boss_radius": (0.01, 0.014), "boss_depth": (0.004, 0.008), "wing_length": (0.028, 0.038),
        "wing_depth": (0.012, 0.018), "wing_thickness": (0.006, 0.009)}
CYLINDER = {"plug_radius": (0.0085, 0.009), "stem_width": (0.01, 0.011), "stem_length": (0.014, 0.024),
            "proud": (0.002, 0.005)}
FITTINGS = {"key": 2.0, "thumb_turn": 1.0, "none": 1.0}
CENTRES = {"72": 2.0, "85": 1.0, "92": 1.0}  # spindle to lock centre (mm), DIN 18251


def mount(ctx):
    p = ctx.p
    root = ctx.builder.create_link("base")
    if ctx.sub.endswith("_rose"):
        part = root.add(rose(p.scope("rose"), ROSE))
        return root, part.anchor("front")[0], None, None
    fitting = p.choice("fitting", FITTINGS)
    c = 0.001 * float(p.choice("centres", CENTRES)) if fitting != "none" else 0.0
    below = c if fitting != "none" else p.uniform("plain_below", 0.06, 0.09)
    part = root.add(back_plate(p.scope("plate"), PLATE, below))
    return root, part.anchor("front")[0], fitting, c


def handle(ctx):
    root, front, _, _ = ctx.out["mount"]
    p = ctx.p
    gap = p.uniform("gap", 0.0012, 0.002)
    T = translation(front, 0.0, 0.0)
    if ctx.sub.startswith("lever"):
        side = 1.0 if p.choice("side", ("+y", "-y")) == "+y" else -1.0
        part = ctx.choose("lever", LEVERS)(p.scope("lever"), side, LEVER, gap)
        mount_turning(ctx.builder, root, part, T, (0.0, p.uniform("lever_limit", 0.7, 0.87)), name="handle")
    else:
        part = ctx.choose("knob", KNOBS)(p.scope("knob"), KNOB, gap)
        a = p.uniform("knob_limit", 1.2, 0.5 * math.pi)
        mount_turning(ctx.builder, root, part, T, (-a, a), name="handle")


def fitting(ctx):
    root, front, kind, c = ctx.out["mount"]
    p = ctx.p
    if kind == "key":
        root.add(euro_cylinder(p.scope("cylinder"), CYLINDER), translation(front, 0.0, -c))
    elif kind == "thumb_turn":
        part = thumb_turn(p.scope("thumb_turn"), TURN, p.uniform("turn_gap", 0.0012, 0.002))
        mount_turning(ctx.builder, root, part, translation(front, 0.0, -c), (0.0, 0.5 * math.pi), name="thumb_turn")


RULE = Category(
    name="door_handle",
    subcategories={"lever_rose": 3.0, "lever_plate": 2.0, "knob_rose": 2.0, "knob_plate": 1.0},
    fixed_base=True,  # screwed to a door: simulated mounted, not dropped on a floor
    # die-cast zinc and hollow stainless levers and plates average to about aluminium's density
    materials={"base": "aluminium", "handle": "aluminium", "knob": "aluminium", "lock": "brass"},
    mass_range=(0.05, 1.2),  # kg: one face's rose and lever to a solid back plate with a knob
    slots=(Slot("mount", mount), Slot("handle", handle, after=("mount",)),
           Slot("fitting", fitting, after=("mount",))),
)
