"""Frames around openings and the leaves and sashes that close them (doors, windows).

Frame convention (``door_frame``, ``window_frame``): the origin is the centre of the
opening's bottom edge on the frame's front plane; the frame spans ``x in [0, depth]``
(its front faces -x), the opening ``y in [-width/2, width/2]`` and ``z in [0, height]``.

Leaves and sashes (``panel_leaf``, ``glazed_panel``) follow the front-panel convention
of :mod:`artipg.templates.panels`: origin at the centre of the back face, the panel
spans ``x in [-thickness, 0]``. Hinge them with
:func:`artipg.templates.mounting.mount_hinged` with ``front_x`` at the back face of
the inset leaf: the hinge line is then the leaf's front edge, which keeps the leaf
clear of the frame if the free edge keeps :func:`swing_clearance` to the frame.
"""

from __future__ import annotations

import math

import numpy as np

from artipg.geometry import cuboid, cuboid_between, cylinder, prism, rect_ring
from artipg.geometry.transforms import Placer, rot_y, translation
from artipg.model.part import Part, Region

_RING_TO_X = Placer(rot_y(np.pi / 2))  # rect ring's thickness axis (z) -> x


def swing_clearance(thickness: float, span: float, margin: float = 0.002) -> float:
    """Gap (metres) a leaf of ``thickness`` and ``span`` (hinge to free edge) needs at
    its free edge so that its back corner, which swings on a radius slightly longer
    than the span, does not graze the frame."""
    return thickness * thickness / (2.0 * span) + margin


def _front(t: float, w: float, h: float, role: str) -> tuple[dict, dict]:
    """Anchors (front, edge mid-points; ``stile`` is added by framed leaves: the middle
    of the +y stile on the front face) and the push region of a front panel."""
    anchors = {"front": (-t, 0.0, 0.0), "edge_+y": (-t, w / 2, 0.0), "edge_-y": (-t, -w / 2, 0.0),
               "edge_+z": (-t, 0.0, h / 2), "edge_-z": (-t, 0.0, -h / 2)}
    face = np.array([[-t - 1e-4, -w / 2, -h / 2], [-t + 1e-4, w / 2, h / 2]])
    return anchors, {"push": Region((role,), face)}


def door_frame(p, width: float, height: float, leaf_thickness: float, casing: bool | None = None,
               stops: bool = True) -> Part:
    """Jambs and head around a door opening, stops and an optional front casing.

    The stops sit behind the closed leaf (x from ``leaf_thickness``), so a leaf inset
    flush with the frame's front rests against them. Anchor ``front``: x of the
    frontmost face (the casing's when there is one).
    """
    d = p.uniform("depth", max(0.09, leaf_thickness + 0.03), 0.16)
    jw = p.uniform("jamb_width", 0.02, 0.045)
    sw, sd = p.uniform("stop_width", 0.01, 0.015), p.uniform("stop_depth", 0.01, 0.02)
    W, H, t = width / 2, height, leaf_thickness
    prims = [cuboid_between((0, -W - jw, 0), (d, -W, H + jw), role="jamb"),
             cuboid_between((0, W, 0), (d, W + jw, H + jw), role="jamb"),
             cuboid_between((0, -W, H), (d, W, H + jw), role="head")]
    if stops:
        prims += [cuboid_between((t, -W, 0), (t + sd, -W + sw, H), role="stop"),
                  cuboid_between((t, W - sw, 0), (t + sd, W, H), role="stop"),
                  cuboid_between((t, -W + sw, H - sw), (t + sd, W - sw, H), role="stop")]
    front = 0.0
    if p.flag("casing", 0.6, fixed=casing):
        cw, ct = p.uniform("casing_width", 0.05, 0.09), p.uniform("casing_thickness", 0.01, 0.02)
        r = p.uniform("reveal", 0.004, 0.008)
        prims += [cuboid_between((-ct, -W - r - cw, 0), (0, -W - r, H + r + cw), role="casing"),
                  cuboid_between((-ct, W + r, 0), (0, W + r + cw, H + r + cw), role="casing"),
                  cuboid_between((-ct, -W - r, H + r), (0, W + r, H + r + cw), role="casing")]
        front = -ct
    return Part("frame", "door_frame", prims, anchors={"top": (0.0, 0.0, H + jw), "front": (front, 0.0, 0.0)})


def window_frame(p, width: float, height: float, depth: float | None = None, sill: bool | None = None) -> Part:
    """Rectangular window frame (one ring) around the opening, optional front sill."""
    d = p.uniform("depth", 0.06, 0.12, fixed=depth)
    fw = p.uniform("frame_width", 0.035, 0.07)
    ring = rect_ring(height + 2 * fw, width + 2 * fw, d, height, width,
                     _RING_TO_X.at(d / 2, 0, height / 2), role="frame")
    prims = [ring]
    if p.flag("sill", 0.5, fixed=sill):
        over = p.uniform("sill_overhang", 0.02, 0.06)
        st = p.uniform("sill_thickness", 0.02, 0.035)
        prims.append(cuboid_between((-over, -width / 2 - fw - over, -fw - st), (d, width / 2 + fw + over, -fw),
                                    role="sill"))
    return Part("frame", "window_frame", prims, anchors={"frame_width": (fw, 0.0, 0.0), "depth": (d, 0.0, 0.0)})


