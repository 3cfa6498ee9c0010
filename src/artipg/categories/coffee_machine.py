"""Coffee machines: drip (filter) machines, semi-automatic espresso machines and
capsule machines.

Parts: a housing of a back tower, a plinth and a head over the front bay where the cup
or carafe stands. Drip: a water-tank lid on the tower top, a filter basket in the
head (a drawer, or swinging out on a side hinge), a warming plate with a glass carafe
on it, 1-3 buttons (power, programme) on the plinth front. Espresso: a group head under the head with a portafilter, a steam
wand beside it, 1-2 knobs (steam, hot water) and 0-4 buttons on the head front, a
water-tank lid on top, a drip tray in the bay. Capsule: a capsule lever over the head,
a water tank standing behind the tower, 1-3 buttons on the head front, a drip tray.
Joints: tank lids revolute about their back edge (+y), 70-100 degrees; swing-out
filter baskets revolute about a vertical front edge, 75-100 degrees; filter drawer
and drip trays prismatic out of the front (-x), 60-90 % of their depth; carafe
prismatic out of the front (slid off the warming plate); portafilter revolute about
the group head's vertical axis, 35-45 degrees from locked; steam wand revolute about x,
35-60 degrees outwards; knobs continuous or revolute (270-300 degrees); buttons
prismatic into the panel (3-6 mm); capsule lever revolute about its back edge,
75-90 degrees; water tank prismatic up, 0.12-0.2 m.
Sizes (metres): drip 0.3-0.4 tall, 0.18-0.28 wide, 0.2-0.28 deep; espresso 0.3-0.4 x
0.22-0.34 x 0.25-0.35; capsule 0.24-0.33 tall, 0.11-0.2 wide, 0.3-0.42 deep with the
tank.
"""

from __future__ import annotations

from artipg.geometry import cuboid_between, cylinder
from artipg.geometry.transforms import translation
from artipg.model.part import Part
from artipg.rules import Category, Slot
from artipg.templates.coffee import (capsule_lever, carafe, coffee_housing, drip_tray, portafilter, steam_wand,
                                     swing_basket, top_lid, water_tank)
from artipg.templates.controls import BUTTONS, KNOBS, mount_button_row, mount_knob
from artipg.templates.mounting import mount_hinged
from artipg.templates.panels import DRAWERS

# sub-category -> depth, width, height, bay depth (share of depth), head height ranges (metres)
SUBS = {
    "drip": ((0.2, 0.28), (0.18, 0.28), (0.3, 0.4), (0.6, 0.72), (0.07, 0.1)),
    "espresso": ((0.25, 0.35), (0.22, 0.34), (0.3, 0.4), (0.38, 0.5), (0.08, 0.12)),
    "capsule": ((0.22, 0.3), (0.11, 0.2), (0.24, 0.33), (0.38, 0.5), (0.08, 0.11)),
}
FILTERS = {"drawer": 1.0, "swing": 1.0}  # a drip machine's filter basket slides or swings out
REST = 0.0008  # rest gap of lids, trays and carafes on the surface under them


def body(ctx):
    p, b = ctx.p, ctx.builder
    dr, wr, hr, br, hh = SUBS[ctx.sub]
    D, W, H = p.uniform("depth", *dr), p.uniform("width", *wr), p.uniform("height", *hr)
    bay = p.uniform("bay", *br) * D
    roof = H - p.uniform("head", *hh)
    floor = p.uniform("plinth", 0.035, 0.06) if ctx.sub == "drip" else p.uniform("plinth", 0.01, 0.03)
    cavity = None
    if ctx.sub == "drip":
        cavity = (H - roof - p.uniform("cavity_margin", 0.02, 0.03), W - 2 * p.uniform("cavity_side", 0.012, 0.02))
    root = b.create_link("body")
    housing = coffee_housing(p.scope("housing"), D, W, H, bay, floor, roof, cavity)
    root.add(housing)
    if ctx.sub != "capsule":  # the water tank's lid on the tower top, hinged at its back edge
        lid = top_lid(p.scope("tank_lid"), p.uniform("lid_depth", 0.6, 0.85) * (D - bay), W - 0.02)
        link = b.create_link("lid", root)
        link.set_joint("revolute", translation(D / 2 - 0.004, 0, H + REST - lid.anchors["bottom"][2]),
                       axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("lid_swing", 1.2, 1.75)))
        link.add(lid)
    return root, housing, (D, W, H, bay, floor, roof)


