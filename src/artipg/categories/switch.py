"""Wall switches: rocker switches, toggle switches, push-button panels, dimmers and
surface-mounted switch boxes.

Parts: a cover plate (flat, stepped, or a European frame around a flush insert) on
the wall, or a deep surface-mounted box (as deep as 0.6-1.6 times its width, like the
boxy switches of the PartNet-Mobility development split), facing -x, carrying 1-4
switch modules side by side (push buttons also in
a 2 x 2 grid): rocker paddles (flat or crowned) in bezels, toggle levers on small
escutcheon bosses, push-button caps (round or rectangular), and, on dimmers, a
rotary knob next to an optional rocker or toggle.
Joints: rockers and toggles revolute about a horizontal axis (y), resting in one
position (tilted by -tilt) with range 2 tilt (rockers +-5-12 deg, toggles +-17-26 deg);
buttons prismatic into the wall (3-6 mm); dimmer knobs revolute (250-300 deg).
Sizes (metres): plates 0.06-0.12 tall, 0.05-0.22 wide, modules 0.025-0.05 apart.
"""

from __future__ import annotations

import math

from artipg.geometry.transforms import translation
from artipg.rules import Category, Slot
from artipg.templates.controls import (BUTTONS, fluted_knob, mount_button, mount_knob, rect_button, round_button,
                                       round_knob)
from artipg.templates.wall_switch import (PLATE_MARGIN, PLATES, ROCKERS, button_bezel, rocker_module, surface_box,
                                         toggle_module)

# sub-category -> number of modules, module pitch (y), plate height
SUBS = {
    "rocker": ((1, 4), (0.036, 0.05), (0.08, 0.12)),
    "toggle": ((1, 3), (0.038, 0.047), (0.1, 0.12)),
    "push_button": ((1, 4), (0.024, 0.034), (0.06, 0.09)),
    "dimmer": ((1, 2), (0.042, 0.05), (0.08, 0.12)),
    "surface_box": ((1, 2), (0.04, 0.05), (0.07, 0.11)),
}
KNOBS = {round_knob: 2.0, fluted_knob: 1.0}


def plate(ctx):
    p = ctx.p
    nr, pr, hr = SUBS[ctx.sub]
    n = p.integers("modules", *nr)
    pitch = p.uniform("pitch", *pr)
    cols = 2 if ctx.sub == "push_button" and n == 4 and p.flag("grid", 0.6) else n
    rows = n // cols
    tmpl = ctx.choose("plate", {surface_box: 1.0} if ctx.sub == "surface_box" else PLATES)
    margin = PLATE_MARGIN[tmpl] + p.uniform("margin", 0.0, 0.01)
    H = max(p.uniform("height", *hr), rows * pitch + 2 * margin)
    W = max(cols * pitch + 2 * margin, p.uniform("min_width", 0.05, 0.07))
    kw = {"depth": p.uniform("depth_ratio", 0.6, 1.6) * W} if tmpl is surface_box else {}
    root = ctx.builder.create_link("plate")
    part = root.add(tmpl(p, W, H, **kw))
    face = part.anchor("face")[0]
    ch = (H - 2 * margin) / rows
    cells = [(-(cols - 1) / 2 * pitch + c * pitch, ((rows - 1) / 2 - r) * ch) for r in range(rows) for c in range(cols)]
    return root, face, cells, pitch, ch


def modules(ctx):
    root, face, cells, cw, ch = ctx.out["plate"]
    p = ctx.p
    rocker = ctx.choose("rocker", ROCKERS)
    button = ctx.choose("button", BUTTONS)
    side = ctx.p.choice("side_module", ("rocker", "toggle")) if ctx.sub in ("dimmer", "surface_box") else None
    for i, (y, z) in enumerate(cells):
        q = p.scope(f"m{i}")
        pose = translation(face, y, z)
        kind = {"dimmer": "knob" if i == 0 else side, "surface_box": side}.get(ctx.sub, ctx.sub)
        if kind == "rocker":
            w = q.uniform("width", 0.5, 0.72) * cw
            h = q.uniform("height", 0.55, 0.85) * (ch - 0.012)
            rocker_module(q, ctx.builder, root, pose, w, h, rocker)
        elif kind == "toggle":
            toggle_module(q, ctx.builder, root, pose, cw - 0.008, ch - 0.008)
        elif kind == "push_button":
            s = min(cw, ch) - 0.006
            if button is round_button:
                part = round_button(q, radius=q.uniform("radius", 0.3, 0.5) * s)
            else:
                part = rect_button(q, width=q.uniform("width", 0.6, 1.0) * s, height=q.uniform("height", 0.6, 1.0) * s)
            root.add(button_bezel(q, part, pose, button is round_button), name="bezel")
            mount_button(ctx.builder, root, part, pose)
        else:
            knob = ctx.choose("knob", KNOBS)(q, radius=q.uniform("radius", 0.3, 0.42) * min(cw, ch))
            mount_knob(ctx.builder, root, knob, pose, continuous=False,
                       limits=(0.0, math.radians(q.uniform("sweep", 250.0, 300.0))))


RULE = Category(
    name="switch",
    subcategories={"rocker": 3.0, "toggle": 2.0, "push_button": 2.0, "dimmer": 1.0, "surface_box": 3.0},
    fixed_base=True,  # mounted on a wall: simulated mounted, not dropped on a floor
    materials={"body": "plastic"},
    mass_range=(0.005, 1.0),  # kg: a wall plate with its modules; a surface box (modelled solid) up to ~0.9
    slots=(Slot("plate", plate), Slot("modules", modules, after=("plate",))),
)