def stop_ring(width: float, height: float, x0: float, depth: float, band: float, centre=(0.0, 0.0)) -> Part:
    """A stop bead: a thin ring ``band`` wide lining an opening of ``width`` x ``height``
    centred at ``centre`` (y, z), spanning ``x in [x0, x0 + depth]``."""
    cy, cz = centre
    return Part("frame", "stop_ring", [rect_ring(height, width, depth, height - 2 * band, width - 2 * band,
                                                 _RING_TO_X.at(x0 + depth / 2, cy, cz), role="stop")])


def panel_leaf(p, width: float, height: float, thickness: float | None = None, semantic: str = "door") -> Part:
    """Panelled (stile and rail) door leaf: a frame with 1-3 x 1-2 recessed panels."""
    t = p.uniform("thickness", 0.035, 0.045, fixed=thickness)
    rail = p.uniform("stile_width", 0.1, 0.14) * min(1.0, width / 0.7)
    rows = p.integers("panel_rows", 1, 3 if height > 1.0 else 1)
    cols = p.integers("panel_cols", 1, 2 if width > 0.5 else 1)
    mid = 0.8 * rail
    pw = (width - 2 * rail - (cols - 1) * mid) / cols
    ph = (height - 2 * rail - (rows - 1) * mid) / rows
    inset = p.uniform("panel_inset", 0.25, 0.4) * t
    prims = [rect_ring(height, width, t, height - 2 * rail, width - 2 * rail,
                       _RING_TO_X.at(-t / 2, 0, 0), role="panel"),
             cuboid(t - 2 * inset, width - 2 * rail, height - 2 * rail, translation(-t / 2, 0, 0), role="inset")]
    for i in range(1, rows):
        z = -height / 2 + rail + i * ph + (i - 0.5) * mid
        prims.append(cuboid(t, width - 2 * rail, mid, translation(-t / 2, 0, z), role="panel"))
    for j in range(1, cols):
        y = -width / 2 + rail + j * pw + (j - 0.5) * mid
        prims.append(cuboid(t, mid, height - 2 * rail, translation(-t / 2, y, 0), role="panel"))
    anchors, regions = _front(t, width, height, "panel")
    anchors["stile"] = (-t, width / 2 - rail / 2, 0.0)
    return Part(semantic, "panel_leaf", prims, anchors=anchors, regions=regions, actionable="hinge_door")


def glazed_panel(p, width: float, height: float, thickness: float | None = None, semantic: str = "sash",
                 rows: int | None = None, cols: int | None = None, rail: float | None = None):
    """A glazed leaf or sash: frame, glass and optional glazing bars (a grid of lites).

    Returns
    -------
    (Part, Part)
        The frame (``semantic``, with the glazing bars) and the glass (``glass``), both
        in the front-panel convention, to be added to the same link.
    """
    t = p.uniform("thickness", 0.04, 0.07, fixed=thickness)
    r = p.uniform("rail_width", 0.04, 0.08, fixed=rail)
    r = min(r, 0.25 * min(width, height))
    nr = p.integers("lite_rows", 1, max(1, min(4, int(height / 0.3))), fixed=rows)
    nc = p.integers("lite_cols", 1, max(1, min(3, int(width / 0.3))), fixed=cols)
    bar = p.uniform("bar_width", 0.015, 0.03)
    gw, gh = width - 2 * r, height - 2 * r
    prims = [rect_ring(height, width, t, gh, gw, _RING_TO_X.at(-t / 2, 0, 0), role="panel")]
    bt = 0.6 * t
    for i in range(1, nr):  # glazing bars on the lites' edges
        prims.append(cuboid(bt, gw, bar, translation(-t / 2, 0, -gh / 2 + i * (gh + bar) / nr - bar / 2), role="bar"))
    for j in range(1, nc):
        prims.append(cuboid(bt, bar, gh, translation(-t / 2, -gw / 2 + j * (gw + bar) / nc - bar / 2, 0), role="bar"))
    anchors, regions = _front(t, width, height, "panel")
    anchors["stile"] = (-t, width / 2 - r / 2, 0.0)
    act = "hinge_door" if semantic == "door" else "none"
    frame = Part(semantic, "glazed_panel", prims, anchors=anchors, regions=regions, actionable=act)
    gt = min(0.3 * t, p.uniform("glass_thickness", 0.004, 0.02))
    # one pane per lite, between the bars (no glass hidden inside them)
    lw, lh = (gw - (nc - 1) * bar) / nc, (gh - (nr - 1) * bar) / nr
    panes = [cuboid(gt, lw, lh, translation(-t / 2, (lw - gw) / 2 + j * (lw + bar), (lh - gh) / 2 + i * (lh + bar)),
                    role="glass") for i in range(nr) for j in range(nc)]
    return frame, Part("glass", "glazed_panel", panes)


