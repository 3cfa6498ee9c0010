"""Windows: casement, awning/hopper, horizontal sliding and double-hung sash windows.

Parts: a rectangular frame (optional front sill); sashes made of a stile-and-rail
frame, glass and optional glazing bars (one to four rows and one to three columns of
lites). Casement windows split the opening with mullions into 1-3 sections, each with
a side-hung sash (revolute about its vertical front edge, opening inwards towards the
viewer, -x, 0..1.2-1.7 rad) or a fixed pane, sashes resting on a stop bead; an
opening sash carries a window handle (fixed base plate, lever revolute 0..pi/2 about
the sash normal). Awning sashes are top-hung (bottom swings out, 0..0.3-0.8 rad) or
bottom-hung hoppers (0..0.2-0.4 rad) with a fixed pull. Sliding windows run 2-3
sashes in two tracks separated by guide strips: sashes in the front track slide
along y (prismatic), those in the back track are fixed or slide the other way.
Double-hung windows run the lower sash up (prismatic +z) in the front track and the
upper sash down (or fixed: single-hung) in the back one; lift handles on the lower rail.
Joints: 1-6 movable. Sizes (metres): 0.4-2.4 wide, 0.4-1.8 tall, frames 35-70 mm.
"""

from __future__ import annotations

import copy
import math

from artipg.geometry import cuboid_between
from artipg.geometry.transforms import Placer, rot_x, translation
from artipg.rules import Category, Slot
from artipg.templates.frames import glazed_panel, inset_leaf, sash_tracks, stop_ring, window_frame
from artipg.templates.handles import arch_handle, edge_pull, flat_bar_handle
from artipg.templates.mounting import free_edge_yz, mount_hinged, mount_sliding
from artipg.templates.turn_handles import casement_handle, mount_turning, replay

# sub-category -> section (casement, awning) or window (sliding, hung) width, height,
# sections or sashes (lo, hi), sash thickness
SIZES = {"casement": ((0.4, 0.75), (0.6, 1.6), (1, 3), (0.045, 0.07)),
         "awning": ((0.5, 1.0), (0.4, 0.8), (1, 2), (0.045, 0.065)),
         "sliding": ((0.8, 2.4), (0.6, 1.5), (2, 3), (0.025, 0.04)),
         "double_hung": ((0.5, 1.2), (0.9, 1.8), (2, 2), (0.035, 0.045))}
PULLS = {arch_handle: 1.0, flat_bar_handle: 1.0, edge_pull: 1.0}
AWNING_HINGES = {"+z": 2.0, "-z": 1.0}
FLAT = Placer(rot_x(math.pi / 2))  # a pull's long axis along y


def frame(ctx):
    p = ctx.p
    w, h, n, t = SIZES[ctx.sub]
    W, H, n, ts = p.uniform("width", *w), p.uniform("height", *h), p.integers("sections", *n), p.uniform(
        "sash_thickness", *t)
    root = ctx.builder.create_link("frame")
    if ctx.sub in ("sliding", "double_hung"):  # the frame's profile includes the tracks
        tracks, depth, xs = sash_tracks(p.scope("tracks"), W, H, ts, vertical=ctx.sub == "double_hung")
        fr = root.add(window_frame(p.scope("frame"), W, H, depth=depth))
        fr.primitives += tracks.primitives
        return root, dict(W=W, H=H, n=2 if W < 1.5 else n, ts=ts, tracks=xs)
    mw = p.uniform("mullion", 0.04, 0.07)
    Wo = n * W + (n - 1) * mw
    fr = root.add(window_frame(p.scope("frame"), Wo, H, depth=ts + p.uniform("stop_room", 0.02, 0.05)))
    ys = [-Wo / 2 + W / 2 + i * (W + mw) for i in range(n)]
    # one frame part: the ring, the mullions and a stop bead lining each section
    fr.primitives += [cuboid_between((0, y + W / 2, 0), (fr.anchor("depth")[0], y + W / 2 + mw, H), role="mullion")
                      for y in ys[:-1]]
    band, sd = p.uniform("stop_band", 0.01, 0.015), p.uniform("stop_depth", 0.008, 0.015)
    for y in ys:
        fr.primitives += stop_ring(W, H, ts, sd, band, (y, H / 2)).primitives
    return root, dict(W=W, H=H, n=n, ts=ts, ys=ys)


