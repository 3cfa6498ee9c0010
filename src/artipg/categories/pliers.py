"""Pliers: slip-joint, needle-nose, diagonal cutters and locking pliers.

Parts: two steel halves crossing at a lap joint: each a jaw (smooth, with a pipe-grip hollow, or
a bevelled cutter), a handle (bare, dipped in plastic, or with cushion grips) and a
half-thickness plate round the pivot; a rivet through both plates. Locking pliers
carry an adjusting screw at the end of the fixed handle.
Joint: the upper half turns about the rivet (revolute, z), 0 = jaws closed, opening
0.35-0.7 rad (wider for needle-nose).
Sizes (metres): slip-joint 0.15-0.22 long, needle-nose 0.15-0.2 (jaws 0.045-0.065),
diagonal 0.13-0.18 (jaws 0.015-0.022), locking 0.18-0.25; 7-14 mm thick.
Frame: jaws point +y, handles -y (as the scissors), the pivot on z.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.plier_halves import GRIPS, PIN_CLEAR, adjust_screw, handle, jaw, pivot_plate, rivet

# sub-category -> jaw kinds, jaw length, jaw root width, jaw tip width, handle length, thickness, opening
SUBS = {
    "slip_joint": ({"pipe_grip": 2.0, "smooth": 1.0}, (0.025, 0.035), (0.01, 0.013), (0.004, 0.006), (0.11, 0.17),
                   (0.008, 0.011), (0.4, 0.6)),
    "needle_nose": ({"smooth": 2.0, "pipe_grip": 1.0}, (0.045, 0.065), (0.008, 0.01), (0.0015, 0.0025),
                    (0.09, 0.12), (0.007, 0.009), (0.5, 0.7)),
    "diagonal": ({"cutter": 1.0}, (0.015, 0.022), (0.01, 0.013), (0.006, 0.009), (0.1, 0.15), (0.009, 0.012),
                 (0.35, 0.5)),
    "locking": ({"pipe_grip": 1.0, "smooth": 1.0}, (0.025, 0.035), (0.011, 0.014), (0.005, 0.007), (0.13, 0.19), (0.01, 0.014),
                (0.4, 0.6)),
}
ALONG_Y = rot_z(math.pi / 2)


def halves(ctx):
    p = ctx.p
    jaws, lr, w0r, w1r, hr, tr, up = SUBS[ctx.sub]
    kind = ctx.choose("jaw", jaws)
    grip = ctx.choose("grip", GRIPS)
    T = p.uniform("thickness", *tr)
    R0 = p.uniform("pivot_radius", 0.0055, 0.0085)
    Lj, w0, w1 = p.uniform("jaw_length", *lr), p.uniform("jaw_width", *w0r), p.uniform("jaw_tip", *w1r)
    Lh = p.uniform("handle_length", *hr)
    g0, g1 = p.uniform("handle_gap", 0.0015, 0.003), p.uniform("handle_spread", 0.006, 0.016)
    hw0, hw1 = p.uniform("handle_root", 0.007, 0.01), p.uniform("handle_end", 0.008, 0.012)
    Th, bow = p.uniform("handle_thickness", 0.6, 0.8) * T, p.uniform("bow", 0.0, 0.006)
    rp = p.uniform("rivet_radius", 0.0022, 0.0032)
    root = ctx.builder.create_link("lower_half")
    for i, hand in enumerate((1.0, -1.0)):
        link = root
        if i == 1:
            link = ctx.builder.create_link("upper_half", root)
            link.set_joint("revolute", translation(), axis=(0.0, 0.0, -1.0), limits=(0.0, p.uniform("open", *up)))
        q = p.scope("lower" if i == 0 else "upper")
        link.add(handle(q, grip, (R0, Lh, g0, g1, hw0, hw1, bow), hand, Th, "hinge_handle" if i else "none"), ALONG_Y,
                 name=f"handle{i}")
        link.add(pivot_plate(hand, R0, T, rp + PIN_CLEAR if i else 0.0, i == 0, (w0, g0, hw0)), ALONG_Y,
                 name=f"plate{i}")
        link.add(jaw(kind, hand, R0, Lj, w0, w1, T), ALONG_Y, name=f"jaw{i}")
    # a head under 1 mm high is thinner than pybullet's 1 mm collision margin on its implicit
    # cylinders, which then reach through the 0.6 mm gap into the moving plate (seed 19 jammed)
    root.add(rivet(rp, T, rp + p.uniform("head", 0.0012, 0.0025), p.uniform("head_height", 0.001, 0.0018)))
    if ctx.sub == "locking":
        root.add(adjust_screw(-R0 - Lh + 0.002, -(g1 + 0.5 * hw1), 0.4 * Th, p.uniform("screw_length", 0.012, 0.02), Th),
                 ALONG_Y)


RULE = Category(
    name="pliers",
    subcategories={"slip_joint": 2.0, "needle_nose": 2.0, "diagonal": 1.5, "locking": 1.0},
    mass_range=(0.05, 0.6),  # kg: small needle-nose to 10-inch locking pliers
    materials={"blade": "steel", "handle": "steel", "hinge": "steel", "knob": "steel"},
    slots=(Slot("halves", halves),),
)
