"""Shaver parts: electric shaver bodies, foil heads with a cover, rotary head units,
pop-up trimmers and razor handles with a pivoting cartridge.

Bodies: origin at the centre of the base on z = 0, +z up, front (the power button's
side) -x; ``D`` deep (x), ``W`` wide (y), ``H`` tall. Anchor ``top`` (0, 0, H).
Head builders ``f(p, builder, parent, top, D, W, ...)`` put their links on ``parent``
(the body link) over the body's top centre ``top`` (x, y, z).
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cylinder, rect_ring
from artipg.geometry.extrusion import extrusion
from artipg.geometry.rounded_box import rounded_box
from artipg.geometry.transforms import Placer, rot_x, translation
from artipg.model.part import Deferred, Part, Region
from artipg.templates.levers import top_grasp
from artipg.templates.squeeze import oval

GAP = 0.002  # clearance (m) kept between moving parts and the parts they pass
_ALONG_Y = Placer(rot_x(math.pi / 2))  # local z -> -y


def _body(name, prims):
    return Part("body", name, prims, regions={"grasp": Region(("grip",)), "lift": Region(("grip",))})


def box_body(p, D: float, W: float, H: float) -> Part:
    """Rounded-box shaver body (most foil shavers)."""
    r = p.uniform("rounding", 0.2, 0.45) * min(D, W) / 2
    return _body("box_shaver_body", [rounded_box(D, W, H, r, translation(0, 0, H / 2), role="grip")])


def waisted_body(p, D: float, W: float, H: float) -> Part:
    """Body with a slimmer grip under a full-width shoulder block (contoured shavers)."""
    hs = p.uniform("shoulder", 0.25, 0.4) * H
    k = p.uniform("waist", 0.75, 0.9)
    r = p.uniform("rounding", 0.2, 0.45) * min(D, W) * k / 2
    return _body("waisted_shaver_body",
                 [rounded_box(D, k * W, H - hs + r, r, translation(0, 0, (H - hs + r) / 2), role="grip"),
                  rounded_box(D, W, hs, r, translation(0, 0, H - hs / 2), role="grip")])


def oval_body(p, D: float, W: float, H: float) -> Part:
    """Oval-section body (four-arc oval prism, wide across y): travel and rotary shavers."""
    loop = oval(D / 2, max(W, D * 1.05) / 2, p.uniform("end_radius", 0.4, 0.8) * D / 2)
    return _body("oval_shaver_body", [extrusion([loop], H, pose=translation(0, 0, H / 2), role="grip")])


BODIES = {box_body: 3.0, waisted_body: 1.5, oval_body: 1.0}


def _head_envelope(corners: np.ndarray, tilt: float) -> tuple[float, float]:
    """(max |x|, min z) of x-z ``corners`` (n, 2) turned about y by +-``tilt``."""
    c, s = math.cos(tilt), math.sin(tilt)
    x = np.abs(np.concatenate([corners[:, 0] * c + corners[:, 1] * s, corners[:, 0] * c - corners[:, 1] * s]))
    z = np.concatenate([-corners[:, 0] * s + corners[:, 1] * c, corners[:, 0] * s + corners[:, 1] * c])
    return float(x.max()), float(z.min())


def foil_head(p, builder, parent, top, D: float, W: float, n_foils=(1, 3), tilt=(0.15, 0.35)):
    """Foil head on a yoke: the yoke (a narrow block on the body's top, a part of
    ``parent``), a head pivoting on a hub across its top (revolute about y, +-``tilt``
    rad) with ``n_foils`` foil cylinders along y, and a protective cover sliding off
    upwards (prismatic +z, removable). Returns (head link, cover link, (max |x|, min z)
    of the head's swept outline in the body frame)."""
    x0, _, z0 = top
    rp = p.uniform("hub_radius", 0.0018, 0.003)
    a = p.uniform("tilt", *tilt)
    yd = min(0.8 * D, 2 * (rp - 0.0005) / math.sin(a))  # head bottom stays off the yoke's top as it tilts
    hd = p.uniform("head_depth", 0.5, 0.8) * D
    # the head's outer bottom edges dip by hd/2 sin(tilt): the yoke keeps them off the body's top
    hy = max(p.uniform("yoke_height", 0.004, 0.009), hd / 2 * math.sin(a) + GAP - rp)
    hw = p.uniform("head_width", 0.9, 1.15) * W
    hh = p.uniform("head_height", 0.012, 0.02)
    yoke = cuboid(yd, p.uniform("yoke_width", 0.6, 0.85) * W, hy, translation(x0, 0, z0 + hy / 2), role="yoke")
    parent.add(Part("body", "shaver_yoke", [yoke]))
    n = p.integers("foils", *n_foils)
    rf = min(p.uniform("foil_radius", 0.004, 0.007), hd / (2 * n))
    xs = (np.arange(n) - (n - 1) / 2) * (hd - 2 * rf) / max(n - 1, 1)
    head = Part("head", "foil_head", [cylinder(rp, 0.6 * hw, _ALONG_Y.at(), role="hub"),
                                      rounded_box(hd, hw, hh, min(0.004, hd / 4), translation(0, 0, hh / 2),
                                                  role="housing")],
                regions={"grasp": Region(("housing",)), "rotate": Region(("housing",))})
    foils = Part("blade", "foils", [cylinder(rf, 0.88 * hw, _ALONG_Y.at(float(x), 0, hh), role="foil") for x in xs],
                 regions={"push": Region(("foil",))})
    hl = builder.create_link("head", parent)
    hl.set_joint("revolute", translation(x0, 0, z0 + hy + rp), axis=(0.0, 1.0, 0.0), limits=(-a, a))
    hl.add(head)
    hl.add(foils)
    c, t = 0.001, p.uniform("cover_wall", 0.0012, 0.002)
    sk = p.uniform("cover_skirt", 0.4, 0.7) * hh
    ztop = hh + rf + 0.0005
    tp = p.uniform("cover_top", 0.0015, 0.0025)
    ox, oy = hd + 2 * (c + t), hw + 2 * (c + t)
    skirt = ztop - (hh - sk)
    cover = Part("cap", "foil_cover", [rect_ring(ox, oy, skirt, hd + 2 * c, hw + 2 * c,
                                                 translation(0, 0, (ztop + hh - sk) / 2), role="cover"),
                                       cuboid(ox, oy, tp, translation(0, 0, ztop + tp / 2), role="cover")],
                 regions={"pull": Region(("cover",)), "grasp": Region(("cover",)), "lift": Region(("cover",))},
                 grasps=Deferred.one(top_grasp, 0.0, 0.0, ztop - skirt / 2, ox + 0.02, "x"), actionable="slider_lid")
    cl = builder.create_link("cover", hl)
    cl.set_joint("prismatic", translation(), axis=(0.0, 0.0, 1.0), limits=(0.0, skirt + p.uniform("lift", 0.005, 0.02)))
    cl.add(cover)
    corners = np.array([[ox / 2, ztop + tp], [ox / 2, hh - sk], [hd / 2, 0.0], [hd / 2, hh]])
    corners = np.concatenate([corners, corners * (-1.0, 1.0)])
    xm, zm = _head_envelope(corners, a)
    return hl, cl, (x0 + xm, z0 + hy + rp + zm)


def popup_trimmer(p, builder, parent, D: float, W: float, H: float, head_reach):
    """Long-hair trimmer on the body's back (+x) face, slid up (prismatic +z): a plate
    with a toothed blade across its top. ``head_reach`` ((max x, min z) the head sweeps)
    limits how high it may rise where the head swings over it."""
    tw = p.uniform("trimmer_width", 0.4, 0.65) * W
    th = p.uniform("trimmer_height", 0.025, 0.045)
    t = p.uniform("trimmer_thickness", 0.003, 0.005)
    z_top = H - p.uniform("trimmer_drop", 0.008, 0.025)
    travel = p.uniform("trimmer_travel", 0.01, 0.02)
    if head_reach[0] > D / 2 - GAP:
        travel = min(travel, head_reach[1] - z_top - GAP)
    teeth = p.uniform("teeth", 0.002, 0.004)
    part = Part("blade", "popup_trimmer",
                [rounded_box(t, tw, th, min(0.4 * t, 0.002), translation(t / 2, 0, -th / 2 - teeth), role="slider"),
                 cuboid(0.6 * t, 0.9 * tw, teeth, translation(0.3 * t, 0, -teeth / 2), role="teeth")],
                regions={"push": Region(("slider",))})
    link = builder.create_link("trimmer", parent)
    link.set_joint("prismatic", translation(D / 2, 0, z_top), axis=(0.0, 0.0, 1.0), limits=(0.0, travel))
    link.add(part)
    return link


ROTARY_HEADS = {3: 3.0, 2: 1.0}  # cutter heads per rotary shaver: three on most, two on travel models


def rotary_head(p, builder, parent, top, D: float, W: float, n_heads=ROTARY_HEADS, open_range=(1.3, 1.9)):
    """Rotary head unit: a holder on the body's top hinged at its front edge (revolute
    about -y: it flips up and forward, ``open_range`` rad) carrying ``n_heads`` (a
    count: weight dict) round cutter heads, each continuous about its own axis. Returns the holder link."""
    x0, _, z0 = top
    n = int(p.choice("heads", n_heads))
    rc = p.uniform("cutter_radius", 0.01, 0.014)
    rr = (rc + p.uniform("cutter_gap", 0.001, 0.003)) / math.sin(math.pi / n)  # cutter centres round the axis
    Rh = rr + rc + p.uniform("rim", 0.002, 0.005)
    hh = p.uniform("holder_height", 0.01, 0.018)
    hinge = min(x0 - Rh, x0 - D / 2)  # at or in front of the body's front: what swings below the top is outside it
    holder = Part("head", "rotary_holder", [cylinder(Rh, hh, translation(Rh, 0, hh / 2), role="holder")],
                  regions={"lift": Region(("holder",)), "grasp": Region(("holder",))},
                  grasps=Deferred.one(top_grasp, Rh, 0.0, hh / 2, 2 * Rh + 0.02, "y"), actionable="hinge_lid")
    hl = builder.create_link("holder", parent)
    hl.set_joint("revolute", translation(hinge, 0, z0), axis=(0.0, -1.0, 0.0),
                 limits=(0.0, p.uniform("open", *open_range)))
    hl.add(holder)
    hc = p.uniform("cutter_height", 0.003, 0.006)
    phase = math.pi if n == 2 else math.pi / 2
    for i in range(n):
        ang = phase + 2 * math.pi * i / n
        q = p.scope(f"cutter{i}")
        cut = Part("blade", "rotary_cutter",
                   [cylinder(rc, hc, translation(0, 0, hc / 2), role="guard"),
                    cylinder(q.uniform("hub", 0.25, 0.4) * rc, 0.0015, translation(0, 0, hc + 0.00075), role="hub")],
                   regions={"push": Region(("guard",))})
        cl = builder.create_link("cutter", hl)
        cl.set_joint("continuous", translation(Rh + rr * math.cos(ang), rr * math.sin(ang), hh), axis=(0.0, 0.0, 1.0))
        cl.add(cut)
    return hl


def razor(p, builder, root, L: float, n_blades=(2, 5), pivot=(0.4, 0.8)):
    """Cartridge razor lying on its handle: the handle (``L`` long along x, flat side
    down, on ``root``), a neck and a hub across its -x end, and a cartridge hinged on the
    hub (revolute about y, tipping up by ``pivot`` rad) with ``n_blades`` blades along y
    on its top face. Returns the cartridge link."""
    w = p.uniform("handle_width", 0.011, 0.018)
    t = p.uniform("handle_thickness", 0.007, 0.012)
    nl = p.uniform("neck_length", 0.008, 0.016)
    rp = p.uniform("hub_radius", 0.0018, 0.003)
    cx, cw = p.uniform("cartridge_depth", 0.009, 0.014), p.uniform("cartridge_width", 0.034, 0.045)
    ct = p.uniform("cartridge_thickness", 0.004, 0.007)
    zh = max(t / 2 + p.uniform("rise", 0.0, 0.004), ct / 2 + 0.0015)
    xh = -L / 2 - nl
    handle = Part("handle", "razor_handle",
                  [rounded_box(L, w, t, min(0.45 * t, 0.004), translation(0, 0, t / 2), role="grip"),
                   cuboid(nl + rp, 0.5 * w, min(0.004, 2 * rp), translation(xh + (nl + rp) / 2, 0, zh), role="neck"),
                   cylinder(rp, 0.7 * w, _ALONG_Y.at(xh, 0, zh), role="neck")],
                  regions={"grasp": Region(("grip",)), "lift": Region(("grip",))})
    root.add(handle)
    n = p.integers("blades", *n_blades)
    bx = (np.arange(n) - (n - 1) / 2) * (0.6 * cx / max(n - 1, 1))
    cart = Part("head", "cartridge",
                [rounded_box(cx, cw, ct, min(0.4 * ct, 0.002), translation(-rp - cx / 2, 0, 0), role="cartridge")]
                + [cuboid(0.0008, 0.88 * cw, 0.0006, translation(-rp - cx / 2 + float(x), 0, ct / 2 + 0.0003),
                       role="blade")
                   for x in bx],
                regions={"grasp": Region(("cartridge",)), "push": Region(("blade",))})
    link = builder.create_link("cartridge", root)
    link.set_joint("revolute", translation(xh, 0, zh), axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("pivot", *pivot)))
    link.add(cart)
    return link