def sashes(ctx):
    root, d = ctx.out["frame"]
    p, ts, W, H = ctx.p, d["ts"], d["W"], d["H"]
    c = p.uniform("gap", 0.002, 0.004)
    bars = p.flag("glazing_bars", 0.4)
    grid = dict(rows=p.integers("rows", 1, 3) if bars else 1, cols=p.integers("cols", 1, 3) if bars else 1,
                rail=p.uniform("rail", 0.035, 0.07))

    def sash(q, w, h):  # the same style for every sash of the window
        return glazed_panel(q, w, h, ts, "sash", rows=min(grid["rows"], max(1, int(h / 0.2))),
                            cols=min(grid["cols"], max(1, int(w / 0.2))), rail=grid["rail"])
    if ctx.sub == "sliding":
        return _sliding(ctx, root, d, c, sash, grid["rail"])
    if ctx.sub == "double_hung":
        return _hung(ctx, root, d, c, sash, grid["rail"])
    if ctx.sub == "awning":  # top-hung, or bottom-hung (a hopper)
        hinge, pull_t = p.choice("awning_hinge", AWNING_HINGES), ctx.choose("pull", PULLS)
        lim = p.uniform("awning_limit", 0.3, 0.8) if hinge == "+z" else p.uniform("hopper_limit", 0.2, 0.4)
    else:
        hinge, lim = None, p.uniform("limit", 1.2, 1.7)
    fixed_mid = d["n"] == 3 and p.flag("fixed_middle", 0.6)
    # one handle design for every sash: drawn once, then copied (casement handles) or
    # replayed (pulls, whose length follows the sash)
    hq, built, handle = p.scope("handle"), False, None
    for i, y in enumerate(d["ys"]):
        q = p.scope(f"sash{i}")
        if fixed_mid and i == 1:
            _place(ctx, root, sash(q, W - 2 * c, H - 2 * c), translation(ts, y, H / 2))
            continue
        outer = "-y" if i == 0 else "+y" if i == d["n"] - 1 else None  # side sashes hinge on the jambs
        side = hinge or (outer if d["n"] > 1 and outer else q.choice("hinge", ("+y", "-y")))
        vertical, sgn = side[1] == "y", 1.0 if side[0] == "+" else -1.0
        (sw, sh), (dy, dz) = inset_leaf(W, H, side, ts, c)
        cy, cz = y + dy, H / 2 + dz
        frame_part, glass = sash(q, sw, sh)
        link = mount_hinged(ctx.builder, root, frame_part, front_x=ts, center_yz=(cy, cz), size_yz=(sw, sh),
                            side=side, limits=(0.0, lim), name="sash")
        link.add(glass, frame_part.pose)
        hy, hz = free_edge_yz(side, (sw, sh), grid["rail"] / 2)
        front = frame_part.pose @ translation(-ts, hy, hz)
        if vertical:  # window handle: fixed base, lever pointing down, a quarter turn
            if handle is None:
                base, lever = handle = casement_handle(hq)
            else:
                base, lever = copy.copy(handle[0]), copy.copy(handle[1])
            link.add(base, front)
            mount_turning(ctx.builder, link, lever, front @ translation(base.anchor("mount")[0], 0, 0),
                          (0.0, math.pi / 2), name="handle", axis=(sgn, 0.0, 0.0))  # towards the hinge
        else:
            hp, built = replay(hq) if built else hq, True
            link.add(pull_t(hp, length=min(0.2, 0.4 * sw)), front @ FLAT.matrix)