def barn_hardware(p, width: float, thickness: float, span: tuple[float, float], drop: float):
    """Track and hangers of a sliding barn door ``width`` wide and ``thickness`` thick.

    Frame: origin at the top of the closed leaf's back face (centre), the leaf hanging
    below in x in [-thickness, 0]. The header board runs along y over ``span`` (y0, y1)
    behind the leaf's plane (its back face is the wall, anchor ``wall``) from ``drop``
    below the leaf top to above the rail; the rail stands off the header on spacers;
    two straps on the leaf's face carry rollers that sit on the rail.

    Returns
    -------
    (Part, Part)
        The track (``frame``: header, rail, spacers) for the parent and the hangers
        (``hinge``: straps, axles, rollers) for the leaf, both in this frame.
    """
    t = thickness
    hdr = p.uniform("header_thickness", 0.015, 0.025)
    gap = p.uniform("wall_gap", 0.005, 0.015)  # leaf back face to header front
    st, wt, e = p.uniform("strap_thickness", 0.005, 0.008), p.uniform("wheel_width", 0.012, 0.02), 0.003
    R, rt, rh = p.uniform("wheel_radius", 0.03, 0.05), p.uniform("rail_thickness", 0.006, 0.01), 0.03
    xr = -t + e + wt / 2  # wheel and rail centre line, behind the straps
    zr = p.uniform("rail_gap", 0.03, 0.06) + rh  # rail top above the leaf
    y0, y1 = span
    prims = [cuboid_between((gap, y0, -drop), (gap + hdr, y1, zr + 2 * R + 0.03), role="header"),
             cuboid_between((xr - rt / 2, y0, zr - rh), (xr + rt / 2, y1, zr), role="rail")]
    for k in range(4):
        y = y0 + 0.04 + k * (y1 - y0 - 0.08) / 3
        prims.append(cylinder(0.008, gap - xr, _RING_TO_X.at((xr + gap) / 2, y, zr - rh / 2),
                              role="spacer"))
    track = Part("frame", "barn_track", prims, anchors={"wall": (gap + hdr, 0.0, 0.0)})
    hw, zc = [], zr + R * math.cos(math.pi / 16)  # roller centre: a 16-gon standing on a flat
    for y in (-0.32 * width, 0.32 * width):  # strap on the leaf face, axle, roller on the rail
        hw += [cuboid_between((-t - st, y - 0.02, -0.12), (-t, y + 0.02, zc + 0.02), role="strap"),
               cylinder(0.006, e + 0.002, _RING_TO_X.at(-t + e / 2, y, zc), role="axle"),
               prism(R, wt, 16, _RING_TO_X.at(xr, y, zc), role="wheel")]
    return track, Part("hinge", "barn_hanger", hw)


def sash_tracks(p, width: float, height: float, sash_thickness: float, vertical: bool):
    """Guides for two tracks of sliding sashes in a window opening (frame convention
    above): lips at the front and back of the frame and a guide strip between the
    tracks, 2 mm clear of the sashes, along the head and the sill (sashes sliding
    sideways) or along the jambs (``vertical``: hung sashes sliding up and down).

    Returns
    -------
    (Part, float, (float, float))
        The guides, the frame depth they need, and the x of the sashes' front faces in
        the front and in the back track.
    """
    lt, gt, gh, e = p.uniform("lip", 0.008, 0.012), p.uniform("guide", 0.008, 0.012), p.uniform(
        "guide_height", 0.015, 0.025), 0.002
    ts, W, H = sash_thickness, width / 2, height
    depth = 2 * lt + 4 * e + 2 * ts + gt
    xs = ((0.0, lt), (lt + 2 * e + ts, lt + 2 * e + ts + gt), (depth - lt, depth))
    if vertical:
        prims = [cuboid_between((x0, y0, 0), (x1, y0 + gh, H), role="guide") for x0, x1 in xs for y0 in (-W, W - gh)]
    else:
        prims = [cuboid_between((x0, -W, z0), (x1, W, z0 + gh), role="guide") for x0, x1 in xs for z0 in (0, H - gh)]
    return Part("frame", "sash_tracks", prims), depth, (lt + e, lt + 3 * e + ts + gt)


def inset_leaf(width: float, height: float, side: str, thickness: float, gap: float):
    """Size and centre offset of a leaf hinged on ``side`` ("+y", "-y", "+z", "-z") of
    a ``width`` x ``height`` opening: ``gap`` on the hinge side and the two sides
    along the hinge, :func:`swing_clearance` on the free side.

    Returns
    -------
    ((float, float), (float, float))
        The leaf's (width, height) and its centre's (dy, dz) from the opening's centre.
    """
    s = 1.0 if side[0] == "+" else -1.0
    if side[1] == "y":
        cf = swing_clearance(thickness, width, gap)
        return (width - gap - cf, height - 2 * gap), (s * (cf - gap) / 2, 0.0)
    cf = swing_clearance(thickness, height, gap)
    return (width - 2 * gap, height - gap - cf), (0.0, s * (cf - gap) / 2)