def drip(ctx):
    """Filter drawer, warming plate, carafe and plinth buttons of a drip machine."""
    root, housing, (D, W, H, bay, floor, roof) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    (_, y0, z0), (_, y1, z1) = housing.anchors["cavity_lo"], housing.anchors["cavity_hi"]
    ch, cw = z1 - z0, y1 - y0
    if ctx.choose("filter", FILTERS) == "swing":
        # a cup of radius <= 0.2 of the cavity width sweeps inside the cavity: every
        # point behind the panel stays within the cavity width of the hinge line
        rc = min(p.uniform("cup_radius", 0.035, 0.055), 0.2 * cw, (bay - 0.03) / 2)
        basket = swing_basket(p.scope("basket"), cw + 0.008, ch + 0.006, rc)
        side = "+y" if p.flag("hinge_left", 0.5) else "-y"
        mount_hinged(b, root, basket, front_x=-D / 2, center_yz=(0.0, (z0 + z1) / 2), size_yz=(cw + 0.008, ch + 0.006),
                     side=side, limits=(0.0, p.uniform("basket_swing", 1.3, 1.75)), name="drawer")
    else:
        t = p.uniform("drawer_front", 0.008, 0.014)
        drawer = ctx.choose("drawer", DRAWERS)(p.scope("drawer"), cw + 0.008, ch + 0.006, bay - 0.012,
                                               (-cw / 2 + 0.0015, cw / 2 - 0.0015, -ch / 2 + 0.0015, ch / 2 - 0.0015),
                                               thickness=t)
        link = b.create_link("drawer", root)
        link.set_joint("prismatic", translation(-D / 2, 0, (z0 + z1) / 2), axis=(-1.0, 0.0, 0.0),
                       limits=(0.0, p.uniform("drawer_pull", 0.6, 0.9) * (bay - 0.012)))
        link.add(drawer)
    xc = -D / 2 + bay / 2
    R = min(p.uniform("carafe_radius", 0.06, 0.08), 0.45 * bay - 0.012, 0.45 * W)
    pt = p.uniform("plate", 0.004, 0.008)
    root.add(Part("body", "warming_plate", [cylinder(1.04 * R, pt, translation(xc, 0, floor + pt / 2),
                                                     role="plate")]))
    hc = roof - floor - pt - REST - p.uniform("headroom", 0.008, 0.02)
    jug = carafe(p.scope("carafe"), R, hc)
    link = b.create_link("carafe", root)
    link.set_joint("prismatic", translation(xc, 0, floor + pt + REST), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, p.uniform("carafe_pull", 0.15, 0.25)))
    link.add(jug)
    k = p.integers("buttons", 1, 3)
    span = min(W - 0.04, 0.035 * k)
    h = floor - 0.012
    mount_button_row(p.scope("buttons"), b, root, ctx.choose("button", BUTTONS), k, translation(-D / 2, 0, 0),
                     -span / 2, span / 2, floor / 2, radius=min(0.008, h / 2), square=(min(0.02, span / k - 0.01), h))


def espresso(ctx):
    """Group head and portafilter, steam wand, knobs and buttons, drip tray."""
    root, housing, (D, W, H, bay, floor, roof) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    xg = -D / 2 + p.uniform("group_x", 0.35, 0.45) * bay
    rg, hg = p.uniform("group_radius", 0.03, 0.04), p.uniform("group_height", 0.015, 0.03)
    root.add(Part("body", "group_head", [cylinder(rg, hg, translation(xg, 0, roof - hg / 2), role="group")]))
    pf = portafilter(p.scope("portafilter"), rg - p.uniform("basket_inset", 0.0, 0.004),
                     p.uniform("basket_depth", 0.02, 0.03))
    link = b.create_link("portafilter", root)
    link.set_joint("revolute", translation(xg, 0, roof - hg - REST), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, p.uniform("lock_turn", 0.6, 0.78)))
    link.add(pf)
    tray_h = p.uniform("tray_height", 0.02, 0.035)
    _tray(ctx, D, W, bay, floor, tray_h)
    # the steam wand hangs beside the group head on the +y side, swinging outwards
    rb = p.uniform("wand_ball", 0.008, 0.012)
    zw = roof - rb
    wand = steam_wand(p.scope("wand"), min(p.uniform("wand_length", 0.1, 0.15), zw - floor - tray_h - 0.04), rb)
    link = b.create_link("wand", root)
    link.set_joint("revolute", translation(xg, W / 2 - p.uniform("wand_inset", 0.025, 0.04), zw),
                   axis=(1.0, 0.0, 0.0), limits=(0.0, p.uniform("wand_swing", 0.6, 1.05)))
    link.add(wand)
    _head_controls(ctx, D, W, H, roof, p.integers("knobs", 1, 2), p.integers("buttons", 0, 4))


