"""Rulers: folding rules, tape measures and hinged rules.

Plain straight rulers have no moving part: the category leaves them out and covers
the articulated kinds only.

Parts and joints per sub-category:
- folding rule: 4-10 flat segments (wood; round, chamfered or square ends) riveted
  end to end in a zig-zag; each segment revolute about the rivet (z) it shares with
  the previous one, 0 = folded back onto it (the rule folds into a stack, each
  segment one layer up), pi = straight out; the joints turn in alternate senses, so
  opened alike they make the rule's zig-zag. Open, the rule is a shallow staircase
  of those layers (a rigid model of the segments' tilt).
- tape measure: a plastic case (two cheeks, the core above the blade slot, the floor
  under it) with a belt clip on one side; the steel blade with its end hook is
  prismatic out of the mouth (-x, 0 = hook against the case), a lock slider on the
  front is prismatic down (0 = unlocked, up). The blade is the rigid straight strip
  that fits in the case (a real blade coils on a drum): it pulls out 0.03-0.09 m.
- hinged rule: two long aluminium arms on a hinge disc, revolute 0 (folded) to pi.
Sizes (metres): folding-rule segments 0.1-0.2 long (1 m and 2 m rules), 14-18 mm wide,
2.5-4 mm thick; tape cases 0.05-0.09 high, 0.9-1.15 of that deep, 0.028-0.05 wide,
blades 0.45-0.62 of the case width (13-30 mm); hinged-rule arms 0.25-0.5 long,
18-30 mm wide, 1.5-3 mm thick.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import rot_z, translation
from artipg.rules import Category, Slot
from artipg.templates.rules_tapes import (RIVET_HEAD, SEGMENT_ENDS, belt_clip, lock_slider, segment, tape_blade,
                                          tape_case)

# folding sub-categories: label, segment count, length, width, thickness, rivet radius (of the width)
FOLDING = {
    "folding_rule": ("segment", (4, 10), (0.1, 0.2), (0.014, 0.018), (0.0025, 0.004), (0.18, 0.26)),
    "hinged_rule": ("arm", (2, 2), (0.25, 0.5), (0.018, 0.03), (0.0015, 0.003), (0.35, 0.45)),
}
LAYER_GAP = RIVET_HEAD + 0.0003  # between stacked segments (over the rivet heads)
SLOT_CLEAR = 0.001  # the blade in its slot, above and below and at the sides


def folding(ctx):
    p = ctx.p
    semantic, nr, lr, wr, tr, rr = FOLDING[ctx.sub]
    n = p.integers("segments", *nr)
    L, w, t = p.uniform("segment_length", *lr), p.uniform("width", *wr), p.uniform("thickness", *tr)
    rivet = p.uniform("rivet", *rr) * w
    ends = ctx.choose("ends", SEGMENT_ENDS)
    pitch = L - w
    link = ctx.builder.create_link("segment")
    link.add(segment(p, ends, semantic, pitch, w, t, 0.0, 0.5 * pitch))
    for k in range(1, n):
        child = ctx.builder.create_link("segment", link)
        # alternate senses: joints opened alike make the zig-zag of a real rule
        child.set_joint("revolute", translation(pitch, 0.0, t + LAYER_GAP) @ rot_z(math.pi),
                        axis=(0.0, 0.0, 1.0 if k % 2 else -1.0), limits=(0.0, math.pi))
        child.add(segment(p, ends, semantic, pitch, w, t, rivet, 0.5 * pitch))
        link = child


def tape(ctx):
    p = ctx.p
    H = p.uniform("height", 0.05, 0.09)
    Lc, W = p.uniform("depth", 0.9, 1.15) * H, p.uniform("width", 0.028, 0.05)
    wb, tb = min(p.uniform("blade_width", 0.45, 0.62) * W, W - 0.01), p.uniform("blade_thickness", 0.0003, 0.0005)
    z0 = p.uniform("floor", 0.002, 0.004)
    slot = (z0, z0 + 2 * SLOT_CLEAR + tb)
    root = ctx.builder.create_link("case")
    case = tape_case(p, Lc, W, H, slot, wb + 2 * SLOT_CLEAR)
    root.add(case)
    z_front = case.anchors["front_top"][2]  # the front face is flat up to here
    hook = (p.uniform("hook_depth", 0.0008, 0.0012), z0 + SLOT_CLEAR - 0.0005, p.uniform("hook_rise", 0.003, 0.006))
    strip = Lc - 0.004
    travel = strip - p.uniform("inside", 0.01, 0.015)
    blade = ctx.builder.create_link("blade", root)
    blade.set_joint("prismatic", translation(0.0, 0.0, z0 + SLOT_CLEAR), axis=(-1.0, 0.0, 0.0), limits=(0.0, travel))
    blade.add(tape_blade(p, strip, wb, tb, hook, 0.5 * travel))
    # the lock slider on the front, clear of the hook at its lowest
    ts = p.uniform("lock_travel", 0.003, 0.005)
    low = z0 + SLOT_CLEAR + tb + hook[2] + 0.0015 + ts
    hs = min(p.uniform("lock_height", 0.008, 0.014), z_front - 0.001 - low)
    lock = ctx.builder.create_link("lock", root)
    lock.set_joint("prismatic", translation(-0.0002, 0.0, low + hs / 2), axis=(0.0, 0.0, -1.0), limits=(0.0, ts))
    lock.add(lock_slider(p, p.uniform("lock_width", 0.4, 0.65) * W, hs, p.uniform("lock_depth", 0.003, 0.005)))
    if p.flag("belt_clip", 0.8):
        lc = min(p.uniform("clip_length", 0.3, 0.5) * Lc, case.anchors["top_flat"][0])
        clip = belt_clip(p, lc, p.uniform("clip_height", 0.5, 0.75) * H, p.uniform("clip_gap", 0.002, 0.004),
                         p.uniform("clip_thickness", 0.001, 0.0015))
        root.add(clip, translation(Lc / 2, W / 2, H - 0.002))


def ruler(ctx):
    return (tape if ctx.sub == "tape_measure" else folding)(ctx)


RULE = Category(
    name="ruler",
    subcategories={"folding_rule": 2.0, "tape_measure": 2.0, "hinged_rule": 1.0},
    mass_range=(0.02, 1.0),  # kg: a 4-segment 0.5 m rule to a large tape measure or long hinged rule
    materials={"segment": "wood", "arm": "aluminium", "body": "plastic"},
    slots=(Slot("ruler", ruler),),
)