def _place(ctx, root, sash, origin, axis=None, travel=0.0):
    """Add a sash (frame, glass) fixed in the frame, or sliding along ``axis``."""
    frame_part, glass = sash
    if axis is None:
        link = root
        link.add(frame_part, origin)
    else:
        link = mount_sliding(ctx.builder, root, frame_part, origin=origin, axis=axis, limits=(0.0, travel), name="sash")
    link.add(glass, frame_part.pose)
    return link


def _sliding(ctx, root, d, c, sash, rail):
    p, ts, Wo, H, n = ctx.p, d["ts"], d["W"], d["H"], d["n"]
    xa, xb = d["tracks"]
    ov = p.uniform("overlap", 0.03, 0.06)
    sh = H - 2 * c
    if n == 2:
        ws = (Wo + ov) / 2 - c
        travel = Wo - ws - 2 * c - 0.002
        s = p.choice("direction", (1.0, -1.0))
        specs = [(xa, -s * (Wo / 2 - c - ws / 2), s, travel), (xb, s * (Wo / 2 - c - ws / 2),
                                                                 -s if p.flag("both_slide", 0.5) else 0.0, travel)]
    else:  # XOX: fixed centre pane behind, side sashes slide towards the centre
        wc = Wo / 2 + 2 * ov
        ws = (Wo - wc) / 2 + ov - c
        travel = (Wo - 2 * c - 2 * ws) / 2 - 0.002
        y = Wo / 2 - c - ws / 2
        specs = [(xb, 0.0, 0.0, 0.0), (xa, -y, 1.0, travel), (xa, y, -1.0, travel)]
    pull = ctx.choose("pull", PULLS)
    for i, (x, y, s, travel) in enumerate(specs):
        w = wc if n == 3 and i == 0 else ws
        link = _place(ctx, root, sash(p.scope(f"sash{i}"), w, sh), translation(x + ts, y, H / 2),
                      (0, s, 0) if s else None, travel)
        if s and x == xa:  # pull on the stile that leads the sash open
            hy = s * (w / 2 - rail / 2)
            link.add(pull(p.scope(f"pull{i}"), length=min(0.2, 0.3 * sh)), translation(-ts, -hy, 0.0))


def _hung(ctx, root, d, c, sash, rail):
    p, ts, W, H = ctx.p, d["ts"], d["W"], d["H"]
    xa, xb = d["tracks"]
    ov = p.uniform("meeting_overlap", 0.03, 0.05)
    hs, ws = (H + ov) / 2 - c, W - 2 * c
    travel = H - 2 * c - hs - 0.002
    link = _place(ctx, root, sash(p.scope("lower"), ws, hs), translation(xa + ts, 0.0, c + hs / 2), (0, 0, 1), travel)
    _place(ctx, root, sash(p.scope("upper"), ws, hs), translation(xb + ts, 0.0, H - c - hs / 2),
           (0, 0, -1) if p.flag("double_hung", 0.6) else None, travel)  # or single-hung
    tmpl, k = ctx.choose("lift", PULLS), p.integers("lifts", 1, 2)
    for i in range(k):
        y = 0.0 if k == 1 else (i - 0.5) * 0.5 * ws
        h = tmpl(p.scope(f"lift{i}"), length=min(0.12, 0.25 * ws))
        link.add(h, FLAT.at(-ts, y, -hs / 2 + rail / 2))


RULE = Category(
    name="window",
    subcategories={"casement": 3.0, "sliding": 2.0, "double_hung": 2.0, "awning": 1.0},
    fixed_base=True,  # set in a wall opening: simulated mounted, not dropped on a floor
    mass_range=(5.0, 150.0),  # kg: frame + sashes + glazing of one opening
    slots=(Slot("frame", frame), Slot("sashes", sashes, after=("frame",))),
)