def capsule(ctx):
    """Capsule lever, water tank behind the tower, head buttons, drip tray."""
    root, housing, (D, W, H, bay, floor, roof) = ctx.out["body"]
    p, b = ctx.p, ctx.builder
    L = p.uniform("lever_length", 0.08, 0.13)
    lever = capsule_lever(p.scope("lever"), L, W - p.uniform("lever_inset", 0.0, 0.02))
    link = b.create_link("lever", root)
    link.set_joint("revolute", translation(-D / 2 + L, 0, H + REST - lever.anchors["bottom"][2]),
                   axis=(0.0, 1.0, 0.0), limits=(0.0, p.uniform("lever_swing", 1.3, 1.57)))
    link.add(lever)
    _tray(ctx, D, W, bay, floor, p.uniform("tray_height", 0.015, 0.03))
    dt, zb = p.uniform("tank_depth", 0.07, 0.11), p.uniform("tank_base", 0.01, 0.03)
    root.add(Part("body", "tank_base", [cuboid_between((D / 2, -W / 2, 0.0), (D / 2 + dt + 0.004, W / 2, zb),
                                                       role="base")]))
    tank = water_tank(p.scope("tank"), dt, W - 0.012, p.uniform("tank_height", 0.6, 0.85) * (H - zb))
    link = b.create_link("tank", root)
    link.set_joint("prismatic", translation(D / 2 + 0.0015, 0, zb + REST), axis=(0.0, 0.0, 1.0),
                   limits=(0.0, p.uniform("tank_lift", 0.12, 0.2)))
    link.add(tank)
    _head_controls(ctx, D, W, H - 0.035, roof, 0, p.integers("buttons", 1, 3))


def _tray(ctx, D, W, bay, floor, h):
    p, b = ctx.p, ctx.builder
    depth = bay - 0.004
    link = b.create_link("tray", ctx.out["body"][0])
    link.set_joint("prismatic", translation(-D / 2, 0, floor + REST), axis=(-1.0, 0.0, 0.0),
                   limits=(0.0, p.uniform("tray_pull", 0.6, 0.9) * depth))
    link.add(drip_tray(p.scope("tray"), depth, W - 0.012, h))


def _head_controls(ctx, D, W, top, roof, n_knobs, k):
    """Knobs at the ends and a row of ``k`` buttons between them on the head front
    (from ``roof`` up to ``top``)."""
    p, b = ctx.p, ctx.builder
    root = ctx.out["body"][0]
    zc = (roof + top) / 2
    R = min(p.uniform("knob_radius", 0.014, 0.022), (top - roof) / 2 - 0.008)
    knob_t = ctx.choose("knob", KNOBS) if n_knobs else None
    ys = [W / 2 - 0.012 - R, -W / 2 + 0.012 + R][:n_knobs]
    for i, y in enumerate(ys):
        q = p.scope(f"knob{i}")
        cont = q.flag("continuous", 0.5)
        mount_knob(b, root, knob_t(q, radius=R), translation(-D / 2, y, zc), continuous=cont,
                   limits=(0.0, q.uniform("turn", 4.7, 5.2)))
    if k:
        lo = -W / 2 + 0.01 + (2 * R + 0.01 if n_knobs == 2 else 0.0)
        hi = W / 2 - 0.01 - (2 * R + 0.01 if n_knobs else 0.0)
        pitch = (hi - lo) / k
        h = min(0.014, top - roof - 0.012)
        mount_button_row(p.scope("buttons"), b, root, ctx.choose("button", BUTTONS), k, translation(-D / 2, 0, zc),
                         lo, hi, 0.0, radius=max(0.003, min(0.008, pitch / 2 - 0.005, h / 2)),
                         square=(max(0.006, min(0.02, pitch - 0.01)), h))


def controls(ctx):
    {"drip": drip, "espresso": espresso, "capsule": capsule}[ctx.sub](ctx)


RULE = Category(
    name="coffee_machine",
    subcategories={"drip": 3.0, "espresso": 2.0, "capsule": 2.0},  # filter machines are the most common
    # housings are hollow plastic or steel shells; carafes glass; portafilters steel
    materials={"body": "shell", "container": "glass", "portafilter": "steel", "lever": "plastic",
               "drawer": "plastic", "nozzle": "steel"},
    mass_range=(1.0, 25.0),  # kg: drip ~1.5-3, capsule ~2.5-5, semi-automatic espresso 5-20
    slots=(Slot("body", body), Slot("controls", controls, after=("body",))),
)
