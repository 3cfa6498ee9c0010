"""Printers: inkjet, laser and all-in-one (print, scan, copy) machines.

Parts: a box housing with paper slots open at the front. Inkjet: an output tray that
slides out of a front slot, a top (cartridge) cover over the front of the top and a
rear paper support (folded flat behind it, or standing against the back face), 1-4
buttons on the front. Laser: a paper
cassette drawer in the bottom slot, a front cover over the toner bay hinged at its
bottom edge, an output flap (paper stop) on the top, 1-4 buttons over the front
cover. All-in-one: a cassette and an output tray, a scanner lid over the whole top,
hinged at the back, often with an automatic document feeder (ADF) cover on it, and a
tilting control panel on the front carrying a display and 2-5 buttons.
Joints: trays and cassettes prismatic out of the front (-x), 60-90 % of their depth;
a standing paper support prismatic up (+z), 50-80 % of its length;
top cover, rear paper support, scanner lid, ADF cover and output flap revolute about
their back edge (+y), 55-100 degrees; front cover and control panel revolute about
their bottom front edge (outwards, -x), 30-90 degrees; buttons prismatic (3-6 mm).
Sizes (metres): inkjet 0.38-0.46 wide, 0.25-0.35 deep, 0.12-0.2 tall; laser 0.35-0.42
x 0.35-0.45 x 0.22-0.35; all-in-one 0.38-0.48 x 0.3-0.42 x 0.18-0.3 (closed trays).
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_y, translation
from artipg.rules import Category, Slot
from artipg.templates.appliance import display
from artipg.templates.controls import BUTTONS, mount_button_row
from artipg.templates.mounting import mount_hinged
from artipg.templates.panels import DRAWERS, slab_door
from artipg.templates.printers import hinged_plate, output_tray, slotted_housing, tilt_panel

# sub-category -> width, depth, height ranges (metres)
SUBS = {
    "inkjet": ((0.38, 0.46), (0.25, 0.35), (0.12, 0.2)),
    "laser": ((0.35, 0.42), (0.35, 0.45), (0.22, 0.35)),
    "all_in_one": ((0.38, 0.48), (0.3, 0.42), (0.18, 0.3)),
}
REST = 0.0008  # rest gap of lids and trays on the surface under them
SUPPORTS = {"folding": 2.0, "sliding": 1.0}  # an inkjet's rear paper support


def _lay_plate(ctx, parent, plate, x_hinge: float, z_surface: float, swing, name: str):
    """Hinge ``plate`` (a :func:`hinged_plate`) lying on a surface at ``z_surface``
    about the axis over ``x_hinge``; it turns up to a swing drawn in ``swing``."""
    link = ctx.builder.create_link(name, parent)
    link.set_joint("revolute", translation(x_hinge, 0, z_surface + REST - plate.anchors["bottom"][2]),
                   axis=(0.0, 1.0, 0.0), limits=(0.0, ctx.p.uniform(f"{name}_swing", *swing)))
    link.add(plate)
    return link


def _cassette(ctx, root, D, z0, h, w, d):
    p = ctx.p
    t = p.uniform("cassette_front", 0.01, 0.015)
    drawer = ctx.choose("cassette", DRAWERS)(p.scope("cassette"), w + 0.01, h + 0.006, d - 0.006,
                                             (-w / 2 + 0.0015, w / 2 - 0.0015, -h / 2 + 0.0015, h / 2 - 0.0015),
                                             thickness=t)
    link = ctx.builder.create_link("drawer", root)
    link.set_joint("prismatic", translation(-D / 2, 0, z0 + h / 2), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, p.uniform("cassette_pull", 0.6, 0.9) * (d - 0.006)))
    link.add(drawer)


def _output(ctx, root, D, z0, h, w, d):
    p = ctx.p
    link = ctx.builder.create_link("tray", root)
    link.set_joint("prismatic", translation(-D / 2, 0, z0 + REST), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, p.uniform("tray_pull", 0.6, 0.9) * (d - 0.004)))
    link.add(output_tray(p.scope("tray"), d - 0.004, w - 0.004, h - 0.003))


def _buttons(ctx, root, pose, y_lo, k, r, h):
    mount_button_row(ctx.p.scope("buttons"), ctx.builder, root, ctx.choose("button", BUTTONS), k, pose,
                     y_lo, y_lo + k * 0.026, 0.0, radius=r, square=(0.016, h))


def body(ctx):
    p, b = ctx.p, ctx.builder
    wr, dr, hr = SUBS[ctx.sub]
    W, D, H = p.uniform("width", *wr), p.uniform("depth", *dr), p.uniform("height", *hr)
    root = b.create_link("body")
    if ctx.sub == "inkjet":
        z0, h = p.uniform("slot_floor", 0.015, 0.03), p.uniform("slot_height", 0.02, 0.035)
        w, d = W - 2 * p.uniform("slot_side", 0.04, 0.08), p.uniform("slot_depth", 0.4, 0.6) * D
        root.add(slotted_housing(p, D, W, H, [(z0, z0 + h, w, d)]))
        _output(ctx, root, D, z0, h, w, d)
        support = ctx.choose("paper_support", SUPPORTS)
        if support == "folding":  # folded flat on the top behind the cover, it turns up
            lc = p.uniform("cover_share", 0.45, 0.6) * D
            ls = D - lc - 0.02
            plate = hinged_plate(p.scope("support"), "tray", ls, p.uniform("support_width", 0.55, 0.8) * W,
                                 actionable="hinge_door")
            _lay_plate(ctx, root, plate, D / 2 - 0.004, H, (1.3, 1.75), "support")
        else:  # standing against the back face, it slides up
            lc = p.uniform("cover_share", 0.75, 0.9) * D
            ls = p.uniform("support_length", 0.5, 0.8) * H
            plate = hinged_plate(p.scope("support"), "tray", ls, p.uniform("support_width", 0.55, 0.8) * W,
                                 actionable="slider_drawer")
            t = -plate.anchors["bottom"][2]  # the plate frame turned so the plate stands up, its lip on top
            link = b.create_link("support", root)
            link.set_joint("prismatic", translation(D / 2 + REST + t, 0, H + 0.005 - ls), axis=(0.0, 0.0, 1.0),
                           limits=(0.0, p.uniform("support_lift", 0.5, 0.8) * ls))
            link.add(plate, rot_y(math.pi / 2))
        _lay_plate(ctx, root, hinged_plate(p.scope("cover"), "lid", lc - 0.006, W - 0.02), -D / 2 + lc, H,
                   (1.0, 1.4), "lid")
        k = p.integers("buttons", 1, 4)
        zb = z0 + h + (H - z0 - h) / 2
        _buttons(ctx, root, translation(-D / 2, 0, zb), -W / 2 + 0.02, k, 0.006, min(0.012, H - z0 - h - 0.014))
    elif ctx.sub == "laser":
        z0, h = p.uniform("slot_floor", 0.01, 0.02), p.uniform("slot_height", 0.05, 0.08)
        w, d = W - 2 * p.uniform("slot_side", 0.02, 0.04), p.uniform("slot_depth", 0.6, 0.8) * D
        root.add(slotted_housing(p, D, W, H, [(z0, z0 + h, w, d)]))
        _cassette(ctx, root, D, z0, h, w, d)
        t = p.uniform("door_thickness", 0.012, 0.02)
        zd0 = z0 + h + 0.003 + t + p.uniform("door_gap", 0.004, 0.01)  # the door's corner dips t as it opens
        zd1 = H - p.uniform("door_top", 0.035, 0.06)
        wd = W - 2 * p.uniform("door_side", 0.015, 0.03)
        door = slab_door(p.scope("door"), wd, zd1 - zd0, t)
        mount_hinged(b, root, door, front_x=-D / 2, center_yz=(0.0, (zd0 + zd1) / 2), size_yz=(wd, zd1 - zd0),
                     side="-z", limits=(0.0, p.uniform("door_swing", 0.6, 1.5)), name="door")
        lf = p.uniform("flap_length", 0.03, 0.06)
        xf = -D / 2 + p.uniform("flap_x", 0.06, 0.12) + lf
        _lay_plate(ctx, root, hinged_plate(p.scope("flap"), "flap", lf, p.uniform("flap_width", 0.3, 0.5) * W,
                                           actionable="none"), xf, H, (1.0, 1.5), "flap")
        k = p.integers("buttons", 1, 4)
        _buttons(ctx, root, translation(-D / 2, 0, (zd1 + H) / 2), -W / 2 + 0.02, k, 0.006,
                 min(0.012, H - zd1 - 0.014))
    else:
        z0, h = p.uniform("slot_floor", 0.01, 0.02), p.uniform("slot_height", 0.035, 0.06)
        w, d = W - 2 * p.uniform("slot_side", 0.02, 0.05), p.uniform("slot_depth", 0.6, 0.8) * D
        z2, h2 = z0 + h + p.uniform("slot_gap", 0.012, 0.025), p.uniform("tray_slot", 0.02, 0.03)
        w2, d2 = w - 0.02, p.uniform("tray_depth", 0.35, 0.5) * D
        root.add(slotted_housing(p, D, W, H, [(z0, z0 + h, w, d), (z2, z2 + h2, w2, d2)]))
        _cassette(ctx, root, D, z0, h, w, d)
        _output(ctx, root, D, z2, h2, w2, d2)
        lid = hinged_plate(p.scope("scanner"), "lid", D - 0.012, W - 0.01, p.uniform("lid_thickness", 0.012, 0.02))
        lid_link = _lay_plate(ctx, root, lid, D / 2 - 0.004, H, (1.2, 1.5), "lid")
        if p.flag("adf", 0.6):  # the document feeder's cover lies on the lid's back half
            la = p.uniform("adf_length", 0.06, 0.1)
            _lay_plate(ctx, lid_link, hinged_plate(p.scope("adf"), "cover", la, p.uniform("adf_width", 0.5, 0.7) * W),
                       -0.015, 0.0, (0.9, 1.3), "adf")
        panel(ctx, root, D, W, H, z2 + h2)


def panel(ctx, root, D, W, H, z_low):
    """The all-in-one's tilting control panel on the front face between the output
    slot (top at ``z_low``) and the scanner lid, with a display and a button row."""
    p, b = ctx.p, ctx.builder
    pw = p.uniform("panel_width", 0.15, 0.25)
    t_gap = p.uniform("panel_gap", 0.004, 0.01)
    z0 = z_low + 0.016 + t_gap  # the panel's back corner dips its thickness as it tilts out
    ph = min(p.uniform("panel_height", 0.045, 0.07), H - 0.006 - z0)
    part = tilt_panel(p.scope("panel"), pw, ph)
    yc = -W / 2 + 0.02 + pw / 2
    link = mount_hinged(b, root, part, front_x=-D / 2, center_yz=(yc, z0 + ph / 2), size_yz=(pw, ph), side="-z",
                        limits=(0.0, p.uniform("panel_tilt", 0.5, 1.2)), name="panel")
    # the link frame is on the bottom front edge: the panel's front face is x = 0
    sw = p.uniform("screen_width", 0.35, 0.5) * pw
    link.add(display(p.scope("screen"), sw, 0.6 * ph), translation(0.0, -pw / 2 + 0.01 + sw / 2, ph / 2))
    k = p.integers("buttons", 2, 5)
    lo = -pw / 2 + 0.02 + sw
    pitch = (pw / 2 - 0.01 - lo) / k
    mount_button_row(p.scope("buttons"), b, link, ctx.choose("button", BUTTONS), k, translation(0.0, 0.0, ph / 2),
                     lo, pw / 2 - 0.01, 0.0, radius=min(0.007, pitch / 2 - 0.003, ph / 2 - 0.008),
                     square=(max(0.006, min(0.016, pitch - 0.006)), min(0.012, ph - 0.016)))


RULE = Category(
    name="printer",
    subcategories={"inkjet": 3.0, "laser": 2.0, "all_in_one": 2.0},
    # plastic shells round paper paths and mechanisms: ~250 kg/m^3 over the housing's solid
    materials={"body": "insulated", "lid": "insulated", "door": "insulated", "drawer": "insulated",
               "tray": "insulated", "flap": "insulated", "cover": "insulated"},
    mass_range=(2.0, 30.0),  # kg: inkjets 3-8, all-in-ones 6-20, office lasers up to ~25
    slots=(Slot("body", body),),
)
